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
 * The LU path, which Cholesky falls back to, is lusolve.c; the power-of-
 * two scalings scale.c; the report's energy balance balance.c.
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

#include "solve/fpass.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/solve.h"
#include "solve/progressive.h"
#include "solve/solvers.h"
#include "util/util.h"

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
 * matrix is allocated (radi_solve_lu, cholesky.c). */
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

/* ---- gauss ---------------------------------------------------------------- */

static rad_status solve_gauss(int n, const double *F, const double *rho, const double *E,
                              double *B, const rad_solve_options *opt, rad_solve_report *rep,
                              rad_error *err)
{
    int done[RAD_BANDS] = {0}, bands[RAD_BANDS], nb;
    while ((nb = radi_next_band_set(n, rho, done, bands)) > 0) {
        const double *rb = rho + (size_t)bands[0] * n;
        rep->systems++;
        if (opt->progress && opt->progress(opt->progress_user, "solve", rep->systems - 1, RAD_BANDS))
            return radi_fail(err, RAD_ERR_INVALID, "interrupted");
        rad_status st = radi_solve_lu(n, F, rb, E, B, bands, nb, opt, rep, err);
        if (st)
            return st;
    }
    if (opt->progress)
        opt->progress(opt->progress_user, "solve", RAD_BANDS, RAD_BANDS);
    return RAD_OK;
}

/* ---- diagnostics ---------------------------------------------------------- */

static rad_status diagnose(int n, const double *F, const double *rho, const double *E,
                           const double *B, const double *area, int ka, int ke,
                           rad_solve_report *rep, rad_error *err)
{
    const size_t n3 = (size_t)n * RAD_BANDS;
    double *H = malloc(sizeof *H * n3), *rs = calloc((size_t)n, sizeof *rs);
    if (!H || !rs) {
        free(H);
        free(rs);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++)
            rs[i] += F[(size_t)i + (size_t)j * n];
    if (radi_fpass_mul(n, F, B, H)) { /* H = F B: the irradiance of Cohen et al. 1988 */
        free(H);
        free(rs);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    radi_solve_balance(n, H, rs, rho, E, B, area, ka, ke, rep);
    free(H);
    free(rs);
    return RAD_OK;
}

/* B = B' 2^ke, or RAD_ERR_INVALID when that leaves the double range (or B'
 * is not finite: an overflow inside a solver that got E unscaled). */
static rad_status unscale_b(double *B, size_t n3, int ke, rad_error *err)
{
    const double m = radi_max_abs(B, n3);
    for (size_t k = 0; k < n3; k++)
        if (!isfinite(B[k]))
            return radi_fail(err, RAD_ERR_INVALID,
                            "the radiosity overflows: it exceeds the largest double (%.3g); "
                            "scale the emission down",
                            DBL_MAX);
    if (ke > 0 && !(m <= ldexp(DBL_MAX, -ke))) {
        /* m 2^ke as d 10^p, for the message */
        const double l = log10(m) + ke * log10(2.0), p = floor(l);
        return radi_fail(err, RAD_ERR_INVALID,
                        "the radiosity would reach %.3ge%+.0f, beyond the largest double "
                        "(%.3g); scale the emission down by a factor of %.3g at least",
                        pow(10, l - p), p, DBL_MAX, pow(10, l - log10(DBL_MAX)));
    }
    radi_scale_by(B, n3, ke);
    return RAD_OK;
}

/* Progressive refinement (progressive.c) on the dense F.  A trace
 * (opt->on_shot) without a reference gets the converged solution, by
 * gauss, solved here before the first shot: the shooter never calls back
 * up into this dispatcher. */
rad_status rad_solve_progressive(const rad_mesh *m, const double *F, const double *rho,
                                 const double *E, const rad_solve_options *opt, double *B,
                                 rad_solve_report *report, rad_error *err)
{
    const rad_shoot_source src = {F, NULL};
    if (!opt->on_shot || opt->reference || !F)
        return radi_progressive_run(m, &src, rho, E, opt, B, report, err);
    rad_solve_options g = *opt, traced = *opt;
    g.solver = RAD_SOLVER_GAUSS;
    g.on_shot = NULL;
    g.reference = NULL;
    g.bounces = -1;
    double *own = malloc(sizeof *own * (size_t)(m->nelements ? m->nelements : 1) * RAD_BANDS);
    if (!own)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the trace's reference");
    rad_status st = rad_solve(m, F, &g, own, NULL, err);
    if (st == RAD_OK) {
        traced.reference = own;
        st = radi_progressive_run(m, &src, rho, E, &traced, B, report, err);
    }
    free(own);
    return st;
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
        return radi_fail(err, RAD_ERR_INVALID, "tolerance must be positive and max-iterations at least 1");
    /* calloc: GCC 12 cannot see that the loop below fills them */
    double *rho = malloc(sizeof *rho * n3), *E = calloc(n3 ? n3 : 1, sizeof *E);
    double *area = calloc((size_t)(n ? n : 1), sizeof *area);
    if (!rho || !E || !area) {
        free(rho);
        free(E);
        free(area);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
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
    const int ke = radi_scale_exponent(E, n3), ka = radi_scale_exponent(area, (size_t)n);
    const int late = progressive && opt->on_shot;
    radi_scale_by(area, (size_t)n, -ka);
    if (!late)
        radi_scale_by(E, n3, -ke);
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
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    else if (opt->solver == RAD_SOLVER_CHOLESKY && opt->bounces < 0)
        st = radi_solve_cholesky(&ms, F, rho, E, B, opt, rep, err);
    else if (opt->solver == RAD_SOLVER_CG && opt->bounces < 0)
        st = radi_solve_cg(&ms, F, rho, E, B, opt, rep, err);
    else
        st = radi_solve_iterate(&ms, F, rho, E, B, opt, rep, err);
    free(els);
    if (late) {
        radi_scale_by(E, n3, -ke);
        radi_scale_by(B, n3, -ke);
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
        radi_scale_by(B, n3, ke);
    free(rho);
    free(E);
    free(area);
    return st;
}
