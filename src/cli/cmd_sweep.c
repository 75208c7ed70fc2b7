/* cmd_sweep.c -- `radiosity sweep`: time against error over meshes, accuracy
 * modes, hemicube resolutions and solvers.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The truth B is, when the scene has one, the closed form: a closed scene
 * whose elements all share one reflectance and emission (the furnace) has
 * B = E / (1 - rho) on every element.  Otherwise it is the reference-mode
 * gauss solution on a mesh twice as fine as the finest listed (or
 * --truth-mesh, raised to the finest listed): never one of the rows.  A coarse
 * solution is compared with a fine truth element by element of the truth:
 * fine element (gi, gj) of an N x M surface lies in coarse element
 * (floor((gi + 1/2) n / N), floor((gj + 1/2) m / M)), so the error measures
 * the piecewise-constant solution against the truth, area-weighted:
 *     rms = sqrt( sum_f A_f sum_b (B_c(f),b - B_f,b)^2 / (3 sum_f A_f) ),
 * Cohen et al. 1988, eq. 14, with the squares averaged over the colour
 * bands (rad_solution_error; not the band-averaged radiosity of
 * `progress`'s rms, rmserror.c: the two agree on grey scenes), and
 * max = the largest |B_c(f) - B_f|.
 *
 * With --resolutions, each mesh is also solved with the hemicube's form
 * factors (hemicube.h) at each resolution R, and every row gets the error
 * of its F against the contour integral in reference mode on the same
 * mesh: ff_error = max_i sum_j |F_ij - F_ij(reference)|, the infinity
 * norm of dF, which bounds what F's error does to B (the relative change
 * of B is at most k / (1 - k), k = ||(I - rho F)^-1|| ||rho dF||: Higham,
 * Accuracy and Stability of Numerical Algorithms, 2002, theorem 7.2).
 * What the 1988 paper traded for speed is then one table: the time and
 * both errors against R.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/cli.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "radiosity/accuracy.h"
#include "radiosity/pipeline.h"
#include "radiosity/accuracy.h"
#include "util/util.h"
#include "render/render.h"

enum { OPT_MESHES = 1200, OPT_ACCURACIES, OPT_SOLVERS, OPT_TRUTH_MESH, OPT_PLOT,
       OPT_RESOLUTIONS };

#define MAX_LIST 32
#define MAX_SERIES 24 /* curves in --plot: (accuracies + resolutions) x solvers */


typedef struct sweep_args {
    cli_common common;
    int meshes[MAX_LIST], nmeshes;
    int acc[3], nacc;
    int solvers[6], nsolvers;
    int res[MAX_LIST], nres;    /* --resolutions: hemicube rows */
    int truth_mesh;
    const char *output, *plot;
} sweep_args;

