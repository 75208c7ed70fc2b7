/* test_fill.c -- the fill module (src/fill/): the dense matrix, its rows per
 * shot, its blocks and pairs, per-surface sums, and the hemicube matrix.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The scene is the closed unit cube, walls facing in, meshed unevenly so
 * that elements of different areas meet (20 elements):
 *     0 bottom z = 0   1 x 1        1 top    z = 1   1 x 1   (opposed to 0)
 *     2 wall   x = 0   1 x 1        3 wall   x = 1   2 x 2   (opposed to 2)
 *     4 wall   y = 0   3 x 1        5 wall   y = 1   5 x 2   (opposed to 4)
 * The areas 1, 1/4, 1/3 and 1/10 have ratios that are not powers of two
 * (10/3, 2/5, ...), so the order of the roundings in F_ij = F_ji (A_j /
 * A_i) shows in the last bit: the bit-for-bit checks below see it.
 * Nothing in a convex room hides anything, so every entry is the
 * unoccluded contour integral of the two elements.
 *
 * What is checked, in default and reference accuracy (the promise p on
 * each entry's relative error: 1e-6 and 1e-9, formfactor.h); classic,
 * which promises nothing, gets every check that holds by construction
 * (zeros, range, reciprocity, threads, per-surface sums, the bit-for-bit
 * comparisons, the statistics) and none against a closed form:
 *   - F_ii = 0 and F_ij = 0 between elements of one wall (coplanar),
 *     exactly; no entry outside [0, 1];
 *   - reciprocity A_i F_ij = A_j F_ji: the fill integrates each pair once
 *     and writes F_ij = F_ji (A_j / A_i) (ffmatrix.c, mirror), so the two
 *     sides differ by round-off only: the mirror's two roundings, the
 *     test's two products, and each area's own round-off (the user's
 *     areas here, the unit frame's areas in the fill: a few ulps each).
 *     Those add up to some 4 ulps plus the areas' few: bound 16
 *     DBL_EPSILON relative (32 ulps);
 *   - closure: each row of the closed cube sums to 1.  Each entry is
 *     within p F_ij of the truth, so the row is within p sum_j F_ij =
 *     p (1 + O(p)) of 1, plus the summation's round-off, n DBL_EPSILON:
 *     bound p (1 + p) + n DBL_EPSILON (the fill's own RAD_ROW_SUM_SLACK
 *     argument, formfactor.h);
 *   - the entry between the two whole opposed unit squares (bottom and
 *     top) against the parallel-rectangle closed form, Howell's catalogue
 *     C-11 (J. R. Howell, "A Catalog of Radiation Heat Transfer
 *     Configuration Factors", factor C-11; Siegel & Howell, "Thermal
 *     Radiation Heat Transfer", appendix C): for a x b rectangles directly
 *     opposed at distance c, X = a/c, Y = b/c,
 *         F = 2/(pi X Y) { ln sqrt[(1+X^2)(1+Y^2)/(1+X^2+Y^2)]
 *                          + X sqrt(1+Y^2) atan(X/sqrt(1+Y^2))
 *                          + Y sqrt(1+X^2) atan(Y/sqrt(1+X^2))
 *                          - X atan X - Y atan Y },
 *     evaluated here in long double; it must be within p F of the fill's
 *     entry (and within the entry's own error estimate);
 *   - additivity (Siegel & Howell, the factor to a sum of areas): the
 *     factor from the 1 x 1 wall x = 0 to the 2 x 2 wall x = 1 is the sum
 *     of its four element entries; that sum is within p of C-11 (each term
 *     is within p of its own truth, all are positive) and within 2p of
 *     rad_ff_polygons on the two whole faces (each side within p);
 *   - the rows per shot (ffrow.h: "every value is the one the dense fill
 *     stores, bit for bit"): every column and row of radi_ffrow_column,
 *     and radi_ffrow_pairs' entries, are compared with memcmp; its
 *     statistics count every pair asked for, and give the dense rows'
 *     smallest and largest sums and their count above 1 +
 *     RAD_ROW_SUM_SLACK (none but in classic, whose nine-point rule puts
 *     five rows of this mesh up to 2e-3 above 1: the dense fill's
 *     statistics must count the same);
 *   - blocks and pairs (ffblock.h: "F_ij from one rank and from the dense
 *     fill are the same double"): a block of scattered rows and columns,
 *     with a leading dimension larger than its rows and the diagonal
 *     inside, and radi_ff_pairs' two entries of a list of pairs, memcmp
 *     against the dense F; a whole-matrix block's row sums (the tally)
 *     equal the dense rows' to round-off;
 *   - the statistics of a filled F (radi_ff_fill_stats) on a 3 x 3 matrix
 *     written here, whose counts are read off by eye: the diagonal, which
 *     would change every count, left out of all but the row sums;
 *   - the dense fill itself is the same doubles on 1 thread and on 2 (each
 *     pair's value does not depend on which thread computes it);
 *   - per-surface factors (persurface.h): radi_ff_surfaces' F_SK equals
 *     (1/A_S) sum_{i in S, j in K} A_i F_ij summed here in long double,
 *     to n DBL_EPSILON relative; A_S = 1; F_SS = 0; rows sum to 1 as the
 *     element rows do; and every one of the 30 wall-to-wall factors is
 *     the closed form within p: C-11 for opposed walls, C-14 for adjacent
 *     ones (Howell's catalogue C-14, two rectangles l x w and l x h with a
 *     common edge l at 90 degrees, H = h/l, W = w/l:
 *         F = 1/(pi W) { W atan(1/W) + H atan(1/H)
 *                        - sqrt(H^2+W^2) atan(1/sqrt(H^2+W^2))
 *                        + 1/4 ln( (1+W^2)(1+H^2)/(1+W^2+H^2)
 *                          * [W^2 (1+W^2+H^2) / ((1+W^2)(W^2+H^2))]^(W^2)
 *                          * [H^2 (1+H^2+W^2) / ((1+H^2)(H^2+W^2))]^(H^2) ) }),
 *     and within the error sums ES the module returns;
 *   - the hemicube matrix (hcmatrix.c, R = 64): F_ii = 0, coplanar 0, no
 *     error estimate (NaN off the diagonal, no promise), and rows that sum
 *     to 1: the deltas are normalised to sum to 1 (hcdelta.c, within 1e-12
 *     in test_hemicube.c) and in a closed room every pixel shows some
 *     element, so aliasing (the per-entry error of O(1/R), hemicube.c)
 *     moves pixels between entries of a row but loses none: bound 1e-12 +
 *     n DBL_EPSILON.  The hemicube's rows per shot (ffrow.h) take row i
 *     from the same hemicube: equal to the matrix's row bit for bit, and
 *     the column F_ji = F_ij A_i / A_j to round-off;
 *   - refusals: quadrature 0 (the fill, the rows, the blocks), an unknown
 *     method (the fill, the rows), blocks by hemicube, and a progress
 *     callback that asks to stop (the contour and the hemicube fills).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fill/ffblock.h"
#include "fill/ffpairs.h"
#include "fill/ffrow.h"
#include "fill/persurface.h"
#include "ff/formfactor.h"
#include "radiosity/base.h"
#include "radiosity/formfactor.h"
#include "radiosity/mesh.h"
#include "radiosity/scene.h"
#include "../tap.h"

#define EPS DBL_EPSILON

/* The cube, its walls as described above, in this order. */
static const char *cube_text =
    "material w reflect 0.5\n"
    "quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 1x1\n"  /* 0: bottom z = 0 */
    "quad w 0 0 1  0 1 1  1 1 1  1 0 1  mesh 1x1\n"  /* 1: top z = 1 */
    "quad w 0 0 0  0 1 0  0 1 1  0 0 1  mesh 1x1\n"  /* 2: x = 0 */
    "quad w 1 0 0  1 0 1  1 1 1  1 1 0  mesh 2x2\n"  /* 3: x = 1 */
    "quad w 0 0 0  0 0 1  1 0 1  1 0 0  mesh 3x1\n"  /* 4: y = 0 */
    "quad w 0 1 0  1 1 0  1 1 1  0 1 1  mesh 5x2\n"; /* 5: y = 1 */
