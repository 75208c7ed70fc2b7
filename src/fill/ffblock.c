/* ffblock.c -- any set of entries of the form-factor matrix.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The same arithmetic as the dense fill (ffmatrix.c), entry by entry: on
 * the mesh normalized to [-1, 1]^3 (radi_mesh_normalized), the unordered
 * pair {i, j}, i < j, gives the contour sum S = radi_ff_pair(i, j), then
 * radi_occ_pair takes the hidden part away; F_ji = S / (2 pi A_j) and
 * F_ij = F_ji (A_j / A_i), the two roundings of the dense fill and its
 * mirror.  So a block filled here holds bit for bit the doubles that the
 * dense matrix holds at the same places, whatever the block's shape: a
 * distributed solve and a serial one see the same F.
 *
 * radi_ff_pairs (ffpairs.h) is the same for a list of pairs, both entries
 * of each: the animation's recomputed pairs.
 *
 * The price is that a pair whose two entries live in different blocks
 * (on different processes) is integrated twice: filling every entry of F
 * in blocks costs twice the dense fill's pair integrations, spread over
 * the processes.  Error estimates follow the dense fill too: the estimate
 * of S, e, gives e / (2 pi A_i) for F_ij.
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
#include "fill/ffpairs.h"
#include "mesh/mesh.h"
#include "util/util.h"

struct rad_ff_block {
    rad_mesh unit;              /* the normalized copy */
    rad_ff_options opt;
    rad_ff_poly *polys;
    rad_vec3 *pts;
    rad_ff_edge *edges;
    double *inv_t;              /* 1 / (2 pi A_k), normalized areas */
    rad_occ *occ;               /* NULL: nothing can be hidden */
    rad_occ_stats setup;        /* the visibility setup's share */
};

void radi_ff_tally_clear(rad_ff_tally *t, int n)
{
    double *rs = t->row_sum, *re = t->row_error;
    memset(t, 0, sizeof *t);
    t->row_sum = rs;
    t->row_error = re;
    t->min_value = HUGE_VAL;
    t->max_value = -HUGE_VAL;
    for (int k = 0; k < n; k++) {
        if (rs)
            rs[k] = 0;
        if (re)
            re[k] = 0;
    }
}

void radi_ff_block_close(rad_ff_block *b)
{
    if (!b)
        return;
    radi_occ_free(b->occ);
    free(b->polys);
    free(b->pts);
    free(b->edges);
    free(b->inv_t);
    rad_mesh_free(&b->unit);
    free(b);
}

rad_status radi_ff_block_open(rad_ff_block **out, const rad_mesh *mesh,
                             const rad_ff_options *opt, rad_error *err)
{
    *out = NULL;
    if (opt->quadrature < 1 || opt->quadrature > RAD_GAUSS_MAX)
        return radi_fail(err, RAD_ERR_INVALID, "quadrature must be from 1 to %d, not %d",
                        RAD_GAUSS_MAX, opt->quadrature);
    if (opt->method != RAD_FF_CONTOUR)
        return radi_fail(err, RAD_ERR_INVALID, "form factors by pairs or blocks need the "
                        "contour integral: the hemicube gives whole rows");
    rad_ff_block *b = calloc(1, sizeof *b);
    if (!b)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    b->opt = *opt;
    rad_frame fr;
    rad_status st = radi_mesh_normalized(mesh, &b->unit, &fr, err);
    if (st != RAD_OK) {
        free(b);
        return st;
    }
    const double snap = radi_occ_scene_snap(b->unit.vertices, b->unit.nvertices,
                                           radi_frame_offset(&fr));
    const int n = b->unit.nelements;
    b->inv_t = malloc(sizeof *b->inv_t * (size_t)(n > 0 ? n : 1));
    if (!b->inv_t || radi_ff_mesh_polys(&b->unit, snap, &b->polys, &b->pts, &b->edges) != RAD_OK) {
        radi_ff_block_close(b);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d elements", n);
    }
    for (int k = 0; k < n; k++)
        b->inv_t[k] = 1 / (2 * RAD_PI * b->polys[k].area);
    st = radi_occ_create(&b->occ, &b->unit, snap, RAD_OCC_AUTO, opt, &b->setup, err);
    if (st != RAD_OK) {
        radi_ff_block_close(b);
        return st;
    }
    *out = b;
    return RAD_OK;
}

