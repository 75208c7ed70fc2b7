/* lu.c -- LU factorisation with partial pivoting, in column blocks so that
 * progress can be reported between them.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The right-looking blocked algorithm of LAPACK's dgetrf (Golub & Van Loan,
 * Matrix Computations, 4th ed., algorithm 3.4.2 in block form; Anderson et
 * al., LAPACK Users' Guide, 3rd ed., section 3.4.1): for each block column
 * of width nb,
 *   1. factor the panel A[k:n, k:k+nb] = P L U (dgetrf on the panel),
 *   2. apply its row interchanges to the columns left and right of it
 *      (dlaswp),
 *   3. U12 = L11^-1 A12 (dtrsm, unit lower triangular),
 *   4. A22 = A22 - L21 U12 (dgemm: almost all of the 2/3 n^3 flops).
 * The result and the pivots are those dgetrf defines (same storage), so
 * dgetrs and dgecon apply unchanged.  Between blocks the progress callback
 * receives the share of the flops done.  Small matrices go to dgetrf in one
 * call.
 */
#include <config.h>

#include "util/util.h"
#include "solve/lu.h"

#define LU_BLOCK 256
#define LU_BLOCKED_MIN 2048

/* flops of LU up to column k of n: sum of 2 (n - j)^2 for j < k, roughly */
static double lu_flops_done(double n, double k)
{
    return (2.0 / 3.0) * (n * n * n - (n - k) * (n - k) * (n - k));
}

int radi_lu_factor(int n, double *A, int *ipiv, rad_progress_fn progress, void *user,
                  const char *stage, int *stopped)
{
    int info = 0, first = 0;
    *stopped = 0;
    if (n < LU_BLOCKED_MIN) {
        dgetrf_(&n, &n, A, &n, ipiv, &info);
        return info;
    }
    const double one = 1, minus_one = -1;
    const int inc = 1;
    const double total = lu_flops_done(n, n);
    for (int k = 0; k < n; k += LU_BLOCK) {
        int b = n - k < LU_BLOCK ? n - k : LU_BLOCK, m = n - k;
        double *panel = A + (size_t)k + (size_t)k * n;
        dgetrf_(&m, &b, panel, &n, ipiv + k, &info);
        if (info > 0 && first == 0)
            first = info + k;
        for (int i = k; i < k + b; i++)
            ipiv[i] += k; /* panel pivots to global (1-based) rows */
        int k1 = k + 1, k2 = k + b;
        if (k > 0)
            dlaswp_(&k, A, &n, &k1, &k2, ipiv, &inc);
        int rest = n - k - b;
        if (rest > 0) {
            double *a12 = A + (size_t)k + (size_t)(k + b) * n;
            dlaswp_(&rest, A + (size_t)(k + b) * n, &n, &k1, &k2, ipiv, &inc);
            dtrsm_("L", "L", "N", "U", &b, &rest, &one, panel, &n, a12, &n, 1, 1, 1, 1);
            dgemm_("N", "N", &rest, &rest, &b, &minus_one, panel + b, &n, a12, &n, &one,
                   A + (size_t)(k + b) + (size_t)(k + b) * n, &n, 1, 1);
        }
        if (progress && progress(user, stage, lu_flops_done(n, k + b), total)) {
            *stopped = 1;
            return first;
        }
    }
    return first;
}
