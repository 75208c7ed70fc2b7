/* cmd_solve.c -- `radiosity solve`, and the solve options every command
 * that solves a scene shares (render, and later animate).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The run itself is one library call (pipeline.h); here are only the
 * options, the checks that can be made before any work (options that
 * contradict each other, outputs that could not be written), the summary
 * on standard error and the writers of the output files, which are all
 * written together at the end (cli_output.c).
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "radiosity/export.h"
#include "radiosity/pipeline.h"
#include "radiosity/export.h"


void cli_solve_init(cli_solve *s)
{
    memset(s, 0, sizeof *s);
    cli_common_init(&s->common);
    rad_solve_options_init(&s->solve);
    s->crease = RAD_CREASE_AUTO;
}

int cli_solve_option(cli_solve *s, int opt, const char *arg)
{
    switch (opt) {
    case OPT_SOLVER:
        s->given_solver = 1;
        if (strcmp(arg, "gauss") == 0)
            s->solve.solver = RAD_SOLVER_GAUSS;
        else if (strcmp(arg, "jacobi") == 0)
            s->solve.solver = RAD_SOLVER_JACOBI;
        else if (strcmp(arg, "gauss-seidel") == 0)
            s->solve.solver = RAD_SOLVER_GAUSS_SEIDEL;
        else if (strcmp(arg, "progressive") == 0)
            s->solve.solver = RAD_SOLVER_PROGRESSIVE;
        else if (strcmp(arg, "cholesky") == 0)
            s->solve.solver = RAD_SOLVER_CHOLESKY;
        else if (strcmp(arg, "cg") == 0)
            s->solve.solver = RAD_SOLVER_CG;
        else {
            cli_error("--solver takes gauss, cholesky, jacobi, gauss-seidel, cg or progressive, "
                      "not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_TOLERANCE:
        s->given_tolerance = 1;
        if (cli_parse_double(arg, &s->solve.tolerance) || !(s->solve.tolerance > 0) ||
            s->solve.tolerance >= 1) {
            cli_error("--tolerance takes a number between 0 and 1, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_MAX_ITERATIONS:
        s->given_max_iterations = 1;
        if (cli_parse_int(arg, 1, 1000000000, &s->solve.max_iterations)) {
            cli_error("--max-iterations takes a positive whole number, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_BOUNCES:
        s->given_bounces = 1;
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
        s->trace = arg;
        return 0;
    case OPT_PATCHES:
        if (!arg) {
            s->solve.patches = 1;
            return 0;
        }
        if (cli_parse_mesh(arg, &s->solve.patch_p, &s->solve.patch_q)) {
            cli_error("--patches takes PxQ (positive whole numbers, e.g. 4x4), not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_VERTEX_RULE:
        if (strcmp(arg, "extrapolate") == 0)
            s->vertex_rule = RAD_VERTEX_EXTRAPOLATE;
        else if (strcmp(arg, "corner") == 0)
            s->vertex_rule = RAD_VERTEX_CORNER;
        else {
            cli_error("--vertex-rule takes extrapolate or corner, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_CREASE:
        if (cli_parse_double(arg, &s->crease) || !(s->crease >= 0 && s->crease <= 180)) {
            cli_error("--crease takes an angle from 0 to 180 degrees, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_ADAPTIVE:
    case OPT_SUBDIVIDE_THRESHOLD:
    case OPT_MAX_DEPTH:
    case OPT_SUBDIVIDE_TEST:
        return cli_adaptive_option(&s->solve, &s->given_adaptive_option, opt, arg);
    case OPT_MATRIX:
        s->given_matrix = 1;
        for (int m = RAD_MATRIX_AUTO; m <= RAD_MATRIX_NONE; m++)
            if (strcmp(arg, rad_matrix_name(m)) == 0) {
                s->matrix = (rad_matrix_mode)m;
                return 0;
            }
        cli_error("--matrix takes none, dense or auto, not '%s'", arg);
        return 2;
    default:
        return cli_common_option(&s->common, opt, arg);
    }
}

int cli_solve_check(const cli_solve *s)
{
    const rad_solver v = s->solve.solver;
    const char *name = rad_solver_name(v);
    const char *bad = NULL;
    if (cli_common_check(&s->common))
        return 2;
    if (s->common.ff.method == RAD_FF_HEMICUBE && s->solve.patch_p > 0 &&
        s->matrix == RAD_MATRIX_NONE)
        bad = "--patches PxQ with --matrix none needs the contour integral: the hemicube "
              "shoots from elements";
    else if (s->given_bounces && s->given_solver)
        bad = "--bounces K is its own solver (Jacobi from B = E, exactly K reflections): "
              "give it without --solver";
    else if (s->given_bounces && (s->given_tolerance || s->given_max_iterations))
        bad = "--bounces K runs exactly K reflections: --tolerance and --max-iterations do "
              "not apply";
    else if (s->trace && v != RAD_SOLVER_PROGRESSIVE)
        bad = "--trace traces the shooting steps of --solver progressive";
    else if ((s->solve.patches || s->solve.patch_p) && v != RAD_SOLVER_PROGRESSIVE)
        bad = "--patches applies to --solver progressive";
    else if (s->given_matrix && (v != RAD_SOLVER_PROGRESSIVE || s->given_bounces))
        bad = "--matrix applies to --solver progressive (the other solvers need F)";
    else if (s->matrix == RAD_MATRIX_NONE && s->form_factors)
        bad = "--matrix none stores no form factors: --form-factors cannot write them";
    else if (s->given_adaptive_option && !s->solve.adaptive)
        bad = "--subdivide-threshold, --subdivide-test and --max-depth apply to --adaptive";
    else if (s->solve.adaptive && (v != RAD_SOLVER_PROGRESSIVE || s->given_bounces))
        bad = "--adaptive applies to --solver progressive";
    else if (s->solve.adaptive && s->crease > 0)
        bad = "--crease moves vertices that --adaptive's hanging vertices must follow: give "
              "one of them";
    else if (s->solve.adaptive && (s->solve.patches || s->solve.patch_p))
        bad = "--adaptive: the mesh's elements are the patches that shoot; give --mesh, "
              "not --patches";
    else if (s->solve.adaptive && s->common.ff.method == RAD_FF_HEMICUBE)
        bad = "--adaptive integrates the new elements' form factors on their outlines: "
              "it needs the contour integral, not the hemicube";
    else if (s->solve.adaptive && (s->matrix == RAD_MATRIX_DENSE || s->form_factors))
        bad = "--adaptive computes its form factors on the fly (as --matrix none): no "
              "--matrix dense, no --form-factors";
    else if (s->solve.error_bounds && (v != RAD_SOLVER_GAUSS || s->given_bounces))
        bad = "--error-bounds applies to --solver gauss (LU) only";
    else if ((s->given_tolerance || s->given_max_iterations) &&
             (v == RAD_SOLVER_GAUSS || v == RAD_SOLVER_CHOLESKY) && !s->given_bounces)
        bad = "--tolerance and --max-iterations apply to the iterative solvers, not to gauss "
              "or cholesky";
    if (bad) {
        cli_error("%s%s%s", bad, s->given_solver ? "; the solver is " : "",
                  s->given_solver ? name : "");
        return 2;
    }
    return 0;
}

int cli_run_load(cli_run *run, cli_solve *s, const char *path)
{
    memset(run, 0, sizeof *run);
    run->s = s;
    run->status = RAD_OK;
    double t0 = cli_seconds();
    if (cli_load_scene(path, &s->common, &run->scene))
        return 1;
    run->t_parse = cli_seconds() - t0;
    return 0;
}

void cli_run_free(cli_run *run)
{
    rad_result_free(&run->res);
    rad_scene_free(&run->scene);
    free(run->shots);
    memset(run, 0, sizeof *run);
}

/* ---- the outputs ---------------------------------------------------------- */

