/* radiosity/mesh.h -- equal elements, and vertex radiosity from element radiosity.
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 */
#ifndef RADIOSITY_MESH_H
#define RADIOSITY_MESH_H

#include "radiosity/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- mesh --------------------------------------------------------------- */

typedef struct rad_element {
    int surface;                /* index of the scene surface it came from */
    int gi, gj;                 /* position in the surface's grid (0,0 for polygons) */
    int nverts;                 /* 4 for quad elements, K for polygons */
    int first;                  /* its vertex indices: mesh.vindex[first..first+nverts) */
    rad_vec3 centroid;
    rad_vec3 normal;            /* unit front normal */
    double area;
    double reflect[RAD_BANDS];
    double emit[RAD_BANDS];
} rad_element;

typedef struct rad_mesh {
    int nelements;
    rad_element *elements;
    int nvertices;
    rad_vec3 *vertices;         /* shared inside a surface, never across */
    int *vindex;                /* element vertex lists, counter-clockwise */
    int nsurfaces;
    int *surface_first;         /* elements of surface s: [first[s], first[s+1]) */
    int *surface_vfirst;        /* vertices of surface s: [vfirst[s], vfirst[s+1]);
                                   a quad's are row-major: (gj) * (n+1) + gi */
    int *surface_n, *surface_m; /* grid size per surface: N x M for a quad,
                                   1 x 1 for a polygon left whole, n x 0
                                   for a polygon cut into triangles (n per
                                   edge; no grid: radiosity-files(5)) */
} rad_mesh;

/* Refuses (RAD_ERR_INVALID, naming the scene's line) an element whose area
 * is not a normal double: the areas are in the user's units. */
RAD_API rad_status rad_mesh_build(rad_mesh *mesh, const rad_scene *scene, rad_error *err);
RAD_API void rad_mesh_free(rad_mesh *mesh);
/* ---- the reported form factors ------------------------------------------ */

/* The rows (and columns) of the form factors as `radiosity formfactor`
 * and `compare` report them, View3D's shape for its files (View3D 3.2's
 * Combine routine; NISTIR 6925): row[e] (mesh->nelements
 * ints) receives element e's reported row, and the count k of rows is
 * returned.  Elements of obstruction surfaces (View3D's O lines) have
 * none (-1).  A surface S whose `combine` names an earlier surface T
 * (View3D's CMB; honoured when T is not an obstruction and its own
 * `combine` is negative) joins T's group: every element of T and of each
 * such S shares one row, numbered where T's first element is.  Every
 * other element has a row of its own.  Rows keep the elements' order
 * (row[e] <= e), so without obstructions and combinations row[e] = e. */
RAD_API int rad_mesh_reported(const rad_scene *scene, const rad_mesh *mesh, int *row);
/* The n x n element matrix F (column-major, F[i + j*n] = F_ij, n =
 * mesh->nelements) reduced in place to the k x k reported one (its first
 * k*k doubles, F[I + J*k] = F_IJ), rows as rad_mesh_reported gave them,
 * by additivity (Siegel & Howell, the factor from a sum of areas; View3D
 * adds the interchange areas A F alike):
 *     F_IJ = (1/A_I) sum_{i in I} sum_{j in J} A_i F_ij,
 *     A_I  = sum_{i in I} A_i,
 * so that a union's factor to a column is the sum of its members' and its
 * self factor F_II is what the union sends to itself.  A row of one
 * element keeps its values bit for bit (no area is multiplied in).  E,
 * the estimated absolute errors, unless NULL, is reduced the same way: a
 * bound on F_IJ's error when each |dF_ij| <= E_ij (triangle inequality).
 * area (k doubles) receives A_I.  RAD_ERR_NOMEM (err filled, F and E
 * untouched) when its scratch does not fit. */
RAD_API rad_status rad_mesh_reduce(const rad_mesh *mesh, const int *row, int k, double *F,
                                   double *E, double *area, rad_error *err);
/* The vertex v (0..nverts-1) of element e. */
RAD_API rad_vec3 rad_mesh_vertex(const rad_mesh *mesh, int e, int v);
/* Elements the scene's mesh specification makes (a double: it may exceed
 * any int), without meshing. */
RAD_API double rad_scene_element_count(const rad_scene *scene);

/* ---- vertex radiosity --------------------------------------------------- */

/* Vertex radiosity from element radiosity (Goral et al. 1984, section 3;
 * Gouraud 1971), never across surfaces.  B is nelements x RAD_BANDS and Bv
 * nvertices x RAD_BANDS, both column-major. */
RAD_API void rad_smooth_vertices(const rad_mesh *mesh, const double *B, double *Bv);

/* How a vertex on a surface's boundary gets its value:
 * EXTRAPOLATE is the 1984 paper's linear extrapolation (the default, what
 * rad_smooth_vertices does); CORNER is the course notes' rule, where the
 * mean of a boundary vertex and its nearest interior vertex equals the
 * mean of the elements that meet at the boundary vertex.  The two agree
 * on edges and on fields linear over the surface; they differ at
 * corners. */
typedef enum rad_vertex_rule {
    RAD_VERTEX_EXTRAPOLATE = 0,
    RAD_VERTEX_CORNER
} rad_vertex_rule;
RAD_API void rad_smooth_vertices_rule(const rad_mesh *mesh, const double *B, double *Bv,
                                      rad_vertex_rule rule);
/* Smooth across surfaces: where surfaces of one object of the scene the
 * mesh was built from (rad_surface.object; those outside every object
 * count as one), of the same material, whose normals differ by less than
 * crease_degrees meet at a vertex (the same point, to 2^-30 of the
 * scene's size), each of their vertices there takes the mean of their
 * Bv, weighted by the area of each one's elements at the point.  0
 * leaves Bv as it is: surfaces never mix, as Goral et al. 1984 smooth;
 * less than 0 (RAD_CREASE_AUTO) takes rad_crease_default(scene).  Not
 * for a mesh with hanging vertices (an adaptive one): they would no
 * longer lie on their edges' values. */
RAD_API rad_status rad_smooth_across(const rad_scene *scene, const rad_mesh *mesh,
                                     double crease_degrees, double *Bv, rad_error *err);
/* The crease angle a scene's format implies: RAD_CREASE_OBJ degrees for
 * an OBJ model (faces of one object are parts of one shape, as modelling
 * tools smooth them), 0 for the native format and View3D's (each surface
 * is a surface of its own). */
#define RAD_CREASE_OBJ 30.0
/* A crease angle (rad_smooth_across, rad_pipeline_options.crease) that
 * asks for what the scene's format implies. */
#define RAD_CREASE_AUTO (-1.0)
RAD_API double rad_crease_default(const rad_scene *scene);
/* "extrapolate", "corner", or NULL. */
RAD_API const char *rad_vertex_rule_name(int rule);

#ifdef __cplusplus
}
#endif

#endif /* RADIOSITY_MESH_H */
