/* compare_print.c -- `radiosity compare`'s report, JSON and histogram
 * (compare_print.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The text report is for a person: three significant digits, the worst
 * pairs with the geometry that usually explains them (which surfaces,
 * how far apart, how large: near-touching and elongated pairs are where
 * solvers disagree), the worst rows, then the identities.  The JSON
 * report carries the same figures with %.17g (a program reads back the
 * same doubles) and NaN or infinity as null, which JSON lacks.  Keys are
 * listed in radiosity-files(5).
 *
 * Element numbers are ours (0-based, mesh order); with --elements the
 * other solver's numbers are matched to them first (elmatch.h).
 */
#include <config.h>

#include <math.h>
#include <stdio.h>

#include "cli/cli.h"
#include "cli/compare_print.h"
#include "util/util.h"
#include "render/render.h"

int compare_within(const compare_ctx *c)
{
    return !c->has_tolerance || c->cmp->max_err <= c->tolerance;
}

static double distance(const rad_mesh *m, int i, int j)
{
    const rad_vec3 a = m->elements[i].centroid, b = m->elements[j].centroid;
    return hypot(hypot(a.x - b.x, a.y - b.y), a.z - b.z);
}

static void head(FILE *out, const compare_ctx *c)
{
    const rad_ffcmp *k = c->cmp;
    const double nn = (double)c->mesh->nelements * c->mesh->nelements;
    fprintf(out, "compare: %s (%s) against %s, %d elements, ours in %s mode\n", c->matrix,
            c->format, c->scene, c->mesh->nelements, rad_accuracy_name(c->accuracy));
    if (c->elements)
        fprintf(out, "elements matched by centroid from %s\n", c->elements);
    fprintf(out, "error of an entry: e_ij = |G_ij - F_ij| / max(|F_ij|, %g), G theirs, "
                 "F ours, row i = from element i\n", k->floor);
    fprintf(out, "entries:                    %.0f\n", nn);
    fprintf(out, "  equal bit for bit:        %ld\n", k->exact);
    if (k->beyond_estimate >= 0) {
        /* radi_ff_pair's errest is an estimate (formfactor.h), not a bound */
        fprintf(out, "  beyond our own estimate:  %ld  (|G_ij - F_ij| > our error estimate)\n",
                k->beyond_estimate);
        fprintf(out, "our error estimate as e:    %.3g at most over the entries\n",
                k->max_own_err);
    } else
        fprintf(out, "our own error:              not estimated (classic mode)\n");
    if (k->nworst_found > 0 && k->max_err > 0)
        fprintf(out, "largest error:              %.3g at i = %d, j = %d\n", k->max_err,
                k->worst[0].i, k->worst[0].j);
    else
        fprintf(out, "largest error:              %.3g\n", k->max_err);
    fprintf(out, "RMS error:                  %.3g\n", k->rms_err);
}

static void worst_pairs(FILE *out, const compare_ctx *c)
{
    const rad_mesh *m = c->mesh;
    if (c->cmp->nworst_found == 0)
        return;
    fprintf(out, "\nworst pairs (surface numbers 0-based in file order):\n"
                 "%6s %6s %12s %12s %9s %5s %5s %29s %29s %9s %9s %9s\n",
            "i", "j", "F_ours", "F_theirs", "error", "S_i", "S_j", "centroid_i",
            "centroid_j", "area_i", "area_j", "distance");
    for (int k = 0; k < c->cmp->nworst_found; k++) {
        const rad_ffcmp_pair *p = &c->cmp->worst[k];
        const rad_element *a = &m->elements[p->i], *b = &m->elements[p->j];
        fprintf(out, "%6d %6d %12.6g %12.6g %9.3g %5d %5d   (%7.3g, %7.3g, %7.3g)   "
                     "(%7.3g, %7.3g, %7.3g) %9.3g %9.3g %9.3g\n",
                p->i, p->j, p->ours, p->theirs, p->err, a->surface, b->surface, a->centroid.x,
                a->centroid.y, a->centroid.z, b->centroid.x, b->centroid.y, b->centroid.z,
                a->area, b->area, distance(m, p->i, p->j));
    }
}

static void worst_rows(FILE *out, const compare_ctx *c)
{
    const int nr = c->nrows < c->mesh->nelements ? c->nrows : c->mesh->nelements;
    if (nr <= 0)
        return;
    fprintf(out, "\nworst rows (row i = from element i):\n%6s %9s %9s %19s %19s\n", "i",
            "max", "rms", "sum_j F_ours", "sum_j F_theirs");
    for (int k = 0; k < nr; k++) {
        const rad_ffcmp_row *r = &c->cmp->rows[k];
        fprintf(out, "%6d %9.3g %9.3g %19.15f %19.15f\n", r->i, r->max, r->rms, r->sum_ours,
                r->sum_theirs);
    }
}

