/* test_compare.c -- the compare module: another solver's form factors
 * against ours (ffcompare.h), its elements matched to ours by centroid
 * (elmatch.h), and the RMS error of Cohen et al. 1988, eq. 14
 * (rmserror.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * References, all worked by hand in the comments:
 *   ffcompare  a 4 x 4 matrix F built to be reciprocal (F_ij = S_ij / A_i,
 *              S symmetric), every entry a power-of-two fraction, against
 *              copies with known perturbations: one entry moved, entries
 *              below the floor, a row scaled, the transpose, a non-finite
 *              entry.  Each e_ij = |G_ij - F_ij| / max(|F_ij|, floor) is
 *              then one exactly rounded division, and every sum of the
 *              row sums is exact: those figures are compared with ==.  The
 *              RMS values are a square root of an exact sum or of a few
 *              rounded terms: relative 1e-15 (a few ulps).
 *   elmatch    a hand-made mesh whose bounding-box diagonal is 13 (the
 *              vertices (0,0,0) and (3,4,12)), so the tolerance is
 *              RAD_MATCH_TOL * 13; a permuted, jittered table read back to
 *              the permutation; a real mesh's own table (rad_export_elements,
 *              the writer of `solve --elements`); every refusal elmatch.h
 *              lists, each "FILE:LINE: ..." at the line it names.
 *   rmserror   eq. 14 and its per-band mean on 3 elements by hand.  Inputs
 *              like 0.3 are not exact and B - Bref rounds: relative 1e-14
 *              (some 50 ulps of a handful of operations on O(1) values).
 */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/export.h"
#include "compare/elmatch.h"
#include "compare/ffcompare.h"
#include "compare/rmserror.h"
#include "../tap.h"

/* Bit-for-bit equality (NaN equals NaN), with both values printed. */
static void same(double got, double want, const char *what)
{
    const int ok = got == want || (isnan(got) && isnan(want));
    tap_ok(ok, "%s: got %.17g want %.17g", what, got, want);
}

/* ==== ffcompare ========================================================== */

#define N 4

/* Our matrix, by rows (F_ij, row i = from element i), and the areas.
 * S_ij = A_i F_ij is symmetric: S_01 = 1/4, S_02 = 1/2, S_03 = 0 (a
 * coplanar pair), S_12 = 3/4, S_13 = 1/8, S_23 = 1/8, with
 * A = (1, 2, 4, 1/2).  Row sums 3/4, 9/16, 11/32, 1/2, so |1 - sum| =
 * 1/4, 7/16, 21/32, 1/2: closure 21/32 = 0.65625 at row 2. */
static const double FROW[N][N] = {{0, 0.25, 0.5, 0},
                                  {0.125, 0, 0.375, 0.0625},
                                  {0.125, 0.1875, 0, 0.03125},
                                  {0, 0.25, 0.25, 0}};
static const double AREA[N] = {1, 2, 4, 0.5};
static const double FLOOR = 0x1p-20; /* the floor of every run but one */

/* The library's layout: M[i + j*n] = M_ij. */
static void ours(double *F)
{
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            F[i + j * N] = FROW[i][j];
}

static int run(rad_ffcmp *c, const double *G, const double *F, const double *E, double floor,
               int nworst)
{
    rad_error err;
    memset(c, 0, sizeof *c);
    c->floor = floor;
    c->nworst = nworst;
    const rad_status st = radi_ffcmp_run(c, G, F, E, AREA, N, &err);
    if (st != RAD_OK)
        tap_ok(0, "radi_ffcmp_run: %s", err.message);
    return st == RAD_OK;
}

/* The row figures of element i (the rows are sorted by their max); a
 * row of NaN that fails every check if it is missing. */
static const rad_ffcmp_row *row_of(const rad_ffcmp *c, int i)
{
    static const rad_ffcmp_row none = {-1, NAN, NAN, NAN, NAN};
    for (int k = 0; k < N; k++)
        if (c->rows[k].i == i)
            return &c->rows[k];
    return &none;
}

static long hist_total(const rad_ffcmp *c)
{
    long t = 0;
    for (int b = 0; b < RAD_FFCMP_BINS; b++)
        t += c->hist[b];
    return t;
}

/* The bin an error falls in, found from the edges alone. */
static int bin_by_edges(double e)
{
    for (int b = 0; b < RAD_FFCMP_BINS; b++)
        if (radi_ffcmp_bin_edge(b) <= e && e < radi_ffcmp_bin_edge(b + 1))
            return b;
    return -1;
}

static int rows_order(const rad_ffcmp *c, int r0, int r1, int r2, int r3)
{
    return c->rows[0].i == r0 && c->rows[1].i == r1 && c->rows[2].i == r2 && c->rows[3].i == r3;
}

static int pair_is(const rad_ffcmp_pair *p, int i, int j, double ours_v, double theirs, double e)
{
    return p->i == i && p->j == j && p->ours == ours_v && p->theirs == theirs && p->err == e;
}

/* G = F: nothing differs; the figures of F alone are still reported. */
static void test_ff_equal(void)
{
    double F[N * N], G[N * N], E[N * N];
    rad_ffcmp c;
    ours(F);
    memcpy(G, F, sizeof G);
    if (!run(&c, G, F, NULL, FLOOR, 5))
        return;
    same(c.max_err, 0, "equal: max e");
    same(c.rms_err, 0, "equal: RMS e");
    tap_ok(c.exact == N * N, "equal: all %d entries exact (%ld)", N * N, c.exact);
    tap_ok(c.nworst_found == 0, "equal: no worst pair (e = 0 is never one) (%d)", c.nworst_found);
    tap_ok(c.hist_zero == N * N && c.hist_over == 0 && hist_total(&c) == 0,
           "equal: histogram all in e = 0 (%ld, %ld, %ld)", c.hist_zero, c.hist_over,
           hist_total(&c));
    tap_ok(c.beyond_estimate == -1 && isnan(c.max_own_err),
           "equal, no E: beyond_estimate -1, max_own_err NaN (%ld, %g)", c.beyond_estimate,
           c.max_own_err);
    tap_ok(rows_order(&c, 0, 1, 2, 3), "equal: rows of equal max in index order");
    int rows_ok = 1;
    for (int i = 0; i < N; i++) {
        const rad_ffcmp_row *r = row_of(&c, i);
        double s = 0;
        for (int j = 0; j < N; j++)
            s += FROW[i][j];
        rows_ok &= r && r->max == 0 && r->rms == 0 && r->sum_ours == s && r->sum_theirs == s;
    }
    tap_ok(rows_ok, "equal: each row max 0, RMS 0, both sums the row's sum");
    same(c.closure_ours, 0.65625, "equal: closure of ours |1 - 11/32|");
    same(c.closure_theirs, 0.65625, "equal: closure of theirs |1 - 11/32|");
    tap_ok(c.closure_ours_row == 2 && c.closure_theirs_row == 2, "equal: closure rows 2, 2 (%d, %d)",
           c.closure_ours_row, c.closure_theirs_row);
    same(c.max_rowsum_diff, 0, "equal: row sums differ by 0");
    same(c.recip_abs, 0, "equal: F is reciprocal, |A_i G_ij - A_j G_ji| = 0");
    same(c.recip_rel, 0, "equal: relative reciprocity 0");
    radi_ffcmp_free(&c);
    tap_ok(c.rows == NULL && c.worst == NULL, "radi_ffcmp_free clears the pointers");

    /* With our errors E = 2^-40 everywhere: no difference to explain, and
     * max_own_err = max E / max(|F|, floor) = 2^-40 / 2^-20 = 2^-20, from
     * the entries where F = 0 (elsewhere it is 2^-40 / |F| <= 2^-35). */
    for (int k = 0; k < N * N; k++)
        E[k] = 0x1p-40;
    if (!run(&c, G, F, E, FLOOR, 5))
        return;
    tap_ok(c.beyond_estimate == 0, "equal, E given: beyond_estimate 0 (%ld)", c.beyond_estimate);
    same(c.max_own_err, 0x1p-20, "equal, E given: max_own_err 2^-40 / floor");
    radi_ffcmp_free(&c);
}

