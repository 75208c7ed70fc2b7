/* lu_rate.c -- LU factorisation rate against the DGEMM rate, same run.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * For each N given (default 2000 4000): time DGEMM (2 N^3 flops), DGETRF
 * (2/3 N^3 flops) and DPOTRF (1/3 N^3 flops, on the upper triangle of the
 * same matrix, symmetric by that reading and diagonally dominant, so
 * positive definite) on a radiosity-like matrix I - 0.5 F with F random
 * and row-stochastic, best of 3 runs each, and print GFLOP/s, their ratio
 * to DGEMM's, and how many times faster Cholesky is than LU.
 * A benchmark, not a test: the machine is shared and noisy.
 */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "util/lapack.h"
#include "solve/lu.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void fill(double *A, int n, unsigned seed)
{
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            seed = seed * 1103515245u + 12345u;
            A[(size_t)i + (size_t)j * n] = -0.5 * ((seed >> 8) & 0xffff) / 65536.0 / n;
        }
    for (int i = 0; i < n; i++)
        A[(size_t)i + (size_t)i * n] += 1;
}

int main(int argc, char **argv)
{
    int sizes[8] = {2000, 4000}, ns = 2;
    if (argc > 1) {
        ns = 0;
        for (int k = 1; k < argc && ns < 8; k++)
            sizes[ns++] = atoi(argv[k]);
    }
    printf("N\tdgemm_gflops\tdgetrf_gflops\tratio\tblocked_lu_gflops\tratio\t"
           "dpotrf_gflops\tratio\tlu_time/cholesky_time\n");
    for (int s = 0; s < ns; s++) {
        const int n = sizes[s];
        double *A = malloc(sizeof *A * (size_t)n * n), *B = malloc(sizeof *B * (size_t)n * n);
        double *C = malloc(sizeof *C * (size_t)n * n);
        int *ipiv = malloc(sizeof *ipiv * (size_t)n), info;
        if (!A || !B || !C || !ipiv)
            return 1;
        const double one = 1, zero = 0;
        double best_mm = 1e300, best_lu = 1e300, best_bl = 1e300, best_ch = 1e300;
        fill(A, n, 1);
        fill(B, n, 2);
        for (int r = 0; r < 3; r++) {
            double t0 = now();
            dgemm_("N", "N", &n, &n, &n, &one, A, &n, B, &n, &zero, C, &n, 1, 1);
            double t1 = now();
            best_mm = t1 - t0 < best_mm ? t1 - t0 : best_mm;
            fill(C, n, 3);
            t0 = now();
            dgetrf_(&n, &n, C, &n, ipiv, &info);
            t1 = now();
            best_lu = t1 - t0 < best_lu ? t1 - t0 : best_lu;
            fill(C, n, 3);
            int stopped;
            t0 = now();
            radi_lu_factor(n, C, ipiv, NULL, NULL, "lu", &stopped);
            t1 = now();
            best_bl = t1 - t0 < best_bl ? t1 - t0 : best_bl;
            fill(C, n, 3);
            t0 = now();
            dpotrf_("U", &n, C, &n, &info, 1);
            t1 = now();
            best_ch = t1 - t0 < best_ch ? t1 - t0 : best_ch;
        }
        double mm = 2.0 * n * n * (double)n / best_mm / 1e9;
        double lu = 2.0 / 3.0 * n * n * (double)n / best_lu / 1e9;
        double bl = 2.0 / 3.0 * n * n * (double)n / best_bl / 1e9;
        double ch = 1.0 / 3.0 * n * n * (double)n / best_ch / 1e9;
        printf("%d\t%.1f\t%.1f\t%.2f\t%.1f\t%.2f\t%.1f\t%.2f\t%.2f\n", n, mm, lu, lu / mm, bl,
               bl / mm, ch, ch / mm, best_lu / best_ch);
        fflush(stdout);
        free(A);
        free(B);
        free(C);
        free(ipiv);
    }
    return 0;
}
