/* iterate.c -- Jacobi, Gauss-Seidel and --bounces, one pass over F per sweep.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The fixed point B = E + diag(rho) F B (Goral et al. 1984, eq. 6-7) by
 *   jacobi        B <- E + diag(rho) F B: one product F B for the three
 *                 bands per sweep (fpass.c);
 *   gauss-seidel  B_i <- E_i + rho_i sum_j F_ij B_j in place, i ascending.
 *                 Row i of a column-major F is strided, so when F obeys
 *                 reciprocity the sum is taken down column i instead:
 *                 sum_j F_ij B_j = (1/A_i) sum_j F_ji W_j, W = A B.  The
 *                 columns go in blocks of GS_BLOCK: the whole-column dot
 *                 products of a block are formed at once, in parallel,
 *                 with W as it stands when the block starts (new values
 *                 above the block, old ones in and below it), then each
 *                 i of the block adds F_ji (W_j^new - W_j^old) for the j
 *                 of the block before it.  That is the same iteration as
 *                 element by element, in another order of sums, and F is
 *                 read once per sweep.  A non-reciprocal F takes the rows
 *                 as they are (slowly);
 *   bounces K     exactly K Jacobi sweeps from B = E, no convergence test:
 *                 B_K = sum_{m=0..K} (diag(rho) F)^m E (the paper's fig. 7).
 *
 * Stopping on a bound of the true error, not the change between sweeps.
 * Both maps B -> E + T B contract in the infinity norm with factors
 *   jacobi        q = ||diag(rho) F||_inf = max_i rho_i sum_j |F_ij|,
 *   gauss-seidel  q = max_i u_i / (1 - l_i) <= q_jacobi,
 *                 l_i = rho_i sum_{j<i} |F_ij|, u_i = rho_i sum_{j>=i} |F_ij|
 * (for the second: if i is where e' = L e' + U e is largest, |e'_i| <=
 * l_i ||e'|| + u_i ||e||; and u / (1 - l) <= l + u when l + u <= 1; Varga,
 * Matrix Iterative Analysis, 1962, section 3.3), and for a map that
 * contracts by q < 1 the iterate's error is at most q / (1 - q) times the
 * last change: ||B_k - B*|| <= q/(1-q) ||B_k - B_(k-1)|| (Banach's fixed
 * point theorem; Golub & Van Loan, Matrix Computations, 4th ed., 11.2).
 * The sweeps stop when that bound, per band, falls to tolerance *
 * ||B||_inf, and report it.  q >= 1 (rho = 1 in a closed scene, or
 * classic mode's form factors outside [0, 1]) bounds nothing: then the
 * sweeps stop on the estimate r / (1 - r) times the change, r the ratio
 * of successive changes, and the report says no bound (NaN).  The sums
 * l_i and u_i come from one scan of F (fpass.c), which also tells whether
 * F is reciprocal; F' = diag(1/A) F^T diag(A), which the reciprocal
 * Gauss-Seidel uses, equals F to 1e-12 relative then, and so do their q.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solve/fpass.h"
#include "solve/solvers.h"
#include "util/util.h"

#define GS_BLOCK 1024

typedef struct iter {
    int n;
    const double *F, *rho, *E;
    double *B, *W, *H, *area;   /* W = A B (gauss-seidel), H = F B (jacobi) */
    double *D, *Wold;           /* GS_BLOCK x 3: a block's dot products, old W */
    int gs, recip;
    double q[RAD_BANDS];        /* contraction factor per band, INFINITY if >= 1 */
} iter;

/* The contraction factors, per band, from the scan's row sums. */
static void contraction(iter *it, const rad_fscan *sc, rad_solve_report *rep)
{
    rep->contraction = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        double qj = 0, qg = 0;
        for (int i = 0; i < it->n; i++) {
            const double r = it->rho[(size_t)i + (size_t)b * it->n];
            const double l = r * sc->lower[i], u = r * sc->upper[i];
            qj = fmax(qj, l + u);
            qg = fmax(qg, l < 1 ? u / (1 - l) : INFINITY);
        }
        rep->contraction = fmax(rep->contraction, qj);
        const double q = it->gs ? qg : qj;
        it->q[b] = q < 1 ? q : INFINITY;
    }
}

