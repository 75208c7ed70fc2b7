/* lusolve.c -- the LU path every direct solver shares.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * (I - diag(rho) F) X = E by LU with partial pivoting (Goral et al. 1984,
 * eq. 6-7, solved as the paper's Gaussian elimination): the factorisation
 * is blocked as LAPACK's dgetrf (lu.c) so progress shows, dgetrs solves,
 * dgecon estimates the reciprocal condition; or dgesvx with forward and
 * backward error bounds.  Bands whose reflectances agree on every element
 * share one factorisation (radi_next_band_set).  The dispatcher (solve.c)
 * calls this for `gauss`, Cholesky (cholesky.c) where the symmetric form
 * is not positive definite.  Arrays are column-major as solve.c states.
 *
 * A system is reported singular when dgetrf meets an exact zero pivot or
 * the reciprocal condition estimate falls below RAD_RCOND_MIN (solvers.h): then fewer
 * than about 6 digits of B could be trusted (round-off 1e-16 times the
 * condition number 1e10).
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/util.h"
#include "solve/lu.h"
#include "radiosity/base.h"
#include "radiosity/solve.h"
#include "solve/solvers.h"


/* The working matrix of LU or Cholesky, refused (RAD_ERR_TOOBIG) before
 * it is allocated when it cannot fit: a solver that reached LU by a
 * fallback was admitted for F alone. */
rad_status radi_solve_matrix_check(int n, int matrices, const char *what, rad_error *err)
{
    return rad_memory_check(matrices * (double)n * (double)n * sizeof(double), what, NULL, err);
}

/* Factor and solve (I - diag(rho) F) X = E for the bands listed in
 * bands[0..nb): rho is that of bands[0]. */
