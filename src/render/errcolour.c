/* errcolour.c -- pseudo-colour error pictures.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen, Chen, Wallace & Greenberg, "A Progressive Refinement Approach to
 * Fast Radiosity Image Generation", SIGGRAPH 1988, figures 2-5 pair each
 * partial solution with an error image: "grey is accurate, blue under,
 * red over", against the converged solution.  The paper does not print
 * its scale; this is the one used here:
 *
 *   Y_i   = (B_i,r + B_i,g + B_i,b) / 3, the band-averaged radiosity (as
 *           in eq. 14) of the partial solution as displayed (with the
 *           ambient term of eq. 13 when the picture shows it);
 *   e_i   = (Y_i - Yref_i) / Yref_i, relative to the converged solution;
 *   t_i   = min(|e_i| / RAD_ERRCOLOUR_FULL, 1), RAD_ERRCOLOUR_FULL = 0.5;
 *   colour = (1 - t) grey + t red   (e > 0: over-estimate),
 *            (1 - t) grey + t blue  (e < 0: under-estimate),
 *   in 8-bit sRGB: grey (128, 128, 128), red (255, 0, 0), blue (0, 0, 255).
 *
 * A relative error shows the shadows, where Yref is small and an ambient
 * term (uniform over the room) overshoots most, as the paper's figures
 * do; an absolute one would show only the bright walls.  Elements with
 * Yref = 0 are grey when Y = 0 and full red otherwise.
 *
 * The picture is drawn by the ordinary renderer: the colour's bytes are
 * decoded from sRGB to linear (IEC 61966-2-1) and handed over as
 * radiosity at exposure 1, flat shading, which encodes them back.
 */
#include <config.h>

#include <math.h>

#include "render/errcolour.h"
#include "radiosity/base.h"
#include "radiosity/render.h"
#include "radiosity/render.h"

static double band_mean(int n, int i, const double *B)
{
    double s = 0;
    for (int b = 0; b < RAD_BANDS; b++)
        s += B[(size_t)i + (size_t)b * (size_t)n];
    return s / RAD_BANDS;
}

double radi_errcolour_relative(int n, int i, const double *B, const double *Bref)
{
    const double y = band_mean(n, i, B), yref = band_mean(n, i, Bref);
    if (yref > 0)
        return (y - yref) / yref;
    return y > 0 ? INFINITY : y < 0 ? -INFINITY : 0;
}

void radi_errcolour_of(double e, unsigned char rgb[3])
{
    static const double grey = 128;
    const double t = isnan(e) ? 0 : fmin(fabs(e) / RAD_ERRCOLOUR_FULL, 1);
    const double target[3] = {e > 0 ? 255 : 0, 0, e > 0 ? 0 : 255};
    for (int b = 0; b < 3; b++)
        rgb[b] = (unsigned char)lround((1 - t) * grey + t * target[b]);
}

void radi_errcolour_field(int n, const double *B, const double *Bref, double *out)
{
    for (int i = 0; i < n; i++) {
        unsigned char c[3];
        radi_errcolour_of(radi_errcolour_relative(n, i, B, Bref), c);
        for (int b = 0; b < RAD_BANDS; b++)
            out[(size_t)i + (size_t)b * (size_t)n] = rad_srgb_decode(c[b] / 255.0);
    }
}
