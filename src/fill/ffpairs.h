/* ffpairs.h -- chosen entries of the form-factor matrix (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The animation (animate.c) keeps one dense F and, after a change,
 * recomputes only the pairs the change can alter.  For a converged frame
 * to equal a fresh solve of the changed scene, each recomputed pair must
 * be the very number the full fill (rad_ff_matrix) would give: so this
 * takes the fill's path entry for entry (ffblock.c: the
 * mesh's frame, the element polygons, the pair kernel, occlusion with
 * RAD_OCC_AUTO, F_ji = S / (2 pi A_j), then F_ij = F_ji A_j / A_i).
 */
#ifndef RAD_FFPAIRS_H
#define RAD_FFPAIRS_H

#include <stddef.h>

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"

/* For k < np: pair (pi[k], pj[k]) of elements of `mesh`, pi[k] < pj[k],
 * gets fij[k] = F_{pi pj} and fji[k] = F_{pj pi}, computed as
 * rad_ff_matrix computes them for this mesh. */
rad_status radi_ff_pairs(const rad_mesh *mesh, const rad_ff_options *opt, const int *pi,
                        const int *pj, size_t np, double *fij, double *fji, rad_error *err);

#endif /* RAD_FFPAIRS_H */
