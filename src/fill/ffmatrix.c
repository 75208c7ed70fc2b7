/* ffmatrix.c -- the form-factor matrix of a mesh, filled in parallel.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * F is n x n, column-major, F[i + j*n] = F_ij (from i to j).  Each unordered
 * pair {i, j} is integrated once: the kernel returns the symmetric contour
 * sum S, F_ji = S/(2 pi A_j) goes into column i, and F_ij = F_ji A_j / A_i
 * is filled by a tiled transpose afterwards: reciprocity A_i F_ij = A_j F_ji
 * (Goral et al. 1984, eq. 4) holds by construction.  Rows are shared among OpenMP threads dynamically (row i
 * has n-1-i pairs); each thread owns its clipping scratch.  The work is cut
 * into blocks of rows so that the progress callback runs between blocks,
 * on the calling thread.
 *
 * Form factors are dimensionless: a scene and the same scene scaled by any
 * factor and moved anywhere have the same F (Goral et al. 1984, eq. 2 has
 * lengths only in ratios).  The kernel's tolerances and the squares and
 * logarithms it takes are those of a scene of size about 1, so everything
 * here works on a private copy of the geometry shifted exactly and scaled
 * by a power of two into [-1, 1]^3 (radi_mesh_normalized, mesh.h): F and its
 * error estimates are then those of the unit-size scene at every scale (two
 * polygons of side 1e-300 or 1e300 alike; a mesh at any scale whose areas
 * rad_mesh_build accepts), and the caller's mesh (areas, centroids: the
 * user's units) is left alone.
 */
#include <config.h>

#include <float.h>
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
#include "ff/formfactor.h"
#include "hemicube/hemicube.h"
#include "mesh/mesh.h"
#include "fill/ffrow.h"
#include "occ/occlusion.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "util/util.h"


/* The two polygons in the frame of their common bounding box (mesh.h):
 * out[0..na) is a, out[na..na+nb) is b; *off the frame's offset.  -1 if
 * the box is not finite. */
static int polygons_normalized(const rad_vec3 *a, int na, const rad_vec3 *b, int nb,
                               rad_vec3 *out, rad_vec3 *off)
{
    rad_vec3 alo, ahi, blo, bhi;
    rad_frame fr;
    v3_bounds(a, na, &alo, &ahi);
    v3_bounds(b, nb, &blo, &bhi);
    if (radi_frame_fit(&fr, v3(fmin(alo.x, blo.x), fmin(alo.y, blo.y), fmin(alo.z, blo.z)),
                      v3(fmax(ahi.x, bhi.x), fmax(ahi.y, bhi.y), fmax(ahi.z, bhi.z))) != 0)
        return -1;
    for (int k = 0; k < na; k++)
        out[k] = radi_frame_apply(&fr, a[k]);
    for (int k = 0; k < nb; k++)
        out[na + k] = radi_frame_apply(&fr, b[k]);
    *off = radi_frame_offset(&fr);
    return 0;
}

double rad_ff_polygons(const rad_vec3 *a, int na, const rad_vec3 *b, int nb,
                       const rad_ff_options *opt, double *errest)
{
    rad_ff_poly pa, pb;
    rad_ff_scratch w;
    double s;
    const size_t nab = (size_t)na + (size_t)nb;
    rad_ff_edge *ea = malloc(sizeof *ea * (size_t)na), *eb = malloc(sizeof *eb * (size_t)nb);
    rad_vec3 *v = malloc(sizeof *v * nab), off;
    if (!ea || !eb || !v || polygons_normalized(a, na, b, nb, v, &off) != 0) {
        free(ea);
        free(eb);
        free(v);
        return NAN;
    }
    radi_ff_poly_make(&pa, v, na, ea);
    radi_ff_poly_make(&pb, v + na, nb, eb);
    pa.snap = pb.snap = radi_occ_scene_snap(v, (int)nab, off); /* the two are the scene */
    radi_ff_scratch_init(&w);
    double f = radi_ff_pair(&pa, &pb, opt, &w, &s, errest);
    if (errest)
        *errest /= 2 * RAD_PI * pa.area;
    radi_ff_scratch_free(&w);
    free(ea);
    free(eb);
    free(v);
    return f;
}

