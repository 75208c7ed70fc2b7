/* rmserror.h -- the area-weighted RMS error of Cohen et al. 1988, eq. 14.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Two readings of one equation, both against a converged solution Bref:
 * radi_rms_eq14 is the paper's (the RMS of the band-averaged radiosity) and
 * radi_rms_bands the mean of the three per-band RMS values this program
 * reported before (kept under the column names *_bands).  Arrays are
 * n x RAD_BANDS, column-major; amb (per band) may be NULL, else the
 * displayed radiosity is B + rho amb (eq. 13).  See rmserror.c.
 */
#ifndef RAD_RMSERROR_H
#define RAD_RMSERROR_H

#include "radiosity/base.h"

/* What the error compares: element areas, their sum, reflectances (read
 * only with amb), the ambient term (or NULL), B and the reference. */
typedef struct rad_rms_input {
    int n;
    const double *area;
    double total_area;
    const double *rho;
    const double *amb;
    const double *B, *Bref;     /* Bref NULL: 0 */
} rad_rms_input;

/* sqrt(sum_i A_i (Bbar_i - Bbar_ref,i)^2 / sum_i A_i), Bbar the mean over
 * the bands (Cohen et al. 1988, eq. 14).  0 when the total area is not
 * positive. */
double radi_rms_eq14(const rad_rms_input *in);

/* (1/3) sum_b sqrt(sum_i A_i (B_ib - Bref_ib)^2 / sum_i A_i): eq. 14 per
 * band, averaged over the bands. */
double radi_rms_bands(const rad_rms_input *in);

/* eq. 14 of B = 0 (the RMS of the band-averaged reference itself): the
 * scale a normalised error curve divides by. */
double radi_rms_of(int n, const double *area, double total_area, const double *B);

#endif /* RAD_RMSERROR_H */
