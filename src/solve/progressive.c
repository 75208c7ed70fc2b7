/* progressive.c -- progressive refinement: shooting, sorting, the ambient term.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen, Chen, Wallace & Greenberg, "A Progressive Refinement Approach to
 * Fast Radiosity Image Generation", SIGGRAPH 1988.  Per colour band, with
 * the unshot radiosity dB:
 *
 *   start  B = E, dB = E.
 *   step   pick the shooter i with the largest unshot power A_i dB_i,
 *          summed over the bands (sorting; ties to round-off go to the
 *          first in file order), or the next one in file order, cycling
 *          (opt->sort = 0); for every element j
 *              dRad_j = rho_j dB_i F_ij A_i / A_j,   B_j += dRad_j,
 *              dB_j += dRad_j;
 *          then dB_i = 0.  By reciprocity (A_i F_ij = A_j F_ji) the factor
 *          F_ij A_i / A_j is F_ji, and column i of the column-major F holds
 *          F_ji for all j contiguously: a shot streams one column.  F_ji is
 *          also what the system (I - diag(rho) F) B = E asks for when F is
 *          reciprocal only to round-off (or not at all): B_j gathers
 *          rho_j F_ji B_i from every i, so shooting uses F_ji as it is.
 *   stop   when the unshot power sum_i A_i |dB_i| is at most tolerance
 *          times the emitted power sum_i A_i E_i, in every band.  (|dB|:
 *          the negative form factors the classic rule may produce must not
 *          hide unshot power.)  After opt->max_iterations steps without
 *          that: RAD_ERR_NOCONV.
 *
 * The limit is the solution of B = E + diag(rho) F B: every radiosity an
 * element ever receives is shot on once, so the sum is the Neumann series.
 *
 * Ambient term (Cohen et al. 1988, eq. 9-13), per band, for display and
 * error curves only: it is never shot and never changes B.
 *     F*_j = A_j / sum_k A_k                                       (eq. 9)
 *     rho_ave = sum_j rho_j A_j / sum_j A_j                        (eq. 10)
 *     R = 1 / (1 - rho_ave)                                        (eq. 11)
 *     Ambient = R sum_j dB_j F*_j                                  (eq. 12)
 *     B'_i = B_i + rho_i Ambient                                   (eq. 13)
 * (R = 0 when rho_ave = 1: a scene that reflects everything has no finite
 * ambient estimate.)
 *
 * Patches and elements (section 3.4), opt->patches: each scene surface P
 * shoots as one patch.  Its unshot power is its elements', A_P dB_P =
 * sum_{i in P} A_i dB_i; its unshot radiosity dB_P is their area-weighted
 * mean, as its radiosity is the area-weighted mean of its elements'.  It
 * shoots to every element j
 *     dRad_j = rho_j sum_{i in P} dB_i F_ij A_i / A_j,
 * which is the paper's rho_j dB_P F_Pj A_P / A_j with the patch-to-element
 * factor F_Pj = sum_{i in P} A_i F_ij / A_P when dB is uniform over P.
 * Keeping each element's own dB costs the same per shot and makes the limit
 * the element solution itself (the same B as gauss), not the substructured
 * approximation in which every element sees only patch means.
 *
 * Patch grids (section 3.4, substructuring after Cohen, Greenberg, Immel
 * & Brock 1986), opt->patch_p x patch_q (patchgrid.h): each patch P keeps
 * one unshot radiosity dB_P and shoots it to every element j,
 *     dRad_j = rho_j dB_P F_jP,   F_jP = sum_{i in P} F_ji  (additivity),
 * and what element j receives goes to its own patch Q area-weighted,
 * dB_Q += dRad_j A_j / A_Q; the unshot power is sum_P A_P |dB_P|.  Here a
 * shot costs n pairs (one per receiver, against the patch's outline, when
 * matrix-free), not |P| n, which is what makes a scene of 10^5 elements
 * converge in minutes; the price is the limit: B_j = E_j + rho_j sum_P
 * F_jP Bbar_P with Bbar_P the area mean of B over P, the patch-element
 * solution, not the element solution gauss gives (the two meet when every
 * patch is one element).
 *
 * Where the columns come from (rad_shoot_source, progressive.h): the
 * dense F, or rad_ffrow (ffrow.h) computing column i when element i shoots
 * (F_jP when patch P shoots) and forgetting it: the paper's O(n) storage.
 * The computed values are the dense fill's bit for bit, so the steps and
 * B are the same either way.
 *
 * Error (eq. 14, rmserror.c): sqrt(sum_i A_i (B_i - B_conv_i)^2 / sum_i
 * A_i), the area-weighted RMS difference from the converged solution of
 * the radiosity averaged over the three bands; with the ambient term B'
 * replaces B.  The mean of the three per-band values goes beside it
 * (rms_bands).
 *
 * The trace: when opt->on_shot is set it receives one rad_shot per step:
 * step, shooter (element or patch), shot (power shot, summed over the
 * bands), unshot (unshot power left), rms and rms_ambient (and their
 * per-band means rms_bands, rms_ambient_bands) against
 * opt->reference, or against a gauss solve of the mesh's own reflectances
 * and emissions when that is NULL (NaN without a matrix to solve).  The solver writes nothing itself: the
 * caller keeps or prints the rows (the command writes them as a TSV file,
 * also when the iteration gives up: they say what happened).
 *
 * The race of figure 7 (progressive.h) runs the gathering method of
 * Gauss-Seidel, one element row per step, B_i <- E_i + rho_i sum_j F_ij B_j
 * for i = step mod n, beside shooting in file order, sorted shooting, and
 * sorted shooting shown with the ambient term; the command draws the four
 * error curves through the plotting module (plotxy.c).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


#include "fill/fill.h"
#include "mesh/mesh.h"
#include "solve/progressive.h"
#include "solve/solvers.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/solve.h"
#include "compare/compare.h"
#include "util/util.h"

#define NB RAD_BANDS

/* ---- small helpers ------------------------------------------------------- */

