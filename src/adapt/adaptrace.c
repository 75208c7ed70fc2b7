/* adaptrace.c -- the race of figure 7 with adaptive subdivision.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * `radiosity progress --adaptive` lets one watch adaptive subdivision
 * (Cohen, Chen, Wallace & Greenberg 1988, section 4) work: the shooting
 * methods of the race (progressive.h) run through the adaptive solver
 * itself (adaptive.c, followed by its watcher hook: no second shooting
 * loop), and after each shot and its subdivision this file measures and
 * shows the leaves of that moment.
 *
 *   shooting        radi_solve_adaptive with sort 0 (patches in file order)
 *   sorted          sort 1, the largest unshot power first (what `solve
 *                   --solver progressive --adaptive` runs)
 *   sorted_ambient  the sorted run displayed with the ambient term:
 *                   B'_j = B_j + rho_j Ambient, Ambient = R U / sum A,
 *                   R = 1 / (1 - rho_ave), U the unshot power
 *                   (1988, eqs. 9-13, as progressive.c; rho_ave is the
 *                   area mean over the patches, the same over any leaves)
 *
 * Gathering (Gauss-Seidel) is not run: it updates the rows of a fixed set
 * of elements and has no shot after which to subdivide; its column is NaN.
 *
 * The error.  The shooting order changes where the mesh is refined, so
 * the two orders converge to different patch-element solutions on
 * different leaves.  Each method is measured against its own: the same
 * options run to convergence (the caller hands both in, as the pipeline
 * makes them), projected onto the leaves of step k by adaptproject.c
 * (the area mean of the final leaves inside a leaf; a leaf inside a final
 * leaf takes its value).  Eq. 14 of the band-averaged radiosity and the
 * per-band mean (rmserror.c) then compare, leaf by leaf, with the leaves'
 * areas.  At the step where the solve's convergence test holds the run
 * is the converged one bit for bit, so its error is 0 there; the race
 * stops it there, and later rows repeat that step (a converged solve does
 * not shoot again).
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adapt/adaptive.h"
#include "adapt/adaptmesh.h"
#include "adapt/adaptproject.h"
#include "adapt/adaptrace.h"
#include "compare/compare.h"
#include "util/util.h"

#define NB RAD_BANDS

/* One method's run and what it measures with. */
typedef struct run {
    const rad_adapt_race *ar;
    const rad_race_options *opt;
    int sort;                   /* 0: file order; 1: sorted (and its ambient) */
    double *rms;
    int *reached;
    double ambient_R[NB], total_area; /* eq. 10-11: R = 1 / (1 - rho_ave) */
    double scale;               /* max |Bref| of the converged leaves */
    size_t nn;                  /* nodes */
    double *Rn;                 /* nodes x NB: the reference on every node */
    double *Bn;                 /* nodes x NB: displayed B (ambient) */
    int nl;                     /* leaves now */
    double *area, *rho, *B, *ref; /* leaves now (nl, nl x NB) */
    rad_error *err;
    rad_status st;              /* a failure inside the watcher */
} run;

static void run_free(run *r)
{
    free(r->Rn);
    free(r->Bn);
    free(r->area);
    free(r->rho);
    free(r->B);
    free(r->ref);
}

/* Area, reflectance, B and reference of the leaves, in node order (the
 * leaf mesh's element order, adaptmesh.h). */
static void gather_leaves(run *r, const rad_adapt_view *v)
{
    const rad_mesh *m = &v->nodes->mesh;
    int nl = 0;
    for (size_t j = 0; j < r->nn; j++)
        nl += v->leaf[j] != 0;
    r->nl = nl;
    for (size_t j = 0, i = 0; j < r->nn; j++) {
        if (!v->leaf[j])
            continue;
        r->area[i] = m->elements[j].area;
        for (int b = 0; b < NB; b++) {
            r->rho[i + (size_t)b * nl] = m->elements[j].reflect[b];
            r->B[i + (size_t)b * nl] = v->B[j + (size_t)b * r->nn];
            r->ref[i + (size_t)b * nl] = r->Rn[j + (size_t)b * r->nn];
        }
        i++;
    }
}

