/* occrule.c -- the quadrature rules of the hidden-part integral
 * (occhidden.c) on one triangle of the outer element.
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
 * the rule is exact for d <= 2k - 2.  Where hidden(x) is smooth (inside
 * the pieces that the event planes cut: occdomain.c) its error falls as
 * h^(2k - 1) with the triangle's size h, against h^3 for the 3-point rule,
 * so the adaptive rule of occhidden.c reaches 1e-9 of a pair's value with
 * a few levels instead of millions of triangles.
 */
#include <config.h>

#include <math.h>

#include "gausstab.h"
#include "occspace.h"
#include "vec.h"

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

/* The collapsed k x k Gauss product rule (1).  Rules of odd order share
 * one point, u = v = 1/2 (the node 0 of each): with `center` not NULL
 * its value is taken from *center when that is not NaN, else stored
 * there, so that a triangle's rules of orders 1, 3 and 5 evaluate it once
 * (the point is computed by the same expression, so the value is the
 * same bit for bit). */
static int rule_collapsed(occ_space *sp, const pair_ctx *c, int k, const rad_vec3 *p,
                          double area, double *q, double *center)
{
    const double *t = gl_nodes(k), *w = gl_weights(k);
    const rad_vec3 e1 = v3_sub(p[1], p[0]), e2 = v3_sub(p[2], p[1]);
    double sum = 0;
    for (int a = 0; a < k; a++) {
        const double u = 0.5 * (1 + t[a]); /* [-1, 1] to [0, 1] */
        double row = 0;
        for (int b = 0; b < k; b++) {
            const double v = 0.5 * (1 + t[b]);
            rad_vec3 x = v3_add(p[0], v3_add(v3_scale(e1, u), v3_scale(e2, u * v)));
            double h;
            const int mid = center && t[a] == 0 && t[b] == 0;
            if (mid && !isnan(*center))
                h = *center;
            else if (occ_hidden_at(sp, c, x, &h))
                return -1;
            else if (mid)
                *center = h;
            row += w[b] * h;
        }
        sum += w[a] * u * row;
    }
    /* (1) with du dv = (1/2)(1/2) of the weights' [-1, 1] measure */
    *q = 2 * area * 0.25 * sum;
    return 0;
}

/* The collapsed rule of order k (1 <= k <= RAD_GAUSS_MAX); center as
 * for rule_collapsed (may be NULL). */
int occ_rule_order(occ_space *sp, const pair_ctx *c, int k, const rad_vec3 *p, double area,
                   double *q, double *center)
{
    return rule_collapsed(sp, c, k, p, area, q, center);
}

/* The integral of hidden(x) over triangle p (area `area`) by c's rule. */
int occ_rule(occ_space *sp, const pair_ctx *c, const rad_vec3 *p, double area, double *q)
{
    return c->order >= 2 ? rule_collapsed(sp, c, c->order, p, area, q, NULL)
                         : rule3(sp, c, p, area, q);
}
