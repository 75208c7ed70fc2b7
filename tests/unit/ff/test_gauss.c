/* test_gauss.c -- the Gauss-Legendre tables integrate polynomials of degree
 * 2k-1 exactly (Abramowitz & Stegun 1964, 25.4.29).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Reference: integral_-1^1 x^p dx = 2/(p+1) for even p, 0 for odd p.
 * Tolerance: a sum of k terms of size <= 2 carries round-off of about
 * k * eps, so 8 k eps (eps = 2^-52) bounds it with room to spare.
 */
#include <config.h>

#include <float.h>
#include <math.h>

#include "radiosity/formfactor.h"
#include "../tap.h"

int main(void)
{
    for (int k = 1; k <= RAD_GAUSS_MAX; k++) {
        const double *x = rad_gauss_nodes(k), *w = rad_gauss_weights(k);
        double worst = 0, wsum = 0;
        for (int p = 0; p <= 2 * k - 1; p++) {
            double s = 0;
            for (int i = 0; i < k; i++)
                s += w[i] * pow(x[i], p);
            double exact = p % 2 ? 0.0 : 2.0 / (p + 1);
            worst = fmax(worst, fabs(s - exact));
        }
        for (int i = 0; i < k; i++)
            wsum += w[i];
        tap_ok(worst <= 8 * k * DBL_EPSILON,
               "k = %2d: degree <= %2d exact (worst error %.3g)", k, 2 * k - 1, worst);
        /* degree 2k is NOT exact: proves the check can fail */
        double s = 0;
        for (int i = 0; i < k; i++)
            s += w[i] * pow(x[i], 2 * k);
        tap_ok(fabs(s - 2.0 / (2 * k + 1)) > 64 * k * DBL_EPSILON,
               "k = %2d: degree %d is not exact (as it must not be)", k, 2 * k);
        int sym = 1;
        for (int i = 0; i < k; i++)
            sym &= x[i] == -x[k - 1 - i] && w[i] == w[k - 1 - i];
        tap_ok(sym && fabs(wsum - 2) <= 4 * k * DBL_EPSILON,
               "k = %2d: nodes symmetric, weights sum to 2", k);
    }
    tap_ok(rad_gauss_nodes(0) == NULL && rad_gauss_nodes(RAD_GAUSS_MAX + 1) == NULL,
           "out-of-range k gives NULL");
    return tap_done();
}