static double *element_areas(const rad_mesh *m)
{
    double *area = malloc(sizeof *area * (size_t)(m->nelements ? m->nelements : 1));
    if (area)
        for (int i = 0; i < m->nelements; i++)
            area[i] = m->elements[i].area;
    return area;
}

static double sum(const double *x, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++)
        s += x[i];
    return s;
}

static double max_diff(const double *a, const double *b, size_t n)
{
    double d = 0;
    for (size_t k = 0; k < n; k++)
        d = fmax(d, fabs(a[k] - b[k]));
    return d;
}

/* ---- the shooting state -------------------------------------------------- */

typedef struct shooter {
    int n;                      /* elements */
    int nshooters;              /* n, or the number of patches */
    const int *first;           /* patches: shooter s owns elements
                                   [first[s], first[s+1]); NULL: s is element s */
    const double *F;            /* the dense matrix, or NULL: columns from row */
    rad_ffrow *row;             /* matrix-free: each column computed per shot */
    const rad_patch_grid *grid; /* substructured patches, or NULL */
    const double *rho, *area;
    int sort;                   /* largest unshot power first */
    int next;                   /* file order: the next shooter */
    double *B;                  /* n x NB, the caller's */
    double *dB;                 /* n x NB unshot radiosity (np x NB with a grid) */
    double *saved;              /* a patch's unshot radiosity while it shoots */
    double *col;                /* n: a computed column */
    rad_error *err;             /* where a failed column says why */
} shooter;

static void shooter_range(const shooter *sh, int s, int *lo, int *hi)
{
    *lo = sh->first ? sh->first[s] : s;
    *hi = sh->first ? sh->first[s + 1] : s + 1;
}

static void shooter_free(shooter *sh)
{
    free(sh->dB);
    free(sh->saved);
    free(sh->col);
    sh->dB = sh->saved = sh->col = NULL;
}

/* Rows of the unshot radiosity: elements, or the grid's patches. */
static size_t shooter_rows(const shooter *sh)
{
    return sh->grid ? (size_t)sh->grid->npatches : (size_t)sh->n;
}

/* dB of a grid patch: the area-weighted mean of its elements' E. */
static void grid_init(shooter *sh, const double *E)
{
    const rad_patch_grid *g = sh->grid;
    const size_t np = (size_t)g->npatches;
    for (int b = 0; b < NB; b++)
        for (size_t p = 0; p < np; p++) {
            double s = 0;
            for (int k = g->first[p]; k < g->first[p + 1]; k++) {
                const int i = g->member[k];
                s += sh->area[i] * E[(size_t)i + (size_t)b * sh->n];
            }
            sh->dB[p + b * np] = g->area[p] > 0 ? s / g->area[p] : 0;
        }
}

/* B = E, dB = E (per patch with a grid). */
static rad_status shooter_init(shooter *sh, const rad_mesh *m, const rad_shoot_source *src,
                               const rad_patch_grid *grid, const double *rho, const double *E, const double *area,
                               int patches, int sort, double *B, rad_error *err)
{
    const int n = m->nelements;
    const size_t n3 = (size_t)n * NB;
    int widest = 1;
    memset(sh, 0, sizeof *sh);
    sh->n = n;
    sh->grid = grid;
    sh->nshooters = sh->grid ? sh->grid->npatches : patches ? m->nsurfaces : n;
    sh->first = !sh->grid && patches ? m->surface_first : NULL;
    sh->F = src->F;
    sh->row = src->row;
    sh->rho = rho;
    sh->area = area;
    sh->sort = sort;
    sh->B = B;
    sh->err = err;
    for (int s = 0; s < sh->nshooters && !sh->grid; s++) {
        int lo, hi;
        shooter_range(sh, s, &lo, &hi);
        widest = hi - lo > widest ? hi - lo : widest;
    }
    const size_t rows = shooter_rows(sh) * NB;
    sh->dB = malloc(sizeof *sh->dB * (rows ? rows : 1));
    sh->saved = malloc(sizeof *sh->saved * (size_t)widest * NB);
    sh->col = !sh->F || sh->grid ? malloc(sizeof *sh->col * (size_t)(n ? n : 1)) : NULL;
    if (!sh->dB || !sh->saved || (!sh->col && (!sh->F || sh->grid))) {
        shooter_free(sh);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for progressive refinement");
    }
    memcpy(B, E, sizeof *B * n3);
    if (sh->grid)
        grid_init(sh, E);
    else
        memcpy(sh->dB, E, sizeof *sh->dB * n3);
    return RAD_OK;
}