/* The pair {i, j}, i < j: its occluded contour sum S, S's estimated
 * error (0 in classic) and what the promise is relative to (*sc, may be
 * NULL: occlusion.h), as fill_column (ffmatrix.c) computes them.
 * Returns -1 when scratch ran out. */
static int pair_sum(const rad_ff_block *b, rad_ff_scratch *w, rad_occ_work *ow, int i, int j,
                    double *s, double *e, double *sc)
{
    const int want = b->opt.accuracy != RAD_ACCURACY_CLASSIC;
    *e = 0;
    if (isnan(radi_ff_pair(&b->polys[i], &b->polys[j], &b->opt, w, s, want ? e : NULL)))
        return -1;
    if (sc)
        *sc = fabs(*s);
    if (ow && radi_occ_pair(ow, b->polys, i, j, s, want ? e : NULL, sc) != 0)
        return -1;
    return 0;
}

/* Entry F_{gi, gj}, gi != gj, its estimated absolute error and relative
 * error e / sc (sc = |S| but for nearly hidden pairs: occlusion.h; both
 * NaN in classic, and the relative one when S = 0, as the dense fill
 * skips those).  Returns -1 when scratch ran out. */
static int entry(const rad_ff_block *b, rad_ff_scratch *w, rad_occ_work *ow, int gi, int gj,
                 double *f, double *ef, double *rel)
{
    const int i = gi < gj ? gi : gj, j = gi < gj ? gj : gi;
    const int want = b->opt.accuracy != RAD_ACCURACY_CLASSIC;
    double s, e, sc;
    if (pair_sum(b, w, ow, i, j, &s, &e, &sc) != 0)
        return -1;
    const double fji = s * b->inv_t[j];
    *f = gi == j ? fji : fji * (b->polys[j].area / b->polys[i].area);
    *ef = want ? e * b->inv_t[gi] : NAN;
    *rel = want && s != 0 ? e / sc : NAN;
    return 0;
}

/* The scalar part of a tally, one per thread. */
typedef struct part {
    double entries, nonzero, negative, above_one, min_value, max_value;
    double max_errest, max_relerr, unmet;
} part;

/* One entry f with its estimates (entry()): the dense fill's statistics
 * (ffmatrix.c, fill_column), per entry. */
static void part_add(part *p, double f, double ef, double rel, double promise)
{
    p->entries += 1;
    p->nonzero += f != 0;
    p->negative += f < 0;
    p->above_one += f > 1;
    p->min_value = f < p->min_value ? f : p->min_value;
    p->max_value = f > p->max_value ? f : p->max_value;
    if (isnan(rel))
        return;
    p->max_errest = ef > p->max_errest ? ef : p->max_errest;
    p->max_relerr = rel > p->max_relerr ? rel : p->max_relerr;
    p->unmet += rel > promise;
}