/* One entry moved: G_01 = F_01 + d, d = 2^-10, F_01 = 1/4. */
static void test_ff_one_entry(void)
{
    const double d = 0x1p-10, e = 0x1p-8; /* e = d / (1/4) */
    double F[N * N], G[N * N], E[N * N];
    rad_ffcmp c;
    ours(F);
    memcpy(G, F, sizeof G);
    G[0 + 1 * N] += d;
    if (!run(&c, G, F, NULL, FLOOR, 5))
        return;
    same(c.max_err, e, "one entry: max e = d / F_01 = 2^-8");
    /* one e of 2^-8 among 16 entries: sqrt(2^-16 / 16) = 2^-10 */
    same(c.rms_err, 0x1p-10, "one entry: RMS e = sqrt(e^2 / 16)");
    tap_ok(c.exact == N * N - 1, "one entry: 15 exact (%ld)", c.exact);
    tap_ok(c.nworst_found == 1 && pair_is(&c.worst[0], 0, 1, 0.25, 0.25 + d, e),
           "one entry: the worst pair is (0, 1), 1/4 against 1/4 + d, e = 2^-8");
    /* log10(2^-8) = -2.408: (-2.408 + 18) / 0.25 = 62.4, bin 62, whose
     * edges are 10^-2.5 = 0.00316 and 10^-2.25 = 0.00562 */
    tap_ok(c.hist[62] == 1 && hist_total(&c) == 1 && c.hist_zero == N * N - 1 && c.hist_over == 0,
           "one entry: one count in bin 62, 15 at e = 0");
    tap_ok(bin_by_edges(e) == 62, "bin 62's edges hold 2^-8 (%d)", bin_by_edges(e));
    const rad_ffcmp_row *r0 = row_of(&c, 0);
    tap_ok(c.rows[0].i == 0 && r0->max == e && r0->rms == 0x1p-9,
           "one entry: row 0 first, max 2^-8, RMS sqrt(e^2 / 4) = 2^-9");
    tap_ok(rows_order(&c, 0, 1, 2, 3), "one entry: then rows 1, 2, 3 (max 0, by index)");
    same(r0->sum_theirs, 0.75 + d, "one entry: row 0 theirs sums to 3/4 + d");
    same(c.max_rowsum_diff, d, "one entry: row sums differ by d");
    tap_ok(c.rowsum_diff_row == 0, "one entry: in row 0 (%d)", c.rowsum_diff_row);
    /* theirs: |1 - sum| = 1/4 - d, 7/16, 21/32, 1/2: still row 2 */
    same(c.closure_theirs, 0.65625, "one entry: closure of theirs unchanged, 21/32");
    /* A_0 G_01 = 1/4 + d against A_1 G_10 = 2 (1/8) = 1/4 */
    same(c.recip_abs, d, "one entry: |A_0 G_01 - A_1 G_10| = d");
    same(c.recip_rel, d / (0.25 + d), "one entry: relative reciprocity d / (1/4 + d)");
    tap_ok(c.recip_abs_i == 0 && c.recip_abs_j == 1 && c.recip_rel_i == 0 && c.recip_rel_j == 1,
           "one entry: both at the pair (0, 1)");
    radi_ffcmp_free(&c);

    /* against our estimates: |G - F| > E counts, |G - F| = E does not */
    for (int k = 0; k < N * N; k++)
        E[k] = 0x1p-40;
    if (run(&c, G, F, E, FLOOR, 5))
        tap_ok(c.beyond_estimate == 1, "one entry, E = 2^-40: 1 beyond the estimate (%ld)",
               c.beyond_estimate);
    radi_ffcmp_free(&c);
    E[0 + 1 * N] = d;
    if (run(&c, G, F, E, FLOOR, 5))
        tap_ok(c.beyond_estimate == 0, "one entry, E_01 = d: explained (%ld)", c.beyond_estimate);
    radi_ffcmp_free(&c);
    E[0 + 1 * N] = d / 2;
    if (run(&c, G, F, E, FLOOR, 5))
        tap_ok(c.beyond_estimate == 1, "one entry, E_01 = d/2: beyond (%ld)", c.beyond_estimate);
    radi_ffcmp_free(&c);

    /* floor 1/2 > F_01 = 1/4: the difference in units of the floor,
     * e = d / (1/2) = 2^-9 */
    if (run(&c, G, F, NULL, 0.5, 5))
        same(c.max_err, 0x1p-9, "floor 1/2 above F_01: e = d / floor = 2^-9");
    radi_ffcmp_free(&c);
}

/* Entries where F = 0 (the floor's units), a large error, and the order
 * of the worst pairs, the rows and the histogram.  floor = 2^-20:
 *   G_03 = 3 floor        F_03 = 0        e = 3
 *   G_22 = floor / 4      F_22 = 0        e = 1/4
 *   G_10 = 1/8 - 2^-12    F_10 = 1/8      e = 2^-12 / 2^-3 = 2^-9
 *   G_32 = 2500           F_32 = 1/4      e = 2499.75 / 0.25 = 9999 */