/* One Jacobi sweep: B <- E + rho F B.  Changes per band in chg. */
static int jacobi_sweep(iter *it, double chg[RAD_BANDS])
{
    const int n = it->n;
    if (radi_fpass_mul(n, it->F, it->B, it->H))
        return -1;
    for (int b = 0; b < RAD_BANDS; b++) {
        double c = 0;
        for (size_t k = (size_t)b * n; k < (size_t)(b + 1) * n; k++) {
            const double v = it->E[k] + it->rho[k] * it->H[k];
            c = fmax(c, fabs(v - it->B[k]));
            it->B[k] = v;
        }
        chg[b] = c;
    }
    return 0;
}

/* New B_i from h = sum_j F_ij B_j; W_i follows. */
static void gs_update(iter *it, int i, const double h[RAD_BANDS], double chg[RAD_BANDS])
{
    for (int b = 0; b < RAD_BANDS; b++) {
        const size_t k = (size_t)i + (size_t)b * it->n;
        const double v = it->E[k] + it->rho[k] * h[b];
        chg[b] = fmax(chg[b], fabs(v - it->B[k]));
        it->B[k] = v;
        it->W[k] = it->area[i] * v;
    }
}

/* One block [s, e) of the reciprocal Gauss-Seidel (see the top). */
static void gs_block(iter *it, int s, int e, double chg[RAD_BANDS])
{
    const int n = it->n;
    for (int b = 0; b < RAD_BANDS; b++)
        memcpy(it->Wold + (size_t)b * GS_BLOCK, it->W + (size_t)s + (size_t)b * n,
               sizeof *it->W * (size_t)(e - s));
    radi_fpass_dot_cols(n, it->F, s, e, it->W, it->D, GS_BLOCK);
    for (int i = s; i < e; i++) {
        const double *col = it->F + (size_t)i * n;
        double h[RAD_BANDS];
        for (int b = 0; b < RAD_BANDS; b++) {
            const double *w = it->W + (size_t)b * n, *wo = it->Wold + (size_t)b * GS_BLOCK - s;
            double d = it->D[(size_t)(i - s) + (size_t)b * GS_BLOCK];
            for (int j = s; j < i; j++)
                d += col[j] * (w[j] - wo[j]);
            h[b] = d / it->area[i];
        }
        gs_update(it, i, h, chg);
    }
}

/* One Gauss-Seidel sweep in place.  Changes per band in chg. */
static void gs_sweep(iter *it, double chg[RAD_BANDS])
{
    const int n = it->n;
    for (int b = 0; b < RAD_BANDS; b++)
        chg[b] = 0;
    if (it->recip) {
        for (int s = 0; s < n; s += GS_BLOCK)
            gs_block(it, s, s + GS_BLOCK < n ? s + GS_BLOCK : n, chg);
        return;
    }
    for (int i = 0; i < n; i++) { /* rows of F as they are: strided */
        double h[RAD_BANDS] = {0, 0, 0};
        for (int j = 0; j < n; j++)
            for (int b = 0; b < RAD_BANDS; b++)
                h[b] += it->F[(size_t)i + (size_t)j * n] * it->B[(size_t)j + (size_t)b * n];
        gs_update(it, i, h, chg);
    }
}

/* The bound on ||B_k - B*||_inf (NaN when some band has no contraction
 * factor below 1), and the estimate to stop on when there is none. */
static double error_bound(const iter *it, const double chg[RAD_BANDS], double rate,
                          double *stop_on)
{
    double bound = 0, est = 0;
    int none = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        const double q = it->q[b];
        if (q < 1)
            bound = fmax(bound, q / (1 - q) * chg[b]);
        else
            none = 1;
        est = fmax(est, fmax(chg[b], rate > 0 && rate < 1 ? rate / (1 - rate) * chg[b]
                                                          : chg[b] > 0 ? INFINITY : 0));
    }
    *stop_on = none ? est : bound;
    return none ? NAN : bound;
}

static void iter_free(iter *it)
{
    free(it->H);
    free(it->W);
    free(it->area);
    free(it->D);
    free(it->Wold);
}

