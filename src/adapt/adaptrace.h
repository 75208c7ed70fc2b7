/* adaptrace.h -- the race of figure 7 with adaptive subdivision (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * `radiosity progress --adaptive`: the shooting methods of the race
 * (progressive.h) run with adaptive subdivision (adaptive.h), step by
 * step, each against its own converged adaptive solution projected onto
 * the leaves of the moment.  See adaptrace.c.
 */
#ifndef RAD_ADAPTRACE_H
#define RAD_ADAPTRACE_H

#include "solve/solve.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"

/* A converged adaptive solution as the pipeline hands it back (its
 * rad_result): the conforming mesh of its leaves, their B (leaves x
 * RAD_BANDS) and levels. */
typedef struct rad_adapt_ref {
    const rad_mesh *mesh;
    const double *B;
    const int *level;
} rad_adapt_ref;

/* What one snapshot shows: the leaves after that step. */
typedef struct rad_adapt_frame {
    const rad_mesh *mesh;       /* the conforming mesh of the leaves (adaptmesh.h) */
    const double *B, *Bv;       /* displayed radiosity of the leaves, of the vertices */
    const double *Bref;         /* the converged solution projected onto the leaves */
    const int *level;           /* each leaf's level */
} rad_adapt_frame;

/* Called at the snapshot steps of rad_race_options; non-zero stops the race
 * (RAD_ERR_INVALID, "interrupted"). */
typedef int (*rad_adapt_snapshot_fn)(void *user, int method, int step, const rad_adapt_frame *f);

typedef struct rad_adapt_race {
    const rad_mesh *start;      /* the starting mesh: its elements are the patches */
    const rad_ff_options *ff;
    const rad_solve_options *solve; /* threshold, depth, tolerance, max_iterations */
    rad_adapt_ref ref[2];       /* converged from the same start and options:
                                   [0] shooting in file order (sort 0),
                                   [1] sorted (sort 1) */
    rad_adapt_snapshot_fn snapshot; /* may be NULL */
    void *snapshot_user;
} rad_adapt_race;

/* The race of radi_race_run_source for the three shooting methods, each
 * shooting step followed by subdivision.  rms, rms_bands and reached as
 * there; the gathering column (Gauss-Seidel over a fixed mesh, which
 * cannot subdivide) is NaN and reached[RAD_RACE_GATHERING] is -1.  A run
 * that converges (the solve's test) before opt->steps stays where it is:
 * its later rows repeat that step's.  opt->snapshot and opt->patches are
 * not used (patches: RAD_ERR_INVALID). */
rad_status radi_adapt_race_run(const rad_adapt_race *ar, const rad_race_options *opt,
                              double *rms, int *reached, rad_error *err);

#endif /* RAD_ADAPTRACE_H */