static void test_ff_floor_and_order(void)
{
    double F[N * N], G[N * N];
    rad_ffcmp c;
    ours(F);
    memcpy(G, F, sizeof G);
    G[0 + 3 * N] = 3 * FLOOR;
    G[2 + 2 * N] = FLOOR / 4;
    G[1 + 0 * N] = 0.125 - 0x1p-12;
    G[3 + 2 * N] = 2500;
    if (!run(&c, G, F, NULL, FLOOR, 3))
        return;
    same(c.max_err, 9999, "floor: max e 9999");
    tap_close(c.rms_err, sqrt((9999.0 * 9999 + 9 + 0.0625 + 0x1p-18) / 16), 1e-15,
              "floor: RMS e = sqrt((9999^2 + 3^2 + (1/4)^2 + (2^-9)^2) / 16)");
    tap_ok(c.exact == 12, "floor: 12 exact (%ld)", c.exact);
    tap_ok(c.nworst_found == 3 && pair_is(&c.worst[0], 3, 2, 0.25, 2500, 9999) &&
               pair_is(&c.worst[1], 0, 3, 0, 3 * FLOOR, 3) &&
               pair_is(&c.worst[2], 2, 2, 0, FLOOR / 4, 0.25),
           "floor, nworst 3: (3,2) e 9999, (0,3) e 3 = 3 floor / floor, (2,2) e 1/4");
    /* bins: log10 3 = 0.477 -> 73.9 -> 73; log10 1/4 = -0.602 -> 69.6 ->
     * 69; log10 2^-9 = -2.709 -> 61.2 -> 61; log10 9999 = 4.0 > 3: over */
    tap_ok(c.hist[73] == 1 && c.hist[69] == 1 && c.hist[61] == 1 && hist_total(&c) == 3 &&
               c.hist_over == 1 && c.hist_zero == 12,
           "floor: bins 73, 69, 61, one over 1e3, 12 zero");
    tap_ok(bin_by_edges(3) == 73 && bin_by_edges(0.25) == 69 && bin_by_edges(0x1p-9) == 61 &&
               bin_by_edges(9999) == -1,
           "floor: those bins by their edges");
    same(radi_ffcmp_bin_edge(0), 1e-18, "bin 0 starts at 1e-18");
    tap_close(radi_ffcmp_bin_edge(RAD_FFCMP_BINS), 1e3, 1e-15, "the last bin ends at 1e3");
    tap_ok(rows_order(&c, 3, 0, 2, 1), "floor: rows by max: 3 (9999), 0 (3), 2 (1/4), 1 (2^-9)");
    tap_ok(row_of(&c, 3)->rms == 9999.0 / 2 && row_of(&c, 0)->rms == 1.5 &&
               row_of(&c, 2)->rms == 0.125 && row_of(&c, 1)->rms == 0x1p-10,
           "floor: row RMS = e / sqrt(4) for their one error each");
    /* row 3 of theirs: 0 + 1/4 + 2500 + 0 = 2500.25, ours 1/2 */
    same(c.max_rowsum_diff, 2499.75, "floor: row sums differ by 2500.25 - 1/2");
    same(c.closure_theirs, 2499.25, "floor: closure of theirs |1 - 2500.25|");
    tap_ok(c.rowsum_diff_row == 3 && c.closure_theirs_row == 3, "floor: both in row 3");
    /* reciprocity of G: (2,3): A_2 G_23 = 4/32 = 1/8, A_3 G_32 = 1250,
     * d = 1249.875, the largest; (0,3): A_0 G_03 = 3 floor, A_3 G_30 = 0,
     * relative 1, the largest; (0,1): 1/4 against 1/4 - 2^-11 */
    same(c.recip_abs, 1249.875, "floor: largest |A_i G_ij - A_j G_ji| = |1/8 - 1250|");
    tap_ok(c.recip_abs_i == 2 && c.recip_abs_j == 3, "floor: at (2, 3)");
    same(c.recip_rel, 1, "floor: largest relative: 3 floor against 0");
    tap_ok(c.recip_rel_i == 0 && c.recip_rel_j == 3, "floor: at (0, 3), not the absolute's pair");
    radi_ffcmp_free(&c);

    if (run(&c, G, F, NULL, FLOOR, 10))
        tap_ok(c.nworst_found == 4 && pair_is(&c.worst[3], 1, 0, 0.125, 0.125 - 0x1p-12, 0x1p-9),
               "floor, nworst 10: 4 found, the last (1,0) e 2^-9");
    radi_ffcmp_free(&c);
    if (run(&c, G, F, NULL, FLOOR, 0))
        tap_ok(c.nworst_found == 0 && c.max_err == 9999, "floor, nworst 0: none kept, max still");
    radi_ffcmp_free(&c);
}

/* Equal errors: the worst pairs keep the order met, column by column.
 * (1,0), (0,1), (0,2) all scaled by 1 + 2^-4: e = 2^-4 each. */
static void test_ff_ties(void)
{
    double F[N * N], G[N * N];
    rad_ffcmp c;
    ours(F);
    memcpy(G, F, sizeof G);
    G[1 + 0 * N] *= 1 + 0x1p-4;
    G[0 + 1 * N] *= 1 + 0x1p-4;
    G[0 + 2 * N] *= 1 + 0x1p-4;
    if (!run(&c, G, F, NULL, FLOOR, 2))
        return;
    tap_ok(c.nworst_found == 2 && c.worst[0].i == 1 && c.worst[0].j == 0 && c.worst[1].i == 0 &&
               c.worst[1].j == 1 && c.worst[0].err == 0x1p-4 && c.worst[1].err == 0x1p-4,
           "ties, nworst 2: (1,0) then (0,1), as met in column order");
    tap_ok(rows_order(&c, 0, 1, 2, 3), "ties: rows 0 and 1 (max 2^-4) by index, then 2, 3");
    /* row 0: two errors 2^-4 of four: RMS sqrt(2 * 2^-8 / 4) = 2^-4 / sqrt 2 */
    tap_close(row_of(&c, 0)->rms, 0x1p-4 / sqrt(2), 1e-15, "ties: row 0 RMS 2^-4 / sqrt(2)");
    radi_ffcmp_free(&c);
}

/* Row 2 of theirs is 3 times ours: e = |3F - F| / F = 2 on its three
 * nonzero entries; its diagonal stays 0 = 3 * 0. */
