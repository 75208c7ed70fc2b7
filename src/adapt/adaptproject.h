/* adaptproject.h -- a converged adaptive solution seen on any set of leaves.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * `progress --adaptive` compares the leaves of step k with the converged
 * solution, whose leaves are others.  Both are nodes of the same quadtree
 * (adaptnodes.h), so every node gets one value of the converged solution
 * (see adaptproject.c), and the leaves of any step read theirs.
 */
#ifndef RAD_ADAPTPROJECT_H
#define RAD_ADAPTPROJECT_H

#include "adapt/adaptnodes.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"

/* Rn (nodes x RAD_BANDS, column-major) from a converged solution given as
 * its leaf mesh (adaptmesh.h: surface, level and the level grid's gi, gj
 * of each leaf), B (leaves x RAD_BANDS) and levels: a final leaf's node
 * has its B, a node above final leaves their area mean, a node below one
 * its value.  RAD_ERR_INVALID when the leaves are not a partition of a's
 * patches (another starting mesh or depth). */
rad_status radi_adapt_project(const rad_adapt_nodes *a, const rad_mesh *mesh, const double *B,
                             const int *level, double *Rn, rad_error *err);

#endif /* RAD_ADAPTPROJECT_H */
