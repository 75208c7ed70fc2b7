/* adaptive.c -- progressive refinement with adaptive subdivision.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen, Chen, Wallace & Greenberg, "A Progressive Refinement Approach to
 * Fast Radiosity Image Generation", SIGGRAPH 1988, sections 3.4 and 4:
 * patches shoot, elements receive, and elements are subdivided where the
 * radiosity varies, "after each patch shoots".  The starting mesh's
 * elements are the patches and stay fixed; the elements are the leaves of
 * a quadtree over each of them (adaptnodes.h), split down to
 * opt->max_depth levels by adaptsplit.c.
 *
 *   start  leaves = the starting elements, B = E; per patch P the unshot
 *          radiosity dB_P = E_P and the shot radiosity S_P = 0.
 *   step   shoot the patch P with the largest unshot power A_P |dB_P|
 *          summed over the bands (ties to round-off to the first, as
 *          progressive.c; file order with opt->sort = 0): d = dB_P,
 *          dB_P = 0, S_P += d; every leaf j off P's surface receives
 *              dRad_j = rho_j d F_jP,  B_j += dRad_j,
 *              dB_Q += dRad_j A_j / A_Q  (Q: j's patch)       (1988, eq. 6
 *          with substructuring, section 3.4, as patch grids do in
 *          progressive.c); then subdivide (adaptsplit.c), once every
 *          emitting patch has shot: until then the direct light is only
 *          partly there (a lamp of 4 x 4 patches, one of them shot,
 *          lights the surface under that patch alone), and its
 *          differences, which the finished solution does not have, would
 *          split elements that no later shot can merge back.  The paper's
 *          lamps are one patch each, so there the first shot completes
 *          the direct light and the two rules agree.  On
 *          data/blocker.scene (a lamp of 16 patches) the wait saves a
 *          fifth of the elements for the uniform 16 x 16 mesh's RMS
 *          error (556 against 697, tests/papers/adaptive.sh).
 *   stop   when sum_P A_P |dB_P| <= tolerance x sum A E in every band,
 *          the paper's test; RAD_ERR_NOCONV after opt->max_iterations
 *          shots.
 *
 * The limit is the patch-element solution on the final leaves,
 * B_j = E_j + rho_j sum_P F_jP Bbar_P (adaptsplit.c, eq. 2): what
 * `--patches PxQ` converges to on a uniform mesh, here with elements
 * where the light changes.  Its form factors are always computed on the
 * fly (ffrow.h: the dense fill's kernel and visibility), never stored:
 * the leaves change as the run goes, and a matrix over all the nodes a
 * run might make would be 16/9 of the finest mesh's squared.  So
 * `--adaptive` is `--matrix none` (auto and none are accepted, dense is
 * a usage error).
 *
 * The watcher (radi_solve_adaptive_watch): `radiosity progress --adaptive`
 * follows the run step by step through a callback given the nodes, the
 * leaves and B after each shot and its subdivision (and at step 0), as
 * the race follows the non-adaptive shooter; it may end the run early.
 * The shooting loop is this one in both cases.
 *
 * The report.  The energy balance is computed after convergence from
 * fresh factors on the final leaves, for each patch P and leaf j:
 *     H_j = sum_P F_jP Bbar_P                          (incident radiosity)
 *     emitted = sum_j A_j E_j,  absorbed = sum_j A_j (1 - rho_j) H_j,
 *     escaped = sum_P A_P Bbar_P - sum_j A_j H_j     (leaving the scene),
 * and balance = (emitted - absorbed - escaped) / emitted, which is
 * -sum_j A_j (B_j - E_j - rho_j H_j) / emitted: the residual of (2), zero
 * up to the unshot power when (2) holds (Goral et al. 1984, section 2:
 * emitted = absorbed + escaped).  The residual is max_j |B_j - E_j -
 * rho_j H_j| / max_j E_j over the bands.  Not computed (NaN): rcond, the
 * spectral radius, the error bounds.  No E scaling is done (as
 * solvefree.c does): B is in the user's units throughout, which the trace
 * wants anyway.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adapt/adaptive.h"
#include "adapt/adaptmesh.h"
#include "adapt/adaptstate.h"
#include "solve/solve.h"
#include "util/util.h"

#define NB RAD_BANDS
#define PICK_TIE 1e-12 /* as progressive.c */

