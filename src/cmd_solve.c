/* cmd_solve.c -- `radiosity solve` and the pipeline render and sweep share.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * scene -> mesh -> form factors -> solve per band -> smooth -> outputs.
 * Only parsing, dispatch, timing and messages live here.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "atomicfile.h"
#include "cli.h"
#include "export.h"

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void cli_solve_init(cli_solve *s)
{
    memset(s, 0, sizeof *s);
    cli_common_init(&s->common);
    rad_solve_options_init(&s->solve);
}

int cli_solve_option(cli_solve *s, int opt, const char *arg)
{
    switch (opt) {
    case OPT_SOLVER:
        if (strcmp(arg, "gauss") == 0)
            s->solve.solver = RAD_SOLVER_GAUSS;
        else if (strcmp(arg, "jacobi") == 0)
            s->solve.solver = RAD_SOLVER_JACOBI;
        else if (strcmp(arg, "gauss-seidel") == 0)
            s->solve.solver = RAD_SOLVER_GAUSS_SEIDEL;
        else if (strcmp(arg, "progressive") == 0)
            s->solve.solver = RAD_SOLVER_PROGRESSIVE;
        else {
            cli_error("--solver takes gauss, jacobi, gauss-seidel or progressive, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_TOLERANCE:
        if (cli_parse_double(arg, &s->solve.tolerance) || !(s->solve.tolerance > 0) ||
            s->solve.tolerance >= 1) {
            cli_error("--tolerance takes a number between 0 and 1, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_MAX_ITERATIONS:
        if (cli_parse_int(arg, 1, 1000000000, &s->solve.max_iterations)) {
            cli_error("--max-iterations takes a positive whole number, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_BOUNCES:
        if (cli_parse_int(arg, 0, 1000000000, &s->solve.bounces)) {
            cli_error("--bounces takes a whole number >= 0, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_ERROR_BOUNDS:
        s->solve.error_bounds = 1;
        return 0;
    case OPT_REPORT:
        s->report = arg;
        return 0;
    case OPT_ELEMENTS:
        s->elements = arg;
        return 0;
    case OPT_FORM_FACTORS:
        s->form_factors = arg;
        return 0;
    case OPT_TRACE:
        s->solve.trace = arg;
        return 0;
    case OPT_PATCHES:
        s->solve.patches = 1;
        return 0;
    default:
        return cli_common_option(&s->common, opt, arg);
    }
}

void cli_result_free(cli_result *r)
{
    free(r->B);
    free(r->Bv);
    rad_mesh_free(&r->mesh);
    rad_scene_free(&r->scene);
    memset(r, 0, sizeof *r);
}

typedef struct out_ctx {
    const cli_result *r;
    const double *F;
    const rad_run_info *info;
} out_ctx;

static int w_elements(FILE *out, const void *c)
{
    const out_ctx *o = c;
    return rad_export_elements(out, &o->r->mesh, o->r->B);
}

static int w_matrix(FILE *out, const void *c)
{
    const out_ctx *o = c;
    char comment[512];
    snprintf(comment, sizeof comment, "form factors of %s; row i = from element i",
             o->r->scene.filename);
    return rad_export_matrix_market(out, o->F, o->r->mesh.nelements, comment);
}

static int w_report(FILE *out, const void *c)
{
    const out_ctx *o = c;
    return rad_export_report(out, o->info);
}

static void summary(const rad_run_info *in)
{
    const rad_solve_report *s = in->solve;
    static const char *const solvers[] = {"gauss", "jacobi", "gauss-seidel", "progressive"};
    fprintf(stderr, "radiosity: %d elements, %.1f MiB of matrices; form factors %.3g s "
                    "(%.3g pairs/s, %s), solve %.3g s\n",
            in->nelements, in->memory_bytes / 1048576.0, in->t_formfactor,
            in->ff_pairs_per_second, in->accuracy, in->t_solve);
    if (in->ff && in->ff->vis_needed)
        fprintf(stderr, "radiosity: visibility: %.0f of %.0f pairs blockable, %.0f hidden, "
                        "%.0f partly; %.3g s\n",
                in->ff->vis_pairs_blockable, in->ff->vis_pairs_tested, in->ff->vis_pairs_blocked,
                in->ff->vis_pairs_partial, in->ff->vis_seconds);
    else if (in->ff)
        fprintf(stderr, "radiosity: visibility: no pair can be blocked, none computed\n");
    if (!s)
        return;
    if (s->bounces >= 0)
        fprintf(stderr, "radiosity: %d bounces (Jacobi from B = E)", s->bounces);
    else if (s->solver == RAD_SOLVER_GAUSS) {
        fprintf(stderr, "radiosity: gauss, %d factorisation%s, rcond %.3g", s->systems,
                s->systems == 1 ? "" : "s", s->rcond);
        if (!isnan(s->ff_error_bound))
            fprintf(stderr, "; F's error moves B by %.3g relative at most", s->ff_error_bound);
    }
    else if (s->solver == RAD_SOLVER_PROGRESSIVE)
        fprintf(stderr, "radiosity: progressive, %d shooting steps", s->sweeps);
    else
        fprintf(stderr, "radiosity: %s, %d sweeps, convergence factor %.6g", solvers[s->solver],
                s->sweeps, s->spectral_radius);
    fprintf(stderr, "; residual %.3g; F row sums [%.15g, %.15g]\n", s->residual,
            s->row_sum_min, s->row_sum_max);
    fprintf(stderr, "radiosity: energy balance (emitted - absorbed - escaped)/emitted: "
                    "%.3g %.3g %.3g\n",
            s->balance[0], s->balance[1], s->balance[2]);
}

/* Refuse before allocating what the machine cannot hold. */
static int check_memory(double need, double have, int n)
{
    if (have > 0 && need > have) {
        cli_error("%d elements need %.0f MiB for the matrices (2 x 8 N^2 bytes), but only "
                  "%.0f MiB are available; use a coarser --mesh",
                  n, need / 1048576.0, have / 1048576.0);
        return 1;
    }
    return 0;
}