static int w_elements(FILE *out, const void *c)
{
    const cli_run *r = c;
    return rad_export_elements_level(out, &r->res.mesh, r->res.B, r->res.level);
}

static int w_matrix(FILE *out, const void *c)
{
    const cli_run *r = c;
    char comment[512];
    snprintf(comment, sizeof comment, "form factors of %s; row i = from element i",
             r->scene.filename);
    return rad_export_matrix_market(out, r->res.F, r->res.mesh.nelements, comment);
}

static int w_elements_npy(FILE *out, const void *c)
{
    const cli_run *r = c;
    return rad_export_elements_npy(out, &r->res.mesh, r->res.B);
}

static int w_matrix_npy(FILE *out, const void *c)
{
    const cli_run *r = c;
    return rad_export_matrix_npy(out, r->res.F, r->res.mesh.nelements);
}

static void run_info(const cli_run *r, rad_run_info *in)
{
    const rad_result *res = &r->res;
    memset(in, 0, sizeof *in);
    in->scene = r->scene.filename;
    /* the hemicube reads neither: the report says null, not the defaults */
    const int contour = r->s->common.ff.method == RAD_FF_CONTOUR;
    in->accuracy = contour ? rad_accuracy_name(r->s->common.ff.accuracy) : NULL;
    in->quadrature = contour ? r->s->common.ff.quadrature : 0;
    in->method = rad_ff_method_name(r->s->common.ff.method);
    in->resolution = r->s->common.ff.resolution;
    in->repaired = &r->scene;
    in->nelements = res->mesh.nelements;
    in->memory_bytes = res->memory_bytes;
    in->memory_available = res->memory_available;
    in->t_parse = r->t_parse;
    in->t_mesh = res->t_mesh;
    in->t_formfactor = res->t_formfactor;
    in->t_solve = res->t_solve;
    in->t_smooth = res->t_smooth;
    in->t_output = r->t_output;
    in->ff_pairs_per_second = res->t_formfactor > 0 ? res->ff.pairs / res->t_formfactor : 0;
    in->matrix = rad_matrix_name(res->matrix ? res->matrix : RAD_MATRIX_DENSE);
    if (res->matrix == RAD_MATRIX_NONE) /* the pairs are integrated inside the shots */
        in->ff_pairs_per_second = res->t_solve > 0 ? res->ff.pairs / res->t_solve : 0;
    in->ff = res->ff_done ? &res->ff : NULL;
    in->solve = res->solve_done ? &res->solve : NULL;
    in->b_negative = res->solve_done && r->status == RAD_OK ? res->b_negative : -1;
    in->status = r->promise_unmet                ? "promise unmet"
                 : r->status == RAD_OK             ? "ok"
                 : r->status == RAD_ERR_SINGULAR ? "singular"
                 : r->status == RAD_ERR_NOCONV   ? "not converged"
                                                 : "error";
}

