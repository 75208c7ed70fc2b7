/* cmd_compare.c -- `radiosity compare`: another solver's form factors
 * against ours.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The order of the work is the order of the costs: the scene and the
 * output paths are checked, the other matrix is read (ffread.h) and, with
 * --elements, renumbered into our element order (elmatch.h), all before
 * the form factors are computed, so that a wrong file fails in
 * milliseconds rather than after the reference fill.  Our values are the
 * library's (rad_ff_matrix) in reference mode unless --accuracy says
 * otherwise, with their own error estimates, which tell how small a
 * difference the comparison can resolve.  The figures are ffcompare.c's;
 * the printing is compare_print.c's.
 *
 * Exit status: 0, or 1 when --tolerance is given and the largest error
 * is above it, so that another project's CI can run its solver and this
 * command; 1 on an input error ("radiosity: FILE:LINE: ..."), 2 on a
 * usage error.
 */
#include <config.h>

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/compare_print.h"
#include "compare/compare.h"
#include "io/ffread.h"

#define DEFAULT_FLOOR 1e-6
#define DEFAULT_WORST 10

static void help(void)
{
    printf("Usage: radiosity compare [OPTIONS] SCENE MATRIX\n"
           "Read another solver's element-to-element form factors for SCENE and\n"
           "report how they differ from this program's, computed in reference mode.\n"
           "MATRIX is told by its content: Matrix Market (array or coordinate, real\n"
           "general, as --form-factors writes), NumPy .npy (float64 or float32, 2-D,\n"
           "C or Fortran order; float32's rounding is named in the report), the\n"
           "table of 'radiosity formfactor' (header 'i j F'), or NIST View3D's\n"
           "view-factor file (text or binary format).  Row i is from element i:\n"
           "G_ij is the fraction of what leaves element i that arrives at element j.\n"
           "For a View3D file MATRIX may have View3D's shape (no rows for O\n"
           "surfaces, one for each union of surfaces combined by CMB, as\n"
           "'radiosity formfactor' writes it): ours is reduced to it.\n"
           "\n"
           "The error of an entry is e_ij = |G_ij - F_ij| / max(|F_ij|, FLOOR), G\n"
           "theirs, F ours: relative where F_ij >= FLOOR, the difference in units of\n"
           "FLOOR below it.  Reported: the largest and RMS e over all n^2 entries,\n"
           "the worst pairs with their geometry, the worst rows, closure (row sums)\n"
           "of both matrices, and the reciprocity A_i G_ij = A_j G_ji of theirs.\n"
           "\n"
           "Options:\n"
           "      --elements TABLE    their element order: a table with the columns\n"
           "                          element, cx, cy, cz (as solve --elements\n"
           "                          writes); elements are matched by centroid\n"
           "                          (within 1e-6 of the scene's diagonal)\n"
           "      --tolerance T       exit 1 when the largest error exceeds T\n"
           "      --floor F           the floor of the relative error (default 1e-6)\n"
           "      --worst N           list the N worst pairs and rows (default 10)\n"
           "      --report FILE       the figures as JSON\n"
           "      --plot FILE.png     a histogram of log10 of the errors\n"
           CLI_COMMON_HELP
           "The default --accuracy here is reference; -q prints no report (the exit\n"
           "status and --report still say it).\n"
           "\n"
           "Examples:\n"
           "  radiosity formfactor -q --mesh 4x4 -o F.npy data/grey-cube.scene\n"
           "  radiosity compare --mesh 4x4 --tolerance 1e-8 data/grey-cube.scene F.npy\n"
           "  radiosity compare --mesh 4x4 --plot e.png data/grey-cube.scene F.npy\n"
           "\n"
           "Exit status: 0 on success (within --tolerance), 1 when the largest error\n"
           "is above --tolerance or on an error, 2 on a usage error.\n");
}

typedef struct compare_args {
    cli_common c;
    const char *elements, *report, *plot;
    double tolerance, floor;
    int has_tolerance, worst;
} compare_args;

