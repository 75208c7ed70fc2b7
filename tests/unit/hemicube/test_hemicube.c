/* test_hemicube.c -- the hemicube's table and its error against closed forms.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * What is checked, and against what:
 *   1. the delta form factors (hcdelta.c) sum to 1 within 1e-12 after
 *      their normalisation; before it, their sum is the midpoint rule for
 *      an integral that is exactly 1 (the projected hemisphere over pi),
 *      so it misses 1 by an error of order R^-2, which falls by 4 per
 *      doubling of R (the midpoint rule's error expansion,
 *      c h^2 + O(h^4): Davis & Rabinowitz, "Methods of Numerical
 *      Integration", 2nd ed. 1984, section 2.9);
 *   2. a hemicube's row is the form factor of a differential area at the
 *      element's centre: Lambert's closed form for a point and a polygon,
 *          F = (1/2 pi) sum_k gamma_k n . (R_k x R_k+1) / |R_k x R_k+1|
 *      (Lambert 1760; Baum, Rushmeier & Winget 1989, eq. 3), R_k the
 *      vertices relative to the point, gamma_k the angle between R_k and
 *      R_k+1.  The pixels err only where the receiver's outline crosses
 *      them (a pixel counts wholly for what covers its centre): a
 *      segment of length l on a face of pixel side 2/R passes through at
 *      most (|l_x| + |l_y|) R/2 + 2 <= sqrt(2) l R/2 + 2 pixels, each off
 *      by at most the largest delta, 4 / (pi R^2) (the top face's centre;
 *      the sides' are smaller, and the normalisation only lowers them).
 *      An outline of total length L on the faces in K pieces is then
 *      within (sqrt(2) L R/2 + 2 K) 4 / (pi R^2) of the closed form, plus
 *      the normalisation's share (each delta scaled by 1 / raw sum =
 *      1 - 0.54 R^-2: below R^-2 on an F <= 1): the bound C/R + D/R^2
 *      asserted below, C = 2 sqrt(2) L / pi; over turns of a unit square
 *      by 0..44 degrees the largest error falls over R = 16, 64, 256 and
 *      1024, against Lambert and against the contour integral of a
 *      shooter of side 1/100;
 *   3. on two facing unit squares at distance 1 (the closed form
 *      0.19982489569838746, Howell's catalogue C-11, as
 *      `radiosity analytic parallel-rectangles 1 1 1`) and on the unit
 *      cube's adjacent faces (0.20004377607540316, Howell C-14), with
 *      the shooter meshed: every row (element centre) obeys the bound of
 *      2, its largest error falls over R = 16, 64, 256, and the
 *      per-surface factor is within that bound plus the centre rule's
 *      own error (the area-weighted Lambert values at the centres
 *      against the closed form, the limit R -> infinity) of the contour's
 *      closed form.  That centre rule's error, not the pixels, is what
 *      is left at high R: it falls with the mesh, not with R (bench/
 *      hemicube.sh prints the table from 16 to 1024).
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fill/ffrow.h"
#include "hemicube/hemicube.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "../tap.h"
#include "util/vec.h"

#define PI 3.14159265358979323846
#define F_PARALLEL 0.19982489569838746 /* unit squares, distance 1 */
#define F_ADJACENT 0.20004377607540316 /* unit squares at 90 degrees, one edge */

/* ---- 1. the table ---------------------------------------------------------- */

static long double table_sum(const rad_hc_table *t)
{
    const size_t R = (size_t)t->res;
    long double s = 0;
    for (size_t k = 0; k < R * R; k++)
        s += t->top[k];
    for (size_t k = 0; k < R * (R / 2); k++)
        s += 4.0L * t->side[k];
    return s;
}

