/* cli_adaptive.c -- the options of adaptive subdivision, for solve (and
 * render, sweep) and progress alike.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * --adaptive, --subdivide-threshold T, --subdivide-test and --max-depth D
 * (Cohen et al. 1988, section 4; adaptive.c) are parsed here once, so
 * that every command
 * that takes them has the same defaults (rad_solve_options_init: T = 0.1,
 * D = 3) and refuses the same values with the same words.
 */
#include <config.h>

#include <math.h>
#include <string.h>

#include "cli/cli.h"

int cli_adaptive_option(rad_solve_options *so, int *given_option, int opt, const char *arg)
{
    switch (opt) {
    case OPT_ADAPTIVE:
        so->adaptive = 1;
        return 0;
    case OPT_SUBDIVIDE_THRESHOLD:
        *given_option = 1;
        if (cli_parse_double(arg, &so->subdivide_threshold) || !(so->subdivide_threshold >= 0) ||
            !isfinite(so->subdivide_threshold)) {
            cli_error("--subdivide-threshold takes a number >= 0, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_MAX_DEPTH:
        *given_option = 1;
        if (cli_parse_int(arg, 0, 8, &so->max_depth)) {
            cli_error("--max-depth takes a whole number from 0 to 8, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_SUBDIVIDE_TEST:
        *given_option = 1;
        if (strcmp(arg, "difference") == 0 || strcmp(arg, "error") == 0) {
            so->subdivide_by_error = arg[0] == 'e';
            return 0;
        }
        cli_error("--subdivide-test takes difference or error, not '%s'", arg);
        return 2;
    default:
        return 1;
    }
}
