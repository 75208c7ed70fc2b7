/* ffgauss.c -- default mode's fast path: Gauss product rules (4 x 4 and
 * 8 x 8 points) on the contour, with an a priori error bound.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * For two polygons apart from each other, every integrand ln(r/s) of the
 * contour sum (formfactor.c) is analytic well beyond the edges, and a
 * Gauss-Legendre product rule converges geometrically.  This file applies
 * the K-point rule (K = 4, then 8 for closer pairs) in each variable to
 * every edge pair and bounds its error before trusting it; pairs whose
 * bound misses the tolerance go on to the closed forms and adaptive
 * quadrature of formfactor.c.
 *
 * The rule.  Gauss nodes come in symmetric pairs of equal weight (A&S
 * 25.4.29), K/2 distinct weights, so the K^2 products w_a w_b take
 * K/2 (K/2 + 1) / 2 values (3 for K = 4, 10 for K = 8): as for the
 * nine-point rule, the K^2 logs of an edge pair group into that many logs
 * of products, taken in batches by rad_log_batch (vecmath.h).  Points are
 * stored per edge as x[K], y[K], z[K], so 4-lane vector operations give
 * the squared distances.
 *
 * The bound.  Write each edge on [-1, 1] (half-length h).  For a point Q
 * of the other polygon, ln r^2 as a function of the complex parameter x
 * vanishes nowhere in the Bernstein ellipse E_rho whose semi-minor axis b
 * is below dist(Q, edge)/h: the filled ellipse lies within b of [-1, 1]
 * (its half-axes are a = sqrt(1 + b^2) and b, and a - 1 <= b).  With
 * D <= dist(A, B) from the centroids and the radii about them (largest
 * centroid-vertex distance),
 *   D = |c_a - c_b| - radius_a - radius_b,   beta = D/h,   b1 = THETA beta,
 * on E_rho1 (rho1 = b1 + sqrt(1 + b1^2)):
 *   |r^2| >= ((1 - THETA) D)^2  and  |r^2| <= (a1 h + R)^2,
 *   R = |c_a - c_b| + radius_a + radius_b,
 * and |arg r^2| < 2 pi (two non-vanishing linear factors on a convex set),
 * so |ln(r/s)| <= M = (max |ln(|r^2|/s^2)| + 2 pi) / 2 (each |ln| bounded
 * from the exponent bits, within ln 2).  Gauss-Legendre
 * with K points (degree 2K - 1, Trefethen's n = K - 1) then errs by at most
 *   E = 64/15 M rho1^(-2(K-1)) / (rho1^2 - 1)
 *     = 64/15 M rho1^(-2K) / (1 - rho1^-2)     (Trefethen 2013, Thm 19.3)
 * per unit interval integral, and the product rule on an edge pair of
 * lengths lp, lq by at most (lp lq / 4) * 2 (E_x + E_y) <= lp lq E (weights
 * positive, summing to 2).  Summed with the factors |e_p . e_q|, the error
 * of S is below P E, P = sum |e_p . e_q| lp lq, using the longest edge of
 * either polygon for h.
 *
 * A second bound, from derivatives on the real edges, is far sharper for
 * pairs many edge lengths apart (it holds no ln r magnitude and no
 * ellipse margin), and the smaller of the two is used.  The K-point rule
 * on an interval of length L errs by
 *   L^(2K+1) (K!)^4 / ((2K+1) ((2K)!)^3) f^(2K)(xi)    (A&S 25.4.30),
 * and along an edge ln r = Re ln(s - z), z complex with |s - z| = r, so
 * |d^n ln r / ds^n| <= (n-1)! / r^n <= (n-1)! / D^n.  The product rule's
 * error is the outer rule's on the inner integral plus the outer sum of
 * the inner rule's errors, so for an edge pair
 *   |E_pq| <= C_K lp lq (lp^(2K) + lq^(2K)) / D^(2K),
 *   C_K = (K!)^4 (2K-1)! / ((2K+1) ((2K)!)^3) = 1/16800, 1/352800,
 *         1/45053236800 for K = 3, 4, 8,
 * and |E_S| <= 2 C_K P (lmax / D)^(2K), lmax the longest edge of either.
 *
 * D, a lower bound on the distance between the polygons, is the largest
 * of the centroid distance less both radii and the caller's own bound
 * (rad_ff_pair: the gap between bounding boxes, and the distance of each
 * polygon's nearest vertex from the other's plane).  Round-off adds 16 eps
 * times the sum of the magnitudes of the terms, as in formfactor.c.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "formfactor.h"
#include "vec.h"
#include "vecmath.h"

#define RAD_PI 3.14159265358979323846
#define THETA 0.9 /* how far towards the singularity the ellipse reaches */
#define G_BATCH 32 /* edge pairs per batch of logs */
#define G_CLASSES 10 /* product classes for K = 8 (3 for K = 4) */