/* Unshot power of shooter s, summed over the bands. */
static double shooter_power(const shooter *sh, int s)
{
    int lo, hi;
    double p = 0;
    if (sh->grid) {
        const size_t np = (size_t)sh->grid->npatches;
        for (int b = 0; b < NB; b++)
            p += sh->grid->area[s] * fabs(sh->dB[(size_t)s + b * np]);
        return p;
    }
    shooter_range(sh, s, &lo, &hi);
    for (int i = lo; i < hi; i++)
        for (int b = 0; b < NB; b++)
            p += sh->area[i] * fabs(sh->dB[(size_t)i + (size_t)b * sh->n]);
    return p;
}

/* The next shooter: the largest unshot power, or file order.  Powers within
 * PICK_TIE of each other are ties (equal elements of one light differ only
 * by round-off in their areas) and go to the first in file order, so that
 * the order does not depend on the last bits of the areas. */
#define PICK_TIE 1e-12

static int shooter_pick(shooter *sh)
{
    if (!sh->sort) {
        int s = sh->next;
        sh->next = (s + 1) % sh->nshooters;
        return s;
    }
    int best = 0;
    double most = -1;
    for (int s = 0; s < sh->nshooters; s++) {
        double p = shooter_power(sh, s);
        if (p > most * (1 + PICK_TIE)) {
            most = p;
            best = s;
        }
    }
    return best;
}

/* Column i of F, F_ji for every j: the matrix's, or computed now. */
static const double *shooter_column(shooter *sh, int i, rad_status *st)
{
    if (sh->F)
        return sh->F + (size_t)i * sh->n;
    *st = radi_ffrow_column(sh->row, i, sh->col, NULL, sh->err);
    return sh->col;
}

/* Element i shoots d (band b) through col = F_.i: dRad_j = rho_j d F_ji. */
static void shoot_element(shooter *sh, const double *col, int b, double d)
{
    const size_t n = (size_t)sh->n;
    double *B = sh->B + b * n, *dB = sh->dB + b * n;
    const double *rho = sh->rho + b * n;
    for (size_t j = 0; j < n; j++) {
        double r = rho[j] * d * col[j];
        B[j] += r;
        dB[j] += r;
    }
}

/* Patch p's factors F_jP = sum_{i in P} F_ji: the sum of its elements'
 * columns of the matrix (additivity over the receiving area), or the
 * patch outline integrated directly (ffrow.h). */
static const double *patch_column(shooter *sh, int p, rad_status *st)
{
    const rad_patch_grid *g = sh->grid;
    const size_t n = (size_t)sh->n;
    if (!sh->F) {
        *st = radi_ffrow_patch(sh->row, p, sh->col, sh->err);
        return sh->col;
    }
    memset(sh->col, 0, sizeof *sh->col * n);
    for (int k = g->first[p]; k < g->first[p + 1]; k++) {
        const double *c = sh->F + (size_t)g->member[k] * n;
        for (size_t j = 0; j < n; j++)
            sh->col[j] += c[j];
    }
    return sh->col;
}

/* Substructuring (Cohen et al. 1988, section 3.4): patch p shoots its one
 * unshot radiosity d to the elements, dRad_j = rho_j d F_jP, and each
 * element's share goes to its own patch's unshot radiosity, area-weighted:
 * dB_Q += dRad_j A_j / A_Q. */
static rad_status grid_shoot(shooter *sh, int p, double shot[NB])
{
    const rad_patch_grid *g = sh->grid;
    const size_t n = (size_t)sh->n, np = (size_t)g->npatches;
    double d[NB];
    rad_status st = RAD_OK;
    for (int b = 0; b < NB; b++) {
        d[b] = sh->dB[(size_t)p + b * np];
        sh->dB[(size_t)p + b * np] = 0;
        shot[b] = g->area[p] * d[b];
    }
    const double *col = patch_column(sh, p, &st);
    if (st != RAD_OK)
        return st;
    for (int b = 0; b < NB; b++) {
        double *B = sh->B + b * n, *dB = sh->dB + b * np;
        const double *rho = sh->rho + b * n;
        for (size_t j = 0; j < n && d[b] != 0; j++) {
            const double r = rho[j] * d[b] * col[j];
            const int q = g->patch_of[j];
            B[j] += r;
            dB[q] += r * (sh->area[j] / g->area[q]);
        }
    }
    return RAD_OK;
}

