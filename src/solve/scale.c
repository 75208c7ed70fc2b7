/* scale.c -- exact scalings by powers of two.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The radiosity system is linear in E and the solvers weigh by area only
 * in ratios, so E and the areas are scaled by powers of two (exact: only
 * the exponent changes, C11 7.12.6.6 ldexp) to a largest value in
 * [1/2, 1) before solving, and B scaled back at the end (solve.c, Range;
 * solvefree.c).
 */
#include <config.h>

#include <math.h>

#include "radiosity/base.h"
#include "solve/solvers.h"

/* The largest |x_k| (0 for n = 0; NaN entries are passed over by fmax). */
double radi_max_abs(const double *x, size_t n)
{
    double m = 0;
    for (size_t k = 0; k < n; k++)
        m = fmax(m, fabs(x[k]));
    return m;
}

/* 2^e with 2^(e-1) <= max |x_k| < 2^e (0 for all zeros or a non-finite
 * maximum): the exponent that scales x to a largest value in [1/2, 1). */
int radi_scale_exponent(const double *x, size_t n)
{
    int e = 0;
    const double m = radi_max_abs(x, n);
    if (m > 0 && isfinite(m))
        frexp(m, &e);
    return e;
}

void radi_scale_by(double *x, size_t n, int e)
{
    for (size_t k = 0; k < n; k++)
        x[k] = ldexp(x[k], e);
}