/* Storage order: K = 4 ascending; K = 8 as nodes 0 1 2 3 7 6 5 4, so that
 * position p has weight class p % 4 (0 outermost, 3 innermost) and both
 * 4-lane halves of an edge line up class by class. */
void rad_ff_gauss_soa(const rad_ff_edge *e, int k, double *out)
{
    const double *x = rad_gauss_nodes(k); /* ascending */
    for (int a = 0; a < k; a++) {
        const int node = k == 8 && a >= 4 ? 11 - a : a;
        rad_vec3 v = v3_add(e->p0, v3_scale(e->d, 0.5 * (1 + x[node])));
        out[a] = v.x;
        out[k + a] = v.y;
        out[2 * k + a] = v.z;
    }
}
/* |ln x| <= (|k| + 1) ln 2 for x = 2^k z, z in [1, 2): a bound from the
 * exponent bits alone (x positive normal). */
static inline double abs_ln_bound(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    const double k = (double)((int)(b >> 52) - 1023);
    return (fabs(k) + 1) * 0.69314718055994530942;
}

int rad_ff_gauss_apart(const rad_ff_poly *a, const rad_ff_poly *b, double sep2,
                       double scale2, double dmin, rad_ff_gauss_bounds *g)
{
    const double c = sqrt(sep2);
    /* every point of a polygon is within its radius of its centroid (it is
     * convex, so within the farthest vertex); a relative margin of 1e-12
     * covers the round-off of the radii */
    const double ra = a->radius * (1 + 1e-12), rb = b->radius * (1 + 1e-12);
    const double Dc = c - ra - rb, R = c + ra + rb;
    const double D = Dc > dmin ? Dc : dmin;
    const double h = 0.5 * (a->lmax > b->lmax ? a->lmax : b->lmax);
    if (!(D > 1e-9 * c) || !(h > 0) || !(scale2 > DBL_MIN))
        return 0;
    const double inv_s2 = 1 / scale2;
    const double dlo = D * D * inv_s2, rhi = R * R * inv_s2;
    if (!(dlo > DBL_MIN) || !(rhi < DBL_MAX))
        return 0;
    g->D = D;
    g->R = R;
    g->h = h;
    g->inv_s2 = inv_s2;
    g->pp = 1;
    g->q2 = 4 * h * h / (D * D); /* (lmax / D)^2 */
    g->rho2 = 0;                 /* the ellipse bound: not yet */
    /* round-off: on the real edges |ln(r^2/s^2)| <= Lr (D <= r <= R); the
     * terms sum to at most P Lr / 2 in size (sum of w_a w_b is 4, each
     * coefficient lp lq / 8), and each grouped log carries about 10 eps
     * absolute from its product and its evaluation */
    const double l1 = abs_ln_bound(dlo), l2 = abs_ln_bound(rhi);
    g->roundoff = 16 * DBL_EPSILON * 0.5 * ((l1 > l2 ? l1 : l2) + 1);
    return 1;
}

