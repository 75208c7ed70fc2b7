/* cmd_formfactor.c -- `radiosity formfactor`: the table of all form factors.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "export.h"
#include "mesh.h"

static void help(void)
{
    printf("Usage: radiosity formfactor [OPTIONS] SCENE\n"
           "Mesh the scene and print the form factor of every ordered pair of\n"
           "distinct elements as a tab-separated table with the header\n"
           "'i j F error': F is the form factor from element i to element j\n"
           "(0-based, in mesh order), error its estimated absolute error (NaN\n"
           "where the accuracy mode gives no estimate: classic).\n"
           "\n"
           "Options:\n"
           "  -o, --output FILE       write the table to FILE (default: standard output)\n"
           CLI_COMMON_HELP
           "\n"
           "Exit status: 0 on success, 1 on an error, 2 on a usage error.\n");
}

typedef struct table_ctx {
    const double *F, *E;
    int n;
} table_ctx;

static int write_table(FILE *out, const void *ctx)
{
    const table_ctx *t = ctx;
    return rad_export_ff_table(out, t->F, t->E, t->n);
}

int cmd_formfactor(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"output", required_argument, NULL, 'o'}, CLI_COMMON_LONGOPTS, {NULL, 0, NULL, 0}};
    cli_common c;
    const char *output = "-";
    int opt, r;
    cli_common_init(&c);
    while ((opt = getopt_long(argc, argv, "o:q", longopts, NULL)) != -1) {
        if (opt == OPT_HELP) {
            help();
            return 0;
        }
        if (opt == 'o') {
            output = optarg;
            continue;
        }
        r = cli_common_option(&c, opt, optarg);
        if (r == 2 || (r == 1 && (opt == '?' || opt == ':')))
            return cli_usage_hint("formfactor");
        if (r == 1)
            return cli_usage_hint("formfactor");
    }
    if (optind != argc - 1) {
        cli_error(optind >= argc ? "formfactor needs a SCENE" : "formfactor takes one SCENE");
        return cli_usage_hint("formfactor");
    }
    rad_scene scene;
    rad_mesh mesh;
    rad_error err;
    if (cli_load_scene(argv[optind], &c, &scene))
        return 1;
    if (rad_mesh_build(&mesh, &scene, &err) != RAD_OK) {
        rad_scene_free(&scene);
        cli_error_rec(&err);
        return 1;
    }
    const size_t n = (size_t)mesh.nelements;
    int want_err = c.ff.accuracy != RAD_ACCURACY_CLASSIC;
    const size_t nn = n > 0 ? n * n : 1;
    double *F = malloc(sizeof *F * nn);
    double *E = want_err ? malloc(sizeof *E * nn) : NULL;
    int status = 1;
    rad_ff_stats st;
    if (!F || (want_err && !E)) {
        cli_error("out of memory for %zu x %zu form factors", n, n);
        goto done;
    }
    cli_progress_attach(&c);
    if (rad_ff_matrix(&mesh, &c.ff, F, E, &st, &err) != RAD_OK) {
        cli_error_rec(&err);
        goto done;
    }
    if (st.negative || st.above_one)
        cli_error("warning: %ld form factors below 0 and %ld above 1 (min %.3g, max %.3g): "
                  "the %s rule is unreliable for this geometry; try --accuracy default",
                  st.negative, st.above_one, st.min_value, st.max_value,
                  c.ff.accuracy == RAD_ACCURACY_CLASSIC ? "classic" : "chosen");
    table_ctx t = {F, E, (int)n};
    if (cli_write_atomic(output, write_table, &t))
        goto done;
    status = 0;
done:
    free(F);
    free(E);
    rad_mesh_free(&mesh);
    rad_scene_free(&scene);
    return status;
}
