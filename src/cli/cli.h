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

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "radiosity/render.h"
#include "radiosity/pipeline.h"
#include "radiosity/pipeline.h"

#define EXIT_USAGE 2

/* Options every numerical subcommand accepts. */
typedef struct cli_common {
    int mesh_n, mesh_m;         /* 0: keep the scene's */
    double max_size;            /* --max-element-size, or 0 */
    rad_ff_options ff;
    int quiet;
    int strict;                 /* --strict: an unmet accuracy promise is an error */
    int given_resolution;       /* --resolution was given */
    int given_accuracy;         /* --accuracy or --quadrature was given */
    rad_scene_format format;    /* --format: the scene's, or AUTO (by its name) */
} cli_common;

/* Long-option ids for the common options (above any short option). */
enum {
    OPT_MESH = 1000,
    OPT_QUADRATURE,
    OPT_ACCURACY,
    OPT_THREADS,
    OPT_QUIET,
    OPT_STRICT,
    OPT_FF_METHOD,
    OPT_RESOLUTION,
    OPT_HELP,
    OPT_FORMAT,
    OPT_MAX_SIZE,
    OPT_COMMON_END
};

#define CLI_COMMON_LONGOPTS                                       \
    {"mesh", required_argument, NULL, OPT_MESH},                  \
    {"max-element-size", required_argument, NULL, OPT_MAX_SIZE},  \
    {"quadrature", required_argument, NULL, OPT_QUADRATURE},      \
    {"accuracy", required_argument, NULL, OPT_ACCURACY},          \
    {"threads", required_argument, NULL, OPT_THREADS},            \
    {"quiet", no_argument, NULL, OPT_QUIET},                      \
    {"strict", no_argument, NULL, OPT_STRICT},                    \
    {"format", required_argument, NULL, OPT_FORMAT},              \
    {"help", no_argument, NULL, OPT_HELP}

/* The last lines of the programs' --help (radiosity, radiosity-mpi):
 * where bugs go (GNU coding standards, --help).  The project publishes
 * no address of its own. */
#define CLI_BUG_HELP                                                             \
    "Report bugs to the issue tracker of the repository the source came\n"     \
    "from, with the command, the scene file and the output of --version;\n"    \
    "README.md (installed beside the examples) says what else helps.\n"

#define CLI_COMMON_HELP                                                          \
    "      --mesh NxM          mesh every quad into N x M elements, and every\n"\
    "                          triangle into max(N,M)^2 (a polygon: each of the\n"\
    "                          triangles around its centroid)\n"             \
    "      --max-element-size L\n"                                           \
    "                          mesh every surface so that no element side is\n"\
    "                          longer than L (the scene's units)\n"          \
    "      --quadrature K      Gauss points per edge (1-20; 3 is the paper's\n"  \
    "                          nine-point rule)\n"                               \
    "      --accuracy MODE     classic (the 1984 rule alone), default (that\n"   \
    "                          rule made safe) or reference (error-controlled)\n"\
    "      --threads N         OpenMP threads (default: all cores)\n"            \
    "      --strict            an unmet accuracy promise (a form factor whose own\n" \
    "                          error estimate exceeds the mode's 1e-6 or 1e-9)\n"\
    "                          is an error (exit 1), not a warning; so is each\n"\
    "                          repair of an OBJ file (radiosity-scene(5))\n"     \
    "      --format F          the scene's format: scene, obj or vs3 (default: by\n"\
    "                          its name, .obj or .vs3, else scene; for '-',\n" \
    "                          standard input, and other names)\n"              \
    "  -q, --quiet             no progress bar or summary\n"                     \
    "  -h, --help              show this help and exit\n"

/* The form-factor method, for the commands that can use either
 * (formfactor, solve, render, progress): cli_common_option parses them. */
#define CLI_METHOD_LONGOPTS                                               \
    {"form-factors-method", required_argument, NULL, OPT_FF_METHOD},      \
    {"resolution", required_argument, NULL, OPT_RESOLUTION}

