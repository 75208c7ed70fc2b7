/* cg.c -- conjugate gradients on the symmetric form, three bands per pass.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The symmetric form of band b (cholesky.c says why it is symmetric and
 * positive definite when q_b = ||diag(rho_b) F||_inf < 1):
 *
 *     K y = c,   K = D^-1 M D,   M = I - diag(rho) F,   D = diag(sqrt(rho_i / A_i)),
 *
 * on the elements with rho_i > 0 (the others keep B_i = E_i), y = D^-1 B.
 * K is applied without being formed: K p = D^-1 (D p - diag(rho) F (D p)),
 * one product F X for the three bands (fpass.c), so an iteration reads F
 * once.  The three bands run as three independent conjugate gradient
 * recurrences (Hestenes & Stiefel 1952; Golub & Van Loan, Matrix
 * Computations, 4th ed., algorithm 11.3.2) sharing that product:
 *
 *     alpha = r.r / p.Kp,  y += alpha p,  r -= alpha Kp,
 *     beta = r'.r' / r.r,  p = r' + beta p,
 *
 * kept in B's variables: y += alpha p is B += alpha D p.  The start is
 * B = E, whose residual is diag(rho) F E.
 *
 * Stopping on a bound of the true error: the residual of the original
 * system is r_M = E - M B = D r, and ||M^-1||_inf <= 1 / (1 - q) (Neumann
 * series, q = ||diag(rho) F||_inf < 1; Higham 2002, Accuracy and
 * Stability of Numerical Algorithms, lemma 6.8 with ||.||_inf), so
 *
 *     ||B - B*||_inf <= ||D r||_inf / (1 - q)          (per band).
 *
 * The recurrence's r drifts from the true residual by round-off, so when
 * the recurrence says the bound is met with a factor 2 to spare, the true
 * residual is formed (one more pass) and decides; if it is not met the
 * recurrences restart from it.  The bound reported is the true one.
 *
 * Where the form does not apply the whole solve goes to cholesky.c (which
 * goes on to LU where it must), and the report's fallback says why: F not
 * reciprocal (K would not be symmetric), q >= 1 (no bound, and K need not
 * be positive definite), or a step that finds p.Kp <= 0 (K is not).
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

typedef struct cg {
    int n;
    const double *F, *rho, *E;
    double *B;
    double *v;                  /* n x 3: sqrt(rho / A), 0 where rho = 0 */
    double *r, *p, *x, *H;      /* n x 3: residual of K, direction, D p, F D p */
    double rr[RAD_BANDS], q[RAD_BANDS];
    int live[RAD_BANDS];        /* band still iterating */
} cg;

static void cg_free(cg *c)
{
    free(c->v);
    free(c->r);
    free(c->p);
    free(c->x);
    free(c->H);
}

/* Allocate; scan F.  0, 1 when the form does not apply (why in the
 * report), -1 out of memory. */
static int cg_init(cg *c, const rad_mesh *m, const double *F, const double *rho,
                   const double *E, double *B, rad_solve_report *rep)
{
    const int n = m->nelements;
    const size_t n3 = (size_t)n * RAD_BANDS;
    char why[200];
    rad_fscan sc;
    *c = (cg){.n = n, .F = F, .rho = rho, .E = E, .B = B};
    c->v = malloc(sizeof *c->v * (n3 + 1));
    c->r = malloc(sizeof *c->r * (n3 + 1));
    c->p = malloc(sizeof *c->p * (n3 + 1));
    c->x = malloc(sizeof *c->x * (n3 + 1));
    c->H = malloc(sizeof *c->H * (n3 + 1));
    if (!c->v || !c->r || !c->p || !c->x || !c->H)
        return -1;
    for (size_t k = 0; k < n3; k++) /* areas into v for the scan */
        c->v[k] = m->elements[k % (size_t)n].area;
    if (radi_fscan_run(n, F, c->v, &sc))
        return -1;
    rep->contraction = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        c->q[b] = 0;
        for (int i = 0; i < n; i++)
            c->q[b] = fmax(c->q[b], rho[(size_t)i + (size_t)b * n] * (sc.lower[i] + sc.upper[i]));
        rep->contraction = fmax(rep->contraction, c->q[b]);
    }
    int r = 0;
    if (sc.defect > RAD_RECIPROCITY_TOL) {
        snprintf(why, sizeof why, "cg: F is not reciprocal (A_i F_ij and A_j F_ji differ by "
                 "%.3g relative at i = %d, j = %d): solved by cholesky", sc.defect, sc.di, sc.dj);
        r = 1;
    } else if (!(rep->contraction < 1)) {
        snprintf(why, sizeof why, "cg: ||diag(rho) F||_inf = %.6g >= 1 bounds no error (rho = 1 "
                 "in a closed scene?): solved by cholesky", rep->contraction);
        r = 1;
    }
    if (r)
        radi_report_fallback(rep, why);
    radi_fscan_free(&sc);
    for (size_t k = 0; k < n3; k++)
        c->v[k] = rho[k] > 0 ? sqrt(rho[k] / m->elements[k % (size_t)n].area) : 0;
    return r;
}

/* r = D^-1 (E - B + rho F B), p = r, from the true residual (one pass);
 * returns the bound max_b ||E - M B||_inf / (1 - q_b), or -1. */