static void test_table(void)
{
    static const int res[] = {2, 16, 64, 256, 1024, 4096};
    rad_error err;
    for (size_t k = 0; k < sizeof res / sizeof res[0]; k++) {
        rad_hc_table t;
        if (radi_hc_table_make(&t, res[k], &err) != RAD_OK) {
            tap_ok(0, "R = %d: %s", res[k], err.message);
            continue;
        }
        const double s = (double)table_sum(&t);
        tap_ok(fabs(s - 1) <= 1e-12, "R = %d: the deltas sum to 1 within 1e-12 (%.17g)",
               res[k], s);
        radi_hc_table_free(&t);
    }
    /* the raw sum: the midpoint rule, error c R^-2 (c the same sign for all) */
    double prev = NAN;
    for (int R = 16; R <= 1024; R *= 2) {
        rad_hc_table t;
        if (radi_hc_table_make(&t, R, &err) != RAD_OK)
            continue;
        const double e = (double)(t.raw_sum - 1);
        if (!isnan(prev))
            tap_ok(e > 0 && prev / e > 3.9 && prev / e < 4.1,
                   "raw sum - 1 at R = %d: %.6g, %.4g times less than at R/2 (midpoint rule: 4)",
                   R, e, prev / e);
        prev = e;
        radi_hc_table_free(&t);
    }
    tap_ok(radi_hc_table_make(&(rad_hc_table){0}, 15, &err) == RAD_ERR_INVALID,
           "an odd resolution is refused: %s", err.message);
}

/* ---- 2. one point: Lambert's closed form ------------------------------------ */

/* The form factor from a differential area at p with normal nrm to the
 * convex polygon v[0..k) wholly in front of it (Lambert). */
static double lambert(rad_vec3 p, rad_vec3 nrm, const rad_vec3 *v, int k)
{
    double s = 0;
    for (int a = 0; a < k; a++) {
        const rad_vec3 r0 = v3_sub(v[a], p), r1 = v3_sub(v[(a + 1) % k], p);
        const rad_vec3 c = v3_cross(r0, r1);
        const double cn = v3_norm(c);
        if (cn == 0)
            continue;
        const double gamma = atan2(cn, v3_dot(r0, r1));
        s += gamma * v3_dot(nrm, c) / cn;
    }
    return fabs(s) / (2 * PI);
}

/* The bound of the header, item 2, for an outline of length L (face
 * units) with K edges. */
static double alias_bound(int R, double L, int K)
{
    return (sqrt(2.0) * L * R / 2 + 2.0 * K) * 4 / (PI * R * (double)R) +
           1.0 / ((double)R * R);
}

/* F from surface 0 to surface 1 of the scene text, per surface
 * (area-weighted over surface 0's elements), by the hemicube at R; and the
 * hemicube's limit, Lambert's value at each of surface 0's centres. */
/* The exact point factor from element e's centre to what it sees of the
 * receiver (surface 1 of the scene). */
typedef double (*exact_fn)(const rad_element *e, const rad_scene *sc);

static double exact_open(const rad_element *e, const rad_scene *sc)
{
    const rad_surface *recv = &sc->surfaces[1];
    return lambert(e->centroid, e->normal, recv->verts, recv->nverts);
}

static int surface_factor_by(const char *text, int R, exact_fn exact, double *f, double *limit,
                             double *rowmax)
{
    rad_scene sc;
    rad_mesh m;
    rad_error err;
    rad_ff_options o;
    if (rad_scene_parse(&sc, text, strlen(text), "t.scene", &err) != RAD_OK ||
        rad_mesh_build(&m, &sc, &err) != RAD_OK) {
        tap_diag("%s", err.message);
        return -1;
    }
    const int n = m.nelements;
    double *F = malloc(sizeof *F * (size_t)n * n);
    rad_ff_options_init(&o);
    o.method = RAD_FF_HEMICUBE;
    o.resolution = R;
    int rc = !F || rad_ff_matrix(&m, &o, F, NULL, NULL, &err) != RAD_OK ? -1 : 0;
    if (rc)
        tap_diag("%s", F ? err.message : "out of memory");
    double a0 = 0, s = 0, lim = 0;
    *rowmax = 0;
    for (int i = 0; i < n && rc == 0; i++) {
        const rad_element *e = &m.elements[i];
        if (e->surface != 0)
            continue;
        double fi = 0;
        for (int j = 0; j < n; j++)
            fi += m.elements[j].surface == 1 ? F[i + (size_t)j * n] : 0;
        const double li = exact(e, &sc);
        a0 += e->area;
        s += e->area * fi;
        lim += e->area * li;
        *rowmax = fmax(*rowmax, fabs(fi - li));
    }
    *f = s / a0;
    *limit = lim / a0;
    free(F);
    rad_mesh_free(&m);
    rad_scene_free(&sc);
    return rc;
}

