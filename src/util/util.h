/* util/util.h -- the face of src/util/: what the modules above use of the toolkit: the error record, 3-vectors and
 * their vectorised log and atan, convex polygons, the line and number
 * readers, exact printing, JSON strings and the LAPACK prototypes.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_UTIL_FACE_H
#define RAD_UTIL_FACE_H

#include "util/status.h"
#include "util/readfile.h"
#include "util/readnum.h"
#include "util/fmtdouble.h"
#include "util/jsonstr.h"
#include "util/lapack.h"
/* the inline vector, logarithm and polygon code is C (hex-float
 * constants, C99 initialisers): the one C++ file (occ/visibility.cc)
 * needs none of it */
#ifndef __cplusplus
#include "util/vec.h"
#include "util/vecmath.h"
#include "util/polygon.h"
#endif

#endif /* RAD_UTIL_FACE_H */