enum { OPT_ELEMENTS_TABLE = OPT_COMMON_END, OPT_TOL, OPT_FLOOR, OPT_WORST, OPT_REPORT_FILE,
       OPT_PLOT };

/* One option of compare's own: 0 handled, 2 usage error (printed). */
static int own_option(compare_args *a, int opt, const char *arg)
{
    switch (opt) {
    case OPT_ELEMENTS_TABLE: a->elements = arg; return 0;
    case OPT_REPORT_FILE: a->report = arg; return 0;
    case OPT_PLOT: a->plot = arg; return 0;
    case OPT_TOL:
        a->has_tolerance = 1;
        if (cli_parse_double(arg, &a->tolerance) || a->tolerance < 0) {
            cli_error("--tolerance takes a number >= 0, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_FLOOR:
        if (cli_parse_double(arg, &a->floor) || !(a->floor > 0)) {
            cli_error("--floor takes a number > 0, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_WORST:
        if (cli_parse_int(arg, 0, 100000, &a->worst)) {
            cli_error("--worst takes a whole number from 0 to 100000, not '%s'", arg);
            return 2;
        }
        return 0;
    default:
        return 1;
    }
}

/* Parse argv: 0, a usage error (2, printed), or -1 after --help. */
static int parse(compare_args *a, int argc, char **argv)
{
    static const struct option longopts[] = {
        {"elements", required_argument, NULL, OPT_ELEMENTS_TABLE},
        {"tolerance", required_argument, NULL, OPT_TOL},
        {"floor", required_argument, NULL, OPT_FLOOR},
        {"worst", required_argument, NULL, OPT_WORST},
        {"report", required_argument, NULL, OPT_REPORT_FILE},
        {"plot", required_argument, NULL, OPT_PLOT},
        CLI_COMMON_LONGOPTS,
        {NULL, 0, NULL, 0}};
    int opt;
    while ((opt = getopt_long(argc, argv, "hq", longopts, NULL)) != -1) {
        if (opt == OPT_HELP || opt == 'h') {
            help();
            return -1;
        }
        int r = own_option(a, opt, optarg);
        if (r == 1)
            r = cli_common_option(&a->c, opt, optarg);
        if (r != 0)
            return cli_usage_hint("compare");
    }
    if (optind != argc - 2) {
        cli_error(optind >= argc - 1 ? "compare needs a SCENE and a MATRIX"
                                     : "compare takes one SCENE and one MATRIX");
        return cli_usage_hint("compare");
    }
    if (strcmp(argv[optind + 1], "-") == 0) {
        cli_error("compare reads MATRIX from a file, not from standard input");
        return cli_usage_hint("compare");
    }
    return 0;
}

/* The scene's mesh, refused when its matrices (count of n x n doubles)
 * would not fit: 0, or 1 (printed). */
static int load_mesh(const compare_args *a, const char *path, rad_scene *scene,
                     rad_mesh *mesh, int count)
{
    rad_error err;
    char what[96];
    memset(mesh, 0, sizeof *mesh);
    if (cli_load_scene(path, &a->c, scene))
        return 1;
    const double ne = rad_scene_element_count(scene);
    snprintf(what, sizeof what, "%.0f elements (%d x 8 N^2 bytes of matrices)", ne, count);
    if (ne > INT_MAX)
        cli_error("the scene's meshes make %.0f elements, more than %d", ne, INT_MAX);
    else if (rad_memory_check(8.0 * count * ne * ne, what, NULL, &err) != RAD_OK ||
             rad_mesh_build(mesh, scene, &err) != RAD_OK)
        cli_error_rec(&err);
    else
        return 0;
    rad_scene_free(scene);
    return 1;
}

/* Their matrix G into our element order (perm[k] = ours of their k). */
static void renumber(const double *G, double *out, const int *perm, size_t n)
{
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < n; i++)
            out[(size_t)perm[i] + (size_t)perm[j] * n] = G[i + j * n];
}

/* Read their matrix into G (work: n x n scratch, or NULL without
 * --elements): 0, or 1 (printed). */
static int read_theirs(const compare_args *a, const char *path, const rad_mesh *mesh,
                       double *G, double *work, const char **format)
{
    rad_error err;
    const int n = mesh->nelements;
    int *perm = NULL;
    if (radi_ff_read(path, n, work ? work : G, format, &err) != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    if (!work)
        return 0;
    perm = malloc(sizeof *perm * ((size_t)n + 1));
    if (!perm) {
        cli_error("out of memory for %d elements", n);
        return 1;
    }
    if (radi_elements_match(a->elements, mesh, perm, &err) != RAD_OK) {
        cli_error_rec(&err);
        free(perm);
        return 1;
    }
    renumber(work, G, perm, (size_t)n);
    free(perm);
    return 0;
}

/* A scene that View3D reports in fewer rows (O surfaces left out,
 * combined surfaces joined): their matrix may have that shape, as
 * View3D's has.  Try it first, into S (k x k); *embedded 1 when it was
 * read so, 0 when the whole matrix was (into G).  0, or 1 (printed). */
static int read_kept(const char *path, const rad_mesh *mesh, const cli_shape *sh,
                     double *G, double *S, const char **format, int *embedded)
{
    rad_error err, whole;
    *embedded = 0;
    if (radi_ff_read(path, sh->k, S, format, &err) == RAD_OK) {
        *embedded = 1;
        return 0;
    }
    if (radi_ff_read(path, mesh->nelements, G, format, &whole) == RAD_OK)
        return 0;
    char o[64] = "", j[64] = "";
    if (sh->obstructed)
        snprintf(o, sizeof o, ", its O surfaces' %d elements left out", sh->obstructed);
    if (sh->joined)
        snprintf(j, sizeof j, ", its %d combined surfaces joined", sh->joined);
    cli_error("%s (View3D's shape for the scene: %d rows%s%s; or one per element: %d)",
              err.message, sh->k, o, j, mesh->nelements);
    return 1;
}

/* Our matrix and its error estimates: 0, or 1 (printed). */
static int ours(compare_args *a, const rad_mesh *mesh, double *F, double **E)
{
    rad_error err;
    rad_ff_stats st;
    cli_progress_attach(&a->c);
    if (a->c.ff.accuracy == RAD_ACCURACY_CLASSIC) { /* the paper's rule estimates nothing */
        free(*E);
        *E = NULL;
    }
    if (rad_ff_matrix(mesh, &a->c.ff, F, *E, &st, &err) != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    return cli_ff_verdict(&a->c, &st);
}

/* Ours reduced to View3D's shape (rad_mesh_reduce), their k x k block
 * from W into G, A the rows' areas and *view a mesh of one element a row
 * (the first of its elements, with the row's area: the report's
 * geometry).  0, or 1 (printed). */
static int reduce_ours(const rad_mesh *mesh, const cli_shape *sh, double *G,
                       const double *W, double *F, double *E, double *A, rad_mesh *view)
{
    const size_t k = (size_t)sh->k;
    rad_error err;
    rad_element *el = malloc(sizeof *el * (k + 1));
    if (!el) {
        cli_error("out of memory for %zu rows", k);
        return 1;
    }
    if (rad_mesh_reduce(mesh, sh->row, sh->k, F, E, A, &err) != RAD_OK) {
        cli_error_rec(&err);
        free(el);
        return 1;
    }
    memcpy(G, W, sizeof *G * k * k);
    for (int e = mesh->nelements - 1; e >= 0; e--)
        if (sh->row[e] >= 0)
            el[sh->row[e]] = mesh->elements[e];
    for (size_t I = 0; I < k; I++)
        el[I].area = A[I];
    view->nelements = sh->k;
    view->elements = el;
    return 0;
}

/* What the reduction left out and joined, on standard error. */
static void say_shape(const cli_shape *sh)
{
    if (sh->obstructed)
        fprintf(stderr, CLI_PROGRAM ": their matrix leaves out the %d elements of the O "
                        "surfaces, as View3D does: compared on the other %d\n",
                sh->obstructed, sh->k);
    if (sh->joined)
        fprintf(stderr, CLI_PROGRAM ": their matrix has one row and column for each union of "
                        "combined surfaces (%d joined, View3D's CMB), as View3D's has: "
                        "compared on %d rows with the unions' areas\n", sh->joined, sh->k);
}

/* After the mesh: read, compute, compare, print; the exit status. */
static int run(compare_args *a, char **paths, const rad_mesh *mesh, const cli_shape *sh,
               const cli_output *o, int no)
{
    const size_t n = (size_t)mesh->nelements, nn = n > 0 ? n * n : 1;
    double *G = malloc(sizeof *G * nn), *F = malloc(sizeof *F * nn);
    const int reduced = sh->k < (int)n;
    double *E = malloc(sizeof *E * nn);
    double *W = a->elements || reduced ? malloc(sizeof *W * nn) : NULL;
    int embedded = 0;
    double *A = malloc(sizeof *A * (n + 1));
    rad_ffcmp cmp = {.floor = a->floor, .nworst = a->worst};
    rad_mesh view = *mesh;
    compare_ctx ctx = {paths[0], paths[1], "", a->elements, mesh, &cmp, a->c.ff.accuracy,
                       a->has_tolerance, a->tolerance, a->worst, 0, 0};
    rad_error err;
    int status = 1;
    if (!G || !F || !E || !A || ((a->elements || reduced) && !W)) {
        cli_error("out of memory for %zu x %zu form factors", n, n);
        goto done;
    }
    if (reduced && a->elements) {
        cli_error("--elements: a scene with View3D O or combined surfaces keeps View3D's "
                  "order");
        status = EXIT_USAGE;
        goto done;
    }
    double t0 = cli_seconds();
    if (reduced ? read_kept(paths[1], mesh, sh, G, W, &ctx.format, &embedded)
                : read_theirs(a, paths[1], mesh, G, W, &ctx.format))
        goto done;
    double t1 = cli_seconds();
    if (ours(a, mesh, F, &E))
        goto done;
    if (embedded) {
        if (reduce_ours(mesh, sh, G, W, F, E, A, &view))
            goto done;
        ctx.mesh = &view;
        if (!a->c.quiet)
            say_shape(sh);
    } else
        for (size_t i = 0; i < n; i++)
            A[i] = mesh->elements[i].area;
    ctx.seconds_read = t1 - t0;
    ctx.seconds_ff = cli_seconds() - t1;
    if (radi_ffcmp_run(&cmp, G, F, E, A, view.nelements, &err) != RAD_OK) {
        cli_error_rec(&err);
        goto done;
    }
    cli_output out[2] = {o[0], o[1]};
    out[0].ctx = out[1].ctx = &ctx;
    if (!a->c.quiet && compare_print_text(stdout, &ctx))
        goto done;
    if (cli_outputs_write(out, no))
        goto done;
    status = compare_within(&ctx) ? 0 : 1;
done:
    radi_ffcmp_free(&cmp);
    if (view.elements != mesh->elements)
        free(view.elements);
    free(G);
    free(F);
    free(E);
    free(W);
    free(A);
    return status;
}

int cmd_compare(int argc, char **argv)
{
    compare_args a = {.floor = DEFAULT_FLOOR, .worst = DEFAULT_WORST};
    cli_common_init(&a.c);
    a.c.ff.accuracy = RAD_ACCURACY_REFERENCE;
    const int r = parse(&a, argc, argv);
    if (r != 0)
        return r < 0 ? 0 : r;
    const cli_output o[2] = {{a.report, compare_print_json, NULL},
                             {a.plot, compare_plot, NULL}};
    rad_scene scene;
    rad_mesh mesh;
    if (cli_outputs_check(o, 2) ||
        load_mesh(&a, argv[optind], &scene, &mesh, a.elements ? 4 : 3))
        return 1;
    cli_shape sh;
    const int status = cli_shape_of(&scene, &mesh, &sh) ? 1 : run(&a, argv + optind, &mesh, &sh, o, 2);
    free(sh.row);
    rad_mesh_free(&mesh);
    rad_scene_free(&scene);
    return status;
}
