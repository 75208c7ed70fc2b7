/* mesh.h -- mesh internals shared with the solver and the tests.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_MESH_H
#define RAD_MESH_H

#include <stddef.h>

#include <stddef.h>
#include <stdint.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "mesh/patchgrid.h"

/* How many elements, vertices and vertex indices the scene's mesh has,
 * without building it (for the memory check).  RAD_ERR_TOOBIG when one of
 * the counts exceeds RADI_MESH_COUNT_MAX, a quarter of INT32_MAX, so that
 * every count and index of the mesh fits in an int with room to spare. */
#define RADI_MESH_COUNT_MAX (INT32_MAX / 4)
rad_status radi_mesh_count(const rad_scene *scene, size_t *nelem, size_t *nvert,
                          size_t *nindex);

/* A frame that makes geometry scale-free: p -> (p - shift) 2^-exponent
 * maps a bounding box into [-1, 1]^3 exactly (the shift is 0, or an end of
 * the box that lies within a factor 2 of all of it, so the subtraction is
 * exact by Sterbenz's lemma; the scaling is by a power of two), barring
 * subnormal results. */
typedef struct rad_frame {
    rad_vec3 shift;
    int exponent;
} rad_frame;

/* The frame of the box [lo, hi]; -1 (and the identity) when the box is a
 * point or not finite. */
int radi_frame_fit(rad_frame *frame, rad_vec3 lo, rad_vec3 hi);
rad_vec3 radi_frame_apply(const rad_frame *frame, rad_vec3 p);
/* shift 2^-exponent: a point's coordinates as the user gave them are, in
 * the frame's units, its coordinates in the frame plus this.  They carry
 * the user's rounding, eps of their size (radi_occ_scene_snap,
 * occlusion.h). */
rad_vec3 radi_frame_offset(const rad_frame *frame);

/* A private copy of the mesh's geometry in the frame of its bounding box
 * (frame may be NULL): the same elements, surfaces, normals and vertex
 * lists; vertices, areas and centroids in the frame.  Form factors and
 * visibility computed on it are those of the mesh at any scale.  Free it
 * with rad_mesh_free. */
rad_status radi_mesh_normalized(const rad_mesh *mesh, rad_mesh *out, rad_frame *frame,
                               rad_error *err);

/* The point (1-v)((1-u) q0 + u q1) + v((1-u) q3 + u q2) of the quad q,
 * by the formula rad_mesh_build grids a quad with (exact at the corners):
 * a finer grid of the same quad repeats the coarse grid's vertices bit
 * for bit (adaptnodes.c). */
rad_vec3 radi_mesh_bilinear(const rad_vec3 q[4], double u, double v);

/* Surface s is a polygon cut into triangles (meshtri.c), not a grid of
 * quadrilaterals nor a lone element. */
int radi_mesh_is_fan(const rad_mesh *m, int s);
/* The outline of surface s, counter-clockwise: a grid's four corners, a
 * lone element's vertices, or the corners of a polygon cut into triangles;
 * returns their count (out may be NULL to ask it). */
int radi_mesh_outline(const rad_mesh *m, int s, rad_vec3 *out);

/* creaseedge.c: the points where crease.c found vertices of several
 * surfaces, and whether two surfaces may be smoothed across; then, on
 * each outline edge, the points one side has and the other lacks take
 * the interpolation of the points both have (tol: the distance within
 * which a vertex lies on an edge) */
typedef struct radi_crease_points {
    const int *point_of;        /* per vertex: its point, -1: none */
    const size_t *first;        /* point p's members: [first[p], first[p+1]) */
    const int *surface;         /* each member's surface */
    int (*may_join)(const void *ctx, int s, int t);
    const void *ctx;
} radi_crease_points;
rad_status radi_crease_edges(const rad_mesh *m, const radi_crease_points *cp, double tol,
                             double *out, rad_error *err);

/* meshtri.c: a K-gon cut into triangles with n > 1 parts per edge (its
 * surface_n is n, its surface_m 0) */
void radi_mesh_fan_count(int K, int n, size_t *ne, size_t *nv);
void radi_mesh_fan(rad_mesh *m, const rad_scene *scene, int s, rad_vec3 nrm, int *ne, int *nv,
                   int *ni);

/* meshgeom.c: (p - o) 2^-e, exactly unless the result is subnormal; the
 * unit normal of a planar polygon (Newell's vector at size about 1) */
rad_vec3 radi_mesh_shrink(rad_vec3 p, rad_vec3 o, int e);
rad_vec3 radi_mesh_unit_normal(const rad_vec3 *p, int n);

/* Element e: (gi, gj) of surface s, its n corners p (vertex indices from
 * vindex[first]), the surface's unit normal, its own area and centroid,
 * the material's reflectance and emission. */
void radi_mesh_element_set(rad_element *e, int s, int gi, int gj, const rad_vec3 *p, int n,
                           int first, rad_vec3 nrm, const rad_material *mat);

/* Area and centroid of the planar polygon p (n vertices, unit normal nrm)
 * as rad_mesh_build computes an element's. */
void radi_mesh_area_centroid(const rad_vec3 *p, int n, rad_vec3 nrm, double *area,
                            rad_vec3 *centroid);

#endif /* RAD_MESH_H */