#define CLI_METHOD_HELP                                                             \
    "      --form-factors-method M  contour (the contour integral between\n"        \
    "                          elements, the default) or hemicube (Cohen &\n"       \
    "                          Greenberg 1985: a z-buffer on each element's\n"     \
    "                          centre; faster where surfaces hide each other,\n"   \
    "                          less accurate: its pixels alias and its centre\n"   \
    "                          stands for the element; --accuracy,\n"            \
    "                          --quadrature and --strict are the contour's)\n"    \
    "      --resolution R      hemicube: R x R pixels on the top face, R x R/2 on\n"\
    "                          each side (even, 2-4096; default 64)\n"

void cli_common_init(cli_common *c);
/* After the options: --resolution without --form-factors-method hemicube,
 * and --accuracy, --quadrature or --strict with it (the contour's), are
 * usage errors.  0, or 2 (printed). */
int cli_common_check(const cli_common *c);
/* Handle a common option: 0 handled, 1 not a common option, 2 usage error
 * (message printed). */
int cli_common_option(cli_common *c, int opt, const char *arg);

/* Say what the form factors cannot stand behind: values outside [0, 1],
 * rows summing above 1, entries whose own estimate misses the mode's
 * promise (the classic rule's faults point to --accuracy default).  Warns
 * on standard error; returns 1 when --strict makes an unmet promise an
 * error (printed), else 0. */
int cli_ff_verdict(const cli_common *c, const rad_ff_stats *st);

/* The name that starts every message: the program's own (radiosity-mpi
 * compiles these files with its name, Makefile.am). */
#ifndef CLI_PROGRAM
#define CLI_PROGRAM "radiosity"
#endif

/* CLI_PROGRAM ": " + message on standard error. */
void cli_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void cli_error_rec(const rad_error *err);
/* "Try 'radiosity CMD --help'." and return EXIT_USAGE. */
int cli_usage_hint(const char *cmd);

/* Join "--patches PxQ" (two words) into "--patches=PxQ" in argv, for the
 * option's optional argument; argv keeps its length (the rest shifts). */
void cli_join_optional(int *argc, char **argv);

/* Parse "NxM" into positive n, m. */
int cli_parse_mesh(const char *arg, int *n, int *m);
int cli_parse_int(const char *arg, long lo, long hi, int *out);
int cli_parse_double(const char *arg, double *out);
/* Parse "X,Y,Z". */
int cli_parse_vec3(const char *arg, rad_vec3 *out);
/* --exposure-from reflectors|all: 0, or 2 (the usage error printed). */
int cli_parse_exposure_from(const char *arg, rad_exposure_from *out);
#define CLI_EXPOSURE_FROM_HELP                                                   \
    "      --exposure-from SET which elements the automatic exposure maps to\n"   \
    "                          full scale: reflectors (default: the brightest\n" \
    "                          element that emits nothing is white, brighter\n"  \
    "                          lamps clip) or all (the brightest element, lamps\n"\
    "                          included)\n"

/* ---- outputs (cli_output.c) --------------------------------------------- */

/* A writer prints ctx to out and returns 0, or -1 on a write error. */
typedef int (*cli_writer_fn)(FILE *out, const void *ctx);

/* One output of a run; a NULL path is skipped. */
typedef struct cli_output {
    const char *path;
    cli_writer_fn write;
    const void *ctx;
} cli_output;

#define CLI_MAX_OUTPUTS 16

/* Remove registered temporaries and exit 128 + signal on SIGINT, SIGTERM
 * and SIGHUP (those not ignored at start-up). */
void cli_signals_install(void);
/* For a command that runs until a signal (view): while deferred, SIGINT,
 * SIGTERM and SIGHUP are only noted, in whichever thread takes them, and
 * cli_signal_taken returns the one noted (0: none) and forgets it. */
void cli_signals_defer(int defer);
int cli_signal_taken(void);
/* Before any work: could every path be written?  0, or 1 (printed). */
int cli_outputs_check(const cli_output *o, int n);
/* A picture's path whose extension names another image format (out.jpg):
 * 1 (printed, naming `option`), else 0. */
int cli_png_name_check(const char *path, const char *option);
/* Write every output to its temporary, then rename them all together
 * (atomicfile.h): 0, or 1 with the error printed and nothing replaced. */