int cli_solve_run(cli_solve *s, const char *path, cli_result *r)
{
    rad_error err;
    rad_ff_stats ffs;
    rad_solve_report rep;
    rad_run_info info;
    double *F = NULL;
    int status = 1;
    const char *accuracy[] = {"classic", "default", "reference"};
    memset(r, 0, sizeof *r);
    memset(&info, 0, sizeof info);
    info.scene = path;
    info.accuracy = accuracy[s->common.ff.accuracy];
    info.quadrature = s->common.ff.quadrature;
    info.status = "ok";
    double t0 = seconds();
    if (cli_load_scene(path, &s->common, &r->scene))
        return 1;
    double t1 = seconds();
    if (rad_mesh_build(&r->mesh, &r->scene, &err) != RAD_OK) {
        cli_error_rec(&err);
        goto fail;
    }
    const int n = r->mesh.nelements;
    const size_t nn = (size_t)n * n;
    double t2 = seconds();
    info.nelements = n;
    info.memory_bytes = rad_solve_bytes(n, s->solve.error_bounds);
    info.memory_available = rad_memory_available();
    if (check_memory(info.memory_bytes, info.memory_available, n))
        goto fail;
    F = malloc(sizeof *F * (nn ? nn : 1));
    r->B = malloc(sizeof *r->B * (size_t)n * RAD_BANDS);
    r->Bv = malloc(sizeof *r->Bv * (size_t)(r->mesh.nvertices ? r->mesh.nvertices : 1) * RAD_BANDS);
    if (!F || !r->B || !r->Bv) {
        cli_error("out of memory for %d elements", n);
        goto fail;
    }
    cli_progress_attach(&s->common);
    if (rad_ff_matrix(&r->mesh, &s->common.ff, F, NULL, &ffs, &err) != RAD_OK) {
        cli_error_rec(&err);
        goto fail;
    }
    double t3 = seconds();
    info.ff = &ffs;
    info.t_formfactor = t3 - t2;
    info.ff_pairs_per_second = info.t_formfactor > 0 ? ffs.pairs / info.t_formfactor : 0;
    if (ffs.negative || ffs.above_one)
        cli_error("warning: %ld form factors below 0 and %ld above 1 (min %.3g, max %.3g): "
                  "the %s rule is unreliable for this geometry",
                  ffs.negative, ffs.above_one, ffs.min_value, ffs.max_value, info.accuracy);
    s->solve.progress = s->common.ff.progress;
    s->solve.progress_user = s->common.ff.progress_user;
    s->solve.ff_row_error = ffs.max_row_error; /* NaN in classic: no bound */
    rad_status st = rad_solve(&r->mesh, F, &s->solve, r->B, &rep, &err);
    double t4 = seconds();
    info.solve = &rep;
    info.t_parse = t1 - t0;
    info.t_mesh = t2 - t1;
    info.t_solve = t4 - t3;
    out_ctx ctx = {r, F, &info};
    if (st != RAD_OK) {
        cli_error_rec(&err);
        info.status = st == RAD_ERR_SINGULAR ? "singular" : st == RAD_ERR_NOCONV ? "not converged" : "error";
        if (s->report) /* the report says why; no solution file is written */
            cli_write_atomic(s->report, w_report, &ctx);
        goto fail;
    }
    rad_smooth_vertices(&r->mesh, r->B, r->Bv);
    double t5 = seconds();
    info.t_smooth = t5 - t4;
    if ((s->elements && cli_write_atomic(s->elements, w_elements, &ctx)) ||
        (s->form_factors && cli_write_atomic(s->form_factors, w_matrix, &ctx)))
        goto fail;
    info.t_output = seconds() - t5;
    if (s->report && cli_write_atomic(s->report, w_report, &ctx))
        goto fail;
    if (!s->common.quiet)
        summary(&info);
    status = 0;
fail:
    free(F);
    if (status)
        cli_result_free(r);
    return status;
}

