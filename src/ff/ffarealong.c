/* ffarealong.c -- one order of the area rules again in long double.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Where two polygons see each other nearly edge on, the cosines of the
 * area form (ffarea.c) are differences of terms far larger than
 * themselves: n . d, with d nearly in the plane of n, loses the digits
 * that |d| / (n . d) counts, and the points' own rounding, relative to an
 * origin up to R0 away, adds R0 / (n . d) more.  ffarea.c bounds that
 * round-off (its eq. R1); where the bound exceeds what the pair's
 * tolerance leaves for it, the order that passed is summed again here
 * with every point, normal, weight and product in long double (a 64-bit
 * significand on x86, 2^11 times double's precision; where long double is
 * double this gains nothing and the bound says so).  The rule is the
 * same: the Gauss nodes and weights are the double ones, so the two sums
 * differ by round-off alone.
 *
 * The normals: on a twisted polygon each point's, computed here in long
 * double (as in ffarea.c); on a planar one the caller's, which defines
 * the plane the pair is integrated over (the surface's normal, not the
 * element's own vertices', which sit off it by the mesh's rounding), so
 * that both sums integrate the same thing.  Its error bound stays the
 * double one (ffarea.c, R3); a twisted polygon's point normals are
 * bounded by R3 with the long double's epsilon (radi_ff_normal_doubt,
 * scaled).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "ff/formfactor.h"
#include "radiosity/base.h"
#include "radiosity/formfactor.h"
#include "util/util.h"

typedef struct lv3 {
    long double x, y, z;
} lv3;

static lv3 lv_of(rad_vec3 a, rad_vec3 o)
{
    return (lv3){(long double)a.x - o.x, (long double)a.y - o.y, (long double)a.z - o.z};
}
static lv3 lv_sub(lv3 a, lv3 b) { return (lv3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static lv3 lv_add(lv3 a, lv3 b) { return (lv3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static lv3 lv_scale(lv3 a, long double s) { return (lv3){a.x * s, a.y * s, a.z * s}; }
static long double lv_dot(lv3 a, lv3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static lv3 lv_cross(lv3 a, lv3 b)
{
    return (lv3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static lv3 lv_lerp(lv3 a, lv3 b, long double t) { return lv_add(a, lv_scale(lv_sub(b, a), t)); }

/* Gauss points of p (n vertices) relative to origin, order k, cut nu x nv
 * (a quadrilateral), as polygon_points in ffarea.c but in long double;
 * nrm the planar normal, used unless twisted.  Returns the count. */
static int points_long(const rad_vec3 *p, int n, rad_vec3 origin, int k, int nu, int nv,
                       int twisted, lv3 nrm, lv3 *pts, long double *w, lv3 *nv_)
{
    const double *x = rad_gauss_nodes(k), *gw = rad_gauss_weights(k);
    int m = 0;
    if (n == 4) {
        lv3 q[4];
        for (int c = 0; c < 4; c++)
            q[c] = lv_of(p[c], origin);
        for (int iu = 0; iu < nu; iu++)
            for (int iv = 0; iv < nv; iv++)
                for (int i = 0; i < k; i++)
                    for (int j = 0; j < k; j++) {
                        const long double u = (iu + 0.5L * (1 + x[i])) / nu;
                        const long double v = (iv + 0.5L * (1 + x[j])) / nv;
                        const lv3 a = lv_lerp(q[0], q[1], u), b = lv_lerp(q[3], q[2], u);
                        const lv3 pu = lv_add(lv_scale(lv_sub(q[1], q[0]), 1 - v),
                                              lv_scale(lv_sub(q[2], q[3]), v));
                        const lv3 cr = lv_cross(pu, lv_sub(b, a));
                        const long double jac = sqrtl(lv_dot(cr, cr));
                        pts[m] = lv_lerp(a, b, v);
                        nv_[m] = twisted ? lv_scale(cr, 1 / jac) : nrm;
                        w[m++] = 0.25L * gw[i] * gw[j] * jac / (nu * nv);
                    }
        return m;
    }
    const lv3 v0 = lv_of(p[0], origin);
    for (int t = 1; t + 1 < n; t++) {
        const lv3 e1 = lv_of(p[t], p[0]), e2 = lv_of(p[t + 1], p[t]);
        const lv3 cr = lv_cross(e1, e2);
        const long double twice = sqrtl(lv_dot(cr, cr));
        const lv3 nt = twisted && twice > 0 ? lv_scale(cr, 1 / twice) : nrm;
        for (int i = 0; i < k; i++)
            for (int j = 0; j < k; j++) {
                const long double u = 0.5L * (1 + x[i]), v = 0.5L * (1 + x[j]);
                pts[m] = lv_add(v0, lv_add(lv_scale(e1, u), lv_scale(e2, u * v)));
                nv_[m] = nt;
                w[m++] = 0.25L * gw[i] * gw[j] * twice * u;
            }
    }
    return m;
}

int radi_ff_area_long(const rad_ff_area_part *a, const rad_ff_area_part *b, rad_vec3 origin,
                     int k, double *s, double nu[2])
{
    const rad_ff_area_part *side[2] = {a, b};
    lv3 nrm[2];
    int cap[2];
    for (int c = 0; c < 2; c++) {
        const rad_ff_area_part *q = side[c];
        nrm[c] = lv_of(q->nrm, v3(0, 0, 0));
        nu[c] = q->twisted ? radi_ff_normal_doubt(q->p, q->n) * (LDBL_EPSILON / DBL_EPSILON)
                            : q->doubt;
        cap[c] = q->n == 4 ? k * k * q->nu * q->nv : (q->n - 2) * k * k;
    }
    const size_t tot = (size_t)cap[0] + (size_t)cap[1];
    lv3 *pts = malloc(sizeof *pts * 2 * tot);
    long double *w = malloc(sizeof *w * tot);
    if (!pts || !w) {
        free(pts);
        free(w);
        return -1;
    }
    lv3 *nv_ = pts + tot;
    const int ma = points_long(a->p, a->n, origin, k, a->nu, a->nv, a->twisted, nrm[0], pts, w,
                               nv_);
    const int mb = points_long(b->p, b->n, origin, k, b->nu, b->nv, b->twisted, nrm[1],
                               pts + cap[0], w + cap[0], nv_ + cap[0]);
    long double sum = 0;
    for (int i = 0; i < ma; i++) {
        long double inner = 0;
        for (int j = cap[0]; j < cap[0] + mb; j++) {
            const lv3 d = lv_sub(pts[j], pts[i]);
            const long double r2 = lv_dot(d, d);
            inner += w[j] * (lv_dot(nv_[i], d) * -lv_dot(nv_[j], d)) / (r2 * r2);
        }
        sum += w[i] * inner;
    }
    free(pts);
    free(w);
    *s = (double)(2 * sum);
    return 0;
}
