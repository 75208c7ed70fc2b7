/* radiosity.h -- the public C API of the radiosity library.
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 * The umbrella header: a user who wants the whole library includes this
 * one; each part (radiosity/base.h, scene.h, mesh.h, formfactor.h,
 * solve.h, pipeline.h, render.h, export.h, plyread.h, accuracy.h,
 * changes.h, animate.h) stands alone too.  The conventions the whole API
 * follows are stated once, in radiosity/base.h; radiosity(3) documents
 * every function.
 */
#ifndef RADIOSITY_H
#define RADIOSITY_H

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "radiosity/pipeline.h"
#include "radiosity/render.h"
#include "radiosity/export.h"
#include "radiosity/plyread.h"
#include "radiosity/accuracy.h"
#include "radiosity/changes.h"
#include "radiosity/animate.h"

#endif /* RADIOSITY_H */
