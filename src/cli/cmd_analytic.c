/* cmd_analytic.c -- `radiosity analytic`: closed-form form factors.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct analytic_case {
    const char *name;
    int nargs;
    const char *args;
    const char *what;
} analytic_case;

static const analytic_case cases[] = {
    {"point-disk", 2, "R H",
     "differential area on the axis of a coaxial parallel\n"
     "                        disk of radius R at distance H:\n"
     "                        F = R^2 / (H^2 + R^2)"},
    {"disk-disk", 3, "R1 R2 H",
     "from a disk of radius R1 to a coaxial parallel disk\n"
     "                        of radius R2, H apart"},
    {"parallel-rectangles", 3, "A B C", "directly opposed A x B rectangles, C apart"},
    {"perpendicular-rectangles", 3, "L W H",
     "from the L x W rectangle to the L x H rectangle\n"
     "                        that shares its edge of length L at a right angle"},
};
#define NCASES (int)(sizeof cases / sizeof cases[0])

static void help(void)
{
    printf("Usage: radiosity analytic CASE PARAMETERS...\n"
           "Print the closed-form form factor of a configuration on one line\n"
           "(%%.17g).  Lengths are in any one unit; all must be positive.\n"
           "\nCases:\n");
    for (int k = 0; k < NCASES; k++)
        printf("  %s %s\n                        %s\n", cases[k].name, cases[k].args,
               cases[k].what);
    printf("\nOptions:\n"
           "  -h, --help              show this help and exit\n"
           "\nExamples:\n"
           "  radiosity analytic parallel-rectangles 1 1 1     (0.19982489569838...)\n"
           "  radiosity analytic perpendicular-rectangles 1 1 1 (0.20004377607540...)\n"
           "  radiosity analytic disk-disk 1 1 1e-300\n"
           "\nExit status: 0 on success, 1 on an error, 2 on a usage error.\n");
}

int cmd_analytic(int argc, char **argv)
{
    if (argc >= 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        help();
        return 0;
    }
    if (argc < 2) {
        cli_error("analytic needs a CASE");
        return cli_usage_hint("analytic");
    }
    const analytic_case *c = NULL;
    for (int k = 0; k < NCASES; k++)
        if (strcmp(argv[1], cases[k].name) == 0)
            c = &cases[k];
    if (!c) {
        cli_error("unknown analytic case '%s'", argv[1]);
        return cli_usage_hint("analytic");
    }
    if (argc - 2 != c->nargs) {
        cli_error("analytic %s takes %d parameters (%s), not %d", c->name, c->nargs,
                  c->args, argc - 2);
        return cli_usage_hint("analytic");
    }
    double x[3] = {0, 0, 0};
    for (int k = 0; k < c->nargs; k++)
        if (cli_parse_double(argv[2 + k], &x[k]) || !(x[k] > 0)) {
            cli_error("analytic %s: '%s' is not a positive finite number", c->name,
                      argv[2 + k]);
            return cli_usage_hint("analytic");
        }
    double f;
    if (c == &cases[0])
        f = rad_analytic_point_disk(x[0], x[1]);
    else if (c == &cases[1])
        f = rad_analytic_disk_disk(x[0], x[1], x[2]);
    else if (c == &cases[2])
        f = rad_analytic_parallel_rectangles(x[0], x[1], x[2]);
    else
        f = rad_analytic_perpendicular_rectangles(x[0], x[1], x[2]);
    if (!isfinite(f)) {
        cli_error("analytic %s: no finite value for these parameters", c->name);
        return 1;
    }
    /* a failed write (full disk, closed pipe) is caught when main closes
     * standard output (cli.c) */
    printf("%.17g\n", f);
    return 0;
}