static void identities(FILE *out, const compare_ctx *c)
{
    const rad_ffcmp *k = c->cmp;
    fprintf(out, "\nclosure, max_i |1 - sum_j F_ij| (0 in a closed scene):\n"
                 "  ours    %.3g (row %d)\n  theirs  %.3g (row %d)\n",
            k->closure_ours, k->closure_ours_row, k->closure_theirs, k->closure_theirs_row);
    fprintf(out, "row sums differ by at most %.3g (row %d)\n", k->max_rowsum_diff,
            k->rowsum_diff_row);
    fprintf(out, "reciprocity of theirs, |A_i G_ij - A_j G_ji|:\n"
                 "  largest     %.3g at i = %d, j = %d\n"
                 "  relative    %.3g at i = %d, j = %d (of max(A_i G_ij, A_j G_ji))\n",
            k->recip_abs, k->recip_abs_i, k->recip_abs_j, k->recip_rel, k->recip_rel_i,
            k->recip_rel_j);
}

int compare_print_text(FILE *out, const void *ctx)
{
    const compare_ctx *c = ctx;
    head(out, c);
    worst_pairs(out, c);
    worst_rows(out, c);
    identities(out, c);
    if (c->has_tolerance)
        fprintf(out, "\nverdict: the largest error %.3g is %s the tolerance %g\n",
                c->cmp->max_err, compare_within(c) ? "within" : "OUTSIDE", c->tolerance);
    return ferror(out) ? -1 : 0;
}

/* ---- JSON ---------------------------------------------------------------- */

static void num(FILE *out, const char *key, double v, const char *end)
{
    if (isfinite(v))
        fprintf(out, "  \"%s\": %.17g%s\n", key, v, end);
    else
        fprintf(out, "  \"%s\": null%s\n", key, end);
}

/* A JSON string (paths may hold quotes or backslashes). */
static void str(FILE *out, const char *key, const char *s)
{
    fprintf(out, "  \"%s\": ", key);
    radi_json_string(out, s);
    fputs(",\n", out);
}

static void json_pairs(FILE *out, const compare_ctx *c)
{
    fputs("  \"worst_pairs\": [", out);
    for (int k = 0; k < c->cmp->nworst_found; k++) {
        const rad_ffcmp_pair *p = &c->cmp->worst[k];
        const rad_element *a = &c->mesh->elements[p->i], *b = &c->mesh->elements[p->j];
        fprintf(out, "%s\n    {\"i\": %d, \"j\": %d, \"F_ours\": %.17g, ", k ? "," : "",
                p->i, p->j, p->ours);
        if (isfinite(p->theirs))
            fprintf(out, "\"F_theirs\": %.17g, \"error\": %.17g, ", p->theirs, p->err);
        else
            fputs("\"F_theirs\": null, \"error\": null, ", out);
        fprintf(out, "\"surface_i\": %d, \"surface_j\": %d, \"area_i\": %.17g, "
                     "\"area_j\": %.17g, \"distance\": %.17g}",
                a->surface, b->surface, a->area, b->area, distance(c->mesh, p->i, p->j));
    }
    fputs("\n  ],\n", out);
}

static void json_rows(FILE *out, const compare_ctx *c)
{
    const int nr = c->nrows < c->mesh->nelements ? c->nrows : c->mesh->nelements;
    fputs("  \"worst_rows\": [", out);
    for (int k = 0; k < nr; k++) {
        const rad_ffcmp_row *r = &c->cmp->rows[k];
        fprintf(out, "%s\n    {\"i\": %d, \"max\": ", k ? "," : "", r->i);
        fprintf(out, isfinite(r->max) ? "%.17g" : "null", r->max);
        fprintf(out, ", \"rms\": ");
        fprintf(out, isfinite(r->rms) ? "%.17g" : "null", r->rms);
        fprintf(out, ", \"sum_ours\": %.17g, \"sum_theirs\": ", r->sum_ours);
        fprintf(out, isfinite(r->sum_theirs) ? "%.17g}" : "null}", r->sum_theirs);
    }
    fputs("\n  ],\n", out);
}

/* The histogram: counts per quarter decade from 10^log10_lo on. */
static void json_histogram(FILE *out, const rad_ffcmp *k)
{
    fprintf(out, "  \"histogram\": {\"log10_lo\": %g, \"log10_bin\": %g, \"zero\": %ld, "
                 "\"over\": %ld, \"counts\": [", RAD_FFCMP_LOG_LO, RAD_FFCMP_BIN, k->hist_zero,
            k->hist_over);
    for (int b = 0; b < RAD_FFCMP_BINS; b++)
        fprintf(out, "%s%ld", b ? ", " : "", k->hist[b]);
    fputs("]},\n", out);
}

