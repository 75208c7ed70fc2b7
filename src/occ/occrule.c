/* occrule.c -- the quadrature rules of the hidden-part integral
 * (occhidden.c) on one cell (triangle or quadrilateral) of the outer
 * element.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Two rules, chosen by pair_ctx.order:
 *
 * order 0 (classic mode): the 3-point degree-2 rule (Strang & Fix 1973):
 * points at barycentric (2/3, 1/6, 1/6) and its permutations, weights
 * area / 3.
 *
 * order k >= 2 (default and reference modes): the collapsed Gauss product
 * rule (the conical product of Stroud, "Approximate Calculation of
 * Multiple Integrals", 1971, sec. 2.7; the map is Duffy's, SIAM J. Numer.
 * Anal. 19, 1982).  The triangle p0 p1 p2 is the image of the unit square
 * under
 *     x(u, v) = p0 + u (p1 - p0) + u v (p2 - p1),   dx = 2 A u du dv      (1)
 * (A the triangle's area), and the k-point Gauss-Legendre rule (A & S
 * 25.4.29, gausstab.h) runs in u and in v.  A polynomial of degree d in x
 * becomes one of degree d + 1 in u (with the Jacobian's u) and d in v, so
 * the rule is exact for d <= 2k - 2.  A convex quadrilateral piece of the
 * domain is one cell, not two triangles: the product rule on its bilinear
 * map (2, below) has the same exactness with the same k^2 points, so it
 * halves the first evaluations of a quadrilateral piece and of its
 * children.  Where hidden(x) is smooth (inside
 * the pieces that the event planes cut: occdomain.c) its error falls as
 * h^(2k - 1) with the cell's size h, against h^3 for the 3-point rule,
 * so the adaptive rule of occhidden.c reaches 1e-9 of a pair's value with
 * a few levels instead of millions of triangles.
 */
#include <config.h>

#include <math.h>
#include <string.h>

#include "ff/formfactor.h"
#include "occ/occspace.h"
#include "util/util.h"

/* The 3-point degree-2 rule (order 0, above). */
static int rule3(occ_space *sp, const pair_ctx *c, const rad_vec3 *p, double area, double *q)
{
    double sum = 0;
    for (int k = 0; k < 3; k++) {
        rad_vec3 x = v3_add(v3_scale(p[k], 2.0 / 3.0),
                            v3_scale(v3_add(p[(k + 1) % 3], p[(k + 2) % 3]), 1.0 / 6.0));
        double h;
        if (occ_hidden_at(sp, c, x, &h))
            return -1;
        sum += h;
    }
    *q = area / 3.0 * sum;
    return 0;
}

/* The points and weights of the collapsed k x k Gauss product rule (1)
 * on triangle p of area `area`. */
static void points_collapsed(int k, const rad_vec3 *p, double area, rad_vec3 *x, double *w)
{
    const double *t = gl_nodes(k), *g = gl_weights(k);
    const rad_vec3 e1 = v3_sub(p[1], p[0]), e2 = v3_sub(p[2], p[1]);
    for (int a = 0; a < k; a++) {
        const double u = 0.5 * (1 + t[a]); /* [-1, 1] to [0, 1] */
        for (int b = 0; b < k; b++) {
            const double v = 0.5 * (1 + t[b]);
            x[a * k + b] = v3_add(p[0], v3_add(v3_scale(e1, u), v3_scale(e2, u * v)));
            /* (1) with du dv = (1/2)(1/2) of the weights' [-1, 1] measure */
            w[a * k + b] = 2 * area * 0.25 * g[a] * u * g[b];
        }
    }
}

/* The points and weights of the k x k Gauss product rule on the convex
 * planar quadrilateral p0 p1 p2 p3, the image of the unit square under
 * the bilinear map
 *     x(u, v) = (1-u)(1-v) p0 + u(1-v) p1 + u v p2 + (1-u) v p3
 *             = p0 + u a + v b + u v e,                                 (2)
 * a = p1 - p0, b = p3 - p0, e = p2 - p3 - p1 + p0, with
 *     dx = |x_u x x_v| du dv = |(a + v e) x (b + u e)| du dv
 * (Stroud 1971, sec. 1.6; the isoparametric quadrilateral of finite
 * elements, Zienkiewicz & Taylor, "The Finite Element Method", vol. 1,
 * sec. 8.4).  On a plane e x e = 0 leaves the Jacobian affine in u and v,
 * so the rule is exact, as (1) is, for polynomials of degree <= 2k - 2 in
 * x; it spends none of its points crowding a collapsed corner, and one
 * quadrilateral takes half the points of its two fan triangles.  The map
 * covers the cell once only when the cell is convex (the pieces of the
 * domain are: each is a convex polygon cut by planes); |J| then never
 * changes sign, and a repeated vertex or three in a line only make it
 * vanish at a corner, where the rule stays exact. */
