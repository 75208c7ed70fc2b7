/* ffarea.c -- form factors of distant pairs by area-area quadrature.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * For a pair that is small against its separation the contour integral
 * cancels catastrophically: its terms are of order L^2 ln r while the
 * result is of order A^2 / r^2.  The area form
 *
 *     2 pi A_a F_ab = 2 * integral_A integral_B (n_a . d)(-n_b . d) / |d|^4 dA dB,
 *     d = y - x  (x on A, y on B),
 *
 * (the definition of the form factor, e.g. Cohen & Wallace 1993, eq. 4.6,
 * times 2 pi A_a to match the symmetric contour sum S) has only positive
 * terms there, and its integrand is smooth on the scale of the separation,
 * so product Gauss rules converge geometrically.  Each polygon is covered
 * by Gauss points: a quadrilateral through its bilinear map from the unit
 * square (tensor Gauss-Legendre, Jacobian |P_u x P_v|); any other convex
 * polygon as a fan of triangles from its first vertex, each the collapsed
 * square of Duffy (1982): P(u, v) = v0 + u (v_k - v0) + u v (v_k+1 - v_k),
 * dA = 2 A_k u du dv.  Orders k = 2, 3, ... are tried until two successive
 * results agree to the tolerance.  The error estimate is the geometric
 * tail of the differences: with d_k = |S_k - S_k-1| falling by q =
 * d_k / d_k-1 an order, S_k errs by about d_k q / (1 - q), and the estimate
 * is d_k max(1, q / (1 - q)) (d_k alone when they fall faster than
 * halving; infinite when they do not fall).  Two orders can agree by
 * chance, both erring alike: S_k errs by at least about S_k-1's error less
 * d_k, and S_k-1's is about d_k-1 times the ratio before, so d_k is taken
 * as at least d_k-1^2 / d_k-2 once three differences are known (two
 * strips at 2.6 degrees: differences 6.8e-15, 4.9e-16, 5.3e-20, 6.1e-18,
 * and S_9 off by 1.5e-10 of itself under an estimate of 1.5e-12; fuzzed
 * scene 38:164 of geomfuzz.py).  Nor do the errors fall faster than the rule
 * converges: a K-point Gauss rule on a part of longest side L, its
 * integrand analytic within the box gap D of it, errs as rho^-2K with
 * (L/2)(rho - 1/rho)/2 = D, the Bernstein ellipse of semi-minor axis D
 * (Trefethen 2013, Thm 19.3): rho = t + sqrt(1 + t^2), t = 2D/L.  So d_k
 * is also taken as at least d_k-1 / rho^2 (with L the longest part side
 * of either polygon).  That is a floor, not a bound: a part farther than
 * D converges faster, and is only given more orders.  (A square of
 * 1.6e-5 0.9 above a plate of 1 x 0.5 cut 3 x 2: differences 3.7e-15,
 * then 1.03e-19 at 4 points, where S_4 was off by 3.2e-9 of itself, the
 * predicted rho^-8; fuzzed scene 43:368.)
 *
 * The normal in the integrand is the polygon's own (the caller's) but on
 * a twisted quadrilateral, whose vertices lie off one plane by more than
 * the round-off of the coordinates: there the bilinear surface is the one
 * integrated over, and its normal P_u x P_v turns across it, so the rule
 * takes it point by point.  That is what makes the area form the contour
 * integral's value (Stokes: any surface spanning the contour gives it);
 * with one normal, a leaf twisted by 1e-13 of its size at a 179.9-degree
 * hinge was off by 6e-10 of S, which the orders' agreement cannot see
 * (fuzzed scene 36:91).  A twisted polygon of more than four vertices
 * (the scene accepts 1e-6 of its size off its plane, scene.c) is
 * integrated over its fan of triangles, each with its own normal: the fan
 * spans the contour too.  With one normal a pentagon with one vertex 5e-7
 * off the plane of the others (2.6e-7 of its size), 5 from a plate at 30
 * degrees to it, was off by 5e-7 of S in reference mode under an estimate
 * of 2e-12 of it (tests/accuracy/twisted.sh).  On a planar polygon the
 * caller's normal is kept: the cross product of a sliver's edges is much
 * the worse normal.
 *
 * A quadrilateral longer than the pair's distance (a strip beside another
 * polygon) is cut into n_u x n_v equal parts of its parameter square, each
 * at most half the distance D long, so that the integrand, which varies on
 * the scale of D, is smooth on every part (additivity of the integral);
 * D is the gap between the polygons' bounding boxes.
 *
 * Round-off.  Nothing cancels in the sum, but each cosine does: n_a . d,
 * with d nearly in a's plane (two polygons nearly edge on), is a small
 * difference of terms as large as |d| = r, and the points themselves,
 * relative to an origin up to R0 away (R0 the farthest vertex of either
 * polygon from it), are rounded on the scale of R0.  With eps the
 * machine epsilon: each point is within 8 eps R0 of its place in every
 * coordinate (the origin's subtraction and two interpolations), so d is
 * off by at most 32 eps R0 in length; a normal is off by nu radians (R3,
 * below); the dot product adds 3 eps r.  So n_k . d, and likewise n_l . d,
 * is off by at most (nu_a + 6 eps) r + 32 eps R0, and r^4 by
 * eps (112 R0 / r + 7) of itself.  A term t = w_k w_l a_k a_l / r^4
 * (a_k = n_k . d, a_l = -n_l . d) is then off by at most
 *     |w_k w_l| [((nu_a + 6 eps) r + 32 eps R0) |a_l|
 *                + ((nu_b + 6 eps) r + 32 eps R0) |a_k|] / r^4
 *     + |t| (112 eps R0 / r + eps (20 + m_a + m_b) + 2 (nu_a + nu_b)),
 * the last part the weights' rounding (their Jacobians carry the normals')
 * and the two running sums of m_a and m_b terms (Higham 2002, eq. 4.4),
 * and the sum S (twice the sum of the terms) by twice the sum of these.   (R1)
 * With |a| <= r and r >= r_min, the gap between the polygons, R1 is at
 * most
 *     2 W_a W_b / r_min^2 [(nu_a + nu_b + 12 eps) + eps (20 + m_a + m_b)
 *                          + 2 (nu_a + nu_b) + 176 eps R0 / r_min],       (R2)
 * W the sums of |w|: no evaluation, and enough for most pairs, whose
 * cosines are far from 0.  R2 is taken where it is below a tenth of the
 * pair's tolerance, R1 elsewhere, and where R1 is above that too, the
 * order is summed again in long double (ffarealong.c), S becomes that
 * sum and R1 its bound with long double's epsilon, plus the rounding of
 * S to double.  The normals: the caller's, a unit vector from the
 * element's Newell vector (ffmatrix.c), the n - 2 cross products of its
 * fan each off by about 4 eps |e1| |e2| <= 4 eps size^2 in every
 * component, against its length of twice the area A:
 *     nu = eps (4 + 8 (n - 2) size^2 / (2 A)),                           (R3)
 * the normalising taking the 4.  Each bound is for the numbers as the
 * program holds them.  Two rectangles of 2^-6 x 2^-6 sqrt 2, exact in
 * binary, 1.4 apart and 2^-26 from one plane: default's area sum is 8e-9
 * of itself off, as before, but under an estimate of 6e-7 (R3's share),
 * where it was 4e-10; at 2^-18 both modes were 2.6e-11 off under 8e-12,
 * and are 3e-11 off under 2.5e-9 (tests/accuracy/edgeon.sh).  The adaptive rule
 * (below) bounds
 * each close pair of parts alike; a part's corners are rounded once per
 * cut, by half an ulp of R0, not counted beyond the 8 eps R0 above.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ff/formfactor.h"
#include "radiosity/base.h"
#include "radiosity/formfactor.h"
#include "util/util.h"

#define AREA_ORDER_MAX 10

#define AREA_SPLIT_MAX 16 /* parts per side of a quadrilateral */