static int surface_factor(const char *text, int R, double *f, double *limit, double *rowmax)
{
    return surface_factor_by(text, R, exact_open, f, limit, rowmax);
}

/* A small square (side 1/100) about (1/2, 1/2, 0) facing up, and a unit
 * square about (1/2, 1/2, 1) facing down, turned by `deg` degrees about
 * the common axis: the outline crosses the pixels obliquely, where they
 * alias (an outline along pixel edges would not).  The hemicube sees only
 * the small square's centre and normal; the contour integral its area,
 * which differs from the centre's value by the centre rule's error,
 * O(side^2) (computed, and allowed for). */
static void turned_pair(double deg, char *text, size_t len, rad_vec3 shoot[4], rad_vec3 recv[4])
{
    const double c = cos(deg * PI / 180), s = sin(deg * PI / 180);
    for (int k = 0; k < 4; k++) { /* (+-0.5, +-0.5) turned, about (0.5, 0.5) */
        const double x = (k == 1 || k == 2) ? 0.5 : -0.5, y = k >= 2 ? 0.5 : -0.5;
        recv[3 - k] = v3(0.5 + c * x - s * y, 0.5 + s * x + c * y, 1); /* clockwise */
        shoot[k] = v3(0.5 + x / 100, 0.5 + y / 100, 0);
    }
    snprintf(text, len,
             "material w reflect 0.5\n"
             "quad w 0.495 0.495 0  0.505 0.495 0  0.505 0.505 0  0.495 0.505 0\n"
             "quad w %.17g %.17g 1  %.17g %.17g 1  %.17g %.17g 1  %.17g %.17g 1\n",
             recv[0].x, recv[0].y, recv[1].x, recv[1].y, recv[2].x, recv[2].y, recv[3].x,
             recv[3].y);
}

/* One row's aliasing depends on where the outline falls among the
 * pixels, erratically: at a single angle the error may grow from one R
 * to the next.  Its largest value over the turns 0, 1, ..., 44 degrees is
 * what falls with R, under the bound C/R + D/R^2 of the header. */
static void test_point(void)
{
    rad_ff_options ref;
    rad_ff_options_init(&ref);
    ref.accuracy = RAD_ACCURACY_REFERENCE;
    double prev = HUGE_VAL, prevc = HUGE_VAL;
    for (int R = 16; R <= 1024; R *= 4) {
        double e = 0, ec = 0, centre = 0;
        int fails = 0;
        for (int deg = 0; deg < 45; deg++) {
            char text[1024];
            rad_vec3 shoot[4], recv[4];
            double f, lim, rowmax;
            turned_pair(deg, text, sizeof text, shoot, recv);
            fails += surface_factor(text, R, &f, &lim, &rowmax) != 0;
            const double contour = rad_ff_polygons(shoot, 4, recv, 4, &ref, NULL);
            e = fmax(e, fabs(f - lim));
            ec = fmax(ec, fabs(f - contour));
            centre = fmax(centre, fabs(contour - lim));
        }
        const double b = alias_bound(R, 4, 4);
        tap_ok(!fails && e <= b && e < prev,
               "a point and a unit square turned 0..44 degrees, R = %d: largest error against "
               "Lambert %.3g <= %.3g (C/R + D/R^2), below R/4's", R, e, b);
        tap_ok(!fails && ec <= b + centre && ec < prevc,
               "... against the contour integral (reference) of a square of side 1/100: "
               "largest error %.3g <= %.3g (pixels) + %.3g (centre rule), below R/4's", ec, b,
               centre);
        prev = e;
        prevc = ec;
    }
}

