/* pipeline.c -- the whole run, scene to smoothed radiosity, as one call.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The order is the data flow of doc/design.md, "The program and its data
 * flow"; each stage owns its data structure and hands it on.  The memory
 * check comes first and from the scene alone: element counts follow from
 * the mesh specifications, so a mesh that cannot be solved is refused
 * before it is built (a 4000x4000 mesh of the cube would otherwise take
 * 24 s and 16 GB to mesh, only to be refused).  Times are wall-clock
 * seconds (CLOCK_MONOTONIC).
 */
#include <config.h>

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "radiosity/pipeline.h"
#include "radiosity/pipeline.h"
#include "mesh/mesh.h"
#include "adapt/adapt.h"
#include "solve/solve.h"
#include "hemicube/hemicube.h"
#include "util/util.h"


void rad_pipeline_options_init(rad_pipeline_options *opt)
{
    memset(opt, 0, sizeof *opt);
    rad_ff_options_init(&opt->ff);
    rad_solve_options_init(&opt->solve);
    opt->crease = RAD_CREASE_AUTO;
}

const char *rad_matrix_name(int mode)
{
    static const char *const names[] = {"auto", "dense", "none"};
    return mode >= 0 && mode <= RAD_MATRIX_NONE ? names[mode] : NULL;
}

/* Dense or none: what the options ask, auto deciding by the memory (the
 * dense peak in at most half of what is allowed: room for the rest of the
 * machine's work).  Only progressive refinement can do without F. */
static rad_matrix_mode choose_matrix(const rad_pipeline_options *opt, double dense_bytes,
                                     double limit)
{
    if (opt->solve.solver != RAD_SOLVER_PROGRESSIVE || opt->solve.bounces >= 0 ||
        opt->keep_form_factors)
        return RAD_MATRIX_DENSE;
    if (opt->matrix != RAD_MATRIX_AUTO)
        return opt->matrix;
    return limit > 0 && dense_bytes > 0.5 * limit ? RAD_MATRIX_NONE : RAD_MATRIX_DENSE;
}

/* The estimate checked before meshing: rad_solve_bytes for the dense
 * path, radi_matrix_free_bytes without the matrix. */
static rad_status check_size(const rad_scene *scene, const rad_pipeline_options *opt,
                             rad_result *r, rad_error *err)
{
    double n = rad_scene_element_count(scene);
    size_t ne, nv, ni;
    char what[128];
    if (n > INT_MAX || radi_mesh_count(scene, &ne, &nv, &ni) != RAD_OK)
        return radi_fail(err, RAD_ERR_TOOBIG, "the scene's meshes make %.0f elements; "
                         "elements, vertices and vertex indices must each number at most "
                         "%d; use a coarser `mesh`", n, (int)RADI_MESH_COUNT_MAX);
    if (opt->matrix == RAD_MATRIX_NONE && (opt->solve.solver != RAD_SOLVER_PROGRESSIVE ||
                                           opt->solve.bounces >= 0 || opt->keep_form_factors))
        return radi_fail(err, RAD_ERR_INVALID, "`matrix` none works with `solver` progressive "
                        "only, and cannot write the form factors");
    if (opt->solve.adaptive &&
        (opt->solve.solver != RAD_SOLVER_PROGRESSIVE || opt->solve.bounces >= 0 ||
         opt->keep_form_factors || opt->matrix == RAD_MATRIX_DENSE || opt->solve.patches ||
         opt->solve.patch_p > 0))
        return radi_fail(err, RAD_ERR_INVALID, "adaptive subdivision works with `solver` "
                        "progressive only, its elements shooting (no `patches`), and "
                        "computes its form factors on the fly (no `matrix` dense, no "
                        "`keep_form_factors`)");
    if (opt->solve.adaptive) { /* every node a run may make (adaptnodes.h) */
        const double nodes = n * (ldexp(1, 2 * (opt->solve.max_depth + 1)) - 1) / 3;
        r->matrix = RAD_MATRIX_NONE;
        r->memory_available = rad_memory_limit();
        r->memory_bytes = radi_matrix_free_bytes(nodes, nodes, 0);
        snprintf(what, sizeof what, "%.0f possible adaptive elements", nodes);
        return rad_memory_check(r->memory_bytes, what, &r->memory_available, err);
    }
    const double dense = rad_solve_bytes_for((int)n, &opt->solve);
    r->memory_available = rad_memory_limit();
    r->matrix = choose_matrix(opt, dense, r->memory_available);
    if (r->matrix == RAD_MATRIX_DENSE) {
        r->memory_bytes = dense;
        snprintf(what, sizeof what, "%.0f elements (%.0f x 8 N^2 bytes of matrices for %s)", n,
                 floor(dense / (8 * n * n + 1)),
                 opt->solve.bounces >= 0 ? "`bounces`" : rad_solver_name(opt->solve.solver));
    } else {
        const double np = opt->solve.patch_p > 0 ? (double)scene->nsurfaces *
                                                       opt->solve.patch_p * opt->solve.patch_q
                                                 : 0;
        r->memory_bytes = radi_matrix_free_bytes(n, (double)nv, np < n ? np : n);
        snprintf(what, sizeof what, "%.0f elements without a stored matrix (O(N))", n);
    }
    if (opt->ff.method == RAD_FF_HEMICUBE) { /* and one R x R picture at a time (hemicube.c) */
        const double R = opt->ff.resolution;
        const size_t len = strlen(what);
        r->memory_bytes += RAD_HEMICUBE_PIXEL_BYTES * R * R;
        snprintf(what + len, sizeof what - len, " and a hemicube picture of %.0f x %.0f", R, R);
    }
    rad_status st = rad_memory_check(r->memory_bytes, what, &r->memory_available, err);
    if (st == RAD_ERR_TOOBIG && r->matrix == RAD_MATRIX_DENSE && !opt->keep_form_factors &&
        opt->solve.bounces < 0 && !opt->solve.patches && opt->solve.patch_p <= 0) {
        /* the way round the matrix, where nothing asks for it */
        const size_t len = strlen(err->message);
        snprintf(err->message + len, sizeof err->message - len,
                 ", or `solver` progressive with `matrix` none (no stored matrix: %.0f MiB)",
                 radi_matrix_free_bytes(n, (double)nv, 0) / 1048576.0);
    }
    return st;
}

