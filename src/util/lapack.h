/* lapack.h -- the few LAPACK and BLAS routines radiosity calls (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Fortran calling convention: every argument by reference, column-major
 * arrays, and one hidden length argument (size_t, as in LAPACK 3.9's
 * lapack.h FORTRAN_STRLEN) per CHARACTER argument, at the end.  Debian's
 * OpenBLAS serves both liblapack.so.3 and libblas.so.3.
 */
#ifndef RAD_LAPACK_H
#define RAD_LAPACK_H

#include <stddef.h>

void dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);
void dgetrs_(const char *trans, const int *n, const int *nrhs, const double *a,
             const int *lda, const int *ipiv, double *b, const int *ldb, int *info,
             size_t trans_len);
void dgecon_(const char *norm, const int *n, const double *a, const int *lda,
             const double *anorm, double *rcond, double *work, int *iwork, int *info,
             size_t norm_len);
void dgesvx_(const char *fact, const char *trans, const int *n, const int *nrhs, double *a,
             const int *lda, double *af, const int *ldaf, int *ipiv, char *equed, double *r,
             double *c, double *b, const int *ldb, double *x, const int *ldx, double *rcond,
             double *ferr, double *berr, double *work, int *iwork, int *info, size_t fact_len,
             size_t trans_len, size_t equed_len);
/* Cholesky of a symmetric positive definite matrix (cholesky.c) */
void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info,
             size_t uplo_len);
void dpotrs_(const char *uplo, const int *n, const int *nrhs, const double *a,
             const int *lda, double *b, const int *ldb, int *info, size_t uplo_len);
void dpocon_(const char *uplo, const int *n, const double *a, const int *lda,
             const double *anorm, double *rcond, double *work, int *iwork, int *info,
             size_t uplo_len);
/* Hager-Higham 1-norm estimator by reverse communication (Higham 2002,
 * algorithm 15.4): kase = 1 asks for x := A x, kase = 2 for x := A^T x */
void dlacn2_(const int *n, double *v, double *x, int *isgn, double *est, int *kase,
             int *isave);
void dlaswp_(const int *n, double *a, const int *lda, const int *k1, const int *k2,
             const int *ipiv, const int *incx);
void dtrsm_(const char *side, const char *uplo, const char *transa, const char *diag,
            const int *m, const int *n, const double *alpha, const double *a, const int *lda,
            double *b, const int *ldb, size_t side_len, size_t uplo_len, size_t transa_len,
            size_t diag_len);
void dgemm_(const char *transa, const char *transb, const int *m, const int *n, const int *k,
            const double *alpha, const double *a, const int *lda, const double *b,
            const int *ldb, const double *beta, double *c, const int *ldc, size_t transa_len,
            size_t transb_len);

/* Stop OpenBLAS's idle worker threads, which spin for a tenth of a
 * second after the library is loaded (blasthreads.c).  For programs, at
 * start-up, before any other thread calls BLAS; a library function never
 * calls it. */
void radi_blas_park_threads(void);

#endif /* RAD_LAPACK_H */