#define NSURF 6
#define NELEM 20
/* the whole faces x = 0 and x = 1 as polygons, as in cube_text */
static const rad_vec3 face_x0[4] = {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}};
static const rad_vec3 face_x1[4] = {{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}};
/* opposed[S]: the wall facing S */
static const int opposed[NSURF] = {1, 0, 3, 2, 5, 4};

/* Howell C-11, directly opposed a x b rectangles at distance c (header). */
static double c11(double a, double b, double c)
{
    const long double X = (long double)a / c, Y = (long double)b / c;
    const long double X2 = X * X, Y2 = Y * Y;
    const long double sx = sqrtl(1 + X2), sy = sqrtl(1 + Y2);
    const long double br = 0.5L * logl((1 + X2) * (1 + Y2) / (1 + X2 + Y2)) +
                           X * sy * atanl(X / sy) + Y * sx * atanl(Y / sx) - X * atanl(X) -
                           Y * atanl(Y);
    return (double)(2 / (3.14159265358979323846264338327950288L * X * Y) * br);
}

/* Howell C-14, from the l x w rectangle to the l x h one sharing the edge
 * l at 90 degrees (header). */
static double c14(double l, double w, double h)
{
    const long double H = (long double)h / l, W = (long double)w / l;
    const long double H2 = H * H, W2 = W * W, HW = sqrtl(H2 + W2);
    const long double lnarg = logl((1 + W2) * (1 + H2) / (1 + W2 + H2)) +
                              W2 * logl(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2))) +
                              H2 * logl(H2 * (1 + H2 + W2) / ((1 + H2) * (H2 + W2)));
    const long double br = W * atanl(1 / W) + H * atanl(1 / H) - HW * atanl(1 / HW) + 0.25L * lnarg;
    return (double)(br / (3.14159265358979323846264338327950288L * W));
}

static rad_ff_options opts(rad_accuracy acc)
{
    rad_ff_options o;
    rad_ff_options_init(&o);
    o.accuracy = acc;
    return o;
}

/* The promise on an entry's relative error (formfactor.h); 0 in classic,
 * where nothing is promised and no check below uses it. */
static double promise_of(rad_accuracy acc)
{
    return acc == RAD_ACCURACY_REFERENCE ? 1e-9 : acc == RAD_ACCURACY_DEFAULT ? 1e-6 : 0;
}

static int build_cube(rad_mesh *m)
{
    rad_scene s;
    rad_error err;
    if (rad_scene_parse(&s, cube_text, strlen(cube_text), "cube", &err) != RAD_OK)
        return -1;
    rad_status st = rad_mesh_build(m, &s, &err);
    rad_scene_free(&s);
    return st == RAD_OK ? 0 : -1;
}