/* The report is written last (cli_run_write), so its output time is that
 * of every other output, measured up to now. */
static int w_report(FILE *out, const void *c)
{
    const cli_run *r = c;
    rad_run_info in;
    run_info(r, &in);
    if (r->t_output_start > 0)
        in.t_output = cli_seconds() - r->t_output_start;
    return rad_export_report(out, &in);
}

static int w_trace(FILE *out, const void *c)
{
    const cli_run *r = c;
    fputs("step\tshooter\tshot\tunshot\trms\trms_ambient\trms_bands\trms_ambient_bands\n", out);
    for (int k = 0; k < r->nshots; k++) {
        const rad_shot *t = &r->shots[k];
        fprintf(out, "%d\t%d\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", t->step, t->shooter,
                t->shot, t->unshot, t->rms, t->rms_ambient, t->rms_bands, t->rms_ambient_bands);
    }
    return ferror(out) ? -1 : 0;
}

int cli_run_outputs(const cli_run *run, int done, cli_output *o)
{
    const cli_solve *s = run->s;
    const int ok = !done || run->status == RAD_OK;
    int n = 0;
    /* a name ending in .npy asks for NumPy's binary format */
    if (ok && s->elements)
        o[n++] = (cli_output){s->elements,
                              rad_export_is_npy(s->elements) ? w_elements_npy : w_elements, run};
    if (ok && s->form_factors)
        o[n++] = (cli_output){s->form_factors,
                              rad_export_is_npy(s->form_factors) ? w_matrix_npy : w_matrix, run};
    if (s->trace && (ok || run->status == RAD_ERR_NOCONV)) /* it says why */
        o[n++] = (cli_output){s->trace, w_trace, run};
    if (s->report && (!done || run->res.ff_done))
        o[n++] = (cli_output){s->report, w_report, run};
    return n;
}

/* ---- the run -------------------------------------------------------------- */

static int keep_shot(void *user, const rad_shot *row)
{
    cli_run *r = user;
    if (r->nshots == r->cap) {
        int cap = r->cap ? 2 * r->cap : 1024;
        rad_shot *p = realloc(r->shots, sizeof *p * (size_t)cap);
        if (!p)
            return 1; /* stops the solve: "interrupted" */
        r->shots = p;
        r->cap = cap;
    }
    r->shots[r->nshots++] = *row;
    return 0;
}