static double cg_restart(cg *c)
{
    const int n = c->n;
    double bound = 0;
    if (radi_fpass_mul(n, c->F, c->B, c->H))
        return -1;
    for (int b = 0; b < RAD_BANDS; b++) {
        double rr = 0, rm = 0;
        for (size_t k = (size_t)b * n; k < (size_t)(b + 1) * n; k++) {
            const double res = c->E[k] - c->B[k] + c->rho[k] * c->H[k];
            rm = fmax(rm, fabs(res));
            c->r[k] = c->p[k] = c->v[k] > 0 ? res / c->v[k] : 0;
            rr += c->r[k] * c->r[k];
        }
        c->rr[b] = rr;
        c->live[b] = rr > 0;
        bound = fmax(bound, rm / (1 - c->q[b]));
    }
    return bound;
}

/* One step for the live bands.  Returns the recurrence's bound, -1 out of
 * memory, -2 when p.Kp <= 0 (K not positive definite). */
static double cg_step(cg *c)
{
    const int n = c->n;
    const size_t n3 = (size_t)n * RAD_BANDS;
    double bound = 0;
    for (size_t k = 0; k < n3; k++)
        c->x[k] = c->v[k] * c->p[k];
    if (radi_fpass_mul(n, c->F, c->x, c->H))
        return -1;
    for (int b = 0; b < RAD_BANDS; b++) {
        const size_t k0 = (size_t)b * n, k1 = k0 + (size_t)n;
        if (!c->live[b])
            continue;
        double pkp = 0, rr = 0, rm = 0;
        for (size_t k = k0; k < k1; k++) /* H := K p */
            if (c->v[k] > 0) {
                c->H[k] = (c->x[k] - c->rho[k] * c->H[k]) / c->v[k];
                pkp += c->p[k] * c->H[k];
            }
        if (!(pkp > 0))
            return -2;
        const double alpha = c->rr[b] / pkp;
        for (size_t k = k0; k < k1; k++)
            if (c->v[k] > 0) {
                c->B[k] += alpha * c->x[k];
                c->r[k] -= alpha * c->H[k];
                rr += c->r[k] * c->r[k];
                rm = fmax(rm, fabs(c->v[k] * c->r[k]));
            }
        const double beta = rr / c->rr[b];
        for (size_t k = k0; k < k1; k++)
            c->p[k] = c->r[k] + beta * c->p[k];
        c->rr[b] = rr;
        c->live[b] = rr > 0;
        bound = fmax(bound, rm / (1 - c->q[b]));
    }
    return bound;
}

enum { CG_OK, CG_NOCONV, CG_NOMEM, CG_NOTPD, CG_STOPPED };

/* Iterate until the true bound meets the goal. */
static int cg_run(cg *c, const rad_solve_options *opt, rad_solve_report *rep)
{
    const size_t n3 = (size_t)c->n * RAD_BANDS;
    double bound = cg_restart(c);
    int k = 0;
    while (bound >= 0) {
        const double goal = opt->tolerance * radi_max_abs(c->B, n3);
        rep->error_bound = bound / fmax(radi_max_abs(c->B, n3), DBL_MIN);
        if (bound <= goal)
            break;
        if (k == opt->max_iterations)
            return rep->sweeps = k, CG_NOCONV;
        double est = cg_step(c);
        k++;
        if (est < 0)
            return rep->sweeps = k, est == -2 ? CG_NOTPD : CG_NOMEM;
        if (opt->progress && k % 4 == 0 && goal > 0 &&
            opt->progress(opt->progress_user, "iterate",
                          fmin(fmax(log(fmax(est / goal, 1) * opt->tolerance) /
                                        log(opt->tolerance), 0), 1), 1))
            return rep->sweeps = k, CG_STOPPED;
        bound = est <= goal / 2 ? cg_restart(c) : est; /* the true residual decides */
    }
    rep->sweeps = k;
    return bound < 0 ? CG_NOMEM : CG_OK;
}

rad_status radi_solve_cg(const rad_mesh *m, const double *F, const double *rho,
                        const double *E, double *B, const rad_solve_options *opt,
                        rad_solve_report *rep, rad_error *err)
{
    cg c;
    rad_status st = RAD_OK;
    memcpy(B, E, sizeof *B * (size_t)m->nelements * RAD_BANDS); /* B_0 = E */
    const int init = cg_init(&c, m, F, rho, E, B, rep);
    const int r = init == 0 ? cg_run(&c, opt, rep) : init < 0 ? CG_NOMEM : CG_NOTPD;
    cg_free(&c);
    if (r == CG_NOTPD) { /* the form does not apply: cholesky, or LU */
        if (init == 0)
            radi_report_fallback(rep, "cg: a step found p.Kp <= 0, the symmetric form is not "
                                     "positive definite: solved by cholesky");
        rep->error_bound = NAN;
        return radi_solve_cholesky(m, F, rho, E, B, opt, rep, err);
    }
    if (r == CG_NOMEM)
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    else if (r == CG_STOPPED)
        st = radi_fail(err, RAD_ERR_INVALID, "interrupted");
    else if (r == CG_NOCONV)
        st = radi_fail(err, RAD_ERR_NOCONV,
                      "cg did not converge in %d iterations: error bound %.3g relative > "
                      "tolerance %g; raise `max_iterations` or use `solver` cholesky",
                      rep->sweeps, rep->error_bound, opt->tolerance);
    return st;
}