rad_status radi_ff_block_fill(rad_ff_block *b, const int *rows, int nr, const int *cols, int nc,
                             double *out, size_t ld, rad_ff_tally *t, rad_error *err)
{
    const int threads = b->opt.threads > 0 ? b->opt.threads : omp_get_max_threads();
    const double promise = radi_ff_promise(b->opt.accuracy);
    const size_t nrs = (size_t)(nr > 0 ? nr : 1);
    double *rsum = calloc((size_t)threads * nrs * 2, sizeof *rsum); /* sums, errors */
    int failed = 0;
    if (!rsum)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    part tot = {0, 0, 0, 0, HUGE_VAL, -HUGE_VAL, 0, 0, 0};
    rad_occ_stats vis = b->setup;
    double clamped = 0;
#pragma omp parallel num_threads(threads) reduction(|| : failed) reduction(+ : clamped)
    {
        rad_ff_scratch w;
        rad_occ_work ow;
        part p = {0, 0, 0, 0, HUGE_VAL, -HUGE_VAL, 0, 0, 0};
        double *my = rsum + (size_t)omp_get_thread_num() * nrs * 2;
        radi_ff_scratch_init(&w);
        radi_occ_work_init(&ow, b->occ);
#pragma omp for schedule(dynamic, 1)
        for (int c = 0; c < nc; c++)
            for (int r = 0; r < nr; r++) {
                double f = 0, ef = 0, rel = 0;
                double *o = out + (size_t)r + (size_t)c * ld;
                if (rows[r] == cols[c]) {
                    *o = 0;
                    continue;
                }
                if (entry(b, &w, b->occ ? &ow : NULL, rows[r], cols[c], &f, &ef, &rel) != 0) {
                    failed = 1;
                    continue;
                }
                *o = f;
                part_add(&p, f, ef, rel, promise);
                my[r] += f;
                if (!isnan(rel))
                    my[nrs + r] += ef;
            }
#pragma omp critical(rad_ff_block_tally)
        {
            tot.entries += p.entries;
            tot.nonzero += p.nonzero;
            tot.negative += p.negative;
            tot.above_one += p.above_one;
            tot.min_value = fmin(tot.min_value, p.min_value);
            tot.max_value = fmax(tot.max_value, p.max_value);
            tot.max_errest = fmax(tot.max_errest, p.max_errest);
            tot.max_relerr = fmax(tot.max_relerr, p.max_relerr);
            tot.unmet += p.unmet;
            radi_occ_stats_add(&vis, &ow.stats);
        }
        clamped += w.clamped;
        radi_occ_work_free(&ow);
        radi_ff_scratch_free(&w);
    }
    b->setup.seconds = 0; /* the setup is counted once */
    if (failed) {
        free(rsum);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory in the form-factor kernel");
    }
    for (int c = 0; c < nc; c++)
        for (int r = 0; r < nr; r++)
            if (!isfinite(out[(size_t)r + (size_t)c * ld])) {
                free(rsum);
                return radi_fail(err, RAD_ERR_INVALID,
                                "the form factor from element %d to element %d is not a "
                                "finite double: the scene's sizes and distances differ by "
                                "more orders of magnitude than double precision holds",
                                rows[r], cols[c]);
            }
    if (t) {
        t->entries += tot.entries;
        t->nonzero += tot.nonzero;
        t->negative += tot.negative;
        t->above_one += tot.above_one;
        t->min_value = fmin(t->min_value, tot.min_value);
        t->max_value = fmax(t->max_value, tot.max_value);
        t->max_errest = fmax(t->max_errest, tot.max_errest);
        t->max_relerr = fmax(t->max_relerr, tot.max_relerr);
        t->unmet += tot.unmet;
        t->clamped += clamped;
        radi_occ_stats_add(&t->vis, &vis);
        for (int th = 0; th < threads; th++)
            for (int r = 0; r < nr; r++) {
                const double *my = rsum + (size_t)th * nrs * 2;
                if (t->row_sum)
                    t->row_sum[rows[r]] += my[r];
                if (t->row_error && b->opt.accuracy != RAD_ACCURACY_CLASSIC)
                    t->row_error[rows[r]] += my[nrs + r];
            }
    }
    free(rsum);
    return RAD_OK;
}

rad_status radi_ff_block_pairs(rad_ff_block *b, const int *pi, const int *pj, size_t np,
                              double *fij, double *fji, rad_error *err)
{
    const int threads = b->opt.threads > 0 ? b->opt.threads : omp_get_max_threads();
    int failed = 0;
#pragma omp parallel num_threads(threads) reduction(|| : failed)
    {
        rad_ff_scratch w;
        rad_occ_work ow;
        radi_ff_scratch_init(&w);
        radi_occ_work_init(&ow, b->occ);
#pragma omp for schedule(dynamic, 16)
        for (size_t k = 0; k < np; k++) {
            const int i = pi[k], j = pj[k];
            double s, e;
            if (pair_sum(b, &w, b->occ ? &ow : NULL, i, j, &s, &e, NULL) != 0) {
                failed = 1;
                continue;
            }
            fji[k] = s * b->inv_t[j]; /* the fill's column, then its mirror */
            fij[k] = fji[k] * (b->polys[j].area / b->polys[i].area);
        }
        radi_occ_work_free(&ow);
        radi_ff_scratch_free(&w);
    }
    b->setup.seconds = 0;
    if (failed)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory in the form-factor kernel");
    for (size_t k = 0; k < np; k++)
        if (!isfinite(fij[k]) || !isfinite(fji[k]))
            return radi_fail(err, RAD_ERR_INVALID, "the form factor between elements %d and %d "
                            "is not a finite double", pi[k], pj[k]);
    return RAD_OK;
}

rad_status radi_ff_pairs(const rad_mesh *m, const rad_ff_options *opt, const int *pi,
                        const int *pj, size_t np, double *fij, double *fji, rad_error *err)
{
    rad_ff_block *b;
    rad_status st = radi_ff_block_open(&b, m, opt, err);
    if (st == RAD_OK)
        st = radi_ff_block_pairs(b, pi, pj, np, fij, fji, err);
    radi_ff_block_close(b);
    return st;
}
