/* solvefree.h -- progressive refinement without a stored matrix (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The pipeline's `--matrix none`: see solvefree.c for the design.
 */
#ifndef RAD_SOLVEFREE_H
#define RAD_SOLVEFREE_H

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"

/* Progressive refinement (opt->solver must be RAD_SOLVER_PROGRESSIVE)
 * with each shooter's form factors computed when it shoots, by the kernel
 * options ff and the visibility the scene needs.  B is n x RAD_BANDS; rep
 * and ffst (may be NULL) as rad_solve and rad_ff_matrix fill them, over
 * the rows computed (see solvefree.c for what is NaN). */
rad_status radi_solve_matrix_free(const rad_mesh *m, const rad_ff_options *ff,
                                 const rad_solve_options *opt, double *B,
                                 rad_solve_report *rep, rad_ff_stats *ffst, rad_error *err);

/* The report of a shooting run without a matrix before its first shot:
 * what it does not measure NaN (solvefree.c and adaptive.c). */
void radi_report_init_shooting(rad_solve_report *rep);

/* An upper estimate of the bytes a matrix-free run of n elements with
 * nvertices vertices and npatches patches holds at its peak, besides the
 * visibility structure's (which grows with the surfaces, not the
 * elements): 64 MiB of slack for it and the program. */
double radi_matrix_free_bytes(double n, double nvertices, double npatches);

#endif /* RAD_SOLVEFREE_H */
