/* cli.h -- what the subcommands share: options, messages, loading.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The command-line layer only parses and dispatches; every number comes
 * from the library.  Exit status: 0 success, 1 error, 2 usage error.
 */
#ifndef RAD_CLI_H
#define RAD_CLI_H

#include <getopt.h>
#include <stdio.h>

#include "radiosity.h"

#define EXIT_USAGE 2

/* Options every numerical subcommand accepts. */
typedef struct cli_common {
    int mesh_n, mesh_m;         /* 0: keep the scene's */
    rad_ff_options ff;
    int quiet;
} cli_common;

/* Long-option ids for the common options (above any short option). */
enum {
    OPT_MESH = 1000,
    OPT_QUADRATURE,
    OPT_ACCURACY,
    OPT_THREADS,
    OPT_QUIET,
    OPT_HELP,
    OPT_COMMON_END
};

#define CLI_COMMON_LONGOPTS                                       \
    {"mesh", required_argument, NULL, OPT_MESH},                  \
    {"quadrature", required_argument, NULL, OPT_QUADRATURE},      \
    {"accuracy", required_argument, NULL, OPT_ACCURACY},          \
    {"threads", required_argument, NULL, OPT_THREADS},            \
    {"quiet", no_argument, NULL, OPT_QUIET},                      \
    {"help", no_argument, NULL, OPT_HELP}

#define CLI_COMMON_HELP                                                          \
    "      --mesh NxM          mesh every quad into N x M elements\n"            \
    "      --quadrature K      Gauss points per edge (1-20; 3 is the paper's\n"  \
    "                          nine-point rule)\n"                               \
    "      --accuracy MODE     classic (the 1984 rule alone), default (that\n"   \
    "                          rule made safe) or reference (error-controlled)\n"\
    "      --threads N         OpenMP threads (default: all cores)\n"            \
    "  -q, --quiet             no progress bar or summary\n"                     \
    "  -h, --help              show this help and exit\n"

void cli_common_init(cli_common *c);
/* Handle a common option: 0 handled, 1 not a common option, 2 usage error
 * (message printed). */
int cli_common_option(cli_common *c, int opt, const char *arg);

/* "radiosity: " + message on standard error. */
void cli_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void cli_error_rec(const rad_error *err);
/* "Try 'radiosity CMD --help'." and return EXIT_USAGE. */
int cli_usage_hint(const char *cmd);

/* Parse "NxM" into positive n, m. */
int cli_parse_mesh(const char *arg, int *n, int *m);
int cli_parse_int(const char *arg, long lo, long hi, int *out);
int cli_parse_double(const char *arg, double *out);
/* Parse "X,Y,Z". */
int cli_parse_vec3(const char *arg, rad_vec3 *out);

/* Write an output through fn, atomically (atomicfile.h): 0, or 1 with the
 * error printed.  fn returns 0, or -1 on a write error. */
typedef int (*cli_writer_fn)(FILE *out, const void *ctx);
int cli_write_atomic(const char *path, cli_writer_fn fn, const void *ctx);

/* Load the scene and apply --mesh; prints the error and returns 1 on
 * failure. */
int cli_load_scene(const char *path, const cli_common *c, rad_scene *scene);

/* A progress bar with time left on standard error when it is a terminal. */
int cli_progress(void *user, const char *stage, double done, double total);
void cli_progress_attach(cli_common *c);

/* ---- the solve pipeline, shared by solve, render and sweep ------------- */

enum {
    OPT_SOLVER = 1100,
    OPT_TOLERANCE,
    OPT_MAX_ITERATIONS,
    OPT_BOUNCES,
    OPT_ERROR_BOUNDS,
    OPT_REPORT,
    OPT_ELEMENTS,
    OPT_FORM_FACTORS,
    OPT_TRACE,
    OPT_PATCHES,
    OPT_SOLVE_END
};

typedef struct cli_solve {
    cli_common common;
    rad_solve_options solve;
    const char *report;         /* --report FILE (JSON), or NULL */
    const char *elements;       /* --elements FILE, or NULL */
    const char *form_factors;   /* --form-factors FILE, or NULL */
} cli_solve;

#define CLI_SOLVE_LONGOPTS                                                \
    {"solver", required_argument, NULL, OPT_SOLVER},                      \
    {"tolerance", required_argument, NULL, OPT_TOLERANCE},                \
    {"max-iterations", required_argument, NULL, OPT_MAX_ITERATIONS},      \
    {"bounces", required_argument, NULL, OPT_BOUNCES},                    \
    {"error-bounds", no_argument, NULL, OPT_ERROR_BOUNDS},                \
    {"report", required_argument, NULL, OPT_REPORT},                      \
    {"elements", required_argument, NULL, OPT_ELEMENTS},                  \
    {"form-factors", required_argument, NULL, OPT_FORM_FACTORS},          \
    {"trace", required_argument, NULL, OPT_TRACE},                        \
    {"patches", no_argument, NULL, OPT_PATCHES},                          \
    CLI_COMMON_LONGOPTS

#define CLI_SOLVE_HELP                                                             \
    "      --solver NAME       gauss (LU with partial pivoting, LAPACK; default),\n" \
    "                          jacobi, gauss-seidel or progressive (shooting,\n"  \
    "                          Cohen et al. 1988)\n"                              \
    "      --trace FILE        progressive: one TSV row per shooting step\n"       \
    "      --patches           progressive: each surface shoots as one patch\n"    \
    "      --tolerance T       iterative solvers: stop when the relative change\n"\
    "                          of B between sweeps is below T (default 1e-12;\n"  \
    "                          progressive: unshot power / emitted power)\n"      \
    "      --max-iterations N  iterative solvers: give up after N sweeps (or\n"     \
    "                          shooting steps)\n"                                 \
    "                          (default 100000)\n"                                \
    "      --bounces K         exactly K reflections: B = sum_{m<=K} (rho F)^m E\n"\
    "      --error-bounds      gauss: forward and backward error bounds (dgesvx)\n"\
    "      --report FILE       full diagnostics as JSON\n"                         \
    "      --elements FILE     per-element table (TSV)\n"                          \
    "      --form-factors FILE the form-factor matrix (Matrix Market)\n"          \
    CLI_COMMON_HELP

/* The solution of a scene, as the pipeline leaves it. */
typedef struct cli_result {
    rad_scene scene;
    rad_mesh mesh;
    double *B;                  /* nelements x RAD_BANDS, column-major */
    double *Bv;                 /* nvertices x RAD_BANDS, column-major */
} cli_result;

void cli_solve_init(cli_solve *s);
/* 0 handled, 1 not a solve/common option, 2 usage error (printed). */
int cli_solve_option(cli_solve *s, int opt, const char *arg);
/* Load, mesh, form factors, solve, smooth, and write --report, --elements
 * and --form-factors; prints the summary unless quiet.  0 on success, 1 on
 * an error (printed).  On success the caller owns r (cli_result_free). */
int cli_solve_run(cli_solve *s, const char *scene_path, cli_result *r);
void cli_result_free(cli_result *r);

int cmd_formfactor(int argc, char **argv);
int cmd_solve(int argc, char **argv);
int cmd_render(int argc, char **argv);
int cmd_progress(int argc, char **argv);
int cmd_sweep(int argc, char **argv);
int cmd_analytic(int argc, char **argv);

#endif /* RAD_CLI_H */
