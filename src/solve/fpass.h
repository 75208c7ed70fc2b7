/* fpass.h -- one pass over the form-factor matrix (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The iterative solvers are bound by memory: each sweep must read F (8 n^2
 * bytes) once for all three bands, and nothing else of size n^2.  These
 * are the passes they are built from (fpass.c).  F is n x n column-major,
 * F[i + j*n] = F_ij; X, H, W are n x RAD_BANDS column-major.
 */
#ifndef RAD_FPASS_H
#define RAD_FPASS_H

#include "radiosity/base.h"

/* Reciprocity A_i F_ij = A_j F_ji holds to this relative defect or better
 * where the symmetric form is used.  The fill makes it hold to two
 * roundings (ffmatrix.c: F_ij = F_ji A_j / A_i); 1e-12 also admits a
 * matrix written and read back with 13 or more significant digits, and
 * perturbs each entry by at most 1e-12 relative, B by cond * 1e-12. */
#define RAD_RECIPROCITY_TOL 1e-12

/* H = F X for the three bands: one pass over F.  0, or -1 when the
 * per-thread accumulators could not be allocated. */
int radi_fpass_mul(int n, const double *F, const double *X, double *H);

/* D[k + b*ld] = sum_j F_ji W[j + b*n] for the columns i = c0 + k in
 * [c0, c1): dot products down contiguous columns of F, in parallel. */
void radi_fpass_dot_cols(int n, const double *F, int c0, int c1, const double *W, double *D,
                        int ld);

/* What one tiled pass over F finds. */
typedef struct rad_fscan {
    double *lower;      /* n: sum_{j<i} |F_ij| */
    double *upper;      /* n: sum_{j>=i} |F_ij| (the diagonal counts here) */
    double defect;      /* max over pairs of |A_i F_ij - A_j F_ji| / max(|.|, |.|) */
    int di, dj;         /* the pair where it is largest (-1 if none) */
} rad_fscan;

/* Scan F with the element areas: row sums split at the diagonal and the
 * reciprocity defect.  0, or -1 out of memory.  radi_fscan_free after. */
int radi_fscan_run(int n, const double *F, const double *area, rad_fscan *s);
void radi_fscan_free(rad_fscan *s);

#endif /* RAD_FPASS_H */
