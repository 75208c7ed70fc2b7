/* solvers.h -- the band solvers behind rad_solve (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Each solves (I - diag(rho_b) F) B_b = E_b for the three bands; rho, E
 * and B are n x RAD_BANDS column-major, F n x n column-major (solve.c
 * says how).  They fill the solver's fields of the report; rad_solve
 * fills the rest (residual, energy balance).
 */
#ifndef RAD_SOLVERS_H
#define RAD_SOLVERS_H

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/solve.h"

/* A system is reported singular when the reciprocal condition estimate
 * falls below this: then fewer than about 6 digits of B could be trusted
 * (round-off 1e-16 times the condition number 1e10).  LU (lusolve.c),
 * Cholesky (cholesky.c) and the distributed solve (mpi_solve.c) share it. */
#define RAD_RCOND_MIN 1e-10

/* The next set of bands that share one reflectance vector and are not yet
 * done: their indices in bands[], marked done; returns how many (0 when
 * every band is done).  One factorisation serves each set (lusolve.c). */
int radi_next_band_set(int n, const double *rho, int done[RAD_BANDS], int bands[RAD_BANDS]);

/* LU (lusolve.c) of the bands listed in bands[0..nb), which share the
 * reflectances rho (those of bands[0]). */
rad_status radi_solve_lu(int n, const double *F, const double *rho, const double *E, double *B,
                        const int *bands, int nb, const rad_solve_options *opt,
                        rad_solve_report *rep, rad_error *err);

/* The symmetric form by Cholesky, LU where it is not positive definite
 * (cholesky.c). */
rad_status radi_solve_cholesky(const rad_mesh *m, const double *F, const double *rho,
                              const double *E, double *B, const rad_solve_options *opt,
                              rad_solve_report *rep, rad_error *err);

/* Jacobi, Gauss-Seidel and --bounces (iterate.c). */
rad_status radi_solve_iterate(const rad_mesh *m, const double *F, const double *rho,
                             const double *E, double *B, const rad_solve_options *opt,
                             rad_solve_report *rep, rad_error *err);

/* Conjugate gradients on the symmetric form (cg.c). */
rad_status radi_solve_cg(const rad_mesh *m, const double *F, const double *rho,
                        const double *E, double *B, const rad_solve_options *opt,
                        rad_solve_report *rep, rad_error *err);

/* The report's row sums, residual and energy balance from H = F B and
 * the row sums rs of F (balance.c); area and E scaled by 2^-ka and 2^-ke,
 * which the powers undo.  The distributed solve (mpi_solve.c) reduces H
 * and rs over its processes and calls this on rank 0. */
void radi_solve_balance(int n, const double *H, const double *rs, const double *rho,
                       const double *E, const double *B, const double *area, int ka, int ke,
                       rad_solve_report *rep);

/* The exponent e with max |x_k| in [2^(e-1), 2^e) (0 for all zeros or a
 * non-finite maximum), and x *= 2^e exactly: the scalings of E and the
 * areas that keep every solver inside the double range (scale.c;
 * solve.c, Range). */
int radi_scale_exponent(const double *x, size_t n);
/* max_k |x_k|, the norm every solver's stopping test and scaling uses
 * (scale.c). */
double radi_max_abs(const double *x, size_t n);
void radi_scale_by(double *x, size_t n, int e);

/* RAD_ERR_TOOBIG (the message names `what`) when `matrices` n x n
 * matrices of doubles would not fit in the memory available now: the
 * check before LU's or Cholesky's working matrix (lusolve.c). */
rad_status radi_solve_matrix_check(int n, int matrices, const char *what, rad_error *err);

/* Append "why" to the report's fallback note (count it): cholesky, cg. */
void radi_report_fallback(rad_solve_report *rep, const char *why);

#endif /* RAD_SOLVERS_H */
