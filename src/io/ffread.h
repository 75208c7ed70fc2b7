/* ffread.h -- another solver's form-factor matrix, read back (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * `radiosity compare` reads the matrix a user's own solver wrote, in any of
 * the formats such matrices travel in, into the library's layout: n x n,
 * column-major, F[i + j*n] = F_ij, the factor from element i to element j
 * (row i = from element i; doc/design.md, "Conventions").  The format is
 * told by the content, never by the name alone:
 *
 *   "\x93NUMPY"                 NumPy .npy, float64 or float32, 2-D, C or Fortran order
 *                               (npyread.c)
 *   "%%MatrixMarket matrix"     Matrix Market, `array real general` (what
 *                               --form-factors writes) or `coordinate real
 *                               general` (absent entries are 0)
 *   "View3D V F E D N"          NIST View3D's view-factor file, its text
 *                               (F = 0) or binary (F = 1) form (vfread.c)
 *   a first line "i j F ..."    the program's own form-factor table
 *                               (`radiosity formfactor`): 0-based i, j,
 *                               every ordered pair of distinct elements
 *                               once (F_ii, 0, may be given); more
 *                               columns allowed
 *
 * The caller says how many elements the scene has: a matrix of another
 * size is refused before anything of its size is allocated.  Every
 * failure names the file, and the line for text ("FILE:LINE: what").
 */
#ifndef RAD_FFREAD_H
#define RAD_FFREAD_H

#include <stddef.h>

#include "radiosity/base.h"

/* Read the n x n matrix at path into F (n * n doubles the caller owns).
 * *format receives a short name of the format found ("npy", "Matrix
 * Market array", ...).  RAD_ERR_IO when the file cannot be read,
 * RAD_ERR_PARSE (message "FILE:LINE: ..." or "FILE: ...") otherwise. */
rad_status radi_ff_read(const char *path, int n, double *F, const char **format,
                       rad_error *err);

/* NumPy .npy (npyread.c): a 2-D n x n float64 or float32 array; *bits
 * receives 64 or 32. */
rad_status radi_npy_read_square(const char *path, int n, double *F, int *bits, rad_error *err);

/* View3D's view-factor file (vfread.c): text (format 0) or binary
 * (format 1), as View3D 3.x's SaveVF writes them. */
rad_status radi_vf_read_text(const char *path, int n, double *F, rad_error *err);
rad_status radi_vf_read_binary(const char *path, int n, double *F, rad_error *err);

#endif /* RAD_FFREAD_H */
