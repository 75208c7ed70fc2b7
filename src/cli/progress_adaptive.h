/* progress_adaptive.h -- `radiosity progress --adaptive` (command side).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The options, their checks, the converged solutions the race measures
 * against and the race itself (adaptrace.h), for cmd_progress.c.
 */
#ifndef RAD_PROGRESS_ADAPTIVE_H
#define RAD_PROGRESS_ADAPTIVE_H

#include "cli/cli.h"
#include "cli/progress_snap.h"
#include "solve/solve.h"

typedef struct progress_adaptive {
    rad_solve_options solve;    /* adaptive, subdivide_threshold, max_depth:
                                   solve's defaults (rad_solve_options_init) */
    int given_option;           /* --subdivide-threshold, --max-depth or
                                   --subdivide-test */
} progress_adaptive;

/* What the adaptive race runs on: the starting mesh (of the scene's
 * present part) and the run in file order converged; the sorted one
 * converged is the command's result (its mesh the one it reports). */
typedef struct progress_adaptive_run {
    rad_scene present;          /* a copy without absent objects, or empty */
    rad_mesh start;
    rad_result file_order;
} progress_adaptive_run;

/* progress --help's part (a printf format: no bare percent signs). */
#define PROGRESS_ADAPTIVE_HELP                                                     \
    "      --adaptive          the shooting methods with adaptive subdivision, as\n"\
    "                          'solve --solver progressive --adaptive' (Cohen et\n"\
    "                          al. 1988 sec. 4): the mesh's elements shoot as\n"  \
    "                          fixed patches, elements split after each shot;\n" \
    "                          gathering (Gauss-Seidel: a fixed mesh, no shot to\n"\
    "                          split after) is left out of the table, the plot\n"\
    "                          and the snapshots.  Each method runs to\n"        \
    "                          convergence first (sorted: the solve's result;\n" \
    "                          file order: its own, as the order decides the\n"  \
    "                          mesh); the error of step k (the table, the error\n"\
    "                          pictures, --reach) is against that, projected\n" \
    "                          onto the elements of step k: the area mean of\n" \
    "                          the converged elements inside each (the value of\n"\
    "                          the one around it where the step is finer); 0 at\n"\
    "                          convergence, after which the rows repeat it.\n"  \
    "                          --steps defaults to the longer run's steps to\n" \
    "                          convergence (at most 10000); snapshots show the\n"\
    "                          mesh of their step and their tables end with the\n"\
    "                          column level; form factors on the fly (--matrix\n"\
    "                          none; dense, --patches and the hemicube are usage\n"\
    "                          errors)\n"                                          \
    "      --subdivide-threshold T  --adaptive: split an element where |B -\n"    \
    "                          B_neighbour| > T times the largest reflected\n"  \
    "                          radiosity (B - E), in some band (default 0.1)\n" \
    "      --max-depth D       --adaptive: at most D splits below a starting\n"\
    "                          element, 0 to 8 (default 3); refused when\n"   \
    "                          every level's elements together could pass\n"  \
    "                          4,000,000\n"                                   \
    "      --subdivide-test difference|error  --adaptive: T bounds the\n"     \
    "                          difference (default) or the difference times\n"\
    "                          the element's side over the largest patch's\n"

void progress_adaptive_init(progress_adaptive *o);
/* 0 handled, 1 not ours, 2 usage error (printed). */
int progress_adaptive_option(progress_adaptive *o, int opt, const char *arg);
/* The combinations solve refuses: 0, or 2 (printed). */
int progress_adaptive_check(const progress_adaptive *o, const cli_common *c, int patches,
                            rad_matrix_mode matrix);

/* Both shooting orders run to convergence through the pipeline (sorted into
 * *sorted: `solve --solver progressive --adaptive` exactly) and the
 * starting mesh.  0, or 1 (printed). */
int progress_adaptive_prepare(const progress_adaptive *o, cli_common *c, const rad_scene *scene,
                              rad_result *sorted, progress_adaptive_run *run);
/* --steps by default: the longer of the two runs to convergence. */
int progress_adaptive_steps(const progress_adaptive_run *run, const rad_result *sorted);
/* The race (rms, reached as radi_race_run_source's); snap NULL: no
 * snapshots.  0, or 1 (printed). */
int progress_adaptive_race(const progress_adaptive *o, const cli_common *c,
                           const progress_adaptive_run *run, const rad_result *sorted,
                           rad_race_options *race, progress_snap *snap, double *rms,
                           int *reached);
/* The summary's lines of its own (standard error). */
void progress_adaptive_summary(const progress_adaptive_run *run, const rad_result *sorted);
void progress_adaptive_run_free(progress_adaptive_run *run);

#endif /* RAD_PROGRESS_ADAPTIVE_H */