static void summary(const cli_run *r)
{
    rad_run_info in;
    char hc[32];
    run_info(r, &in);
    if (r->s->common.ff.method == RAD_FF_HEMICUBE) { /* its "accuracy" is the resolution */
        snprintf(hc, sizeof hc, "hemicube %d", in.resolution);
        in.accuracy = hc;
    }
    const rad_solve_report *s = in.solve;
    if (r->res.matrix == RAD_MATRIX_NONE)
        fprintf(stderr, CLI_PROGRAM ": %d elements, matrix none (form factors per shot, %.1f MiB "
                        "estimated); solve %.3g s with %.0f %s (%.3g pairs/s, %s)\n",
                in.nelements, in.memory_bytes / 1048576.0, in.t_solve, in.ff ? in.ff->pairs : 0,
                /* the hemicube integrates nothing: it reads item buffers */
                r->s->common.ff.method == RAD_FF_HEMICUBE ? "pairs from hemicube rows"
                                                          : "pair integrals",
                in.ff_pairs_per_second, in.accuracy);
    else
        fprintf(stderr, CLI_PROGRAM ": %d elements, matrix dense, %.1f MiB of matrices; form "
                        "factors %.3g s (%.3g pairs/s, %s), solve %.3g s\n",
                in.nelements, in.memory_bytes / 1048576.0, in.t_formfactor,
                in.ff_pairs_per_second, in.accuracy, in.t_solve);
    if (r->res.level) {
        int count[16] = {0}, top = 0;
        for (int e = 0; e < r->res.mesh.nelements; e++) {
            const int l = r->res.level[e] < 15 ? r->res.level[e] : 15;
            count[l]++;
            top = l > top ? l : top;
        }
        fprintf(stderr, CLI_PROGRAM ": adaptive subdivision: %d splits; elements by level",
                r->res.splits);
        for (int l = 0; l <= top; l++)
            fprintf(stderr, " %d", count[l]);
        fputc('\n', stderr);
    }
    if (in.ff && r->s->common.ff.method == RAD_FF_HEMICUBE)
        fprintf(stderr, CLI_PROGRAM ": visibility: the hemicubes' z-buffers\n");
    else if (in.ff && in.ff->vis_needed)
        fprintf(stderr, CLI_PROGRAM ": visibility: %.0f of %.0f pairs blockable, %.0f hidden, "
                        "%.0f partly; %.3g s; %.3g candidate blockers a blockable pair; "
                        "%.3g evaluations of the hidden part a partly hidden pair\n",
                in.ff->vis_pairs_blockable, in.ff->vis_pairs_tested, in.ff->vis_pairs_blocked,
                in.ff->vis_pairs_partial, in.ff->vis_seconds,
                in.ff->vis_pairs_blockable > 0 ? in.ff->vis_candidates / in.ff->vis_pairs_blockable
                                               : 0.0,
                in.ff->vis_pairs_partial > 0 ? in.ff->vis_evaluations / in.ff->vis_pairs_partial
                                             : 0.0);
    else if (in.ff)
        fprintf(stderr, CLI_PROGRAM ": visibility: no pair can be blocked, none computed\n");
    if (!s)
        return;
    if (s->bounces >= 0)
        fprintf(stderr, CLI_PROGRAM ": %d bounces (Jacobi from B = E)", s->bounces);
    else if (s->solver == RAD_SOLVER_GAUSS || s->solver == RAD_SOLVER_CHOLESKY ||
             (s->solver == RAD_SOLVER_CG && s->fallbacks)) {
        fprintf(stderr, CLI_PROGRAM ": %s, %d factorisation%s, rcond %.3g", rad_solver_name(s->solver),
                s->systems, s->systems == 1 ? "" : "s", s->rcond);
        if (!isnan(s->ff_error_bound))
            fprintf(stderr, "; F's error moves B by %.3g relative at most", s->ff_error_bound);
    }
    else if (s->solver == RAD_SOLVER_PROGRESSIVE)
        fprintf(stderr, CLI_PROGRAM ": progressive, %d shooting steps", s->sweeps);
    else {
        fprintf(stderr, CLI_PROGRAM ": %s, %d %s, ||diag(rho) F||inf %.6g, ", rad_solver_name(s->solver),
                s->sweeps, s->solver == RAD_SOLVER_CG ? "iterations" : "sweeps", s->contraction);
        if (isnan(s->error_bound))
            fprintf(stderr, "no error bound");
        else
            fprintf(stderr, "error <= %.3g relative", s->error_bound);
        if (s->solver != RAD_SOLVER_CG)
            fprintf(stderr, ", convergence factor %.6g", s->spectral_radius);
    }
    fprintf(stderr, "; residual %.3g; F row sums [%.15g, %.15g]\n", s->residual,
            s->row_sum_min, s->row_sum_max);
    if (s->fallbacks)
        fprintf(stderr, CLI_PROGRAM ": %s\n", s->fallback);
    if (s->emitted[0] > 0 || s->emitted[1] > 0 || s->emitted[2] > 0) {
        /* a band that emits nothing has no ratio: '-' (radi_solve_balance
         * keeps the difference there) */
        fprintf(stderr, CLI_PROGRAM ": energy balance (emitted - absorbed - escaped)/emitted:");
        for (int b = 0; b < RAD_BANDS; b++)
            if (s->emitted[b] > 0)
                fprintf(stderr, " %.3g", s->balance[b]);
            else
                fprintf(stderr, " -");
        fprintf(stderr, "\n");
    }
    else
        fprintf(stderr, CLI_PROGRAM ": energy balance: nothing is emitted\n");
}