int compare_print_json(FILE *out, const void *ctx)
{
    const compare_ctx *c = ctx;
    const rad_ffcmp *k = c->cmp;
    fputs("{\n", out);
    str(out, "scene", c->scene);
    str(out, "matrix", c->matrix);
    str(out, "format", c->format);
    str(out, "elements_table", c->elements);
    fprintf(out, "  \"elements\": %d,\n  \"accuracy\": \"%s\",\n", c->mesh->nelements,
            rad_accuracy_name(c->accuracy));
    num(out, "floor", k->floor, ",");
    fprintf(out, "  \"entries_exact\": %ld,\n", k->exact);
    num(out, "entries_beyond_estimate", k->beyond_estimate >= 0 ? (double)k->beyond_estimate
                                                                : NAN, ",");
    num(out, "own_error_max", k->max_own_err, ",");
    num(out, "max_error", k->max_err, ",");
    num(out, "rms_error", k->rms_err, ",");
    if (k->nworst_found > 0)
        fprintf(out, "  \"max_error_pair\": [%d, %d],\n", k->worst[0].i, k->worst[0].j);
    else
        fputs("  \"max_error_pair\": null,\n", out);
    json_pairs(out, c);
    json_rows(out, c);
    json_histogram(out, k);
    num(out, "closure_ours", k->closure_ours, ",");
    fprintf(out, "  \"closure_ours_row\": %d,\n", k->closure_ours_row);
    num(out, "closure_theirs", k->closure_theirs, ",");
    fprintf(out, "  \"closure_theirs_row\": %d,\n", k->closure_theirs_row);
    num(out, "max_row_sum_difference", k->max_rowsum_diff, ",");
    fprintf(out, "  \"row_sum_difference_row\": %d,\n", k->rowsum_diff_row);
    num(out, "reciprocity_abs", k->recip_abs, ",");
    fprintf(out, "  \"reciprocity_abs_pair\": [%d, %d],\n", k->recip_abs_i, k->recip_abs_j);
    num(out, "reciprocity_rel", k->recip_rel, ",");
    fprintf(out, "  \"reciprocity_rel_pair\": [%d, %d],\n", k->recip_rel_i, k->recip_rel_j);
    num(out, "tolerance", c->has_tolerance ? c->tolerance : NAN, ",");
    fprintf(out, "  \"within_tolerance\": %s,\n", compare_within(c) ? "true" : "false");
    num(out, "seconds_read", c->seconds_read, ",");
    num(out, "seconds_formfactor", c->seconds_ff, "");
    fputs("}\n", out);
    return ferror(out) ? -1 : 0;
}

/* ---- the histogram --------------------------------------------------------- */

int compare_plot(FILE *out, const void *ctx)
{
    const compare_ctx *c = ctx;
    const rad_ffcmp *k = c->cmp;
    int lo = RAD_FFCMP_BINS, hi = -1;
    for (int b = 0; b < RAD_FFCMP_BINS; b++)
        if (k->hist[b] > 0)
            lo = b < lo ? b : lo, hi = b;
    if (hi < 0)
        lo = hi = 0;
    lo = lo > 0 ? lo - 1 : lo;
    hi = hi < RAD_FFCMP_BINS - 1 ? hi + 1 : hi;
    /* a step curve: each bin drawn from its lower to its upper edge */
    double x[2 * RAD_FFCMP_BINS], y[2 * RAD_FFCMP_BINS];
    int np = 0;
    for (int b = lo; b <= hi; b++) {
        x[np] = RAD_FFCMP_LOG_LO + RAD_FFCMP_BIN * b;
        y[np++] = (double)k->hist[b];
        x[np] = x[np - 1] + RAD_FFCMP_BIN;
        y[np++] = (double)k->hist[b];
    }
    char title[160];
    snprintf(title, sizeof title, "%s: %ld entries equal, %ld above 1e3 (not drawn)",
             c->matrix, k->hist_zero, k->hist_over);
    const rad_series s = {"entries", x, y, np};
    const rad_plot_spec spec = {title, "log10 of the error e_ij", "entries per 1/4 decade",
                                0, 0, 0, 0};
    rad_error err;
    if (radi_plot_xy(&s, 1, &spec, out, &err) != RAD_OK) {
        cli_error_rec(&err);
        return -1;
    }
    return 0;
}
