/* progressive.h -- the convergence race of progressive refinement (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * rad_solve_progressive (radiosity.h) is the solver.  This header adds what
 * `radiosity progress` needs to redraw figure 7 of Cohen, Chen, Wallace &
 * Greenberg, "A Progressive Refinement Approach to Fast Radiosity Image
 * Generation", SIGGRAPH 1988: the area-weighted RMS error (their eq. 14) of
 * four methods step by step, and its plot.  Arrays follow the library's
 * column-major convention.
 */
#ifndef RAD_PROGRESSIVE_H
#define RAD_PROGRESSIVE_H

#include "fill/fill.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"

/* Where a shot's form factors come from: the dense matrix F (column i is
 * F_ji for every j), or, when F is NULL, rad_ffrow computing each column
 * (and each patch's F_jP) when it shoots and forgetting it. */
typedef struct rad_shoot_source {
    const double *F;
    rad_ffrow *row;
} rad_shoot_source;

/* rad_solve_progressive on either source (rho, E, B as there); a trace's
 * reference is opt->reference alone (none: the rows' RMS error is NaN). */
rad_status radi_progressive_run(const rad_mesh *m, const rad_shoot_source *src,
                               const double *rho, const double *E,
                               const rad_solve_options *opt, double *B,
                               rad_solve_report *report, rad_error *err);

/* The four methods of the race, in the order of the table's columns. */
typedef enum rad_race_method {
    RAD_RACE_GATHERING = 0,     /* Gauss-Seidel, one element row per step */
    RAD_RACE_SHOOTING,          /* shooting in file order, cycling */
    RAD_RACE_SORTED,            /* shooting the largest unshot power first */
    RAD_RACE_SORTED_AMBIENT,    /* the same, displayed with the ambient term */
    RAD_RACE_METHODS
} rad_race_method;

/* Column name of a method: "gathering", "shooting", "sorted", "sorted_ambient". */
const char *radi_race_name(int method);

/* Called with the displayed radiosity (n x RAD_BANDS) of `method` after
 * `step` steps; return non-zero to stop the race (RAD_ERR_INVALID, with the
 * message "interrupted"). */
typedef int (*rad_race_snapshot_fn)(void *user, int method, int step, const double *B);

typedef struct rad_race_options {
    int steps;                  /* steps per method, >= 1 */
    int patches;                /* the shooters shoot as patches (surfaces) */
    double reach;               /* reached[]: max |B - Bref| <= reach * max |Bref| */
    int snapshot_every;         /* call snapshot every K steps (and at 0); 0: never */
    const int *snapshot_at;     /* ... and at these steps (ascending), or NULL */
    int nsnapshot_at;
    rad_race_snapshot_fn snapshot;
    void *snapshot_user;
    rad_progress_fn progress;   /* may be NULL */
    void *progress_user;
    double *rms_bands;          /* NULL, or laid out as rms: the per-band RMS
                                   errors averaged over the bands (rmserror.h) */
} rad_race_options;

void radi_race_options_init(rad_race_options *opt);
/* Is step k one of opt's snapshot steps (every snapshot_every, or listed
 * in snapshot_at)?  Whether there is a snapshot callback is not asked. */
int radi_race_snapshot_due(const rad_race_options *opt, int k);

/* Run the four methods for opt->steps steps each from B = E against the
 * converged solution Bref (n x RAD_BANDS).  rms is (steps + 1) x
 * RAD_RACE_METHODS, column-major: rms[k + m*(steps + 1)] is the RMS error of
 * method m after k steps (eq. 14: of the band-averaged radiosity) (row 0: B = E).  reached[m] is the first step
 * within opt->reach of Bref, or -1 if none within the steps. */
rad_status radi_race_run(const rad_mesh *mesh, const double *F, const double *Bref,
                        const rad_race_options *opt, double *rms, int *reached,
                        rad_error *err);

/* The same race on either source of form factors: without a matrix the
 * gathering row F_i. and each shooter's column are computed when needed
 * (ffrow.h), the same values as the matrix's. */
rad_status radi_race_run_source(const rad_mesh *mesh, const rad_shoot_source *src,
                               const double *Bref, const rad_race_options *opt, double *rms,
                               int *reached, rad_error *err);

/* One method at a time, one step at a time, for a live view (the race's
 * methods, and Jacobi sweeps for contrast): from B = E on the dense F, each
 * radi_stepper_step is one shot (shooting, sorted, sorted_ambient), one
 * element row gathered (gathering: Gauss-Seidel) or one sweep of every row
 * from the last sweep's B (jacobi).  radi_stepper_shown is the radiosity
 * the method displays (n x RAD_BANDS: with the ambient term for
 * sorted_ambient, eq. 13), radi_stepper_last the element that shot or was
 * gathered last (-1: none, or a sweep), radi_stepper_unshot the unshot
 * power over the emitted power (NaN for the gathering methods).  F must
 * outlive the stepper. */
#define RAD_STEP_JACOBI RAD_RACE_METHODS
#define RAD_STEP_METHODS (RAD_RACE_METHODS + 1)
typedef struct radi_stepper radi_stepper;
rad_status radi_stepper_new(radi_stepper **s, const rad_mesh *mesh, const double *F, int method,
                            rad_error *err);
rad_status radi_stepper_step(radi_stepper *s, rad_error *err);
const double *radi_stepper_shown(const radi_stepper *s);
int radi_stepper_last(const radi_stepper *s);
long radi_stepper_steps(const radi_stepper *s);
double radi_stepper_unshot(const radi_stepper *s);
void radi_stepper_free(radi_stepper *s);

#endif /* RAD_PROGRESSIVE_H */