/* Shooter s shoots all its unshot radiosity; shot[b] = the power shot. */
static rad_status shooter_shoot(shooter *sh, int s, double shot[NB])
{
    const size_t n = (size_t)sh->n;
    int lo, hi;
    rad_status st = RAD_OK;
    if (sh->grid)
        return grid_shoot(sh, s, shot);
    shooter_range(sh, s, &lo, &hi);
    const size_t w = (size_t)(hi - lo);
    for (int b = 0; b < NB; b++) /* take it first: a patch may light itself */
        for (int i = lo; i < hi; i++) {
            double *d = &sh->dB[(size_t)i + b * n];
            sh->saved[(size_t)(i - lo) + b * w] = *d;
            *d = 0;
        }
    for (int b = 0; b < NB; b++)
        shot[b] = 0;
    for (int i = lo; i < hi && st == RAD_OK; i++) {
        const double *d = &sh->saved[(size_t)(i - lo)];
        if (d[0] == 0 && d[w] == 0 && d[2 * w] == 0)
            continue;
        const double *col = shooter_column(sh, i, &st);
        for (int b = 0; b < NB && st == RAD_OK; b++) {
            if (d[b * w] == 0)
                continue;
            shot[b] += sh->area[i] * d[b * w];
            shoot_element(sh, col, b, d[b * w]);
        }
    }
    return st;
}

/* U[b] = sum_i A_i |dB_i| (sum_P A_P |dB_P| with a grid). */
static void unshot_power(const shooter *sh, double U[NB])
{
    const size_t rows = shooter_rows(sh);
    const double *A = sh->grid ? sh->grid->area : sh->area;
    for (int b = 0; b < NB; b++) {
        const double *dB = sh->dB + (size_t)b * rows;
        U[b] = 0;
        for (size_t i = 0; i < rows; i++)
            U[b] += A[i] * fabs(dB[i]);
    }
}

/* ---- the ambient term and the error -------------------------------------- */

typedef struct ambient {
    double total_area;          /* sum A */
    double R[NB];               /* 1 / (1 - rho_ave), eq. 10-11 */
} ambient;

static ambient ambient_init(int n, const double *area, const double *rho)
{
    ambient a;
    a.total_area = sum(area, n);
    for (int b = 0; b < NB; b++) {
        double s = 0;
        for (int i = 0; i < n; i++)
            s += rho[(size_t)i + (size_t)b * n] * area[i];
        double ave = a.total_area > 0 ? s / a.total_area : 0;
        a.R[b] = ave < 1 ? 1 / (1 - ave) : 0;
    }
    return a;
}

/* Ambient = R sum_j dB_j F*_j = R U / sum A (eq. 9, 12), U the unshot power. */
static void ambient_value(const ambient *a, const double U[NB], double amb[NB])
{
    for (int b = 0; b < NB; b++)
        amb[b] = a->total_area > 0 ? a->R[b] * U[b] / a->total_area : 0;
}

/* B' = B + rho Ambient (eq. 13). */
static void ambient_display(int n, const double *B, const double *rho, const double amb[NB],
                            double *out)
{
    for (int b = 0; b < NB; b++)
        for (int i = 0; i < n; i++) {
            size_t k = (size_t)i + (size_t)b * n;
            out[k] = B[k] + rho[k] * amb[b];
        }
}

/* ---- the trace ----------------------------------------------------------- */

/* The per-step rows handed to opt->on_shot, and their reference: the
 * caller's (rad_solve_progressive solves for it when it has F), or none,
 * and then the rows' RMS error is NaN. */
typedef struct trace {
    int on;
    const double *Bref;
} trace;

static void trace_open(trace *tr, const rad_solve_options *opt)
{
    memset(tr, 0, sizeof *tr);
    tr->on = opt->on_shot != NULL;
    tr->Bref = tr->on ? opt->reference : NULL;
}

static void trace_close(trace *tr)
{
    memset(tr, 0, sizeof *tr);
}

/* ---- the solver ---------------------------------------------------------- */

static int converged(const double U[NB], const double emitted[NB], double tolerance)
{
    for (int b = 0; b < NB; b++)
        if (!(U[b] <= tolerance * emitted[b]))
            return 0;
    return 1;
}

static double unshot_fraction(const double U[NB], const double emitted[NB])
{
    double f = 0;
    for (int b = 0; b < NB; b++)
        f = fmax(f, emitted[b] > 0 ? U[b] / emitted[b] : U[b] > 0 ? HUGE_VAL : 0);
    return f;
}

