/* visibility.h -- segment and box queries against the scene's polygons,
 * answered by a CGAL AABB tree (visibility.cc, the only C++ file).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The tree holds the triangles of a fan triangulation of each polygon
 * given to radi_vis_create (the occlusion code gives it the scene's
 * surfaces; a caller may as well give it elements).  Every triangle
 * remembers the polygon it came from, its owner, so that a query can
 * ignore two polygons: the two ends of a segment lie on them and always
 * touch them.
 *
 * What is exact: each query's answer, for the double coordinates it is
 * given.  The queries use only predicates of CGAL's
 * Exact_predicates_inexact_constructions_kernel (do_intersect, collinear:
 * filtered interval arithmetic with an exact fallback), so the tree and
 * the brute-force loop radi_vis_segment_blocked_brute agree on every
 * segment, touching included (triangles and segments are closed sets).
 * The coordinates themselves are rounded doubles computed by the caller.
 *
 * What is not: the hidden surfaces of the form factors.  occshaft.c uses
 * only radi_vis_box_polygons, once per pair of surfaces at setup, as a
 * conservative pre-filter: the box is the bounding box of the two surfaces
 * clipped to the front of each other's plane (in floating point), padded
 * by 1e-9 of the scene's size, so it holds the pair's shaft, and a surface
 * it does not list cannot block the pair; one it lists may not block it.
 * Whether and how much a listed surface hides is decided in occshaft.c and
 * occhidden.c in
 * floating-point arithmetic with stated tolerances (separating planes of
 * the shaft, the fully-hidden test, the integration of the hidden part),
 * not by exact predicates.  The segment queries serve the tests
 * (tests/unit/occ/test_visibility.c).
 *
 * Thread safety: the tree is built completely in radi_vis_create; after
 * that every query is const and may run from many threads at once.  No
 * exception crosses this interface: each function catches all of them and
 * returns a status (RAD_ERR_NOMEM for std::bad_alloc, RAD_ERR_INVALID for
 * anything else, with the reason in err) or -1.
 */
#ifndef RAD_VISIBILITY_H
#define RAD_VISIBILITY_H

#include "radiosity/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The tree and its triangles; opaque. */
typedef struct rad_vis rad_vis;

/* Build the tree of npolys convex planar polygons: polygon k has the
 * vertices verts[first[k] .. first[k+1]), so first has npolys + 1
 * entries.  Degenerate triangles of a fan (colinear corners, by the exact
 * predicate) are left out: they have no area and block nothing. */
rad_status radi_vis_create(rad_vis **vis, const rad_vec3 *verts, const int *first, int npolys,
                          rad_error *err);
void radi_vis_free(rad_vis *vis);

/* The number of triangles in the tree. */
int radi_vis_triangles(const rad_vis *vis);

/* Does the closed segment pq (the point p when q = p) meet a triangle
 * whose owner is neither skip_a nor skip_b (pass -1 to skip nothing)?
 * 1 yes, 0 no, -1 on an error inside CGAL. */
int radi_vis_segment_blocked(const rad_vis *vis, rad_vec3 p, rad_vec3 q, int skip_a, int skip_b);

/* The same answer by a loop over every triangle, with the same exact
 * predicate (for tests). */
int radi_vis_segment_blocked_brute(const rad_vis *vis, rad_vec3 p, rad_vec3 q, int skip_a,
                                  int skip_b);

/* The polygons with a triangle that meets the closed box [lo, hi]: their
 * indices, distinct and ascending, go to owners (room for npolys).
 * Returns how many, or -1 on an error. */
int radi_vis_box_polygons(const rad_vis *vis, rad_vec3 lo, rad_vec3 hi, int *owners);

#ifdef __cplusplus
}
#endif

#endif /* RAD_VISIBILITY_H */
