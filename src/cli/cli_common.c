/* cli_common.c -- what every command shares: messages, the parsers of
 * option values, the common options, the scene loader, progress on the
 * terminal, --version and the last check of standard output.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The dispatcher (cli.c) names every command; the commands call down into
 * this file, never up into the dispatcher.
 */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli/atomicfile.h"
#include "cli/cli.h"
#include "util/util.h"

/* The library names its parameters as a C caller knows them, in
 * backquotes (`max_iterations`, `mesh`: the option fields of radiosity.h);
 * the program speaks of its options.  Each parameter of the table becomes
 * its option; anything else, a path that happens to hold backquotes
 * included, is written as it is.  tests/source/libwords.sh checks that
 * the library names no option itself, and that this table knows every
 * parameter the library names. */
static void put_option_names(const char *s, FILE *out)
{
    static const struct {
        const char *param, *option;
    } names[] = {
        {"`patch_p` x `patch_q`", "--patches PxQ"},
        {"`keep_form_factors`", "--form-factors"},
        {"`max_iterations`", "--max-iterations"},
        {"`max_depth`", "--max-depth"},
        {"`resolution`", "--resolution"},
        {"`accuracy`", "--accuracy"},
        {"`bounces`", "--bounces"},
        {"`patches`", "--patches"},
        {"`matrix`", "--matrix"},
        {"`solver`", "--solver"},
        {"`mesh`", "--mesh"},
    };
    const size_t count = sizeof names / sizeof names[0];
    while (*s) {
        size_t k = 0;
        while (k < count && strncmp(s, names[k].param, strlen(names[k].param)) != 0)
            k++;
        if (k < count) {
            fputs(names[k].option, out);
            s += strlen(names[k].param);
        } else {
            fputc(*s++, out);
        }
    }
}

void cli_error(const char *fmt, ...)
{
    char msg[2048];
    va_list ap;
    va_start(ap, fmt);
    const int len = vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    fputs(CLI_PROGRAM ": ", stderr);
    if (len >= 0 && (size_t)len < sizeof msg) {
        put_option_names(msg, stderr);
    } else { /* longer than any message of ours: as it is */
        va_start(ap, fmt);
        vfprintf(stderr, fmt, ap);
        va_end(ap);
    }
    fputc('\n', stderr);
}

void cli_error_rec(const rad_error *err)
{
    cli_error("%s", err->message);
}

int cli_usage_hint(const char *cmd)
{
    fprintf(stderr, "Try 'radiosity %s%s--help' for more information.\n", cmd ? cmd : "",
            cmd ? " " : "");
    return EXIT_USAGE;
}

int cli_parse_int(const char *arg, long lo, long hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(arg, &end, 10);
    if (end == arg || *end || errno || v < lo || v > hi)
        return -1;
    *out = (int)v;
    return 0;
}

