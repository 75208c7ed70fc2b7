/* test_occrule.c -- the points and weights of the hidden-part rules
 * (src/occ/occrule.c, occ_rule_points): the collapsed rule on a triangle and
 * the bilinear product rule on a quadrilateral integrate polynomials of
 * degree <= 2k - 2 exactly, a quadrilateral's four children
 * (occ_cell_children: at its edges' midpoints and its vertices' mean) add
 * up to it, and the odd orders share their middle point with order 1.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The exact integrals come from the divergence theorem, not from a rule:
 * with s and t orthonormal coordinates of the cell's plane (s along a
 * unit direction n of the plane, t along N x n, N the cell's normal),
 *     integral over P of s^d dA = contour integral of s^(d+1)/(d+1) dt,
 * and along an edge from (s0, t0) to (s1, t1), s linear in the edge's
 * parameter,
 *     (t1 - t0) (s1^(d+2) - s0^(d+2)) / ((d+1)(d+2)(s1 - s0))
 * (the limit (t1 - t0) s0^(d+1) / (d+1) when s1 = s0).  Powers of linear
 * forms in three directions span the polynomials of each degree in two
 * variables up to degree 2 (and enough of every degree to catch a wrong
 * Jacobian, which errs already at degree 0), so checking s^d for three
 * directions and every d <= 2k - 2 checks the claimed exactness.  The
 * cells lie on a tilted plane far from the origin, and the quadrilateral
 * is no parallelogram (its Jacobian is not constant).  Tolerance 1e-12
 * relative: k^2 <= 100 terms of one sign, each within a few ulps.
 */
#include <config.h>

#include <math.h>

#include "ff/gausstab.h"
#include "occ/occspace.h"
#include "../tap.h"
#include "util/vec.h"

/* The exact integral of (n . (x - o))^d over the convex polygon p (m
 * vertices counter-clockwise about N), by the edge formula above. */
static double exact(const rad_vec3 *p, int m, rad_vec3 N, rad_vec3 n, rad_vec3 o, int d)
{
    const rad_vec3 tdir = v3_cross(N, n);
    double sum = 0;
    for (int k = 0; k < m; k++) {
        const rad_vec3 a = v3_sub(p[k], o), b = v3_sub(p[(k + 1) % m], o);
        const double s0 = v3_dot(n, a), s1 = v3_dot(n, b);
        const double dt = v3_dot(tdir, b) - v3_dot(tdir, a);
        if (fabs(s1 - s0) > 1e-12 * (fabs(s0) + fabs(s1)))
            sum += dt * (pow(s1, d + 2) - pow(s0, d + 2)) / ((d + 1.0) * (d + 2.0) * (s1 - s0));
        else
            sum += dt * pow(s0, d + 1) / (d + 1.0);
    }
    return sum;
}

static rad_vec3 unit(rad_vec3 a)
{
    return v3_scale(a, 1.0 / v3_norm(a));
}

static double by_rule(int k, const rad_vec3 *p, int nv, double area, rad_vec3 n, rad_vec3 o,
                      int d)
{
    rad_vec3 x[RAD_GAUSS_MAX * RAD_GAUSS_MAX];
    double w[RAD_GAUSS_MAX * RAD_GAUSS_MAX];
    const int m = occ_rule_points(k, p, nv, area, x, w);
    double sum = 0;
    for (int l = 0; l < m; l++)
        sum += w[l] * pow(v3_dot(n, v3_sub(x[l], o)), d);
    return sum;
}

/* The worst relative error of the rule over k = 1..10, three directions
 * and degrees 0..2k-2 (+ extra: degrees past the claim). */
static double worst(const rad_vec3 *p, int nv, rad_vec3 N, const rad_vec3 *dirs, rad_vec3 o,
                    int extra)
{
    const double area = 0.5 * v3_norm(v3_newell(p, nv));
    double w = 0;
    for (int k = 1; k <= 10; k++)
        for (int j = 0; j < 3; j++)
            for (int d = 0; d <= 2 * k - 2 + extra; d++) {
                const double e = exact(p, nv, N, dirs[j], o, d);
                w = fmax(w, fabs(by_rule(k, p, nv, area, dirs[j], o, d) - e) / fabs(e));
            }
    return w;
}