#define AT(F, n, i, j) ((F)[(size_t)(i) + (size_t)(j) * (size_t)(n)])

/* ---- checks of the scene's own numbers ------------------------------------- */

static void test_closed_forms(void)
{
    /* the catalogue's values for unit squares, as test_formfactor.c and
     * `radiosity analytic` use them: to a few ulps */
    tap_close(c11(1, 1, 1), 0.19982489569838746, 4 * EPS, "C-11 as written here, unit squares");
    tap_close(c11(2, 0.5, 0.7), rad_analytic_parallel_rectangles(2, 0.5, 0.7), 16 * EPS,
              "C-11 as written here equals rad_analytic_parallel_rectangles (2, 0.5, 0.7)");
    tap_close(c14(1, 1, 1), 0.20004377607540316, 4 * EPS, "C-14 as written here, unit squares");
    tap_close(c14(1, 0.5, 2), rad_analytic_perpendicular_rectangles(1, 0.5, 2), 16 * EPS,
              "C-14 as written here equals rad_analytic_perpendicular_rectangles (1, 0.5, 2)");
}

static void test_mesh(const rad_mesh *m)
{
    static const int want[NSURF] = {1, 1, 1, 4, 3, 10};
    int ok = m->nelements == NELEM && m->nsurfaces == NSURF;
    for (int S = 0; ok && S < NSURF; S++)
        ok = m->surface_first[S + 1] - m->surface_first[S] == want[S];
    tap_ok(ok, "the cube's mesh: %d elements, walls of 1, 1, 1, 4, 3, 10", m->nelements);
}

/* ---- the dense fill --------------------------------------------------------- */

/* F_ii, coplanar zeros, range, reciprocity, closure (E: the entries'
 * estimated errors, NULL in classic). */
static void check_matrix(const rad_mesh *m, const double *F, const double *E, rad_accuracy acc,
                         const char *name)
{
    const int n = m->nelements;
    const double p = promise_of(acc);
    int diag = 1, coplanar = 1, range = 1;
    double worst_rec = 0, worst_row = 0, worst_row_vs_est = -HUGE_VAL;
    for (int i = 0; i < n; i++) {
        double row = 0, rowpos = 0, rowerr = 0;
        diag &= AT(F, n, i, i) == 0;
        for (int j = 0; j < n; j++) {
            const double fij = AT(F, n, i, j), fji = AT(F, n, j, i);
            range &= fij >= 0 && fij <= 1;
            if (j != i && m->elements[i].surface == m->elements[j].surface)
                coplanar &= fij == 0;
            row += fij;
            rowpos += fabs(fij);
            if (E)
                rowerr += AT(E, n, i, j);
            const double ai = m->elements[i].area, aj = m->elements[j].area;
            if (fji != 0)
                worst_rec = fmax(worst_rec, fabs(ai * fij - aj * fji) / (aj * fji));
            else if (fij != 0)
                worst_rec = HUGE_VAL;
        }
        worst_row = fmax(worst_row, fabs(row - 1) - (p * rowpos + n * EPS));
        if (E) /* the row's error estimates against its actual error */
            worst_row_vs_est = fmax(worst_row_vs_est, fabs(row - 1) - (rowerr + n * EPS));
    }
    tap_ok(diag, "%s: F_ii = 0 exactly", name);
    tap_ok(coplanar, "%s: F_ij = 0 exactly between elements of one wall", name);
    tap_ok(range, "%s: every entry in [0, 1]", name);
    tap_ok(worst_rec <= 16 * EPS,
           "%s: reciprocity A_i F_ij = A_j F_ji within 16 DBL_EPSILON relative (worst %.3g)",
           name, worst_rec);
    if (acc != RAD_ACCURACY_CLASSIC) {
        tap_ok(worst_row <= 0,
               "%s: every row sums to 1 within p sum_j F_ij + n DBL_EPSILON, p = %g "
               "(worst excess %.3g)",
               name, p, worst_row);
        if (E)
            tap_ok(worst_row_vs_est <= 0,
                   "%s: |sum_j F_ij - 1| <= sum_j (estimated error of F_ij) + n DBL_EPSILON "
                   "(worst excess %.3g)",
                   name, worst_row_vs_est);
    }
}

/* The entries between whole faces against the closed form, and the
 * additivity over the 2 x 2 wall. */
