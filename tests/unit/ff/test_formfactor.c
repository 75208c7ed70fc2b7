/* test_formfactor.c -- the contour-integral kernel against closed forms,
 * published values and identities.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Sources of the expected values:
 *   - two facing unit squares 1 apart: F = 0.19982489569838746 (Howell's
 *     catalogue C-11); the nine-point rule's own value, 0.1998348614034
 *     to 13 digits, is recomputed here by a plain 9-log loop;
 *   - perpendicular unit squares sharing an edge: 0.20004377607540316
 *     (Howell C-14); the rule gives 0.2000378639180;
 *   - the log integrals: brute-force Gauss quadrature in long double on
 *     panels graded geometrically toward the singularity;
 *   - identities: reciprocity, closure of the cube, additivity, F_ii = 0,
 *     clipping against the perpendicular-rectangle closed form.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ff/formfactor.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "../tap.h"

static const rad_vec3 sq_bottom[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
static const rad_vec3 sq_top[4] = {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};
static const rad_vec3 sq_wall[4] = {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}};

static rad_ff_options opts(rad_accuracy acc)
{
    rad_ff_options o;
    rad_ff_options_init(&o);
    o.accuracy = acc;
    return o;
}

/* The nine-point rule written out plainly (no grouping of logs): edges of
 * the two facing squares, 3 x 3 Gauss points, F = S / (2 pi A). */
static double nine_point_plain(const rad_vec3 *a, const rad_vec3 *b)
{
    const double x[3] = {-sqrt(0.6), 0, sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    double s = 0;
    for (int p = 0; p < 4; p++)
        for (int q = 0; q < 4; q++) {
            rad_vec3 p0 = a[p], p1 = a[(p + 1) % 4], q0 = b[q], q1 = b[(q + 1) % 4];
            rad_vec3 dp = {p1.x - p0.x, p1.y - p0.y, p1.z - p0.z};
            rad_vec3 dq = {q1.x - q0.x, q1.y - q0.y, q1.z - q0.z};
            double dot = dp.x * dq.x + dp.y * dq.y + dp.z * dq.z; /* lengths 1 */
            if (dot == 0)
                continue;
            double I = 0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) {
                    double ti = 0.5 * (1 + x[i]), tj = 0.5 * (1 + x[j]);
                    double rx = p0.x + ti * dp.x - q0.x - tj * dq.x;
                    double ry = p0.y + ti * dp.y - q0.y - tj * dq.y;
                    double rz = p0.z + ti * dp.z - q0.z - tj * dq.z;
                    I += w[i] * w[j] * 0.5 * log(rx * rx + ry * ry + rz * rz);
                }
            s += dot * 0.25 * I;
        }
    return s / (2 * M_PI);
}

/* Brute force for integral_a^b integral_c^d ln sqrt((s-t)^2 + dd^2) dt ds:
 * 20-point Gauss in long double on panels that halve toward every point
 * where the integrand (or the outer integrand) is not smooth, 45 levels
 * deep (each panel's singularity lies a panel-length away, where the
 * 20-point rule converges to ~1e-15). */
static int graded(long double lo, long double hi, int slo, int shi, long double *br)
{
    int n = 0;
    if (slo && shi) {
        long double m = 0.5L * (lo + hi);
        n = graded(lo, m, 1, 0, br);
        return n - 1 + graded(m, hi, 0, 1, br + n - 1);
    }
    /* stop halving where panels would be narrower than ~1e3 ulps of the
     * coordinates; what is left (< 1e-15 wide) contributes < 1e-13 */
    const long double floor_w = 1e-16L * (fabsl(lo) + fabsl(hi) + 1e-300L);
    br[n++] = lo;
    if (slo)
        for (int k = 45; k >= 1; k--)
            if ((hi - lo) * ldexpl(1.0L, -k) > floor_w)
                br[n++] = lo + (hi - lo) * ldexpl(1.0L, -k);
    if (shi)
        for (int k = 1; k <= 45; k++)
            if ((hi - lo) * ldexpl(1.0L, -k) > floor_w)
                br[n++] = hi - (hi - lo) * ldexpl(1.0L, -k);
    br[n++] = hi;
    return n;
}

