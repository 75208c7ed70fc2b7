/* adapt/adapt.h -- the face of src/adapt/: adaptive subdivision for the modules above: the solve
 * (adaptive.h), its leaves as a mesh (adaptmesh.h) and the race of progress --adaptive
 * (adaptrace.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_ADAPT_FACE_H
#define RAD_ADAPT_FACE_H

#include "adapt/adaptive.h"
#include "adapt/adaptmesh.h"
#include "adapt/adaptrace.h"

#endif /* RAD_ADAPT_FACE_H */
