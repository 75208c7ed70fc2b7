/* radiosity/scene.h -- the scene: surfaces, materials, objects, camera.
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 */
#ifndef RADIOSITY_SCENE_H
#define RADIOSITY_SCENE_H

#include "radiosity/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- scene -------------------------------------------------------------- */

#define RAD_NAME_MAX 64

typedef struct rad_material {
    char name[RAD_NAME_MAX];
    double reflect[RAD_BANDS];  /* rho in [0, 1] */
    double emit[RAD_BANDS];     /* E >= 0 */
    int line;                   /* where it was defined */
} rad_material;

typedef enum rad_surface_kind {
    RAD_SURFACE_QUAD = 0,       /* meshed into mesh_n x mesh_m elements */
    RAD_SURFACE_POLYGON         /* convex planar polygon, one element */
} rad_surface_kind;

typedef struct rad_surface {
    rad_surface_kind kind;
    int material;               /* index into rad_scene.materials */
    int nverts;                 /* 4 for a quad, K >= 3 for a polygon */
    rad_vec3 *verts;            /* counter-clockwise about the front */
    int mesh_n, mesh_m;         /* quad: v1->v2 in N parts, v2->v3 in M parts;
                                   polygon: each edge of its fan's triangles
                                   in N parts (M = N; 1: one element) */
    int line;                   /* input line, for messages */
    int object;                 /* index into rad_scene.objects; -1: the static
                                   environment (outside every object) */
    int obstruction;            /* 1: blocks the view but is left out of the
                                   reported form factors (View3D's O lines,
                                   which come after every other surface) */
    int combine;                /* index of the earlier surface whose row this
                                   one's factors join in the reported form
                                   factors (View3D's CMB); -1: its own row */
} rad_surface;

/* A named group of surfaces that a change may move, add or remove (the
 * dynamic-scene contract of radiosity-scene(5)): `object NAME [absent]`
 * ... `end` in a scene file, `o` and `g` statements in OBJ. */
typedef struct rad_object {
    char name[RAD_NAME_MAX];
    int absent;                 /* 1: joins the scene only when a change adds it */
    int line;                   /* where it was first named */
} rad_object;

typedef struct rad_camera {
    int defined;                /* 0: the scene has no camera line */
    rad_vec3 eye, at, up;
    double fov;                 /* vertical, degrees */
} rad_camera;

/* What reading a foreign format (OBJ) repaired, so that the caller can say
 * it: counts, and the input line of the first of each kind (0: none). */
typedef struct rad_scene_repairs {
    int undefined_materials;    /* faces whose usemtl named no material read
                                   (or none): given RAD_DEFAULT_GREY */
    int spaced_names;           /* names with spaces, with bytes beyond ASCII,
                                   or empty, taken as written */
    int degenerate_faces;       /* faces left out: fewer than 3 distinct
                                   corners, or no area */
    int split_faces;            /* faces not planar or not convex, cut into */
    int split_triangles;        /* ... this many triangles (ear clipping) */
    int first_line[4];          /* of each kind above, in that order */
} rad_scene_repairs;

/* The kinds of repair above, in the order of first_line. */
#define RAD_SCENE_REPAIR_KINDS 4

/* The material given to faces whose material is undefined. */
#define RAD_DEFAULT_GREY "(default grey 0.5)"

/* The formats a scene may be read in; AUTO picks by the name's ending as
 * rad_scene_load does ("-" and other names: the native format). */
typedef enum rad_scene_format {
    RAD_SCENE_FORMAT_AUTO = 0,
    RAD_SCENE_FORMAT_SCENE,     /* radiosity-scene(5) */
    RAD_SCENE_FORMAT_OBJ,       /* Wavefront OBJ + MTL (mtllib relative to the
                                   file, to the current folder for "-") */
    RAD_SCENE_FORMAT_VS3        /* View3D 3.x input */
} rad_scene_format;

typedef struct rad_scene {
    char *filename;
    rad_material *materials;
    int nmaterials;
    rad_surface *surfaces;
    int nsurfaces;
    rad_object *objects;
    int nobjects;
    rad_camera camera;
    rad_scene_repairs repairs;  /* all 0 for the native format and View3D's */
    rad_scene_format format;    /* what it was read as (never AUTO once read) */
} rad_scene;

/* Parse a scene file (format: radiosity-scene(5)).  "-" reads standard
 * input.  A name ending in ".obj" is read as Wavefront OBJ (its mtllib
 * files relative to it), one ending in ".vs3" as View3D 3.x input (both
 * case-insensitive; radiosity-scene(5) says what they map to).  On
 * failure *scene is left empty and err says FILE:LINE: why. */
RAD_API rad_status rad_scene_load(rad_scene *scene, const char *path, rad_error *err);
/* rad_scene_load in a given format, whatever the name (standard input,
 * a file with another ending).  An OBJ file is read as mainstream
 * importers read it, its repairs counted in scene->repairs; with
 * RAD_SCENE_STRICT in flags every such repair is the error it names
 * instead (the native format and View3D's are always strict). */
#define RAD_SCENE_STRICT 1u
RAD_API rad_status rad_scene_load_format(rad_scene *scene, const char *path,
                                         rad_scene_format format, unsigned flags,
                                         rad_error *err);
/* Parse scene text held in memory; `name` is used in messages and picks
 * the format by its ending as rad_scene_load does. */
RAD_API rad_status rad_scene_parse(rad_scene *scene, const char *text, size_t len,
                           const char *name, rad_error *err);
RAD_API void rad_scene_free(rad_scene *scene);
/* One line saying repair kind k (0 .. RAD_SCENE_REPAIR_KINDS - 1) of the
 * scene, as "FILE:LINE: repaired: 2 faces without area (...) left out"
 * (LINE: the first such face).  Returns 1 when the reader made repairs of
 * that kind and buf has room (size > 0; the line is cut to fit), else 0
 * (buf untouched). */
RAD_API int rad_scene_repair_text(const rad_scene *scene, int k, char *buf, size_t size);
/* Override the mesh of every surface (the --mesh option): quads into
 * n x m elements, triangles and other polygons into max(n, m)^2
 * triangles per triangle of their fan (a K-gon, K > 3, is first cut into
 * K triangles around its centroid). */
RAD_API void rad_scene_set_mesh(rad_scene *scene, int n, int m);
/* Mesh every surface so that no side of an element is longer than size
 * (> 0; the --max-element-size option): quads by the longer of each pair
 * of opposite sides, polygons by the longest edge of their fan's
 * triangles; a finer mesh the scene gives a surface stays.  Returns how
 * many surfaces it made finer (0: every element is already that small). */
RAD_API int rad_scene_set_max_element_size(rad_scene *scene, double size);
/* 1 if some surface belongs to an absent object. */
RAD_API int rad_scene_has_absent(const rad_scene *scene);
/* A copy of the scene with only the present surfaces, in file order:
 * present[o] (nobjects entries) says which objects are in, or, when
 * present is NULL, the objects not declared absent.  Free it with
 * rad_scene_free. */
RAD_API rad_status rad_scene_present_copy(const rad_scene *in, const unsigned char *present,
                                          rad_scene *out, rad_error *err);

#ifdef __cplusplus
}
#endif

#endif /* RADIOSITY_SCENE_H */