/* ---- 3. meshed shooters against the contour's closed forms ------------------ */

static void test_meshed(const char *what, const char *text, double exact, double L, int K)
{
    double e[3];
    int k = 0;
    for (int R = 16; R <= 256; R *= 4, k++) {
        double f, lim;
        e[k] = NAN;
        if (surface_factor(text, R, &f, &lim, &e[k]) != 0) {
            tap_ok(0, "%s, R = %d", what, R);
            continue;
        }
        const double b = alias_bound(R, L, K), centre = fabs(lim - exact);
        tap_ok(e[k] <= b, "%s, R = %d: every row within %.3g of its centre's Lambert value "
               "(largest error %.3g)", what, R, b, e[k]);
        tap_ok(fabs(f - exact) <= b + centre, "%s, R = %d: per surface F = %.10f, closed form "
               "%.17g, error %.3g <= %.3g (pixels) + %.3g (the centre rule, R -> infinity)",
               what, R, f, exact, fabs(f - exact), b, centre);
    }
    tap_ok(e[0] > e[1] && e[1] > e[2], "%s: the rows' largest error falls with R: "
           "%.3g (16) > %.3g (64) > %.3g (256)", what, e[0], e[1], e[2]);
}

/* ---- 4. visibility: a one-sided blocker seen from behind -------------------- */

/* The ceiling z = 1 seen from a floor point p past the square [1/4, 3/4]^2
 * at z = 1/2: the blocker's shadow from p on the ceiling's plane is the
 * square [1/2 - p, 3/2 - p]^2 (doubled about p), and what p sees is the
 * ceiling less the shadow's part on it (a rectangle, or nothing): by
 * additivity over the solid angle, Lambert(ceiling) - Lambert(that part). */
static double exact_blocked(const rad_element *e, const rad_scene *sc)
{
    const rad_vec3 p = e->centroid;
    const double x0 = fmax(0, 0.5 - p.x), x1 = fmin(1, 1.5 - p.x);
    const double y0 = fmax(0, 0.5 - p.y), y1 = fmin(1, 1.5 - p.y);
    const double open = exact_open(e, sc);
    if (!(x1 > x0 && y1 > y0))
        return open;
    const rad_vec3 r[4] = {v3(x0, y0, 1), v3(x1, y0, 1), v3(x1, y1, 1), v3(x0, y1, 1)};
    return open - lambert(p, e->normal, r, 4);
}

/* The blocker faces the ceiling: the floor sees its back.  The contour's
 * visibility counts every surface opaque from both sides (occlusion.h),
 * and so must the hemicube's item buffer (hemicube.c, the turned-round
 * twins); without them the floor would see the whole ceiling. */
static void test_blocker(void)
{
    static const char text[] = "material w reflect 0.5\n"
                               "quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 7x7\n"
                               "quad w 0 0 1  0 1 1  1 1 1  1 0 1\n"
                               "quad w 0.25 0.25 0.5  0.75 0.25 0.5  0.75 0.75 0.5  0.25 0.75 0.5\n";
    double prev = HUGE_VAL;
    for (int R = 16; R <= 256; R *= 4) {
        double f, lim, rowmax;
        if (surface_factor_by(text, R, exact_blocked, &f, &lim, &rowmax) != 0) {
            tap_ok(0, "blocker, R = %d", R);
            continue;
        }
        /* outlines on the top face: the ceiling's and the shadow's, each
         * at most 4 units, 4 edges */
        const double b = alias_bound(R, 8, 8);
        tap_ok(rowmax <= b, "a one-sided blocker seen from behind hides the ceiling, R = %d: "
               "every floor row within %.3g of its exact value (largest error %.3g; per "
               "surface %.6f, exact limit %.6f, unblocked %.6f)", R, b, rowmax, f, lim,
               F_PARALLEL);
        tap_ok(rowmax < prev, "... and its largest error is smaller than at R/4");
        prev = rowmax;
    }
}

/* ---- 5. a receiver closer than the renderer's own near plane --------------- */