static long double gauss_panels(const long double *br, int nb, long double (*f)(long double, const long double *),
                                const long double *ctx)
{
    const double *x = rad_gauss_nodes(20), *w = rad_gauss_weights(20);
    long double sum = 0;
    for (int k = 0; k + 1 < nb; k++) {
        long double m = 0.5L * (br[k] + br[k + 1]), r = 0.5L * (br[k + 1] - br[k]);
        if (r > 0)
            for (int i = 0; i < 20; i++)
                sum += r * w[i] * f(m + r * x[i], ctx);
    }
    return sum;
}

static long double f_inner(long double t, const long double *ctx)
{
    long double u = ctx[0] - t;
    return 0.5L * logl(u * u + ctx[1] * ctx[1]);
}

/* ctx: c, d, dd */
static long double f_outer(long double s, const long double *ctx)
{
    long double br[256], in[2] = {s, ctx[2]};
    int nb;
    if (s > ctx[0] && s < ctx[1]) {
        nb = graded(ctx[0], s, 0, 1, br);
        nb += graded(s, ctx[1], 1, 0, br + nb - 1) - 1;
    } else {
        /* s outside [c, d]: grade toward the near end, where the
         * integrand is (nearly) singular */
        nb = graded(ctx[0], ctx[1], s <= ctx[0], s >= ctx[1], br);
    }
    return gauss_panels(br, nb, f_inner, in);
}

static double brute_parallel(double a, double b, double c, double d, double dd)
{
    long double pts[4] = {a, b, c, d}, cut[4], br[2048], ctx[3] = {c, d, dd};
    int nc = 0, nb = 0;
    for (int k = 0; k < 4; k++) {
        int dup = 0;
        for (int j = 0; j < nc; j++)
            dup |= cut[j] == pts[k];
        if (!dup && pts[k] >= a && pts[k] <= b)
            cut[nc++] = pts[k];
    }
    for (int i = 0; i < nc; i++) /* sort the few cut points */
        for (int j = i + 1; j < nc; j++)
            if (cut[j] < cut[i]) {
                long double t = cut[i];
                cut[i] = cut[j];
                cut[j] = t;
            }
    for (int k = 0; k + 1 < nc; k++) {
        int slo = cut[k] == c || cut[k] == d, shi = cut[k + 1] == c || cut[k + 1] == d;
        int m = graded(cut[k], cut[k + 1], slo, shi, br + (nb ? nb - 1 : 0));
        nb += nb ? m - 1 : m;
    }
    return (double)gauss_panels(br, nb, f_outer, ctx);
}

static void test_log_integrals(void)
{
    static const double cases[][5] = {
        /* a1 a2 b1 b2 d */
        {0, 1, 0, 1, 0},        /* identical: 1^2 (ln 1 - 3/2) = -1.5 */
        {0, 2, 1, 3, 0},        /* overlapping */
        {0, 3, 1, 2, 0},        /* nested */
        {0, 1, 1, 2.5, 0},      /* sharing an endpoint */
        {0, 1, 2, 4, 0},        /* disjoint */
        {0, 1, 0, 1, 0.5},      /* parallel, facing */
        {0, 1, 3, 3.5, 2},      /* parallel, offset */
        {0, 1e-3, 0, 2e-3, 1e-4}, /* small */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const double *c = cases[k];
        double got = rad_ln_parallel(c[0], c[1], c[2], c[3], c[4]);
        double want = brute_parallel(c[0], c[1], c[2], c[3], c[4]);
        char what[128];
        snprintf(what, sizeof what, "ln-integral [%g,%g]x[%g,%g] d=%g vs graded quadrature",
                 c[0], c[1], c[2], c[3], c[4]);
        /* graded 20-point quadrature in long double: ~1e-15; 1e-12 leaves room */
        tap_close(got, want, 1e-12, what);
    }
    tap_close(rad_ln_parallel(0, 1, 0, 1, 0), -1.5, 1e-15, "identical unit segments: -3/2 exactly");
}

