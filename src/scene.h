/* scene.h -- scene parsing internals shared with the tests.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_SCENE_H
#define RAD_SCENE_H

#include "radiosity.h"

#define RAD_MESH_MAX 100000     /* largest N or M in `mesh NxM` */
#define RAD_POLYGON_MAX 65536   /* most vertices of a polygon or disk */

/* Check that p[0..n) is a planar, convex, simple polygon of non-zero area;
 * `what` names it in the message "FILE:LINE: what is ...". */
rad_status rad_polygon_check(const rad_vec3 *p, int n, const char *what,
                             const char *file, int line, rad_error *err);

#endif /* RAD_SCENE_H */