int cli_outputs_write(const cli_output *o, int n);
/* One output alone. */
int cli_write_atomic(const char *path, cli_writer_fn fn, const void *ctx);

/* Outputs written one by one during a run (animate's frames) and renamed
 * together at its end: each is written to its temporary and closed at
 * once (no descriptor held); cli_staged_commit renames them all with the
 * signals held; cli_staged_abort, a failure or a signal removes them all,
 * so a failed run replaces none.  One staged set at a time. */
typedef struct cli_staged {
    struct rad_afile *f;
    int n, cap;
} cli_staged;
int cli_staged_begin(cli_staged *s, int capacity);                   /* 0, or 1 (printed) */
int cli_staged_write(cli_staged *s, const char *path, cli_writer_fn fn, const void *ctx);
int cli_staged_commit(cli_staged *s);                                /* 0, or 1 (printed) */
void cli_staged_abort(cli_staged *s);

/* Load the scene and apply --mesh; prints the error and returns 1 on
 * failure. */
/* What View3D's shape (rad_mesh_reported) does to the scene: k rows for
 * n elements, `obstructed` of them left out, `joined` surfaces combined
 * with earlier ones; row (free it) each element's row, -1 none.  0, or 1
 * (printed). */
typedef struct cli_shape {
    int k, obstructed, joined;
    int *row;
} cli_shape;
int cli_shape_of(const rad_scene *scene, const rad_mesh *mesh, cli_shape *sh);
int cli_load_scene(const char *path, const cli_common *c, rad_scene *scene);

/* Wall-clock seconds (CLOCK_MONOTONIC), for the summary's timings. */
double cli_seconds(void);

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
    OPT_VERTEX_RULE,
    OPT_CREASE,
    OPT_MATRIX,
    OPT_ADAPTIVE,
    OPT_SUBDIVIDE_THRESHOLD,
    OPT_MAX_DEPTH,
    OPT_SUBDIVIDE_TEST,
    OPT_SOLVE_END
};

