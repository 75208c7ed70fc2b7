/* render/render.h -- the face of src/render/: what the modules above use of the renderer: plots
 * (plot.h, plotxy.h) and pseudo-colour error pictures; the renderer
 * itself is public (radiosity/render.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_RENDER_FACE_H
#define RAD_RENDER_FACE_H

#include "render/plot.h"
#include "render/plotxy.h"
#include "render/errcolour.h"

#endif /* RAD_RENDER_FACE_H */
