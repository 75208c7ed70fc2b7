/* readnum.h -- numbers from the tokens of a line (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The OBJ and View3D readers take their numbers from the tokens the line
 * reader (readfile.h) made, in C strtod / strtol syntax; a token that is
 * not wholly a number, or a number out of range, fails with
 * "NAME:LINE: what is wrong" naming the token and what it was for.
 */
#ifndef RAD_READNUM_H
#define RAD_READNUM_H

#include "util/readfile.h"

/* Token k as a finite double. */
rad_status radi_tok_number(const rad_lines *r, int k, const char *what, double *out);
/* Tokens k, k+1, k+2 as a point. */
rad_status radi_tok_vec(const rad_lines *r, int k, const char *what, rad_vec3 *out);
/* Text t (a token or part of one) as a whole number from lo to hi. */
rad_status radi_tok_long(const rad_lines *r, const char *t, const char *what, long lo,
                        long hi, long *out);
/* One value (grey) or three (R G B) from token k on, each from lo to hi,
 * and nothing after them. */
rad_status radi_tok_bands(const rad_lines *r, int k, const char *what, double lo, double hi,
                         double out[RAD_BANDS]);

#endif /* RAD_READNUM_H */