/* Everything one run of the solver works with. */
typedef struct run {
    const rad_mesh *m;
    const double *rho;
    const rad_solve_options *opt;
    shooter sh;
    rad_patch_grid grid;        /* opt->patch_p x patch_q, or npatches 0 */
    trace tr;
    ambient amb;
    double emitted[NB];
    double U[NB];
    double *area;
} run;

/* The area-weighted RMS error of B (with the ambient amb, or not)
 * against the trace's reference (eq. 14, or its per-band mean with
 * bands); NaN without one. */
static double run_rms(const run *r, const double *amb, int bands)
{
    if (!r->tr.Bref)
        return NAN;
    const rad_rms_input in = {r->sh.n, r->area, r->amb.total_area, r->rho, amb, r->sh.B,
                              r->tr.Bref};
    return bands ? radi_rms_bands(&in) : radi_rms_eq14(&in);
}

/* One shooting step and its trace row: RAD_OK, or the failure of a
 * computed column; *stop non-zero when the caller's on_shot asks to stop. */
static rad_status run_step(run *r, int step, int *stop)
{
    double shot[NB], a[NB];
    int s = shooter_pick(&r->sh);
    rad_status st = shooter_shoot(&r->sh, s, shot);
    *stop = 0;
    if (st != RAD_OK)
        return st;
    unshot_power(&r->sh, r->U);
    if (!r->tr.on)
        return RAD_OK;
    ambient_value(&r->amb, r->U, a);
    rad_shot row = {step, s, shot[0] + shot[1] + shot[2], r->U[0] + r->U[1] + r->U[2],
                    run_rms(r, NULL, 0), run_rms(r, a, 0), run_rms(r, NULL, 1),
                    run_rms(r, a, 1)};
    *stop = r->opt->on_shot(r->opt->shot_user, &row);
    return RAD_OK;
}

/* Report progress; non-zero when the caller asks to stop. */
static int run_progress(const run *r, int step)
{
    const rad_solve_options *o = r->opt;
    if (!o->progress || step % 64 != 0)
        return 0;
    double f = unshot_fraction(r->U, r->emitted);
    double done = f > 0 && f < 1 ? log(f) / log(o->tolerance) : 1;
    return o->progress(o->progress_user, "shoot", fmin(fmax(done, 0), 1), 1);
}

static rad_status no_convergence(const run *r, double at_half, rad_error *err)
{
    const double f = unshot_fraction(r->U, r->emitted);
    const double now = r->U[0] + r->U[1] + r->U[2];
    return radi_fail(err, RAD_ERR_NOCONV,
                    "progressive refinement did not converge in %d shooting steps: unshot "
                    "power %.3g of the emitted > tolerance %g%s",
                    r->opt->max_iterations, f, r->opt->tolerance,
                    r->opt->max_iterations >= 2 && now >= 0.999 * at_half
                        ? ": the unshot power hardly decreases, the system looks singular "
                          "(rho = 1 in a closed scene?)"
                        : "; raise `max_iterations` or use `solver` gauss");
}

static void run_free(run *r)
{
    trace_close(&r->tr);
    shooter_free(&r->sh);
    radi_patch_grid_free(&r->grid);
    free(r->area);
}

/* Areas, the ambient's constants, the emitted power and the patch grid. */
static rad_status run_init(run *r, const rad_mesh *m, const double *rho, const double *E,
                           const rad_solve_options *opt, rad_error *err)
{
    const int n = m->nelements;
    memset(r, 0, sizeof *r);
    r->m = m;
    r->rho = rho;
    r->opt = opt;
    if (!(r->area = element_areas(m)))
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    r->amb = ambient_init(n, r->area, rho);
    for (int b = 0; b < NB; b++) {
        r->emitted[b] = 0;
        for (int i = 0; i < n; i++)
            r->emitted[b] += r->area[i] * fabs(E[(size_t)i + (size_t)b * n]);
        if (!isfinite(r->emitted[b])) /* U <= tol * inf would stop at once */
            return radi_fail(err, RAD_ERR_INVALID,
                            "the emitted power sum A_i E_i exceeds the largest double (%.3g): "
                            "progressive refinement with a trace measures power in the "
                            "scene's units; scale the emission or the scene down",
                            DBL_MAX);
    }
    if (opt->patch_p > 0 && opt->patch_q > 0)
        return radi_patch_grid_build(&r->grid, m, opt->patch_p, opt->patch_q, err);
    return RAD_OK;
}

