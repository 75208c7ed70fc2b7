/* ffrow.c -- form factors one shooter at a time, for matrix-free shooting.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Design (see ffrow.h for the contract).  radi_ffrow_create copies the mesh
 * into the unit frame (radi_mesh_normalized, as the dense fill does), makes
 * the element polygons with the fill's own routine (radi_ff_mesh_polys),
 * appends one polygon per patch when a grid is given, builds the
 * visibility structure (radi_occ_create) and one clipping scratch and one
 * visibility work space per thread.  A column then costs n - 1 pair
 * integrals, split among the threads in chunks (schedule dynamic: pairs
 * that need visibility cost far more than those that do not).
 *
 * The values, for the shooter i and a receiver j (Goral et al. 1984,
 * eq. 13 for S; the fill stores F_ba = S / (2 pi A_b) in column a for
 * a < b and mirrors the rest by reciprocity, A_a F_ab = A_b F_ba):
 *     j > i:  S = pair(i, j);  F_ji = S / (2 pi A_j),  F_ij = F_ji (A_j / A_i)
 *     j < i:  S = pair(j, i);  F_ij = S / (2 pi A_i),  F_ji = F_ij (A_i / A_j)
 * each written as the fill writes it, so the doubles are the same.
 *
 * Patches: the patch polygon P (index n + p among the polygons) against
 * element j, S = pair(P, j), F_jP = S / (2 pi A_j).  For visibility the
 * culling structure is built on the normalized mesh with the patches
 * appended as extra elements of their surfaces (radi_occ_create reads an
 * element's surface only; the surfaces' outlines come from the grid
 * vertices), so radi_occ_pair treats a patch as it treats an element.
 *
 * Statistics are kept per thread and merged after each column: the
 * largest error estimates, the promise test and the extremes of the
 * values, as the fill reports them.
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

#include "fill/ffrow.h"
#include "hemicube/hemicube.h"
#include "mesh/mesh.h"
#include "util/util.h"

/* Columns shorter than this run on one thread: a parallel region per shot
 * costs a barrier, and on a loaded machine (more runnable threads than
 * cores) a barrier waits for a descheduled thread's time slice, which
 * dwarfs a short column (measured: 600 elements, 2 threads on 2 busy
 * cores, 13 times slower than one thread). */
#define PARALLEL_MIN 16384

/* One thread's counts, merged into the row's after each column. */
typedef struct tally {
    double pairs, maxerr, maxrel, minv, maxv;
    long unmet, negative, above_one;
} tally;

struct rad_ffrow {
    rad_mesh unit;              /* the normalized copy */
    double snap;                /* its on-plane tolerance (radi_occ_scene_snap) */
    rad_element *aug;           /* unit's elements + one per patch (visibility) */
    int n, np;
    rad_ff_options opt;
    rad_ff_poly *polys;         /* n elements, then np patches */
    rad_vec3 *pts;
    rad_ff_edge *edges;
    rad_patch_grid grid;        /* on the unit mesh; npatches 0: none */
    rad_ff_edge *pedges;
    int *esurf;                 /* surface of each element */
    double *inv_t;              /* 1 / (2 pi A_k), unit frame */
    rad_occ *occ;
    rad_occ_stats vst;
    rad_hemicube *hc;           /* the hemicube method: rows from centres */
    int threads;
    rad_ff_scratch *w;
    rad_occ_work *ow;
    tally *t;                   /* per thread */
    tally all;
    double clamped;
    unsigned char *seen;        /* rows whose sum was counted */
    long rows_above_one;
    double row_min, row_max;
};

static void tally_init(tally *t)
{
    memset(t, 0, sizeof *t);
    t->minv = HUGE_VAL;
    t->maxv = -HUGE_VAL;
}

static void tally_add(tally *into, const tally *t)
{
    into->pairs += t->pairs;
    into->maxerr = t->maxerr > into->maxerr ? t->maxerr : into->maxerr;
    into->maxrel = t->maxrel > into->maxrel ? t->maxrel : into->maxrel;
    into->minv = fmin(into->minv, t->minv);
    into->maxv = fmax(into->maxv, t->maxv);
    into->unmet += t->unmet;
    into->negative += t->negative;
    into->above_one += t->above_one;
}