static void test_ff_row_scaled(void)
{
    double F[N * N], G[N * N];
    rad_ffcmp c;
    ours(F);
    memcpy(G, F, sizeof G);
    for (int j = 0; j < N; j++)
        G[2 + j * N] *= 3;
    if (!run(&c, G, F, NULL, FLOOR, 5))
        return;
    same(c.max_err, 2, "row x3: max e = (3 - 1) F / F = 2");
    tap_close(c.rms_err, sqrt(3 * 4.0 / 16), 1e-15, "row x3: RMS e = sqrt(3 * 2^2 / 16)");
    tap_ok(c.exact == 13, "row x3: 13 exact, the diagonal among them (%ld)", c.exact);
    const rad_ffcmp_row *r2 = row_of(&c, 2);
    tap_ok(rows_order(&c, 2, 0, 1, 3) && r2->max == 2, "row x3: row 2 first, max 2");
    tap_close(r2->rms, sqrt(3 * 4.0 / 4), 1e-15, "row x3: row 2 RMS sqrt(3 * 2^2 / 4)");
    same(r2->sum_ours, 0.34375, "row x3: row 2 ours sums to 11/32");
    same(r2->sum_theirs, 1.03125, "row x3: row 2 theirs sums to 3 * 11/32 = 33/32");
    same(c.max_rowsum_diff, 0.6875, "row x3: row sums differ by 2 * 11/32");
    tap_ok(c.rowsum_diff_row == 2, "row x3: in row 2 (%d)", c.rowsum_diff_row);
    /* theirs: |1 - sum| = 1/4, 7/16, 1/32, 1/2 */
    same(c.closure_theirs, 0.5, "row x3: closure of theirs 1/2");
    tap_ok(c.closure_theirs_row == 3, "row x3: at row 3 (%d)", c.closure_theirs_row);
    same(c.closure_ours, 0.65625, "row x3: closure of ours still 21/32");
    tap_ok(c.closure_ours_row == 2, "row x3: ours at row 2 (%d)", c.closure_ours_row);
    /* pairs with element 2: A_2 G_2j = 3 S_2j against A_j G_j2 = S_2j,
     * d = 2 S_2j: (0,2) 1, (1,2) 3/2, (2,3) 1/4; relative 2S / 3S = 2/3 */
    same(c.recip_abs, 1.5, "row x3: largest |A_i G_ij - A_j G_ji| = 2 S_12 = 3/2");
    tap_ok(c.recip_abs_i == 1 && c.recip_abs_j == 2, "row x3: at (1, 2)");
    same(c.recip_rel, 2.0 / 3, "row x3: relative (3 - 1) / 3");
    tap_ok(c.recip_rel_i == 2 || c.recip_rel_j == 2, "row x3: at a pair of element 2 (%d, %d)",
           c.recip_rel_i, c.recip_rel_j);
    radi_ffcmp_free(&c);
}

/* Theirs is our transpose: reciprocity breaks wherever the areas differ.
 * A_i G_ij - A_j G_ji = A_i F_ji - A_j F_ij = S_ij (A_i/A_j - A_j/A_i):
 *   (0,1) 1/4 * 3/2 = 0.375      (0,2) 1/2 * 15/4 = 1.875
 *   (0,3) 0                      (1,2) 3/4 * 3/2 = 1.125
 *   (1,3) 1/8 * 15/4 = 0.46875   (2,3) 1/8 * 63/8 = 0.984375
 * relative 1 - (A_small / A_large)^2: largest where the areas differ most,
 * (2,3) (8 times): 1 - 1/64 = 63/64. */
static void test_ff_transposed(void)
{
    double F[N * N], G[N * N];
    rad_ffcmp c;
    ours(F);
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            G[i + j * N] = FROW[j][i];
    if (!run(&c, G, F, NULL, FLOOR, 5))
        return;
    same(c.recip_abs, 1.875, "transposed: largest |A_i G_ij - A_j G_ji| = 1.875");
    tap_ok(c.recip_abs_i == 0 && c.recip_abs_j == 2, "transposed: at (0, 2) (%d, %d)",
           c.recip_abs_i, c.recip_abs_j);
    same(c.recip_rel, 63.0 / 64, "transposed: largest relative 1 - (1/8)^2 = 63/64");
    tap_ok(c.recip_rel_i == 2 && c.recip_rel_j == 3, "transposed: at (2, 3) (%d, %d)",
           c.recip_rel_i, c.recip_rel_j);
    /* e_23 = |F_32 - F_23| / F_23 = (1/4 - 1/32) / (1/32) = 7, the largest */
    same(c.max_err, 7, "transposed: max e = (1/4 - 1/32) / (1/32)");
    tap_ok(c.worst[0].i == 2 && c.worst[0].j == 3, "transposed: worst pair (2, 3)");
    tap_ok(c.exact == 6, "transposed: 6 exact, the diagonal and F_03 = F_30 = 0 (%ld)", c.exact);
    /* their row sums are our column sums: 1/4, 11/16, 9/8, 3/32 */
    tap_ok(row_of(&c, 0)->sum_theirs == 0.25 && row_of(&c, 1)->sum_theirs == 0.6875 &&
               row_of(&c, 2)->sum_theirs == 1.125 && row_of(&c, 3)->sum_theirs == 0.09375,
           "transposed: their row sums are our column sums");
    /* |column sum - row sum|: 1/2, 1/8, 25/32, 13/32 */
    same(c.max_rowsum_diff, 0.78125, "transposed: row sums differ by |9/8 - 11/32|");
    tap_ok(c.rowsum_diff_row == 2, "transposed: in row 2 (%d)", c.rowsum_diff_row);
    radi_ffcmp_free(&c);
}

/* A non-finite entry of theirs is the largest error, never skipped. */
static void test_ff_nonfinite(void)
{
    double F[N * N], G[N * N];
    rad_ffcmp c;
    ours(F);
    memcpy(G, F, sizeof G);
    G[1 + 3 * N] = NAN;
    if (!run(&c, G, F, NULL, FLOOR, 5))
        return;
    tap_ok(isinf(c.max_err) && isinf(c.rms_err), "NaN entry: max and RMS e infinite");
    tap_ok(c.nworst_found == 1 && c.worst[0].i == 1 && c.worst[0].j == 3 && isinf(c.worst[0].err),
           "NaN entry: the worst pair (1, 3), e infinite");
    tap_ok(c.hist_over == 1 && c.hist_zero == 15 && hist_total(&c) == 0 && c.exact == 15,
           "NaN entry: counted above the last bin, 15 exact");
    tap_ok(c.rows[0].i == 1 && isinf(c.rows[0].max), "NaN entry: row 1 first, max infinite");
    radi_ffcmp_free(&c);

    G[1 + 3 * N] = INFINITY;
    if (!run(&c, G, F, NULL, FLOOR, 5))
        return;
    tap_ok(isinf(c.max_err) && c.worst[0].i == 1 && c.worst[0].j == 3 && c.hist_over == 1,
           "infinite entry: max e infinite, at (1, 3), above the last bin");
    tap_ok(isinf(c.closure_theirs) && c.closure_theirs_row == 1 && isinf(c.max_rowsum_diff) &&
               c.rowsum_diff_row == 1,
           "infinite entry: closure and row-sum difference infinite, at row 1");
    tap_ok(isinf(c.recip_abs) && c.recip_abs_i == 1 && c.recip_abs_j == 3,
           "infinite entry: reciprocity infinite at (1, 3)");
    radi_ffcmp_free(&c);
}