void rad_ff_gauss_ellipse(rad_ff_gauss_bounds *g)
{
    const double D = g->D, h = g->h, R = g->R;
    const double b1 = THETA * D / h, a1 = sqrt(1 + b1 * b1), rho = b1 + a1;
    const double lo = (1 - THETA) * D * (1 - THETA) * D * g->inv_s2;
    const double hi = (a1 * h + R) * (a1 * h + R) * g->inv_s2;
    g->rho2 = 1; /* no bound (1 - 1/rho2 = 0) unless both ends are normal */
    g->M = 0;
    if (!(lo > DBL_MIN) || !(hi < DBL_MAX))
        return;
    const double llo = abs_ln_bound(lo), lhi = abs_ln_bound(hi);
    g->M = 0.5 * ((llo > lhi ? llo : lhi) + 2 * RAD_PI);
    g->rho2 = rho * rho;
}

/* x^K for K = 3, 4, 8 */
static inline double pow_k(double x, int k)
{
    const double x2 = x * x, x4 = x2 * x2;
    return k == 3 ? x2 * x : k == 4 ? x4 : x4 * x4;
}

double rad_ff_gauss_bound(const rad_ff_gauss_bounds *g, int k)
{
    /* C_K of the derivative bound (see the top of the file) */
    const double ck = k == 3 ? 1 / 16800.0 : k == 4 ? 1 / 352800.0 : 1 / 45053236800.0;
    double e = 2 * ck * pow_k(g->q2, k);
    if (g->rho2 > 1) { /* Thm 19.3 with n = K - 1 */
        const double ellipse = (64.0 / 15.0) * g->M / (pow_k(g->rho2, k) * (1 - 1 / g->rho2));
        e = ellipse < e ? ellipse : e;
    }
    return g->pp * (e + g->roundoff);
}

#if defined(__GNUC__)
typedef double lane4 __attribute__((vector_size(32)));

static inline __attribute__((always_inline)) void
g_flush(const double *arg, const double *coef, int m, const double *w, int nc, double *s)
{
    double lg[G_CLASSES * G_BATCH];
    rad_log_batch(lg, arg, nc * m);
    for (int k = 0; k < m; k++) {
        double t = 0;
        for (int c = 0; c < nc; c++)
            t += w[c] * lg[nc * k + c];
        *s += coef[k] * t;
    }
}

/* squared distances over s^2 from A's stored point i of edge p to 4 of B's
 * points (lanes) */
#define G_R2(ga, stride, i, bx, by, bz)                                                   \
    ({                                                                                   \
        const lane4 dx_ = (ga)[i] - (bx), dy_ = (ga)[(stride) + (i)] - (by),             \
                    dz_ = (ga)[2 * (stride) + (i)] - (bz);                               \
        (dx_ * dx_ + dy_ * dy_ + dz_ * dz_) * inv_s2;                                    \
    })

/* The grouped products of one edge pair.  K = 4 (ascending nodes; 0, 3
 * outer, 1, 2 inner): inner x inner, mixed, outer x outer.  K = 8 (classes
 * c = position % 4): acc[ci] lane cj holds the product over A's class ci
 * and B's class cj; class pairs (i, j) and (j, i) share one weight. */
static inline __attribute__((always_inline)) void
g_products(const double *ga, const lane4 *bx, const lane4 *by, const lane4 *bz, int K,
           double inv_s2, double *out)
{
    if (K == 4) {
        lane4 r[4];
        for (int i = 0; i < 4; i++)
            r[i] = G_R2(ga, 4, i, bx[0], by[0], bz[0]);
        const lane4 m03 = r[0] * r[3], m12 = r[1] * r[2];
        out[0] = m12[1] * m12[2];
        out[1] = (m03[1] * m03[2]) * (m12[0] * m12[3]);
        out[2] = m03[0] * m03[3];
        return;
    }
    lane4 acc[4];
    for (int c = 0; c < 4; c++)
        acc[c] = (G_R2(ga, 8, c, bx[0], by[0], bz[0]) * G_R2(ga, 8, c, bx[1], by[1], bz[1])) *
                 (G_R2(ga, 8, c + 4, bx[0], by[0], bz[0]) *
                  G_R2(ga, 8, c + 4, bx[1], by[1], bz[1]));
    int n = 0;
    for (int i = 0; i < 4; i++)
        for (int j = i; j < 4; j++)
            out[n++] = i == j ? acc[i][i] : acc[i][j] * acc[j][i];
}