/* A value computed: extremes and the classic rule's faults. */
static void tally_value(tally *t, double f)
{
    t->minv = f < t->minv ? f : t->minv;
    t->maxv = f > t->maxv ? f : t->maxv;
    t->negative += f < 0;
    t->above_one += f > 1;
}

/* The error estimate e of S for the polygons a, b (as the fill keeps it),
 * the promise being relative to sc (occlusion.h, radi_occ_pair). */
static void tally_error(tally *t, double s, double e, double sc, double inv_a, double inv_b,
                        double promise)
{
    if (s == 0)
        return;
    const double ea = e * inv_a, eb = e * inv_b, m = ea > eb ? ea : eb;
    t->maxerr = m > t->maxerr ? m : t->maxerr;
    if (e > t->maxrel * sc)
        t->maxrel = e / sc;
    t->unmet += e > promise * sc;
}

void radi_ffrow_free(rad_ffrow *r)
{
    if (!r)
        return;
    for (int k = 0; k < r->threads && r->w; k++) {
        radi_ff_scratch_free(&r->w[k]);
        radi_occ_work_free(&r->ow[k]);
    }
    free(r->w);
    free(r->ow);
    free(r->t);
    radi_occ_free(r->occ);
    radi_hemicube_free(r->hc);
    free(r->polys);
    free(r->pts);
    free(r->edges);
    radi_patch_grid_free(&r->grid);
    free(r->pedges);
    free(r->esurf);
    free(r->inv_t);
    free(r->seen);
    free(r->aug);
    rad_mesh_free(&r->unit);
    free(r);
}

int radi_ffrow_threads(const rad_ffrow *r)
{
    return r->threads;
}

/* The patches' polygons after the elements' (polys[n + p]), with their
 * surface's normal as the elements have it. */
static rad_status patch_polys(rad_ffrow *r, int P, int Q, rad_error *err)
{
    rad_status st = radi_patch_grid_build(&r->grid, &r->unit, P, Q, err);
    if (st != RAD_OK)
        return st;
    const int np = r->grid.npatches, nc = r->grid.cfirst[np];
    r->np = np;
    r->pedges = malloc(sizeof *r->pedges * (size_t)(nc ? nc : 1));
    rad_ff_poly *grown = realloc(r->polys, sizeof *grown * (size_t)(r->n + np ? r->n + np : 1));
    if (grown)
        r->polys = grown;
    if (!r->pedges || !grown)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d patches", np);
    for (int p = 0; p < np; p++) {
        const int c0 = r->grid.cfirst[p], k = r->grid.cfirst[p + 1] - c0;
        rad_ff_poly *q = &r->polys[r->n + p];
        radi_ff_poly_make(q, r->grid.corner + c0, k, r->pedges + c0);
        q->snap = r->snap;
        q->normal = r->unit.elements[r->grid.member[r->grid.first[p]]].normal;
        q->nu = radi_ff_element_doubt(&r->unit, r->grid.member[r->grid.first[p]]);
    }
    return RAD_OK;
}

/* The culling structure, on the unit mesh with the patches appended as
 * elements of their surfaces (see the header essay). */
static rad_status make_occ(rad_ffrow *r, rad_occ_mode mode, rad_error *err)
{
    rad_mesh m = r->unit;
    if (r->np > 0) {
        r->aug = malloc(sizeof *r->aug * (size_t)(r->n + r->np));
        if (!r->aug)
            return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d patches", r->np);
        memcpy(r->aug, r->unit.elements, sizeof *r->aug * (size_t)r->n);
        for (int p = 0; p < r->np; p++) {
            rad_element *e = &r->aug[r->n + p];
            *e = r->unit.elements[r->grid.member[r->grid.first[p]]];
            e->area = r->polys[r->n + p].area;
            e->centroid = r->polys[r->n + p].centroid;
        }
        m.elements = r->aug;
        m.nelements = r->n + r->np;
    }
    return radi_occ_create(&r->occ, &m, r->snap, mode, &r->opt, &r->vst, err);
}