static void test_squares(void)
{
    rad_ff_options cl = opts(RAD_ACCURACY_CLASSIC), df = opts(RAD_ACCURACY_DEFAULT);
    double f = rad_ff_polygons(sq_bottom, 4, sq_top, 4, &cl, NULL);
    /* the rule value has 13 digits: absolute 1e-12 */
    tap_ok(fabs(f - 0.1998348614034) < 1e-12, "facing squares, classic: %.15g (rule value 0.1998348614034)", f);
    tap_close(f, nine_point_plain(sq_bottom, sq_top), 1e-13, "classic equals the plain nine-point loop");
    /* default and reference: within their promises (1e-6, 1e-9) and
     * within their own error estimates */
    double e;
    f = rad_ff_polygons(sq_bottom, 4, sq_top, 4, &df, &e);
    tap_close(f, 0.19982489569838746, 1e-6, "facing squares, default (exact C-11)");
    tap_ok(fabs(f - 0.19982489569838746) <= e / (2 * M_PI) + 1e-15,
           "facing squares, default: error %.2g within its estimate %.2g",
           fabs(f - 0.19982489569838746), e / (2 * M_PI));
    rad_ff_options rf = opts(RAD_ACCURACY_REFERENCE);
    f = rad_ff_polygons(sq_bottom, 4, sq_top, 4, &rf, &e);
    tap_close(f, rad_analytic_parallel_rectangles(1, 1, 1), 1e-9, "facing squares, reference = analytic");
    tap_ok(fabs(f - 0.19982489569838746) <= e / (2 * M_PI) + 1e-15,
           "facing squares, reference: error %.2g within its estimate %.2g",
           fabs(f - 0.19982489569838746), e / (2 * M_PI));
    f = rad_ff_polygons(sq_bottom, 4, sq_wall, 4, &cl, NULL);
    tap_ok(fabs(f - 0.2000378639180) < 1e-12, "perpendicular squares, classic: %.15g (rule 0.2000378639180)", f);
    f = rad_ff_polygons(sq_bottom, 4, sq_wall, 4, &df, NULL);
    tap_close(f, 0.20004377607540316, 1e-13, "perpendicular squares, default (exact C-14)");
    /* reciprocity of the pair kernel: equal areas, so F_ab = F_ba */
    double g = rad_ff_polygons(sq_wall, 4, sq_bottom, 4, &df, NULL);
    tap_close(g, f, 1e-14, "perpendicular squares: F_ab = F_ba");
    /* on one plane, behind, facing away: 0 */
    const rad_vec3 beside[4] = {{2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}};
    const rad_vec3 below[4] = {{0, 0, -2}, {0, 1, -2}, {1, 1, -2}, {1, 0, -2}};
    const rad_vec3 away[4] = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    tap_ok(rad_ff_polygons(sq_bottom, 4, beside, 4, &df, NULL) == 0, "coplanar: F = 0");
    tap_ok(rad_ff_polygons(sq_bottom, 4, below, 4, &df, NULL) == 0, "behind: F = 0");
    tap_ok(rad_ff_polygons(sq_bottom, 4, away, 4, &cl, NULL) == 0, "facing away: F = 0");
    /* straddling: the wall x = 0.5 facing -x, z from -1 to 1; only its
     * upper half is seen, and only from the part x < 0.5 of the square:
     * F = 0.5 * F_perp(l = 1, w = 0.5, h = 1) */
    const rad_vec3 strad[4] = {{0.5, 0, -1}, {0.5, 0, 1}, {0.5, 1, 1}, {0.5, 1, -1}};
    f = rad_ff_polygons(sq_bottom, 4, strad, 4, &df, NULL);
    tap_close(f, 0.5 * rad_analytic_perpendicular_rectangles(1, 0.5, 1), 1e-12,
              "straddling wall is clipped to the front");
}

/* The closed unit cube (walls facing in), n x n per wall. */
static const char *cube_text =
    "material w reflect 0.5\n"
    "quad w 0 0 0  1 0 0  1 1 0  0 1 0\n"
    "quad w 0 0 1  0 1 1  1 1 1  1 0 1\n"
    "quad w 0 0 0  0 1 0  0 1 1  0 0 1\n"
    "quad w 1 0 0  1 0 1  1 1 1  1 1 0\n"
    "quad w 0 0 0  0 0 1  1 0 1  1 0 0\n"
    "quad w 0 1 0  1 1 0  1 1 1  0 1 1\n";

