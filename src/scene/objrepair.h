/* objrepair.h -- what the OBJ reader repairs, as mainstream importers do.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_OBJREPAIR_H
#define RAD_OBJREPAIR_H

#include "radiosity/scene.h"
#include "scene/scenebuild.h"
#include "util/util.h"

/* The kinds of rad_scene_repairs, in the order of its first_line. */
enum { RADI_REPAIR_MATERIAL, RADI_REPAIR_NAME, RADI_REPAIR_DEGENERATE, RADI_REPAIR_SPLIT };

/* Count one repair of `kind` at input line `line` (0: not known). */
void radi_obj_note(rad_scene_repairs *rep, int kind, int line);

/* Add face v[0..n) (malloc'd; taken over, freed on every path) of the OBJ
 * line r is at, repairing what importers repair: a face with fewer than
 * 3 distinct corners or no area is left out; one that is not planar or
 * not convex is cut into triangles by ear clipping; `undefined` counts it
 * as given the default grey.  A face that cannot be repaired (it crosses
 * itself) is refused as radi_polygon_check says. */
rad_status radi_obj_repair_face(rad_scene_build *b, rad_lines *r, rad_vec3 *v, int n, int mat,
                                int object, int undefined);

#endif /* RAD_OBJREPAIR_H */
