/* rmserror.c -- the area-weighted RMS error of Cohen et al. 1988, eq. 14.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen, Chen, Wallace & Greenberg, "A Progressive Refinement Approach to
 * Fast Radiosity Image Generation", SIGGRAPH 1988, eq. 14, measures a
 * partial solution by
 *     RMS error = sqrt( sum_i (B_i^conv - B_i^(k))^2 A_i / sum_i A_i )
 * with one radiosity per element: the paper's B_i is the radiosity
 * averaged over the colour bands.  radi_rms_eq14 is that.  radi_rms_bands
 * applies the formula to each band and averages the three results, as this
 * program once did for `rms`; the two agree on grey scenes and whenever the
 * three bands' errors are proportional, and differ otherwise (errors of
 * opposite sign in two bands cancel in the first and not in the second).
 *
 * With the ambient term (eq. 13) the displayed B'_i = B_i + rho_i Ambient
 * replaces B_i.
 *
 * Scaling: the weights are A_i / sum A and the differences are divided by
 * their largest magnitude before squaring, so that neither A d^2 nor d^2
 * overflows or underflows where the RMS itself is a double (as hypot does;
 * areas of 1e300, radiosities of 1e300).
 */
#include <config.h>

#include <math.h>

#include "compare/rmserror.h"

#define NB RAD_BANDS

/* Element i's difference from the reference in band b (eq. 13-14); a
 * NULL reference is 0. */
static double diff(const rad_rms_input *in, int i, int b)
{
    const size_t k = (size_t)i + (size_t)b * (size_t)in->n;
    return in->B[k] + (in->amb ? in->rho[k] * in->amb[b] : 0) - (in->Bref ? in->Bref[k] : 0);
}

/* The band-averaged difference of element i, or band b's alone (b >= 0). */
static double diff_of(const rad_rms_input *in, int i, int b)
{
    if (b >= 0)
        return diff(in, i, b);
    double s = 0;
    for (int c = 0; c < NB; c++)
        s += diff(in, i, c);
    return s / NB;
}

/* sqrt(sum_i A_i d_i^2 / sum A) of diff_of(., ., b), scaled as above. */
static double rms_of_diff(const rad_rms_input *in, int b)
{
    double dmax = 0, s = 0;
    if (!(in->total_area > 0))
        return 0;
    for (int i = 0; i < in->n; i++)
        dmax = fmax(dmax, fabs(diff_of(in, i, b)));
    if (!(dmax > 0))
        return 0;
    for (int i = 0; i < in->n; i++) {
        const double d = diff_of(in, i, b) / dmax;
        s += in->area[i] / in->total_area * d * d;
    }
    return dmax * sqrt(s);
}

double radi_rms_eq14(const rad_rms_input *in)
{
    return rms_of_diff(in, -1);
}

double radi_rms_bands(const rad_rms_input *in)
{
    double mean = 0;
    for (int b = 0; b < NB; b++)
        mean += rms_of_diff(in, b);
    return mean / NB;
}

double radi_rms_of(int n, const double *area, double total_area, const double *B)
{
    const rad_rms_input in = {n, area, total_area, NULL, NULL, B, NULL};
    return rms_of_diff(&in, -1);
}