/* The reference on the nodes and the scratch, at step 0 (when the nodes
 * are first seen). */
static rad_status run_start(run *r, const rad_adapt_view *v)
{
    const rad_adapt_ref *ref = &r->ar->ref[r->sort];
    const size_t nn = (size_t)v->nodes->mesh.nelements, n = nn ? nn : 1;
    r->nn = nn;
    r->Rn = malloc(sizeof *r->Rn * n * NB);
    r->Bn = malloc(sizeof *r->Bn * n * NB);
    r->area = malloc(sizeof *r->area * n);
    r->rho = malloc(sizeof *r->rho * n * NB);
    r->B = malloc(sizeof *r->B * n * NB);
    r->ref = malloc(sizeof *r->ref * n * NB);
    if (!r->Rn || !r->Bn || !r->area || !r->rho || !r->B || !r->ref)
        return radi_fail(r->err, RAD_ERR_NOMEM, "out of memory for %zu adaptive elements", nn);
    r->scale = 0;
    for (size_t k = 0; k < (size_t)ref->mesh->nelements * NB; k++)
        r->scale = fmax(r->scale, fabs(ref->B[k]));
    return radi_adapt_project(v->nodes, ref->mesh, ref->B, ref->level, r->Rn, r->err);
}

/* B' = B + rho Ambient on the leaves (1988, eq. 13), Ambient = R U / sum A
 * (eqs. 9, 12). */
static void add_ambient(run *r, const rad_adapt_view *v)
{
    for (int b = 0; b < NB; b++) {
        const double amb = r->total_area > 0 ? r->ambient_R[b] * v->unshot[b] / r->total_area : 0;
        for (int i = 0; i < r->nl; i++)
            r->B[i + (size_t)b * r->nl] += r->rho[i + (size_t)b * r->nl] * amb;
    }
}

/* The displayed B of the leaves back on the nodes, for the leaf mesh. */
static void leaves_to_nodes(run *r, const rad_adapt_view *v)
{
    for (size_t j = 0, i = 0; j < r->nn; j++)
        if (v->leaf[j]) {
            for (int b = 0; b < NB; b++)
                r->Bn[j + (size_t)b * r->nn] = r->B[i + (size_t)b * r->nl];
            i++;
        }
}

/* The leaf mesh of the view with the displayed B, to the snapshot callback. */
static int show(run *r, const rad_adapt_view *v, int m, int k)
{
    rad_mesh mesh;
    double *B, *Bv;
    int *level;
    leaves_to_nodes(r, v);
    r->st = radi_adapt_leaf_mesh(v->nodes, v->leaf, r->Bn, &mesh, &B, &Bv, &level, r->err);
    if (r->st != RAD_OK)
        return 1;
    const rad_adapt_frame f = {&mesh, B, Bv, r->ref, level};
    const int stop = r->ar->snapshot(r->ar->snapshot_user, m, k, &f);
    if (stop)
        r->st = radi_fail(r->err, RAD_ERR_INVALID, "interrupted");
    rad_mesh_free(&mesh);
    free(B);
    free(Bv);
    free(level);
    return stop;
}

/* Method m's error after step v->step (and, when the run ends there
 * converged, every later step); snapshots on the way.  Non-zero: stop. */
static int record(run *r, const rad_adapt_view *v, int m)
{
    const rad_race_options *o = r->opt;
    const rad_rms_input in = {r->nl, r->area, r->total_area, r->rho, NULL, r->B, r->ref};
    const double e14 = radi_rms_eq14(&in), eb = radi_rms_bands(&in);
    double most = 0;
    for (size_t k = 0; k < (size_t)r->nl * NB; k++)
        most = fmax(most, fabs(r->B[k] - r->ref[k]));
    const int last = v->converged ? o->steps : v->step;
    for (int k = v->step; k <= last; k++) {
        const size_t at = (size_t)k + (size_t)m * (size_t)(o->steps + 1);
        r->rms[at] = e14;
        if (o->rms_bands)
            o->rms_bands[at] = eb;
        if (r->reached[m] < 0 && most <= o->reach * r->scale)
            r->reached[m] = k;
        if (r->ar->snapshot && radi_race_snapshot_due(o, k) && show(r, v, m, k))
            return 1;
    }
    return 0;
}