static void check_closed_form(const rad_mesh *m, const double *F, const double *E,
                              rad_accuracy acc, const char *name)
{
    const int n = m->nelements;
    const double p = promise_of(acc), exact = c11(1, 1, 1);
    const int bot = m->surface_first[0], top = m->surface_first[1], x0 = m->surface_first[2];
    const double fbt = AT(F, n, bot, top), ftb = AT(F, n, top, bot);
    /* the closed form has a few ulps of its own: 4 DBL_EPSILON */
    tap_ok(fabs(fbt - exact) <= p * exact + 4 * EPS * exact &&
               fabs(ftb - exact) <= p * exact + 4 * EPS * exact,
           "%s: bottom to top (whole unit squares, 1 apart) = C-11 within p = %g: "
           "%.17g and %.17g, C-11 %.17g",
           name, p, fbt, ftb, exact);
    tap_ok(fabs(fbt - exact) <= AT(E, n, bot, top) + 4 * EPS * exact,
           "%s: ... and within the entry's own error estimate %.3g (error %.3g)", name,
           AT(E, n, bot, top), fabs(fbt - exact));

    /* additivity: x = 0 (one element) to x = 1 (four) */
    double sum = 0, rsum = 0;
    for (int j = m->surface_first[3]; j < m->surface_first[4]; j++) {
        sum += AT(F, n, x0, j);
        rsum += m->elements[j].area * AT(F, n, j, x0); /* A_x1 F_{x1,x0}, A_x1 = 1 */
    }
    rad_ff_options o = opts(acc);
    double est = 0;
    const double whole = rad_ff_polygons(face_x0, 4, face_x1, 4, &o, &est);
    tap_ok(fabs(sum - exact) <= p * exact + 8 * EPS * exact,
           "%s: x = 0 to the 2 x 2 wall x = 1, the sum of its four entries, = C-11 within p "
           "(%.17g, error %.3g)",
           name, sum, fabs(sum - exact));
    tap_ok(fabs(sum - whole) <= 2 * p * whole + 8 * EPS * whole,
           "%s: additivity: that sum equals rad_ff_polygons on the whole faces within 2p "
           "(%.17g vs %.17g)",
           name, sum, whole);
    tap_ok(fabs(whole - exact) <= p * exact + 4 * EPS * exact,
           "%s: rad_ff_polygons, whole x = 0 to whole x = 1, = C-11 within p (%.17g)", name,
           whole);
    tap_ok(fabs(rsum - exact) <= p * exact + 8 * EPS * exact,
           "%s: and back: (1/A) sum_j A_j F_j,x0 over the four = C-11 within p (%.17g)", name,
           rsum);
}

/* Per-surface factors: the module's sums against ours, and the closed
 * forms. */
static void check_surfaces(const rad_mesh *m, const double *F, const double *E,
                           rad_accuracy acc, const char *name)
{
    const int n = m->nelements, ns = m->nsurfaces;
    const double p = promise_of(acc);
    double FS[NSURF * NSURF], ES[NSURF * NSURF] = {0}, AS[NSURF];
    radi_ff_surfaces(m, F, E, FS, ES, AS);
    int areas = 1, diag = 1;
    double worst_sum = 0, worst_row = 0, worst_exact = 0, worst_es = -HUGE_VAL;
    double worst_rec = 0;
    for (int S = 0; S < ns; S++) {
        areas &= fabs(AS[S] - 1) <= 8 * EPS;
        diag &= FS[S + S * ns] == 0;
        double row = 0;
        for (int K = 0; K < ns; K++) {
            long double num = 0, as = 0;
            for (int i = m->surface_first[S]; i < m->surface_first[S + 1]; i++) {
                as += m->elements[i].area;
                for (int j = m->surface_first[K]; j < m->surface_first[K + 1]; j++)
                    num += (long double)m->elements[i].area * AT(F, n, i, j);
            }
            const double want = (double)(num / as), got = FS[S + K * ns];
            worst_sum = fmax(worst_sum, fabs(got - want) / (want > 0 ? want : 1));
            row += got;
            if (K != S) {
                const double exact = K == opposed[S] ? c11(1, 1, 1) : c14(1, 1, 1);
                worst_exact = fmax(worst_exact, fabs(got - exact) - (p * exact + n * EPS * exact));
                worst_es = fmax(worst_es, fabs(got - exact) - (ES[S + K * ns] + n * EPS * exact));
                worst_rec = fmax(worst_rec, fabs(AS[S] * got - AS[K] * FS[K + S * ns]) /
                                                (AS[K] * FS[K + S * ns]));
            }
        }
        worst_row = fmax(worst_row, fabs(row - 1) - (p * row + (n + ns) * EPS));
    }
    tap_ok(areas, "%s: per surface, every wall's area A_S = 1 to 8 DBL_EPSILON", name);
    tap_ok(worst_sum <= n * EPS,
           "%s: F_SK = (1/A_S) sum_{i in S} sum_{j in K} A_i F_ij to n DBL_EPSILON relative "
           "(worst %.3g)",
           name, worst_sum);
    tap_ok(diag, "%s: F_SS = 0 for every flat wall", name);
    tap_ok(worst_rec <= 4 * n * EPS,
           "%s: per-surface reciprocity A_S F_SK = A_K F_KS within 4 n DBL_EPSILON (worst %.3g)",
           name, worst_rec);
    if (acc == RAD_ACCURACY_CLASSIC)
        return;
    tap_ok(worst_row <= 0, "%s: per-surface rows sum to 1 within p + round-off (worst excess %.3g)",
           name, worst_row);
    tap_ok(worst_exact <= 0,
           "%s: all 30 wall-to-wall factors = C-11 (opposed) or C-14 (adjacent) within p "
           "(worst excess %.3g)",
           name, worst_exact);
    tap_ok(worst_es <= 0,
           "%s: ... and within the summed error estimates ES (worst excess %.3g)", name,
           worst_es);
}

/* The dense rows' sums: the smallest, the largest, how many above 1 +
 * RAD_ROW_SUM_SLACK. */
typedef struct row_range {
    double lo, hi;
    long above;
} row_range;

