/* test_progressive.c -- progressive refinement (Cohen et al. 1988).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Independent references:
 *   - the gauss solve (LU, tested against exact closed forms in
 *     test_solve.c): shooting in any order, by elements or patches, must
 *     converge to it;
 *   - energy, step by step, from B alone: when element i shoots the power
 *     S = sum_b A_i dB_i,b, element j receives the incident power A_i dB_i
 *     F_ij (row i of F, read here, not the column the solver streams) and
 *     reflects rho_j of it, dRad_j = B_j(k) - B_j(k-1).  So
 *         S = sum_j I_j + S (1 - sum_j F_ij),
 *         I_j = sum_b A_j dRad_j,b / rho_j,b   if rho_j > 0 (every band),
 *         I_j = F_ij S                         if rho_j = 0 (every band: it
 *                                              absorbs what it receives),
 *     the second term being what leaves through the row-sum deficit.  And
 *     the bookkeeping: unshot(k) = sum A E + sum A (B(k) - E) - sum of the
 *     shots so far (all summed over the bands);
 *   - eq. 14 and eq. 9-13 of Cohen et al. recomputed here from B(k) (the
 *     ambient on a grey scene, where each band holds a third of the unshot
 *     power);
 *   - the paper's figure 7 order on the shipped cube;
 *   - matrix-free shooting (ffrow.h): each computed column against the
 *     dense fill's column (equal bit for bit, visibility included), the
 *     patch factors F_jP against the sum of the element columns
 *     (additivity, to the kernel's 1e-6), and the solve from columns
 *     against the solve from the matrix (the same steps, the same B).
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fill/ffrow.h"
#include "mesh/patchgrid.h"
#include "solve/progressive.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "../tap.h"

/* A scene from data/, its mesh, F and the gauss solution. */
typedef struct fixture {
    rad_scene scene;
    rad_mesh mesh;
    int n;
    double *F, *Bg;
} fixture;

static int fixture_load(fixture *fx, const char *name, int mesh)
{
    const char *top = getenv("top_srcdir");
    char path[4096];
    rad_error err;
    rad_ff_options fo;
    rad_solve_options so;
    memset(fx, 0, sizeof *fx);
    snprintf(path, sizeof path, "%s/data/%s", top ? top : ".", name);
    if (rad_scene_load(&fx->scene, path, &err)) {
        tap_diag("%s", err.message);
        return -1;
    }
    if (mesh > 0)
        rad_scene_set_mesh(&fx->scene, mesh, mesh);
    if (rad_mesh_build(&fx->mesh, &fx->scene, &err))
        return -1;
    fx->n = fx->mesh.nelements;
    fx->F = malloc(sizeof *fx->F * (size_t)fx->n * fx->n);
    fx->Bg = malloc(sizeof *fx->Bg * (size_t)fx->n * 3);
    rad_ff_options_init(&fo);
    rad_solve_options_init(&so);
    if (!fx->F || !fx->Bg || rad_ff_matrix(&fx->mesh, &fo, fx->F, NULL, NULL, &err) ||
        rad_solve(&fx->mesh, fx->F, &so, fx->Bg, NULL, &err))
        return -1;
    return 0;
}

static void fixture_free(fixture *fx)
{
    free(fx->F);
    free(fx->Bg);
    rad_mesh_free(&fx->mesh);
    rad_scene_free(&fx->scene);
}

static double rel_diff(const double *a, const double *b, size_t n)
{
    double d = 0, s = 0;
    for (size_t k = 0; k < n; k++) {
        d = fmax(d, fabs(a[k] - b[k]));
        s = fmax(s, fabs(b[k]));
    }
    return s > 0 ? d / s : d;
}

/* rho and E of the mesh, n x 3. */
static void mesh_arrays(const rad_mesh *m, double *rho, double *E)
{
    const int n = m->nelements;
    for (int i = 0; i < n; i++)
        for (int b = 0; b < 3; b++) {
            rho[i + (size_t)b * n] = m->elements[i].reflect[b];
            E[i + (size_t)b * n] = m->elements[i].emit[b];
        }
}

