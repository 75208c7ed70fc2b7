/* cmd_progress.c -- `radiosity progress`: the convergence race of Cohen et al. 1988.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Figure 7 of Cohen, Chen, Wallace & Greenberg, "A Progressive Refinement
 * Approach to Fast Radiosity Image Generation", SIGGRAPH 1988: the
 * area-weighted RMS error (their eq. 14) against the converged solution,
 * step by step, of gathering (Gauss-Seidel, one element row per step),
 * shooting in file order, sorted shooting, and sorted shooting shown with
 * the ambient term.  The converged solution is the gauss solve.  scene ->
 * mesh -> form factors -> gauss -> race (progressive.c) -> TSV, plot,
 * snapshots.  Only parsing, dispatch and messages live here.
 *
 * The error is eq. 14 of the band-averaged radiosity (rmserror.c), the
 * per-band mean beside it; the plot is the paper's figure 7 on a log axis
 * or, normalised by the converged solution's own RMS, on a linear one.
 * The snapshots are the paper's figures 2-5 (sorted_ambient at 1, 2, 24,
 * 100 steps) and 8 (every method at 2), each with, on request, its
 * pseudo-colour error picture (errcolour.c) and the element table of the
 * radiosity it shows, so that what a picture claims can be checked
 * (progress_snap.c writes them).  With --adaptive the shooting methods
 * run with adaptive subdivision and gathering is left out
 * (progress_adaptive.c: the table, the plot and the summary here skip
 * its column).
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "render/render.h"
#include "fill/fill.h"
#include "cli/progress_adaptive.h"
#include "cli/progress_snap.h"
#include "solve/solve.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/solve.h"
#include "radiosity/render.h"
#include "radiosity/pipeline.h"
#include "radiosity/render.h"
#include "compare/compare.h"

#define DEFAULT_STEPS_CAP 10000 /* default --steps: 2 x elements, at most this */
#define MAX_STEPS 10000000
#define PLOT_WIDTH 800
#define PLOT_HEIGHT 500

enum {
    OPT_STEPS = 1200,
    OPT_PLOT,
    OPT_REACH,
    OPT_SNAPSHOTS,
    OPT_SNAPSHOT_PREFIX,
    OPT_RACE_PATCHES,
    OPT_RACE_MATRIX,
    OPT_SNAPSHOTS_AT,
    OPT_EXPOSURE_FROM,
    OPT_ERROR_IMAGES,
    OPT_SNAPSHOT_ELEMENTS,
    OPT_PLOT_AXIS,
    OPT_PLOT_NORMALISED
};

#define MAX_SNAPSHOTS_AT 256

typedef struct progress_args {
    cli_common common;
    rad_race_options race;      /* steps 0: the default */
    const char *output;         /* TSV, NULL: standard output */
    const char *plot;           /* PNG, or NULL */
    const char *prefix;         /* snapshot file prefix */
    rad_matrix_mode matrix;     /* --matrix; auto decided in prepare() */
    int at[MAX_SNAPSHOTS_AT];   /* --snapshots-at, ascending */
    int steps_given;
    rad_exposure_from exposure_from; /* of the snapshots */
    int exposure_from_given;
    int error_images;           /* --error-images */
    int snapshot_elements;      /* --snapshot-elements */
    int plot_linear;            /* --plot-axis linear */
    int plot_axis_given;
    int plot_normalised;        /* --plot-normalised */
    progress_adaptive adaptive; /* --adaptive and its options */
} progress_args;

/* The first method of the table: --adaptive leaves gathering out. */
static int first_method(const progress_args *a)
{
    return a->adaptive.solve.adaptive ? RAD_RACE_SHOOTING : RAD_RACE_GATHERING;
}

