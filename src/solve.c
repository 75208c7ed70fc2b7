/* solve.c -- the radiosity system, band by band.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * For each colour band b the radiosities satisfy (Goral et al. 1984,
 * eq. 6-7; Cohen et al. 1988, eq. 4)
 *
 *     B_i = E_i + rho_i sum_j F_ij B_j,   i.e.   (I - diag(rho) F) B = E.
 *
 * Arrays are column-major: F[i + j*n] = F_ij; B, E and rho are n x 3 with
 * band b in column b (B[i + b*n]).
 *
 * Solvers:
 *   gauss         LU with partial pivoting (blocked as LAPACK's dgetrf, in
 *                 lu.c, so progress shows; dgetrs solves; as the paper's
 *                 Gaussian elimination), reciprocal condition from
 *                 dgecon; or dgesvx with forward and backward error bounds.
 *                 Bands whose reflectances agree on every element share one
 *                 factorisation with several right-hand sides, and only one
 *                 working matrix is alive at a time.
 *   cholesky      the symmetric form diag(A/rho) (I - diag(rho) F), by
 *                 LAPACK's dpotrf (cholesky.c), LU where it does not apply.
 *   jacobi, gauss-seidel, bounces K   one pass over F per sweep for the
 *                 three bands, stopping on a bound of the error (iterate.c).
 *   cg            conjugate gradients on the symmetric form (cg.c).
 *   progressive   shooting (progressive.c).
 * A system is reported singular when dgetrf meets an exact zero pivot or
 * the reciprocal condition estimate falls below RAD_RCOND_MIN: then fewer
 * than about 6 digits of B could be trusted (round-off 1e-16 times the
 * condition number 1e10).
 *
 * Range.  The system is linear in E and the solvers weigh by area only in
 * ratios, so E is scaled by a power of two (exact) to a largest value near
 * 1 before solving, and the areas to a largest value near 1, and B scaled
 * back at the end: an emission of 1e308 or 1e-308 solves as one of 1
 * would, and nothing overflows on the way.  Only B itself may not exist
 * in doubles (B = E / (1 - rho) > 1.8e308); then rad_solve refuses with
 * RAD_ERR_INVALID, naming the limit, rather than return an infinity.
 * Progressive refinement with a trace gets E as it is (the trace writes
 * powers and errors in the user's units) and B is scaled after it.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lapack.h"
#include "fpass.h"
#include "lu.h"
#include "radiosity/pipeline.h"
#include "radiosity.h"
#include "solvers.h"
#include "status.h"

#define RAD_RCOND_MIN 1e-10

void rad_solve_options_init(rad_solve_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->solver = RAD_SOLVER_GAUSS;
    opt->tolerance = 1e-12;
    opt->max_iterations = 100000;
    opt->bounces = -1;
    opt->sort = 1;
    opt->ff_row_error = NAN;
    opt->subdivide_threshold = 0.1;
    opt->max_depth = 3;
    opt->subdivide_by_error = 0;
}

double rad_solve_bytes(int n, int with_errbounds)
{
    double nn = (double)n * (double)n * sizeof(double);
    /* F, one working matrix (and dgesvx's factor copy), O(n) vectors */
    return nn * (with_errbounds ? 3 : 2) + 64.0 * n * sizeof(double);
}

/* Matrices of n x n doubles each solver holds at its peak, F included:
 * LU and Cholesky build a working matrix beside F (dgesvx a factor copy
 * too); Jacobi, Gauss-Seidel, CG, progressive and --bounces read F and
 * keep O(n) vectors.  CG may go on to Cholesky and Cholesky to LU where
 * the symmetric form fails: those check the memory again before their
 * matrix is allocated (rad_solve_lu, cholesky.c). */
static int solve_matrices(const rad_solve_options *opt)
{
    if (opt->bounces >= 0)
        return 1;
    switch (opt->solver) {
    case RAD_SOLVER_GAUSS:
        return opt->error_bounds ? 3 : 2;
    case RAD_SOLVER_CHOLESKY:
        return 2;
    default:
        return 1;
    }
}