rad_status radi_progressive_run(const rad_mesh *m, const rad_shoot_source *src,
                               const double *rho, const double *E,
                               const rad_solve_options *opt, double *B,
                               rad_solve_report *report, rad_error *err)
{
    run r;
    int steps = 0;
    double at_half = HUGE_VAL;
    if (!(opt->tolerance > 0) || opt->max_iterations < 1)
        return radi_fail(err, RAD_ERR_INVALID,
                        "tolerance must be positive and max-iterations at least 1");
    rad_status st = run_init(&r, m, rho, E, opt, err);
    if (st == RAD_OK)
        st = shooter_init(&r.sh, m, src, r.grid.npatches ? &r.grid : NULL, rho, E, r.area,
                          opt->patches != 0, opt->sort != 0, B, err);
    if (st != RAD_OK) {
        run_free(&r);
        return st;
    }
    trace_open(&r.tr, opt);
    unshot_power(&r.sh, r.U);
    while (st == RAD_OK && !converged(r.U, r.emitted, opt->tolerance)) {
        if (steps == opt->max_iterations) {
            st = no_convergence(&r, at_half, err);
            break;
        }
        int stop = 0;
        st = run_step(&r, ++steps, &stop);
        if (steps == (opt->max_iterations + 1) / 2)
            at_half = r.U[0] + r.U[1] + r.U[2];
        if (st == RAD_OK && (stop || run_progress(&r, steps)))
            st = radi_fail(err, RAD_ERR_INVALID, "interrupted");
    }
    if (report)
        report->sweeps = steps; /* for progressive, 'sweeps' counts shooting steps */
    if (opt->progress && st == RAD_OK)
        opt->progress(opt->progress_user, "shoot", 1, 1);
    run_free(&r);
    return st;
}

/* ---- the race of figure 7 ------------------------------------------------- */

static const char *const race_names[RAD_RACE_METHODS] = {"gathering", "shooting", "sorted",
                                                         "sorted_ambient"};

const char *radi_race_name(int method)
{
    return method >= 0 && method < RAD_RACE_METHODS ? race_names[method] : "?";
}

void radi_race_options_init(rad_race_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->steps = 1;
    opt->reach = 1e-6;
}

typedef struct race {
    const rad_race_options *opt;
    int n;
    const double *rho, *area, *Bref;
    double total_area, scale;
    double *rms;
    int *reached;
    const rad_shoot_source *src;
    double *row, *col;          /* matrix-free gathering: row i (and column i) */
    rad_error *err;
    rad_status st;              /* a computed row or column that failed */
} race;

int radi_race_snapshot_due(const rad_race_options *o, int k)
{
    if (o->snapshot_every > 0 && k % o->snapshot_every == 0)
        return 1;
    for (int j = 0; j < o->nsnapshot_at; j++)
        if (o->snapshot_at[j] == k)
            return 1;
    return 0;
}

/* Record method m's displayed B after k steps; non-zero: stop. */
static int race_record(const race *rc, int m, int k, const double *B)
{
    const size_t n3 = (size_t)rc->n * NB;
    const rad_race_options *o = rc->opt;
    const size_t at = (size_t)k + (size_t)m * (size_t)(o->steps + 1);
    const rad_rms_input in = {rc->n, rc->area, rc->total_area, rc->rho, NULL, B, rc->Bref};
    rc->rms[at] = radi_rms_eq14(&in);
    if (o->rms_bands)
        o->rms_bands[at] = radi_rms_bands(&in);
    if (rc->reached[m] < 0 && max_diff(B, rc->Bref, n3) <= o->reach * rc->scale)
        rc->reached[m] = k;
    if (o->snapshot && radi_race_snapshot_due(o, k) && o->snapshot(o->snapshot_user, m, k, B))
        return 1;
    return 0;
}

static int race_progress(const race *rc, int done)
{
    const rad_race_options *o = rc->opt;
    if (!o->progress || done % 256 != 0)
        return 0;
    return o->progress(o->progress_user, "race", done, 3.0 * o->steps);
}

/* Gauss-Seidel for one element: B_i <- E_i + rho_i sum_j F_ij B_j, with
 * F_ij = Fi[j * stride] (row i of the matrix, or computed: stride 1). */
static void gather_row(int n, const double *Fi, size_t stride, const double *rho,
                       const double *E, double *B, int i)
{
    double h[NB] = {0, 0, 0};
    for (int j = 0; j < n; j++) {
        const double f = Fi[(size_t)j * stride];
        for (int b = 0; b < NB; b++)
            h[b] += f * B[(size_t)j + (size_t)b * n];
    }
    for (int b = 0; b < NB; b++) {
        const size_t k = (size_t)i + (size_t)b * n;
        B[k] = E[k] + rho[k] * h[b];
    }
}

