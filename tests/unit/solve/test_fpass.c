/* test_fpass.c -- the passes over F (fpass.c) against plain loops.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Independent references: the product and the column dot products by the
 * textbook loops, in long double; the scan's row sums and reciprocity
 * defect of a matrix built here to be reciprocal, with one pair spoiled by
 * a known amount.  Sizes cross the parallel threshold (512) and are not
 * multiples of the tile (32) or of the four-column step.  Tolerances: a
 * sum of n products in any order is within gamma_n sum |terms| of the
 * exact one (Higham 2002, eq. 3.5): we allow n eps sum |terms|.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "solve/fpass.h"
#include "radiosity/base.h"
#include "../tap.h"

static unsigned seed = 12345;

static double uniform(void)
{
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 8) & 0xffffff) / 16777216.0;
}

/* A reciprocal "form-factor" matrix: S symmetric >= 0, F_ij = S_ij / A_i. */
static void make_f(int n, double *F, double *area)
{
    for (int i = 0; i < n; i++)
        area[i] = 0.5 + uniform();
    for (int j = 0; j < n; j++)
        for (int i = 0; i <= j; i++) {
            const double sij = i == j ? 0 : uniform() / n;
            F[i + (size_t)j * n] = sij / area[i];
            F[j + (size_t)i * n] = sij / area[j];
        }
}

static void test_mul(int n)
{
    double *F = malloc(sizeof *F * (size_t)n * n), *area = malloc(sizeof *area * n);
    double *X = malloc(sizeof *X * 3 * n), *H = malloc(sizeof *H * 3 * n);
    double *D = malloc(sizeof *D * 3 * n);
    make_f(n, F, area);
    for (int k = 0; k < 3 * n; k++)
        X[k] = uniform() - 0.25;
    int st = radi_fpass_mul(n, F, X, H);
    radi_fpass_dot_cols(n, F, 7, n - 3, X, D, n);
    double worst_mul = 0, worst_dot = 0;
    for (int b = 0; b < 3; b++)
        for (int i = 0; i < n; i++) {
            long double h = 0, d = 0, mag = 0, magd = 0;
            for (int j = 0; j < n; j++) {
                h += (long double)F[i + (size_t)j * n] * X[j + (size_t)b * n];
                mag += fabs(F[i + (size_t)j * n] * X[j + (size_t)b * n]);
                d += (long double)F[j + (size_t)i * n] * X[j + (size_t)b * n];
                magd += fabs(F[j + (size_t)i * n] * X[j + (size_t)b * n]);
            }
            worst_mul = fmax(worst_mul, fabs(H[i + (size_t)b * n] - (double)h) / (n * DBL_EPSILON * (double)mag));
            if (i >= 7 && i < n - 3)
                worst_dot = fmax(worst_dot, fabs(D[i - 7 + (size_t)b * n] - (double)d) /
                                                (n * DBL_EPSILON * (double)magd));
        }
    tap_ok(st == 0 && worst_mul <= 1, "n = %d: F X within n eps sum|F X| (%.3g of it)", n,
           worst_mul);
    tap_ok(worst_dot <= 1, "n = %d: column dots within n eps sum|F W| (%.3g of it)", n,
           worst_dot);
    free(F);
    free(area);
    free(X);
    free(H);
    free(D);
}

static void test_scan(int n)
{
    double *F = malloc(sizeof *F * (size_t)n * n), *area = malloc(sizeof *area * n);
    rad_fscan sc;
    make_f(n, F, area);
    for (int i = 0; i < n; i++)
        F[i + (size_t)i * n] = 0.125; /* the diagonal counts in `upper` */
    int st = radi_fscan_run(n, F, area, &sc);
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double lo = 0, up = 0;
        for (int j = 0; j < n; j++)
            *(j < i ? &lo : &up) += fabs(F[i + (size_t)j * n]);
        worst = fmax(worst, fmax(fabs(sc.lower[i] - lo), fabs(sc.upper[i] - up)) /
                                (n * DBL_EPSILON * (lo + up)));
    }
    /* F_ji = S_ij / A_j: A_i F_ij and A_j F_ji differ by the rounding of
     * the two divisions and the two products, 4 eps at most */
    tap_ok(st == 0 && worst <= 1 && sc.defect <= 4 * DBL_EPSILON,
           "n = %d: scan row sums within n eps (%.3g of it), reciprocal (defect %.3g)", n, worst,
           sc.defect);
    radi_fscan_free(&sc);
    const int i = n / 3, j = n - 2;
    F[j + (size_t)i * n] *= 1 + 1e-7; /* spoil (j, i) */
    radi_fscan_run(n, F, area, &sc);
    tap_ok(fabs(sc.defect - 1e-7) <= 1e-7 * 1e-6 && sc.di == i && sc.dj == j,
           "n = %d: a pair spoiled by 1e-7 is found: defect %.9g at (%d, %d)", n, sc.defect,
           sc.di, sc.dj);
    radi_fscan_free(&sc);
    free(F);
    free(area);
}

int main(void)
{
    test_mul(37);
    test_mul(601);
    test_scan(37);
    test_scan(601);
    return tap_done();
}