static double *cube_matrix(int nmesh, rad_accuracy acc, rad_mesh *m)
{
    rad_scene s;
    rad_error err;
    rad_ff_options o = opts(acc);
    if (rad_scene_parse(&s, cube_text, strlen(cube_text), "cube", &err))
        return NULL;
    rad_scene_set_mesh(&s, nmesh, nmesh);
    rad_mesh_build(m, &s, &err);
    rad_scene_free(&s);
    size_t n = (size_t)m->nelements;
    double *F = malloc(sizeof *F * n * n);
    if (!F || rad_ff_matrix(m, &o, F, NULL, NULL, &err)) {
        free(F);
        return NULL;
    }
    return F;
}

static void test_cube(rad_accuracy acc, double rowtol, const char *name)
{
    rad_mesh m;
    double *F = cube_matrix(7, acc, &m);
    tap_ok(F != NULL, "%s: 7x7 cube matrix", name);
    if (!F)
        return;
    int n = m.nelements, neg = 0, diag = 1;
    double worst_row = 0, worst_rec = 0;
    for (int i = 0; i < n; i++) {
        double row = 0;
        diag &= F[i + (size_t)i * n] == 0;
        for (int j = 0; j < n; j++) {
            double fij = F[i + (size_t)j * n], fji = F[j + (size_t)i * n];
            row += fij;
            neg += fij < 0;
            double ai = m.elements[i].area, aj = m.elements[j].area;
            if (fij != 0)
                worst_rec = fmax(worst_rec, fabs(ai * fij - aj * fji) / (ai * fij));
        }
        worst_row = fmax(worst_row, fabs(row - 1));
    }
    tap_ok(worst_row <= rowtol, "%s: rows sum to 1 within %g (worst %.3g)", name, rowtol, worst_row);
    tap_ok(worst_rec <= 1e-14, "%s: reciprocity to 1e-14 relative (worst %.3g)", name, worst_rec);
    tap_ok(neg == 0 && diag, "%s: no negative entry, F_ii = 0", name);
    free(F);
    rad_mesh_free(&m);
}

/* Additivity: the wall-to-wall form factor of the 1x1 cube equals the
 * area-weighted sum over a 3x3 subdivision; reference mode promises 1e-9
 * per entry, and the sums of 81 such entries stay within 1e-10. */
static void test_additivity(void)
{
    rad_mesh m1, m3;
    double *F1 = cube_matrix(1, RAD_ACCURACY_REFERENCE, &m1);
    double *F3 = cube_matrix(3, RAD_ACCURACY_REFERENCE, &m3);
    double worst = 0;
    if (F1 && F3) {
        int n3 = m3.nelements;
        for (int I = 0; I < 6; I++)
            for (int J = 0; J < 6; J++) {
                double sum = 0;
                for (int i = 9 * I; i < 9 * I + 9; i++)
                    for (int j = 9 * J; j < 9 * J + 9; j++)
                        sum += m3.elements[i].area * F3[i + (size_t)j * n3];
                double want = F1[I + 6 * J];
                if (want != 0)
                    worst = fmax(worst, fabs(sum - want) / want);
                else
                    worst = fmax(worst, fabs(sum));
            }
    }
    tap_ok(F1 && F3 && worst < 1e-10, "additivity: 3x3 sums equal the 1x1 factors (worst %.3g)", worst);
    free(F1);
    free(F3);
    rad_mesh_free(&m1);
    rad_mesh_free(&m3);
}

/* Coaxial disks as regular K-gons: F converges to the disk value once the
 * polygon's smaller area is accounted for (compare with the disks of equal
 * area, radius r sqrt(A_K / (pi r^2))): the remaining shape difference
 * falls as K^-4 (measured: 6.2e-5 at K = 16, 2.4e-7 at 64, 9.4e-10 at
 * 256, so about 4e-12 at 1024); the test asks each step to fall and
 * K = 1024 to be within 1e-10.  The raw value's error is the area deficit
 * (2 pi / K)^2 / 6 to first order, printed for comparison. */