int main(void)
{
    /* a plane through c with unit normal N, and three in-plane directions */
    const rad_vec3 c = v3(1e3, -2e3, 5e2);
    const rad_vec3 N = unit(v3(1, 2, 2));
    const rad_vec3 e1 = unit(v3_cross(N, v3(0, 0, 1))), e2 = v3_cross(N, e1);
    rad_vec3 dirs[3] = {e1, e2, unit(v3_add(e1, v3_scale(e2, 0.7)))};
    /* in-plane points (2D coordinates), counter-clockwise about N: a
     * quadrilateral that is no parallelogram, and a triangle */
    const double q2[4][2] = {{0, 0}, {2.0, 0.1}, {1.7, 1.3}, {0.2, 0.9}};
    const double t2[3][2] = {{0.3, 0.2}, {1.9, 0.5}, {0.6, 1.4}};
    rad_vec3 q[4], t[3];
    for (int k = 0; k < 4; k++)
        q[k] = v3_add(c, v3_add(v3_scale(e1, q2[k][0]), v3_scale(e2, q2[k][1])));
    for (int k = 0; k < 3; k++)
        t[k] = v3_add(c, v3_add(v3_scale(e1, t2[k][0]), v3_scale(e2, t2[k][1])));
    /* the origin of s near the cells: s^d is then no near-cancelling sum */
    const rad_vec3 o = v3_sub(c, v3_add(e1, e2));

    double wt = worst(t, 3, N, dirs, o, 0);
    tap_ok(wt <= 1e-12, "triangle, collapsed rule: exact for degree <= 2k - 2, k = 1..10 (%.2g)",
           wt);
    double wq = worst(q, 4, N, dirs, o, 0);
    tap_ok(wq <= 1e-12, "quadrilateral, bilinear rule: exact for degree <= 2k - 2, k = 1..10 "
           "(%.2g)", wq);
    /* the check can fail: two degrees past the claim, the rule is off */
    double wx = worst(q, 4, N, dirs, o, 2);
    tap_ok(wx > 1e-9, "quadrilateral: not exact two degrees past the claim (%.2g)", wx);

    /* the children of a split (occ_cell_children) tile the cell: the
     * order-5 rule on the four children integrates s^8 exactly, so their
     * sum is the exact integral over the parent */
    rad_vec3 ch[4][4];
    occ_cell_children(q, 4, ch);
    double sum = 0;
    for (int l = 0; l < 4; l++)
        sum += by_rule(5, ch[l], 4, 0, dirs[2], o, 8);
    const double e = exact(q, 4, N, dirs[2], o, 8);
    tap_ok(fabs(sum - e) <= 1e-12 * fabs(e), "four children of the quadrilateral add up to it "
           "(s^8, order 5: %.2g relative)", fabs(sum - e) / fabs(e));

    /* occ_rule_order evaluates the point u = v = 1/2 once for orders 1, 3
     * and 5 (its index (k/2) k + k/2): that point must be the same, bit
     * for bit, in each */
    int same = 1;
    for (int nv = 3; nv <= 4; nv++) {
        const rad_vec3 *p = nv == 4 ? q : t;
        rad_vec3 x1[1], x[RAD_GAUSS_MAX * RAD_GAUSS_MAX];
        double w1[1], w[RAD_GAUSS_MAX * RAD_GAUSS_MAX];
        occ_rule_points(1, p, nv, 1.0, x1, w1);
        for (int k = 3; k <= 9; k += 2) {
            occ_rule_points(k, p, nv, 1.0, x, w);
            const rad_vec3 m = x[(k / 2) * k + k / 2];
            same &= m.x == x1[0].x && m.y == x1[0].y && m.z == x1[0].z;
        }
    }
    tap_ok(same, "the odd orders' middle point is order 1's, bit for bit (triangle and "
           "quadrilateral, k = 3..9)");
    return tap_done();
}