#define TIME_RUNS 9
#define TIME_SPAN 0.1

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* sorts x[0..n) (n >= 1) and returns its median */
static double median(double *x, int n)
{
    qsort(x, (size_t)n, sizeof *x, cmp_double);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

static void help(void)
{
    printf("Usage: radiosity sweep [OPTIONS] SCENE\n"
           "Measure the speed-accuracy trade: for each mesh, accuracy mode and\n"
           "solver, time the form factors and the solve, and measure the error of B\n"
           "against the best available truth (the closed form B = E/(1 - rho) for a\n"
           "closed scene of one material; otherwise the reference-mode gauss solution\n"
           "on a mesh twice as fine as the finest swept).  The error is the\n"
           "area-weighted RMS of Cohen et al. 1988, eq. 14, its squares averaged over\n"
           "the bands (progress's rms averages the bands' radiosity first: the same\n"
           "on grey scenes), and the maximum, in units of B.  Each time is the median\n"
           "of up to 9 runs, repeated while they took less than 0.1 s in all.\n"
           "\n"
           "Options:\n"
           "      --meshes LIST       N for N x N meshes (default 1,2,3,5,7,10); a\n"
           "                          polygon of K > 3 corners becomes K N^2 triangles\n"
           "      --accuracies LIST   classic,default,reference (default: all)\n"
           "      --solvers LIST      gauss,cholesky,jacobi,gauss-seidel,cg,progressive\n"
           "                          (default gauss)\n"
           "      --resolutions LIST  also solve each mesh with the hemicube's form\n"
           "                          factors at these resolutions (even, 2-4096, e.g.\n"
           "                          16,32,64,128,256), and give every row the error of\n"
           "                          its F against the reference contour integral\n"
           "      --truth-mesh N      mesh of the reference truth, at least the finest\n"
           "                          swept (default: twice the finest swept)\n"
           "  -o, --output FILE       the table (TSV; default standard output)\n"
           "      --plot FILE.png     error against time, log-log, a curve per mode\n"
           "                          (accuracy or resolution) and solver, at most 24\n"
           "      --quadrature K      Gauss points per edge in classic (default 3)\n"
           "      --threads N         OpenMP threads (default: all cores)\n"
           "  -q, --quiet             no progress lines\n"
           "      --help              show this help and exit\n"
           "\n"
           "Columns: mesh elements accuracy solver seconds_formfactor seconds_solve\n"
           "seconds_total rms_error max_error truth row_sum_min row_sum_max method\n"
           "resolution ff_error: method is contour or hemicube (accuracy '-' for the\n"
           "hemicube, resolution '-' for the contour), ff_error max_i sum_j |F_ij -\n"
           "F_ij(reference contour)| on the same mesh (with --resolutions; else nan).\n"
           "\n"
           "Examples:\n"
           "  radiosity sweep --meshes 1,2,4,8 data/furnace.scene\n"
           "  radiosity sweep --meshes 2,5,10 --accuracies classic,default \\\n"
           "      data/goral1984-cube.scene\n"
           "  radiosity sweep --meshes 1,2,3,5 --solvers gauss,jacobi --plot \\\n"
           "      sweep.png data/grey-cube.scene\n"
           "  radiosity sweep --meshes 8 --accuracies default --resolutions \\\n"
           "      16,64,256 data/grey-cube.scene\n"
           "\n"
           "Exit status: 0 on success, 1 on an error, 2 on a usage error.\n");
}

/* A comma-separated list into out[max]: names of name(0..nnames-1), or,
 * with name NULL, whole numbers from lo to hi (even ones only if even);
 * their number, or -1. */
static int parse_list(const char *arg, const char *(*name)(int), int nnames, long lo, long hi,
                      int even, int *out, int max)
{
    char buf[256];
    int n = 0;
    if (strlen(arg) >= sizeof buf)
        return -1;
    strcpy(buf, arg);
    for (char *save = NULL, *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        int v = -1;
        if (name) {
            for (int k = 0; k < nnames; k++)
                if (strcmp(t, name(k)) == 0)
                    v = k;
        } else if (cli_parse_int(t, lo, hi, &v) || (even && v % 2 != 0)) {
            v = -1;
        }
        if (v < 0 || n >= max)
            return -1;
        out[n++] = v;
    }
    return n > 0 ? n : -1;
}

static int parse_args(sweep_args *a, int argc, char **argv)
{
    static const struct option longopts[] = {
        {"meshes", required_argument, NULL, OPT_MESHES},
        {"accuracies", required_argument, NULL, OPT_ACCURACIES},
        {"solvers", required_argument, NULL, OPT_SOLVERS},
        {"truth-mesh", required_argument, NULL, OPT_TRUTH_MESH},
        {"resolutions", required_argument, NULL, OPT_RESOLUTIONS},
        {"plot", required_argument, NULL, OPT_PLOT},
        {"output", required_argument, NULL, 'o'},
        CLI_COMMON_LONGOPTS,
        {NULL, 0, NULL, 0}};
    int opt;
    static const int default_meshes[] = {1, 2, 3, 5, 7, 10};
    memset(a, 0, sizeof *a);
    cli_common_init(&a->common);
    memcpy(a->meshes, default_meshes, sizeof default_meshes);
    a->nmeshes = 6;
    a->nacc = 3;
    for (int k = 0; k < 3; k++)
        a->acc[k] = k;
    a->nsolvers = 1;
    a->output = "-";
    while ((opt = getopt_long(argc, argv, "ho:q", longopts, NULL)) != -1) {
        switch (opt) {
        case OPT_HELP:
        case 'h':
            help();
            return 0;
        case OPT_MESHES:
            if ((a->nmeshes = parse_list(optarg, NULL, 0, 1, 1000, 0, a->meshes, MAX_LIST)) < 0) {
                cli_error("--meshes takes whole numbers from 1 to 1000 separated by commas");
                return 2;
            }
            break;
        case OPT_ACCURACIES:
            if ((a->nacc = parse_list(optarg, rad_accuracy_name, 3, 0, 0, 0, a->acc, 3)) < 0) {
                cli_error("--accuracies takes classic, default, reference separated by commas");
                return 2;
            }
            break;
        case OPT_SOLVERS:
            if ((a->nsolvers = parse_list(optarg, rad_solver_name, 6, 0, 0, 0, a->solvers, 6)) < 0) {
                cli_error("--solvers takes gauss, cholesky, jacobi, gauss-seidel, cg, progressive "
                          "separated by commas");
                return 2;
            }
            break;
        case OPT_TRUTH_MESH:
            if (cli_parse_int(optarg, 1, 1000, &a->truth_mesh)) {
                cli_error("--truth-mesh takes a whole number from 1 to 1000");
                return 2;
            }
            break;
        case OPT_PLOT:
            a->plot = optarg;
            if (cli_png_name_check(optarg, "--plot"))
                return 2;
            break;
        case OPT_RESOLUTIONS:
            if ((a->nres = parse_list(optarg, NULL, 0, 2, RAD_HEMICUBE_MAX, 1, a->res,
                                      MAX_LIST)) < 0) {
                cli_error("--resolutions takes even whole numbers from 2 to %d separated by "
                          "commas, not '%s'", RAD_HEMICUBE_MAX, optarg);
                return 2;
            }
            break;
        case 'o':
            a->output = optarg;
            break;
        default:
            if (cli_common_option(&a->common, opt, optarg) != 0)
                return 2;
        }
    }
    if (a->common.mesh_n || a->common.max_size > 0) {
        cli_error("sweep takes --meshes, not --mesh or --max-element-size");
        return 2;
    }
    if (a->plot && (a->nacc + a->nres) * a->nsolvers > MAX_SERIES) {
        cli_error("--plot draws at most %d curves, one per accuracy or resolution and solver; "
                  "this sweep has %d", MAX_SERIES, (a->nacc + a->nres) * a->nsolvers);
        return 2;
    }
    if (optind != argc - 1) {
        cli_error(optind >= argc ? "sweep needs a SCENE" : "sweep takes one SCENE");
        return 2;
    }
    return -1; /* go on */
}

/* The library's pipeline on the scene meshed n x n, in the given mode
 * with the given solver.  Each stage is timed as the median of up to
 * TIME_RUNS runs, repeated while the runs so far took less than TIME_SPAN
 * s in all: a small mesh takes milliseconds, and one run of it is noise.
 * out keeps the last run's mesh and B. */
static int run_one(rad_scene *scene, int n, const rad_ff_options *ff, int solver, int keep,
                   rad_result *out, double *t_ff, double *t_solve)
{
    rad_error err;
    rad_pipeline_options po;
    double tf[TIME_RUNS], ts[TIME_RUNS], spent = 0;
    int runs = 0;
    rad_status st = RAD_OK;
    rad_scene_set_mesh(scene, n, n);
    rad_pipeline_options_init(&po);
    po.crease = 0; /* no vertex values are used here */
    po.ff = *ff;
    po.solve.solver = (rad_solver)solver;
    po.solve.tolerance = 1e-13;
    po.keep_form_factors = keep; /* for ff_error */
    memset(out, 0, sizeof *out);
    while (st == RAD_OK && runs < TIME_RUNS && spent < TIME_SPAN) {
        rad_result_free(out);
        /* the solve before left OpenBLAS's threads spinning for a tenth
         * of a second (blasthreads.c): they would take a core from the fill */
        radi_blas_park_threads();
        st = rad_pipeline_run(scene, &po, out, &err);
        tf[runs] = out->t_formfactor;
        ts[runs] = out->t_solve;
        spent += tf[runs] + ts[runs];
        runs++;
    }
    if (st != RAD_OK) {
        cli_error("mesh %dx%d, %s, %s: %s", n, n,
                  ff->method == RAD_FF_HEMICUBE ? "hemicube" : rad_accuracy_name(ff->accuracy),
                  rad_solver_name(solver), err.message);
        rad_result_free(out);
        return 1;
    }
    *t_ff = median(tf, runs);
    *t_solve = median(ts, runs);
    return 0;
}

typedef struct row {
    int mesh, elements, acc, solver;
    int res;                    /* 0: the contour; R: the hemicube at R */
    double t_ff, t_solve, rms, max;
    double row_min, row_max;    /* closure: sum_j F_ij, least and largest */
    double ff_error;            /* ||F - F(reference contour)||_inf, or NaN */
} row;

typedef struct table_out {
    const row *r;
    int nr;
    const char *truth;
} table_out;

static int write_table(FILE *out, const row *r, int nr, const char *truth);

static int write_table_to(FILE *out, const void *ctx)
{
    const table_out *t = ctx;
    return write_table(out, t->r, t->nr, t->truth);
}

static int write_table(FILE *out, const row *r, int nr, const char *truth)
{
    fprintf(out, "mesh\telements\taccuracy\tsolver\tseconds_formfactor\tseconds_solve\t"
                 "seconds_total\trms_error\tmax_error\ttruth\trow_sum_min\trow_sum_max\t"
                 "method\tresolution\tff_error\n");
    for (int k = 0; k < nr; k++) {
        char res[16];
        snprintf(res, sizeof res, r[k].res ? "%d" : "-", r[k].res);
        fprintf(out, "%dx%d\t%d\t%s\t%s\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%s\t%.17g\t%.17g\t"
                     "%s\t%s\t%.6g\n",
                r[k].mesh, r[k].mesh, r[k].elements,
                r[k].res ? "-" : rad_accuracy_name(r[k].acc), rad_solver_name(r[k].solver),
                r[k].t_ff, r[k].t_solve, r[k].t_ff + r[k].t_solve, r[k].rms, r[k].max, truth,
                r[k].row_min, r[k].row_max, rad_ff_method_name(r[k].res ? RAD_FF_HEMICUBE
                                                                       : RAD_FF_CONTOUR),
                res, r[k].ff_error);
    }
    return ferror(out) ? -1 : 0;
}

typedef struct xy_plot {
    const rad_series *s;
    int ns;
    const rad_plot_spec *spec;
} xy_plot;

static int write_xy(FILE *out, const void *ctx)
{
    const xy_plot *p = ctx;
    rad_error err;
    if (radi_plot_xy(p->s, p->ns, p->spec, out, &err) != RAD_OK) {
        cli_error_rec(&err);
        return -1;
    }
    return 0;
}

/* Does row r belong to variant v (v < nacc: an accuracy; else a
 * resolution) and solver? */
static int in_series(const sweep_args *a, const row *r, int v, int solver)
{
    if (r->solver != solver)
        return 0;
    return v < a->nacc ? r->res == 0 && r->acc == a->acc[v] : r->res == a->res[v - a->nacc];
}

static int plot(const sweep_args *a, const row *r, int nr, const char *title)
{
    rad_series s[MAX_SERIES]; /* accuracies and resolutions x solvers (parse_args) */
    double x[MAX_SERIES][MAX_LIST], y[MAX_SERIES][MAX_LIST];
    char labels[MAX_SERIES][48];
    int ns = 0;
    for (int v = 0; v < a->nacc + a->nres; v++)
        for (int j = 0; j < a->nsolvers && ns < MAX_SERIES; j++, ns++) {
            s[ns].n = 0;
            if (v < a->nacc)
                snprintf(labels[ns], sizeof labels[ns], "%s, %s", rad_accuracy_name(a->acc[v]),
                         rad_solver_name(a->solvers[j]));
            else
                snprintf(labels[ns], sizeof labels[ns], "hemicube %d, %s", a->res[v - a->nacc],
                         rad_solver_name(a->solvers[j]));
            for (int k = 0; k < nr; k++)
                if (in_series(a, &r[k], v, a->solvers[j]) && s[ns].n < MAX_LIST) {
                    x[ns][s[ns].n] = r[k].t_ff + r[k].t_solve;
                    y[ns][s[ns].n++] = r[k].rms;
                }
            s[ns].label = labels[ns];
            s[ns].x = x[ns];
            s[ns].y = y[ns];
        }
    const rad_plot_spec spec = {title, "time, form factors + solve (s)", "RMS error of B",
                                1, 1, 0, 0};
    const xy_plot p = {s, ns, &spec};
    return cli_write_atomic(a->plot, write_xy, &p);
}

/* The reference contour's F on the scene meshed n x n (n x n elements
 * squared doubles, freed by the caller), for ff_error; NULL with the error
 * printed. */
static double *reference_F(rad_scene *scene, int n, const rad_ff_options *ff, int *ne)
{
    rad_mesh m;
    rad_error err;
    rad_ff_options o = *ff;
    o.method = RAD_FF_CONTOUR;
    o.accuracy = RAD_ACCURACY_REFERENCE;
    rad_scene_set_mesh(scene, n, n);
    if (rad_mesh_build(&m, scene, &err) != RAD_OK) {
        cli_error_rec(&err);
        return NULL;
    }
    *ne = m.nelements;
    double *F = malloc(sizeof *F * (size_t)m.nelements * (size_t)m.nelements + 1);
    if (!F)
        cli_error("out of memory for the reference form factors");
    else if (rad_ff_matrix(&m, &o, F, NULL, NULL, &err) != RAD_OK) {
        cli_error_rec(&err);
        free(F);
        F = NULL;
    }
    rad_mesh_free(&m);
    return F;
}

/* max_i sum_j |F_ij - G_ij| (n x n, column-major). */
static double inf_norm_diff(const double *F, const double *G, int n)
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double s = 0;
        for (int j = 0; j < n; j++)
            s += fabs(F[(size_t)i + (size_t)j * n] - G[(size_t)i + (size_t)j * n]);
        worst = s > worst ? s : worst;
    }
    return worst;
}