/* Rows per shot (ffrow.h): the dense fill's doubles. */
static void check_rows(const rad_mesh *m, const double *F, const row_range *rr,
                       rad_accuracy acc, const char *name)
{
    const int n = m->nelements;
    const double p = promise_of(acc);
    rad_ff_options o = opts(acc);
    rad_error err;
    rad_ffrow *row = NULL;
    double to[NELEM], from[NELEM], few[NELEM];
    int same = 1, fewsame = 1;
    rad_status st = radi_ffrow_create(&row, m, &o, RAD_OCC_AUTO, 0, 0, &err);
    tap_ok(st == RAD_OK, "%s: radi_ffrow_create", name);
    if (st != RAD_OK)
        return;
    /* shoot in a scrambled order, each column once */
    for (int k = 0; k < n && st == RAD_OK; k++) {
        const int i = (7 * k + 3) % n; /* 7 and 20 coprime: a permutation */
        st = radi_ffrow_column(row, i, to, from, &err);
        same &= memcmp(to, F + (size_t)i * n, sizeof to) == 0;
        for (int j = 0; j < n; j++)
            same &= memcmp(&from[j], &AT(F, n, i, j), sizeof *from) == 0;
    }
    tap_ok(st == RAD_OK && same,
           "%s: every column F_.i and row F_i. of radi_ffrow_column is the dense fill's, "
           "bit for bit",
           name);
    /* a few entries of a column, receivers out of order and the shooter among them */
    const int js[5] = {14, 0, 9, 6, 3};
    double asked = (double)n * (n - 1); /* pairs integrated so far: the columns' */
    for (int i = 0; i < n && st == RAD_OK; i += 4) {
        st = radi_ffrow_pairs(row, i, js, 5, few, &err);
        for (int q = 0; q < 5; q++) {
            fewsame &= memcmp(&few[q], &AT(F, n, js[q], i), sizeof *few) == 0;
            asked += js[q] != i;
        }
    }
    tap_ok(st == RAD_OK && fewsame,
           "%s: radi_ffrow_pairs' entries F_ji are the dense fill's, bit for bit", name);
    rad_ff_stats fs;
    double lo = NAN, hi = NAN;
    radi_ffrow_stats(row, &fs, &lo, &hi);
    /* each row summed once, as the test sums the dense rows: n DBL_EPSILON */
    tap_ok(fs.pairs == asked && fs.rows_above_one == rr->above &&
               fabs(lo - rr->lo) <= n * EPS && fabs(hi - rr->hi) <= n * EPS,
           "%s: the rows' statistics: %g pairs as asked (%g), row sums in [%.17g, %.17g] as "
           "the dense rows' [%.17g, %.17g], %ld above 1 as there",
           name, fs.pairs, asked, lo, hi, rr->lo, rr->hi, fs.rows_above_one);
    tap_ok(fs.negative == 0 && fs.above_one == 0 && fs.min_value == 0 && fs.max_value <= 1,
           "%s: the rows' statistics: no entry outside [0, 1], the smallest 0 (coplanar)", name);
    if (acc != RAD_ACCURACY_CLASSIC)
        tap_ok(fs.promise == p && fs.promise_unmet == 0,
               "%s: the rows' statistics: promise %g, met by every entry (%ld unmet)", name,
               fs.promise, fs.promise_unmet);
    radi_ffrow_free(row);
}

/* Blocks and pairs (ffblock.h, ffpairs.h): the dense fill's doubles. */
static void check_blocks(const rad_mesh *m, const double *F, rad_accuracy acc, const char *name)
{
    const int n = m->nelements;
    rad_ff_options o = opts(acc);
    rad_error err;
    rad_ff_block *b = NULL;
    rad_status st = radi_ff_block_open(&b, m, &o, &err);
    tap_ok(st == RAD_OK, "%s: radi_ff_block_open", name);
    if (st != RAD_OK)
        return;
    /* rows and columns scattered and overlapping (the diagonal 3, 9, 14 inside) */
    const int rows[6] = {14, 3, 0, 9, 7, 11}, cols[5] = {9, 2, 14, 3, 5};
    const size_t ld = 8; /* > 6 rows: the two spare places must stay untouched */
    double out[8 * 5];
    for (size_t k = 0; k < 8 * 5; k++)
        out[k] = -7;
    st = radi_ff_block_fill(b, rows, 6, cols, 5, out, ld, NULL, &err);
    int same = st == RAD_OK, pad = 1;
    for (int c = 0; c < 5; c++) {
        for (int r = 0; r < 6; r++)
            same &= memcmp(&out[r + c * ld], &AT(F, n, rows[r], cols[c]), sizeof *out) == 0;
        pad &= out[6 + c * ld] == -7 && out[7 + c * ld] == -7;
    }
    tap_ok(same, "%s: a 6 x 5 block of scattered rows and columns holds the dense fill's "
           "doubles, bit for bit (0 on the diagonal)", name);
    tap_ok(pad, "%s: the block leaves the places past its rows alone (ld 8)", name);

    /* the whole matrix as one block, with the tally's row sums */
    int all[NELEM];
    double whole[NELEM * NELEM], rs[NELEM], re[NELEM];
    for (int k = 0; k < n; k++)
        all[k] = k;
    rad_ff_tally t;
    t.row_sum = rs;
    t.row_error = re;
    radi_ff_tally_clear(&t, n);
    if (st == RAD_OK)
        st = radi_ff_block_fill(b, all, n, all, n, whole, (size_t)n, &t, &err);
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double r = 0;
        for (int j = 0; j < n; j++)
            r += AT(F, n, i, j);
        worst = fmax(worst, fabs(rs[i] - r));
    }
    tap_ok(st == RAD_OK && memcmp(whole, F, sizeof *F * (size_t)n * n) == 0,
           "%s: the whole matrix as one block is the dense F, bit for bit", name);
    tap_ok(st == RAD_OK && worst <= n * EPS && t.entries == (double)n * (n - 1) &&
               t.negative == 0 && t.above_one == 0,
           "%s: its tally: n (n - 1) entries, none outside [0, 1], row sums the dense rows' "
           "to n DBL_EPSILON (%.3g)",
           name, worst);

    /* pairs, i < j, each giving both entries */
    const int pi[6] = {0, 0, 2, 3, 4, 9}, pj[6] = {1, 14, 3, 8, 5, 10};
    double fij[6], fji[6];
    if (st == RAD_OK)
        st = radi_ff_pairs(m, &o, pi, pj, 6, fij, fji, &err);
    same = st == RAD_OK;
    for (int k = 0; k < 6; k++)
        same &= memcmp(&fij[k], &AT(F, n, pi[k], pj[k]), sizeof *fij) == 0 &&
                memcmp(&fji[k], &AT(F, n, pj[k], pi[k]), sizeof *fji) == 0;
    tap_ok(same, "%s: radi_ff_pairs gives F_ij and F_ji of six pairs as the dense fill, bit for "
           "bit", name);
    radi_ff_block_close(b);
}

