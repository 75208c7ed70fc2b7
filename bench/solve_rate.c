/* solve_rate.c -- the solve phase of every solver on one form-factor matrix.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Usage: solve_rate SCENE NxM [REPEATS [SOLVER...]]
 * Fills F once (default accuracy), then in each of REPEATS rounds (default
 * 3) runs rad_solve with every SOLVER in turn (default gauss cholesky
 * jacobi gauss-seidel cg), so that a slow spell of the shared machine falls
 * on all of them, and prints per solver the median and best wall time, the
 * median CPU time (all threads), sweeps or factorisations, the error bound
 * the solver reports, and how far its B is from the first solver's
 * (max |B - B_1| / max |B_1| over the three bands); then the ratio of the
 * first two solvers' median times.  Only rad_solve is timed, which
 * includes its diagnostics (residual, energy balance: two passes over F).
 * A benchmark, not a test: the machine is shared and noisy, hence medians.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"

#define MAX_SOLVERS 8
#define MAX_REPEATS 31

static const char *const names[] = {"gauss",       "jacobi",   "gauss-seidel",
                                    "progressive", "cholesky", "cg"};

static double clock_of(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *x, int n)
{
    qsort(x, (size_t)n, sizeof *x, cmp);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

static int solver_of(const char *s)
{
    for (int k = 0; k < (int)(sizeof names / sizeof *names); k++)
        if (strcmp(s, names[k]) == 0)
            return k;
    return -1;
}

typedef struct run {
    int solver;
    double wall[MAX_REPEATS], cpu[MAX_REPEATS];
    double *B;
    rad_solve_report rep;
    rad_status st;
} run;

static int setup(const char *path, const char *mesh, rad_scene *s, rad_mesh *m, double **F,
                 double *row_error)
{
    rad_error err;
    rad_ff_options fo;
    rad_ff_stats stats;
    int a, b;
    if (sscanf(mesh, "%dx%d", &a, &b) != 2 || rad_scene_load(s, path, &err))
        return fprintf(stderr, "solve_rate: cannot read %s (%s)\n", path, err.message), 1;
    rad_scene_set_mesh(s, a, b);
    if (rad_mesh_build(m, s, &err))
        return fprintf(stderr, "solve_rate: %s\n", err.message), 1;
    const size_t n = (size_t)m->nelements;
    *F = malloc(sizeof **F * n * n);
    rad_ff_options_init(&fo);
    double t0 = clock_of(CLOCK_MONOTONIC);
    if (!*F || rad_ff_matrix(m, &fo, *F, NULL, &stats, &err))
        return fprintf(stderr, "solve_rate: form factors: %s\n", *F ? err.message : "no memory"), 1;
    printf("# %s %s: %zu elements, form factors %.1f s\n", path, mesh, n,
           clock_of(CLOCK_MONOTONIC) - t0);
    *row_error = stats.max_row_error;
    return 0;
}

/* one row; r->wall sorted */
static void report(run *r, int reps, const run *first, size_t n3)
{
    double dm = 0, vm = 0;
    for (size_t k = 0; k < n3; k++) {
        dm = fmax(dm, fabs(r->B[k] - first->B[k]));
        vm = fmax(vm, fabs(first->B[k]));
    }
    const double best = r->wall[0];
    printf("%s\t%s\t%.3f\t%.3f\t%.3f\t%d\t%d\t%.3g\t%.3g\t%s\n", names[r->solver],
           r->st == RAD_OK ? "ok" : rad_strstatus(r->st), median(r->wall, reps), best,
           median(r->cpu, reps), r->rep.systems, r->rep.sweeps, r->rep.error_bound,
           vm > 0 ? dm / vm : dm, r->rep.fallbacks ? r->rep.fallback : "-");
}

int main(int argc, char **argv)
{
    rad_scene s;
    rad_mesh m;
    double *F, row_error;
    run runs[MAX_SOLVERS];
    int nr = 0, reps = argc > 3 ? atoi(argv[3]) : 3;
    if (argc < 3 || reps < 1 || reps > MAX_REPEATS) {
        fprintf(stderr, "usage: solve_rate SCENE NxM [REPEATS [SOLVER...]]\n");
        return 2;
    }
    const char *deflt[] = {"gauss", "cholesky", "jacobi", "gauss-seidel", "cg"};
    const int ns = argc > 4 ? argc - 4 : 5;
    for (int k = 0; k < ns && nr < MAX_SOLVERS; k++) {
        int v = solver_of(argc > 4 ? argv[4 + k] : deflt[k]);
        if (v < 0)
            return fprintf(stderr, "solve_rate: unknown solver\n"), 2;
        memset(&runs[nr], 0, sizeof runs[nr]);
        runs[nr++].solver = v;
    }
    if (setup(argv[1], argv[2], &s, &m, &F, &row_error))
        return 1;
    const size_t n3 = (size_t)m.nelements * RAD_BANDS;
    for (int k = 0; k < nr; k++)
        if (!(runs[k].B = malloc(sizeof *runs[k].B * n3)))
            return 1;
    for (int r = 0; r < reps; r++)
        for (int k = 0; k < nr; k++) {
            rad_solve_options o;
            rad_error err;
            rad_solve_options_init(&o);
            o.solver = (rad_solver)runs[k].solver;
            o.ff_row_error = row_error; /* as the pipeline does */
            double w0 = clock_of(CLOCK_MONOTONIC), c0 = clock_of(CLOCK_PROCESS_CPUTIME_ID);
            runs[k].st = rad_solve(&m, F, &o, runs[k].B, &runs[k].rep, &err);
            runs[k].wall[r] = clock_of(CLOCK_MONOTONIC) - w0;
            runs[k].cpu[r] = clock_of(CLOCK_PROCESS_CPUTIME_ID) - c0;
        }
    printf("solver\tstatus\tmedian_s\tbest_s\tmedian_cpu_s\tsystems\tsweeps\terror_bound\t"
           "vs_%s\tfallback\n", names[runs[0].solver]);
    double med[MAX_SOLVERS];
    for (int k = 0; k < nr; k++) {
        double w[MAX_REPEATS];
        memcpy(w, runs[k].wall, sizeof w);
        med[k] = median(w, reps);
        qsort(runs[k].wall, (size_t)reps, sizeof *runs[k].wall, cmp);
        report(&runs[k], reps, &runs[0], n3);
    }
    if (nr > 1)
        printf("# %s / %s median time: %.2f\n", names[runs[0].solver], names[runs[1].solver],
               med[0] / med[1]);
    for (int k = 0; k < nr; k++)
        free(runs[k].B);
    free(F);
    rad_mesh_free(&m);
    rad_scene_free(&s);
    return 0;
}