/* A polygon's side of the pair: its front normal and whether it is a
 * twisted quadrilateral, one whose surface normals P_u x P_v the rules
 * must follow (see the top of the file). */
typedef struct area_side {
    rad_vec3 nrm;
    int twisted;
    double nu;     /* the bound on nrm's error, radians (R3) */
} area_side;

/* For P = q0 + u a + v b + u v c (c = q0 - q1 + q2 - q3), P_u x P_v =
 * a x b + u a x c + v c x b, off the plane only through c's part along
 * the normal, 4 times the vertices' alternating distance from it: twisted
 * when that is beyond the round-off of the coordinates relative to the
 * origin (64 eps of their largest).  A polygon of more vertices is twisted
 * when its vertices' heights along the normal spread by as much; a
 * triangle never is. */
static area_side side_of(const rad_vec3 *p, int n, rad_vec3 origin, const rad_ff_poly *el)
{
    const rad_vec3 nrm = el->normal; /* the surface's, ffmatrix.c */
    area_side sd = {nrm, 0, el->nu};
    if (n < 4)
        return sd;
    double big = 0, hlo = INFINITY, hhi = -INFINITY;
    for (int k = 0; k < n; k++) {
        const rad_vec3 q = v3_sub(p[k], origin);
        big = fmax(big, v3_maxabs(q));
        hlo = fmin(hlo, v3_dot(q, nrm));
        hhi = fmax(hhi, v3_dot(q, nrm));
    }
    if (n == 4) {
        const rad_vec3 c = v3_add(v3_sub(p[0], p[1]), v3_sub(p[2], p[3]));
        sd.twisted = fabs(v3_dot(c, nrm)) > 64 * DBL_EPSILON * big;
    } else {
        sd.twisted = hhi - hlo > 64 * DBL_EPSILON * big;
    }
    return sd;
}

/* Gauss points of polygon p (n vertices) relative to `origin`, order k, a
 * quadrilateral cut into nu x nv parts: fills pts, w (the weights, the
 * Jacobian included) and nv_ (the unit normals: the surface's own,
 * P_u x P_v / |P_u x P_v|, on a twisted quadrilateral, each fan
 * triangle's on another twisted polygon, sd's elsewhere)
 * (room for count_points(n, k, nu, nv)); returns the count. */