/* Progressive solve; the status, B and the steps. */
static rad_status progressive(const fixture *fx, const rad_solve_options *o, double *B,
                              int *steps, rad_error *err)
{
    const size_t n3 = (size_t)fx->n * 3;
    double *rho = malloc(sizeof *rho * n3), *E = malloc(sizeof *E * n3);
    rad_solve_report rep;
    memset(&rep, 0, sizeof rep);
    mesh_arrays(&fx->mesh, rho, E);
    rad_status st = rad_solve_progressive(&fx->mesh, fx->F, rho, E, o, B, &rep, err);
    if (steps)
        *steps = rep.sweeps;
    free(rho);
    free(E);
    return st;
}

/* ---- collecting a trace ---------------------------------------------------- */

/* The solver hands each step to on_shot (the command writes the rows as
 * TSV; tests/commands/progress.sh checks that file).  Columns: step shooter shot
 * unshot rms rms_ambient. */
#define TRACE_COLS 6

typedef struct trace {
    int rows, cap;
    int header_ok;              /* kept for the checks below: always 1 here */
    int steps_ok;               /* step column runs 1, 2, ... */
    int stop_after;             /* > 0: ask the solver to stop after that many */
    double *col[TRACE_COLS];
} trace;

static void trace_free(trace *t)
{
    for (int c = 0; c < TRACE_COLS; c++)
        free(t->col[c]);
    memset(t, 0, sizeof *t);
}

static void trace_init(trace *t)
{
    memset(t, 0, sizeof *t);
    t->header_ok = t->steps_ok = 1;
}

static int trace_add(void *user, const rad_shot *r)
{
    trace *t = user;
    if (t->rows == t->cap) {
        t->cap = t->cap ? 2 * t->cap : 256;
        for (int c = 0; c < TRACE_COLS; c++)
            t->col[c] = realloc(t->col[c], sizeof *t->col[c] * (size_t)t->cap);
    }
    const double v[TRACE_COLS] = {r->step, r->shooter, r->shot, r->unshot, r->rms,
                                  r->rms_ambient};
    for (int c = 0; c < TRACE_COLS; c++)
        t->col[c][t->rows] = v[c];
    t->steps_ok &= r->step == t->rows + 1;
    t->rows++;
    return t->stop_after > 0 && t->rows >= t->stop_after;
}

/* Trace into t from now on (t emptied). */
static void trace_on(rad_solve_options *o, trace *t)
{
    trace_free(t);
    trace_init(t);
    o->on_shot = trace_add;
    o->shot_user = t;
}

/* ---- the tests ------------------------------------------------------------ */

static void test_converges(const fixture *fx)
{
    const size_t n3 = (size_t)fx->n * 3;
    double *B = malloc(sizeof *B * n3), *B2 = malloc(sizeof *B2 * n3);
    rad_solve_options o;
    rad_solve_report rep;
    rad_error err;
    int steps;
    rad_solve_options_init(&o);
    o.solver = RAD_SOLVER_PROGRESSIVE;
    o.tolerance = 1e-14; /* unshot power: B then within ~1e-14 / (1 - rho) */
    for (int patches = 0; patches <= 1; patches++)
        for (int sort = 1; sort >= 0; sort--) {
            o.patches = patches;
            o.sort = sort;
            rad_status st = progressive(fx, &o, B, &steps, &err);
            double d = rel_diff(B, fx->Bg, n3);
            tap_ok(st == RAD_OK && d <= 1e-10,
                   "%s, %s: converges to the gauss solution within 1e-10 relative (%.3g, %d "
                   "shots)", patches ? "patches" : "elements", sort ? "sorted" : "file order",
                   d, steps);
        }
    o.patches = 0;
    o.sort = 1;
    progressive(fx, &o, B, &steps, &err);
    rad_status st = rad_solve(&fx->mesh, fx->F, &o, B2, &rep, &err);
    tap_ok(st == RAD_OK && memcmp(B, B2, sizeof *B * n3) == 0 && rep.sweeps == steps &&
               rep.solver == RAD_SOLVER_PROGRESSIVE && rep.residual <= 1e-12,
           "rad_solve dispatches --solver progressive (sweeps = %d shooting steps, residual %.3g)",
           rep.sweeps, rep.residual);
    free(B);
    free(B2);
}

/* F with reciprocity broken: shooting down the columns (F_ji) still solves
 * (I - diag(rho) F) B = E. */