/* The watcher (adaptive.h): measure, show, and end the run after the
 * race's last step. */
static int on_step(void *user, const rad_adapt_view *v)
{
    run *r = user;
    const rad_race_options *o = r->opt;
    if (v->step == 0 && (r->st = run_start(r, v)) != RAD_OK)
        return 1;
    gather_leaves(r, v);
    if (record(r, v, r->sort ? RAD_RACE_SORTED : RAD_RACE_SHOOTING))
        return 1;
    if (r->sort) {
        add_ambient(r, v);
        if (record(r, v, RAD_RACE_SORTED_AMBIENT))
            return 1;
    }
    const int done = (r->sort ? o->steps : 0) + (v->converged ? o->steps : v->step);
    if (o->progress && o->progress(o->progress_user, "race", done, 2.0 * o->steps)) {
        r->st = radi_fail(r->err, RAD_ERR_INVALID, "interrupted");
        return 1;
    }
    return v->step >= o->steps;
}

/* R = 1 / (1 - rho_ave) per band, rho_ave the area mean of rho over the
 * patches (1988, eqs. 10-11), and the total area. */
static void ambient_init(run *r, const rad_mesh *m)
{
    r->total_area = 0;
    for (int i = 0; i < m->nelements; i++)
        r->total_area += m->elements[i].area;
    for (int b = 0; b < NB; b++) {
        double s = 0;
        for (int i = 0; i < m->nelements; i++)
            s += m->elements[i].reflect[b] * m->elements[i].area;
        const double ave = r->total_area > 0 ? s / r->total_area : 0;
        r->ambient_R[b] = ave < 1 ? 1 / (1 - ave) : 0;
    }
}

/* One shooting order through the adaptive solver, watched. */
static rad_status race_one(const rad_adapt_race *ar, const rad_race_options *opt, int sort,
                           double *rms, int *reached, rad_error *err)
{
    run r;
    memset(&r, 0, sizeof r);
    r.ar = ar;
    r.opt = opt;
    r.sort = sort;
    r.rms = rms;
    r.reached = reached;
    r.err = err;
    r.st = RAD_OK;
    ambient_init(&r, ar->start);
    rad_solve_options so = *ar->solve;
    so.sort = sort;
    so.on_shot = NULL;
    so.progress = NULL;
    rad_status st = radi_solve_adaptive_watch(ar->start, ar->ff, &so, on_step, &r, NULL, NULL,
                                             NULL, err);
    if (st == RAD_OK && r.st != RAD_OK)
        st = r.st;
    else if (st == RAD_OK && r.nn == 0)
        st = radi_fail(err, RAD_ERR_INVALID, "the adaptive run showed no step");
    run_free(&r);
    return st;
}

rad_status radi_adapt_race_run(const rad_adapt_race *ar, const rad_race_options *opt,
                              double *rms, int *reached, rad_error *err)
{
    const size_t rows = (size_t)opt->steps + 1;
    if (opt->steps < 1 || !(opt->reach > 0) || opt->patches)
        return radi_fail(err, RAD_ERR_INVALID, "the adaptive race needs at least one step, "
                        "reach > 0 and its elements shooting (no patches)");
    for (int m = 0; m < RAD_RACE_METHODS; m++)
        reached[m] = -1;
    for (size_t k = 0; k < rows; k++) { /* gathering: not run */
        rms[k] = NAN;
        if (opt->rms_bands)
            opt->rms_bands[k] = NAN;
    }
    rad_status st = RAD_OK;
    for (int sort = 0; sort <= 1 && st == RAD_OK; sort++)
        st = race_one(ar, opt, sort, rms, reached, err);
    return st;
}
