/* errcolour.h -- pseudo-colour error pictures (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The colour scale of the error images of Cohen, Chen, Wallace & Greenberg
 * 1988 (figures 2-5): grey where a partial solution is accurate, blue where
 * it is under the converged one, red where it is over.  See errcolour.c.
 */
#ifndef RAD_ERRCOLOUR_H
#define RAD_ERRCOLOUR_H

#include "radiosity/base.h"

/* Relative error at which the colour is full red or full blue. */
#define RAD_ERRCOLOUR_FULL 0.5

/* The signed relative error of element i's band-averaged radiosity:
 * (Y - Yref) / Yref, Y the mean over the bands of B (n x RAD_BANDS,
 * column-major), Yref that of Bref; +-INFINITY (or 0 when Y = 0 too)
 * where Yref is 0. */
double radi_errcolour_relative(int n, int i, const double *B, const double *Bref);

/* The 8-bit sRGB colour of a relative error e: grey (128, 128, 128) at
 * 0, moving linearly to red (255, 0, 0) at e >= RAD_ERRCOLOUR_FULL and to
 * blue (0, 0, 255) at e <= -RAD_ERRCOLOUR_FULL. */
void radi_errcolour_of(double e, unsigned char rgb[3]);

/* "Radiosity" (n x RAD_BANDS, column-major) that the renderer, at exposure
 * 1 and flat shading, draws in each element's error colour: the sRGB
 * bytes decoded to linear. */
void radi_errcolour_field(int n, const double *B, const double *Bref, double *out);

#endif /* RAD_ERRCOLOUR_H */