static void test_nonreciprocal(const fixture *fx)
{
    const int n = fx->n;
    const size_t n3 = (size_t)n * 3;
    fixture f2 = *fx;
    double *F = malloc(sizeof *F * (size_t)n * n), *B = malloc(sizeof *B * n3);
    double *Bg = malloc(sizeof *Bg * n3);
    rad_solve_options o;
    rad_error err;
    memcpy(F, fx->F, sizeof *F * (size_t)n * n);
    for (int j = 0; j < n; j++)
        F[60 + (size_t)j * n] *= 0.9; /* row 60: a grey back-wall element */
    f2.F = F;
    rad_solve_options_init(&o);
    rad_solve(&fx->mesh, F, &o, Bg, NULL, &err);
    o.tolerance = 1e-14;
    rad_status st = progressive(&f2, &o, B, NULL, &err);
    double d = rel_diff(B, Bg, n3);
    tap_ok(st == RAD_OK && d <= 1e-10,
           "non-reciprocal F: converges to that system's gauss solution (%.3g)", d);
    free(F);
    free(B);
    free(Bg);
}

/* Energy at every one of the first K steps (identity in the file header). */
static void test_energy(const fixture *fx)
{
    enum { K = 80 };
    const int n = fx->n;
    const size_t n3 = (size_t)n * 3;
    double *prev = malloc(sizeof *prev * n3), *B = malloc(sizeof *B * n3);
    rad_solve_options o;
    rad_error err;
    trace t;
    trace_init(&t);
    rad_solve_options_init(&o);
    o.max_iterations = K;
    o.reference = fx->Bg;
    trace_on(&o, &t);
    rad_status st = progressive(fx, &o, B, NULL, &err);
    int ok = st == RAD_ERR_NOCONV && t.rows == K;
    tap_ok(ok, "%d steps traced (stopped by max_iterations: %s)", K, err.message);
    if (!ok) {
        free(prev);
        free(B);
        return;
    }
    double worst = 0, worst_book = 0, shots = 0, emitted = 0;
    for (int i = 0; i < n; i++)
        for (int b = 0; b < 3; b++) {
            prev[i + (size_t)b * n] = fx->mesh.elements[i].emit[b];
            emitted += fx->mesh.elements[i].area * fx->mesh.elements[i].emit[b];
        }
    o.on_shot = NULL;
    for (int k = 1; k <= K; k++) {
        const int i = (int)t.col[1][k - 1];
        const double S = t.col[2][k - 1];
        o.max_iterations = k;
        progressive(fx, &o, B, NULL, &err);
        double in = 0, rowsum = 0, gained = 0;
        for (int j = 0; j < n; j++) {
            const rad_element *e = &fx->mesh.elements[j];
            const double fij = fx->F[i + (size_t)j * n];
            rowsum += fij;
            if (e->reflect[0] == 0 && e->reflect[1] == 0 && e->reflect[2] == 0)
                in += fij * S;
            for (int b = 0; b < 3; b++) {
                const size_t q = j + (size_t)b * n;
                if (e->reflect[b] > 0)
                    in += e->area * (B[q] - prev[q]) / e->reflect[b];
                gained += e->area * (B[q] - e->emit[b]);
            }
        }
        shots += S;
        worst = fmax(worst, fabs(S - in - S * (1 - rowsum)) / S);
        worst_book = fmax(worst_book, fabs(t.col[3][k - 1] - (emitted + gained - shots)) / emitted);
        memcpy(prev, B, sizeof *B * n3);
    }
    /* differences of B(k) lose digits: 1e-11 leaves a margin of ~100 over
     * the worst seen (a few 1e-14) */
    tap_ok(worst <= 1e-11,
           "energy at every step: shot = sum_j incident_j + shot (1 - sum_j F_ij) "
           "(worst %.3g of the shot)", worst);
    tap_ok(worst_book <= 1e-12,
           "unshot = emitted + sum A (B - E) - shots so far, at every step (worst %.3g)",
           worst_book);
    trace_free(&t);
    free(prev);
    free(B);
}