static int count_points(int n, int k, int nu, int nv)
{
    return n == 4 ? k * k * nu * nv : (n - 2) * k * k;
}

static int polygon_points(const rad_vec3 *p, int n, rad_vec3 origin, int k, int nu, int nv,
                          const area_side *sd, rad_vec3 *pts, double *w, rad_vec3 *nv_)
{
    const double *x = rad_gauss_nodes(k), *gw = rad_gauss_weights(k);
    int m = 0;
    if (n == 4) {
        rad_vec3 q[4];
        for (int c = 0; c < 4; c++)
            q[c] = v3_sub(p[c], origin);
        for (int pu_ = 0; pu_ < nu; pu_++)
            for (int pv_ = 0; pv_ < nv; pv_++)
                for (int i = 0; i < k; i++) {
                    double u = (pu_ + 0.5 * (1 + x[i])) / nu;
                    for (int j = 0; j < k; j++) {
                        double v = (pv_ + 0.5 * (1 + x[j])) / nv;
                        /* P(u,v) = (1-u)(1-v) q0 + u(1-v) q1 + u v q2 + (1-u) v q3 */
                        rad_vec3 a = v3_lerp(q[0], q[1], u), b = v3_lerp(q[3], q[2], u);
                        rad_vec3 pu = v3_add(v3_scale(v3_sub(q[1], q[0]), 1 - v),
                                             v3_scale(v3_sub(q[2], q[3]), v));
                        rad_vec3 pv = v3_sub(b, a), x_ = v3_cross(pu, pv);
                        const double jac = v3_norm(x_);
                        pts[m] = v3_lerp(a, b, v);
                        nv_[m] = sd->twisted ? v3_scale(x_, 1 / jac) : sd->nrm;
                        w[m++] = 0.25 * gw[i] * gw[j] * jac / (nu * nv);
                    }
                }
        return m;
    }
    for (int t = 1; t + 1 < n; t++) {
        rad_vec3 v0 = v3_sub(p[0], origin), e1 = v3_sub(p[t], p[0]), e2 = v3_sub(p[t + 1], p[t]);
        const rad_vec3 cr = v3_cross(e1, e2);
        const double twice = v3_norm(cr); /* 2 A_t */
        const rad_vec3 nt = sd->twisted && twice > 0 ? v3_scale(cr, 1 / twice) : sd->nrm;
        for (int i = 0; i < k; i++) {
            double u = 0.5 * (1 + x[i]);
            for (int j = 0; j < k; j++) {
                double v = 0.5 * (1 + x[j]);
                pts[m] = v3_add(v0, v3_add(v3_scale(e1, u), v3_scale(e2, u * v)));
                nv_[m] = nt;
                w[m++] = 0.25 * gw[i] * gw[j] * twice * u;
            }
        }
    }
    return m;
}

/* Bounding-box gap between the vertex sets a and b (0 if they overlap). */
static double vertex_box_gap(const rad_vec3 *a, int na, const rad_vec3 *b, int nb)
{
    rad_vec3 alo, ahi, blo, bhi;
    v3_bounds(a, na, &alo, &ahi);
    v3_bounds(b, nb, &blo, &bhi);
    return sqrt(v3_box_gap2(alo, ahi, blo, bhi));
}

/* The longest side of a part of p cut nu x nv (a quadrilateral), or of p
 * (any other polygon: its fan's triangles are no longer than its
 * bounding box's diagonal). */
static double part_side(const rad_vec3 *p, int n, int nu, int nv)
{
    if (n != 4) {
        rad_vec3 lo, hi;
        v3_bounds(p, n, &lo, &hi);
        return v3_norm(v3_sub(hi, lo));
    }
    const double lu = fmax(v3_norm(v3_sub(p[1], p[0])), v3_norm(v3_sub(p[2], p[3])));
    const double lv = fmax(v3_norm(v3_sub(p[3], p[0])), v3_norm(v3_sub(p[2], p[1])));
    return fmax(lu / nu, lv / nv);
}

/* 1 / rho^2 for the rule on parts of longest side L at distance D (see
 * the top of the file); 0 (no floor) when D is 0 */
static double fastest_fall(double L, double D)
{
    if (!(D > 0) || !(L > 0))
        return 0;
    const double t = 2 * D / L, rho = t + sqrt(1 + t * t);
    return 1 / (rho * rho);
}

/* Parts per side of quadrilateral p for pieces at most D/2 long. */
static void split_counts(const rad_vec3 *p, int n, double D, int *nu, int *nv)
{
    *nu = *nv = 1;
    if (n != 4 || !(D > 0))
        return;
    const double lu = fmax(v3_norm(v3_sub(p[1], p[0])), v3_norm(v3_sub(p[2], p[3])));
    const double lv = fmax(v3_norm(v3_sub(p[3], p[0])), v3_norm(v3_sub(p[2], p[1])));
    const double cu = ceil(2 * lu / D), cv = ceil(2 * lv / D);
    *nu = cu < 1 ? 1 : cu > AREA_SPLIT_MAX ? AREA_SPLIT_MAX : (int)cu;
    *nv = cv < 1 ? 1 : cv > AREA_SPLIT_MAX ? AREA_SPLIT_MAX : (int)cv;
}