void radi_adapt_out_free(rad_adapt_out *o)
{
    rad_mesh_free(&o->mesh);
    free(o->B);
    free(o->Bv);
    free(o->level);
    memset(o, 0, sizeof *o);
}

static double patch_area(const rad_adapt_state *s, int p)
{
    return s->a->mesh.elements[s->a->root[p]].area;
}

static double *dB_of(rad_adapt_state *s, int p, int b)
{
    return &s->dB[(size_t)p + (size_t)b * (size_t)s->np];
}

static void unshot(rad_adapt_state *s, double U[NB])
{
    for (int b = 0; b < NB; b++) {
        U[b] = 0;
        for (int p = 0; p < s->np; p++)
            U[b] += patch_area(s, p) * fabs(*dB_of(s, p, b));
    }
}

static int pick(rad_adapt_state *s, int *next)
{
    if (!s->opt->sort) {
        const int p = *next;
        *next = (p + 1) % s->np;
        return p;
    }
    int best = 0;
    double most = -1;
    for (int p = 0; p < s->np; p++) {
        double w = 0;
        for (int b = 0; b < NB; b++)
            w += patch_area(s, p) * fabs(*dB_of(s, p, b));
        if (w > most * (1 + PICK_TIE)) {
            most = w;
            best = p;
        }
    }
    return best;
}

/* The leaves off surface surf into s->list; their count. */
static int receivers(rad_adapt_state *s, int surf)
{
    int k = 0;
    for (int j = 0; j < s->nn; j++)
        if (s->leaf[j] && s->a->mesh.elements[j].surface != surf)
            s->list[k++] = j;
    return k;
}

/* Patch p shoots all its unshot radiosity; shot = the power, summed. */
static rad_status shoot(rad_adapt_state *s, int p, double *shot)
{
    const rad_adapt_nodes *a = s->a;
    const int r = a->root[p];
    double d[NB];
    *shot = 0;
    for (int b = 0; b < NB; b++) {
        d[b] = *dB_of(s, p, b);
        *dB_of(s, p, b) = 0;
        s->S[(size_t)p + (size_t)b * s->np] += d[b];
        *shot += patch_area(s, p) * d[b];
    }
    const int k = receivers(s, a->mesh.elements[r].surface);
    rad_status st = radi_ffrow_pairs(s->row, r, s->list, k, s->list_f, s->err);
    for (int q = 0; q < k && st == RAD_OK; q++) {
        const int j = s->list[q], Q = a->patch[j];
        const rad_element *el = &a->mesh.elements[j];
        for (int b = 0; b < NB; b++) {
            const double got = el->reflect[b] * d[b] * s->list_f[q];
            *radi_adapt_b(s, j, b) += got;
            *dB_of(s, Q, b) += got * (el->area / patch_area(s, Q));
        }
    }
    return st;
}

static void state_free(rad_adapt_state *s)
{
    radi_ffrow_free(s->row);
    free(s->leaf);
    free(s->B);
    free(s->dB);
    free(s->S);
    free(s->list);
    free(s->list_f);
}

static rad_status state_init(rad_adapt_state *s, const rad_adapt_nodes *a,
                             const rad_ff_options *ff, const rad_solve_options *opt,
                             rad_error *err)
{
    memset(s, 0, sizeof *s);
    s->a = a;
    s->opt = opt;
    s->err = err;
    s->nn = a->mesh.nelements;
    s->np = a->npatches;
    const size_t nn = (size_t)(s->nn ? s->nn : 1), np = (size_t)(s->np ? s->np : 1);
    s->leaf = calloc(nn, 1);
    s->B = calloc(nn * NB, sizeof *s->B);
    s->dB = calloc(np * NB, sizeof *s->dB);
    s->S = calloc(np * NB, sizeof *s->S);
    s->list = malloc(sizeof *s->list * nn);
    s->list_f = malloc(sizeof *s->list_f * nn);
    if (!s->leaf || !s->B || !s->dB || !s->S || !s->list || !s->list_f)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d adaptive elements", s->nn);
    for (int p = 0; p < s->np; p++) {
        const rad_element *el = &a->mesh.elements[a->root[p]];
        s->leaf[a->root[p]] = 1;
        for (int b = 0; b < NB; b++) {
            *radi_adapt_b(s, a->root[p], b) = el->emit[b];
            *dB_of(s, p, b) = el->emit[b];
        }
    }
    return radi_ffrow_create(&s->row, &a->mesh, ff, RAD_OCC_AUTO, 0, 0, err);
}

