/* fpass.c -- passes over the form-factor matrix at the speed of memory.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A product F X with X of three columns does 6 flops per 8 bytes of F
 * read, so it runs at the memory's rate, not the cores': the aim is to
 * read every entry of F once, from contiguous columns, and to keep what is
 * written (H, n x 3, 24 n bytes) in cache.  DGEMM with three columns packs
 * panels of F into a buffer first; on this project's 15,000-element cube
 * a product took 0.5 s with OpenBLAS against 0.25 s with the loop below
 * (two threads), which reads F straight through.
 *
 *   radi_fpass_mul       H = F X.  Each thread takes a contiguous range of
 *                       columns and accumulates H_t = F(:, J_t) X(J_t, :)
 *                       four columns at a time (axpy form, which the
 *                       compiler vectorises without reordering sums); the
 *                       H_t are added at the end.
 *   radi_fpass_dot_cols  dot products of whole columns with W, for
 *                       Gauss-Seidel on a reciprocal F (iterate.c).
 *   radi_fscan_run       one tiled pass: row sums of |F| split at the
 *                       diagonal (the contraction factors of Jacobi and
 *                       Gauss-Seidel, iterate.c) and the reciprocity
 *                       defect (the symmetric form needs it: cholesky.c,
 *                       cg.c).  A pair (i, j) and its mirror (j, i) lie in
 *                       two T x T tiles that are read together, so the
 *                       strided one stays in the level-1 cache.
 * Sums in the dot products are reordered by `omp simd reduction` (several
 * partial sums): the result differs from the sequential sum by round-off
 * within the usual bound, |error| <= gamma_n sum |F_ji W_j| (Higham 2002,
 * eq. 3.5).
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#else
#define omp_get_max_threads() 1
#define omp_get_thread_num() 0
#define omp_get_num_threads() 1
#endif

#include "solve/fpass.h"

#define PAR_MIN 512 /* below this n one thread does the product */
#define TILE 32

/* h += F(:, j0:j1) X(j0:j1, :), h n x 3 */
#if defined(HAVE_ATTRIBUTE_TARGET_CLONES)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
static void mul_cols(int n, const double *F, const double *X, int j0, int j1, double *h)
{
    int j = j0;
    for (; j + 4 <= j1; j += 4) {
        const double *c0 = F + (size_t)j * n, *c1 = c0 + n, *c2 = c1 + n, *c3 = c2 + n;
        for (int b = 0; b < RAD_BANDS; b++) {
            const double *x = X + (size_t)b * n + j;
            const double x0 = x[0], x1 = x[1], x2 = x[2], x3 = x[3];
            double *hb = h + (size_t)b * n;
#pragma omp simd
            for (int i = 0; i < n; i++)
                hb[i] += c0[i] * x0 + c1[i] * x1 + c2[i] * x2 + c3[i] * x3;
        }
    }
    for (; j < j1; j++) {
        const double *c0 = F + (size_t)j * n;
        for (int b = 0; b < RAD_BANDS; b++) {
            const double x0 = X[(size_t)b * n + j];
            double *hb = h + (size_t)b * n;
#pragma omp simd
            for (int i = 0; i < n; i++)
                hb[i] += c0[i] * x0;
        }
    }
}

int radi_fpass_mul(int n, const double *F, const double *X, double *H)
{
    const size_t n3 = (size_t)n * RAD_BANDS;
    const int nt = n >= PAR_MIN ? omp_get_max_threads() : 1;
    if (nt <= 1) {
        memset(H, 0, sizeof *H * n3);
        mul_cols(n, F, X, 0, n, H);
        return 0;
    }
    double *acc = malloc(sizeof *acc * n3 * (size_t)nt);
    if (!acc)
        return -1;
#pragma omp parallel num_threads(nt)
    {
        const int t = omp_get_thread_num(), tn = omp_get_num_threads();
        double *h = acc + n3 * (size_t)t;
        memset(h, 0, sizeof *h * n3);
        mul_cols(n, F, X, (int)((long long)n * t / tn), (int)((long long)n * (t + 1) / tn), h);
#pragma omp barrier
#pragma omp for schedule(static)
        for (size_t k = 0; k < n3; k++) {
            double s = 0;
            for (int u = 0; u < tn; u++)
                s += acc[k + n3 * (size_t)u];
            H[k] = s;
        }
    }
    free(acc);
    return 0;
}