/* Warn when the energy balance of an emitting band is off by more than
 * BALANCE_WARN of what it emits.  With reciprocal form factors
 * (A_i F_ij = A_j F_ji, which the contour integral keeps exactly) the
 * balance is the solve's residual, far below this; the hemicube samples
 * each row at its element's centre and breaks reciprocity (0.456 seen on
 * a model whose floor's centre sat under it), and the classic rule's
 * factors leave [0, 1] where elements touch.  The warning names the
 * likely cause. */
#define BALANCE_WARN 1e-2
static void balance_warning(const cli_run *r)
{
    rad_run_info in;
    run_info(r, &in);
    const rad_solve_report *s = in.solve;
    if (!s)
        return;
    double worst = 0;
    for (int b = 0; b < RAD_BANDS; b++)
        if (s->emitted[b] > 0 && isfinite(s->balance[b]))
            worst = fmax(worst, fabs(s->balance[b]));
    if (!(worst > BALANCE_WARN))
        return;
    const char *why =
        r->s->common.ff.method == RAD_FF_HEMICUBE
            ? "the hemicube samples each element from its centre, so its factors are not "
              "reciprocal; a finer --resolution or --mesh, or --form-factors-method contour"
        : r->s->common.ff.accuracy == RAD_ACCURACY_CLASSIC
            ? "the classic rule's form factors are off where elements touch; try --accuracy "
              "default"
            : "see the form factors' row sums and the residual (--report)";
    cli_error("warning: energy balance off by %.3g of what is emitted (above %g): %s", worst,
              BALANCE_WARN, why);
}

/* Is every element's radiosity exactly 0 (nothing emits)? */
static int no_light(const rad_result *r)
{
    const size_t n = (size_t)r->mesh.nelements * RAD_BANDS;
    if (!r->B || n == 0)
        return 0;
    for (size_t k = 0; k < n; k++)
        if (r->B[k] != 0)
            return 0;
    return 1;
}