static void test_ff_empty(void)
{
    rad_ffcmp c = {.floor = FLOOR, .nworst = 3};
    rad_error err;
    const double one = 0;
    tap_ok(radi_ffcmp_run(&c, &one, &one, NULL, AREA, 0, &err) == RAD_OK && c.max_err == 0 &&
               c.rms_err == 0 && c.exact == 0 && c.nworst_found == 0 && c.recip_abs == 0 &&
               c.max_rowsum_diff == 0,
           "0 x 0: RAD_OK, every figure 0");
    radi_ffcmp_free(&c);
}

/* ==== elmatch ============================================================ */

#define NE 6

/* A hand-made mesh: centroids only, and two vertices spanning the box
 * (0,0,0)-(3,4,12), whose diagonal is sqrt(9 + 16 + 144) = 13. */
static const rad_vec3 CENTROID[NE] = {{0.5, 0.5, 0.5}, {1.5, 0.5, 1}, {2.5, 3.5, 11},
                                      {0.5, 3.5, 6},   {2, 2, 2},     {1, 1, 9}};
static const double TOL = RAD_MATCH_TOL * 13;

static rad_vec3 hand_v[2] = {{0, 0, 0}, {3, 4, 12}};

/* The mesh of the NE centroids c, its elements in el (caller's). */
static rad_mesh hand_mesh(rad_element el[NE], const rad_vec3 *c)
{
    rad_mesh m;
    memset(&m, 0, sizeof m);
    memset(el, 0, sizeof *el * NE);
    for (int e = 0; e < NE; e++)
        el[e].centroid = c[e];
    m.nelements = NE;
    m.elements = el;
    m.nvertices = 2;
    m.vertices = hand_v;
    return m;
}

static char tmpdir[256];
static int nfiles;

/* text into a new file of the scratch folder: its path (static). */
static const char *put(const char *text)
{
    static char path[300];
    snprintf(path, sizeof path, "%s/t%02d.tsv", tmpdir, nfiles++);
    FILE *f = fopen(path, "w");
    if (!f)
        return NULL;
    fputs(text, f);
    fclose(f);
    return path;
}

/* Rows "k cx cy cz" appended to buf. */
static void add_row(char *buf, size_t size, long k, rad_vec3 c)
{
    const size_t len = strlen(buf);
    snprintf(buf + len, size - len, "%ld %.17g %.17g %.17g\n", k, c.x, c.y, c.z);
}

static rad_vec3 plus(rad_vec3 a, double dx, double dy, double dz)
{
    return (rad_vec3){a.x + dx, a.y + dy, a.z + dz};
}

/* The identity table of the hand mesh, with row `moved` at centroid c. */
static void identity_table(char *buf, size_t size, int moved, rad_vec3 c)
{
    snprintf(buf, size, "element cx cy cz\n");
    for (int k = 0; k < NE; k++)
        add_row(buf, size, k, k == moved ? c : CENTROID[k]);
}

/* A refusal: RAD_ERR_PARSE, "PATH:LINE: ..." holding `words`. */
static void refused(const char *text, const rad_mesh *m, int line, const char *words,
                    const char *what)
{
    int perm[NE];
    rad_error err;
    char prefix[340];
    const char *path = put(text);
    if (!path) {
        tap_ok(0, "%s: scratch file", what);
        return;
    }
    const rad_status st = radi_elements_match(path, m, perm, &err);
    snprintf(prefix, sizeof prefix, "%s:%d: ", path, line);
    tap_ok(st == RAD_ERR_PARSE && strncmp(err.message, prefix, strlen(prefix)) == 0 &&
               strstr(err.message, words) != NULL,
           "%s: refused at line %d (%s)", what, line, st ? err.message : "accepted");
}

/* Their element k is our sigma[k], listed in a shuffled order, jittered
 * well inside the tolerance, with the columns of `solve --elements` (the
 * ones elmatch ignores among them), a comment and blank lines. */
static void test_match_permuted(void)
{
    static const int sigma[NE] = {3, 0, 5, 1, 4, 2};
    static const int order[NE] = {2, 0, 5, 3, 1, 4};
    rad_element el[NE];
    const rad_mesh m = hand_mesh(el, CENTROID);
    char text[4096];
    int perm[NE];
    rad_error err;
    size_t len = (size_t)snprintf(text, sizeof text,
                                  "# another solver's elements\n\nelement\tsurface\tgi\tgj\tcx"
                                  "\tcy\tcz\tnx\tny\tnz\tarea\tr\tg\tb\n");
    for (int r = 0; r < NE; r++) {
        const int k = order[r];
        /* |jitter| <= sqrt(6^2 + 3.5^2 + 2^2) 1e-6 = 7.2e-6 < TOL = 1.3e-5 */
        const rad_vec3 c = plus(CENTROID[sigma[k]], (k + 1) * 1e-6, -k * 0.7e-6, 2e-6);
        len += (size_t)snprintf(text + len, sizeof text - len,
                                "%d\t7\t0\t0\t%.17g\t%.17g\t%.17g\t0\t0\t1\t0.25\t9\t9\t9\n%s", k,
                                c.x, c.y, c.z, r == 2 ? "\n" : "");
    }
    const char *path = put(text);
    const rad_status st = path ? radi_elements_match(path, &m, perm, &err) : RAD_ERR_IO;
    int ok = st == RAD_OK;
    for (int k = 0; ok && k < NE; k++)
        ok = perm[k] == sigma[k];
    tap_ok(ok, "permuted, jittered table: perm = the permutation (%s)",
           st ? err.message : "matched");

    /* space-separated, columns in another order, rows in index order */
    snprintf(text, sizeof text, "cz   element cy cx\n");
    for (int k = 0; k < NE; k++) {
        const rad_vec3 c = CENTROID[sigma[k]];
        len = strlen(text);
        snprintf(text + len, sizeof text - len, "%.17g %d %.17g %.17g\n", c.z, k, c.y, c.x);
    }
    path = put(text);
    ok = path && radi_elements_match(path, &m, perm, &err) == RAD_OK;
    for (int k = 0; ok && k < NE; k++)
        ok = perm[k] == sigma[k];
    tap_ok(ok, "columns found by name in any order");
}

/* The tolerance, RAD_MATCH_TOL times the diagonal: 0.9 of it matches,
 * 1.1 of it does not. */
