/* ff_rate.c -- form-factor fill rate of a scene, in unordered pairs/s.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Usage: ff_rate SCENE NxM [REPEATS [MODE]]
 * For 1 and 2 threads, fills the form-factor matrix REPEATS times (default
 * 5) in each accuracy mode (or MODE only), the modes taking turns within
 * each round so that a slow spell of the machine falls on all of them, and
 * prints per mode the median and best rate (N(N-1)/2 pairs per second of
 * wall time), the median rate per second of CPU time summed over threads,
 * and the worst row-sum deviation from 1; then the ratios of the median
 * times of default and reference to classic.
 * Only rad_ff_matrix is timed: no parsing, no solve, no output.  A
 * benchmark, not a test: the machine is shared and noisy, hence medians.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "util/lapack.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* sorts x[0..n) and returns its median */
static double median(double *x, int n)
{
    qsort(x, (size_t)n, sizeof *x, cmp);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

static double row_dev(const double *F, int n)
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double s = 0;
        for (int j = 0; j < n; j++)
            s += F[(size_t)i + (size_t)j * n];
        worst = fmax(worst, fabs(s - 1));
    }
    return worst;
}

int main(int argc, char **argv)
{
    static const char *names[] = {"classic", "default", "reference"};
    rad_scene scene;
    rad_mesh mesh;
    rad_error err;
    int nx = 20, ny = 20, reps = argc > 3 ? atoi(argv[3]) : 5;
    radi_blas_park_threads(); /* OpenBLAS's spinning threads would take a core */
    if (argc < 3 || sscanf(argv[2], "%dx%d", &nx, &ny) != 2 || reps < 1 || reps > 100) {
        fprintf(stderr, "usage: ff_rate SCENE NxM [REPEATS [MODE]]\n");
        return 2;
    }
    if (rad_scene_load(&scene, argv[1], &err) != RAD_OK) {
        fprintf(stderr, "ff_rate: %s\n", err.message);
        return 1;
    }
    rad_scene_set_mesh(&scene, nx, ny);
    if (rad_mesh_build(&mesh, &scene, &err) != RAD_OK) {
        fprintf(stderr, "ff_rate: %s\n", err.message);
        return 1;
    }
    const int n = mesh.nelements;
    const double pairs = 0.5 * (double)n * (n - 1);
    double *F = malloc(sizeof *F * (size_t)n * (size_t)n);
    if (!F)
        return 1;
    printf("accuracy\tthreads\tmedian_pairs_per_second\tbest_pairs_per_second\tmedian_seconds\t"
           "pairs_per_cpu_second\tmax_row_sum_error\n");
    for (int threads = 1; threads <= 2; threads++) {
        double med[3] = {NAN, NAN, NAN}, worst[3] = {0, 0, 0};
        static double t[3][100], cpu[3][100];
        for (int r = 0; r < reps; r++)
            for (int acc = 0; acc < 3; acc++) {
                if (argc > 4 && strcmp(argv[4], names[acc]) != 0)
                    continue;
                rad_ff_options opt;
                rad_ff_options_init(&opt);
                opt.accuracy = (rad_accuracy)acc;
                opt.threads = threads;
                double t0 = now(), c0 = cpu_now();
                if (rad_ff_matrix(&mesh, &opt, F, NULL, NULL, &err) != RAD_OK) {
                    fprintf(stderr, "ff_rate: %s\n", err.message);
                    return 1;
                }
                t[acc][r] = now() - t0;
                cpu[acc][r] = cpu_now() - c0;
                if (r == 0)
                    worst[acc] = row_dev(F, n);
            }
        for (int acc = 0; acc < 3; acc++) {
            if (argc > 4 && strcmp(argv[4], names[acc]) != 0)
                continue;
            med[acc] = median(t[acc], reps);
            double cmed = median(cpu[acc], reps);
            printf("%s\t%d\t%.3g\t%.3g\t%.4f\t%.3g\t%.2g\n", names[acc], threads, pairs / med[acc],
                   pairs / t[acc][0], med[acc], pairs / cmed, worst[acc]);
        }
        if (!isnan(med[0]))
            printf("# %d thread%s: median time of default / classic %.3f, reference / classic %.3f\n",
                   threads, threads > 1 ? "s" : "", med[1] / med[0], med[2] / med[0]);
        fflush(stdout);
    }
    free(F);
    rad_mesh_free(&mesh);
    rad_scene_free(&scene);
    return 0;
}