/* Eq. 14 and eq. 9-13 recomputed here from B(k), on the grey cube. */
static void test_ambient(void)
{
    fixture g;
    if (fixture_load(&g, "grey-cube.scene", 3)) {
        tap_ok(0, "grey cube");
        return;
    }
    const int n = g.n, k = 12;
    const size_t n3 = (size_t)n * 3;
    double *B0 = malloc(sizeof *B0 * n3), *B1 = malloc(sizeof *B1 * n3);
    rad_solve_options o;
    rad_error err;
    trace t;
    trace_init(&t);
    rad_solve_options_init(&o);
    o.max_iterations = k;
    trace_on(&o, &t);
    o.ambient = 0;
    progressive(&g, &o, B0, NULL, &err);
    o.ambient = 1;
    progressive(&g, &o, B1, NULL, &err); /* and the gauss reference computed inside */
    tap_ok(memcmp(B0, B1, sizeof *B0 * n3) == 0,
           "the ambient term never changes B (bit for bit, after %d steps)", k);
    o.tolerance = 1e-14;
    o.max_iterations = 100000;
    progressive(&g, &o, B1, NULL, &err);
    tap_ok(rel_diff(B1, g.Bg, n3) <= 1e-10, "with ambient = 1 it still converges to gauss (%.3g)",
           rel_diff(B1, g.Bg, n3));
    o.max_iterations = k;
    o.tolerance = 1e-12;
    trace_on(&o, &t);
    progressive(&g, &o, B1, NULL, &err);
    if (t.rows != k) {
        tap_ok(0, "ambient trace");
        trace_free(&t);
        return;
    }
    double A = 0, rA = 0, s = 0, sa = 0;
    for (int i = 0; i < n; i++) {
        A += g.mesh.elements[i].area;
        rA += g.mesh.elements[i].reflect[0] * g.mesh.elements[i].area;
    }
    const double R = 1 / (1 - rA / A);             /* eq. 10-11 */
    const double amb = R * (t.col[3][k - 1] / 3) / A; /* eq. 9, 12: grey, a third per band */
    for (int i = 0; i < n; i++) {
        const double a = g.mesh.elements[i].area, rho = g.mesh.elements[i].reflect[0];
        const double d = B1[i] - g.Bg[i], da = B1[i] + rho * amb - g.Bg[i]; /* eq. 13 */
        s += a * d * d;
        sa += a * da * da;
    }
    tap_close(t.col[4][k - 1], sqrt(s / A), 1e-12, "trace rms is eq. 14 of B(k)");
    tap_close(t.col[5][k - 1], sqrt(sa / A), 1e-12, "trace rms_ambient is eq. 14 of B(k) + rho Ambient");
    trace_free(&t);
    free(B0);
    free(B1);
    fixture_free(&g);
}

static void test_trace_and_noconv(const fixture *fx)
{
    const size_t n3 = (size_t)fx->n * 3;
    double *B = malloc(sizeof *B * n3);
    rad_solve_options o;
    rad_error err;
    trace t;
    int steps;
    trace_init(&t);
    rad_solve_options_init(&o);
    o.solver = RAD_SOLVER_PROGRESSIVE;
    o.tolerance = 1e-6;
    trace_on(&o, &t);
    rad_status st = progressive(fx, &o, B, &steps, &err);
    int read = st == RAD_OK;
    tap_ok(read && t.header_ok && t.rows == steps && t.steps_ok,
           "trace: one row per step, steps numbered 1, 2, ... (%d rows, %d steps)",
           read ? t.rows : -1, steps);
    if (read) {
        double last = t.col[3][t.rows - 1];
        tap_ok(last <= 1e-6 * 3 && t.col[3][t.rows - 2] > 1e-6,
               "it stops when the unshot power falls below tolerance x emitted (%.3g)", last);
    }
    trace_free(&t);
    o.on_shot = NULL;
    o.max_iterations = 10;
    st = rad_solve(&fx->mesh, fx->F, &o, B, NULL, &err);
    tap_ok(st == RAD_ERR_NOCONV && strstr(err.message, "did not converge in 10 shooting steps"),
           "10 steps are not enough: %s", err.message);
    trace_on(&o, &t);
    t.stop_after = 3;
    o.max_iterations = 100000;
    st = rad_solve(&fx->mesh, fx->F, &o, B, NULL, &err);
    tap_ok(st == RAD_ERR_INVALID && strstr(err.message, "interrupted") && t.rows == 3,
           "on_shot asking to stop ends the solve after that step (%s, %d rows)", err.message,
           t.rows);
    trace_free(&t);
    o.on_shot = NULL;
    o.tolerance = 0;
    st = progressive(fx, &o, B, NULL, &err);
    tap_ok(st == RAD_ERR_INVALID, "tolerance 0 is refused (%s)", err.message);
    free(B);
}