static void test_mode(const rad_mesh *m, rad_accuracy acc)
{
    const char *name = rad_accuracy_name(acc);
    const int n = m->nelements;
    const double p = promise_of(acc);
    rad_ff_options o = opts(acc);
    rad_error err;
    rad_ff_stats stats;
    double *F = malloc(sizeof *F * (size_t)n * n), *E = malloc(sizeof *E * (size_t)n * n);
    double *F1 = malloc(sizeof *F1 * (size_t)n * n);
    rad_status st = F && E && F1 ? rad_ff_matrix(m, &o, F, E, &stats, &err) : RAD_ERR_NOMEM;
    tap_ok(st == RAD_OK, "%s: rad_ff_matrix on the cube", name);
    if (st != RAD_OK) {
        free(F);
        free(E);
        free(F1);
        return;
    }
    /* the rows as summed here: extremes, and those the fill must count as
     * above 1 (formfactor.h: sum_j F_ij > 1 + RAD_ROW_SUM_SLACK) */
    row_range rr = {HUGE_VAL, -HUGE_VAL, 0};
    for (int i = 0; i < n; i++) {
        double r = 0;
        for (int j = 0; j < n; j++)
            r += AT(F, n, i, j);
        rr.lo = fmin(rr.lo, r);
        rr.hi = fmax(rr.hi, r);
        rr.above += r > 1 + RAD_ROW_SUM_SLACK;
    }
    /* classic's nine-point rule may push rows past 1 (README: classic's
     * impossible values are counted); the other modes' promise may not */
    tap_ok(stats.pairs == 0.5 * n * (n - 1) && stats.rows_above_one == rr.above &&
               (acc == RAD_ACCURACY_CLASSIC || rr.above == 0) && stats.negative == 0 &&
               stats.above_one == 0 && stats.vis_pairs_blocked == 0,
           "%s: stats: n (n - 1) / 2 = %g pairs, nothing outside [0, 1], nothing hidden, "
           "%ld rows above 1 + RAD_ROW_SUM_SLACK as counted here (%ld)",
           name, stats.pairs, stats.rows_above_one, rr.above);
    if (acc != RAD_ACCURACY_CLASSIC)
        tap_ok(stats.promise == p && stats.promise_unmet == 0 && stats.max_relerr <= p,
               "%s: stats: promise %g, every entry's estimate within it (largest relative "
               "estimate %.3g)",
               name, stats.promise, stats.max_relerr);
    else
        tap_ok(isnan(stats.promise) && isnan(stats.max_row_error),
               "classic: stats: no promise, no error bound (NaN)");
    check_matrix(m, F, acc != RAD_ACCURACY_CLASSIC ? E : NULL, acc, name);

    /* one thread and two: the same doubles */
    o.threads = 1;
    st = rad_ff_matrix(m, &o, F1, NULL, NULL, &err);
    int same1 = st == RAD_OK && memcmp(F1, F, sizeof *F * (size_t)n * n) == 0;
    o.threads = 2;
    st = rad_ff_matrix(m, &o, F1, NULL, NULL, &err);
    tap_ok(same1 && st == RAD_OK && memcmp(F1, F, sizeof *F * (size_t)n * n) == 0,
           "%s: the fill on 1 thread and on 2 gives the same doubles", name);
    o.threads = 0;

    if (acc != RAD_ACCURACY_CLASSIC)
        check_closed_form(m, F, E, acc, name);
    check_surfaces(m, F, acc != RAD_ACCURACY_CLASSIC ? E : NULL, acc, name);
    check_rows(m, F, &rr, acc, name);
    check_blocks(m, F, acc, name);
    free(F);
    free(E);
    free(F1);
}

/* ---- the hemicube matrix ---------------------------------------------------- */

