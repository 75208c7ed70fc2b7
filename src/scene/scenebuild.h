/* scenebuild.h -- a scene under construction, shared by the readers (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The scene parser (scene.c), the OBJ reader (objread.c) and the View3D
 * reader (vs3read.c) all build a rad_scene the same way: materials and
 * objects found by name through a hash (so a parse takes time linear in its
 * input), surfaces appended one at a time and counted against
 * RAD_ELEMENTS_MAX.  Nothing here reads text or checks geometry: the
 * readers validate a surface (radi_polygon_check, polycheck.h) before they add
 * it.  Errors name the scene file and the line given.
 */
#ifndef RAD_SCENEBUILD_H
#define RAD_SCENEBUILD_H

#include <stddef.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"

/* Names to indices: open addressing, a power-of-two table of index + 1. */
typedef struct rad_name_index {
    int *slot;
    size_t nslot;
} rad_name_index;

typedef struct rad_scene_build {
    rad_scene s;                /* the scene so far; s.filename names it */
    rad_error *err;
    rad_name_index materials, objects;
    int matcap, surfcap, objcap;
    double elements;            /* in the surfaces so far */
    int object;                 /* scene.c: the object whose `end` is awaited,
                                   or -1 (radi_build_start sets it) */
} rad_scene_build;

/* Start an empty scene read from `filename` (copied). */
rad_status radi_build_start(rad_scene_build *b, const char *filename, rad_error *err);
/* Hand the scene over to *out (st == RAD_OK) or free it and leave *out
 * empty (st != RAD_OK); return st. */
rad_status radi_build_finish(rad_scene_build *b, rad_status st, rad_scene *out);

/* The index of a material or object by name, or -1. */
int radi_build_find_material(const rad_scene_build *b, const char *name);
int radi_build_find_object(const rad_scene_build *b, const char *name);

/* Append a material whose name is new (the caller checks); `file` and
 * `line` only name the place in an out-of-memory message. */
rad_status radi_build_add_material(rad_scene_build *b, const rad_material *m,
                                  const char *file, int line);
/* The object called `name`, appended (present, first named at `line`) if
 * it is new; its index in *index.  Names longer than RAD_NAME_MAX - 1
 * characters are refused with the scene file's name and `line`. */
rad_status radi_build_object(rad_scene_build *b, const char *name, int line, int *index);

/* Append a surface read at `line` of the scene file, which takes `verts`
 * (n vertices; freed here on failure); `object` is -1 or an object index. */
rad_status radi_build_add_surface(rad_scene_build *b, int line, rad_surface_kind kind,
                                 int material, int object, rad_vec3 *verts, int n,
                                 int mesh_n, int mesh_m);

#endif /* RAD_SCENEBUILD_H */