/* Elements of one flat surface see nothing of each other: the kernel's
 * first plane test (formfactor.c, pair_setup) takes every vertex of one
 * as on the other's plane, so F = 0 with no doubt, and visibility is then
 * not asked (radi_occ_pair: S = 0).  Such a pair still cost the kernel
 * about 260 instructions, 2.8% of the 1984 cube's classic fill at
 * --mesh 10x10.  This finds the surfaces where that provably holds, so
 * that the fill can store their zeros without the kernel: every element
 * has one normal n (bit for bit: the surface's), and every vertex v lies
 * within h of the plane through c0, the first element's centroid, as
 * computed.  For a vertex v_B of element B and any vertex v_A of A,
 *     |n.(v_B - c_A)| <= |n.(v_B - c0)| + |n.(c0 - v_A)| + |n.(v_A - c_A)|
 *                     <= 2 h + twist_A,
 * plus the round-off of the distances, computed here and in the kernel,
 * a few eps |v - c| each (the subtraction is rounded once): 64 eps (R +
 * C) bounds it, R the largest |v - c0| and C the largest coordinate of
 * c0 (the C term is margin).  The kernel's tolerance for "on the plane"
 * is at least the twists plus the scene's snap (pair_setup), so a
 * surface is flat when snap > 0 and 2 h + 64 eps (R + C) <= snap.  A
 * twisted surface, whose elements may see a little of each other (a
 * saddle), fails the test and its pairs go through the kernel.  Returns,
 * per element, its surface when flat, else -1; NULL (no pair skipped)
 * when memory ran out. */
static int *flat_surfaces(const rad_mesh *m, const rad_ff_poly *polys, double snap)
{
    int *flat = malloc(sizeof *flat * (size_t)(m->nelements > 0 ? m->nelements : 1));
    for (int e = 0; flat && e < m->nelements; e++)
        flat[e] = -1;
    for (int sf = 0; flat && sf < m->nsurfaces; sf++) {
        const int e0 = m->surface_first[sf], e1 = m->surface_first[sf + 1];
        if (e0 >= e1)
            continue;
        const rad_vec3 n = polys[e0].normal, c0 = polys[e0].centroid;
        int same = snap > 0;
        double h = 0, r = 0;
        for (int e = e0; e < e1 && same; e++) {
            same = memcmp(&polys[e].normal, &n, sizeof n) == 0;
            for (int k = 0; k < polys[e].n; k++) {
                const rad_vec3 d = v3_sub(polys[e].v[k], c0);
                const double dh = fabs(v3_dot(d, n)), dr = v3_norm(d);
                h = dh > h ? dh : h;
                r = dr > r ? dr : r;
            }
        }
        same = same && 2 * h + 64 * DBL_EPSILON * (r + v3_maxabs(c0)) <= snap;
        for (int e = e0; e < e1; e++)
            flat[e] = same ? sf : -1;
    }
    return flat;
}

/* Pairs (i, j > i): the contour sum S gives F_ji = S/(2 pi A_j), stored in
 * column i (contiguous, so threads on neighbouring i do not share cache
 * lines); mirror() fills F_ij afterwards.  Tracks the largest estimated
 * absolute and relative errors, and adds each entry's estimated error to
 * its row's sum in rowerr (the thread's own, NULL in classic).  inv_t[k]
 * is 1 / (2 pi A_k).  Returns 0, or -1 when scratch ran out. */
static int fill_column(const rad_ff_poly *polys, const int *flat, const double *inv_t, int n,
                       int i, const rad_ff_options *opt, rad_ff_scratch *w, rad_occ_work *ow,
                       double *F, double *errest, double *rowerr, double *maxerr, double *maxrel,
                       long *unmet)
{
    const double promise = radi_ff_promise(opt->accuracy); /* NaN: no test */
    const int want = errest != NULL || opt->accuracy != RAD_ACCURACY_CLASSIC;
    double *col = F + (size_t)i * n, *ecol = errest ? errest + (size_t)i * n : NULL;
    double row_i = 0;
    for (int j = i + 1; j < n; j++) {
        double s, e = 0;
        if (flat && flat[i] >= 0 && flat[i] == flat[j]) {
            /* what the kernel's S = +0 and estimate 0 give below, even
             * where inv_t overflows (a subnormal area: NaN, refused) */
            col[j] = 0 * inv_t[j];
            if (ecol)
                ecol[j] = want ? 0 * inv_t[j] : NAN;
            continue;
        }
        double fij = radi_ff_pair(&polys[i], &polys[j], opt, w, &s, want ? &e : NULL);
        if (isnan(fij))
            return -1;
        /* hidden surfaces (occlusion.h): S stays symmetric, or unchanged;
         * sc is what the promise is relative to */
        double sc = fabs(s);
        if (ow && radi_occ_pair(ow, polys, i, j, &s, want ? &e : NULL, &sc) != 0)
            return -1;
        col[j] = s * inv_t[j];
        if (want && s != 0) {
            const double ej = e * inv_t[j], ei = e * inv_t[i];
            const double ea = ej > ei ? ej : ei;
            *maxerr = ea > *maxerr ? ea : *maxerr; /* not fmax: a libm call here */
            if (e > *maxrel * sc)
                *maxrel = e / sc;
            *unmet += e > promise * sc;
            if (rowerr) {
                row_i += ei;
                rowerr[j] += ej;
            }
        }
        if (ecol)
            ecol[j] = want ? e * inv_t[j] : NAN;
    }
    if (rowerr)
        rowerr[i] += row_i;
    col[i] = 0;
    if (ecol)
        ecol[i] = 0;
    return 0;
}