/* S by the K x K rule (K = 4 or 8: a constant after inlining) */
static inline __attribute__((always_inline)) double
g_sum(const rad_ff_poly *a, const rad_ff_poly *b, const double *ga, const double *gb,
      const int K, double scale2, double *pp)
{
    const int V = K / 4, nc = K == 4 ? 3 : 10;
    const rad_ff_edge *ea = a->edges, *eb = b->edges;
    const rad_vec3 shift = v3_sub(b->centroid, a->centroid);
    const double inv_s2 = 1.0 / scale2;
    const double *gw = rad_gauss_weights(K);
    double w[G_CLASSES], arg[G_CLASSES * G_BATCH], coef[G_BATCH], s = 0, sum_ll = 0;
    int m = 0;
    if (K == 4) { /* inner x inner, mixed, outer x outer */
        w[0] = gw[1] * gw[1];
        w[1] = gw[0] * gw[1];
        w[2] = gw[0] * gw[0];
    } else { /* class pairs (i <= j) in the order of g_products */
        int n = 0;
        for (int i = 0; i < 4; i++)
            for (int j = i; j < 4; j++)
                w[n++] = gw[i] * gw[j];
    }
    for (int q = 0; q < b->nedges; q++) {
        lane4 bx[2], by[2], bz[2];
        for (int v = 0; v < V; v++)
            for (int l = 0; l < 4; l++) {
                bx[v][l] = gb[3 * K * q + 4 * v + l] + shift.x;
                by[v][l] = gb[3 * K * q + K + 4 * v + l] + shift.y;
                bz[v][l] = gb[3 * K * q + 2 * K + 4 * v + l] + shift.z;
            }
        for (int p = 0; p < a->nedges; p++) {
            const double dot = v3_dot(ea[p].e, eb[q].e);
            if (fabs(dot) < 1e-14)
                continue; /* perpendicular: no contribution */
            g_products(ga + 3 * K * p, bx, by, bz, K, inv_s2, arg + nc * m);
            /* integral of ln(r/s) = (lp lq / 4) sum w w ln(r/s)
             *                      = (lp lq / 8) sum w w ln(r^2/s^2) */
            coef[m++] = dot * 0.125 * ea[p].len * eb[q].len;
            sum_ll += fabs(dot) * ea[p].len * eb[q].len;
            if (m == G_BATCH) {
                g_flush(arg, coef, m, w, nc, &s);
                m = 0;
            }
        }
    }
    if (m > 0)
        g_flush(arg, coef, m, w, nc, &s);
    if (pp)
        *pp = sum_ll;
    return s;
}

#if defined(HAVE_ATTRIBUTE_TARGET_CLONES)
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
double rad_ff_gauss_sum(const rad_ff_poly *a, const rad_ff_poly *b, int k, double scale2,
                        double *pp)
{
    return k == 4 ? g_sum(a, b, a->gauss4, b->gauss4, 4, scale2, pp)
                  : g_sum(a, b, a->gauss8, b->gauss8, 8, scale2, pp);
}
#else
double rad_ff_gauss_sum(const rad_ff_poly *a, const rad_ff_poly *b, int k, double scale2,
                        double *pp)
{
    (void)a, (void)b, (void)k, (void)scale2, (void)pp;
    return NAN; /* without vector extensions the path is not used */
}
#endif