static void test_match_tolerance(void)
{
    rad_element el[NE];
    const rad_mesh m = hand_mesh(el, CENTROID);
    char text[2048];
    int perm[NE];
    rad_error err;
    identity_table(text, sizeof text, 4, plus(CENTROID[4], 0.9 * TOL, 0, 0));
    const char *path = put(text);
    tap_ok(path && radi_elements_match(path, &m, perm, &err) == RAD_OK && perm[4] == 4,
           "0.9 of the tolerance (1e-6 of the diagonal 13) away: matched");
    identity_table(text, sizeof text, 4, plus(CENTROID[4], 0, 0, -1.1 * TOL));
    /* the header is line 1, element 4 line 6 */
    refused(text, &m, 6, ": no element of the scene within 1.3e-05",
            "1.1 of the tolerance away");
}

/* What elmatch.h refuses, each at the line it names. */
static void test_match_refusals(void)
{
    rad_element el[NE];
    const rad_mesh m = hand_mesh(el, CENTROID);
    char text[2048];
    int perm[NE];
    rad_error err;

    /* two of ours at one centroid (the two sides of a thin wall) */
    rad_vec3 wall[NE];
    memcpy(wall, CENTROID, sizeof wall);
    wall[5] = wall[1];
    rad_element el_thin[NE];
    const rad_mesh thin = hand_mesh(el_thin, wall);
    identity_table(text, sizeof text, -1, wall[0]);
    refused(text, &thin, 3, "scene's elements 1 and 5: ambiguous",
            "thin wall: ambiguous, naming both of ours");

    /* two of ours 1.5 TOL apart, theirs midway: within TOL of both */
    rad_vec3 near[NE];
    memcpy(near, CENTROID, sizeof near);
    near[3] = plus(near[2], 1.5 * TOL, 0, 0);
    rad_element el_near[NE];
    const rad_mesh close2 = hand_mesh(el_near, near);
    identity_table(text, sizeof text, 2, plus(near[2], 0.75 * TOL, 0, 0));
    refused(text, &close2, 4, "ambiguous", "two of ours within the tolerance: ambiguous");

    /* one of ours claimed twice: their 0 and 1 both nearest to our 2 */
    snprintf(text, sizeof text, "# comment\nelement cx cy cz\n");
    add_row(text, sizeof text, 0, plus(CENTROID[2], 1e-6, 0, 0));
    add_row(text, sizeof text, 1, plus(CENTROID[2], -1e-6, 0, 0));
    refused(text, &m, 4, "element 1 matches the scene's element 2, as the element of line 3 does",
            "one of ours claimed twice");

    identity_table(text, sizeof text, -1, CENTROID[0]);
    add_row(text, sizeof text, 0, CENTROID[0]); /* a 7th row, line 8 */
    refused(text, &m, 8, "more than the scene's 6 elements", "a row too many");

    snprintf(text, sizeof text, "element cx cy cz\n");
    for (int k = 0; k < NE; k++)
        add_row(text, sizeof text, k == 3 ? 1 : k, CENTROID[k == 3 ? 1 : k]);
    refused(text, &m, 5, "element 1 is listed twice", "an element listed twice");

    snprintf(text, sizeof text, "element cx cy cz\n");
    for (int k = 0; k < NE - 1; k++)
        add_row(text, sizeof text, k, CENTROID[k]);
    refused(text, &m, 6, "5 elements; the scene has 6", "a row too few");

    static const long bad_index[2] = {6, -1};
    for (int t = 0; t < 2; t++) {
        char words[64], what[64];
        snprintf(text, sizeof text, "element cx cy cz\n");
        for (int k = 0; k < NE; k++)
            add_row(text, sizeof text, k == 5 ? bad_index[t] : k, CENTROID[k]);
        snprintf(words, sizeof words, "element must be from 0 to 5, not '%ld'", bad_index[t]);
        snprintf(what, sizeof what, "index %ld, outside 0..n-1", bad_index[t]);
        refused(text, &m, 7, words, what);
    }

    refused("\n# only a comment\n\n", &m, 3, "empty element table", "no header");
    refused("# theirs\nelement cx cy z\n0 1 2 3\n", &m, 2, "'cz' is missing", "no cz column");
    refused("element cx cy cz\n0 0.5 0.5\n", &m, 2, "3 fields; the header names more",
            "a short row");
    refused("element cx cy cz\n0 0.5 half 0.5\n", &m, 2, "'half' is not a number (cy)",
            "a centroid that is not a number");

    char missing[300];
    snprintf(missing, sizeof missing, "%s/absent.tsv", tmpdir);
    tap_ok(radi_elements_match(missing, &m, perm, &err) == RAD_ERR_IO &&
               strstr(err.message, "absent.tsv") != NULL,
           "a missing file: RAD_ERR_IO naming it (%s)", err.message);
}

/* A real mesh: its own table (as `solve --elements` writes it) matches
 * itself, and a renumbered copy reads back to the renumbering. */