/* Allocate, scan F (row sums, reciprocity) and start from B = E. */
static int iter_init(iter *it, const rad_mesh *m, const double *F, const double *rho,
                     const double *E, double *B, const rad_solve_options *opt,
                     rad_solve_report *rep)
{
    const int n = m->nelements;
    const size_t n3 = (size_t)n * RAD_BANDS;
    rad_fscan sc;
    memset(it, 0, sizeof *it);
    *it = (iter){.n = n, .F = F, .rho = rho, .E = E, .B = B};
    it->gs = opt->solver == RAD_SOLVER_GAUSS_SEIDEL && opt->bounces < 0;
    it->H = malloc(sizeof *it->H * (n3 + 1));
    it->W = malloc(sizeof *it->W * (n3 + 1));
    it->area = malloc(sizeof *it->area * ((size_t)n + 1));
    it->D = malloc(sizeof *it->D * GS_BLOCK * RAD_BANDS);
    it->Wold = malloc(sizeof *it->Wold * GS_BLOCK * RAD_BANDS);
    if (!it->H || !it->W || !it->area || !it->D || !it->Wold)
        return -1;
    for (int i = 0; i < n; i++)
        it->area[i] = m->elements[i].area;
    if (radi_fscan_run(n, F, it->area, &sc))
        return -1;
    contraction(it, &sc, rep);
    it->recip = sc.defect <= RAD_RECIPROCITY_TOL;
    radi_fscan_free(&sc);
    memcpy(B, E, sizeof *B * n3); /* B_0 = E */
    for (size_t k = 0; k < n3; k++)
        it->W[k] = it->area[k % (size_t)n] * B[k];
    return 0;
}

rad_status radi_solve_iterate(const rad_mesh *m, const double *F, const double *rho,
                             const double *E, double *B, const rad_solve_options *opt,
                             rad_solve_report *rep, rad_error *err)
{
    const size_t n3 = (size_t)m->nelements * RAD_BANDS;
    const int limit = opt->bounces >= 0 ? opt->bounces : opt->max_iterations;
    double chg[RAD_BANDS] = {0, 0, 0}, change = 0, prev = 0, rate = 0, bound = NAN, stop_on = 0;
    int k;
    iter it;
    rad_status st = RAD_OK;
    if (iter_init(&it, m, F, rho, E, B, opt, rep)) {
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
        goto done;
    }
    for (k = 1; k <= limit; k++) {
        if (it.gs)
            gs_sweep(&it, chg);
        else if (jacobi_sweep(&it, chg)) {
            st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
            goto done;
        }
        change = fmax(chg[0], fmax(chg[1], chg[2]));
        /* asymptotic factor: the ratio of successive changes, while they are
         * well above round-off (below 1e4 eps |B| the ulps of B dominate) */
        if (prev > 0 && change > 0 && change > 1e4 * DBL_EPSILON * radi_max_abs(B, n3))
            rate = change / prev;
        prev = change;
        bound = error_bound(&it, chg, k > 1 ? rate : 0, &stop_on);
        const double goal = opt->tolerance * radi_max_abs(B, n3);
        if (opt->progress && k % 16 == 0 && opt->bounces < 0 && goal > 0) {
            /* digits gained of those asked for */
            const double frac = stop_on > goal ? log(stop_on / goal * opt->tolerance) /
                                                     log(opt->tolerance) : 1;
            if (opt->progress(opt->progress_user, "iterate", fmin(fmax(frac, 0), 1), 1)) {
                st = radi_fail(err, RAD_ERR_INVALID, "interrupted");
                goto done;
            }
        }
        if (opt->bounces < 0 && stop_on <= goal)
            break;
    }
    rep->sweeps = k > limit ? limit : k;
    rep->spectral_radius = rate;
    rep->error_bound = bound / fmax(radi_max_abs(B, n3), DBL_MIN);
    if (opt->bounces < 0 && k > limit) {
        char what[96];
        snprintf(what, sizeof what, isnan(rep->error_bound)
                     ? "no error bound (||diag(rho) F||inf = %.12g >= 1)"
                     : "error bound %.3g relative", isnan(rep->error_bound)
                     ? rep->contraction : rep->error_bound);
        st = radi_fail(err, RAD_ERR_NOCONV,
                      "%s did not converge in %d sweeps: %s, tolerance %g (change %.3g; "
                      "convergence factor per sweep %.6f%s)",
                      it.gs ? "gauss-seidel" : "jacobi", limit, what, opt->tolerance,
                      change / fmax(radi_max_abs(B, n3), DBL_MIN), rate,
                      rate >= 1 - 1e-9 ? ": the system looks singular (rho = 1 in a closed scene?)"
                                       : "; raise `max_iterations` or use `solver` gauss");
    }
done:
    iter_free(&it);
    return st;
}