/* ---- radiosity solve ------------------------------------------------------ */

static void help(void)
{
    printf("Usage: radiosity solve [OPTIONS] SCENE\n"
           "Mesh the scene, compute the form factors, solve the radiosity system\n"
           "(I - diag(rho) F) B = E for each colour band (Goral et al. 1984) and\n"
           "write the results.  A summary goes to standard error.\n"
           "\n"
           "Options:\n"
           "  -o, --output FILE       the solution as PLY (mesh, smoothed vertex\n"
           "                          radiosity, element radiosity); '-' is stdout\n"
           CLI_SOLVE_HELP
           "\n"
           "Outputs are written to a temporary file and renamed: a failed run never\n"
           "leaves a partial file.  Exit status: 0 on success, 1 on an error\n"
           "(including a singular or non-converged system), 2 on a usage error.\n");
}

typedef struct ply_ctx {
    const cli_result *r;
} ply_ctx;

static int w_ply(FILE *out, const void *c)
{
    const ply_ctx *p = c;
    return rad_export_ply(out, &p->r->scene, &p->r->mesh, p->r->B, p->r->Bv);
}

int cmd_solve(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"output", required_argument, NULL, 'o'}, CLI_SOLVE_LONGOPTS, {NULL, 0, NULL, 0}};
    cli_solve s;
    cli_result r;
    const char *output = NULL;
    int opt;
    cli_solve_init(&s);
    while ((opt = getopt_long(argc, argv, "ho:q", longopts, NULL)) != -1) {
        if (opt == OPT_HELP || opt == 'h') {
            help();
            return 0;
        }
        if (opt == 'o') {
            output = optarg;
            continue;
        }
        if (cli_solve_option(&s, opt, optarg) != 0)
            return cli_usage_hint("solve");
    }
    if (optind != argc - 1) {
        cli_error(optind >= argc ? "solve needs a SCENE" : "solve takes one SCENE");
        return cli_usage_hint("solve");
    }
    if (cli_solve_run(&s, argv[optind], &r))
        return 1;
    ply_ctx p = {&r};
    int status = output ? cli_write_atomic(output, w_ply, &p) : 0;
    cli_result_free(&r);
    return status;
}