/* F_ij = F_ji A_j / A_i for i < j (reciprocity), in cache-sized tiles. */
static void mirror(const rad_ff_poly *polys, int n, double *M, int threads)
{
    const int T = 64;
    const int nt = (n + T - 1) / T;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int tj = 0; tj < nt; tj++)
        for (int ti = 0; ti <= tj; ti++)
            for (int j = tj * T; j < n && j < (tj + 1) * T; j++)
                for (int i = ti * T; i < j && i < (ti + 1) * T; i++)
                    M[(size_t)i + (size_t)j * n] =
                        M[(size_t)j + (size_t)i * n] * (polys[j].area / polys[i].area);
}

rad_status rad_ff_matrix(const rad_mesh *m, const rad_ff_options *opt, double *F,
                         double *errest, rad_ff_stats *stats, rad_error *err)
{
    if (opt->method == RAD_FF_HEMICUBE) /* rows from element centres (hcmatrix.c) */
        return radi_hemicube_matrix(m, opt, F, errest, stats, err);
    if (opt->method != RAD_FF_CONTOUR)
        return radi_fail(err, RAD_ERR_INVALID, "unknown form-factor method %d", (int)opt->method);
    return radi_ff_matrix_occ(m, opt, RAD_OCC_AUTO, F, errest, stats, NULL, err);
}

static rad_status ff_matrix_unit(const rad_mesh *m, double snap, const rad_ff_options *opt,
                                 rad_occ_mode mode, double *F, double *errest,
                                 rad_ff_stats *stats, rad_occ_stats *vstats, rad_error *err);

rad_status radi_ff_matrix_occ(const rad_mesh *m, const rad_ff_options *opt, rad_occ_mode mode,
                             double *F, double *errest, rad_ff_stats *stats,
                             rad_occ_stats *vstats, rad_error *err)
{
    rad_mesh unit;
    rad_frame fr;
    if (opt->quadrature < 1 || opt->quadrature > RAD_GAUSS_MAX)
        return radi_fail(err, RAD_ERR_INVALID, "quadrature must be from 1 to %d, not %d",
                        RAD_GAUSS_MAX, opt->quadrature);
    rad_status st = radi_mesh_normalized(m, &unit, &fr, err);
    if (st != RAD_OK)
        return st;
    const double snap = radi_occ_scene_snap(unit.vertices, unit.nvertices, radi_frame_offset(&fr));
    st = ff_matrix_unit(&unit, snap, opt, mode, F, errest, stats, vstats, err);
    rad_mesh_free(&unit);
    return st;
}

/* The fill itself, on a mesh of size about 1 (radi_mesh_normalized) whose
 * on-plane tolerance is snap (radi_occ_scene_snap). */