static int converged(const double U[NB], const double emitted[NB], double tol)
{
    for (int b = 0; b < NB; b++)
        if (!(U[b] <= tol * emitted[b]))
            return 0;
    return 1;
}

/* How far along, 0 to 1: the unshot fraction's logarithm against the
 * tolerance's (as progressive.c reports it). */
static double done_fraction(const double U[NB], const double emitted[NB], double tol)
{
    double f = 0;
    for (int b = 0; b < NB; b++)
        f = fmax(f, emitted[b] > 0 ? U[b] / emitted[b] : 0);
    const double done = f > 0 && f < 1 ? log(f) / log(tol) : f >= 1 ? 0 : 1;
    return fmin(fmax(done, 0), 1);
}

/* Has every emitting patch shot (S != 0)?  Subdivision waits for it. */
static int emitters_have_shot(const rad_adapt_state *s)
{
    for (int p = 0; p < s->np; p++) {
        const rad_element *el = &s->a->mesh.elements[s->a->root[p]];
        const size_t np = (size_t)s->np;
        if ((el->emit[0] > 0 || el->emit[1] > 0 || el->emit[2] > 0) &&
            s->S[p] == 0 && s->S[p + np] == 0 && s->S[p + 2 * np] == 0)
            return 0;
    }
    return 1;
}

typedef struct watcher {
    rad_adapt_watch_fn fn;      /* may be NULL */
    void *user;
} watcher;

/* Show the watcher the state after `step` steps; non-zero: it ends the solve. */
static int watch(const rad_adapt_state *s, const watcher *w, int step, const double U[NB],
                 int done)
{
    if (!w->fn)
        return 0;
    const rad_adapt_view v = {s->a, s->leaf, s->B, step, {U[0], U[1], U[2]}, done};
    return w->fn(w->user, &v);
}

/* Shoot and subdivide until converged (or the watcher has seen enough). */
static rad_status iterate(rad_adapt_state *s, const double emitted[NB], const watcher *w,
                          int *steps)
{
    const rad_solve_options *o = s->opt;
    double U[NB];
    int next = 0;
    rad_status st = RAD_OK;
    unshot(s, U);
    int stop = watch(s, w, 0, U, converged(U, emitted, o->tolerance));
    while (st == RAD_OK && !stop && !converged(U, emitted, o->tolerance)) {
        double shot;
        if (*steps == o->max_iterations)
            return radi_fail(s->err, RAD_ERR_NOCONV,
                            "progressive refinement with adaptive subdivision did not converge "
                            "in %d shooting steps; raise `max_iterations`",
                            o->max_iterations);
        const int p = pick(s, &next);
        st = shoot(s, p, &shot);
        if (st == RAD_OK && emitters_have_shot(s))
            st = radi_adapt_subdivide(s);
        unshot(s, U);
        ++*steps;
        rad_shot row = {*steps, p, shot, U[0] + U[1] + U[2], NAN, NAN, NAN, NAN};
        if (st == RAD_OK && o->on_shot && o->on_shot(o->shot_user, &row))
            st = radi_fail(s->err, RAD_ERR_INVALID, "interrupted");
        if (st == RAD_OK && o->progress && *steps % 64 == 0 &&
            o->progress(o->progress_user, "shoot", done_fraction(U, emitted, o->tolerance), 1))
            st = radi_fail(s->err, RAD_ERR_INVALID, "interrupted");
        if (st == RAD_OK)
            stop = watch(s, w, *steps, U, converged(U, emitted, o->tolerance));
    }
    return st;
}

/* H_j = sum_P F_jP Bbar_P over the leaves (H: nn x NB, zero first). */
static rad_status incident(rad_adapt_state *s, double *H)
{
    const rad_adapt_nodes *a = s->a;
    for (int p = 0; p < s->np; p++) {
        double mean[NB];
        for (int b = 0; b < NB; b++) /* Bbar_P = S_P + dB_P, the invariant (*) */
            mean[b] = s->S[(size_t)p + (size_t)b * s->np] + *dB_of(s, p, b);
        if (mean[0] == 0 && mean[1] == 0 && mean[2] == 0)
            continue;
        const int k = receivers(s, a->mesh.elements[a->root[p]].surface);
        rad_status st = radi_ffrow_pairs(s->row, a->root[p], s->list, k, s->list_f, s->err);
        if (st != RAD_OK)
            return st;
        for (int q = 0; q < k; q++)
            for (int b = 0; b < NB; b++)
                H[(size_t)s->list[q] + (size_t)b * s->nn] += s->list_f[q] * mean[b];
    }
    return RAD_OK;
}