static void test_singular_and_dark(void)
{
    static const char *walls =
        "quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 2x2\nquad w 0 0 1  0 1 1  1 1 1  1 0 1 mesh 2x2\n"
        "quad w 0 0 0  0 1 0  0 1 1  0 0 1 mesh 2x2\nquad w 1 0 0  1 0 1  1 1 1  1 1 0 mesh 2x2\n"
        "quad w 0 0 0  0 0 1  1 0 1  1 0 0 mesh 2x2\nquad w 0 1 0  1 1 0  1 1 1  0 1 1 mesh 2x2\n";
    static const char *const mats[2] = {"material w reflect 1 emit 1\n",
                                        "material w reflect 0.5\n"};
    for (int c = 0; c < 2; c++) {
        char text[2048];
        fixture fx;
        rad_error err;
        rad_ff_options fo;
        rad_solve_options o;
        rad_solve_report rep;
        memset(&fx, 0, sizeof fx);
        snprintf(text, sizeof text, "%s%s", mats[c], walls);
        rad_scene_parse(&fx.scene, text, strlen(text), "box", &err);
        rad_mesh_build(&fx.mesh, &fx.scene, &err);
        fx.n = fx.mesh.nelements;
        fx.F = malloc(sizeof *fx.F * (size_t)fx.n * fx.n);
        double *B = malloc(sizeof *B * (size_t)fx.n * 3);
        rad_ff_options_init(&fo);
        rad_ff_matrix(&fx.mesh, &fo, fx.F, NULL, NULL, &err);
        rad_solve_options_init(&o);
        o.solver = RAD_SOLVER_PROGRESSIVE;
        o.max_iterations = 2000;
        memset(&rep, 0, sizeof rep);
        rad_status st = rad_solve(&fx.mesh, fx.F, &o, B, &rep, &err);
        if (c == 0) {
            tap_ok(st == RAD_ERR_NOCONV && strstr(err.message, "looks singular"),
                   "closed box, rho = 1: no convergence, looks singular (%s)", err.message);
        } else {
            double m = 0;
            for (int k = 0; k < 3 * fx.n; k++)
                m = fmax(m, fabs(B[k]));
            tap_ok(st == RAD_OK && rep.sweeps == 0 && m == 0,
                   "nothing emits: converged after 0 steps, B = 0");
        }
        free(B);
        fixture_free(&fx);
    }
}

/* The race of figure 7 on the shipped cube. */
static void test_race(const fixture *fx)
{
    const int n = fx->n, steps = 2 * n, lights = 49;
    const size_t rows = (size_t)steps + 1;
    double *rms = malloc(sizeof *rms * rows * RAD_RACE_METHODS);
    int reached[RAD_RACE_METHODS];
    rad_race_options ro;
    rad_error err;
    radi_race_options_init(&ro);
    ro.steps = steps;
    rad_status st = radi_race_run(&fx->mesh, fx->F, fx->Bg, &ro, rms, reached, &err);
    tap_ok(st == RAD_OK, "the race runs (%d steps)", steps);
    const double *g = rms, *sh = rms + rows, *so = rms + 2 * rows, *am = rms + 3 * rows;
    int order = 1, strict = 1, same = 1;
    for (int k = 1; k <= steps; k++) {
        order &= am[k] < so[k] && so[k] <= sh[k] && sh[k] < g[k];
        if (k > lights)
            strict &= so[k] < sh[k];
        else
            same &= so[k] == sh[k];
    }
    tap_ok(order, "steps 1-%d: sorted + ambient < sorted <= shooting < gathering (the paper's "
                  "order)", steps);
    tap_ok(same, "steps 1-%d: the %d light elements tie, sorted shoots them in file order",
           lights, lights);
    tap_ok(strict, "steps %d-%d: sorted shooting's RMS error is below file order's", lights + 1,
           steps);
    tap_ok(am[lights] < so[lights],
           "after one step per light element (%d): ambient %.4g < sorted %.4g", lights,
           am[lights], so[lights]);
    tap_ok(g[0] == sh[0] && sh[0] == so[0] && am[0] < so[0], "step 0: B = E for all");
    /* the race's sorted curve is the trace's rms */
    rad_solve_options o;
    trace t;
    trace_init(&t);
    double *B = malloc(sizeof *B * (size_t)n * 3), d = 0;
    rad_solve_options_init(&o);
    o.max_iterations = steps;
    trace_on(&o, &t);
    o.reference = fx->Bg;
    progressive(fx, &o, B, NULL, &err);
    if (t.rows == steps) {
        for (int k = 1; k <= steps; k++)
            d = fmax(d, fabs(t.col[4][k - 1] - so[k]) + fabs(t.col[5][k - 1] - am[k]));
    } else {
        d = HUGE_VAL;
    }
    trace_free(&t);
    tap_ok(d == 0, "the race's sorted curves equal the solver's trace (%.3g)", d);
    ro.steps = 4000;
    double *rms2 = malloc(sizeof *rms2 * (size_t)(ro.steps + 1) * RAD_RACE_METHODS);
    radi_race_run(&fx->mesh, fx->F, fx->Bg, &ro, rms2, reached, &err);
    tap_ok(reached[RAD_RACE_SORTED] > 0 && reached[RAD_RACE_SORTED] < reached[RAD_RACE_GATHERING],
           "within 1e-6 of gauss: sorted after %d shots, gathering after %d element updates",
           reached[RAD_RACE_SORTED], reached[RAD_RACE_GATHERING]);
    free(rms);
    free(rms2);
    free(B);
}