static void help(void)
{
    printf("Usage: radiosity progress [OPTIONS] SCENE\n"
           "The convergence race of Cohen, Chen, Wallace & Greenberg 1988 (figure 7):\n"
           "the area-weighted RMS error (their eq. 14) against the gauss solution,\n"
           "step by step, of four methods, all from B = E:\n"
           "  gathering       Gauss-Seidel, one element row per step\n"
           "  shooting        progressive refinement, shooters in file order\n"
           "  sorted          the largest unshot power shoots first\n"
           "  sorted_ambient  the same, displayed with the ambient term\n"
           "The table (TSV, %%.17g) has the columns step gathering shooting sorted\n"
           "sorted_ambient (eq. 14: the RMS error of the radiosity averaged over the\n"
           "bands), then gathering_bands ... sorted_ambient_bands (the RMS error of\n"
           "each band, averaged over the bands), one row per step from 0.  A summary\n"
           "goes to standard error.\n"
           "\n"
           "Options:\n"
           "      --steps N           steps per method (default: 2 x the element\n"
           "                          count, at most %d)\n"
           "  -o, --output FILE       the table; '-' or none: standard output\n"
           "      --plot FILE.png     the four curves (eq. 14) on a log-scale error axis\n"
           "      --plot-axis AXIS    log (default) or linear: the error axis of --plot\n"
           "      --plot-normalised   --plot divides each curve by the RMS of the\n"
           "                          converged solution (eq. 14 against B = 0), as a\n"
           "                          fraction of it; with --plot-axis linear this is\n"
           "                          the paper's figure 7\n"
           "      --reach TOL         the summary gives the first step of each method\n"
           "                          within TOL (max norm, relative) of the gauss\n"
           "                          solution (default 1e-6)\n"
           "      --patches           the shooters shoot as patches (whole surfaces)\n"
           "      --matrix MODE       dense (fill F first; the reference is the gauss\n"
           "                          solution), none (each step computes the row or\n"
           "                          column it needs and forgets it: O(N) memory; the\n"
           "                          reference is progressive refinement converged to\n"
           "                          1e-12 without a matrix) or auto (default: dense\n"
           "                          when 8 N^2 bytes fit in half the memory allowed)\n"
           "      --snapshots K       render every K steps of every method (the\n"
           "                          scene's camera, 512 x 512, the automatic exposure\n"
           "                          of the converged solution, see --exposure-from)\n"
           "                          to PREFIX-METHOD-STEP.png\n"
           "      --snapshots-at LIST render at these steps of every method (comma-\n"
           "                          separated, e.g. 1,2,24,100 as the paper's figures\n"
           "                          2-5; the sorted_ambient images show the ambient\n"
           "                          term); --steps grows to the last one if not given\n"
           "      --snapshot-prefix P file prefix of the snapshots (default 'progress')\n"
           CLI_METHOD_HELP
           "      --error-images      beside each snapshot, PREFIX-METHOD-STEP-error.png:\n"
           "                          each element in a pseudo-colour of the relative\n"
           "                          error e = (Y - Yc) / Yc of its band-averaged\n"
           "                          radiosity Y as displayed against the converged\n"
           "                          Yc (flat): grey (128,128,128) where e = 0, moving\n"
           "                          linearly to red (255,0,0) at e >= +50%% (over)\n"
           "                          and to blue (0,0,255) at e <= -50%% (under), as\n"
           "                          the paper's figures 2-5\n"
           "      --snapshot-elements beside each snapshot, PREFIX-METHOD-STEP.tsv: the\n"
           "                          radiosity it shows as an element table (the\n"
           "                          format of 'solve --elements')\n"
           CLI_EXPOSURE_FROM_HELP
           PROGRESS_ADAPTIVE_HELP
           CLI_COMMON_HELP
           "\n"
           "Examples:\n"
           "  radiosity progress --mesh 3x3 data/goral1984-cube.scene --plot \\\n"
           "      race.png\n"
           "  radiosity progress --patches --mesh 3x3 data/cornell-box.scene -o \\\n"
           "      race.tsv\n"
           "  radiosity progress --mesh 3x3 --snapshots 24 data/cornell-box.scene\n"
           "  radiosity progress --mesh 3x3 --snapshots-at 1,2,24,100 \\\n"
           "      --snapshot-prefix fig data/cornell-box.scene\n"
           "  radiosity progress --matrix none --mesh 5x5 --steps 100 \\\n"
           "      data/goral1984-cube.scene\n"
           "  radiosity progress --adaptive --mesh 4x4 --snapshots 20 \\\n"
           "      --snapshot-elements data/blocker.scene\n"
           "\n"
           "A regular file is written to a temporary beside it and renamed at the\n"
           "end: a failed or interrupted run leaves the old file whole; a device or\n"
           "FIFO is written in place.  Exit status: 0 on success, 1 on an error, 2\n"
           "on a usage error; 128 + signal when interrupted.\n",
           DEFAULT_STEPS_CAP);
}