/* Two unit squares facing each other a gap g apart (g of the scene's size;
 * the renderer's default near plane is 1e-6 of it, which once clipped such
 * a receiver away: F fell from 1 to 0.29 at g = 1e-6 and 0.003 at 1e-7).
 * From the shooter's centre the receiver covers the whole top face and
 * each side face up to the height 2g, so its outline there lies along the
 * four sides' bottom rows: L = 8, K = 8 (as the blocker's).  Lambert's
 * value at the centre is 1 - O(g). */
static void test_close(void)
{
    const double gaps[] = {1e-5, 1e-7, 1e-8};
    for (size_t k = 0; k < sizeof gaps / sizeof *gaps; k++) {
        char text[512];
        double f, lim, rowmax;
        const double g = gaps[k];
        snprintf(text, sizeof text,
                 "material w reflect 0.5\n"
                 "quad w 0 0 0  1 0 0  1 1 0  0 1 0\n"
                 "quad w 0 0 %.17g  0 1 %.17g  1 1 %.17g  1 0 %.17g\n", g, g, g, g);
        const int R = 64;
        const int rc = surface_factor(text, R, &f, &lim, &rowmax);
        const double b = alias_bound(R, 8, 8);
        tap_ok(rc == 0 && fabs(f - lim) <= b,
               "facing unit squares %g apart, R = %d: F = %.12f, Lambert %.12f, within %.3g", g,
               R, f, lim, b);
    }
}

/* ---- 6. an unknown method is refused by the matrix and the rows alike ------- */

static void test_unknown_method(void)
{
    static const char text[] = "material w reflect 0.5\n"
                               "quad w 0 0 0  1 0 0  1 1 0  0 1 0\n"
                               "quad w 0 0 1  0 1 1  1 1 1  1 0 1\n";
    rad_scene sc;
    rad_mesh m;
    rad_error err;
    rad_ff_options o;
    rad_ffrow *row = NULL;
    double F[4];
    if (rad_scene_parse(&sc, text, strlen(text), "t.scene", &err) != RAD_OK ||
        rad_mesh_build(&m, &sc, &err) != RAD_OK) {
        tap_ok(0, "unknown method: %s", err.message);
        return;
    }
    rad_ff_options_init(&o);
    o.method = (rad_ff_method)7;
    tap_ok(rad_ff_matrix(&m, &o, F, NULL, NULL, &err) == RAD_ERR_INVALID,
           "rad_ff_matrix refuses method 7: %s", err.message);
    err.message[0] = '\0';
    tap_ok(radi_ffrow_create(&row, &m, &o, RAD_OCC_AUTO, 0, 0, &err) == RAD_ERR_INVALID &&
               !row,
           "radi_ffrow_create (matrix-free shooting) refuses it too: %s", err.message);
    radi_ffrow_free(row);
    rad_mesh_free(&m);
    rad_scene_free(&sc);
}

int main(void)
{
    test_table();
    test_point();
    /* shooter 13 x 13 (its centres off every power-of-two pixel grid),
     * receiver whole.  The receiver's outline on the faces: the parallel
     * square is a unit square on the top face from every centre (L = 4,
     * K = 4 edges); the adjacent square seen from the floor is one convex
     * region of the hemisphere spread over the top face and three sides,
     * its outline on each a convex curve no longer than that face's
     * perimeter (8 on top, 6 on a half side): L <= 26, in K <= 4 x 4
     * segments */
    test_meshed("facing unit squares, 13x13 shooter",
                "material w reflect 0.5\n"
                "quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 13x13\n"
                "quad w 0 0 1  0 1 1  1 1 1  1 0 1\n",
                F_PARALLEL, 4, 4);
    test_meshed("adjacent unit squares, 13x13 shooter",
                "material w reflect 0.5\n"
                "quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 13x13\n"
                "quad w 0 0 0  0 1 0  0 1 1  0 0 1\n",
                F_ADJACENT, 26, 16);
    test_blocker();
    test_close();
    test_unknown_method();
    return tap_done();
}