/* ---- matrix-free shooting ------------------------------------------------- */

/* Every computed column (and row) is the dense fill's, bit for bit. */
static void test_columns(const fixture *fx, const char *what)
{
    rad_ff_options fo;
    rad_error err;
    rad_ffrow *row = NULL;
    const int n = fx->n;
    rad_ff_options_init(&fo);
    double *to = malloc(sizeof *to * (size_t)n), *from = malloc(sizeof *from * (size_t)n);
    int same = 1, st = radi_ffrow_create(&row, &fx->mesh, &fo, RAD_OCC_AUTO, 0, 0, &err);
    for (int i = 0; i < n && st == RAD_OK && same; i++) {
        st = radi_ffrow_column(row, i, to, from, &err);
        same = memcmp(to, fx->F + (size_t)i * n, sizeof *to * (size_t)n) == 0;
        for (int j = 0; j < n && same; j++)
            same = memcmp(&from[j], &fx->F[(size_t)i + (size_t)j * n], sizeof *from) == 0;
    }
    tap_ok(st == RAD_OK && same, "%s: every column F_.i and row F_i. computed per shooter "
           "is the dense fill's, bit for bit", what);
    rad_ff_stats fs;
    double lo, hi;
    if (row)
        radi_ffrow_stats(row, &fs, &lo, &hi);
    tap_ok(row && fs.pairs == (double)n * (n - 1) && lo > 0 && hi < 1 + 1e-6,
           "%s: the rows' statistics count n (n - 1) pairs, row sums in [%.6g, %.6g]", what,
           row ? lo : NAN, row ? hi : NAN);
    radi_ffrow_free(row);
    free(to);
    free(from);
}

/* F_jP on the patch outline = sum_{i in P} F_ji (additivity). */
static void test_patch_columns(const fixture *fx, const char *what, double tol)
{
    rad_ff_options fo;
    rad_error err;
    rad_ffrow *row = NULL;
    rad_patch_grid g;
    const int n = fx->n;
    rad_ff_options_init(&fo);
    double *to = malloc(sizeof *to * (size_t)n), worst = 0, area = 0, mesh_area = 0;
    int st = radi_patch_grid_build(&g, &fx->mesh, 2, 2, &err), once = 1;
    if (st == RAD_OK)
        st = radi_ffrow_create(&row, &fx->mesh, &fo, RAD_OCC_AUTO, 2, 2, &err);
    for (int p = 0; st == RAD_OK && p < g.npatches; p++) {
        st = radi_ffrow_patch(row, p, to, &err);
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int k = g.first[p]; k < g.first[p + 1]; k++)
                s += fx->F[(size_t)j + (size_t)g.member[k] * n];
            worst = fmax(worst, fabs(to[j] - s) / fmax(s, 1e-300));
        }
        area += g.area[p];
        for (int k = g.first[p]; k < g.first[p + 1]; k++)
            once &= g.patch_of[g.member[k]] == p;
    }
    for (int i = 0; i < n; i++)
        mesh_area += fx->mesh.elements[i].area;
    tap_ok(st == RAD_OK && g.npatches == 4 * fx->mesh.nsurfaces && once &&
               fabs(area - mesh_area) <= 1e-12 * mesh_area,
           "%s: patch grid 2x2, %d patches, each element in one, areas sum to the mesh's",
           what, g.npatches);
    tap_ok(st == RAD_OK && worst <= tol,
           "%s: F_jP on the patch outline = sum of the element columns within %g (%.3g)",
           what, tol, worst);
    radi_ffrow_free(row);
    radi_patch_grid_free(&g);
    free(to);
}

