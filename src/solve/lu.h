/* lu.h -- blocked LU with progress (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_LU_H
#define RAD_LU_H

#include "radiosity/formfactor.h"

/* Factor the n x n column-major A in place as dgetrf does (same L, U and
 * 1-based pivots).  Returns dgetrf's info: 0, or i > 0 when U(i,i) is
 * exactly zero.  progress (may be NULL) runs between column blocks; if it
 * returns non-zero the factorisation stops and *stopped is set. */
int radi_lu_factor(int n, double *A, int *ipiv, rad_progress_fn progress, void *user,
                  const char *stage, int *stopped);

#endif /* RAD_LU_H */
