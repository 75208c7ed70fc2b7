/* objread.h -- the Wavefront OBJ + MTL reader (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_OBJREAD_H
#define RAD_OBJREAD_H

#include <stddef.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "util/util.h"

/* Read the OBJ lines of r (opened with '#' as its comment character) into
 * *scene, r->name naming the file in messages and r->err taking the error.
 * Each `mtllib` file is opened relative to the directory of r->name; when
 * mtl is not NULL, the first `mtllib` reads mtl[0..mtl_len) instead, named
 * by its first file name, and later ones read nothing (tests, fuzzing).
 * On failure *scene is left empty. */
rad_status radi_obj_read(rad_scene *scene, rad_lines *r, const char *mtl, size_t mtl_len,
                         unsigned flags);

#endif /* RAD_OBJREAD_H */
