/* cmd_formfactor.c -- `radiosity formfactor`: the table of all form factors.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include <math.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/export.h"
#include "fill/fill.h"
#include "mesh/mesh.h"

static void help(void)
{
    printf("Usage: radiosity formfactor [OPTIONS] SCENE\n"
           "Mesh the scene and print the form factor of every ordered pair of\n"
           "distinct elements as a tab-separated table with the header\n"
           "'i j F error': F is the form factor from element i to element j\n"
           "(0-based, in mesh order), error its estimated absolute error (NaN\n"
           "where the accuracy mode gives no estimate: classic, and the hemicube).\n"
           "A View3D file's factors have View3D's shape: its O surfaces have no\n"
           "rows or columns, and surfaces combined by CMB share one, the union's\n"
           "(area-weighted rows, summed columns; the table then lists i = j too).\n"
           "\n"
           "With --per-surface, the factors between whole surfaces instead:\n"
           "F_SK = (1/A_S) sum over elements i of S and j of K of A_i F_ij, one\n"
           "row per ordered pair of surfaces (S = K included), header\n"
           "'S K F error S_line K_line S_area': S and K are 0-based in file\n"
           "order, S_line and K_line the scene-file lines that define them\n"
           "(every surface, View3D's O and combined surfaces included).\n"
           "\n"
           "An output FILE whose name ends in .npy gets NumPy's binary format\n"
           "(version 1.0, float64): the whole n x n matrix, row i = from element\n"
           "i, zero diagonal (numpy.load(FILE)[i, j] = F_ij), or with\n"
           "--per-surface the surfaces' matrix.\n"
           "\n"
           "Options:\n"
           "  -o, --output FILE       write the table to FILE (default: standard output)\n"
           "      --per-surface       surface-to-surface factors instead of elements'\n"
           CLI_METHOD_HELP
           CLI_COMMON_HELP
           "\n"
           "Examples:\n"
           "  radiosity formfactor --mesh 3x3 data/grey-cube.scene -o F.tsv\n"
           "  radiosity formfactor --mesh 20x20 data/goral1984-cube.scene -o F.npy\n"
           "  radiosity formfactor --per-surface --accuracy reference \\\n"
           "      data/grey-cube.scene\n"
           "  radiosity formfactor --per-surface --form-factors-method hemicube \\\n"
           "      --resolution 256 data/grey-cube.scene\n"
           "\n"
           "Exit status: 0 on success, 1 on an error, 2 on a usage error.\n");
}

/* What the writers need, whichever of them runs. */
typedef struct table_ctx {
    const rad_scene *scene;
    const rad_mesh *mesh;
    const double *F, *E;        /* n x n: the element matrix and its errors */
    const double *FS, *ES, *AS; /* ns x ns, ns: the surfaces', or NULL */
    int n;
    int diagonal;               /* 1: the table lists F_ii too (unions) */
} table_ctx;

static int write_table(FILE *out, const void *ctx)
{
    const table_ctx *t = ctx;
    return t->diagonal ? rad_export_ff_table_diagonal(out, t->F, t->E, t->n)
                       : rad_export_ff_table(out, t->F, t->E, t->n);
}

static int write_matrix_npy(FILE *out, const void *ctx)
{
    const table_ctx *t = ctx;
    return rad_export_matrix_npy(out, t->F, t->n);
}

static int write_surfaces(FILE *out, const void *ctx)
{
    const table_ctx *t = ctx;
    return rad_export_surface_table(out, t->scene, t->mesh, t->FS, t->ES, t->AS);
}

static int write_surfaces_npy(FILE *out, const void *ctx)
{
    const table_ctx *t = ctx;
    const size_t ns = (size_t)t->mesh->nsurfaces;
    return rad_export_npy(out, t->FS, ns, ns);
}

/* The per-surface matrices into t (freed by the caller); 0, or 1 with the
 * error printed. */
static int per_surface(table_ctx *t, double **FS, double **ES, double **AS)
{
    const size_t ns = (size_t)t->mesh->nsurfaces, nn = ns > 0 ? ns * ns : 1;
    *FS = malloc(sizeof **FS * nn);
    *ES = t->E ? malloc(sizeof **ES * nn) : NULL;
    *AS = malloc(sizeof **AS * (ns > 0 ? ns : 1));
    if (!*FS || !*AS || (t->E && !*ES)) {
        cli_error("out of memory for %zu x %zu surface factors", ns, ns);
        return 1;
    }
    radi_ff_surfaces(t->mesh, t->F, t->E, *FS, *ES, *AS);
    t->FS = *FS;
    t->ES = *ES;
    t->AS = *AS;
    return 0;
}