typedef struct cli_solve {
    cli_common common;
    rad_solve_options solve;
    const char *report;         /* --report FILE (JSON), or NULL */
    const char *elements;       /* --elements FILE, or NULL */
    const char *form_factors;   /* --form-factors FILE, or NULL */
    const char *trace;          /* --trace FILE (progressive), or NULL */
    rad_matrix_mode matrix;     /* --matrix, default auto */
    int given_solver, given_tolerance, given_max_iterations, given_bounces, given_matrix;
    rad_pipeline_fn pipeline;   /* NULL: rad_pipeline_run (radiosity-mpi
                                   sets its distributed one) */
    rad_vertex_rule vertex_rule;  /* --vertex-rule */
    double crease;              /* --crease DEG, 0: never across surfaces;
                                   RAD_CREASE_AUTO when not given */
    int given_adaptive_option;  /* --subdivide-threshold, --max-depth or
                                   --subdivide-test */
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
    {"patches", optional_argument, NULL, OPT_PATCHES},                    \
    {"matrix", required_argument, NULL, OPT_MATRIX},                      \
    {"vertex-rule", required_argument, NULL, OPT_VERTEX_RULE},            \
    {"crease", required_argument, NULL, OPT_CREASE},                      \
    CLI_METHOD_LONGOPTS,                                                  \
    {"adaptive", no_argument, NULL, OPT_ADAPTIVE},                        \
    {"subdivide-threshold", required_argument, NULL, OPT_SUBDIVIDE_THRESHOLD}, \
    {"max-depth", required_argument, NULL, OPT_MAX_DEPTH},                \
    {"subdivide-test", required_argument, NULL, OPT_SUBDIVIDE_TEST},      \
    CLI_COMMON_LONGOPTS

#define CLI_SOLVE_HELP CLI_SOLVE_HELP_SOLVERS CLI_SOLVE_HELP_FILES CLI_METHOD_HELP CLI_COMMON_HELP

/* ... in parts: the solvers and their options (radiosity-mpi has its own,
 * the distributed ones), then the output files, which both programs write
 * alike. */
#define CLI_SOLVE_HELP_SOLVERS                                                     \
    "      --solver NAME       gauss (LU with partial pivoting, LAPACK; default),\n" \
    "                          cholesky (the symmetric form diag(A/rho)(I - rho F),\n"\
    "                          half LU's flops; LU where it is not positive\n"   \
    "                          definite), jacobi, gauss-seidel, cg (conjugate\n" \
    "                          gradients on the symmetric form) or progressive\n"\
    "                          (shooting, Cohen et al. 1988)\n"                   \
    "      --trace FILE        progressive: one TSV row per shooting step (step\n" \
    "                          shooter shot unshot rms rms_ambient)\n"           \
    "      --patches[=PxQ]     progressive: each surface shoots as one patch (its\n"\
    "                          elements keep their own unshot radiosity: the\n" \
    "                          same B as gauss); with PxQ each quad surface is\n"\
    "                          cut into a P x Q grid of patches, each shooting\n"\
    "                          one unshot radiosity (substructuring, Cohen et\n"\
    "                          al. 1988 sec. 3.4): elements receive, the limit\n"\
    "                          is the patch-element solution, not gauss's\n"   \
    "      --matrix MODE       progressive: dense (fill F first), none (each\n" \
    "                          shot computes its shooter's form factors and\n" \
    "                          forgets them: O(N) memory) or auto (default:\n" \
    "                          dense when 8 N^2 bytes fit in half the memory\n"\
    "                          allowed, else none)\n"                           \
    "      --adaptive          progressive: adaptive subdivision (Cohen et al.\n"\
    "                          1988 sec. 4): the mesh's elements shoot as fixed\n"\
    "                          patches; after each shot an element whose B\n"   \
    "                          differs from an edge neighbour's by more than\n"\
    "                          the threshold is split into four, and the new\n"\
    "                          elements receive from every patch that has\n"   \
    "                          shot; form factors on the fly (as --matrix\n"   \
    "                          none); the element table gets a last column\n"  \
    "                          `level' (0: a starting element); outputs show\n"\
    "                          the adaptive mesh, hanging vertices interpolated\n"\
    "                          along their edge (no cracks)\n"                \
    "      --subdivide-threshold T  --adaptive: split an element where |B -\n"\
    "                          B_neighbour| > T times the largest reflected\n" \
    "                          radiosity (B - E) in the scene, in some band\n" \
    "                          (default 0.1)\n"                                \
    "      --max-depth D       --adaptive: at most D splits below a starting\n"\
    "                          element, 0 to 8 (default 3: sides down to 1/8);\n"\
    "                          refused when every level's elements together\n"\
    "                          could pass 4,000,000\n"                       \
    "      --subdivide-test difference|error  --adaptive: what T bounds: the\n"\
    "                          difference itself (default, the paper's test)\n"\
    "                          or the difference times the element's side\n" \
    "                          over the largest patch's (error: what each\n"  \
    "                          split gains in area-weighted RMS error evened\n"\
    "                          out; fewer elements for the same RMS)\n"      \
    "      --tolerance T       jacobi, gauss-seidel, cg, progressive: stop when a\n"\
    "                          bound on the relative error of B is below T\n"   \
    "                          (q/(1-q) times the last change, q the contraction\n"\
    "                          factor; cg: residual/(1-q)) (default 1e-12;\n"   \
    "                          progressive: unshot power / emitted power)\n"    \
    "      --max-iterations N  jacobi, gauss-seidel, cg, progressive: give up\n" \
    "                          after N sweeps or steps (default 100000)\n"     \
    "      --bounces K         exactly K reflections: B = sum_{m<=K} (rho F)^m E\n"\
    "                          (a solver of its own: no --solver, --tolerance)\n"\
    "      --error-bounds      gauss: forward and backward error bounds (dgesvx)\n"

#define CLI_SOLVE_HELP_FILES                                                       \
    "      --report FILE       full diagnostics as JSON\n"                         \
    "      --elements FILE     per-element table (TSV; FILE.npy: B as an n x 3\n"  \
    "                          float64 NumPy array)\n"                           \
    "      --form-factors FILE the form-factor matrix (Matrix Market; FILE.npy:\n"\
    "                          n x n float64 NumPy array, row i = from i)\n"     \
    "      --vertex-rule RULE  vertex radiosity on a surface's boundary:\n"     \
    "                          extrapolate (linear, Goral et al. 1984; default)\n"\
    "                          or corner ((vertex + nearest interior vertex)/2\n"\
    "                          = mean of the elements at the vertex)\n"         \
    "      --crease DEG        smooth vertex radiosity across surfaces of one\n"\
    "                          object and material that meet at a point with\n"\
    "                          normals less than DEG degrees apart (default:\n"\
    "                          30 for an OBJ model, whose faces are parts of\n"\
    "                          one shape, 0 (never) for scene and .vs3 files;\n"\
    "                          not with --adaptive)\n"

/* One run of the pipeline (pipeline.h) as a command sees it. */
typedef struct cli_run {
    rad_scene scene;
    rad_result res;
    rad_status status;          /* of rad_pipeline_run (RAD_ERR_INVALID when
                                   --strict refused an unmet promise) */
    int promise_unmet;          /* --strict refused the run for that */
    double t_parse, t_output;
    double t_output_start;      /* when the outputs began (cli_run_write) */
    rad_shot *shots;            /* the --trace rows */
    int nshots, cap;
    cli_solve *s;
} cli_run;

void cli_solve_init(cli_solve *s);
/* 0 handled, 1 not a solve/common option, 2 usage error (printed). */
int cli_solve_option(cli_solve *s, int opt, const char *arg);
/* Options that contradict each other or that the chosen solver would
 * ignore: 0, or 2 (printed). */
int cli_solve_check(const cli_solve *s);
/* --adaptive, --subdivide-threshold, --max-depth, --subdivide-test into
 * so (cli_adaptive.c; *given_option set by the last three): 0 handled, 1
 * not one of them, 2 usage error (printed). */
int cli_adaptive_option(rad_solve_options *so, int *given_option, int opt, const char *arg);
/* Load the scene and apply --mesh: 0, or 1 (printed). */
int cli_run_load(cli_run *run, cli_solve *s, const char *path);
/* The outputs the solve options ask for (--report, --elements,
 * --form-factors, --trace), appended at o; returns how many.  Before the
 * run (done = 0) all of them, for cli_outputs_check; after a failed run
 * only what says why (the report, and the trace of a solve that did not
 * converge). */
int cli_run_outputs(const cli_run *run, int done, cli_output *o);
/* The pipeline on the loaded scene; prints the summary unless quiet.  0,
 * or 1 with the error printed (run->status says which). */
int cli_run_solve(cli_run *run);
/* Write the run's outputs together with the command's own (extra, written
 * only when the run succeeded; cli_outputs_write): 0, or 1 (printed). */
int cli_run_write(cli_run *run, const cli_output *extra, int n_extra);
void cli_run_free(cli_run *run);

/* `solve` with another pipeline (radiosity-mpi): its own help, a check
 * of the options it cannot honour (0, or 2 printed), and the run. */
typedef struct cli_solve_variant {
    void (*help)(void);
    int (*check)(const cli_solve *s);
    rad_pipeline_fn pipeline;
    const char *program; /* for "Try 'PROGRAM solve --help'": NULL is radiosity */
} cli_solve_variant;
int cmd_solve_variant(int argc, char **argv, const cli_solve_variant *v);

/* The program's main (cli.c), and the end of it: close standard output
 * and say if it failed (rc, or 1). */
int cli_main(int argc, char **argv);
int cli_finish_stdout(int rc);
void cli_version(const char *program);

int cmd_formfactor(int argc, char **argv);
int cmd_solve(int argc, char **argv);
int cmd_render(int argc, char **argv);
int cmd_progress(int argc, char **argv);
int cmd_view(int argc, char **argv);
int cmd_sweep(int argc, char **argv);
int cmd_analytic(int argc, char **argv);
int cmd_animate(int argc, char **argv);
int cmd_compare(int argc, char **argv);

#endif /* RAD_CLI_H */