int cli_parse_double(const char *arg, double *out)
{
    char *end;
    double v = strtod(arg, &end);
    if (end == arg || *end || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

int cli_parse_vec3(const char *arg, rad_vec3 *out)
{
    char *end;
    const char *p = arg;
    double v[3];
    for (int k = 0; k < 3; k++) {
        v[k] = strtod(p, &end);
        if (end == p || !isfinite(v[k]) || (k < 2 ? *end != ',' : *end != '\0'))
            return -1;
        p = end + 1;
    }
    *out = (rad_vec3){v[0], v[1], v[2]};
    return 0;
}

int cli_parse_exposure_from(const char *arg, rad_exposure_from *out)
{
    if (rad_exposure_from_parse(arg, out) == 0)
        return 0;
    cli_error("--exposure-from takes reflectors or all, not '%s'", arg);
    return 2;
}

int cli_parse_mesh(const char *arg, int *n, int *m)
{
    char buf[64];
    char *x;
    if (strlen(arg) >= sizeof buf)
        return -1;
    strcpy(buf, arg);
    x = strpbrk(buf, "xX");
    if (!x)
        return -1;
    *x = '\0';
    return cli_parse_int(buf, 1, 100000, n) || cli_parse_int(x + 1, 1, 100000, m) ? -1 : 0;
}

/* Shaped like a grid "PxQ", valid or not ("4x4", "0x2", "-1x3"): digits
 * and signs on both sides of one 'x'. */
static int grid_shaped(const char *w)
{
    const char *const num = "0123456789+-";
    size_t a = strspn(w, num);
    return a > 0 && w[a] == 'x' && strspn(w + a + 1, num) > 0 &&
           w[a + 1 + strspn(w + a + 1, num)] == '\0';
}

/* getopt_long takes an optional argument only as "--patches=PxQ"; the
 * documented "--patches PxQ" is joined here when the next word is shaped
 * like a grid, so that a bad one ("0x2") gets the --patches message (a
 * scene file named like "4x4" would need "./4x4"). */
void cli_join_optional(int *argc, char **argv)
{
    for (int k = 1; k + 1 < *argc; k++) {
        if (strcmp(argv[k], "--") == 0)
            return;
        if (strcmp(argv[k], "--patches") != 0 || !grid_shaped(argv[k + 1]))
            continue;
        /* lives as long as argv, the process: never freed */
        char *joined = malloc(strlen(argv[k + 1]) + sizeof "--patches=");
        if (!joined)
            return; /* getopt then sees the grid as an operand: a usage error */
        sprintf(joined, "--patches=%s", argv[k + 1]);
        argv[k] = joined;
        for (int j = k + 1; j + 1 < *argc; j++)
            argv[j] = argv[j + 1];
        argv[--*argc] = NULL;
    }
}

void cli_common_init(cli_common *c)
{
    memset(c, 0, sizeof *c);
    rad_ff_options_init(&c->ff);
}

int cli_common_option(cli_common *c, int opt, const char *arg)
{
    switch (opt) {
    case OPT_FORMAT:
        if (strcmp(arg, "scene") == 0)
            c->format = RAD_SCENE_FORMAT_SCENE;
        else if (strcmp(arg, "obj") == 0)
            c->format = RAD_SCENE_FORMAT_OBJ;
        else if (strcmp(arg, "vs3") == 0)
            c->format = RAD_SCENE_FORMAT_VS3;
        else {
            cli_error("--format takes scene, obj or vs3, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_MESH:
        if (c->max_size > 0) {
            cli_error("give --mesh or --max-element-size, not both");
            return 2;
        }
        if (cli_parse_mesh(arg, &c->mesh_n, &c->mesh_m)) {
            cli_error("--mesh takes NxM with whole numbers from 1 to 100000, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_MAX_SIZE:
        if (c->mesh_n > 0) {
            cli_error("give --mesh or --max-element-size, not both");
            return 2;
        }
        if (cli_parse_double(arg, &c->max_size) || !(c->max_size > 0) ||
            !isfinite(c->max_size)) {
            cli_error("--max-element-size takes a positive length, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_QUADRATURE:
        c->given_accuracy = 1;
        if (cli_parse_int(arg, 1, RAD_GAUSS_MAX, &c->ff.quadrature)) {
            cli_error("--quadrature takes a whole number from 1 to %d, not '%s'",
                      RAD_GAUSS_MAX, arg);
            return 2;
        }
        return 0;
    case OPT_ACCURACY:
        c->given_accuracy = 1;
        if (strcmp(arg, "classic") == 0)
            c->ff.accuracy = RAD_ACCURACY_CLASSIC;
        else if (strcmp(arg, "default") == 0)
            c->ff.accuracy = RAD_ACCURACY_DEFAULT;
        else if (strcmp(arg, "reference") == 0)
            c->ff.accuracy = RAD_ACCURACY_REFERENCE;
        else {
            cli_error("--accuracy takes classic, default or reference, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_THREADS:
        if (cli_parse_int(arg, 1, 4096, &c->ff.threads)) {
            cli_error("--threads takes a positive whole number, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_FF_METHOD:
        for (int m = RAD_FF_CONTOUR; m <= RAD_FF_HEMICUBE; m++)
            if (strcmp(arg, rad_ff_method_name(m)) == 0) {
                c->ff.method = (rad_ff_method)m;
                return 0;
            }
        cli_error("--form-factors-method takes contour or hemicube, not '%s'", arg);
        return 2;
    case OPT_RESOLUTION:
        c->given_resolution = 1;
        if (cli_parse_int(arg, 2, RAD_HEMICUBE_MAX, &c->ff.resolution) ||
            c->ff.resolution % 2 != 0) {
            cli_error("--resolution takes an even whole number from 2 to %d, not '%s'",
                      RAD_HEMICUBE_MAX, arg);
            return 2;
        }
        return 0;
    case 'q':
    case OPT_QUIET:
        c->quiet = 1;
        return 0;
    case OPT_STRICT:
        c->strict = 1;
        return 0;
    default:
        return 1;
    }
}

int cli_common_check(const cli_common *c)
{
    if (c->given_resolution && c->ff.method != RAD_FF_HEMICUBE) {
        cli_error("--resolution is the hemicube's: give it with --form-factors-method "
                  "hemicube");
        return 2;
    }
    if (c->given_accuracy && c->ff.method == RAD_FF_HEMICUBE) {
        cli_error("--accuracy and --quadrature are the contour integral's: the hemicube's "
                  "accuracy is its --resolution");
        return 2;
    }
    if (c->strict && c->ff.method == RAD_FF_HEMICUBE) {
        cli_error("--strict enforces the contour integral's accuracy promise; the hemicube "
                  "makes none (its error falls with --resolution)");
        return 2;
    }
    return 0;
}

int cli_ff_verdict(const cli_common *c, const rad_ff_stats *st)
{
    static const char *const names[] = {"classic", "default", "reference"};
    const char *mode = names[c->ff.accuracy];
    const char *hint = c->ff.accuracy == RAD_ACCURACY_CLASSIC
                           ? ": the classic rule fails for this geometry; try --accuracy default"
                           : "";
    if (st->negative || st->above_one)
        cli_error("warning: %ld form factors below 0 and %ld above 1 (min %.3g, max %.3g)%s",
                  st->negative, st->above_one, st->min_value, st->max_value, hint);
    if (st->rows_above_one)
        cli_error("warning: %ld rows of F sum to more than 1 + %g (energy from nowhere)%s",
                  st->rows_above_one, RAD_ROW_SUM_SLACK, hint);
    if (st->clamped_to_one > 0 && !c->quiet)
        cli_error("note: %.0f form factors came out above 1 by less than their error bound "
                  "and were set just below 1", st->clamped_to_one);
    if (st->promise_unmet == 0)
        return 0;
    cli_error("%s%ld form factors miss the %s mode's promise of %g relative error (their own "
              "estimates say so)%s",
              c->strict ? "" : "warning: ", st->promise_unmet, mode, st->promise,
              c->strict ? "; --strict makes that an error"
                        : c->ff.accuracy == RAD_ACCURACY_DEFAULT
                            ? "; try --accuracy reference (it cannot lift a twisted polygon's "
                              "doubt: radiosity(1), ACCURACY MODES)"
                            : "");
    return c->strict;
}

/* One line per kind of repair the reader made (OBJ). */
static void say_repairs(const rad_scene *scene)
{
    char line[RAD_ERRMSG_MAX];
    for (int k = 0; k < RAD_SCENE_REPAIR_KINDS; k++)
        if (rad_scene_repair_text(scene, k, line, sizeof line))
            cli_error("%s", line);
}

int cli_load_scene(const char *path, const cli_common *c, rad_scene *scene)
{
    rad_error err;
    if (rad_scene_load_format(scene, path, c->format, c->strict ? RAD_SCENE_STRICT : 0, &err) !=
        RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    say_repairs(scene);
    if (c->mesh_n > 0)
        rad_scene_set_mesh(scene, c->mesh_n, c->mesh_m);
    /* an option that changes nothing is said, not ignored */
    if (c->max_size > 0 && rad_scene_set_max_element_size(scene, c->max_size) == 0 &&
        scene->nsurfaces > 0)
        cli_error("warning: --max-element-size %g makes no surface of %s finer: every "
                  "element is already that small", c->max_size, path);
    return 0;
}

/* ---- progress bar ------------------------------------------------------- */

typedef struct progress_state {
    struct timespec start;
    char stage[64];
    double last;
} progress_state;

double cli_seconds(void)
{
    return radi_seconds();
}

int cli_shape_of(const rad_scene *scene, const rad_mesh *mesh, cli_shape *sh)
{
    const int n = mesh->nelements;
    memset(sh, 0, sizeof *sh);
    sh->row = malloc(sizeof *sh->row * ((size_t)n + 1));
    if (!sh->row) {
        cli_error("out of memory for %d elements", n);
        return 1;
    }
    sh->k = rad_mesh_reported(scene, mesh, sh->row);
    for (int e = 0; e < n; e++)
        sh->obstructed += sh->row[e] < 0;
    for (int s = 0; s < scene->nsurfaces; s++)
        sh->joined += scene->surfaces[s].combine >= 0;
    return 0;
}

int cli_progress(void *user, const char *stage, double done, double total)
{
    progress_state *p = user;
    double t = cli_seconds();
    if (strncmp(p->stage, stage, sizeof p->stage - 1) != 0) {
        snprintf(p->stage, sizeof p->stage, "%s", stage);
        p->start.tv_sec = (time_t)t;
        p->start.tv_nsec = (long)((t - (double)(time_t)t) * 1e9);
        p->last = 0;
    }
    double t0 = (double)p->start.tv_sec + 1e-9 * (double)p->start.tv_nsec;
    if (t - p->last < 0.2 && done < total)
        return 0;
    p->last = t;
    double frac = total > 0 ? done / total : 1;
    int width = 30, fill = (int)(frac * width + 0.5);
    double left = frac > 0 ? (t - t0) * (1 - frac) / frac : 0;
    fprintf(stderr, "\r%-14.14s [", stage);
    for (int k = 0; k < width; k++)
        fputc(k < fill ? '#' : '.', stderr);
    fprintf(stderr, "] %3.0f%%  %6.1f s left ", 100 * frac, left);
    if (done >= total)
        fputc('\n', stderr);
    fflush(stderr);
    return 0;
}

void cli_progress_attach(cli_common *c)
{
    static progress_state state; /* one per process: the CLI is single-run */
    if (c->quiet || !isatty(STDERR_FILENO))
        return;
    memset(&state, 0, sizeof state);
    c->ff.progress = cli_progress;
    c->ff.progress_user = &state;
}

/* Standard output must reach its file: a full disk or a closed pipe after
 * a value was printed is an error, not a success (GNU coding standards on
 * --help and --version; gnulib's close_stdout).  Closes stdout and returns
 * rc, or 1 with the reason when rc was 0 and a write failed.  With rc != 0
 * the command has reported its error already (a failed "-" output is
 * reported by atomicfile.c), and one message is enough.  The reason is
 * the errno of the failing close (which flushes what is left, so a
 * stream that failed earlier fails again there with the same cause). */
int cli_finish_stdout(int rc)
{
    const int earlier = ferror(stdout);
    int closed, e;
    errno = 0;
    closed = fclose(stdout) == 0;
    e = errno;
    if (rc == 0 && (!closed || earlier)) {
        cli_error("write error on standard output: %s",
                  e ? strerror(e) : "a write failed before the end");
        return 1;
    }
    return rc;
}

void cli_version(const char *program)
{
    printf("%s %s\n"
           "Copyright (C) 2026 The radiosity authors.\n"
           "License GPLv3+: GNU GPL version 3 or later <https://gnu.org/licenses/gpl.html>.\n"
           "This is free software: you are free to change and redistribute it.\n"
           "There is NO WARRANTY, to the extent permitted by law.\n",
           program, PACKAGE_VERSION);
}