static int race_gather(race *rc, const double *E, double *B)
{
    const double *F = rc->src->F;
    memcpy(B, E, sizeof *B * (size_t)rc->n * NB);
    for (int k = 0; k <= rc->opt->steps; k++) {
        const int i = rc->n > 0 ? (k - 1) % rc->n : 0;
        if (k > 0 && rc->n > 0 && !F &&
            (rc->st = radi_ffrow_column(rc->src->row, i, rc->col, rc->row, rc->err)) != RAD_OK)
            return 1;
        if (k > 0 && rc->n > 0)
            gather_row(rc->n, F ? F + i : rc->row, F ? (size_t)rc->n : 1, rc->rho, E, B, i);
        if (race_record(rc, RAD_RACE_GATHERING, k, B) || race_progress(rc, k))
            return 1;
    }
    return 0;
}

/* Shooting from sh (already initialised); sorted also records the ambient. */
static int race_shoot(race *rc, shooter *sh, int done, double *disp)
{
    const ambient amb = ambient_init(rc->n, rc->area, rc->rho);
    const int m = sh->sort ? RAD_RACE_SORTED : RAD_RACE_SHOOTING;
    for (int k = 0; k <= rc->opt->steps; k++) {
        double shot[NB], U[NB], a[NB];
        if (k > 0 && sh->nshooters > 0 &&
            (rc->st = shooter_shoot(sh, shooter_pick(sh), shot)) != RAD_OK)
            return 1;
        if (race_record(rc, m, k, sh->B) || race_progress(rc, done + k))
            return 1;
        if (!sh->sort)
            continue;
        unshot_power(sh, U);
        ambient_value(&amb, U, a);
        ambient_display(rc->n, sh->B, rc->rho, a, disp);
        if (race_record(rc, RAD_RACE_SORTED_AMBIENT, k, disp))
            return 1;
    }
    return 0;
}

rad_status radi_race_run(const rad_mesh *mesh, const double *F, const double *Bref,
                        const rad_race_options *opt, double *rms, int *reached, rad_error *err)
{
    const rad_shoot_source src = {F, NULL};
    return radi_race_run_source(mesh, &src, Bref, opt, rms, reached, err);
}

rad_status radi_race_run_source(const rad_mesh *mesh, const rad_shoot_source *src,
                               const double *Bref, const rad_race_options *opt, double *rms,
                               int *reached, rad_error *err)
{
    const int n = mesh->nelements;
    const size_t n3 = (size_t)(n ? n : 1) * NB;
    rad_status st = RAD_OK;
    if (opt->steps < 1 || !(opt->reach > 0))
        return radi_fail(err, RAD_ERR_INVALID, "the race needs at least one step and reach > 0");
    double *rho = malloc(sizeof *rho * n3), *E = malloc(sizeof *E * n3);
    double *B = malloc(sizeof *B * n3), *disp = malloc(sizeof *disp * n3);
    double *area = element_areas(mesh);
    double *row = src->F ? NULL : malloc(sizeof *row * n3);
    if (!rho || !E || !B || !disp || !area || (!src->F && !row)) {
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for the race");
        goto done;
    }
    for (int i = 0; i < n; i++)
        for (int b = 0; b < NB; b++) {
            rho[(size_t)i + (size_t)b * n] = mesh->elements[i].reflect[b];
            E[(size_t)i + (size_t)b * n] = mesh->elements[i].emit[b];
        }
    for (int m = 0; m < RAD_RACE_METHODS; m++)
        reached[m] = -1;
    race rc = {opt, n, rho, area, Bref, sum(area, n), radi_max_abs(Bref, (size_t)n * NB), rms,
               reached, src, row, row ? row + n : NULL, err, RAD_OK};
    int stop = race_gather(&rc, E, B);
    for (int sort = 0; sort <= 1 && !stop && st == RAD_OK; sort++) {
        shooter sh;
        st = shooter_init(&sh, mesh, src, NULL, rho, E, area, opt->patches, sort, B, err);
        if (st == RAD_OK)
            stop = race_shoot(&rc, &sh, (1 + sort) * opt->steps, disp);
        shooter_free(&sh);
    }
    if (stop && st == RAD_OK)
        st = rc.st != RAD_OK ? rc.st : radi_fail(err, RAD_ERR_INVALID, "interrupted");
done:
    free(row);
    free(rho);
    free(E);
    free(B);
    free(disp);
    free(area);
    return st;
}

/* ---- one step at a time (the live view) ----------------------------------- */

struct radi_stepper {
    int method, n, last;
    int row;                    /* gathering: the next row, 0 .. n-1 */
    long steps;                 /* 64 bits: 2^31 steps are 3 minutes of a
                                   small scene at rate 0 */
    shooter sh;                 /* the shooting methods */
    ambient amb;                /* sorted_ambient */
    const double *F;
    double *rho, *E, *area, *B, *shown, *work;
    double emitted;             /* sum A E over the bands */
};

void radi_stepper_free(radi_stepper *s)
{
    if (!s)
        return;
    shooter_free(&s->sh);
    free(s->rho);
    free(s->E);
    free(s->area);
    free(s->B);
    free(s->shown);
    free(s->work);
    free(s);
}