int cli_run_solve(cli_run *run)
{
    cli_solve *s = run->s;
    rad_pipeline_options po;
    rad_error err;
    rad_pipeline_options_init(&po);
    cli_progress_attach(&s->common);
    po.ff = s->common.ff;
    po.solve = s->solve;
    po.keep_form_factors = s->form_factors != NULL;
    po.vertex_rule = s->vertex_rule;
    po.crease = s->crease;
    po.matrix = s->matrix;
    if (s->trace) {
        po.solve.on_shot = keep_shot;
        po.solve.shot_user = run;
    }
    run->status = (s->pipeline ? s->pipeline : rad_pipeline_run)(&run->scene, &po, &run->res,
                                                                 &err);
    if (run->res.ff_done && cli_ff_verdict(&s->common, &run->res.ff)) {
        run->promise_unmet = 1;
        if (run->status == RAD_OK) { /* the report says why; nothing else */
            run->status = RAD_ERR_INVALID;
            return 1;
        }
    }
    if (run->status != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    if (run->res.b_negative)
        cli_error("warning: B is negative in %ld element-band values: no physical "
                  "solution%s", run->res.b_negative,
                  s->common.ff.accuracy == RAD_ACCURACY_CLASSIC
                      ? " (the classic rule's form factors are wrong here; try --accuracy "
                        "default)"
                      : "");
    if (no_light(&run->res))
        cli_error("warning: every radiosity is 0: no surface of the scene emits (a material "
                  "with emit above 0; in an OBJ file's MTL, Ke)");
    else
        balance_warning(run);
    if (!s->common.quiet)
        summary(run);
    return 0;
}

/* Write what the run produced together with the command's own outputs
 * (extra, n_extra; written only when the run succeeded); 0 or 1. */
int cli_run_write(cli_run *run, const cli_output *extra, int n_extra)
{
    cli_output o[CLI_MAX_OUTPUTS];
    int n = cli_run_outputs(run, 1, o);
    for (int k = 0; k < n_extra && run->status == RAD_OK; k++)
        o[n++] = extra[k];
    for (int k = 0; k + 1 < n; k++) /* the report last: it states the others' time */
        if (o[k].write == w_report) {
            const cli_output rep = o[k];
            memmove(o + k, o + k + 1, sizeof *o * (size_t)(n - k - 1));
            o[n - 1] = rep;
            break;
        }
    double t0 = cli_seconds();
    run->t_output_start = t0;
    int st = cli_outputs_write(o, n);
    run->t_output = cli_seconds() - t0;
    return st;
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
           "Examples:\n"
           "  radiosity solve data/goral1984-cube.scene --elements B.tsv --report \\\n"
           "      run.json\n"
           "  radiosity solve --mesh 20x20 --solver cg data/goral1984-cube.scene \\\n"
           "      -o cube.ply\n"
           "  radiosity solve --accuracy reference --strict data/grey-cube.scene \\\n"
           "      --elements B.npy\n"
           "\n"
           "Output paths are checked before any work.  A regular file is written to\n"
           "a temporary beside it, and all outputs are renamed together at the end:\n"
           "a failed or interrupted run (SIGINT, SIGTERM, SIGHUP: exit 128 + signal)\n"
           "leaves the old files whole.  A device or FIFO is written in place; a\n"
           "symbolic link is followed and its target replaced.  An option that the\n"
           "chosen solver would ignore is a usage error.  Exit status: 0 on success,\n"
           "1 on an error (including a singular or non-converged system, or a mesh\n"
           "that does not fit in memory, refused before meshing), 2 on a usage error.\n");
}

static int w_ply(FILE *out, const void *c)
{
    const cli_run *r = c;
    return rad_export_ply(out, &r->scene, &r->res.mesh, r->res.B, r->res.Bv);
}

int cmd_solve(int argc, char **argv)
{
    const cli_solve_variant serial = {help, NULL, NULL, NULL};
    return cmd_solve_variant(argc, argv, &serial);
}

/* The hint names the program that was run: radiosity-mpi's usage errors
 * point to its own --help, which lists what it accepts. */
static int solve_usage_hint(const cli_solve_variant *v)
{
    if (!v->program)
        return cli_usage_hint("solve");
    fprintf(stderr, "Try '%s solve --help' for more information.\n", v->program);
    return EXIT_USAGE;
}

int cmd_solve_variant(int argc, char **argv, const cli_solve_variant *v)
{
    static const struct option longopts[] = {
        {"output", required_argument, NULL, 'o'}, CLI_SOLVE_LONGOPTS, {NULL, 0, NULL, 0}};
    cli_solve s;
    cli_run run;
    const char *output = NULL;
    int opt;
    cli_solve_init(&s);
    cli_join_optional(&argc, argv);
    while ((opt = getopt_long(argc, argv, "ho:q", longopts, NULL)) != -1) {
        if (opt == OPT_HELP || opt == 'h') {
            v->help();
            return 0;
        }
        if (opt == 'o') {
            output = optarg;
            continue;
        }
        if (cli_solve_option(&s, opt, optarg) != 0)
            return solve_usage_hint(v);
    }
    if (optind != argc - 1) {
        cli_error(optind >= argc ? "solve needs a SCENE" : "solve takes one SCENE");
        return solve_usage_hint(v);
    }
    if (cli_solve_check(&s) || (v->check && v->check(&s)))
        return solve_usage_hint(v);
    s.pipeline = v->pipeline;
    if (cli_run_load(&run, &s, argv[optind]))
        return 1;
    cli_output o[CLI_MAX_OUTPUTS];
    const cli_output ply = {output, w_ply, &run};
    int n = cli_run_outputs(&run, 0, o);
    o[n++] = ply;
    int status = cli_outputs_check(o, n);
    if (!status) {
        status = cli_run_solve(&run);
        status = cli_run_write(&run, &ply, 1) || status;
    }
    cli_run_free(&run);
    return status;
}
