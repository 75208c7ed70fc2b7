/* polycheck.h -- what one scene may ask for, and the polygon check.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_POLYCHECK_H
#define RAD_POLYCHECK_H

#include "radiosity/base.h"

/* What one scene may ask for (radiosity-scene(5) documents them).  A
 * polygon's form factors cost K_a * K_b edge pairs, so two polygons of
 * RAD_POLYGON_MAX vertices cost about 16.8 million pairs, about 2 s;
 * a 4096-gon's area is within 4e-7 of its disk's.  RAD_ELEMENTS_MAX keeps
 * every count and index of the mesh in an int, whatever the scene. */
#define RAD_MESH_MAX 100000         /* largest N or M in `mesh NxM` */
#define RAD_POLYGON_MAX 4096        /* most vertices of a polygon or disk */
#define RAD_ELEMENTS_MAX 100000000  /* most elements per surface and per scene */

/* Check that p[0..n) is a planar, convex, simple polygon of non-zero area;
 * `what` names it in the message "FILE:LINE: what is ...". */
rad_status radi_polygon_check(const rad_vec3 *p, int n, const char *what,
                             const char *file, int line, rad_error *err);

#endif /* RAD_POLYCHECK_H */