/* The solve from computed columns: the steps and B of the matrix's. */
static void test_matrix_free_solve(const fixture *fx)
{
    rad_ff_options fo;
    rad_solve_options so;
    rad_solve_report r1, r2;
    rad_error err;
    rad_ffrow *row = NULL;
    const size_t n3 = (size_t)fx->n * 3;
    double *rho = malloc(sizeof *rho * n3), *E = malloc(sizeof *E * n3);
    double *B1 = malloc(sizeof *B1 * n3), *B2 = malloc(sizeof *B2 * n3);
    rad_ff_options_init(&fo);
    rad_solve_options_init(&so);
    so.solver = RAD_SOLVER_PROGRESSIVE;
    so.tolerance = 1e-10;
    mesh_arrays(&fx->mesh, rho, E);
    const rad_shoot_source dense = {fx->F, NULL};
    int st = radi_progressive_run(&fx->mesh, &dense, rho, E, &so, B1, &r1, &err);
    if (st == RAD_OK)
        st = radi_ffrow_create(&row, &fx->mesh, &fo, RAD_OCC_AUTO, 0, 0, &err);
    const rad_shoot_source none = {NULL, row};
    if (st == RAD_OK)
        st = radi_progressive_run(&fx->mesh, &none, rho, E, &so, B2, &r2, &err);
    tap_ok(st == RAD_OK && r1.sweeps == r2.sweeps && memcmp(B1, B2, sizeof *B1 * n3) == 0,
           "shooting from computed columns: %d steps and B bit for bit as from the matrix "
           "(%d)", st == RAD_OK ? r2.sweeps : -1, r1.sweeps);
    tap_ok(st == RAD_OK && rel_diff(B2, fx->Bg, n3) <= 1e-8,
           "... and within 1e-8 of gauss (%.3g)", st == RAD_OK ? rel_diff(B2, fx->Bg, n3) : NAN);
    radi_ffrow_free(row);
    free(rho);
    free(E);
    free(B1);
    free(B2);
}

int main(void)
{
    fixture cube;
    if (fixture_load(&cube, "goral1984-cube.scene", 0)) {
        tap_ok(0, "load the shipped cube (top_srcdir = %s)", getenv("top_srcdir"));
        return tap_done();
    }
    test_converges(&cube);
    test_nonreciprocal(&cube);
    test_energy(&cube);
    test_ambient();
    test_trace_and_noconv(&cube);
    test_singular_and_dark();
    test_race(&cube);
    test_columns(&cube, "cube");
    test_patch_columns(&cube, "cube", 1e-6);
    test_matrix_free_solve(&cube);
    fixture_free(&cube);
    fixture blocker;
    if (fixture_load(&blocker, "blocker.scene", 2) == 0) {
        test_columns(&blocker, "blocker (visibility)");
        fixture_free(&blocker);
    } else {
        tap_ok(0, "load the blocker scene");
    }
    if (fixture_load(&blocker, "blocker.scene", 4) == 0) {
        /* the hidden parts of partly occluded pairs are integrated to about
         * 1e-4 in default mode (the fill's own estimates miss the 1e-6
         * promise on them and say so); in reference mode the patch and
         * element solutions agree to 1e-7 */
        test_patch_columns(&blocker, "blocker 4x4 (visibility)", 1e-3);
        fixture_free(&blocker);
    } else {
        tap_ok(0, "load the blocker scene");
    }
    return tap_done();
}