static rad_status thread_space(rad_ffrow *r, rad_error *err)
{
    const int T = r->threads;
    r->w = calloc((size_t)T, sizeof *r->w);
    r->ow = calloc((size_t)T, sizeof *r->ow);
    r->t = calloc((size_t)T, sizeof *r->t);
    r->inv_t = malloc(sizeof *r->inv_t * (size_t)(r->n ? r->n : 1));
    r->seen = calloc((size_t)(r->n ? r->n : 1), 1);
    if (!r->w || !r->ow || !r->t || !r->inv_t || !r->seen)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d elements", r->n);
    for (int k = 0; k < T; k++) {
        radi_ff_scratch_init(&r->w[k]);
        radi_occ_work_init(&r->ow[k], r->occ);
    }
    for (int k = 0; k < r->n; k++) /* as the fill: 1 / (2 pi A_k) */
        r->inv_t[k] = 1 / (2 * RAD_PI * r->polys[k].area);
    return RAD_OK;
}

rad_status radi_ffrow_create(rad_ffrow **out, const rad_mesh *m, const rad_ff_options *opt,
                            rad_occ_mode mode, int P, int Q, rad_error *err)
{
    *out = NULL;
    if (opt->quadrature < 1 || opt->quadrature > RAD_GAUSS_MAX)
        return radi_fail(err, RAD_ERR_INVALID, "quadrature must be from 1 to %d, not %d",
                        RAD_GAUSS_MAX, opt->quadrature);
    if (!rad_ff_method_name((int)opt->method)) /* as rad_ff_matrix refuses it */
        return radi_fail(err, RAD_ERR_INVALID, "unknown form-factor method %d",
                        (int)opt->method);
    rad_ffrow *r = calloc(1, sizeof *r);
    if (!r)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    r->opt = *opt;
    r->n = m->nelements;
    r->threads = opt->threads > 0 ? opt->threads : omp_get_max_threads();
    r->row_min = NAN;
    r->row_max = NAN;
    tally_init(&r->all);
    rad_frame fr = {{0, 0, 0}, 0};
    rad_status st = radi_mesh_normalized(m, &r->unit, &fr, err);
    if (st == RAD_OK)
        r->snap = radi_occ_scene_snap(r->unit.vertices, r->unit.nvertices, radi_frame_offset(&fr));
    if (st == RAD_OK &&
        radi_ff_mesh_polys(&r->unit, r->snap, &r->polys, &r->pts, &r->edges) != RAD_OK)
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d elements", r->n);
    const int hemi = opt->method == RAD_FF_HEMICUBE;
    if (st == RAD_OK && hemi && P > 0)
        st = radi_fail(err, RAD_ERR_INVALID, "the hemicube shoots from elements: a patch grid "
                      "(`patch_p` x `patch_q`) needs the contour integral");
    if (st == RAD_OK && P > 0 && Q > 0)
        st = patch_polys(r, P, Q, err);
    if (st == RAD_OK && hemi) /* its z-buffer is its visibility */
        st = radi_hemicube_create(&r->hc, &r->unit, opt->resolution, err);
    else if (st == RAD_OK)
        st = make_occ(r, mode, err);
    if (st == RAD_OK)
        st = thread_space(r, err);
    if (st != RAD_OK) {
        radi_ffrow_free(r);
        return st;
    }
    *out = r;
    return RAD_OK;
}

/* S of the pair (a, b) with visibility, its estimate and what the
 * promise is relative to (*sc: occlusion.h); -1 when scratch ran out. */
static int pair_sum(rad_ffrow *r, int k, int a, int b, double *s, double *e, double *sc)
{
    const int want = r->opt.accuracy != RAD_ACCURACY_CLASSIC;
    *e = 0;
    double f = radi_ff_pair(&r->polys[a], &r->polys[b], &r->opt, &r->w[k], s, want ? e : NULL);
    if (isnan(f))
        return -1;
    *sc = fabs(*s);
    if (r->occ && radi_occ_pair(&r->ow[k], r->polys, a, b, s, want ? e : NULL, sc) != 0)
        return -1;
    return 0;
}

/* Merge the threads' tallies after a column. */
static void merge(rad_ffrow *r)
{
    for (int k = 0; k < r->threads; k++) {
        tally_add(&r->all, &r->t[k]);
        tally_init(&r->t[k]);
        r->clamped += r->w[k].clamped;
        r->w[k].clamped = 0;
    }
}

static rad_status not_finite(rad_error *err, int j, int i)
{
    return radi_fail(err, RAD_ERR_INVALID,
                    "the form factor from element %d to element %d is not a finite double: "
                    "the scene's sizes and distances differ by more orders of magnitude than "
                    "double precision holds",
                    j, i);
}