static rad_status allocate(rad_result *r, rad_error *err)
{
    const size_t n = (size_t)r->mesh.nelements;
    const size_t nv = (size_t)r->mesh.nvertices;
    if (r->matrix == RAD_MATRIX_DENSE)
        r->F = malloc(sizeof *r->F * (n ? n * n : 1));
    r->B = malloc(sizeof *r->B * (n ? n : 1) * RAD_BANDS);
    r->Bv = malloc(sizeof *r->Bv * (nv ? nv : 1) * RAD_BANDS);
    if ((!r->F && r->matrix == RAD_MATRIX_DENSE) || !r->B || !r->Bv)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %zu elements", n);
    return RAD_OK;
}

/* Smooth B and count its negative values (a solved run). */
static rad_status finish(const rad_scene *scene, rad_result *r,
                         const rad_pipeline_options *opt, double t_solved, rad_error *err)
{
    for (size_t k = 0; k < (size_t)r->mesh.nelements * RAD_BANDS; k++)
        r->b_negative += r->B[k] < 0;
    rad_smooth_vertices_rule(&r->mesh, r->B, r->Bv, opt->vertex_rule);
    rad_status st = rad_smooth_across(scene, &r->mesh, opt->crease, r->Bv, err);
    r->t_smooth = radi_seconds() - t_solved;
    return st;
}

/* --matrix none: the form factors are computed inside the solve, shot by
 * shot (solvefree.h); their statistics come with the solve. */
static rad_status run_matrix_free(const rad_scene *scene, rad_result *r,
                                  const rad_pipeline_options *opt, double t1, rad_error *err)
{
    rad_solve_options so = opt->solve;
    if (!so.progress) {
        so.progress = opt->ff.progress;
        so.progress_user = opt->ff.progress_user;
    }
    rad_status st = radi_solve_matrix_free(&r->mesh, &opt->ff, &so, r->B, &r->solve, &r->ff, err);
    double t3 = radi_seconds();
    r->t_solve = t3 - t1;
    r->ff_done = r->solve_done = 1;
    if (st == RAD_OK)
        st = finish(scene, r, opt, t3, err);
    return st;
}

/* --adaptive: the solve builds its own mesh of leaves over the starting
 * one (adaptive.h), with its smoothed vertex radiosity; the result takes
 * that mesh in place of the starting one. */