/* 2 sum_k sum_l w_k w_l (n_k . d)(-n_l . d) / |d|^4 */
static double area_sum(const rad_vec3 *pa, const double *wa, const rad_vec3 *na, int ma,
                       const rad_vec3 *pb, const double *wb, const rad_vec3 *nb, int mb)
{
    double s = 0;
    for (int k = 0; k < ma; k++) {
        double inner = 0;
        for (int l = 0; l < mb; l++) {
            rad_vec3 d = v3_sub(pb[l], pa[k]);
            double r2 = v3_dot(d, d);
            inner += wb[l] * (v3_dot(na[k], d) * -v3_dot(nb[l], d)) / (r2 * r2);
        }
        s += wa[k] * inner;
    }
    return 2 * s;
}

/* The sums over the same points as area_sum that R1 (see the top of the
 * file) is made of, with w = |w_k w_l|, a_k = |n_k . d|, a_l = |n_l . d|:
 *     t[0] = sum w r a_l / r^4,  t[1] = sum w a_l / r^4,
 *     t[2] = sum w r a_k / r^4,  t[3] = sum w a_k / r^4,
 *     t[4] = sum w a_k a_l / r^5,  t[5] = sum w a_k a_l / r^4,
 * so that R1 for any epsilon and normals' doubt is a combination of six
 * numbers (area_roundoff): one pass over the terms serves the bound in
 * double and the bound of the sum again in long double. */
typedef struct area_terms {
    double t[6];
    int known;
} area_terms;

/* One term's share of the six sums: w = |w_k w_l| / r^4 */
static void add_terms(double t[6], double w, double r, double ak, double al)
{
    t[0] += w * r * al;
    t[1] += w * al;
    t[2] += w * r * ak;
    t[3] += w * ak;
    t[4] += w * ak * al / r;
    t[5] += w * ak * al;
}

/* area_sum and the six sums above in one pass over the terms (the sum
 * bit for bit area_sum's); R1 alone discards the sum. */
static double area_sum_terms(const rad_vec3 *pa, const double *wa, const rad_vec3 *na, int ma,
                             const rad_vec3 *pb, const double *wb, const rad_vec3 *nb, int mb,
                             area_terms *at)
{
    double s = 0, t[6] = {0, 0, 0, 0, 0, 0};
    for (int k = 0; k < ma; k++) {
        double inner = 0;
        for (int l = 0; l < mb; l++) {
            const rad_vec3 d = v3_sub(pb[l], pa[k]);
            const double r2 = v3_dot(d, d), r = sqrt(r2);
            const double dk = v3_dot(na[k], d), dl = v3_dot(nb[l], d);
            inner += wb[l] * (dk * -dl) / (r2 * r2);
            const double w = fabs(wa[k] * wb[l]) / (r2 * r2);
            const double ak = fabs(dk), al = fabs(dl);
            add_terms(t, w, r, ak, al);
        }
        s += wa[k] * inner;
    }
    for (int k = 0; k < 6; k++)
        at->t[k] = t[k];
    at->known = 1;
    return 2 * s;
}

/* The six sums of area_sum_terms without the sum itself, for R1 where
 * the caller has the sum already (area_roundoff).  They bound an error,
 * so their order does not matter (their own rounding is of second order
 * in eps): with vector extensions, b's points go into lanes, four terms
 * at a time, which takes about a third of the scalar pass's instructions
 * (R1 was half the area rules' cost on the cube's distant pairs in
 * reference mode). */
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
RAD_KERNEL_CLONES
static int area_terms_lanes(const rad_vec3 *pa, const double *wa, const rad_vec3 *na, int ma,
                            const rad_vec3 *pb, const double *wb, const rad_vec3 *nb, int mb,
                            area_terms *at)
{
    const int m4 = (mb + 3) & ~3;
    double *buf = malloc(sizeof *buf * 7 * (size_t)(m4 > 0 ? m4 : 4));
    if (!buf)
        return 0;
    double *bx = buf, *by = bx + m4, *bz = by + m4, *cx = bz + m4, *cy = cx + m4,
           *cz = cy + m4, *bw = cz + m4;
    for (int l = 0; l < m4; l++) { /* padded with b's first point, weighted 0 */
        const int i = l < mb ? l : 0;
        bx[l] = pb[i].x, by[l] = pb[i].y, bz[l] = pb[i].z;
        cx[l] = nb[i].x, cy[l] = nb[i].y, cz[l] = nb[i].z;
        bw[l] = l < mb ? fabs(wb[i]) : 0;
    }
    rad_v4d t[6] = {{0}};
    for (int k = 0; k < ma; k++) {
        const double wk = fabs(wa[k]);
        for (int l = 0; l < m4; l += 4) {
            rad_v4d dx, dy, dz, nx, ny, nz, w;
            memcpy(&dx, bx + l, sizeof dx);
            memcpy(&dy, by + l, sizeof dy);
            memcpy(&dz, bz + l, sizeof dz);
            memcpy(&nx, cx + l, sizeof nx);
            memcpy(&ny, cy + l, sizeof ny);
            memcpy(&nz, cz + l, sizeof nz);
            memcpy(&w, bw + l, sizeof w);
            dx -= pa[k].x, dy -= pa[k].y, dz -= pa[k].z;
            const rad_v4d r2 = dx * dx + dy * dy + dz * dz;
            rad_v4d dk = na[k].x * dx + na[k].y * dy + na[k].z * dz;
            rad_v4d dl = nx * dx + ny * dy + nz * dz;
            const rad_v4d r = {sqrt(r2[0]), sqrt(r2[1]), sqrt(r2[2]), sqrt(r2[3])};
            dk = (rad_v4d)((rad_v4u)dk & 0x7fffffffffffffffULL); /* |n_k . d| */
            dl = (rad_v4d)((rad_v4u)dl & 0x7fffffffffffffffULL);
            w = wk * w / (r2 * r2);
            const rad_v4d u = w * dl, v = w * dk, x = u * dk;
            t[0] += u * r;
            t[1] += u;
            t[2] += v * r;
            t[3] += v;
            t[4] += x / r;
            t[5] += x;
        }
    }
    free(buf);
    for (int i = 0; i < 6; i++)
        at->t[i] = (t[i][0] + t[i][1]) + (t[i][2] + t[i][3]);
    at->known = 1;
    return 1;
}
#pragma GCC diagnostic pop
#else
static int area_terms_lanes(const rad_vec3 *pa, const double *wa, const rad_vec3 *na, int ma,
                            const rad_vec3 *pb, const double *wb, const rad_vec3 *nb, int mb,
                            area_terms *at)
{
    (void)pa, (void)wa, (void)na, (void)ma, (void)pb, (void)wb, (void)nb, (void)mb, (void)at;
    return 0;
}
#endif