rad_status radi_solve_lu(int n, const double *F, const double *rho, const double *E,
                        double *B, const int *bands, int nb, const rad_solve_options *opt,
                        rad_solve_report *rep, rad_error *err)
{
    if (radi_solve_matrix_check(n, opt->error_bounds ? 2 : 1, "the LU factorisation's "
                               "working matrix", err) != RAD_OK)
        return err ? err->status : RAD_ERR_TOOBIG;
    const size_t nn = (size_t)n * n;
    double *A = malloc(sizeof *A * nn), *AF = NULL;
    int *ipiv = malloc(sizeof *ipiv * (size_t)n), *iwork = malloc(sizeof *iwork * (size_t)n);
    double *work = malloc(sizeof *work * 4 * (size_t)n);
    double *rhs = malloc(sizeof *rhs * (size_t)n * nb), *X = malloc(sizeof *X * (size_t)n * nb);
    double *rowabs = calloc((size_t)n, sizeof *rowabs);
    double anorm = 0, rcond = 0, ainf = 0, rho_max = 0;
    int info = 0;
    rad_status st = RAD_OK;
    if (opt->error_bounds)
        AF = malloc(sizeof *AF * nn);
    if (!A || !ipiv || !iwork || !work || !rhs || !X || !rowabs || (opt->error_bounds && !AF)) {
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for the %d x %d system", n, n);
        goto done;
    }
    for (int j = 0; j < n; j++) { /* A = I - diag(rho) F; anorm = ||A||_1 */
        double col = 0;
        for (int i = 0; i < n; i++) {
            double a = (i == j) - rho[i] * F[(size_t)i + (size_t)j * n];
            A[(size_t)i + (size_t)j * n] = a;
            col += fabs(a);
            rowabs[i] += fabs(a);
        }
        anorm = fmax(anorm, col);
    }
    for (int i = 0; i < n; i++) { /* ||A||_inf, max rho */
        ainf = fmax(ainf, rowabs[i]);
        rho_max = fmax(rho_max, rho[i]);
    }
    for (int k = 0; k < nb; k++)
        memcpy(rhs + (size_t)k * n, E + (size_t)bands[k] * n, sizeof *rhs * (size_t)n);
    if (opt->error_bounds) {
        char equed = 'N';
        double *ferr = malloc(sizeof *ferr * (size_t)nb), *berr = malloc(sizeof *berr * (size_t)nb);
        if (!ferr || !berr) {
            free(ferr);
            free(berr);
            st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
            goto done;
        }
        dgesvx_("N", "N", &n, &nb, A, &n, AF, &n, ipiv, &equed, NULL, NULL, rhs, &n, X, &n,
                &rcond, ferr, berr, work, iwork, &info, 1, 1, 1);
        for (int k = 0; k < nb; k++) {
            rep->ferr = fmax(rep->ferr, ferr[k]);
            rep->berr = fmax(rep->berr, berr[k]);
        }
        free(ferr);
        free(berr);
        if (info > 0 && info <= n)
            rcond = 0;
    } else {
        int stopped;
        info = radi_lu_factor(n, A, ipiv, opt->progress, opt->progress_user, "factorise",
                             &stopped);
        if (stopped) {
            st = radi_fail(err, RAD_ERR_INVALID, "interrupted");
            goto done;
        }
        if (info == 0) {
            dgecon_("1", &n, A, &n, &anorm, &rcond, work, iwork, &info, 1);
            dgetrs_("N", &n, &nb, A, &n, ipiv, rhs, &n, &info, 1);
            memcpy(X, rhs, sizeof *X * (size_t)n * nb);
        } else {
            rcond = 0;
        }
    }
    rep->rcond = rep->systems == 1 ? rcond : fmin(rep->rcond, rcond);
    if (!(rcond >= RAD_RCOND_MIN)) {
        /* rho = 1 is the one physical cause; with every rho < 1 and F
         * sane, (I - rho F) is diagonally dominant and cannot be singular */
        st = radi_fail(err, RAD_ERR_SINGULAR, "the radiosity system is singular (reciprocal "
                      "condition %.3g < %g): %s", rcond, RAD_RCOND_MIN,
                      rho_max >= 1 ? "a closed enclosure that reflects everything (rho = 1) "
                                     "never absorbs light, so no steady state exists"
                                   : "every rho is below 1, so the form factors are at fault "
                                     "(not finite, or rows of F summing above 1: see the "
                                     "warnings above, and try `accuracy` default)");
        goto done;
    }
    if (opt->ff_row_error >= 0) {
        /* The error dF of the form factors perturbs A by at most
         * ||diag(rho) dF||_inf <= rho_max ||dF||_inf =: d, and B by at
         * most k / (1 - k) relative, k = ||A^-1||_inf d (the normwise
         * perturbation bound, Higham 2002, Accuracy and Stability of
         * Numerical Algorithms, thm. 7.2), ||A^-1||_inf = 1 / (rcond_inf
         * ||A||_inf) from LAPACK's estimate (dgecon).  k >= 1: F is not known well enough to tell
         * the system from a singular one. */
        double rinf = 0;
        int inf2 = 0;
        dgecon_("I", &n, AF ? AF : A, &n, &ainf, &rinf, work, iwork, &inf2, 1);
        const double k = rho_max * opt->ff_row_error / (rinf * ainf);
        const double bound = k < 1 ? k / (1 - k) : INFINITY;
        rep->ff_error_bound = isnan(rep->ff_error_bound) ? bound : fmax(rep->ff_error_bound, bound);
        if (!(k < 1)) {
            st = radi_fail(err, RAD_ERR_SINGULAR,
                          "the radiosity system is singular within the accuracy of its form "
                          "factors: their error (up to %.3g per row) could make it singular "
                          "(||(I - rho F)^-1|| ||rho dF|| = %.3g >= 1); a closed enclosure "
                          "that reflects (nearly) everything needs them exact",
                          opt->ff_row_error, k);
            goto done;
        }
    }
    for (int k = 0; k < nb; k++)
        memcpy(B + (size_t)bands[k] * n, X + (size_t)k * n, sizeof *B * (size_t)n);
done:
    free(rowabs);
    free(A);
    free(AF);
    free(ipiv);
    free(iwork);
    free(work);
    free(rhs);
    free(X);
    return st;
}

int radi_next_band_set(int n, const double *rho, int done[RAD_BANDS], int bands[RAD_BANDS])
{
    int b = 0, nb = 0;
    while (b < RAD_BANDS && done[b])
        b++;
    for (int c = b; c < RAD_BANDS; c++) /* bands with the same reflectances */
        if (!done[c] &&
            memcmp(rho + (size_t)b * n, rho + (size_t)c * n, sizeof *rho * (size_t)n) == 0) {
            bands[nb++] = c;
            done[c] = 1;
        }
    return nb;
}
