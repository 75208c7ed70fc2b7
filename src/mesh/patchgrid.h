/* patchgrid.h -- shooting patches: a coarse P x Q grid over each surface.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen, Chen, Wallace & Greenberg 1988, section 3.4 (after Cohen,
 * Greenberg, Immel & Brock 1986): patches shoot, elements receive.  A quad
 * surface meshed into N x M elements is cut into P x Q patches along its
 * own grid lines (P <= N, Q <= M: a larger request is cut down to the
 * mesh); patch (pi, pj) holds the elements with gi in [pi N / P,
 * (pi + 1) N / P) and gj likewise (integer division: the patches differ by
 * at most one element row).  A polygon surface (one element) is one patch.
 * Patches are numbered surface by surface in file order, row-major
 * (pj * P + pi) inside a surface.
 *
 * Areas are in the mesh's units; corners are the patch's outline, four
 * grid vertices counter-clockwise about the surface's front (as the
 * surface's own outline), or a polygon element's vertices, taken from the
 * mesh given (so a grid built on a normalized mesh has normalized corners).
 */
#ifndef RAD_PATCHGRID_H
#define RAD_PATCHGRID_H

#include "radiosity/base.h"
#include "radiosity/mesh.h"

typedef struct rad_patch_grid {
    int npatches;
    int nelements;
    int *first;         /* patch p owns member[first[p] .. first[p+1]) */
    int *member;        /* element indices, nelements of them */
    int *patch_of;      /* the patch of each element */
    int *surface;       /* the surface of each patch */
    double *area;       /* the sum of its elements' areas */
    int *cfirst;        /* corners of patch p: corner[cfirst[p] .. cfirst[p+1]) */
    rad_vec3 *corner;
} rad_patch_grid;

/* Build the grid of P x Q patches per quad surface (P, Q >= 1). */
rad_status radi_patch_grid_build(rad_patch_grid *g, const rad_mesh *m, int P, int Q,
                                rad_error *err);
void radi_patch_grid_free(rad_patch_grid *g);

#endif /* RAD_PATCHGRID_H */
