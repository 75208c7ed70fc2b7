/* fill/fill.h -- the face of src/fill/: the matrix F for the modules above: any block of it
 * (ffblock.h), chosen pairs (ffpairs.h), one shooter's column per shot
 * (ffrow.h), sums per surface (persurface.h); the dense fill is public
 * (rad_ff_matrix, radiosity/formfactor.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_FILL_FACE_H
#define RAD_FILL_FACE_H

#include "fill/ffblock.h"
#include "fill/ffrow.h"
#include "fill/ffpairs.h"
#include "fill/persurface.h"

#endif /* RAD_FILL_FACE_H */