/* R2 (see the top of the file) for the points' weights, or infinity
 * when the point sets may touch (rmin 0). */
static double prior_bound(const double *wa, int ma, const double *wb, int mb, double eps,
                          const double nu[2], double R0, double rmin)
{
    if (!(rmin > 0))
        return INFINITY;
    double Wa = 0, Wb = 0;
    for (int k = 0; k < ma; k++)
        Wa += fabs(wa[k]);
    for (int l = 0; l < mb; l++)
        Wb += fabs(wb[l]);
    const double ca = nu[0] + 6 * eps, cb = nu[1] + 6 * eps;
    const double c3 = eps * (20 + ma + mb) + 2 * (nu[0] + nu[1]);
    return 2 * Wa * Wb / (rmin * rmin) * (ca + cb + c3 + 176 * eps * (R0 / rmin));
}

/* The round-off of area_sum over the same points, bounded (see the top
 * of the file, eqs. R1 and R2): the a priori R2 where it is within
 * `budget`, else R1 from the sums *at (computed on first need).  R0
 * bounds the distance of the points' corners from the points' origin,
 * rmin the distance between the point sets. */
static double area_roundoff(const rad_vec3 *pa, const double *wa, const rad_vec3 *na, int ma,
                            const rad_vec3 *pb, const double *wb, const rad_vec3 *nb, int mb,
                            double eps, const double nu[2], double R0, double rmin,
                            double budget, area_terms *at)
{
    const double pri = prior_bound(wa, ma, wb, mb, eps, nu, R0, rmin); /* R2 */
    if (pri <= budget)
        return pri;
    if (!at->known && !area_terms_lanes(pa, wa, na, ma, pb, wb, nb, mb, at)) /* R1 */
        (void)area_sum_terms(pa, wa, na, ma, pb, wb, nb, mb, at);
    const double ca = nu[0] + 6 * eps, cb = nu[1] + 6 * eps, c2 = 32 * eps * R0;
    const double c3 = eps * (20 + ma + mb) + 2 * (nu[0] + nu[1]);
    const double *t = at->t;
    return 2 * (ca * t[0] + c2 * (t[1] + t[3]) + cb * t[2] + 112 * eps * R0 * t[4] + c3 * t[5]);
}

/* The sum *s of the rule of order k over the points pts (ma of a at pa,
 * mb of b at pb, weights and normals alike), parts a and b: its round-off
 * bound, and where that exceeds budget, the sum again in long double
 * (ffarealong.c) in *s, with its own bound and the rounding to double. */
static double sum_roundoff(const rad_vec3 *pa, const double *wa, const rad_vec3 *na, int ma,
                           const rad_vec3 *pb, const double *wb, const rad_vec3 *nb, int mb,
                           const rad_ff_area_part *a, const rad_ff_area_part *b,
                           rad_vec3 origin, int k, double R0, double rmin, double budget,
                           area_terms *at, double *s)
{
    const double nu[2] = {a->doubt, b->doubt};
    const double ro = area_roundoff(pa, wa, na, ma, pb, wb, nb, mb, DBL_EPSILON, nu, R0, rmin,
                                    budget, at);
    double sl, nul[2];
    if (ro <= budget || LDBL_EPSILON >= DBL_EPSILON ||
        radi_ff_area_long(a, b, origin, k, &sl, nul) != 0)
        return ro;
    *s = sl;
    return area_roundoff(pa, wa, na, ma, pb, wb, nb, mb, LDBL_EPSILON, nul, R0, rmin, budget,
                         at) +
           0.5 * DBL_EPSILON * fabs(sl);
}

