/* adaptmesh.h -- the adaptive mesh as the outputs see it: conforming leaves.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * After an adaptive solve (adaptive.h) the leaves of the quadtrees
 * (adaptnodes.h) are the elements.  A leaf beside smaller ones has their
 * corners on its edges (T-junctions, "hanging" vertices).  Written as
 * plain quads such a mesh would crack: the renderer would draw the long
 * edge and the short ones from different endpoints, and Gouraud shading
 * would be linear along the long edge but not match the small elements'
 * corner values.  So each leaf's polygon lists every vertex on its
 * boundary (collinear points are allowed by the polygon check: no turn
 * backwards), making every edge shared whole by the two faces beside it,
 * and the vertex radiosity is made to agree:
 *
 *   - a vertex on no leaf's edge interior takes the mean of the leaves that
 *     have it as a corner (the interior rule of Goral et al. 1984,
 *     section 3, for four equal elements; on a surface's boundary the mean
 *     of its one or two elements, not the paper's extrapolation, which
 *     needs a uniform row behind it);
 *   - a hanging vertex at fraction t along the edge from corner P to
 *     corner Q of the larger leaf takes (1 - t) B_P + t B_Q, the value
 *     Gouraud shading of the larger leaf has there (Baum, Mann, Smith &
 *     Winget, "Making radiosity usable: automatic preprocessing and
 *     meshing techniques for the generation of accurate radiosity
 *     solutions", SIGGRAPH 1991, section 3.2: T-vertices take the value
 *     interpolated along the edge).  Larger leaves are done first, so P
 *     and Q are final when used (an endpoint may itself hang on a still
 *     larger leaf).
 *
 * Vertices are the lattice points that are some leaf's corner, renumbered
 * surface by surface; elements are the leaves in node order (surface,
 * level, row, column), each with its node's gi, gj (its position on its
 * own level's grid), area, centroid and material.
 */
#ifndef RAD_ADAPTMESH_H
#define RAD_ADAPTMESH_H

#include "adapt/adaptnodes.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"

/* The conforming mesh of the leaves (leaf[node] != 0) and its radiosity:
 * *B (leaves x RAD_BANDS) from Bn (nodes x RAD_BANDS, column-major), *Bv
 * (vertices x RAD_BANDS) by the rules above, *level the leaves' levels.
 * The caller frees *B, *Bv, *level and the mesh (rad_mesh_free). */
rad_status radi_adapt_leaf_mesh(const rad_adapt_nodes *a, const unsigned char *leaf,
                               const double *Bn, rad_mesh *out, double **B, double **Bv,
                               int **level, rad_error *err);

#endif /* RAD_ADAPTMESH_H */
