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
    "      --help              show this help and exit\n"

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

/* Load the scene and apply --mesh; prints the error and returns 1 on
 * failure. */
int cli_load_scene(const char *path, const cli_common *c, rad_scene *scene);

/* A progress bar with time left on standard error when it is a terminal. */
int cli_progress(void *user, const char *stage, double done, double total);
void cli_progress_attach(cli_common *c);

int cmd_formfactor(int argc, char **argv);
int cmd_analytic(int argc, char **argv);

#endif /* RAD_CLI_H */