/* Count row i's sum sum_j F_ij once. */
static void row_sum(rad_ffrow *r, int i, double sum)
{
    if (r->seen[i])
        return;
    r->seen[i] = 1;
    r->rows_above_one += sum > 1 + RAD_ROW_SUM_SLACK;
    r->row_min = isnan(r->row_min) ? sum : fmin(r->row_min, sum);
    r->row_max = isnan(r->row_max) ? sum : fmax(r->row_max, sum);
}

/* The hemicube's column: row i from i's centre (hemicube.c), and F_ji =
 * F_ij A_i / A_j by reciprocity, as Cohen et al. 1988 (section 3.1, eq. 6)
 * shoot from a hemicube. */
static rad_status hemicube_column(rad_ffrow *r, int i, double *to, double *from,
                                  rad_error *err)
{
    const int n = r->n;
    const rad_ff_poly *P = r->polys;
    tally *t = &r->t[0];
    double *row = from ? from : to, sum = 0;
    rad_status st = radi_hemicube_row(r->hc, i, row, err);
    if (st != RAD_OK)
        return st;
    for (int j = 0; j < n; j++) {
        const double fij = row[j];
        sum += fij;
        to[j] = fij * (P[i].area / P[j].area);
        if (j == i)
            continue;
        t->pairs++;
        tally_value(t, fij);
        tally_value(t, to[j]);
        if (!isfinite(to[j]))
            return not_finite(err, j, i);
    }
    merge(r);
    row_sum(r, i, sum);
    return RAD_OK;
}

/* After a parallel loop over pairs: the threads' tallies merged, then
 * its failure (out of memory) or the first pair whose factor is not
 * finite (bad >= 0, in row `row` as not_finite names it). */
static rad_status loop_end(rad_ffrow *r, int failed, int bad, int row, rad_error *err)
{
    merge(r);
    if (failed)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory in the form-factor kernel");
    if (bad >= 0)
        return not_finite(err, bad, row);
    return RAD_OK;
}

/* F_ji and F_ij of the pair (i, j) from its contour sum s, as the dense
 * fill writes them: the entry in the column of the lower index, and its
 * mirror by reciprocity (A_i F_ij = A_j F_ji), so that the values are the
 * fill's bit for bit. */
static void pair_factors(const rad_ffrow *r, int i, int j, double s, double *fji, double *fij)
{
    const rad_ff_poly *P = r->polys;
    if (j > i) { /* the fill's column i, and its mirror */
        *fji = s * r->inv_t[j];
        *fij = *fji * (P[j].area / P[i].area);
    } else { /* the fill's column j, and its mirror */
        *fij = s * r->inv_t[i];
        *fji = *fij * (P[i].area / P[j].area);
    }
}

rad_status radi_ffrow_column(rad_ffrow *r, int i, double *to, double *from, rad_error *err)
{
    if (r->hc)
        return hemicube_column(r, i, to, from, err);
    const int n = r->n;
    const double *inv_t = r->inv_t, promise = radi_ff_promise(r->opt.accuracy);
    int failed = 0, bad = -1;
    double sum = 0;
#pragma omp parallel num_threads(n >= PARALLEL_MIN ? r->threads : 1) reduction(|| : failed) \
    reduction(+ : sum)
    {
        const int k = omp_get_thread_num();
        tally *t = &r->t[k];
#pragma omp for schedule(dynamic, 256)
        for (int j = 0; j < n; j++) {
            double s, e, sc, fji, fij;
            if (j == i || failed) {
                to[j] = 0;
                if (from)
                    from[j] = 0;
                continue;
            }
            if (pair_sum(r, k, j < i ? j : i, j < i ? i : j, &s, &e, &sc) != 0) {
                failed = 1;
                continue;
            }
            pair_factors(r, i, j, s, &fji, &fij);
            to[j] = fji;
            if (from)
                from[j] = fij;
            sum += fij;
            if (!isfinite(fji) || !isfinite(fij))
#pragma omp critical(rad_ffrow_bad)
                bad = j;
            t->pairs++;
            tally_value(t, fji);
            tally_value(t, fij);
            if (r->opt.accuracy != RAD_ACCURACY_CLASSIC)
                tally_error(t, s, e, sc, inv_t[i], inv_t[j], promise);
        }
    }
    rad_status st = loop_end(r, failed, bad, i, err);
    if (st == RAD_OK)
        row_sum(r, i, sum);
    return st;
}

