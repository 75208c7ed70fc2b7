/* vs3read.h -- the View3D 3.x input reader (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_VS3READ_H
#define RAD_VS3READ_H

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "util/util.h"

/* Read the View3D lines of r (opened with '!' as its comment character)
 * into *scene, r->name naming the file in messages and r->err taking the
 * error.  On failure *scene is left empty. */
rad_status radi_vs3_read(rad_scene *scene, rad_lines *r);

#endif /* RAD_VS3READ_H */