/* What is shown: B, or B with the ambient term (eq. 13). */
static void stepper_show(radi_stepper *s)
{
    const size_t n3 = (size_t)s->n * NB;
    if (s->method != RAD_RACE_SORTED_AMBIENT) {
        memcpy(s->shown, s->B, sizeof *s->B * n3);
        return;
    }
    double U[NB], a[NB];
    unshot_power(&s->sh, U);
    ambient_value(&s->amb, U, a);
    ambient_display(s->n, s->B, s->rho, a, s->shown);
}

rad_status radi_stepper_new(radi_stepper **out, const rad_mesh *m, const double *F, int method,
                            rad_error *err)
{
    const int n = m->nelements;
    const size_t n3 = (size_t)(n ? n : 1) * NB;
    *out = NULL;
    if (method < 0 || method > RAD_STEP_JACOBI)
        return radi_fail(err, RAD_ERR_INVALID, "no step method %d", method);
    radi_stepper *s = calloc(1, sizeof *s);
    if (!s)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the stepper");
    s->method = method;
    s->n = n;
    s->F = F;
    s->last = -1;
    s->rho = malloc(sizeof *s->rho * n3);
    s->E = malloc(sizeof *s->E * n3);
    s->B = malloc(sizeof *s->B * n3);
    s->shown = malloc(sizeof *s->shown * n3);
    s->work = malloc(sizeof *s->work * n3);
    s->area = element_areas(m);
    if (!s->rho || !s->E || !s->B || !s->shown || !s->work || !s->area) {
        radi_stepper_free(s);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the stepper");
    }
    for (int i = 0; i < n; i++)
        for (int b = 0; b < NB; b++) {
            s->rho[(size_t)i + (size_t)b * n] = m->elements[i].reflect[b];
            s->E[(size_t)i + (size_t)b * n] = m->elements[i].emit[b];
            s->emitted += s->area[i] * m->elements[i].emit[b];
        }
    memcpy(s->B, s->E, sizeof *s->B * (size_t)n * NB);
    if (method == RAD_RACE_SHOOTING || method == RAD_RACE_SORTED ||
        method == RAD_RACE_SORTED_AMBIENT) {
        const rad_shoot_source src = {F, NULL};
        rad_status st = shooter_init(&s->sh, m, &src, NULL, s->rho, s->E, s->area, 0,
                                     method != RAD_RACE_SHOOTING, s->B, err);
        if (st != RAD_OK) {
            radi_stepper_free(s);
            return st;
        }
        s->amb = ambient_init(n, s->area, s->rho);
    }
    stepper_show(s);
    *out = s;
    return RAD_OK;
}

/* One Jacobi sweep: B <- E + rho F B, every row from the last sweep's B. */
static void jacobi_sweep(radi_stepper *s)
{
    const size_t n = (size_t)s->n;
    for (int b = 0; b < NB; b++) {
        const double *Bb = s->B + b * n;
        double *h = s->work + b * n;
        memset(h, 0, sizeof *h * n);
        for (size_t j = 0; j < n; j++) /* column j of F: F_ij for every i */
            for (size_t i = 0; i < n; i++)
                h[i] += s->F[i + j * n] * Bb[j];
        for (size_t i = 0; i < n; i++)
            h[i] = s->E[i + b * n] + s->rho[i + b * n] * h[i];
    }
    memcpy(s->B, s->work, sizeof *s->B * n * NB);
}

rad_status radi_stepper_step(radi_stepper *s, rad_error *err)
{
    if (s->n == 0)
        return RAD_OK;
    if (s->method == RAD_RACE_GATHERING) {
        const int i = s->row; /* Gauss-Seidel, one element row */
        s->row = (i + 1) % s->n;
        gather_row(s->n, s->F + i, (size_t)s->n, s->rho, s->E, s->B, i);
        s->last = i;
    } else if (s->method == RAD_STEP_JACOBI) {
        jacobi_sweep(s);
        s->last = -1;
    } else {
        double shot[NB];
        s->sh.err = err;
        const int k = shooter_pick(&s->sh);
        rad_status st = shooter_shoot(&s->sh, k, shot);
        if (st != RAD_OK)
            return st;
        s->last = k;
    }
    s->steps++;
    stepper_show(s);
    return RAD_OK;
}

const double *radi_stepper_shown(const radi_stepper *s)
{
    return s->shown;
}

int radi_stepper_last(const radi_stepper *s)
{
    return s->last;
}

long radi_stepper_steps(const radi_stepper *s)
{
    return s->steps;
}

double radi_stepper_unshot(const radi_stepper *s)
{
    if (s->method == RAD_RACE_GATHERING || s->method == RAD_STEP_JACOBI || !(s->emitted > 0))
        return NAN;
    double U[NB], u = 0;
    unshot_power(&s->sh, U);
    for (int b = 0; b < NB; b++)
        u += U[b];
    return u / s->emitted;
}