static void test_hemicube(const rad_mesh *m)
{
    const int n = m->nelements;
    rad_ff_options o = opts(RAD_ACCURACY_DEFAULT);
    rad_error err;
    rad_ff_stats stats;
    o.method = RAD_FF_HEMICUBE;
    o.resolution = 64;
    double *F = malloc(sizeof *F * (size_t)n * n), *E = malloc(sizeof *E * (size_t)n * n);
    rad_status st = F && E ? rad_ff_matrix(m, &o, F, E, &stats, &err) : RAD_ERR_NOMEM;
    tap_ok(st == RAD_OK, "hemicube R = 64: rad_ff_matrix on the cube");
    if (st != RAD_OK) {
        free(F);
        free(E);
        return;
    }
    int diag = 1, coplanar = 1, range = 1, est = 1;
    double worst_row = 0;
    for (int i = 0; i < n; i++) {
        double row = 0;
        diag &= AT(F, n, i, i) == 0;
        for (int j = 0; j < n; j++) {
            const double f = AT(F, n, i, j);
            range &= f >= 0 && f <= 1;
            row += f;
            if (j != i && m->elements[i].surface == m->elements[j].surface)
                coplanar &= f == 0;
            est &= j == i ? AT(E, n, i, j) == 0 : isnan(AT(E, n, i, j));
        }
        worst_row = fmax(worst_row, fabs(row - 1));
    }
    tap_ok(diag && coplanar && range,
           "hemicube: F_ii = 0, 0 between elements of one wall, every entry in [0, 1]");
    tap_ok(est && isnan(stats.promise) && isnan(stats.max_errest) && stats.rows_above_one == 0,
           "hemicube: no error estimate (NaN off the diagonal, 0 on it), no promise, no row "
           "above 1");
    tap_ok(worst_row <= 1e-12 + n * EPS,
           "hemicube: every row of the closed cube sums to 1 within 1e-12 + n DBL_EPSILON, the "
           "normalised deltas' sum: pixels move between entries, none is lost (worst %.3g)",
           worst_row);

    /* its rows per shot: row i from the same hemicube */
    rad_ffrow *row = NULL;
    double to[NELEM], from[NELEM];
    int same = 1;
    double worst_col = 0;
    st = radi_ffrow_create(&row, m, &o, RAD_OCC_AUTO, 0, 0, &err);
    for (int i = 0; i < n && st == RAD_OK; i++) {
        st = radi_ffrow_column(row, i, to, from, &err);
        for (int j = 0; j < n; j++) {
            same &= memcmp(&from[j], &AT(F, n, i, j), sizeof *from) == 0;
            const double ai = m->elements[i].area, aj = m->elements[j].area;
            if (from[j] != 0)
                worst_col = fmax(worst_col, fabs(aj * to[j] - ai * from[j]) / (ai * from[j]));
            else if (to[j] != 0)
                worst_col = HUGE_VAL;
        }
    }
    tap_ok(st == RAD_OK && same,
           "hemicube: radi_ffrow_column's row i is the hemicube matrix's row, bit for bit");
    tap_ok(st == RAD_OK && worst_col <= 16 * EPS,
           "hemicube: its column F_ji = F_ij A_i / A_j within 16 DBL_EPSILON (worst %.3g)",
           worst_col);
    radi_ffrow_free(row);

    rad_ff_block *b = NULL;
    st = radi_ff_block_open(&b, m, &o, &err);
    tap_ok(st == RAD_ERR_INVALID && b == NULL, "hemicube: blocks are refused (%s)",
           st != RAD_OK ? err.message : "accepted");
    radi_ff_block_close(b);
    free(F);
    free(E);
}

/* ---- refusals ----------------------------------------------------------------- */

static int stop_now(void *user, const char *stage, double done, double total)
{
    (void)stage;
    (void)done;
    (void)total;
    ++*(int *)user;
    return 1;
}

static void test_refusals(const rad_mesh *m)
{
    const int n = m->nelements;
    double *F = malloc(sizeof *F * (size_t)n * n);
    rad_ff_options o = opts(RAD_ACCURACY_DEFAULT);
    rad_error err;
    rad_ffrow *row = NULL;
    rad_ff_block *b = NULL;

    o.quadrature = 0;
    rad_status st = rad_ff_matrix(m, &o, F, NULL, NULL, &err);
    tap_ok(st == RAD_ERR_INVALID && strstr(err.message, "quadrature"),
           "quadrature 0 is refused by the fill (%s)", err.message);
    st = radi_ffrow_create(&row, m, &o, RAD_OCC_AUTO, 0, 0, &err);
    tap_ok(st == RAD_ERR_INVALID && row == NULL, "... and by the rows (%s)", err.message);
    st = radi_ff_block_open(&b, m, &o, &err);
    tap_ok(st == RAD_ERR_INVALID && b == NULL, "... and by the blocks (%s)", err.message);

    o = opts(RAD_ACCURACY_DEFAULT);
    o.method = (rad_ff_method)7;
    st = rad_ff_matrix(m, &o, F, NULL, NULL, &err);
    tap_ok(st == RAD_ERR_INVALID && strstr(err.message, "method"),
           "an unknown method is refused by the fill (%s)", err.message);
    st = radi_ffrow_create(&row, m, &o, RAD_OCC_AUTO, 0, 0, &err);
    tap_ok(st == RAD_ERR_INVALID && row == NULL, "... and by the rows (%s)", err.message);

    int calls = 0;
    o = opts(RAD_ACCURACY_DEFAULT);
    o.progress = stop_now;
    o.progress_user = &calls;
    st = rad_ff_matrix(m, &o, F, NULL, NULL, &err);
    tap_ok(st == RAD_ERR_INVALID && strstr(err.message, "interrupted") && calls == 1,
           "a progress callback asking to stop interrupts the fill after its first call (%s)",
           err.message);
    calls = 0;
    o.method = RAD_FF_HEMICUBE;
    st = rad_ff_matrix(m, &o, F, NULL, NULL, &err);
    tap_ok(st == RAD_ERR_INVALID && strstr(err.message, "interrupted") && calls == 1,
           "... and the hemicube fill (%s)", err.message);
    free(F);
}