static rad_status ff_matrix_unit(const rad_mesh *m, double snap, const rad_ff_options *opt,
                                 rad_occ_mode mode, double *F, double *errest,
                                 rad_ff_stats *stats, rad_occ_stats *vstats, rad_error *err)
{
    const int n = m->nelements;
    rad_ff_poly *polys = NULL;
    rad_vec3 *pts = NULL;
    rad_ff_edge *edges = NULL;
    int failed = 0, stop = 0;
    double maxerr = 0, maxrel = 0, clamped = 0;
    long unmet = 0;
    if (radi_ff_mesh_polys(m, snap, &polys, &pts, &edges) != RAD_OK) {
        free(polys);
        free(pts);
        free(edges);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d elements", n);
    }
    rad_occ *occ = NULL;
    rad_occ_stats vst;
    rad_status vs = radi_occ_create(&occ, m, snap, mode, opt, &vst, err);
    if (vs != RAD_OK) {
        free(polys);
        free(pts);
        free(edges);
        return vs;
    }
    const double total = 0.5 * (double)n * (n - 1);
    const int threads = opt->threads > 0 ? opt->threads : omp_get_max_threads();
    /* 1 / (2 pi A_k), and each thread's row sums of the error estimates */
    double *inv_t = malloc(sizeof *inv_t * (size_t)(n > 0 ? n : 1));
    int *flat = flat_surfaces(m, polys, snap); /* (NULL: every pair to the kernel) */
    double *rowerr = opt->accuracy != RAD_ACCURACY_CLASSIC
                         ? calloc((size_t)threads * (size_t)(n > 0 ? n : 1), sizeof *rowerr)
                         : NULL;
    const int nomem = !inv_t || (opt->accuracy != RAD_ACCURACY_CLASSIC && !rowerr);
    for (int k = 0; k < n && !nomem; k++)
        inv_t[k] = 1 / (2 * RAD_PI * polys[k].area);
    /* blocks of rows between progress calls: few parallel regions (each
     * ends in a barrier, costly when the cores are shared) */
    const int block = n / 50 > 64 ? n / 50 : 64;
    for (int i0 = 0; i0 < n && !failed && !stop && !nomem; i0 += block) {
        const int i1 = i0 + block < n ? i0 + block : n;
#pragma omp parallel num_threads(threads) reduction(|| : failed) reduction(max : maxerr, maxrel) \
    reduction(+ : unmet, clamped)
        {
            rad_ff_scratch w;
            rad_occ_work ow;
            radi_ff_scratch_init(&w);
            radi_occ_work_init(&ow, occ);
            double *my_rowerr = rowerr ? rowerr + (size_t)omp_get_thread_num() * n : NULL;
#pragma omp for schedule(dynamic, 1)
            for (int i = i0; i < i1; i++)
                if (fill_column(polys, flat, inv_t, n, i, opt, &w, occ ? &ow : NULL, F, errest,
                                my_rowerr, &maxerr, &maxrel, &unmet) != 0)
                    failed = 1;
#pragma omp critical(rad_occ_stats)
            radi_occ_stats_add(&vst, &ow.stats);
            clamped += w.clamped;
            radi_occ_work_free(&ow);
            radi_ff_scratch_free(&w);
        }
        if (opt->progress) {
            double done = total - 0.5 * (double)(n - i1) * (n - i1 - 1);
            stop = opt->progress(opt->progress_user, "form factors", done, total);
        }
    }
    if (!failed && !stop && !nomem) {
        mirror(polys, n, F, threads);
        if (errest)
            mirror(polys, n, errest, threads);
    }
    double max_row_error = NAN;
    if (rowerr && !nomem) { /* the largest row sum of the entries' error estimates */
        max_row_error = 0;
        for (int k = 0; k < n; k++) {
            double r = 0;
            for (int t = 0; t < threads; t++)
                r += rowerr[(size_t)t * n + k];
            max_row_error = r > max_row_error ? r : max_row_error;
        }
    }
    free(inv_t);
    free(flat);
    free(rowerr);
    free(polys);
    free(pts);
    free(edges);
    radi_occ_free(occ);
    if (vstats)
        *vstats = vst;
    if (nomem)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d elements", n);
    if (failed)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory in the form-factor kernel");
    if (stop)
        return radi_fail(err, RAD_ERR_INVALID, "interrupted");
    for (size_t k = 0; k < (size_t)n * n; k++) /* never a NaN passed on as a value */
        if (!isfinite(F[k]))
            return radi_fail(err, RAD_ERR_INVALID,
                            "the form factor from element %zu to element %zu is not a "
                            "finite double: the scene's sizes and distances differ by more "
                            "orders of magnitude than double precision holds",
                            k % (size_t)n, k / (size_t)n);
    if (stats) {
        memset(stats, 0, sizeof *stats);
        radi_ff_fill_stats(F, n, stats);
        stats->max_errest = opt->accuracy == RAD_ACCURACY_CLASSIC ? NAN : maxerr;
        stats->max_relerr = opt->accuracy == RAD_ACCURACY_CLASSIC ? NAN : maxrel;
        stats->max_row_error = max_row_error;
        stats->promise = radi_ff_promise(opt->accuracy);
        stats->promise_unmet = 2 * unmet; /* both entries of each pair */
        radi_occ_stats_to_ff(&vst, stats);
        stats->clamped_to_one = clamped;
    }
    return RAD_OK;
}