static void points_quad(int k, const rad_vec3 *p, rad_vec3 *x, double *w)
{
    const double *t = gl_nodes(k), *g = gl_weights(k);
    const rad_vec3 a = v3_sub(p[1], p[0]), b = v3_sub(p[3], p[0]),
                   e = v3_sub(v3_sub(p[2], p[3]), a);
    for (int i = 0; i < k; i++) {
        const double u = 0.5 * (1 + t[i]);
        const rad_vec3 xv = v3_add(b, v3_scale(e, u));
        for (int j = 0; j < k; j++) {
            const double v = 0.5 * (1 + t[j]);
            x[i * k + j] = v3_add(p[0], v3_add(v3_add(v3_scale(a, u), v3_scale(b, v)),
                                               v3_scale(e, u * v)));
            w[i * k + j] = 0.25 * g[i] * g[j] * v3_norm(v3_cross(v3_add(a, v3_scale(e, v)), xv));
        }
    }
}

void occ_cell_children(const rad_vec3 *p, int nv, rad_vec3 ch[4][4])
{
    if (nv == 3) { /* the midpoint triangles (their fourth vertex unused) */
        rad_vec3 m01 = v3_lerp(p[0], p[1], 0.5), m12 = v3_lerp(p[1], p[2], 0.5),
                 m20 = v3_lerp(p[2], p[0], 0.5);
        rad_vec3 t[4][4] = {{p[0], m01, m20}, {m01, p[1], m12}, {m20, m12, p[2]},
                            {m12, m20, m01}};
        memcpy(ch, t, sizeof t);
        return;
    }
    /* the quarters of (2): corners at the edges' midpoints and x(1/2, 1/2),
     * the mean of the four vertices */
    rad_vec3 m01 = v3_lerp(p[0], p[1], 0.5), m12 = v3_lerp(p[1], p[2], 0.5),
             m23 = v3_lerp(p[2], p[3], 0.5), m30 = v3_lerp(p[3], p[0], 0.5),
             mid = v3_lerp(m01, m23, 0.5);
    rad_vec3 t[4][4] = {{p[0], m01, mid, m30}, {m01, p[1], m12, mid},
                        {mid, m12, p[2], m23}, {m30, mid, m23, p[3]}};
    memcpy(ch, t, sizeof t);
}

int occ_rule_points(int k, const rad_vec3 *p, int nv, double area, rad_vec3 *x, double *w)
{
    if (nv == 4)
        points_quad(k, p, x, w);
    else
        points_collapsed(k, p, area, x, w);
    return k * k;
}

/* The rule of order k (1 <= k <= RAD_GAUSS_MAX) on the cell p of nv (3 or
 * 4) vertices: (1) on a triangle, (2) on a quadrilateral.  Rules of odd
 * order share one point, u = v = 1/2 (the middle node of each): with
 * `center` not NULL its value is taken from *center when that is not NaN,
 * else stored there, so that a cell's rules of orders 1, 3 and 5 evaluate
 * it once (the point is computed by the same expression, so the value is
 * the same bit for bit). */
int occ_rule_order(occ_space *sp, const pair_ctx *c, int k, const rad_vec3 *p, int nv,
                   double area, double *q, double *center)
{
    rad_vec3 x[RAD_GAUSS_MAX * RAD_GAUSS_MAX];
    double w[RAD_GAUSS_MAX * RAD_GAUSS_MAX];
    const int n = occ_rule_points(k, p, nv, area, x, w);
    const int mid = center && k % 2 ? (k / 2) * k + k / 2 : -1;
    double sum = 0;
    for (int l = 0; l < n; l++) {
        double h;
        if (l == mid && !isnan(*center))
            h = *center;
        else if (occ_hidden_at(sp, c, x[l], &h))
            return -1;
        else if (l == mid)
            *center = h;
        sum += w[l] * h;
    }
    *q = sum;
    return 0;
}

/* The integral of hidden(x) over triangle p (area `area`) by c's rule. */
int occ_rule(occ_space *sp, const pair_ctx *c, const rad_vec3 *p, double area, double *q)
{
    return c->order >= 2 ? occ_rule_order(sp, c, c->order, p, 3, area, q, NULL)
                         : rule3(sp, c, p, area, q);
}