static void test_match_real_mesh(void)
{
    const char *scene_text = "material w reflect 0.5\n"
                             "quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 2x2\n"
                             "quad w 0 0 1  0 1 1  1 1 1  1 0 1  mesh 2x2\n"
                             "quad w 0 0 0  0 1 0  0 1 1  0 0 1  mesh 2x2\n"
                             "quad w 1 0 0  1 0 1  1 1 1  1 1 0  mesh 2x2\n"
                             "quad w 0 0 0  0 0 1  1 0 1  1 0 0  mesh 2x2\n"
                             "quad w 0 1 0  1 1 0  1 1 1  0 1 1  mesh 2x2\n";
    rad_scene s;
    rad_mesh m;
    rad_error err;
    if (rad_scene_parse(&s, scene_text, strlen(scene_text), "cube", &err) != RAD_OK ||
        rad_mesh_build(&m, &s, &err) != RAD_OK) {
        tap_ok(0, "cube scene: %s", err.message);
        return;
    }
    const int n = m.nelements;
    int *perm = malloc(sizeof *perm * (size_t)n);
    double *B = calloc((size_t)n * RAD_BANDS, sizeof *B);
    char path[300];
    snprintf(path, sizeof path, "%s/own.tsv", tmpdir);
    FILE *f = fopen(path, "w");
    int ok = perm && B && f && rad_export_elements(f, &m, B) == 0;
    if (f)
        fclose(f);
    ok = ok && radi_elements_match(path, &m, perm, &err) == RAD_OK;
    for (int k = 0; ok && k < n; k++)
        ok = perm[k] == k;
    tap_ok(n == 24 && ok, "cube 2x2: its own element table matches itself (%d elements)", n);

    /* their k is our 7k mod 24 (7 is prime to 24) */
    char *text = malloc(80 * (size_t)(n + 1));
    ok = text != NULL;
    if (ok) {
        snprintf(text, 80, "element cx cy cz\n");
        for (int k = 0; k < n; k++)
            add_row(text, 80 * (size_t)(n + 1), k, m.elements[(7 * k) % n].centroid);
        const char *p = put(text);
        ok = p && radi_elements_match(p, &m, perm, &err) == RAD_OK;
    }
    for (int k = 0; ok && k < n; k++)
        ok = perm[k] == (7 * k) % n;
    tap_ok(ok, "cube 2x2: renumbered k -> 7k mod 24, read back");
    free(text);
    free(perm);
    free(B);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

/* ==== rmserror =========================================================== *
 *
 * Cohen, Chen, Wallace & Greenberg 1988, eq. 14:
 *
 *     RMS error = sqrt( sum_i (B_i^conv - B_i^(k))^2 A_i  /  sum_i A_i )
 *
 * with B_i the radiosity averaged over the three bands (radi_rms_eq14);
 * radi_rms_bands is the mean over the bands b of the same formula on
 * B_ib alone.  With the ambient term (eq. 13) B_i + rho_i Ambient stands
 * for B_i. */

#define NR 3

static const double RA[NR] = {1, 2, 5}; /* sum 8 */
/* The reference, by element: band means 0.3, 0.5, 0.7. */
static const double REF[NR][RAD_BANDS] = {{0.2, 0.3, 0.4}, {0.4, 0.5, 0.6}, {0.6, 0.7, 0.8}};
/* The differences B - Bref, by element, and their band means:
 *   element 0  (0.3, 0.9, 0.6)    mean 0.6
 *   element 1  (-0.3, 0, 0.3)     mean 0
 *   element 2  (0.2, 0.1, -0.6)   mean -0.1 */
static const double DIFF[NR][RAD_BANDS] = {{0.3, 0.9, 0.6}, {-0.3, 0, 0.3}, {0.2, 0.1, -0.6}};

/* out = ref + k diff + c, column-major (out[i + b n]). */
static void make_b(double *out, const double ref[NR][RAD_BANDS],
                   const double diff[NR][RAD_BANDS], double k, double c)
{
    for (int i = 0; i < NR; i++)
        for (int b = 0; b < RAD_BANDS; b++)
            out[i + b * NR] = (ref ? ref[i][b] : 0) + (diff ? k * diff[i][b] : 0) + c;
}

static void test_rms_hand(void)
{
    double B[NR * RAD_BANDS], Bref[NR * RAD_BANDS];
    make_b(Bref, REF, NULL, 0, 0);
    make_b(B, REF, DIFF, 1, 0);
    rad_rms_input in = {.n = NR, .area = RA, .total_area = 8, .B = B, .Bref = Bref};
    /* eq. 14: sqrt((1 * 0.6^2 + 2 * 0^2 + 5 * (-0.1)^2) / 8) = sqrt(0.41 / 8) = 0.22638 */
    const double eq14 = sqrt((1 * 0.6 * 0.6 + 2 * 0.0 * 0.0 + 5 * 0.1 * 0.1) / 8);
    tap_close(radi_rms_eq14(&in), eq14, 1e-14, "eq. 14: sqrt(sum A_i (mean_b d_ib)^2 / sum A)");
    /* per band: b0 sqrt((0.09 + 2 * 0.09 + 5 * 0.04) / 8) = sqrt(0.47 / 8)
     *           b1 sqrt((0.81 + 0 + 5 * 0.01) / 8)     = sqrt(0.86 / 8)
     *           b2 sqrt((0.36 + 2 * 0.09 + 5 * 0.36) / 8) = sqrt(2.34 / 8)
     * mean (0.24238 + 0.32787 + 0.54083) / 3 = 0.37036 */
    const double bands = (sqrt((1 * 0.09 + 2 * 0.09 + 5 * 0.04) / 8) +
                          sqrt((1 * 0.81 + 2 * 0.0 + 5 * 0.01) / 8) +
                          sqrt((1 * 0.36 + 2 * 0.09 + 5 * 0.36) / 8)) / 3;
    tap_close(radi_rms_bands(&in), bands, 1e-14, "per-band mean of eq. 14");

    /* equal solutions: 0 */
    in.B = Bref;
    same(radi_rms_eq14(&in), 0, "eq. 14 of equal solutions");
    same(radi_rms_bands(&in), 0, "per-band mean of equal solutions");

    /* Bref NULL: the reference is 0, and radi_rms_of is that */
    in.B = Bref;
    in.Bref = NULL;
    /* sqrt((1 * 0.3^2 + 2 * 0.5^2 + 5 * 0.7^2) / 8) = sqrt(3.04 / 8) */
    const double of = sqrt((1 * 0.09 + 2 * 0.25 + 5 * 0.49) / 8);
    tap_close(radi_rms_eq14(&in), of, 1e-14, "eq. 14 against a reference of 0");
    tap_close(radi_rms_of(NR, RA, 8, Bref), of, 1e-14, "radi_rms_of: eq. 14 of B = 0");

    /* no area: 0 */
    in.Bref = Bref;
    in.B = B;
    in.total_area = 0;
    tap_ok(radi_rms_eq14(&in) == 0 && radi_rms_bands(&in) == 0, "total area 0: 0");
    in.total_area = -8;
    tap_ok(radi_rms_eq14(&in) == 0 && radi_rms_bands(&in) == 0, "total area < 0: 0");
}

/* A uniform offset c: every difference is c, so eq. 14 is
 * sqrt(sum A c^2 / sum A) = |c|, linear in |c|, and so is each band. */
static void test_rms_offset(void)
{
    double B[NR * RAD_BANDS], Bref[NR * RAD_BANDS];
    make_b(Bref, REF, NULL, 0, 0);
    rad_rms_input in = {.n = NR, .area = RA, .total_area = 8, .B = B, .Bref = Bref};
    static const double cs[] = {0.25, 0.5, -1.5, 3e-9};
    for (size_t t = 0; t < sizeof cs / sizeof *cs; t++) {
        char what[96];
        make_b(B, REF, NULL, 0, cs[t]);
        snprintf(what, sizeof what, "offset %g: eq. 14 = |c|", cs[t]);
        /* B - Bref recovers c to an ulp of B (~1e-16): relative 1e-14 of
         * c >= 0.25, 1e-7 of c = 3e-9 */
        const double tol = fabs(cs[t]) < 1e-3 ? 1e-7 : 1e-14;
        tap_close(radi_rms_eq14(&in), fabs(cs[t]), tol, what);
        snprintf(what, sizeof what, "offset %g: per-band mean = |c|", cs[t]);
        tap_close(radi_rms_bands(&in), fabs(cs[t]), tol, what);
    }
    /* the differences scaled by k: both figures scale by |k| */
    make_b(B, REF, DIFF, 1, 0);
    const double e1 = radi_rms_eq14(&in), b1 = radi_rms_bands(&in);
    make_b(B, REF, DIFF, -3, 0);
    tap_close(radi_rms_eq14(&in), 3 * e1, 1e-14, "differences x -3: eq. 14 x 3");
    tap_close(radi_rms_bands(&in), 3 * b1, 1e-14, "differences x -3: per-band mean x 3");
}

/* Where the two readings agree and where they do not (rmserror.c). */
static void test_rms_readings(void)
{
    double B[NR * RAD_BANDS], Bref[NR * RAD_BANDS];
    make_b(Bref, REF, NULL, 0, 0);
    rad_rms_input in = {.n = NR, .area = RA, .total_area = 8, .B = B, .Bref = Bref};
    /* grey errors (every band alike): d_i = 0.1, -0.2, 0.4 -> both
     * sqrt((0.01 + 2 * 0.04 + 5 * 0.16) / 8) = sqrt(0.89 / 8) */
    static const double grey[NR][RAD_BANDS] = {{0.1, 0.1, 0.1}, {-0.2, -0.2, -0.2},
                                               {0.4, 0.4, 0.4}};
    make_b(B, REF, grey, 1, 0);
    const double g = sqrt((1 * 0.01 + 2 * 0.04 + 5 * 0.16) / 8);
    tap_close(radi_rms_eq14(&in), g, 1e-14, "grey errors: eq. 14");
    tap_close(radi_rms_bands(&in), g, 1e-14, "grey errors: per-band mean the same");
    /* opposite signs in two bands: element 0 (0.3, -0.3, 0), the rest 0:
     * the band means are 0, so eq. 14 is 0; per band sqrt(0.09 / 8) twice
     * and 0: (2 * 0.3 / sqrt 8) / 3 */
    static const double opposite[NR][RAD_BANDS] = {{0.3, -0.3, 0}, {0, 0, 0}, {0, 0, 0}};
    make_b(B, REF, opposite, 1, 0);
    tap_ok(radi_rms_eq14(&in) < 1e-16, "opposite errors: eq. 14 cancels to 0 (%g)",
           radi_rms_eq14(&in));
    tap_close(radi_rms_bands(&in), 2 * 0.3 / sqrt(8) / 3, 1e-14,
              "opposite errors: per-band mean (2 * 0.3 / sqrt 8) / 3");
}

/* eq. 13: the displayed B_i + rho_i Ambient stands for B_i. */
static void test_rms_ambient(void)
{
    double B[NR * RAD_BANDS], rho[NR * RAD_BANDS];
    static const double rhos[NR][RAD_BANDS] = {{0.5, 0.5, 0.5}, {0.8, 0.2, 0.1}, {0, 0, 0}};
    static const double amb[RAD_BANDS] = {0.1, 0.2, 0.4};
    make_b(B, REF, NULL, 0, 0);
    make_b(rho, rhos, NULL, 0, 0);
    rad_rms_input in = {.n = NR, .area = RA, .total_area = 8, .rho = rho, .amb = amb,
                        .B = B, .Bref = B};
    /* differences rho_ib amb_b: element 0 (0.05, 0.1, 0.2), mean 0.35/3;
     * element 1 (0.08, 0.04, 0.04), mean 0.16/3; element 2 0 */
    const double m0 = 0.35 / 3, m1 = 0.16 / 3;
    tap_close(radi_rms_eq14(&in), sqrt((1 * m0 * m0 + 2 * m1 * m1) / 8), 1e-14,
              "ambient: eq. 14 of rho Ambient");
    const double bands = (sqrt((1 * 0.05 * 0.05 + 2 * 0.08 * 0.08) / 8) +
                          sqrt((1 * 0.1 * 0.1 + 2 * 0.04 * 0.04) / 8) +
                          sqrt((1 * 0.2 * 0.2 + 2 * 0.04 * 0.04) / 8)) / 3;
    tap_close(radi_rms_bands(&in), bands, 1e-14, "ambient: per-band mean");
    in.amb = NULL;
    same(radi_rms_eq14(&in), 0, "no ambient: rho is not read, B = Bref gives 0");
}

/* The scaling of rmserror.c: neither A d^2 nor d^2 overflows or
 * underflows where the RMS itself is a double. */
static void test_rms_extremes(void)
{
    double B[NR * RAD_BANDS];
    const double area_big[NR] = {1e300, 2e300, 5e300};
    rad_rms_input in = {.n = NR, .area = RA, .total_area = 8, .B = B};
    make_b(B, DIFF, NULL, 0, 0);
    const double base = radi_rms_eq14(&in), base_b = radi_rms_bands(&in);
    in.area = area_big;
    in.total_area = 8e300;
    tap_close(radi_rms_eq14(&in), base, 1e-14, "areas of 1e300: eq. 14 unchanged");
    tap_close(radi_rms_bands(&in), base_b, 1e-14, "areas of 1e300: per-band mean unchanged");
    in.area = RA;
    in.total_area = 8;
    make_b(B, NULL, DIFF, 1e300, 0);
    tap_close(radi_rms_eq14(&in), 1e300 * base, 1e-14, "differences of 1e300: finite, x 1e300");
    make_b(B, NULL, DIFF, 1e-300, 0);
    tap_close(radi_rms_eq14(&in), 1e-300 * base, 1e-14, "differences of 1e-300: not 0, x 1e-300");
    tap_close(radi_rms_bands(&in), 1e-300 * base_b, 1e-14, "per-band mean at 1e-300");
}

int main(void)
{
    test_ff_equal();
    test_ff_one_entry();
    test_ff_floor_and_order();
    test_ff_ties();
    test_ff_row_scaled();
    test_ff_transposed();
    test_ff_nonfinite();
    test_ff_empty();

    const char *t = getenv("TMPDIR");
    snprintf(tmpdir, sizeof tmpdir, "%s/test_compare.XXXXXX", t && *t ? t : "/tmp");
    if (!mkdtemp(tmpdir)) {
        tap_ok(0, "scratch folder %s: %s", tmpdir, strerror(errno));
    } else {
        test_match_permuted();
        test_match_tolerance();
        test_match_refusals();
        test_match_real_mesh();
        char p[300];
        for (int k = 0; k < nfiles; k++) {
            snprintf(p, sizeof p, "%s/t%02d.tsv", tmpdir, k);
            remove(p);
        }
        snprintf(p, sizeof p, "%s/own.tsv", tmpdir);
        remove(p);
        rmdir(tmpdir);
    }

    test_rms_hand();
    test_rms_offset();
    test_rms_readings();
    test_rms_ambient();
    test_rms_extremes();
    return tap_done();
}