rad_status radi_ffrow_pairs(rad_ffrow *r, int i, const int *js, int k, double *to,
                           rad_error *err)
{
    const double *inv_t = r->inv_t, promise = radi_ff_promise(r->opt.accuracy);
    int failed = 0, bad = -1;
#pragma omp parallel num_threads(k >= PARALLEL_MIN ? r->threads : 1) reduction(|| : failed)
    {
        const int w = omp_get_thread_num();
        tally *t = &r->t[w];
#pragma omp for schedule(dynamic, 256)
        for (int q = 0; q < k; q++) {
            const int j = js[q];
            double s, e, sc;
            if (j == i || failed) {
                to[q] = 0;
                continue;
            }
            if (pair_sum(r, w, j < i ? j : i, j < i ? i : j, &s, &e, &sc) != 0) {
                failed = 1;
                continue;
            }
            double fij;
            pair_factors(r, i, j, s, &to[q], &fij);
            if (!isfinite(to[q]))
#pragma omp critical(rad_ffrow_bad)
                bad = j;
            t->pairs++;
            tally_value(t, to[q]);
            if (r->opt.accuracy != RAD_ACCURACY_CLASSIC)
                tally_error(t, s, e, sc, inv_t[i], inv_t[j], promise);
        }
    }
    return loop_end(r, failed, bad, i, err);
}

rad_status radi_ffrow_patch(rad_ffrow *r, int p, double *to, rad_error *err)
{
    const int n = r->n, a = n + p, surf = r->grid.surface[p];
    const double promise = radi_ff_promise(r->opt.accuracy);
    const double inv_p = 1 / (2 * RAD_PI * r->polys[a].area);
    int failed = 0, bad = -1;
#pragma omp parallel num_threads(n >= PARALLEL_MIN ? r->threads : 1) reduction(|| : failed)
    {
        const int k = omp_get_thread_num();
        tally *t = &r->t[k];
#pragma omp for schedule(dynamic, 256)
        for (int j = 0; j < n; j++) {
            double s, e, sc;
            if (r->unit.elements[j].surface == surf || failed) {
                to[j] = 0; /* one plane: nothing seen */
                continue;
            }
            if (pair_sum(r, k, a, j, &s, &e, &sc) != 0) {
                failed = 1;
                continue;
            }
            to[j] = s * r->inv_t[j];
            if (!isfinite(to[j]))
#pragma omp critical(rad_ffrow_bad)
                bad = j;
            t->pairs++;
            tally_value(t, to[j]);
            if (r->opt.accuracy != RAD_ACCURACY_CLASSIC)
                tally_error(t, s, e, sc, inv_p, r->inv_t[j], promise);
        }
    }
    return loop_end(r, failed, bad, -1 - p, err);
}

void radi_ffrow_stats(const rad_ffrow *r, rad_ff_stats *st, double *min_row_sum,
                     double *max_row_sum)
{
    /* no error estimate in classic mode, nor from the hemicube */
    const int classic = r->opt.accuracy == RAD_ACCURACY_CLASSIC || r->hc;
    rad_occ_stats v = r->vst;
    for (int k = 0; k < r->threads; k++)
        radi_occ_stats_add(&v, &r->ow[k].stats);
    memset(st, 0, sizeof *st);
    st->pairs = r->all.pairs;
    st->integrated = r->all.pairs;
    st->negative = r->all.negative;
    st->above_one = r->all.above_one;
    st->min_value = r->all.pairs > 0 ? r->all.minv : 0;
    st->max_value = r->all.pairs > 0 ? r->all.maxv : 0;
    st->max_errest = classic ? NAN : r->all.maxerr;
    st->max_relerr = classic ? NAN : r->all.maxrel;
    st->max_row_error = NAN; /* a bound over whole rows: not kept */
    st->promise = r->hc ? NAN : radi_ff_promise(r->opt.accuracy);
    st->promise_unmet = r->all.unmet;
    st->rows_above_one = r->rows_above_one;
    radi_occ_stats_to_ff(&v, st);
    st->clamped_to_one = r->clamped;
    if (min_row_sum)
        *min_row_sum = r->row_min;
    if (max_row_sum)
        *max_row_sum = r->row_max;
}