/* --snapshots-at 1,2,24,100: ascending steps >= 0; 0 or 2 (printed). */
static int parse_steps(progress_args *a, const char *arg)
{
    char buf[4096], *save = NULL;
    int n = 0;
    if (strlen(arg) >= sizeof buf || !*arg || arg[0] == ',' || strstr(arg, ",,"))
        goto bad; /* strtok_r would skip the empty item */
    strcpy(buf, arg);
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        int k;
        if (n == MAX_SNAPSHOTS_AT || cli_parse_int(t, 0, MAX_STEPS, &k) ||
            (n > 0 && k <= a->at[n - 1]))
            goto bad;
        a->at[n++] = k;
    }
    if (n == 0 || arg[strlen(arg) - 1] == ',')
        goto bad;
    a->race.snapshot_at = a->at;
    a->race.nsnapshot_at = n;
    return 0;
bad:
    cli_error("--snapshots-at takes ascending steps from 0 to %d separated by commas (at "
              "most %d), not '%s'", MAX_STEPS, MAX_SNAPSHOTS_AT, arg);
    return 2;
}

/* 0 handled, 1 not ours, 2 usage error (printed). */
static int parse_option(progress_args *a, int opt, const char *arg)
{
    switch (opt) {
    case OPT_STEPS:
        a->steps_given = 1;
        if (cli_parse_int(arg, 1, MAX_STEPS, &a->race.steps)) {
            cli_error("--steps takes a whole number from 1 to %d, not '%s'", MAX_STEPS, arg);
            return 2;
        }
        return 0;
    case 'o':
        a->output = arg;
        return 0;
    case OPT_PLOT:
        a->plot = arg;
        return cli_png_name_check(arg, "--plot") ? 2 : 0;
    case OPT_REACH:
        if (cli_parse_double(arg, &a->race.reach) || !(a->race.reach > 0) || a->race.reach >= 1) {
            cli_error("--reach takes a number between 0 and 1, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_SNAPSHOTS:
        if (cli_parse_int(arg, 1, MAX_STEPS, &a->race.snapshot_every)) {
            cli_error("--snapshots takes a positive whole number, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_SNAPSHOTS_AT:
        return parse_steps(a, arg);
    case OPT_SNAPSHOT_PREFIX:
        a->prefix = arg;
        return 0;
    case OPT_EXPOSURE_FROM:
        a->exposure_from_given = 1;
        return cli_parse_exposure_from(arg, &a->exposure_from);
    case OPT_ERROR_IMAGES:
        a->error_images = 1;
        return 0;
    case OPT_SNAPSHOT_ELEMENTS:
        a->snapshot_elements = 1;
        return 0;
    case OPT_PLOT_NORMALISED:
        a->plot_normalised = 1;
        return 0;
    case OPT_PLOT_AXIS:
        if (strcmp(arg, "log") == 0 || strcmp(arg, "linear") == 0) {
            a->plot_linear = strcmp(arg, "linear") == 0;
            a->plot_axis_given = 1;
            return 0;
        }
        cli_error("--plot-axis takes log or linear, not '%s'", arg);
        return 2;
    case OPT_RACE_PATCHES:
        a->race.patches = 1;
        return 0;
    case OPT_RACE_MATRIX:
        for (int m = RAD_MATRIX_AUTO; m <= RAD_MATRIX_NONE; m++)
            if (strcmp(arg, rad_matrix_name(m)) == 0) {
                a->matrix = (rad_matrix_mode)m;
                return 0;
            }
        cli_error("--matrix takes none, dense or auto, not '%s'", arg);
        return 2;
    default: {
        const int r = progress_adaptive_option(&a->adaptive, opt, arg);
        return r != 1 ? r : cli_common_option(&a->common, opt, arg);
    }
    }
}

/* ---- snapshots (progress_snap.c) ------------------------------------------ */

/* The fixed mesh's snapshots: its vertex radiosity smoothed from B. */
typedef struct snap_ctx {
    progress_snap snap;
    const rad_mesh *mesh;
    double *Bv;
    const double *Bref;         /* the converged solution */
} snap_ctx;

static int snapshot(void *user, int method, int step, const double *B)
{
    snap_ctx *c = user;
    rad_smooth_vertices(c->mesh, B, c->Bv);
    const progress_frame f = {c->mesh, B, c->Bv, c->Bref, NULL};
    return progress_snap_write(&c->snap, method, step, &f);
}

/* ---- outputs --------------------------------------------------------------- */

typedef struct table_ctx {
    const double *rms, *rms_bands;
    int steps;
    int first;                  /* the first method written */
} table_ctx;

static int write_table_to(FILE *out, const void *ctx)
{
    const table_ctx *t = ctx;
    const size_t rows = (size_t)t->steps + 1;
    fprintf(out, "step");
    for (int m = t->first; m < RAD_RACE_METHODS; m++)
        fprintf(out, "\t%s", radi_race_name(m));
    for (int m = t->first; m < RAD_RACE_METHODS; m++)
        fprintf(out, "\t%s_bands", radi_race_name(m));
    fputc('\n', out);
    for (size_t k = 0; k < rows; k++) {
        fprintf(out, "%zu", k);
        for (int m = t->first; m < RAD_RACE_METHODS; m++)
            fprintf(out, "\t%.17g", t->rms[k + (size_t)m * rows]);
        for (int m = t->first; m < RAD_RACE_METHODS; m++)
            fprintf(out, "\t%.17g", t->rms_bands[k + (size_t)m * rows]);
        fputc('\n', out);
    }
    return ferror(out) ? -1 : 0;
}

typedef struct plot_ctx {
    const double *rms;
    int steps;
    const char *title;
    int linear;                 /* a linear error axis, else log */
    double scale;               /* > 0: the curves divided by it */
    int first;                  /* the first method drawn */
} plot_ctx;

/* Figure 7 of Cohen et al. 1988: the RMS error of each method against the
 * step, on a log axis (steps where it is 0 are not drawn) or a linear one,
 * in the unit of B or divided by the RMS of the converged solution. */
static int write_plot_to(FILE *out, const void *ctx)
{
    static const char *const label[RAD_RACE_METHODS] = {
        "gathering (Gauss-Seidel)", "shooting, file order", "shooting, sorted",
        "sorted + ambient"};
    const plot_ctx *p = ctx;
    const size_t rows = (size_t)p->steps + 1;
    rad_series s[RAD_RACE_METHODS];
    rad_error err;
    double *x = malloc(sizeof *x * rows * (1 + (p->scale > 0 ? RAD_RACE_METHODS : 0)));
    if (!x) {
        cli_error("out of memory for the plot");
        return -1;
    }
    for (size_t k = 0; k < rows; k++)
        x[k] = (double)k;
    for (int m = p->first; m < RAD_RACE_METHODS; m++) {
        const double *y = p->rms + (size_t)m * rows;
        if (p->scale > 0) { /* normalised: eq. 14 over the converged RMS */
            double *yn = x + rows * (size_t)(1 + m);
            for (size_t k = 0; k < rows; k++)
                yn[k] = y[k] / p->scale;
            y = yn;
        }
        s[m - p->first] = (rad_series){label[m], x, y, (int)rows};
    }
    const rad_plot_spec spec = {p->title, "shooting or gathering steps",
                                p->scale > 0 ? "RMS error (eq. 14) / RMS of the converged B"
                                             : "RMS error of B (eq. 14)",
                                0, !p->linear, PLOT_WIDTH, PLOT_HEIGHT};
    rad_status st = radi_plot_xy(s, RAD_RACE_METHODS - p->first, &spec, out, &err);
    free(x);
    if (st != RAD_OK) {
        cli_error_rec(&err);
        return -1;
    }
    return 0;
}

/* Shooters that emit: elements, or surfaces with --patches. */
static int light_sources(const rad_mesh *m, int patches)
{
    int count = 0;
    for (int s = 0; s < (patches ? m->nsurfaces : m->nelements); s++) {
        int lo = patches ? m->surface_first[s] : s, hi = patches ? m->surface_first[s + 1] : s + 1;
        int lit = 0;
        for (int i = lo; i < hi; i++)
            for (int b = 0; b < RAD_BANDS; b++)
                lit |= m->elements[i].emit[b] > 0;
        count += lit;
    }
    return count;
}

static void summary(const rad_mesh *m, const rad_race_options *o, const double *rms,
                    const int *reached, rad_matrix_mode matrix, int first)
{
    static const char *const label[RAD_RACE_METHODS] = {"gathering", "shooting", "sorted",
                                                        "sorted+ambient"};
    const size_t rows = (size_t)o->steps + 1;
    const int lights = light_sources(m, o->patches);
    const int k = lights < 1 ? 1 : lights > o->steps ? o->steps : lights;
    fprintf(stderr, CLI_PROGRAM ": %d elements, %d emitting %s, %d steps per method, matrix %s\n",
            m->nelements, lights,
            o->patches ? (lights == 1 ? "patch" : "patches") : (lights == 1 ? "element" : "elements"),
            o->steps, rad_matrix_name(matrix));
    fprintf(stderr, CLI_PROGRAM ": RMS error after %d step%s:", k, k == 1 ? "" : "s");
    for (int j = first; j < RAD_RACE_METHODS; j++)
        fprintf(stderr, "%s %s %.6g", j > first ? "," : "", label[j],
                rms[(size_t)k + (size_t)j * rows]);
    fprintf(stderr, "\nradiosity: first step within %g of the %s solution:", o->reach,
            matrix == RAD_MATRIX_NONE ? "converged" : "gauss");
    for (int j = first; j < RAD_RACE_METHODS; j++) {
        if (reached[j] >= 0)
            fprintf(stderr, "%s %s %d", j > first ? "," : "", label[j], reached[j]);
        else
            fprintf(stderr, "%s %s > %d", j > first ? "," : "", label[j], o->steps);
    }
    fputc('\n', stderr);
}

/* ---- the run ------------------------------------------------------------- */

typedef struct pipeline {
    rad_scene scene;
    rad_result res;             /* mesh, F and the converged (gauss) B; or
                                   without a matrix, the mesh and B converged
                                   by progressive refinement to 1e-12 */
    rad_ffrow *row;             /* matrix-free: the rows and columns */
    progress_adaptive_run ad;   /* --adaptive: res is the sorted run converged */
    double *rms, *rms_bands, *Bv;
    int reached[RAD_RACE_METHODS];
} pipeline;

static void pipeline_free(pipeline *p)
{
    free(p->rms);
    free(p->rms_bands);
    free(p->Bv);
    radi_ffrow_free(p->row);
    progress_adaptive_run_free(&p->ad);
    rad_result_free(&p->res);
    rad_scene_free(&p->scene);
}

/* auto: dense when the dense peak fits in half the memory allowed (as
 * the pipeline decides for progressive refinement). */
static rad_matrix_mode decide_matrix(const progress_args *a, const rad_scene *scene)
{
    if (a->matrix != RAD_MATRIX_AUTO)
        return a->matrix;
    const double n = rad_scene_element_count(scene), limit = rad_memory_limit();
    const double dense = n <= 2147483647.0 ? rad_solve_bytes((int)n, 0) : HUGE_VAL;
    return limit > 0 && dense > 0.5 * limit ? RAD_MATRIX_NONE : RAD_MATRIX_DENSE;
}

/* Mesh, form factors and the gauss solution: the library's pipeline,
 * keeping F for the race.  Without a matrix: the converged solution by
 * matrix-free progressive refinement, and the rows for the race. */
static int prepare(progress_args *a, pipeline *p)
{
    rad_error err;
    rad_pipeline_options po;
    rad_pipeline_options_init(&po);
    po.crease = 0; /* no vertex values are used here */
    cli_progress_attach(&a->common);
    po.ff = a->common.ff;
    if (a->adaptive.solve.adaptive) {
        a->matrix = RAD_MATRIX_NONE;
        return progress_adaptive_prepare(&a->adaptive, &a->common, &p->scene, &p->res, &p->ad);
    }
    a->matrix = decide_matrix(a, &p->scene);
    if (a->matrix == RAD_MATRIX_NONE) {
        po.solve.solver = RAD_SOLVER_PROGRESSIVE;
        po.solve.tolerance = 1e-12;
        po.matrix = RAD_MATRIX_NONE;
    } else {
        po.keep_form_factors = 1;
    }
    rad_status st = rad_pipeline_run(&p->scene, &po, &p->res, &err);
    if (st == RAD_OK && a->matrix == RAD_MATRIX_NONE)
        st = radi_ffrow_create(&p->row, &p->res.mesh, &a->common.ff, RAD_OCC_AUTO, 0, 0, &err);
    if (st != RAD_OK) {
        if (p->res.ff_done)
            cli_error("the converged (%s) solution: %s",
                      a->matrix == RAD_MATRIX_NONE ? "progressive" : "gauss", err.message);
        else
            cli_error_rec(&err);
        return 1;
    }
    return 0;
}

/* --steps when not given (2 x the elements; --adaptive: the longer run to
 * convergence; at least to the last --snapshots-at) and the rms arrays. */
static int race_arrays(progress_args *a, pipeline *p)
{
    const int n = p->res.mesh.nelements;
    const int want = a->adaptive.solve.adaptive ? progress_adaptive_steps(&p->ad, &p->res) : 2 * n;
    if (a->race.steps == 0)
        a->race.steps = want < 1 ? 1 : want > DEFAULT_STEPS_CAP ? DEFAULT_STEPS_CAP : want;
    const int last = a->race.nsnapshot_at ? a->race.snapshot_at[a->race.nsnapshot_at - 1] : 0;
    if (!a->steps_given && last > a->race.steps)
        a->race.steps = last;
    p->rms = malloc(sizeof *p->rms * ((size_t)a->race.steps + 1) * RAD_RACE_METHODS);
    p->rms_bands = malloc(sizeof *p->rms * ((size_t)a->race.steps + 1) * RAD_RACE_METHODS);
    a->race.rms_bands = p->rms_bands;
    if (!p->rms || !p->rms_bands) {
        cli_error("out of memory for %d steps", a->race.steps);
        return 1;
    }
    return 0;
}

static int snapshots_wanted(const progress_args *a)
{
    return a->race.snapshot_every > 0 || a->race.nsnapshot_at > 0;
}

/* The snapshots' files, camera and exposure (the converged solution's),
 * and for the fixed mesh its callback.  0, or 1 (printed). */
static int snap_setup(progress_args *a, pipeline *p, snap_ctx *sc)
{
    memset(sc, 0, sizeof *sc);
    if (!snapshots_wanted(a))
        return 0;
    sc->snap.prefix = a->prefix ? a->prefix : "progress";
    rad_render_options_init(&sc->snap.ropt);
    sc->snap.ropt.camera = p->scene.camera;
    sc->snap.ropt.exposure = rad_mesh_auto_exposure(&p->res.mesh, p->res.B, a->exposure_from);
    sc->snap.error_images = a->error_images;
    sc->snap.elements = a->snapshot_elements;
    if (a->adaptive.solve.adaptive) /* its frames bring their own mesh */
        return 0;
    sc->mesh = &p->res.mesh;
    sc->Bref = p->res.B;
    sc->Bv = p->Bv = malloc(sizeof *p->Bv * (size_t)(p->res.mesh.nvertices + 1) * RAD_BANDS);
    if (!p->Bv) {
        cli_error("out of memory");
        return 1;
    }
    a->race.snapshot = snapshot;
    a->race.snapshot_user = sc;
    return 0;
}

static int race(progress_args *a, pipeline *p)
{
    rad_error err;
    snap_ctx sc;
    if (race_arrays(a, p) || snap_setup(a, p, &sc))
        return 1;
    if (a->adaptive.solve.adaptive)
        return progress_adaptive_race(&a->adaptive, &a->common, &p->ad, &p->res, &a->race,
                                      snapshots_wanted(a) ? &sc.snap : NULL, p->rms, p->reached);
    a->race.progress = a->common.ff.progress;
    a->race.progress_user = a->common.ff.progress_user;
    const rad_shoot_source src = {p->res.F, p->row};
    if (radi_race_run_source(&p->res.mesh, &src, p->res.B, &a->race, p->rms, p->reached, &err) !=
        RAD_OK) {
        cli_error_rec(sc.snap.failed ? &sc.snap.err : &err);
        return 1;
    }
    return 0;
}

/* eq. 14 of the converged solution against B = 0: the RMS of its
 * band-averaged radiosity, the unit of a normalised plot (0 when it
 * cannot be had: the plot is then not normalised). */
static double converged_rms(const rad_mesh *m, const double *B)
{
    const int n = m->nelements;
    double *area = malloc(sizeof *area * (size_t)(n ? n : 1)), total = 0;
    if (!area)
        return 0;
    for (int i = 0; i < n; i++)
        total += area[i] = m->elements[i].area;
    const double r = radi_rms_of(n, area, total, B);
    free(area);
    return r;
}

static int outputs(const progress_args *a, const pipeline *p)
{
    char title[512];
    const char *name = strrchr(p->scene.filename, '/');
    snprintf(title, sizeof title, "Progressive refinement (Cohen et al. 1988, fig. 7): %s",
             name ? name + 1 : p->scene.filename);
    const table_ctx t = {p->rms, p->rms_bands, a->race.steps, first_method(a)};
    const plot_ctx pl = {p->rms, a->race.steps, title, a->plot_linear,
                         a->plot_normalised ? converged_rms(&p->res.mesh, p->res.B) : 0,
                         first_method(a)};
    const cli_output o[2] = {{a->output ? a->output : "-", write_table_to, &t},
                             {a->plot, write_plot_to, &pl}};
    if (cli_outputs_write(o, 2))
        return 1;
    if (!a->common.quiet) {
        summary(&p->res.mesh, &a->race, p->rms, p->reached, a->matrix, first_method(a));
        if (a->adaptive.solve.adaptive)
            progress_adaptive_summary(&p->ad, &p->res);
        if (pl.scale > 0)
            fprintf(stderr, CLI_PROGRAM ": --plot-normalised divides by the RMS of the converged "
                            "solution, %.17g\n", pl.scale);
    }
    return 0;
}

static int run(progress_args *a, const char *path)
{
    pipeline p;
    rad_error err;
    int status = 1;
    memset(&p, 0, sizeof p);
    if (cli_load_scene(path, &a->common, &p.scene))
        return 1;
    if ((a->race.snapshot_every > 0 || a->race.nsnapshot_at > 0) &&
        (!p.scene.camera.defined || rad_camera_check(&p.scene.camera, &err) != RAD_OK)) {
        if (p.scene.camera.defined)
            cli_error("%s: --snapshots: %s", path, err.message);
        else
            cli_error("%s: --snapshots needs a camera line in the scene", path);
        goto done;
    }
    const cli_output out[2] = {{a->output, write_table_to, NULL},
                               {a->plot, write_plot_to, NULL}};
    if (cli_outputs_check(out, 2) || progress_snap_check(a->prefix ? a->prefix : "progress", &a->race, a->error_images,
                           a->snapshot_elements, first_method(a)) || prepare(a, &p) || race(a, &p) || outputs(a, &p))
        goto done;
    status = 0;
done:
    pipeline_free(&p);
    return status;
}

int cmd_progress(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"steps", required_argument, NULL, OPT_STEPS},
        {"output", required_argument, NULL, 'o'},
        {"plot", required_argument, NULL, OPT_PLOT},
        {"reach", required_argument, NULL, OPT_REACH},
        {"patches", no_argument, NULL, OPT_RACE_PATCHES},
        {"matrix", required_argument, NULL, OPT_RACE_MATRIX},
        {"snapshots", required_argument, NULL, OPT_SNAPSHOTS},
        {"snapshot-prefix", required_argument, NULL, OPT_SNAPSHOT_PREFIX},
        {"snapshots-at", required_argument, NULL, OPT_SNAPSHOTS_AT},
        CLI_METHOD_LONGOPTS,
        {"exposure-from", required_argument, NULL, OPT_EXPOSURE_FROM},
        {"error-images", no_argument, NULL, OPT_ERROR_IMAGES},
        {"snapshot-elements", no_argument, NULL, OPT_SNAPSHOT_ELEMENTS},
        {"plot-axis", required_argument, NULL, OPT_PLOT_AXIS},
        {"plot-normalised", no_argument, NULL, OPT_PLOT_NORMALISED},
        {"adaptive", no_argument, NULL, OPT_ADAPTIVE},
        {"subdivide-threshold", required_argument, NULL, OPT_SUBDIVIDE_THRESHOLD},
        {"max-depth", required_argument, NULL, OPT_MAX_DEPTH},
        {"subdivide-test", required_argument, NULL, OPT_SUBDIVIDE_TEST},
        CLI_COMMON_LONGOPTS,
        {NULL, 0, NULL, 0}};
    progress_args a;
    int opt;
    memset(&a, 0, sizeof a);
    cli_common_init(&a.common);
    radi_race_options_init(&a.race);
    progress_adaptive_init(&a.adaptive);
    a.race.steps = 0; /* the default depends on the mesh */
    while ((opt = getopt_long(argc, argv, "ho:q", longopts, NULL)) != -1) {
        if (opt == OPT_HELP || opt == 'h') {
            help();
            return 0;
        }
        if (parse_option(&a, opt, optarg) != 0)
            return cli_usage_hint("progress");
    }
    if (cli_common_check(&a.common) ||
        progress_adaptive_check(&a.adaptive, &a.common, a.race.patches, a.matrix))
        return cli_usage_hint("progress");
    if ((a.prefix || a.error_images || a.snapshot_elements || a.exposure_from_given) &&
        a.race.snapshot_every == 0 && a.race.nsnapshot_at == 0) {
        cli_error("%s needs --snapshots K or --snapshots-at LIST",
                  a.prefix               ? "--snapshot-prefix"
                  : a.error_images       ? "--error-images"
                  : a.snapshot_elements  ? "--snapshot-elements"
                                         : "--exposure-from");
        return cli_usage_hint("progress");
    }
    if ((a.plot_axis_given || a.plot_normalised) && !a.plot) {
        cli_error("%s needs --plot FILE.png", a.plot_axis_given ? "--plot-axis" : "--plot-normalised");
        return cli_usage_hint("progress");
    }
    if (a.steps_given && a.race.nsnapshot_at > 0 &&
        a.race.snapshot_at[a.race.nsnapshot_at - 1] > a.race.steps) {
        cli_error("--snapshots-at %d is beyond --steps %d: that image would never be made",
                  a.race.snapshot_at[a.race.nsnapshot_at - 1], a.race.steps);
        return cli_usage_hint("progress");
    }
    if (optind != argc - 1) {
        cli_error(optind >= argc ? "progress needs a SCENE" : "progress takes one SCENE");
        return cli_usage_hint("progress");
    }
    return run(&a, argv[optind]);
}