/* What every row of one mesh measures against. */
typedef struct truth_ref {
    const rad_result *truth;    /* reference gauss on the finest mesh, or */
    const double *closed;       /* the furnace's closed form (have_closed) */
    int have_closed;
    const double *Fref;         /* this mesh's reference contour F, or NULL */
    int nref;
} truth_ref;

/* One row: the scene meshed `mesh` x `mesh` with the form-factor options
 * o and the solver; 0, or 1 (printed). */
static int sweep_row(const sweep_args *a, rad_scene *scene, int mesh, const rad_ff_options *o,
                     int solver, const truth_ref *t, row *w)
{
    rad_result sol;
    if (run_one(scene, mesh, o, solver, t->Fref != NULL, &sol, &w->t_ff, &w->t_solve))
        return 1;
    w->mesh = mesh;
    w->elements = sol.mesh.nelements;
    w->acc = o->method == RAD_FF_HEMICUBE ? -1 : (int)o->accuracy;
    w->res = o->method == RAD_FF_HEMICUBE ? o->resolution : 0;
    w->solver = solver;
    w->row_min = sol.solve.row_sum_min;
    w->row_max = sol.solve.row_sum_max;
    w->ff_error = t->Fref && sol.F && t->nref == sol.mesh.nelements
                      ? inf_norm_diff(sol.F, t->Fref, t->nref)
                      : NAN;
    rad_solution_error(&sol.mesh, sol.B, t->have_closed ? NULL : &t->truth->mesh,
                       t->truth->B, t->closed, &w->rms, &w->max);
    if (!a->common.quiet)
        fprintf(stderr, CLI_PROGRAM ": %dx%d %s %s: %.3g s, rms error %.3g\n", w->mesh, w->mesh,
                w->res ? "hemicube" : rad_accuracy_name(w->acc), rad_solver_name(w->solver),
                w->t_ff + w->t_solve, w->rms);
    rad_result_free(&sol);
    return 0;
}