/* View3D's shape (cli_shape_of): O surfaces block but have no rows or
 * columns, combined surfaces share one; F and E reduced in place to
 * *k x *k, *joined the surfaces combined.  0, or 1 (printed). */
static int reported(const rad_scene *scene, const rad_mesh *mesh, const cli_common *c,
                    double *F, double *E, int *k, int *joined)
{
    cli_shape sh;
    if (cli_shape_of(scene, mesh, &sh))
        return 1;
    double *area = malloc(sizeof *area * ((size_t)sh.k + 1));
    rad_error err;
    int status = 1;
    *k = sh.k;
    *joined = sh.joined;
    if (!area) {
        cli_error("out of memory for %d rows", sh.k);
        goto done;
    }
    if (sh.k < mesh->nelements &&
        rad_mesh_reduce(mesh, sh.row, sh.k, F, E, area, &err) != RAD_OK) {
        cli_error_rec(&err);
        goto done;
    }
    if (sh.obstructed && !c->quiet)
        fprintf(stderr, CLI_PROGRAM ": %d obstruction elements block but are left out of the "
                        "factors (View3D's O surfaces): %d x %d\n", sh.obstructed, sh.k, sh.k);
    if (sh.joined && !c->quiet)
        fprintf(stderr, CLI_PROGRAM ": %d surfaces combined with earlier ones (View3D's "
                        "CMB), one row and column a union: %d x %d\n", sh.joined, sh.k, sh.k);
    status = 0;
done:
    free(sh.row);
    free(area);
    return status;
}

int cmd_formfactor(int argc, char **argv)
{
    enum { OPT_PER_SURFACE = OPT_COMMON_END };
    static const struct option longopts[] = {{"output", required_argument, NULL, 'o'},
                                              {"per-surface", no_argument, NULL, OPT_PER_SURFACE},
                                              CLI_METHOD_LONGOPTS,
                                              CLI_COMMON_LONGOPTS,
                                              {NULL, 0, NULL, 0}};
    cli_common c;
    const char *output = "-";
    int opt, r, surfaces = 0;
    cli_common_init(&c);
    while ((opt = getopt_long(argc, argv, "ho:q", longopts, NULL)) != -1) {
        if (opt == OPT_HELP || opt == 'h') {
            help();
            return 0;
        }
        if (opt == 'o') {
            output = optarg;
            continue;
        }
        if (opt == OPT_PER_SURFACE) {
            surfaces = 1;
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
    if (cli_common_check(&c))
        return cli_usage_hint("formfactor");
    rad_scene scene;
    rad_mesh mesh;
    rad_error err;
    const cli_output check = {output, NULL, NULL};
    if (cli_outputs_check(&check, 1) || cli_load_scene(argv[optind], &c, &scene))
        return 1;
    /* F, and E with the error estimates: refused before meshing when the
     * scene's mesh specification makes more than the machine holds */
    const double ne = rad_scene_element_count(&scene);
    char what[96];
    snprintf(what, sizeof what, "%.0f elements (%d x 8 N^2 bytes of matrices)", ne,
             c.ff.accuracy != RAD_ACCURACY_CLASSIC ? 2 : 1);
    if (ne > INT_MAX ||
        rad_memory_check((c.ff.accuracy != RAD_ACCURACY_CLASSIC ? 16.0 : 8.0) * ne * ne, what,
                         NULL, &err) != RAD_OK) {
        if (ne > INT_MAX)
            cli_error("the scene's meshes make %.0f elements, more than %d", ne, INT_MAX);
        else
            cli_error_rec(&err);
        rad_scene_free(&scene);
        return 1;
    }
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
    double *FS = NULL, *ES = NULL, *AS = NULL;
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
    if (cli_ff_verdict(&c, &st))
        goto done;
    int kept = (int)n, joined = 0;
    if (!surfaces && reported(&scene, &mesh, &c, F, E, &kept, &joined))
        goto done;
    table_ctx t = {&scene, &mesh, F, E, NULL, NULL, NULL, kept, 0};
    t.diagonal = joined > 0;
    const int npy = rad_export_is_npy(output);
    if (surfaces && per_surface(&t, &FS, &ES, &AS))
        goto done;
    cli_writer_fn fn = surfaces ? (npy ? write_surfaces_npy : write_surfaces)
                                : (npy ? write_matrix_npy : write_table);
    if (cli_write_atomic(output, fn, &t))
        goto done;
    status = 0;
done:
    free(F);
    free(E);
    free(FS);
    free(ES);
    free(AS);
    rad_mesh_free(&mesh);
    rad_scene_free(&scene);
    return status;
}