/* The largest distance of polygon p's vertices from origin */
static double reach(const rad_vec3 *p, int n, rad_vec3 origin)
{
    double R = 0;
    for (int k = 0; k < n; k++)
        R = fmax(R, v3_norm(v3_sub(p[k], origin)));
    return R;
}

/* The error of the last of three or more orders from the differences d
 * (this one's), d1 and d2 (the two before; NaN when not yet known): the
 * geometric tail d q / (1 - q), q = d / d1; d alone for q <= 1/2, and no
 * claim at all without a previous difference that is larger.  d may be
 * small by chance, two orders agreeing while both err (the differences of
 * two strips at 2.6 degrees, cut 16 times where they needed 23: 6.8e-15,
 * 4.9e-16, 5.3e-20, 6.1e-18): where d1 and d2 are known, d is taken as at
 * least what their ratio predicts, d1^2 / d2, and where d1 is, at least
 * d1 qmin, the fastest fall the rule's convergence allows (see the top of
 * the file; 0 for no such floor). */
static double tail(double d, double d1, double d2, double qmin)
{
    if (d2 > 0 && d1 * (d1 / d2) > d)
        d = d1 * (d1 / d2);
    if (d1 * qmin > d)
        d = d1 * qmin;
    const double q = d / d1;
    return q <= 0.5 ? d : q < 1 ? d * q / (1 - q) : INFINITY;
}

int radi_ff_area(const rad_vec3 *a, int na, const rad_vec3 *b, int nb, rad_vec3 origin,
                const rad_ff_poly *const el[2], double rel_tol, double *s_out,
                double *err_out)
{
    enum { SMALL = 2 * AREA_ORDER_MAX * AREA_ORDER_MAX * 3 };
    rad_vec3 pts_small[2 * SMALL];
    double w_small[SMALL];
    const double D = vertex_box_gap(a, na, b, nb);
    const area_side sa = side_of(a, na, origin, el[0]);
    const area_side sb = side_of(b, nb, origin, el[1]);
    int nua, nva, nub, nvb;
    split_counts(a, na, D, &nua, &nva);
    split_counts(b, nb, D, &nub, &nvb);
    const double qmin =
        fastest_fall(fmax(part_side(a, na, nua, nva), part_side(b, nb, nub, nvb)), D);
    const int capa = count_points(na, AREA_ORDER_MAX, nua, nva);
    const int capb = count_points(nb, AREA_ORDER_MAX, nub, nvb);
    const int heap = capa + capb > SMALL;
    /* points, then their normals; weights */
    rad_vec3 *pts = heap ? malloc(sizeof *pts * 2 * (size_t)(capa + capb)) : pts_small;
    double *w = heap ? malloc(sizeof *w * (size_t)(capa + capb)) : w_small;
    double prev = NAN, dprev = NAN, dprev2 = NAN;
    int ok = 0;
    if (!pts || !w) {
        if (heap) {
            free(pts);
            free(w);
        }
        return -1;
    }
    /* polygons of many vertices start at order 1 (their fans are fine already) */
    for (int k = na > 4 || nb > 4 ? 1 : 2; k <= AREA_ORDER_MAX && !ok; k++) {
        rad_vec3 *nrm = pts + capa + capb;
        int ma = polygon_points(a, na, origin, k, nua, nva, &sa, pts, w, nrm);
        int mb = polygon_points(b, nb, origin, k, nub, nvb, &sb, pts + capa, w + capa,
                                nrm + capa);
        double s = area_sum(pts, w, nrm, ma, pts + capa, w + capa, nrm + capa, mb);
        const double d = fabs(s - prev);
        if (isfinite(prev) && d <= rel_tol * fabs(s)) {
            const double e = tail(d, dprev, dprev2, qmin);
            if (e <= rel_tol * fabs(s)) {
                const double R0 = fmax(reach(a, na, origin), reach(b, nb, origin));
                const rad_ff_area_part qa = {a, na, nua, nva, sa.twisted, sa.nrm, sa.nu};
                const rad_ff_area_part qb = {b, nb, nub, nvb, sb.twisted, sb.nrm, sb.nu};
                area_terms at = {{0}, 0};
                const double ro = sum_roundoff(pts, w, nrm, ma, pts + capa, w + capa,
                                               nrm + capa, mb, &qa, &qb, origin, k, R0, D,
                                               0.1 * rel_tol * fabs(s), &at, &s);
                *s_out = s;
                *err_out = e + ro;
                ok = 1;
            }
        }
        dprev2 = dprev;
        dprev = d;
        prev = s;
        if ((size_t)ma * (size_t)mb > 4000000)
            break; /* too many points: the contour is cheaper */
    }
    if (heap) {
        free(pts);
        free(w);
    }
    return ok ? 0 : 1;
}