static void test_disks(void)
{
    rad_ff_options df = opts(RAD_ACCURACY_DEFAULT);
    double prev = HUGE_VAL;
    int falling = 1;
    for (int k = 16; k <= 1024; k *= 4) {
        rad_vec3 *a = malloc(sizeof *a * (size_t)k), *b = malloc(sizeof *b * (size_t)k);
        for (int i = 0; i < k; i++) {
            double t = 2 * M_PI * i / k;
            a[i] = (rad_vec3){cos(t), sin(t), 0};
            b[k - 1 - i] = (rad_vec3){cos(t), sin(t), 1}; /* clockwise seen from +z */
        }
        double f = rad_ff_polygons(a, k, b, k, &df, NULL);
        double area = 0.5 * k * sin(2 * M_PI / k), req = sqrt(area / M_PI);
        double want = rad_analytic_disk_disk(req, req, 1);
        double raw = fabs(f - rad_analytic_disk_disk(1, 1, 1)) / rad_analytic_disk_disk(1, 1, 1);
        double err = fabs(f - want) / want;
        tap_diag("K = %4d: F = %.15f, equal-area disks %.15f (rel %.3g), unit disks rel %.3g", k, f,
                 want, err, raw);
        falling &= err < prev;
        prev = err;
        free(a);
        free(b);
    }
    tap_ok(falling, "K-gon disks converge to the equal-area disk value as K grows");
    tap_ok(prev < 1e-10, "K = 1024: within 1e-10 of the equal-area disk value (%.3g)", prev);
}

/* The a priori bounds of default mode's Gauss rules (ffgauss.c), and the
 * error estimates the kernel returns, against the closed form for opposed
 * a x b rectangles c apart (Howell C-11), over aspect ratios 1..10 and
 * sizes 1e-3..2, separations 0.05..3000 times the longer side.  The closed
 * form carries a few ulps; 1e-15 relative is added for it.  A bound that is
 * not a bound fails here. */
static void rect_at(rad_vec3 *p, double x0, double y0, double a, double b, double z, int up)
{
    rad_vec3 q[4] = {{x0, y0, z}, {x0 + a, y0, z}, {x0 + a, y0 + b, z}, {x0, y0 + b, z}};
    for (int k = 0; k < 4; k++)
        p[k] = q[up ? k : 3 - k];
}