static rad_status run_adaptive(rad_result *r, const rad_pipeline_options *opt, double t1,
                               rad_error *err)
{
    rad_solve_options so = opt->solve;
    rad_adapt_out out;
    if (opt->crease > 0) /* it would move corners under hanging vertices */
        return radi_fail(err, RAD_ERR_INVALID, "a crease angle cannot be used with adaptive "
                                               "subdivision");
    if (!so.progress) {
        so.progress = opt->ff.progress;
        so.progress_user = opt->ff.progress_user;
    }
    rad_status st = radi_solve_adaptive(&r->mesh, &opt->ff, &so, &out, &r->solve, &r->ff, err);
    double t3 = radi_seconds();
    r->t_solve = t3 - t1;
    r->ff_done = r->solve_done = 1;
    if (st != RAD_OK)
        return st;
    rad_mesh_free(&r->mesh);
    free(r->B);
    free(r->Bv);
    r->mesh = out.mesh;
    r->B = out.B;
    r->Bv = out.Bv;
    r->level = out.level;
    r->splits = out.splits;
    for (size_t k = 0; k < (size_t)r->mesh.nelements * RAD_BANDS; k++)
        r->b_negative += r->B[k] < 0;
    return RAD_OK;
}

/* A scene with absent objects is solved without them (radiosity-scene(5)):
 * the run works on the copy of its present surfaces, whose numbering the
 * result's mesh then follows. */
rad_status rad_pipeline_present(const rad_scene *scene, const rad_pipeline_options *opt,
                                rad_result *r, rad_error *err, rad_pipeline_fn run)
{
    if (!rad_scene_has_absent(scene))
        return run(scene, opt, r, err);
    rad_scene present;
    memset(r, 0, sizeof *r);
    rad_status st = rad_scene_present_copy(scene, NULL, &present, err);
    if (st != RAD_OK)
        return st;
    if (present.nsurfaces == 0)
        st = radi_fail(err, RAD_ERR_INVALID, "%s: every surface belongs to an absent object",
                      scene->filename ? scene->filename : "-");
    else
        st = run(&present, opt, r, err);
    rad_scene_free(&present);
    return st;
}

static rad_status run_present(const rad_scene *scene, const rad_pipeline_options *opt,
                              rad_result *r, rad_error *err);

rad_status rad_pipeline_run(const rad_scene *scene, const rad_pipeline_options *opt,
                            rad_result *r, rad_error *err)
{
    return rad_pipeline_present(scene, opt, r, err, run_present);
}

static rad_status run_present(const rad_scene *scene, const rad_pipeline_options *opt,
                              rad_result *r, rad_error *err)
{
    memset(r, 0, sizeof *r);
    rad_status st = check_size(scene, opt, r, err);
    double t0 = radi_seconds();
    if (st == RAD_OK)
        st = rad_mesh_build(&r->mesh, scene, err);
    double t1 = radi_seconds();
    r->t_mesh = t1 - t0;
    if (st == RAD_OK)
        st = allocate(r, err);
    if (st == RAD_OK && opt->solve.adaptive)
        return run_adaptive(r, opt, t1, err);
    if (st == RAD_OK && r->matrix == RAD_MATRIX_NONE)
        return run_matrix_free(scene, r, opt, t1, err);
    if (st == RAD_OK)
        st = rad_ff_matrix(&r->mesh, &opt->ff, r->F, NULL, &r->ff, err);
    double t2 = radi_seconds();
    r->t_formfactor = t2 - t1;
    if (st != RAD_OK)
        return st;
    r->ff_done = 1;
    rad_solve_options so = opt->solve;
    if (!so.progress) {
        so.progress = opt->ff.progress;
        so.progress_user = opt->ff.progress_user;
    }
    so.ff_row_error = r->ff.max_row_error; /* NaN in classic: no bound */
    st = rad_solve(&r->mesh, r->F, &so, r->B, &r->solve, err);
    double t3 = radi_seconds();
    r->t_solve = t3 - t2;
    r->solve_done = 1;
    if (st == RAD_OK)
        st = finish(scene, r, opt, t3, err);
    if (!opt->keep_form_factors) {
        free(r->F);
        r->F = NULL;
    }
    return st;
}

void rad_result_free(rad_result *r)
{
    free(r->F);
    free(r->B);
    free(r->Bv);
    free(r->level);
    rad_mesh_free(&r->mesh);
    memset(r, 0, sizeof *r);
}