/* ---- adaptive area rules ---------------------------------------------------
 *
 * Two long strips end to end, or a strip beside a large plate, are neither
 * small against their distance (so one product rule over each polygon
 * needs orders beyond reach where they come closest) nor free of
 * cancellation in the contour (their terms exceed S by 1e10 when they are
 * nearly coplanar).  Cut into parts, though, every pair of parts is: the
 * polygons become bilinear patches (a quadrilateral its own map of the
 * unit square, any other polygon a fan of collapsed squares, as above),
 * and a pair of patches whose larger is longer than ADAPT_ETA times their
 * distance (the gap between their bounding boxes) has that larger one cut
 * in two across its longer side; a pair close enough is integrated with
 * ADAPT_K and ADAPT_K + 2 points per side, and the difference is its error
 * estimate (the higher order errs far less: a patch at least 1/ADAPT_ETA
 * times its size away lies inside a Bernstein ellipse of rho > 11 for the
 * integrand, so 2k points err by about rho^-2k, 1e-13 and 1e-17).  The
 * integrand has one sign throughout (facing polygons), so the sums over
 * parts do not cancel.  At most ADAPT_LEAVES pairs are integrated;
 * patches that touch never become close enough and end the attempt.
 */

#define ADAPT_ETA 0.35
#define ADAPT_K 6
#define ADAPT_LEAVES 4000
#define ADAPT_STACK 256

typedef struct patch {
    rad_vec3 q[4]; /* the bilinear map's corners, relative to the origin */
    rad_vec3 lo, hi;
    double size;   /* bounding-box diagonal */
} patch;

static void patch_set(patch *p, rad_vec3 q0, rad_vec3 q1, rad_vec3 q2, rad_vec3 q3)
{
    p->q[0] = q0;
    p->q[1] = q1;
    p->q[2] = q2;
    p->q[3] = q3;
    v3_bounds(p->q, 4, &p->lo, &p->hi);
    p->size = v3_norm(v3_sub(p->hi, p->lo));
}

/* Cut p in two across its longer side (the bilinear map restricted to
 * half the square is the bilinear map of the half's corners). */
static void patch_split(const patch *p, patch *a, patch *b)
{
    const rad_vec3 *q = p->q;
    const double lu = v3_norm(v3_sub(q[1], q[0])) + v3_norm(v3_sub(q[2], q[3]));
    const double lv = v3_norm(v3_sub(q[3], q[0])) + v3_norm(v3_sub(q[2], q[1]));
    if (lu >= lv) {
        const rad_vec3 m01 = v3_lerp(q[0], q[1], 0.5), m32 = v3_lerp(q[3], q[2], 0.5);
        patch_set(a, q[0], m01, m32, q[3]);
        patch_set(b, m01, q[1], q[2], m32);
    } else {
        const rad_vec3 m03 = v3_lerp(q[0], q[3], 0.5), m12 = v3_lerp(q[1], q[2], 0.5);
        patch_set(a, q[0], q[1], m12, m03);
        patch_set(b, m03, m12, q[2], q[3]);
    }
}

static double patch_gap(const patch *a, const patch *b)
{
    return sqrt(v3_box_gap2(a->lo, a->hi, b->lo, b->hi));
}

/* The polygon as patches: a quadrilateral one, any other n - 2 collapsed
 * squares (P(u, v) = v0 + u (v_k - v0) + u v (v_k+1 - v_k): corners v0,
 * v_k, v_k+1, v0).  Returns the count. */
static int polygon_patches(const rad_vec3 *p, int n, rad_vec3 origin, patch *out)
{
    if (n == 4) {
        patch_set(out, v3_sub(p[0], origin), v3_sub(p[1], origin), v3_sub(p[2], origin),
                  v3_sub(p[3], origin));
        return 1;
    }
    const rad_vec3 v0 = v3_sub(p[0], origin);
    for (int t = 1; t + 1 < n; t++)
        patch_set(&out[t - 1], v0, v3_sub(p[t], origin), v3_sub(p[t + 1], origin), v0);
    return n - 2;
}

/* Split patch pair stack[2 (top - 1)], [2 (top - 1) + 1] (walk_cuts,
 * below): the larger cut in two, the pair replaced by two (top grows by
 * one). */
static void split_top(patch *stack, int top)
{
    patch *pp = &stack[2 * (top - 1)], *qq = pp + 1;
    patch x1, x2;
    const int first = pp->size >= qq->size;
    patch_split(first ? pp : qq, &x1, &x2);
    const patch other = first ? *qq : *pp;
    pp[0] = first ? x1 : other;
    pp[1] = first ? other : x1;
    pp[2] = first ? x2 : other;
    pp[3] = first ? other : x2;
}

/* The pair of patches x, y, close enough: the rule with ADAPT_K and
 * ADAPT_K + 2 points per side, the second added to *s (in long double
 * where its round-off would take more than its share of rel: sum_roundoff),
 * the difference to *e and the round-off bound to *ro. */
