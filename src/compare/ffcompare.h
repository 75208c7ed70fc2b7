/* ffcompare.h -- how another solver's form factors differ from ours
 * (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The numbers `radiosity compare` reports, from two n x n matrices in the
 * library's layout (column-major, F[i + j*n] = F_ij, row i = from element
 * i): G, the other solver's, and F, ours, with E, our own estimate of each
 * entry's absolute error.  Nothing here prints or opens a file.
 *
 * The error of an entry (every entry, the diagonal included: a planar
 * element sees nothing of itself, so F_ii = 0 and any other value is a
 * difference):
 *
 *     e_ij = |G_ij - F_ij| / max(|F_ij|, floor)
 *
 * a relative error where F_ij >= floor, and the absolute difference in
 * units of the floor below it, so that entries where F is 0 (coplanar
 * pairs, pairs behind each other) cannot make it infinite.  RMS values
 * are sqrt(mean of e^2) over the entries counted.
 */
#ifndef RAD_FFCOMPARE_H
#define RAD_FFCOMPARE_H

#include <stddef.h>

#include "radiosity/base.h"

/* The histogram of log10 e: bins of a quarter decade from 1e-18 to 1e3,
 * plus the entries with e = 0 and those above the last bin. */
#define RAD_FFCMP_LOG_LO (-18.0)
#define RAD_FFCMP_BIN 0.25
#define RAD_FFCMP_BINS 84

typedef struct rad_ffcmp_pair {
    int i, j;
    double ours, theirs, err;
} rad_ffcmp_pair;

typedef struct rad_ffcmp_row {
    int i;
    double max, rms;            /* of e_ij over j */
    double sum_ours, sum_theirs;
} rad_ffcmp_row;

typedef struct rad_ffcmp {
    /* in: set before radi_ffcmp_run */
    double floor;               /* of the relative error (> 0) */
    int nworst;                 /* worst pairs to keep (>= 0) */
    /* out: every entry */
    double max_err, rms_err;    /* of e over the n^2 entries */
    long exact;                 /* entries equal bit for bit */
    long beyond_estimate;       /* entries with |G_ij - F_ij| > E_ij: differences
                                   our own error estimate cannot explain (-1
                                   without E) */
    double max_own_err;         /* max E_ij / max(|F_ij|, floor): the smallest
                                   e this comparison can resolve (NaN without E) */
    rad_ffcmp_pair *worst;      /* the nworst largest e > 0, largest first */
    int nworst_found;
    rad_ffcmp_row *rows;        /* one per row, the largest max first */
    long hist[RAD_FFCMP_BINS], hist_zero, hist_over;
    /* closure: row sums, and the largest |1 - sum| (meaningful where the
     * scene is closed: our own row sums say whether it is) */
    double closure_ours, closure_theirs;
    int closure_ours_row, closure_theirs_row;
    double max_rowsum_diff;     /* max_i |sum_j G_ij - sum_j F_ij| */
    int rowsum_diff_row;
    /* reciprocity of G: d_ij = |A_i G_ij - A_j G_ji|, for i < j; its
     * largest value, and the largest d_ij / max(A_i |G_ij|, A_j |G_ji|) */
    double recip_abs, recip_rel;
    int recip_abs_i, recip_abs_j, recip_rel_i, recip_rel_j;
} rad_ffcmp;

/* Compare G with F (errors E, may be NULL), areas A: fill c's outputs.
 * RAD_ERR_NOMEM, or RAD_OK.  Free with radi_ffcmp_free. */
rad_status radi_ffcmp_run(rad_ffcmp *c, const double *G, const double *F, const double *E,
                         const double *A, int n, rad_error *err);
void radi_ffcmp_free(rad_ffcmp *c);

/* The lower edge of histogram bin b: 10^(RAD_FFCMP_LOG_LO + b BIN). */
double radi_ffcmp_bin_edge(int b);

#endif /* RAD_FFCOMPARE_H */
