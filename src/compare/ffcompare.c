/* ffcompare.c -- another solver's form factors against ours (ffcompare.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * One pass over the entries, column by column as the matrices are stored,
 * gathers everything per entry: the error e_ij (ffcompare.h), the
 * histogram, the worst pairs, and per row the largest e, the sum of e^2
 * and both row sums.  A second pass over the pairs i < j checks the other
 * matrix's reciprocity A_i G_ij = A_j G_ji (Goral et al. 1984, eq. 9; the
 * identity every exact form factor obeys; doc/design.md, "Tests and
 * benchmarks").  Both are O(n^2) reads: a small cost next to the
 * reference fill they follow.
 *
 * A non-finite entry of G (NaN or infinity, which a .npy file can hold)
 * has e = infinity: it is the largest error there is, never skipped.
 * The worst pairs are kept in a small array sorted by insertion (nworst
 * is tens), ties broken by the order met, so the output is deterministic;
 * entries with e = 0 are not among them.  Without our error estimates
 * (classic mode gives none) the counts that need them are -1 and NaN.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compare/ffcompare.h"
#include "util/util.h"

double radi_ffcmp_bin_edge(int b)
{
    return pow(10.0, RAD_FFCMP_LOG_LO + RAD_FFCMP_BIN * b);
}

/* e = |g - f| / max(|f|, floor); infinity where g is not finite. */
static double entry_error(double g, double f, double floor)
{
    if (!isfinite(g))
        return INFINITY;
    const double s = fabs(f) > floor ? fabs(f) : floor;
    return fabs(g - f) / s;
}

static void histogram_add(rad_ffcmp *c, double e)
{
    if (e == 0) {
        c->hist_zero++;
        return;
    }
    const double b = floor((log10(e) - RAD_FFCMP_LOG_LO) / RAD_FFCMP_BIN);
    if (!(b < RAD_FFCMP_BINS))
        c->hist_over++;
    else
        c->hist[b < 0 ? 0 : (int)b]++;
}

/* Keep p if it is among the nworst largest errors so far. */
static void keep_worst(rad_ffcmp *c, rad_ffcmp_pair p)
{
    int k = c->nworst_found;
    if (c->nworst == 0 || !(p.err > 0) || (k == c->nworst && !(p.err > c->worst[k - 1].err)))
        return;
    if (k < c->nworst)
        c->nworst_found++;
    else
        k--;
    while (k > 0 && p.err > c->worst[k - 1].err) {
        c->worst[k] = c->worst[k - 1];
        k--;
    }
    c->worst[k] = p;
}

/* Column j of the entries: errors, histogram, worst pairs, row figures. */
static void column(rad_ffcmp *c, const double *G, const double *F, const double *E, size_t n,
                   size_t j, double *sumsq)
{
    for (size_t i = 0; i < n; i++) {
        const size_t k = i + j * n;
        const double e = entry_error(G[k], F[k], c->floor);
        rad_ffcmp_row *r = &c->rows[i];
        histogram_add(c, e);
        c->exact += G[k] == F[k];
        if (E) {
            c->beyond_estimate += !(fabs(G[k] - F[k]) <= E[k]);
            const double own = entry_error(F[k] + E[k], F[k], c->floor);
            c->max_own_err = own > c->max_own_err ? own : c->max_own_err;
        }
        if (!(e <= r->max))
            r->max = e;
        sumsq[i] += e * e;
        r->sum_ours += F[k];
        r->sum_theirs += G[k];
        keep_worst(c, (rad_ffcmp_pair){(int)i, (int)j, F[k], G[k], e});
    }
}

/* Closure and the row sums' difference, from the rows' sums. */
static void closure(rad_ffcmp *c, size_t n)
{
    c->closure_ours = c->closure_theirs = c->max_rowsum_diff = 0;
    for (size_t i = 0; i < n; i++) {
        const rad_ffcmp_row *r = &c->rows[i];
        const double o = fabs(1 - r->sum_ours), t = fabs(1 - r->sum_theirs);
        const double d = fabs(r->sum_theirs - r->sum_ours);
        if (o > c->closure_ours)
            c->closure_ours = o, c->closure_ours_row = (int)i;
        if (!(t <= c->closure_theirs))
            c->closure_theirs = t, c->closure_theirs_row = (int)i;
        if (!(d <= c->max_rowsum_diff))
            c->max_rowsum_diff = d, c->rowsum_diff_row = (int)i;
    }
}

/* Reciprocity of G: |A_i G_ij - A_j G_ji| for the pairs i < j. */
static void reciprocity(rad_ffcmp *c, const double *G, const double *A, size_t n)
{
    c->recip_abs = c->recip_rel = 0;
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < j; i++) {
            const double a = A[i] * G[i + j * n], b = A[j] * G[j + i * n];
            const double d = fabs(a - b), s = fmax(fabs(a), fabs(b));
            const double rel = s > 0 ? d / s : 0;
            if (!(d <= c->recip_abs))
                c->recip_abs = d, c->recip_abs_i = (int)i, c->recip_abs_j = (int)j;
            if (!(rel <= c->recip_rel))
                c->recip_rel = rel, c->recip_rel_i = (int)i, c->recip_rel_j = (int)j;
        }
}

/* Rows by their largest error, the largest first (then by index). */
static int by_max(const void *a, const void *b)
{
    const rad_ffcmp_row *x = a, *y = b;
    const double u = isnan(x->max) ? INFINITY : x->max, v = isnan(y->max) ? INFINITY : y->max;
    if (u != v)
        return u > v ? -1 : 1;
    return (x->i > y->i) - (x->i < y->i);
}

rad_status radi_ffcmp_run(rad_ffcmp *c, const double *G, const double *F, const double *E,
                         const double *A, int n, rad_error *err)
{
    const size_t m = n > 0 ? (size_t)n : 0;
    double *sumsq = calloc(m + 1, sizeof *sumsq);
    c->rows = calloc(m + 1, sizeof *c->rows);
    c->worst = malloc(sizeof *c->worst * ((size_t)c->nworst + 1));
    if (!sumsq || !c->rows || !c->worst) {
        free(sumsq);
        radi_ffcmp_free(c);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory comparing %d x %d form factors",
                        n, n);
    }
    c->nworst_found = 0;
    c->exact = c->beyond_estimate = c->hist_zero = c->hist_over = 0;
    c->max_own_err = E ? 0 : NAN;
    c->max_err = 0;
    memset(c->hist, 0, sizeof c->hist);
    for (size_t i = 0; i < m; i++)
        c->rows[i] = (rad_ffcmp_row){(int)i, 0, 0, 0, 0};
    for (size_t j = 0; j < m; j++)
        column(c, G, F, E, m, j, sumsq);
    if (!E)
        c->beyond_estimate = -1;
    double total = 0;
    for (size_t i = 0; i < m; i++) {
        total += sumsq[i];
        c->rows[i].rms = sqrt(sumsq[i] / (double)m);
        if (!(c->rows[i].max <= c->max_err))
            c->max_err = c->rows[i].max;
    }
    c->rms_err = m > 0 ? sqrt(total / ((double)m * (double)m)) : 0;
    free(sumsq);
    closure(c, m);
    reciprocity(c, G, A, m);
    qsort(c->rows, m, sizeof *c->rows, by_max);
    return RAD_OK;
}

void radi_ffcmp_free(rad_ffcmp *c)
{
    free(c->rows);
    free(c->worst);
    c->rows = NULL;
    c->worst = NULL;
}
