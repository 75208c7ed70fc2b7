/* cli.c -- the program: subcommand dispatch.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The one file that names every command (cmd_*.c); what they share is in
 * cli_common.c, below all of them.
 */
#include <config.h>

#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "util/util.h"

/* ---- dispatch ----------------------------------------------------------- */

static void usage(FILE *out)
{
    fprintf(out,
            "Usage: radiosity COMMAND [OPTIONS] ...\n"
            "Diffuse global illumination by full-matrix radiosity (Goral, Torrance,\n"
            "Greenberg & Battaile 1984): form factors by the contour integral, the\n"
            "radiosity system solved per colour band.\n"
            "\n"
            "Commands:\n"
            "  solve SCENE             mesh, form factors, solve; write results\n"
            "  render SCENE|SOLUTION -o IMAGE.png\n"
            "                          solve (or read a solution) and draw it\n"
            "  formfactor SCENE        form factors of all element pairs (TSV)\n"
            "  progress SCENE          the convergence race of Cohen et al. 1988\n"
            "  sweep SCENE             time against error over meshes, modes, solvers\n"
            "  animate SCENE CHANGES   redistribution through frames (George et al. 1990)\n"
            "  analytic CASE ARGS...   closed-form form factors\n"
            "  compare SCENE MATRIX    another solver's form factors against ours\n"
            "  view SCENE              watch progressive refinement in a browser\n"
            "\n"
            "Options:\n"
            "  -h, --help              show this help and exit\n"
            "  -V, --version           show the version and exit\n"
            "\n"
            "'radiosity COMMAND --help' describes each command.  The scene file\n"
            "format is described in radiosity-scene(5).\n"
            "\n" CLI_BUG_HELP);
}

/* Run subcommand fn with argv[0] = "radiosity CMD": getopt prefixes its
 * own messages ("unrecognized option") with argv[0], so they name the
 * program and the command as every other message does. */
static int run_command(int (*fn)(int, char **), int argc, char **argv)
{
    char name[64];
    snprintf(name, sizeof name, "radiosity %s", argv[0]);
    argv[0] = name;
    return fn(argc, argv);
}

static int dispatch(int argc, char **argv)
{
    static const struct {
        const char *name;
        int (*fn)(int, char **);
    } commands[] = {
        {"formfactor", cmd_formfactor}, {"analytic", cmd_analytic},
        {"solve", cmd_solve},           {"render", cmd_render},
        {"progress", cmd_progress},     {"sweep", cmd_sweep},
        {"animate", cmd_animate},
        {"compare", cmd_compare},       {"view", cmd_view},
    };
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
        usage(stdout);
        return 0;
    }
    if (strcmp(cmd, "--version") == 0 || strcmp(cmd, "-V") == 0) {
        cli_version("radiosity");
        return 0;
    }
    /* each subcommand sees argv[0] = "radiosity NAME" */
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; k++)
        if (strcmp(cmd, commands[k].name) == 0)
            return run_command(commands[k].fn, argc - 1, argv + 1);
    cli_error("unknown command '%s'", cmd);
    return cli_usage_hint(NULL);
}

int cli_main(int argc, char **argv)
{
    radi_blas_park_threads(); /* see blasthreads.c */
    cli_signals_install();   /* outputs are never left half-written */
    if (argc < 2) {
        usage(stderr);
        return EXIT_USAGE;
    }
    return cli_finish_stdout(dispatch(argc, argv));
}