static void close_pair(const patch *x, const patch *y, const area_side *sa,
                       const area_side *sb, double rel, double *s, double *e, double *ro)
{
    enum { K = ADAPT_K, K2 = ADAPT_K + 2 };
    rad_vec3 pa[K2 * K2], pb[K2 * K2], ma[K2 * K2], mb[K2 * K2];
    double wa[K2 * K2], wb[K2 * K2], sk[2];
    const double R0 = fmax(reach(x->q, 4, v3(0, 0, 0)), reach(y->q, 4, v3(0, 0, 0)));
    const double gap = patch_gap(x, y), nu[2] = {sa->nu, sb->nu};
    area_terms at = {{0}, 0};
    for (int o = 0; o < 2; o++) {
        const int k = o ? K2 : K;
        int na2 = polygon_points(x->q, 4, v3(0, 0, 0), k, 1, 1, sa, pa, wa, ma);
        int nb2 = polygon_points(y->q, 4, v3(0, 0, 0), k, 1, 1, sb, pb, wb, mb);
        /* where R2 will not do (judged by the lower order's sum), the
         * sums R1 needs come in the same pass */
        sk[o] = o && prior_bound(wa, na2, wb, nb2, DBL_EPSILON, nu, R0, gap) >
                         0.1 * rel * fabs(sk[0])
                    ? area_sum_terms(pa, wa, ma, na2, pb, wb, mb, nb2, &at)
                    : area_sum(pa, wa, ma, na2, pb, wb, mb, nb2);
    }
    const rad_ff_area_part qa = {x->q, 4, 1, 1, sa->twisted, sa->nrm, sa->nu};
    const rad_ff_area_part qb = {y->q, 4, 1, 1, sb->twisted, sb->nrm, sb->nu};
    *e += fabs(sk[1] - sk[0]);
    *ro += sum_roundoff(pa, wa, ma, K2 * K2, pb, wb, mb, K2 * K2, &qa, &qb, v3(0, 0, 0), K2, R0,
                        gap, 0.1 * rel * fabs(sk[1]), &at, &sk[1]);
    *s += sk[1];
}

/* The cuts of every pair of patches ta[i], tb[j] (stack: room for
 * ADAPT_STACK pairs), each close pair integrated by close_pair into *s,
 * *e and *ro, or, with s NULL, only counted.  1 when the cuts end within
 * ADAPT_LEAVES close pairs, with no pair touching and no stack deeper
 * than ADAPT_STACK; else 0.  The cuts depend on bounding boxes alone, so
 * a walk with s NULL first lets a pair that cannot succeed give up
 * without a single evaluation, rather than after ADAPT_LEAVES
 * integrations of (ADAPT_K + 2)^4 points.  (Seen in a fuzzed scene, two
 * strips of 2.6e-4 by 1.2e-8 hinged at 0.1 degree, meshed 5x6: every
 * pair that met the hinge spent its 4000 leaves before giving up, 48 s
 * for the scene in default mode.) */
static int walk_cuts(const patch *ta, int ma, const patch *tb, int mb, patch *stack,
                     const area_side *sa, const area_side *sb, double rel, double *s,
                     double *e, double *ro)
{
    int leaves = 0;
    for (int i = 0; i < ma; i++)
        for (int j = 0; j < mb; j++) {
            int top = 1;
            stack[0] = ta[i];
            stack[1] = tb[j];
            while (top > 0) {
                const patch *pp = &stack[2 * (top - 1)], *qq = pp + 1;
                const double gap = patch_gap(pp, qq);
                if (fmax(pp->size, qq->size) <= ADAPT_ETA * gap) {
                    if (++leaves > ADAPT_LEAVES)
                        return 0;
                    if (s)
                        close_pair(pp, qq, sa, sb, rel, s, e, ro);
                    top--;
                } else if (!(gap > 0) || top >= ADAPT_STACK) {
                    return 0; /* touching, or too deep: not for this method */
                } else {
                    split_top(stack, top); /* cut the larger; the pair becomes two */
                    top++;
                }
            }
        }
    return 1;
}

int radi_ff_area_adaptive(const rad_vec3 *a, int na, const rad_vec3 *b, int nb,
                         rad_vec3 origin, const rad_ff_poly *const el[2], double rel_tol,
                         double *s_out, double *err_out)
{
    patch *stack = malloc(sizeof *stack * 2 * ADAPT_STACK);
    patch *ta = malloc(sizeof *ta * (size_t)(na > 2 ? na - 2 : 1));
    patch *tb = malloc(sizeof *tb * (size_t)(nb > 2 ? nb - 2 : 1));
    if (!stack || !ta || !tb) {
        free(stack);
        free(ta);
        free(tb);
        return -1;
    }
    const int ma = polygon_patches(a, na, origin, ta), mb = polygon_patches(b, nb, origin, tb);
    double s = 0, e = 0, ro = 0;
    const area_side sa = side_of(a, na, origin, el[0]);
    const area_side sb = side_of(b, nb, origin, el[1]);
    const int ok = walk_cuts(ta, ma, tb, mb, stack, &sa, &sb, rel_tol, NULL, NULL, NULL) &&
                   walk_cuts(ta, ma, tb, mb, stack, &sa, &sb, rel_tol, &s, &e, &ro);
    free(stack);
    free(ta);
    free(tb);
    if (!ok || !(e <= rel_tol * fabs(s)))
        return 1;
    *s_out = s;
    *err_out = e + ro; /* the round-off, which no finer cut lessens, is not held to rel_tol */
    return 0;
}