/* Every row of one mesh: the accuracies, then the resolutions, each with
 * every solver; the number of rows, or -1 (printed). */
static int sweep_mesh(const sweep_args *a, rad_scene *scene, int mesh, truth_ref *t, row *w)
{
    int nr = 0, nref = 0;
    double *Fref = a->nres > 0 ? reference_F(scene, mesh, &a->common.ff, &nref) : NULL;
    if (a->nres > 0 && !Fref)
        return -1;
    t->Fref = Fref;
    t->nref = nref;
    for (int v = 0; v < a->nacc + a->nres; v++)
        for (int j = 0; j < a->nsolvers; j++) {
            rad_ff_options o = a->common.ff;
            if (v < a->nacc) {
                o.accuracy = (rad_accuracy)a->acc[v];
            } else {
                o.method = RAD_FF_HEMICUBE;
                o.resolution = a->res[v - a->nacc];
            }
            if (sweep_row(a, scene, mesh, &o, a->solvers[j], t, &w[nr])) {
                free(Fref);
                return -1;
            }
            nr++;
        }
    free(Fref);
    t->Fref = NULL;
    return nr;
}

int cmd_sweep(int argc, char **argv)
{
    sweep_args a;
    rad_scene scene;
    int r = parse_args(&a, argc, argv);
    if (r >= 0)
        return r == 2 ? cli_usage_hint("sweep") : r;
    const cli_output outs[2] = {{a.output, write_table_to, NULL}, {a.plot, write_xy, NULL}};
    if (cli_outputs_check(outs, 2) || cli_load_scene(argv[optind], &a.common, &scene))
        return 1;
    double closed[RAD_BANDS];
    int have_closed = 0;
    rad_error err;
    if (rad_furnace_radiosity(&scene, closed) &&
        rad_scene_closed(&scene, 1e-8, &have_closed, NULL, &err) != RAD_OK) {
        cli_error_rec(&err);
        rad_scene_free(&scene);
        return 1;
    }
    rad_result truth;
    memset(&truth, 0, sizeof truth);
    /* the truth's mesh: --truth-mesh, or twice the finest swept, so that
     * no row is compared with itself (a truth on the finest mesh gave that
     * row an error of 0 and bent every curve down to round-off at its end,
     * as if that mesh were exact) */
    int finest = 0;
    for (int k = 0; k < a.nmeshes; k++)
        finest = a.meshes[k] > finest ? a.meshes[k] : finest;
    finest = a.truth_mesh ? (a.truth_mesh > finest ? a.truth_mesh : finest)
                          : (2 * finest <= 1000 ? 2 * finest : 1000);
    int status = 1, nr = 0;
    row *rows = malloc(sizeof *rows * (size_t)a.nmeshes * (size_t)(a.nacc + a.nres) *
                       (size_t)a.nsolvers);
    char tname[64];
    if (!rows) {
        cli_error("out of memory for the table");
        goto done;
    }
    if (have_closed) {
        snprintf(tname, sizeof tname, "closed-form");
    } else {
        rad_ff_options o = a.common.ff;
        double t1, t2;
        o.accuracy = RAD_ACCURACY_REFERENCE;
        if (!a.common.quiet)
            fprintf(stderr, CLI_PROGRAM ": truth: reference gauss on %dx%d\n", finest, finest);
        if (run_one(&scene, finest, &o, RAD_SOLVER_GAUSS, 0, &truth, &t1, &t2))
            goto done;
        snprintf(tname, sizeof tname, "reference-%dx%d", finest, finest);
    }
    truth_ref tr = {&truth, closed, have_closed, NULL, 0};
    for (int m = 0; m < a.nmeshes; m++) {
        const int k = sweep_mesh(&a, &scene, a.meshes[m], &tr, rows + nr);
        if (k < 0)
            goto done;
        nr += k;
    }
    const table_out t = {rows, nr, tname};
    if (cli_write_atomic(a.output, write_table_to, &t))
        goto done;
    if (a.plot && plot(&a, rows, nr, scene.filename))
        goto done;
    status = 0;
done:
    free(rows);
    rad_result_free(&truth);
    rad_scene_free(&scene);
    return status;
}