/* The energy balance and residual of the converged system (see above). */
static rad_status balance(rad_adapt_state *s, rad_solve_report *rep)
{
    const rad_adapt_nodes *a = s->a;
    double *H = calloc((size_t)s->nn * NB, sizeof *H);
    if (!H)
        return radi_fail(s->err, RAD_ERR_NOMEM, "out of memory for the energy balance");
    rad_status st = incident(s, H);
    double rmax = 0, emax = 0;
    for (int b = 0; b < NB && st == RAD_OK; b++) {
        double absorbed = 0, leaving = 0, arriving = 0;
        for (int j = 0; j < s->nn; j++) {
            if (!s->leaf[j])
                continue;
            const rad_element *el = &a->mesh.elements[j];
            const double h = H[(size_t)j + (size_t)b * s->nn], B = *radi_adapt_b(s, j, b);
            absorbed += el->area * (1 - el->reflect[b]) * h;
            arriving += el->area * h;
            leaving += el->area * B;
            rmax = fmax(rmax, fabs(B - el->emit[b] - el->reflect[b] * h));
            emax = fmax(emax, fabs(el->emit[b]));
        }
        rep->absorbed[b] = absorbed;
        rep->escaped[b] = leaving - arriving;
        rep->balance[b] = (rep->emitted[b] - absorbed - rep->escaped[b]) / rep->emitted[b];
    }
    rep->residual = emax > 0 ? rmax / emax : NAN;
    free(H);
    return st;
}

static void report_init(rad_solve_report *rep, const rad_adapt_nodes *a)
{
    radi_report_init_shooting(rep);
    for (int b = 0; b < NB; b++) {
        for (int p = 0; p < a->npatches; p++)
            rep->emitted[b] += a->mesh.elements[a->root[p]].area *
                               fabs(a->mesh.elements[a->root[p]].emit[b]);
    }
}

rad_status radi_solve_adaptive(const rad_mesh *m, const rad_ff_options *ff,
                              const rad_solve_options *opt, rad_adapt_out *out,
                              rad_solve_report *rep, rad_ff_stats *ffst, rad_error *err)
{
    return radi_solve_adaptive_watch(m, ff, opt, NULL, NULL, out, rep, ffst, err);
}

rad_status radi_solve_adaptive_watch(const rad_mesh *m, const rad_ff_options *ff,
                                    const rad_solve_options *opt, rad_adapt_watch_fn watch_fn,
                                    void *watch_user, rad_adapt_out *out,
                                    rad_solve_report *rep, rad_ff_stats *ffst, rad_error *err)
{
    rad_adapt_nodes a;
    rad_adapt_state s;
    rad_solve_report local;
    const watcher w = {watch_fn, watch_user};
    int steps = 0;
    if (out)
        memset(out, 0, sizeof *out);
    memset(&s, 0, sizeof s);
    if (!rep)
        rep = &local;
    if (!(opt->tolerance > 0) || opt->max_iterations < 1 || !(opt->subdivide_threshold >= 0))
        return radi_fail(err, RAD_ERR_INVALID, "tolerance must be positive, max-iterations at "
                        "least 1 and the subdivision threshold not negative");
    rad_status st = radi_adapt_nodes_build(&a, m, opt->max_depth, err);
    if (st != RAD_OK)
        return st;
    report_init(rep, &a);
    st = state_init(&s, &a, ff, opt, err);
    if (st == RAD_OK)
        st = iterate(&s, rep->emitted, &w, &steps);
    rep->sweeps = steps;
    if (st == RAD_OK && out)
        st = balance(&s, rep);
    if (s.row && ffst)
        radi_ffrow_stats(s.row, ffst, &rep->row_sum_min, &rep->row_sum_max);
    if (st == RAD_OK && out)
        st = radi_adapt_leaf_mesh(&a, s.leaf, s.B, &out->mesh, &out->B, &out->Bv, &out->level,
                                 err);
    if (out)
        out->splits = s.splits;
    if (st == RAD_OK && opt->progress)
        opt->progress(opt->progress_user, "shoot", 1, 1);
    state_free(&s);
    radi_adapt_nodes_free(&a);
    return st;
}
