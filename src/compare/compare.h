/* compare/compare.h -- the face of src/compare/: another solver's numbers against ours: its form factors
 * (ffcompare.h), its element order (elmatch.h), RMS errors (rmserror.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_COMPARE_FACE_H
#define RAD_COMPARE_FACE_H

#include "compare/ffcompare.h"
#include "compare/elmatch.h"
#include "compare/rmserror.h"

#endif /* RAD_COMPARE_FACE_H */
