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
 * results agree to the tolerance; |S_k - S_k-1| is the error estimate
 * (conservative: S_k is far more accurate than S_k-1 once they agree).
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "formfactor.h"
#include "radiosity.h"
#include "vec.h"

#define AREA_ORDER_MAX 10

/* Gauss points of polygon p (n vertices) relative to `origin`, order k:
 * fills pts and w (room for count_points(n, k)); returns the count. */
static int count_points(int n, int k)
{
    return n == 4 ? k * k : (n - 2) * k * k;
}

static int polygon_points(const rad_vec3 *p, int n, rad_vec3 origin, int k, rad_vec3 *pts,
                          double *w)
{
    const double *x = rad_gauss_nodes(k), *gw = rad_gauss_weights(k);
    int m = 0;
    if (n == 4) {
        rad_vec3 q[4];
        for (int c = 0; c < 4; c++)
            q[c] = v3_sub(p[c], origin);
        for (int i = 0; i < k; i++) {
            double u = 0.5 * (1 + x[i]);
            for (int j = 0; j < k; j++) {
                double v = 0.5 * (1 + x[j]);
                /* P(u,v) = (1-u)(1-v) q0 + u(1-v) q1 + u v q2 + (1-u) v q3 */
                rad_vec3 a = v3_lerp(q[0], q[1], u), b = v3_lerp(q[3], q[2], u);
                rad_vec3 pu = v3_add(v3_scale(v3_sub(q[1], q[0]), 1 - v),
                                     v3_scale(v3_sub(q[2], q[3]), v));
                rad_vec3 pv = v3_sub(b, a);
                pts[m] = v3_lerp(a, b, v);
                w[m++] = 0.25 * gw[i] * gw[j] * v3_norm(v3_cross(pu, pv));
            }
        }
        return m;
    }
    for (int t = 1; t + 1 < n; t++) {
        rad_vec3 v0 = v3_sub(p[0], origin), e1 = v3_sub(p[t], p[0]), e2 = v3_sub(p[t + 1], p[t]);
        double twice = v3_norm(v3_cross(e1, e2)); /* 2 A_t */
        for (int i = 0; i < k; i++) {
            double u = 0.5 * (1 + x[i]);
            for (int j = 0; j < k; j++) {
                double v = 0.5 * (1 + x[j]);
                pts[m] = v3_add(v0, v3_add(v3_scale(e1, u), v3_scale(e2, u * v)));
                w[m++] = 0.25 * gw[i] * gw[j] * twice * u;
            }
        }
    }
    return m;
}

/* 2 sum_k sum_l w_k w_l (n_a . d)(-n_b . d) / |d|^4 */
static double area_sum(const rad_vec3 *pa, const double *wa, int ma, rad_vec3 na,
                       const rad_vec3 *pb, const double *wb, int mb, rad_vec3 nb)
{
    double s = 0;
    for (int k = 0; k < ma; k++) {
        double inner = 0;
        for (int l = 0; l < mb; l++) {
            rad_vec3 d = v3_sub(pb[l], pa[k]);
            double r2 = v3_dot(d, d);
            inner += wb[l] * (v3_dot(na, d) * -v3_dot(nb, d)) / (r2 * r2);
        }
        s += wa[k] * inner;
    }
    return 2 * s;
}

int rad_ff_area(const rad_vec3 *a, int na, rad_vec3 norm_a, const rad_vec3 *b, int nb,
                rad_vec3 norm_b, rad_vec3 origin, double rel_tol, double *s_out,
                double *err_out)
{
    enum { SMALL = 2 * AREA_ORDER_MAX * AREA_ORDER_MAX * 3 };
    rad_vec3 pts_small[SMALL];
    double w_small[SMALL];
    const int cap = count_points(na > nb ? na : nb, AREA_ORDER_MAX);
    const int heap = 2 * cap > SMALL;
    rad_vec3 *pts = heap ? malloc(sizeof *pts * 2 * (size_t)cap) : pts_small;
    double *w = heap ? malloc(sizeof *w * 2 * (size_t)cap) : w_small;
    double prev = NAN;
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
        int ma = polygon_points(a, na, origin, k, pts, w);
        int mb = polygon_points(b, nb, origin, k, pts + cap, w + cap);
        double s = area_sum(pts, w, ma, norm_a, pts + cap, w + cap, mb, norm_b);
        if (isfinite(prev) && fabs(s - prev) <= rel_tol * fabs(s)) {
            *s_out = s;
            *err_out = fabs(s - prev);
            ok = 1;
        }
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
