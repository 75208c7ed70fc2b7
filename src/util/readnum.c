/* readnum.c -- numbers from the tokens of a line.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Shared by the OBJ and View3D readers, so both word their messages alike:
 * the token as written, then what it should have been.
 */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "util/readnum.h"

rad_status radi_tok_number(const rad_lines *r, int k, const char *what, double *out)
{
    char *end;
    if (k >= r->ntok)
        return radi_lines_fail(r, "missing number: %s", what);
    double v = strtod(r->tok[k], &end);
    if (end == r->tok[k] || *end != '\0')
        return radi_lines_fail(r, "'%s' is not a number (%s)", r->tok[k], what);
    if (!isfinite(v))
        return radi_lines_fail(r, "%s must be finite, not '%s'", what, r->tok[k]);
    *out = v;
    return RAD_OK;
}

rad_status radi_tok_vec(const rad_lines *r, int k, const char *what, rad_vec3 *out)
{
    rad_status st;
    if ((st = radi_tok_number(r, k, what, &out->x)) ||
        (st = radi_tok_number(r, k + 1, what, &out->y)) ||
        (st = radi_tok_number(r, k + 2, what, &out->z)))
        return st;
    return RAD_OK;
}

rad_status radi_tok_long(const rad_lines *r, const char *t, const char *what, long lo,
                        long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(t, &end, 10);
    if (end == t || *end != '\0')
        return radi_lines_fail(r, "'%s' is not a whole number (%s)", t, what);
    if (errno == ERANGE || v < lo || v > hi)
        return radi_lines_fail(r, "%s must be from %ld to %ld, not '%s'", what, lo, hi, t);
    *out = v;
    return RAD_OK;
}

rad_status radi_tok_bands(const rad_lines *r, int k, const char *what, double lo, double hi,
                         double out[RAD_BANDS])
{
    int n = r->ntok - k;
    if (n != 1 && n != RAD_BANDS)
        return radi_lines_fail(r, "%s takes 1 value (grey) or 3 (R G B), not %d", what, n);
    for (int b = 0; b < n; b++) {
        rad_status st = radi_tok_number(r, k + b, what, &out[b]);
        if (st)
            return st;
        if (!(out[b] >= lo && out[b] <= hi)) {
            if (hi < HUGE_VAL)
                return radi_lines_fail(r, "%s must be from %g to %g, not %s", what, lo, hi,
                                      r->tok[k + b]);
            return radi_lines_fail(r, "%s must not be negative, not %s", what, r->tok[k + b]);
        }
    }
    if (n == 1)
        out[1] = out[2] = out[0];
    return RAD_OK;
}
