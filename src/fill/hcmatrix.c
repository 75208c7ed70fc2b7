/* hcmatrix.c -- the form-factor matrix by hemicubes, rows in parallel.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * rad_ff_matrix with opt->method = RAD_FF_HEMICUBE comes here.  Each row
 * F_i. is one hemicube on element i's centre (hemicube.c), independent of
 * every other row, so the rows are shared among OpenMP threads
 * dynamically, each thread with its own row buffer; the item buffers are
 * the renderer's, made per face and freed (render.h is re-entrant).  As
 * in the contour's fill (ffmatrix.c) the geometry is first moved and
 * scaled by a power of two into [-1, 1]^3 (radi_mesh_normalized): F does
 * not depend on the unit of length, and the renderer's near plane and
 * tolerances are then those of a scene of size 1.  Blocks of rows
 * separate the progress calls.
 *
 * Unlike the contour's F, a row here is not mirrored: F_ij comes from i's
 * centre and F_ji from j's, so reciprocity A_i F_ij = A_j F_ji holds only
 * as far as both are accurate (Cohen & Greenberg 1985 solved with such an
 * F; so does `solve --form-factors-method hemicube`).  The hemicube has
 * no error estimate: errest (if given) gets NaN off the diagonal, the
 * statistics no promise.
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
#endif

#include "fill/ffblock.h"
#include "hemicube/hemicube.h"
#include "mesh/mesh.h"
#include "util/util.h"

/* Rows [i0, i1) into F, in parallel; returns the first failure. */
static rad_status fill_rows(const rad_hemicube *hc, int i0, int i1, int threads, double *rows,
                            double *F, rad_error *err)
{
    const int n = radi_hemicube_elements(hc);
    rad_status st = RAD_OK;
    int failed = 0; /* read by every thread, so atomically */
#pragma omp parallel num_threads(threads)
    {
        double *row = rows + (size_t)omp_get_thread_num() * (size_t)n;
        rad_error my;
#pragma omp for schedule(dynamic, 1)
        for (int i = i0; i < i1; i++) {
            int stop;
#pragma omp atomic read
            stop = failed;
            if (stop)
                continue;
            rad_status s = radi_hemicube_row(hc, i, row, &my);
            if (s != RAD_OK) {
#pragma omp critical(rad_hcmatrix_fail)
                if (st == RAD_OK) {
                    st = s;
                    if (err)
                        *err = my;
#pragma omp atomic write
                    failed = 1;
                }
                continue;
            }
            for (int j = 0; j < n; j++)
                F[(size_t)i + (size_t)j * n] = row[j];
        }
    }
    return st;
}

static rad_status fill(const rad_hemicube *hc, const rad_ff_options *opt, double *F,
                       rad_error *err)
{
    const int n = radi_hemicube_elements(hc);
    int threads = opt->threads > 0 ? opt->threads : omp_get_max_threads();
    /* each thread holds one picture at a time (R = 4096: 640 MiB): as
     * many threads as fit in the memory allowed (radi_hemicube_create saw
     * that one does), not an out-of-memory kill halfway */
    const double one = radi_hemicube_row_bytes(hc) + 8.0 * n, limit = rad_memory_limit();
    if (limit > 0 && threads > 1 && threads * one > limit)
        threads = limit / one >= 1 ? (int)(limit / one) : 1;
    rad_status st = RAD_OK;
    double *rows = malloc(sizeof *rows * (size_t)threads * (size_t)(n ? n : 1));
    if (!rows)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d hemicube rows", threads);
    const int block = n / 50 > 16 ? n / 50 : 16;
    for (int i0 = 0; i0 < n && st == RAD_OK; i0 += block) {
        const int i1 = i0 + block < n ? i0 + block : n;
        st = fill_rows(hc, i0, i1, threads, rows, F, err);
        if (st == RAD_OK && opt->progress &&
            opt->progress(opt->progress_user, "hemicubes", i1, n))
            st = radi_fail(err, RAD_ERR_INVALID, "interrupted");
    }
    free(rows);
    return st;
}

rad_status radi_hemicube_matrix(const rad_mesh *m, const rad_ff_options *opt, double *F,
                               double *errest, rad_ff_stats *stats, rad_error *err)
{
    const int n = m->nelements;
    rad_mesh unit;
    rad_hemicube *hc = NULL;
    rad_status st = radi_mesh_normalized(m, &unit, NULL, err);
    if (st != RAD_OK)
        return st;
    st = radi_hemicube_create(&hc, &unit, opt->resolution, err);
    if (st == RAD_OK)
        st = fill(hc, opt, F, err);
    radi_hemicube_free(hc);
    rad_mesh_free(&unit);
    if (st != RAD_OK)
        return st;
    if (errest)
        for (size_t k = 0; k < (size_t)n * n; k++)
            errest[k] = k % ((size_t)n + 1) == 0 ? 0 : NAN;
    if (stats) {
        memset(stats, 0, sizeof *stats);
        radi_ff_fill_stats(F, n, stats);
        stats->max_errest = stats->max_relerr = stats->max_row_error = NAN;
        stats->promise = NAN;
    }
    return RAD_OK;
}
