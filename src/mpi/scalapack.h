/* scalapack.h -- the BLACS, ScaLAPACK and PBLAS routines radiosity-mpi
 * calls (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Debian's libscalapack-openmpi-dev ships no C header, so the prototypes
 * are written here from the reference documentation (ScaLAPACK Users'
 * Guide, 1997, ch. 4 and appendix; the BLACS C interface, Dongarra &
 * Whaley 1997).  Fortran conventions: every argument by address, 32-bit
 * integers, column-major local arrays, one-based global indices (ia, ja).
 * A descriptor is nine integers (descinit_).
 */
#ifndef RAD_SCALAPACK_H
#define RAD_SCALAPACK_H

void Cblacs_pinfo(int *mypnum, int *nprocs);
void Cblacs_get(int icontxt, int what, int *val);
void Cblacs_gridinit(int *icontxt, const char *order, int nprow, int npcol);
void Cblacs_gridinfo(int icontxt, int *nprow, int *npcol, int *myrow, int *mycol);
void Cblacs_gridexit(int icontxt);
void Cblacs_exit(int notdone);

int numroc_(const int *n, const int *nb, const int *iproc, const int *isrcproc,
            const int *nprocs);
void descinit_(int *desc, const int *m, const int *n, const int *mb, const int *nb,
               const int *irsrc, const int *icsrc, const int *ictxt, const int *lld, int *info);

double pdlange_(const char *norm, const int *m, const int *n, const double *a, const int *ia,
                const int *ja, const int *desca, double *work);
double pdlansy_(const char *norm, const char *uplo, const int *n, const double *a,
                const int *ia, const int *ja, const int *desca, double *work);

void pdgetrf_(const int *m, const int *n, double *a, const int *ia, const int *ja,
              const int *desca, int *ipiv, int *info);
void pdgetrs_(const char *trans, const int *n, const int *nrhs, const double *a, const int *ia,
              const int *ja, const int *desca, const int *ipiv, double *b, const int *ib,
              const int *jb, const int *descb, int *info);
void pdgecon_(const char *norm, const int *n, const double *a, const int *ia, const int *ja,
              const int *desca, const double *anorm, double *rcond, double *work,
              const int *lwork, int *iwork, const int *liwork, int *info);

void pdpotrf_(const char *uplo, const int *n, double *a, const int *ia, const int *ja,
              const int *desca, int *info);
void pdpotrs_(const char *uplo, const int *n, const int *nrhs, const double *a, const int *ia,
              const int *ja, const int *desca, double *b, const int *ib, const int *jb,
              const int *descb, int *info);
void pdpocon_(const char *uplo, const int *n, const double *a, const int *ia, const int *ja,
              const int *desca, const double *anorm, double *rcond, double *work,
              const int *lwork, int *iwork, const int *liwork, int *info);

#endif /* RAD_SCALAPACK_H */