#if defined(HAVE_ATTRIBUTE_TARGET_CLONES)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
static void dot_col(int n, const double *c, const double *W, double *d, int ld)
{
    double s0 = 0, s1 = 0, s2 = 0;
    const double *w0 = W, *w1 = W + n, *w2 = W + 2 * (size_t)n;
#pragma omp simd reduction(+ : s0, s1, s2)
    for (int j = 0; j < n; j++) {
        s0 += c[j] * w0[j];
        s1 += c[j] * w1[j];
        s2 += c[j] * w2[j];
    }
    d[0] = s0;
    d[ld] = s1;
    d[2 * (size_t)ld] = s2;
}

void radi_fpass_dot_cols(int n, const double *F, int c0, int c1, const double *W, double *D,
                        int ld)
{
#pragma omp parallel for schedule(static) if (n >= PAR_MIN)
    for (int i = c0; i < c1; i++)
        dot_col(n, F + (size_t)i * n, W, D + (i - c0), ld);
}

/* ---- the scan ------------------------------------------------------------- */

typedef struct scan_acc {
    double *lo, *up;
    double defect;
    int di, dj;
} scan_acc;

/* Tiles (I, J) and (J, I), rows [i0, i1) and columns [j0, j1), i0 <= j0. */
static void scan_tiles(int n, const double *F, const double *area, int i0, int i1, int j0,
                       int j1, scan_acc *a)
{
    for (int j = j0; j < j1; j++)
        for (int i = i0; i < i1 && i <= j; i++) {
            const double fij = F[(size_t)i + (size_t)j * n]; /* i <= j: upper */
            if (i == j) {
                a->up[i] += fabs(fij);
                continue;
            }
            const double fji = F[(size_t)j + (size_t)i * n];
            a->up[i] += fabs(fij);
            a->lo[j] += fabs(fji);
            const double x = area[i] * fij, y = area[j] * fji, big = fmax(fabs(x), fabs(y));
            const double d = big > 0 ? fabs(x - y) / big : x == y ? 0 : INFINITY;
            if (d > a->defect || d != d) {
                a->defect = d != d ? INFINITY : d;
                a->di = i;
                a->dj = j;
            }
        }
}

int radi_fscan_run(int n, const double *F, const double *area, rad_fscan *s)
{
    const int nt = n >= PAR_MIN ? omp_get_max_threads() : 1;
    const size_t nn = (size_t)(n > 0 ? n : 1);
    memset(s, 0, sizeof *s);
    s->di = s->dj = -1;
    double *buf = calloc(2 * nn * (size_t)nt, sizeof *buf);
    s->lower = calloc(nn, sizeof *s->lower);
    s->upper = calloc(nn, sizeof *s->upper);
    if (!buf || !s->lower || !s->upper) {
        free(buf);
        radi_fscan_free(s);
        return -1;
    }
#pragma omp parallel num_threads(nt)
    {
        const int t = omp_get_thread_num();
        scan_acc a = {buf + 2 * nn * (size_t)t, buf + 2 * nn * (size_t)t + nn, 0, -1, -1};
#pragma omp for schedule(dynamic, 1)
        for (int j0 = 0; j0 < n; j0 += TILE) /* tile column J, tiles I <= J */
            for (int i0 = 0; i0 <= j0; i0 += TILE)
                scan_tiles(n, F, area, i0, i0 + TILE < n ? i0 + TILE : n, j0,
                           j0 + TILE < n ? j0 + TILE : n, &a);
#pragma omp critical
        if (a.defect > s->defect || (a.di >= 0 && s->di < 0)) {
            s->defect = a.defect;
            s->di = a.di;
            s->dj = a.dj;
        }
    }
    for (int u = 0; u < nt; u++) {
        const double *lo = buf + 2 * nn * (size_t)u, *up = lo + nn;
        for (int i = 0; i < n; i++) {
            s->lower[i] += lo[i];
            s->upper[i] += up[i];
        }
    }
    free(buf);
    return 0;
}

void radi_fscan_free(rad_fscan *s)
{
    free(s->lower);
    free(s->upper);
    s->lower = s->upper = NULL;
}
