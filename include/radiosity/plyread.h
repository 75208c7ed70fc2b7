/* plyread.h -- read a solution PLY back into a render model.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Reads the ASCII PLY that `radiosity solve --output FILE.ply` writes
 * (radiosity-files(5), SOLUTION) and, as far as they carry what a picture
 * needs, other ASCII PLY files:
 *   - element vertex with x, y, z; vertex radiosity from radiosity_r/g/b,
 *     else from the sRGB colours red/green/blue (decoded to linear), else
 *     the mean of the radiosity of the faces around the vertex;
 *   - element face with the list vertex_indices (or vertex_index), an
 *     optional int surface, an optional `emitting` (non-zero: a light
 *     source, which the automatic exposure leaves out), and face radiosity from radiosity_r/g/b, else
 *     red/green/blue, else the mean of its vertices' radiosity;
 *   - "comment camera eye X Y Z at X Y Z up X Y Z fov F" gives the camera.
 * Properties may come in any order; unknown properties and elements are
 * skipped.  Each element instance must be on a line of its own.  Faces must
 * be planar convex polygons (the tolerances of radiosity-scene(5)).
 * Every error is "FILE:LINE: what is wrong" and leaves the model empty.
 */
#ifndef RAD_PLYREAD_H
#define RAD_PLYREAD_H

#include <stddef.h>

#include "radiosity/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Parse PLY text held in memory; `name` is used in messages.  camera (may
 * be NULL) receives the camera of the comment, or defined = 0. */
RAD_API rad_status rad_ply_parse(rad_render_model *model, rad_camera *camera, const char *text,
                         size_t len, const char *name, rad_error *err);
/* Read a PLY file ("-" is standard input). */
RAD_API rad_status rad_ply_read(rad_render_model *model, rad_camera *camera, const char *path,
                        rad_error *err);

#ifdef __cplusplus
}
#endif

#endif /* RAD_PLYREAD_H */