/* The visibility setup on a scene with a blocker: its progress (stage
 * "visibility", every surface pair counted, before the fill's stage), and
 * its candidate lists made on two threads giving the matrix of one. */
static const char *blocker_text =
    "material w reflect 0.5\n"
    "quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 2x2\n"
    "quad w 0 0 1  0 1 1  1 1 1  1 0 1  mesh 2x2\n"
    "quad w 0.25 0.25 0.5  0.25 0.75 0.5  0.75 0.75 0.5  0.75 0.25 0.5  mesh 1x1\n"
    "quad w 0.25 0.25 0.5  0.75 0.25 0.5  0.75 0.75 0.5  0.25 0.75 0.5  mesh 1x1\n";

typedef struct stages {
    int vis, ff, vis_after_ff;
    double vdone, vtotal;
} stages;

static int record(void *user, const char *stage, double done, double total)
{
    stages *r = user;
    if (strcmp(stage, "visibility") == 0) {
        r->vis++;
        r->vis_after_ff |= r->ff > 0;
        r->vdone = done;
        r->vtotal = total;
    } else if (strcmp(stage, "form factors") == 0) {
        r->ff++;
    }
    return 0;
}

static void test_visibility_setup(void)
{
    rad_scene s;
    rad_mesh m;
    rad_error err;
    if (rad_scene_parse(&s, blocker_text, strlen(blocker_text), "blocker", &err) != RAD_OK ||
        rad_mesh_build(&m, &s, &err) != RAD_OK) {
        tap_ok(0, "the blocker scene builds (%s)", err.message);
        return;
    }
    rad_scene_free(&s);
    const int n = m.nelements;
    double *F1 = malloc(sizeof *F1 * (size_t)n * n), *F2 = malloc(sizeof *F2 * (size_t)n * n);
    stages r = {0};
    rad_ff_options o = opts(RAD_ACCURACY_DEFAULT);
    o.threads = 1;
    rad_status st1 = F1 ? rad_ff_matrix(&m, &o, F1, NULL, NULL, &err) : RAD_ERR_NOMEM;
    o.threads = 2;
    o.progress = record;
    o.progress_user = &r;
    rad_status st2 = F2 ? rad_ff_matrix(&m, &o, F2, NULL, NULL, &err) : RAD_ERR_NOMEM;
    tap_ok(st1 == RAD_OK && st2 == RAD_OK, "the blocker scene fills on one thread and on two");
    tap_ok(r.vis >= 1 && r.vdone == 6 && r.vtotal == 6 && !r.vis_after_ff && r.ff >= 1,
           "the visibility setup tells its progress first, ending at its 6 surface pairs "
           "(%d calls, last %g of %g)", r.vis, r.vdone, r.vtotal);
    tap_ok(st1 == RAD_OK && st2 == RAD_OK &&
               memcmp(F1, F2, sizeof *F1 * (size_t)n * n) == 0,
           "candidates listed on two threads give the one-thread matrix bit for bit");
    int calls = 0;
    o.progress = stop_now;
    o.progress_user = &calls;
    rad_status st3 = rad_ff_matrix(&m, &o, F2, NULL, NULL, &err);
    tap_ok(st3 == RAD_ERR_INVALID && strstr(err.message, "interrupted") && calls == 1,
           "stopping in the visibility setup interrupts the fill (%s)", err.message);
    free(F1);
    free(F2);
    rad_mesh_free(&m);
}

/* Rows (5, -1/4, 1/2), (3/2, -3, 0), (3/10, 1/5, 7), stored by columns.
 * Off the diagonal: one entry below 0 (-1/4, the smallest), one above 1
 * (3/2, the largest), five nonzero (2.5 pairs); rows 0 and 2 sum above 1
 * with their diagonals (5.25, 7.5), row 1 does not (-1.5). */
static void test_stats(void)
{
    const double F[9] = {5, 1.5, 0.3, -0.25, -3, 0.2, 0.5, 0, 7};
    rad_ff_stats st;
    memset(&st, 0, sizeof st);
    radi_ff_fill_stats(F, 3, &st);
    tap_ok(st.pairs == 3 && st.negative == 1 && st.above_one == 1 && st.min_value == -0.25 &&
               st.max_value == 1.5 && st.integrated == 2.5 && st.rows_above_one == 2,
           "a 3 x 3 matrix's statistics: %g pairs, %ld below 0, %ld above 1, in [%g, %g], %g "
           "integrated, %ld rows above 1",
           st.pairs, st.negative, st.above_one, st.min_value, st.max_value, st.integrated,
           st.rows_above_one);
    memset(&st, 0, sizeof st); /* one element: no pair, its row is its diagonal */
    radi_ff_fill_stats(F, 1, &st);
    tap_ok(st.pairs == 0 && st.min_value == 0 && st.max_value == 0 && st.integrated == 0 &&
               st.rows_above_one == 1,
           "a 1 x 1 matrix: no pair, extremes 0, its one row (5) above 1");
}

int main(void)
{
    test_stats();
    rad_mesh m;
    test_closed_forms();
    if (build_cube(&m) != 0) {
        tap_ok(0, "the unevenly meshed cube builds");
        return tap_done();
    }
    test_mesh(&m);
    test_mode(&m, RAD_ACCURACY_DEFAULT);
    test_mode(&m, RAD_ACCURACY_REFERENCE);
    test_mode(&m, RAD_ACCURACY_CLASSIC);
    test_hemicube(&m);
    test_refusals(&m);
    rad_mesh_free(&m);
    test_visibility_setup();
    return tap_done();
}
