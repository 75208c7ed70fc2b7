/* mesh.h -- mesh internals shared with the solver and the tests.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_MESH_H
#define RAD_MESH_H

#include <stddef.h>

#include "radiosity.h"

/* How many elements, vertices and vertex indices the scene's mesh has,
 * without building it (for the memory check).  RAD_ERR_TOOBIG when the
 * counts do not fit in an int. */
rad_status rad_mesh_count(const rad_scene *scene, size_t *nelem, size_t *nvert,
                          size_t *nindex);

#endif /* RAD_MESH_H */