double rad_solve_bytes_for(int n, const rad_solve_options *opt)
{
    const double nn = (double)n * (double)n * sizeof(double);
    /* O(n): rho, E, B, areas, the iterative solvers' per-thread sums */
    return nn * solve_matrices(opt) + 64.0 * n * sizeof(double);
}

/* The working matrix of LU or Cholesky, refused (RAD_ERR_TOOBIG) before
 * it is allocated when it cannot fit: a solver that reached LU by a
 * fallback was admitted for F alone. */
rad_status rad_solve_matrix_check(int n, int matrices, const char *what, rad_error *err)
{
    return rad_memory_check(matrices * (double)n * (double)n * sizeof(double), what, NULL, err);
}

static double max_abs(const double *x, size_t n)
{
    double m = 0;
    for (size_t k = 0; k < n; k++)
        m = fmax(m, fabs(x[k]));
    return m;
}

/* ---- gauss ---------------------------------------------------------------- */

/* Factor and solve (I - diag(rho) F) X = E for the bands listed in
 * bands[0..nb): rho is that of bands[0]. */
rad_status rad_solve_lu(int n, const double *F, const double *rho, const double *E,
                        double *B, const int *bands, int nb, const rad_solve_options *opt,
                        rad_solve_report *rep, rad_error *err)
{
    if (rad_solve_matrix_check(n, opt->error_bounds ? 2 : 1, "the LU factorisation's "
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
        st = rad_fail(err, RAD_ERR_NOMEM, "out of memory for the %d x %d system", n, n);
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
            st = rad_fail(err, RAD_ERR_NOMEM, "out of memory");
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
        info = rad_lu_factor(n, A, ipiv, opt->progress, opt->progress_user, "factorise",
                             &stopped);
        if (stopped) {
            st = rad_fail(err, RAD_ERR_INVALID, "interrupted");
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
        st = rad_fail(err, RAD_ERR_SINGULAR, "the radiosity system is singular (reciprocal "
                      "condition %.3g < %g): %s", rcond, RAD_RCOND_MIN,
                      rho_max >= 1 ? "a closed enclosure that reflects everything (rho = 1) "
                                     "never absorbs light, so no steady state exists"
                                   : "every rho is below 1, so the form factors are at fault "
                                     "(not finite, or rows of F summing above 1: see the "
                                     "warnings above, and try --accuracy default)");
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
            st = rad_fail(err, RAD_ERR_SINGULAR,
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

int rad_next_band_set(int n, const double *rho, int done[RAD_BANDS], int bands[RAD_BANDS])
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

static rad_status solve_gauss(int n, const double *F, const double *rho, const double *E,
                              double *B, const rad_solve_options *opt, rad_solve_report *rep,
                              rad_error *err)
{
    int done[RAD_BANDS] = {0}, bands[RAD_BANDS], nb;
    while ((nb = rad_next_band_set(n, rho, done, bands)) > 0) {
        const double *rb = rho + (size_t)bands[0] * n;
        rep->systems++;
        if (opt->progress && opt->progress(opt->progress_user, "solve", rep->systems - 1, RAD_BANDS))
            return rad_fail(err, RAD_ERR_INVALID, "interrupted");
        rad_status st = rad_solve_lu(n, F, rb, E, B, bands, nb, opt, rep, err);
        if (st)
            return st;
    }
    if (opt->progress)
        opt->progress(opt->progress_user, "solve", RAD_BANDS, RAD_BANDS);
    return RAD_OK;
}

/* ---- diagnostics ---------------------------------------------------------- */

/* The report's powers are sum A_i x_i in the user's units: the sums are
 * taken with the scaled areas and E (2^-ka, 2^-ke) and scaled back, so
 * they are inf only when the power itself exceeds the double range; the
 * balance, a ratio, is computed before that.  H = F B and rs, the row
 * sums of F, come from the caller (solvers.h). */
void rad_solve_balance(int n, const double *H, const double *rs, const double *rho,
                       const double *E, const double *B, const double *area, int ka, int ke,
                       rad_solve_report *rep)
{
    rep->row_sum_min = n ? HUGE_VAL : 0;
    rep->row_sum_max = n ? -HUGE_VAL : 0;
    for (int i = 0; i < n; i++) {
        rep->row_sum_min = fmin(rep->row_sum_min, rs[i]);
        rep->row_sum_max = fmax(rep->row_sum_max, rs[i]);
    }
    double emax = max_abs(E, (size_t)n * RAD_BANDS), res = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        double em = 0, ab = 0, es = 0;
        for (int i = 0; i < n; i++) {
            size_t k = (size_t)i + (size_t)b * n;
            double a = area[i];
            res = fmax(res, fabs(B[k] - rho[k] * H[k] - E[k]));
            em += a * E[k];
            ab += a * (1 - rho[k]) * H[k];
            es += a * B[k] * (1 - rs[i]);
        }
        rep->emitted[b] = ldexp(em, ka + ke);
        rep->absorbed[b] = ldexp(ab, ka + ke);
        rep->escaped[b] = ldexp(es, ka + ke);
        rep->balance[b] = em > 0 ? (em - ab - es) / em : ldexp(em - ab - es, ka + ke);
    }
    rep->residual = emax > 0 ? res / emax : res;
}

static rad_status diagnose(int n, const double *F, const double *rho, const double *E,
                           const double *B, const double *area, int ka, int ke,
                           rad_solve_report *rep, rad_error *err)
{
    const size_t n3 = (size_t)n * RAD_BANDS;
    double *H = malloc(sizeof *H * n3), *rs = calloc((size_t)n, sizeof *rs);
    if (!H || !rs) {
        free(H);
        free(rs);
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++)
            rs[i] += F[(size_t)i + (size_t)j * n];
    if (rad_fpass_mul(n, F, B, H)) { /* H = F B: the irradiance of Cohen et al. 1988 */
        free(H);
        free(rs);
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    rad_solve_balance(n, H, rs, rho, E, B, area, ka, ke, rep);
    free(H);
    free(rs);
    return RAD_OK;
}

/* 2^e with 2^(e-1) <= max |x_k| < 2^e (0 for all zeros or a non-finite
 * maximum): the exponent that scales x to a largest value in [1/2, 1). */
int rad_scale_exponent(const double *x, size_t n)
{
    int e = 0;
    const double m = max_abs(x, n);
    if (m > 0 && isfinite(m))
        frexp(m, &e);
    return e;
}

void rad_scale_by(double *x, size_t n, int e)
{
    for (size_t k = 0; k < n; k++)
        x[k] = ldexp(x[k], e);
}

/* B = B' 2^ke, or RAD_ERR_INVALID when that leaves the double range (or B'
 * is not finite: an overflow inside a solver that got E unscaled). */
static rad_status unscale_b(double *B, size_t n3, int ke, rad_error *err)
{
    const double m = max_abs(B, n3);
    for (size_t k = 0; k < n3; k++)
        if (!isfinite(B[k]))
            return rad_fail(err, RAD_ERR_INVALID,
                            "the radiosity overflows: it exceeds the largest double (%.3g); "
                            "scale the emission down",
                            DBL_MAX);
    if (ke > 0 && !(m <= ldexp(DBL_MAX, -ke))) {
        /* m 2^ke as d 10^p, for the message */
        const double l = log10(m) + ke * log10(2.0), p = floor(l);
        return rad_fail(err, RAD_ERR_INVALID,
                        "the radiosity would reach %.3ge%+.0f, beyond the largest double "
                        "(%.3g); scale the emission down by a factor of %.3g at least",
                        pow(10, l - p), p, DBL_MAX, pow(10, l - log10(DBL_MAX)));
    }
    rad_scale_by(B, n3, ke);
    return RAD_OK;
}

rad_status rad_solve(const rad_mesh *m, const double *F, const rad_solve_options *opt,
                     double *B, rad_solve_report *rep, rad_error *err)
{
    const int n = m->nelements;
    const size_t n3 = (size_t)n * RAD_BANDS;
    rad_solve_report local;
    rad_status st;
    if (!rep)
        rep = &local;
    memset(rep, 0, sizeof *rep);
    rep->solver = opt->bounces >= 0 ? RAD_SOLVER_JACOBI : opt->solver; /* --bounces: Jacobi */
    rep->bounces = opt->bounces;
    rep->rcond = NAN;
    rep->ff_error_bound = NAN;
    rep->spectral_radius = NAN;
    rep->ferr = rep->berr = NAN;
    rep->error_bound = rep->contraction = NAN;
    if (opt->tolerance <= 0 || opt->max_iterations < 1)
        return rad_fail(err, RAD_ERR_INVALID, "tolerance must be positive and max-iterations at least 1");
    /* calloc: GCC 12 cannot see that the loop below fills them */
    double *rho = malloc(sizeof *rho * n3), *E = calloc(n3 ? n3 : 1, sizeof *E);
    double *area = calloc((size_t)(n ? n : 1), sizeof *area);
    if (!rho || !E || !area) {
        free(rho);
        free(E);
        free(area);
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    for (int i = 0; i < n; i++) {
        area[i] = m->elements[i].area;
        for (int b = 0; b < RAD_BANDS; b++) {
            rho[(size_t)i + (size_t)b * n] = m->elements[i].reflect[b];
            E[(size_t)i + (size_t)b * n] = m->elements[i].emit[b];
        }
    }
    /* E and the areas to a largest value in [1/2, 1), exactly (see Range);
     * a traced progressive run shoots the user's E and scales after */
    const int progressive = opt->solver == RAD_SOLVER_PROGRESSIVE && opt->bounces < 0;
    const int ke = rad_scale_exponent(E, n3), ka = rad_scale_exponent(area, (size_t)n);
    const int late = progressive && opt->on_shot;
    rad_scale_by(area, (size_t)n, -ka);
    if (!late)
        rad_scale_by(E, n3, -ke);
    /* the solvers that weigh by area see the scaled areas (see Range):
     * a shallow copy of the mesh with its elements' areas replaced */
    rad_mesh ms = *m;
    rad_element *els = progressive || (opt->solver == RAD_SOLVER_GAUSS && opt->bounces < 0)
                           ? NULL
                           : malloc(sizeof *els * (size_t)(n ? n : 1));
    if (els) {
        memcpy(els, m->elements, sizeof *els * (size_t)n);
        for (int i = 0; i < n; i++)
            els[i].area = area[i];
        ms.elements = els;
    }
    if (opt->solver == RAD_SOLVER_GAUSS && opt->bounces < 0)
        st = solve_gauss(n, F, rho, E, B, opt, rep, err);
    else if (progressive)
        st = rad_solve_progressive(m, F, rho, E, opt, B, rep, err);
    else if (!els)
        st = rad_fail(err, RAD_ERR_NOMEM, "out of memory");
    else if (opt->solver == RAD_SOLVER_CHOLESKY && opt->bounces < 0)
        st = rad_solve_cholesky(&ms, F, rho, E, B, opt, rep, err);
    else if (opt->solver == RAD_SOLVER_CG && opt->bounces < 0)
        st = rad_solve_cg(&ms, F, rho, E, B, opt, rep, err);
    else
        st = rad_solve_iterate(&ms, F, rho, E, B, opt, rep, err);
    free(els);
    if (late) {
        rad_scale_by(E, n3, -ke);
        rad_scale_by(B, n3, -ke);
    }
    if (st == RAD_OK || st == RAD_ERR_NOCONV) {
        rad_error derr;
        if (diagnose(n, F, rho, E, B, area, ka, ke, rep, &derr) != RAD_OK && st == RAD_OK) {
            st = derr.status;
            if (err)
                *err = derr;
        }
    }
    if (st == RAD_OK)
        st = unscale_b(B, n3, ke, err);
    else if (st == RAD_ERR_NOCONV) /* the last iterate, for the caller to inspect */
        rad_scale_by(B, n3, ke);
    free(rho);
    free(E);
    free(area);
    return st;
}