static void test_bounds(void)
{
    static const double sizes[][2] = {{1, 1}, {1, 0.1}, {0.3, 2}, {1e-3, 1e-3}};
    static const double seps[] = {0.05, 0.3, 1, 2.5, 7, 30, 200, 3e3};
    int tried[4] = {0, 0, 0, 0}, honest[4] = {1, 1, 1, 1}, used = 0, est_ok = 1, promise = 1;
    double worst_ratio = 0;
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; i++)
        for (size_t j = 0; j < sizeof seps / sizeof *seps; j++) {
            const double a = sizes[i][0], b = sizes[i][1], c = seps[j] * (a > b ? a : b);
            rad_vec3 lo[4], hi[4];
            rect_at(lo, 0, 0, a, b, 0, 1);
            rect_at(hi, 0, 0, a, b, c, 0);
            const double exact = rad_analytic_parallel_rectangles(a, b, c);
            const double S = exact * 2 * M_PI * a * b, slack = 1e-15 * S;
            rad_ff_poly pa, pb;
            rad_ff_edge ea[4], eb[4];
            radi_ff_poly_make(&pa, lo, 4, ea);
            radi_ff_poly_make(&pb, hi, 4, eb);
            rad_vec3 sep = {pb.centroid.x - pa.centroid.x, pb.centroid.y - pa.centroid.y,
                            pb.centroid.z - pa.centroid.z};
            double sep2 = sep.x * sep.x + sep.y * sep.y + sep.z * sep.z;
            double scale2 = sep2 + pa.size * pa.size + pb.size * pb.size;
            /* every edge pair is parallel or perpendicular: sum |dot| lp lq */
            double pp = 2 * (a * a + b * b);
            rad_ff_gauss_bounds g;
            if (radi_ff_gauss_apart(&pa, &pb, sep2, scale2, c, &g)) {
                static const int ks[4] = {4, 8, 3, 6};
                g.pp = pp;
                /* three bounds: derivative only, ellipse only, the smaller */
                rad_ff_gauss_bounds gd = g, ge = g, gm = g;
                radi_ff_gauss_ellipse(&ge);
                ge.q2 = INFINITY;
                radi_ff_gauss_ellipse(&gm);
                const rad_ff_gauss_bounds *gs[3] = {&gd, &ge, &gm};
                for (int t = 0; t < 4; t++) { /* K = 4, 8, 3, 6 in the quadratic form */
                    double sk = radi_ff_gauss_sum(&pa, &pb, ks[t], scale2, NULL);
                    tried[t]++;
                    for (int v = 0; v < 3; v++) {
                        double bk = radi_ff_gauss_bound(gs[v], ks[t]);
                        honest[t] &= fabs(sk - S) <= bk + slack;
                        if (bk > 0 && fabs(sk - S) / bk > worst_ratio)
                            worst_ratio = fabs(sk - S) / bk;
                    }
                }
                rad_ff_options c3 = opts(RAD_ACCURACY_CLASSIC);
                double f3 = rad_ff_polygons(lo, 4, hi, 4, &c3, NULL);
                tried[2]++;
                for (int v = 0; v < 3; v++)
                    honest[2] &=
                        fabs(f3 * 2 * M_PI * a * b - S) <= radi_ff_gauss_bound(gs[v], 3) + slack;
                used++;
            }
            for (int m = 0; m < 2; m++) {
                rad_ff_options o = opts(m ? RAD_ACCURACY_REFERENCE : RAD_ACCURACY_DEFAULT);
                double e, f = rad_ff_polygons(lo, 4, hi, 4, &o, &e);
                est_ok &= fabs(f - exact) <= e + 1e-15 * exact;
                promise &= fabs(f - exact) <= (m ? 1e-9 : 1e-6) * exact;
            }
        }
    tap_ok(used >= 20, "bounds: %d of 32 rectangle pairs are apart (bounded)", used);
    tap_ok(tried[0] && honest[0], "bounds: 4 x 4 rule within its a priori bound (%d pairs)", tried[0]);
    tap_ok(tried[1] && honest[1], "bounds: 8 x 8 rule within its a priori bound (%d pairs)", tried[1]);
    tap_ok(tried[3] && honest[3], "bounds: 6 x 6 rule within its a priori bound (%d pairs)", tried[3]);
    tap_ok(tried[2] && honest[2], "bounds: nine-point rule within its a priori bound (%d pairs)",
           tried[2]);
    tap_diag("worst error / bound of the 4 x 4 and 8 x 8 rules: %.3g", worst_ratio);
    tap_ok(est_ok, "default and reference: |F - exact| <= the returned error estimate");
    tap_ok(promise, "default within 1e-6, reference within 1e-9 of C-11 on all 32 pairs");
}

/* ffgauss.c keeps its own copies of the 3, 4, 6 and 8 point rules (as
 * constants the compiler folds): they must be gauss.c's, digit for digit. */
static void test_tables(void)
{
    static const int ks[4] = {3, 4, 6, 8};
    for (int t = 0; t < 4; t++) {
        const double *x = radi_ff_gauss_table(ks[t], 0), *w = radi_ff_gauss_table(ks[t], 1);
        int same = x && w;
        for (int i = 0; same && i < ks[t]; i++)
            same = x[i] == rad_gauss_nodes(ks[t])[i] && w[i] == rad_gauss_weights(ks[t])[i];
        tap_ok(same, "ffgauss.c's %d-point rule is gauss.c's", ks[t]);
    }
    tap_ok(radi_ff_gauss_table(5, 0) == NULL, "no 5-point table in ffgauss.c");
}

int main(void)
{
    test_tables();
    test_disks();
    test_log_integrals();
    test_squares();
    /* the nine-point rule's closure error on the 7x7 cube: within 5e-6 */
    test_cube(RAD_ACCURACY_CLASSIC, 5e-6, "classic");
    /* default promises 1e-6 per entry (internal tolerance 1e-8 of each
     * pair's S): rows within 1e-7 */
    test_cube(RAD_ACCURACY_DEFAULT, 1e-7, "default");
    /* reference promises 1e-9 per entry (internal 1e-11): rows within
     * 1e-11 on the cube, where all edge pairs have closed forms */
    test_cube(RAD_ACCURACY_REFERENCE, 1e-11, "reference");
    test_additivity();
    test_bounds();
    return tap_done();
}
