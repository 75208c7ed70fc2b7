/* ffgauss.c -- Gauss product rules on the contour, batched for SIMD: the
 * nine-point rule (classic mode) and the 4 x 4 and 8 x 8 rules under an a
 * priori error bound (the fast path of the default and reference modes).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The contour sum (formfactor.c) is S = sum_pq (e_p . e_q) I_pq with
 * I_pq the integral of ln(r/s) over edges p of A and q of B.  The K-point
 * Gauss-Legendre rule in each variable (A&S 25.4.29, nodes x_a on [-1, 1])
 * puts the points P_a = m_p + x_a d_p / 2 and Q_b = m_q + x_b d_q / 2 on
 * the edges (m the midpoints, d the edge vectors), and
 *   I_pq ~ (lp lq / 8) sum_ab w_a w_b ln(r_ab^2 / s^2).
 * The nodes come in symmetric pairs of equal weight, so the K^2 products
 * w_a w_b take a few values (3 for K = 3 and 4, 10 for K = 8) and the logs
 * group into that many logs of products of r^2 (Goral et al.'s rule has
 * nine points and three such groups).
 *
 * Layout.  The edge pairs of a polygon pair that are not perpendicular
 * (perpendicular ones contribute nothing) are laid out side by side, one
 * per SIMD lane (rad_v4d, vecmath.h), up to BATCH at a time; each lane then
 * runs the whole rule of its edge pair, logs included (rad_log4), with no
 * shuffling between lanes.  A batch is padded to a multiple of 4 with
 * copies of its first pair, weighted 0.
 *
 * Two ways to the squared distances, w = m_p - m_q (B's midpoint moved
 * into A's frame):
 *   direct     r_ab = (w + x_a d_p / 2) - x_b d_q / 2, then r . r: each
 *              r^2 to a few ulps relative to r^2 even when the points
 *              nearly touch.  The classic mode uses it: the rule's values
 *              there carry no error bound, so no extra round-off is added.
 *   quadratic  r_ab^2 = A(x_a) + B(x_b) + C x_a x_b with
 *                A(x) = |w|^2 + x (w . d_p) + x^2 lp^2 / 4,
 *                B(y) = -y (w . d_q) + y^2 lq^2 / 4,   C = -(d_p . d_q) / 2:
 *              two operations per point instead of eight, but the terms
 *              may exceed r^2: the relative error of r^2 is below
 *              8 eps kappa, kappa = ((R + lmax) / D)^2 (every term is at most
 *              (|w| + lp/2 + lq/2)^2 <= (R + lmax)^2, and r >= D, R and D
 *              bounds on the largest and smallest distance between the
 *              polygons, lmax their longest edge).  The logs then err by as
 *              much, which adds 8 eps kappa P to the bound below (sum over
 *              the terms of |coefficient| times w_a w_b is P / 2); kappa is
 *              small wherever the truncation bound passes.
 *
 * The bound (default and reference modes).  Write each edge on [-1, 1]
 * (half-length h).  For a point Q of the other polygon, ln r^2 as a
 * function of the complex parameter x vanishes nowhere in the Bernstein
 * ellipse E_rho whose semi-minor axis b is below dist(Q, edge)/h: the
 * filled ellipse lies within b of [-1, 1] (its half-axes are
 * a = sqrt(1 + b^2) and b, and a - 1 <= b).  With D <= dist(A, B) and
 *   beta = D/h,   b1 = THETA beta,   R = |c_a - c_b| + radius_a + radius_b,
 * on E_rho1 (rho1 = b1 + sqrt(1 + b1^2)):
 *   |r^2| >= ((1 - THETA) D)^2  and  |r^2| <= (a1 h + R)^2,
 * and |arg r^2| < 2 pi (two non-vanishing linear factors on a convex set),
 * so |ln(r/s)| <= M = (max |ln(|r^2|/s^2)| + 2 pi) / 2 (each |ln| bounded
 * from the exponent bits, within ln 2).  Gauss-Legendre with K points
 * (degree 2K - 1, Trefethen's n = K - 1) then errs by at most
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
 *         1/133189056, 1/45053236800 for K = 3, 4, 6, 8,
 * and |E_S| <= 2 C_K P (lmax / D)^(2K), lmax the longest edge of either.
 *
 * D, a lower bound on the distance between the polygons, is the largest
 * of the centroid distance less both radii and the caller's own bound
 * (radi_ff_pair: the gap between bounding boxes, and the distance of each
 * polygon's nearest vertex from the other's plane).  Round-off adds 16 eps
 * times the sum of the magnitudes of the terms, as in formfactor.c, and
 * the quadratic form's share above.
 *
 * Edge pairs within 1e-14 of perpendicular are left out of the rule
 * (exactly perpendicular ones contribute nothing).  What one would add is
 * (e_p . e_q) times the integral of ln(r/s) over the pair, at most
 * |e_p . e_q| lp lq L / 2 with L >= |ln(r^2/s^2)| on the real edges
 * (D <= r <= R, the L of the round-off term).  The dots themselves err by
 * up to 3 eps a, a = sum_i |e_p,i e_q,i| (Higham 2002, eq. 3.5; 4 eps
 * here, a margin for directions a few ulps off unit length): a few eps of
 * the dot wherever a ~ |e_p . e_q|, which the round-off term counts, but
 * not where the products cancel, as they do on nearly perpendicular
 * pairs.  So
 *   X = sum over the pairs left out of (|e_p . e_q| + 4 eps a) lp lq
 *       + sum over the others of 4 eps (a - |e_p . e_q|) lp lq
 * would do, and X L / 2 is added to the bound.  Computed per edge pair,
 * its a and the test that a >= |e_p . e_q| cost 12% of an unobstructed
 * fill; a <= |e_p| |e_q| <= 1 + 1e-12 (unit directions a few ulps off)
 * bounds it by
 *   X <= sum over the pairs left out of |e_p . e_q| lp lq
 *        + 4 eps (1 + 1e-12) P_a P_b,
 * P the perimeters, which costs a product per pair of polygons and a
 * term per edge pair left out (rare).  Only pairs more than about 1e5 of
 * their sizes apart are kept off this path by it (there L ~ size / c);
 * the general path then takes them.
 *
 * Which rule (radi_ff_gauss_tiers).  The 3 x 3 and 4 x 4 rules cost about
 * what the classic nine-point rule does (three logs per edge pair, the
 * logs and distances being most of the work), the 6 x 6 rule about twice
 * and the 8 x 8 rule three times as much.  The bounds are known before any
 * rule runs, except for S itself, so a guess at S (the polygons as two
 * points: S ~ 2 A_a A_b cos_a cos_b / c^2) picks the cheapest rule likely
 * to pass; whatever the guess, a result is accepted only when its bound is
 * within `rel` of the result itself, and a pair that no rule can pass goes
 * to formfactor.c's general path.  The common path takes D from the
 * caller's box gap and plane distances and needs no division or square
 * root before a result passes (fast_bounds); the general one adds the
 * centroid distance less the radii and the ellipse bound (tiers_general).
 * Default mode takes the log series to w^6 (rad_log4_short, 1.2e-14
 * absolute, LOG_SHORT_ERR in the bound), reference the full one.
 *
 * What it buys on the 1984 cube (7 x 7 per wall): of the pairs not on
 * one plane, 30% pass with 3 x 3 points, 60% with 4 x 4 and 9% with 6 x 6
 * or 8 x 8 (the 0.6% that touch take the closed forms), and the fill
 * costs about 1.07 times classic's; on 20 x 20 per wall 90% pass with
 * 3 x 3 points and the cost is classic's (bench/ff_rate).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "ff/formfactor.h"
#include "ff/gausstab.h"
#include "util/util.h"

#define THETA 0.9  /* how far towards the singularity the ellipse reaches */
#define BATCH 64   /* edge pairs per batch (a multiple of 4) */
/* The quadratic-form rules take rad_log4_short, which errs by at most
 * 1.2e-14 absolute per log: over the grouped logs (sum of the class
 * weights at most 4, coefficients lp lq / 8) at most 6e-15 P in S, taken
 * here with a margin, per unit P. */
#define LOG_SHORT_ERR 8e-15

/* The rules here are K = 3, 4, 6 and 8 points of the one Gauss-Legendre
 * table (gausstab.h), which the unrolled rules below fold as constants. */
const double *radi_ff_gauss_table(int k, int weights)
{
    if (k != 3 && k != 4 && k != 6 && k != 8)
        return NULL;
    return weights ? gl_weights(k) : gl_nodes(k);
}

/* ---- the bounds ---------------------------------------------------------- */

/* |ln x| <= (|k| + 1) ln 2 for x = 2^k z, z in [1, 2): a bound from the
 * exponent bits alone (x positive normal). */
static inline double abs_ln_bound(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    const double k = (double)((int)(b >> 52) - 1023);
    return (fabs(k) + 1) * 0.69314718055994530942;
}

static inline __attribute__((always_inline)) int
bounds_apart(const rad_ff_poly *a, const rad_ff_poly *b, double sep2, double scale2,
             double inv_s2, double dmin, rad_ff_gauss_bounds *g)
{
    const double c = sqrt(sep2);
    /* every point of a polygon is within its radius of its centroid (it is
     * convex, so within the farthest vertex); a relative margin of 1e-12
     * covers the round-off of the radii */
    const double ra = a->radius * (1 + 1e-12), rb = b->radius * (1 + 1e-12);
    const double Dc = c - ra - rb, R = c + ra + rb;
    const double D = Dc > dmin ? Dc : dmin;
    const double lmax = a->lmax > b->lmax ? a->lmax : b->lmax;
    const double dlo = D * D * inv_s2, rhi = R * R * inv_s2;
    if (!(D > 1e-9 * c) || !(lmax > 0) || !(dlo > DBL_MIN) || !(rhi < DBL_MAX))
        return 0;
    const double inv_d2 = 1 / (D * D);
    g->D = D;
    g->R = R;
    g->h = 0.5 * lmax;
    g->inv_s2 = inv_s2;
    g->pp = 1;
    g->q2 = lmax * lmax * inv_d2; /* (lmax / D)^2 */
    g->rho2 = 0;                  /* the ellipse bound: not yet */
    /* round-off: on the real edges |ln(r^2/s^2)| <= Lr (D <= r <= R); the
     * terms sum to at most P Lr / 2 in size (sum of w_a w_b is 4, each
     * coefficient lp lq / 8), and each grouped log carries about 10 eps
     * absolute from its product and its evaluation; the quadratic form's
     * r^2 adds 8 eps kappa (see the top of the file) */
    const double l1 = abs_ln_bound(dlo), l2 = abs_ln_bound(rhi);
    /* and, sharper for pairs far apart, |ln x| <= max(x, 1/x) - 1 */
    const double t1 = scale2 * inv_d2 - 1, t2 = rhi - 1;
    const double lb = l1 > l2 ? l1 : l2, lt = t1 > t2 ? t1 : t2;
    const double kappa = (R + lmax) * (R + lmax) * inv_d2;
    g->lr = lt < lb ? lt : lb;
    g->roundoff = DBL_EPSILON * (8 * (g->lr + 1) + 8 * kappa);
    g->px = 0; /* the caller's */
    return 1;
}

int radi_ff_gauss_apart(const rad_ff_poly *a, const rad_ff_poly *b, double sep2,
                       double scale2, double dmin, rad_ff_gauss_bounds *g)
{
    return scale2 > DBL_MIN && bounds_apart(a, b, sep2, scale2, 1 / scale2, dmin, g);
}

void radi_ff_gauss_ellipse(rad_ff_gauss_bounds *g)
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

/* x^K for K = 3, 4, 6, 8 */
static inline double pow_k(double x, int k)
{
    const double x2 = x * x, x4 = x2 * x2;
    return k == 3 ? x2 * x : k == 4 ? x4 : k == 6 ? x4 * x2 : x4 * x4;
}

/* C_K of the derivative bound (see the top of the file), K = 3, 4, 6, 8 */
#define C3 (1 / 16800.0)
#define C4 (1 / 352800.0)
#define C6 (1 / 133189056.0)
#define C8 (1 / 45053236800.0)

static inline __attribute__((always_inline)) double bound_k(const rad_ff_gauss_bounds *g,
                                                            int k)
{
    const double ck = k == 3 ? C3 : k == 4 ? C4 : k == 6 ? C6 : C8;
    double e = 2 * ck * pow_k(g->q2, k);
    if (g->rho2 > 1) { /* Thm 19.3 with n = K - 1 */
        const double ellipse = (64.0 / 15.0) * g->M / (pow_k(g->rho2, k) * (1 - 1 / g->rho2));
        e = ellipse < e ? ellipse : e;
    }
    return g->pp * (e + g->roundoff) + 0.5 * g->px * g->lr;
}

double radi_ff_gauss_bound(const rad_ff_gauss_bounds *g, int k)
{
    return bound_k(g, k);
}

#if defined(__GNUC__)

/* the helpers below are inlined: no vector crosses a call (see vecmath.h) */
#pragma GCC diagnostic ignored "-Wpsabi"

typedef rad_v4d v4;

static inline v4 load4(const double *p)
{
    v4 r;
    memcpy(&r, p, sizeof r);
    return r;
}

static inline double hsum4(v4 x)
{
    return (x[0] + x[1]) + (x[2] + x[3]);
}

/* ---- edge pairs side by side --------------------------------------------- */

/* A batch: per lane one edge pair, w = m_p - m_q (B's midpoint in A's
 * frame), the edge vectors d_p, d_q, and cf = (e_p . e_q) lp lq / 8. */
typedef struct pair_batch {
    double wx[BATCH], wy[BATCH], wz[BATCH];
    double px[BATCH], py[BATCH], pz[BATCH];
    double qx[BATCH], qy[BATCH], qz[BATCH];
    double cf[BATCH];
} pair_batch;

/* Colinear edge pairs (classic mode; they can exist only when `touch`)
 * take the closed form instead of a lane: its sum. */
typedef struct colinear_sum {
    double scale2, ln_s, s;
} colinear_sum;

static int colinear_closed(const rad_ff_edge *ep, const rad_ff_edge *eq, rad_vec3 shift,
                           double dot, colinear_sum *col)
{
    rad_ff_edge qe = *eq;
    qe.p0 = v3_add(qe.p0, shift);
    qe.mid = v3_add(qe.mid, shift);
    const rad_vec3 cr = v3_cross(ep->e, eq->e);
    if (!(v3_dot(cr, cr) < 1e-26 && radi_ff_colinear(ep, &qe)))
        return 0;
    if (isnan(col->ln_s))
        col->ln_s = 0.5 * log(col->scale2);
    col->s += dot * (radi_ff_ln_parallel_edges(ep, &qe) - ep->len * qe.len * col->ln_s);
    return 1;
}

/* The edge pairs from position *pos (q * na + p) on that are not
 * perpendicular, up to a full batch, padded to a multiple of 4 with copies
 * of the first, weighted 0; advances *pos, adds sum |cf| to *acf and
 * returns the count.  col (or NULL) takes the colinear pairs; skip (or
 * NULL) takes X's terms of the pairs left out (see the top of the file). */
static inline __attribute__((always_inline)) int
fill_pairs(const rad_ff_poly *a, const rad_ff_poly *b, rad_vec3 shift, pair_batch *bt, int *pos,
           double *acf, colinear_sum *col, double *skip)
{
    const int na = a->nedges, nb = b->nedges;
    int m = 0, q = *pos / na, p = *pos - q * na;
    /* a local sum, which stays in a register: through the pointer, every
     * pair stored it (the same additions in the same order) */
    double sum = 0, skipped = skip ? *skip : 0;
    /* b's edge in the outer loop, a's in the inner one, in the order
     * q * na + p that *pos counts (one loop that wrapped p at na, and
     * tested the batch at every pair, cost 8% more of the cube's
     * unobstructed fill in default mode) */
    for (; q < nb; q++, p = 0) {
        const rad_ff_edge *const eq = &b->edges[q];
        for (; p < na; p++) {
            const rad_ff_edge *const ep = &a->edges[p];
            const double dot = v3_dot(ep->e, eq->e);
            /* perpendicular pairs contribute nothing; the nearly
             * perpendicular ones left out are bounded (see the top of the
             * file) */
            const int kept = fabs(dot) >= 1e-14;
            if (skip && !kept)
                skipped += fabs(dot) * ep->len * eq->len;
            if (!kept || (col && fabs(dot) > 1 - 1e-12 && colinear_closed(ep, eq, shift, dot, col)))
                continue;
            const rad_vec3 w = v3_sub(ep->mid, v3_add(eq->mid, shift));
            bt->wx[m] = w.x;
            bt->wy[m] = w.y;
            bt->wz[m] = w.z;
            bt->px[m] = ep->d.x;
            bt->py[m] = ep->d.y;
            bt->pz[m] = ep->d.z;
            bt->qx[m] = eq->d.x;
            bt->qy[m] = eq->d.y;
            bt->qz[m] = eq->d.z;
            bt->cf[m] = 0.125 * dot * ep->len * eq->len;
            sum += fabs(bt->cf[m]);
            if (++m == BATCH) { /* full: the next call goes on after this pair */
                if (++p == na) {
                    p = 0;
                    q++;
                }
                goto full;
            }
        }
    }
full:
    *pos = q * na + p;
    *acf += sum;
    if (skip)
        *skip = skipped;
    const int m4 = (m + 3) & ~3;
    for (int k = m; k < m4; k++) {
        double *const arrays[9] = {bt->wx, bt->wy, bt->wz, bt->px, bt->py,
                                   bt->pz, bt->qx, bt->qy, bt->qz};
        for (int i = 0; i < 9; i++)
            arrays[i][k] = arrays[i][0];
        bt->cf[k] = 0;
    }
    return m4;
}

/* ---- the nine-point rule, direct form (classic mode) --------------------- */

/* squared distance over s^2 between U = w + x_a d_p/2 and V = x_b d_q/2 */
#define R2(ux, uy, uz, vx, vy, vz)                                                        \
    ({                                                                                   \
        const v4 dx_ = (ux) - (vx), dy_ = (uy) - (vy), dz_ = (uz) - (vz);                \
        (dx_ * dx_ + dy_ * dy_ + dz_ * dz_) * inv_s2;                                    \
    })
#define R2W(ux, uy, uz) (((ux) * (ux) + (uy) * (uy) + (uz) * (uz)) * inv_s2)

/* S of m (a multiple of 4) edge pairs: weights 5/9, 8/9, 5/9, so w_a w_b
 * is 25/81 at the corners of the 3 x 3 grid, 40/81 at its edge midpoints
 * and 64/81 at its centre */
static inline __attribute__((always_inline)) double nine_eval(const pair_batch *bt, int m,
                                                              double inv_s2)
{
    const double hu = 0.5 * gl_nodes(3)[2]; /* sqrt(3/5) / 2 */
    v4 acc = {0, 0, 0, 0};
    for (int k = 0; k < m; k += 4) {
        const v4 wx = load4(bt->wx + k), wy = load4(bt->wy + k), wz = load4(bt->wz + k);
        const v4 px = hu * load4(bt->px + k), py = hu * load4(bt->py + k),
                 pz = hu * load4(bt->pz + k);
        const v4 qx = hu * load4(bt->qx + k), qy = hu * load4(bt->qy + k),
                 qz = hu * load4(bt->qz + k);
        const v4 mx = wx - px, my = wy - py, mz = wz - pz; /* x_a = -u */
        const v4 lx = wx + px, ly = wy + py, lz = wz + pz; /* x_a = +u */
        const v4 corner = (R2(mx, my, mz, -qx, -qy, -qz) * R2(mx, my, mz, qx, qy, qz)) *
                          (R2(lx, ly, lz, -qx, -qy, -qz) * R2(lx, ly, lz, qx, qy, qz));
        const v4 edge = (R2W(mx, my, mz) * R2W(lx, ly, lz)) *
                        (R2(wx, wy, wz, -qx, -qy, -qz) * R2(wx, wy, wz, qx, qy, qz));
        const v4 centre = R2W(wx, wy, wz);
        acc += load4(bt->cf + k) *
               ((25.0 / 81) * rad_log4(corner) + (40.0 / 81) * rad_log4(edge) +
                (64.0 / 81) * rad_log4(centre));
    }
    return hsum4(acc);
}

RAD_KERNEL_CLONES
double radi_ff_nine_point(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, int touch)
{
    const rad_vec3 shift = v3_sub(b->centroid, a->centroid);
    const double inv_s2 = 1.0 / scale2;
    const int end = a->nedges * b->nedges;
    colinear_sum col = {scale2, NAN, 0};
    pair_batch bt;
    double s = 0, acf = 0;
    for (int pos = 0; pos < end;) {
        const int m = fill_pairs(a, b, shift, &bt, &pos, &acf, touch ? &col : NULL, NULL);
        if (m > 0)
            s += nine_eval(&bt, m, inv_s2);
    }
    return s + col.s;
}

/* ---- the 4 x 4 and 8 x 8 rules, quadratic form ---------------------------- */

/* S of m (a multiple of 4) edge pairs by the K x K rule, K = 3, 4, 6 or 8
 * (a constant after inlining), r^2 / s^2 = A(x) + B(y) + C x y with
 * A(x) = c0 + al x + ga x^2, B(y) = be y + de y^2 (see the top of the
 * file).  Node a has class min(a, K-1-a) (0 outermost; the middle node of
 * odd K is a class of its own); the products of r^2 are grouped by the
 * class pair {class a, class b}, which fixes w_a w_b. */
static inline __attribute__((always_inline)) double quad_eval(const pair_batch *bt, int m,
                                                              double inv_s2, const int K,
                                                              const int short_log)
{
    const double *xs = gl_nodes(K), *ws = gl_weights(K);
    const int H = (K + 1) / 2, NC = H * (H + 1) / 2;
    v4 acc = {0, 0, 0, 0};
    rad_v4i fine = {-1, -1, -1, -1}; /* lanes whose products are all normal */
    for (int k = 0; k < m; k += 4) {
        const v4 wx = load4(bt->wx + k), wy = load4(bt->wy + k), wz = load4(bt->wz + k);
        const v4 px = load4(bt->px + k), py = load4(bt->py + k), pz = load4(bt->pz + k);
        const v4 qx = load4(bt->qx + k), qy = load4(bt->qy + k), qz = load4(bt->qz + k);
        const v4 c0 = (wx * wx + wy * wy + wz * wz) * inv_s2;
        const v4 al = (wx * px + wy * py + wz * pz) * inv_s2;
        const v4 ga = (px * px + py * py + pz * pz) * (0.25 * inv_s2);
        const v4 be = -(wx * qx + wy * qy + wz * qz) * inv_s2;
        const v4 de = (qx * qx + qy * qy + qz * qz) * (0.25 * inv_s2);
        const v4 ep = -(px * qx + py * qy + pz * qz) * (0.5 * inv_s2);
        v4 A[8], B[8], P[10];
#pragma GCC unroll 8
        for (int i = 0; i < K; i++) {
            const double x = xs[i];
            A[i] = x == 0 ? c0 : c0 + (al * x + ga * (x * x));
            B[i] = x == 0 ? (v4){0, 0, 0, 0} : be * x + de * (x * x);
        }
#pragma GCC unroll 10
        for (int c = 0; c < NC; c++)
            P[c] = (v4){1, 1, 1, 1};
#pragma GCC unroll 8
        for (int ia = 0; ia < K; ia++) {
            const v4 ex = ep * xs[ia];
            const int ca = ia < H ? ia : K - 1 - ia;
#pragma GCC unroll 8
            for (int ib = 0; ib < K; ib++) {
                const int cb = ib < H ? ib : K - 1 - ib;
                const int lo = ca < cb ? ca : cb, hi = ca < cb ? cb : ca;
                /* index of the class pair (lo, hi), lo <= hi, in row order */
                const int c = lo * H - lo * (lo - 1) / 2 + (hi - lo);
                const v4 ab = A[ia] + B[ib];
                P[c] *= xs[ia] == 0 || xs[ib] == 0 ? ab : ab + ex * xs[ib];
            }
        }
        v4 t = {0, 0, 0, 0};
        int c = 0;
#pragma GCC unroll 4
        for (int i = 0; i < H; i++)
#pragma GCC unroll 4
            for (int j = i; j < H; j++, c++) {
                fine &= (P[c] >= DBL_MIN) & (P[c] <= DBL_MAX);
                t += (ws[i] * ws[j]) * (short_log ? rad_log4_short(P[c]) : rad_log4_core(P[c]));
            }
        acc += load4(bt->cf + k) * t;
    }
    /* a product out of the normal range (the bounds keep r^2 / s^2 within
     * [D^2/s^2, 3], so only for a pair barely apart): no result */
    if ((fine[0] & fine[1] & fine[2] & fine[3]) != -1)
        return NAN;
    return hsum4(acc);
}

/* K = 3, 4, 6, 8; the short log (default mode's budget) or the full one:
 * each combination its own unrolled code */
#define QUAD_EVAL_SWITCH(sl)                                                              \
    switch (k) {                                                                         \
    case 3:                                                                              \
        return quad_eval(bt, m, inv_s2, 3, sl);                                          \
    case 4:                                                                              \
        return quad_eval(bt, m, inv_s2, 4, sl);                                          \
    case 6:                                                                              \
        return quad_eval(bt, m, inv_s2, 6, sl);                                          \
    default:                                                                             \
        return quad_eval(bt, m, inv_s2, 8, sl);                                          \
    }
static inline __attribute__((always_inline)) double quad_eval_k(const pair_batch *bt, int m,
                                                                double inv_s2, int k,
                                                                int short_log)
{
    if (short_log)
        QUAD_EVAL_SWITCH(1)
    QUAD_EVAL_SWITCH(0)
}

/* quad_eval_k for the general paths, in its own AVX2 clone */
RAD_KERNEL_CLONES
static double quad_eval_any(const pair_batch *bt, int m, double inv_s2, int k)
{
    return quad_eval_k(bt, m, inv_s2, k, 0);
}

double radi_ff_gauss_sum(const rad_ff_poly *a, const rad_ff_poly *b, int k, double scale2,
                        double *pp)
{
    const rad_vec3 shift = v3_sub(b->centroid, a->centroid);
    const int end = a->nedges * b->nedges;
    pair_batch bt;
    double s = 0, acf = 0;
    for (int pos = 0; pos < end;) {
        const int m = fill_pairs(a, b, shift, &bt, &pos, &acf, NULL, NULL);
        if (m > 0)
            s += quad_eval_any(&bt, m, 1.0 / scale2, k);
    }
    if (pp)
        *pp = 8 * acf; /* sum |e_p . e_q| lp lq */
    return s;
}

/* s accepted if positive and its bound within rel of it */
static inline int accept(double s, double bound, double rel)
{
    return s > 0 && bound <= rel * s;
}

/* The tiers' rules, in order */
static const int tier_k[4] = {3, 4, 6, 8};

/* The derivative bound without a division or a square root, for the fast
 * path: with d = D^2/s^2, mu = lmax^2/s^2, rr = R^2/s^2 and P = g.pp, the
 * bound on the K-point rule's error in S times d^K is
 *   T_K = P (2 C_K mu^K + 8 eps d^(K-1) z) + X z d^(K-1) / 2,
 *   z = max(1, rr d) + 2 rr + 2 mu
 * (the round-off term: (L + 1) d <= max(s^2/D^2, R^2/s^2) d = max(1, rr d)
 * by |ln x| <= max(x, 1/x) - 1, and kappa d <= (R + lmax)^2 / s^2 <=
 * 2 rr + 2 mu; X as at the top of the file, L d <= z), so a result s_K is
 * accepted when T_K <= rel s_K d^K.
 * fast_bounds fills T_K and d^K for the four tiers. */
static inline void fast_bounds(double d, double mu, double z, double pp, double px,
                               double log_err, double *t, double *dk)
{
    const double d2 = d * d, d3 = d2 * d, d4 = d2 * d2, d5 = d4 * d, d6 = d4 * d2, d7 = d6 * d;
    const double m2 = mu * mu, m3 = m2 * mu, m4 = m2 * m2, m6 = m4 * m2, m8 = m4 * m4;
    /* the round-off, and px L / 2 with L d <= z (as above) */
    const double r = pp * (8 * DBL_EPSILON * z + log_err * d) + 0.5 * px * z;
    t[0] = pp * 2 * C3 * m3 + r * d2;
    t[1] = pp * 2 * C4 * m4 + r * d3;
    t[2] = pp * 2 * C6 * m6 + r * d5;
    t[3] = pp * 2 * C8 * m8 + r * d7;
    dk[0] = d3;
    dk[1] = d4;
    dk[2] = d6;
    dk[3] = d7 * d;
}

/* sum |e_p . e_q| lp lq over the edge pairs that are not perpendicular;
 * *skip takes X's terms of the pairs left out (see the top of the file) */
static double sum_ll(const rad_ff_poly *a, const rad_ff_poly *b, double *skip)
{
    double pp = 0;
    for (int q = 0; q < b->nedges; q++)
        for (int p = 0; p < a->nedges; p++) {
            const rad_ff_edge *ep = &a->edges[p], *eq = &b->edges[q];
            const double dot = v3_dot(ep->e, eq->e);
            const int kept = fabs(dot) >= 1e-14;
            const double t = fabs(dot) * ep->len * eq->len;
            if (kept)
                pp += t;
            else
                *skip += t;
        }
    return pp;
}

/* A guess at S, only to choose the rule: both polygons as points,
 * S ~ 2 A_a A_b cos_a cos_b / c^2 = 2 G / c^4; returns G. */
static inline double guess_g(const rad_ff_poly *a, const rad_ff_poly *b, rad_vec3 sep)
{
    return a->area * b->area * v3_dot(a->normal, sep) * -v3_dot(b->normal, sep);
}

/* The K-point rule's S: from the batch, or (large polygons) afresh */
static inline double tier_sum(const rad_ff_poly *a, const rad_ff_poly *b, const pair_batch *bt,
                              int m, double scale2, double inv_s2, int k)
{
    return bt ? quad_eval_any(bt, m, inv_s2, k) : radi_ff_gauss_sum(a, b, k, scale2, NULL);
}

/* The general tiers: the bounds of radi_ff_gauss_apart (the centroid
 * distance less the radii too, and the ellipse bound), from tier t on. */
static int tiers_general(const rad_ff_poly *a, const rad_ff_poly *b, const pair_batch *bt, int m,
                         double pp, double px, double scale2, double dmin, double rel, double *s,
                         double *e)
{
    const rad_vec3 sep = v3_sub(b->centroid, a->centroid);
    const double sep2 = v3_dot(sep, sep), inv_s2 = 1 / scale2;
    rad_ff_gauss_bounds g;
    if (!bounds_apart(a, b, sep2, scale2, inv_s2, dmin, &g))
        return 0;
    g.pp = pp;
    g.px = px;
    /* The first rule whose bound is within rel / 2 of the guess at S is
     * tried (or the 8 x 8 rule if its bound is within 4 rel of it). */
    const double sep4 = sep2 * sep2, G = guess_g(a, b, sep);
    int t = 0;
    while (t < 3 && !(bound_k(&g, tier_k[t]) * sep4 <= rel * G))
        t++;
    double est = 8 * G / sep4; /* 4 times the guess */
    for (; t < 4; t++) {
        const int K = tier_k[t];
        double bk = bound_k(&g, K);
        if (!(bk <= rel * est) && g.rho2 == 0) { /* the ellipse bound: close pairs */
            radi_ff_gauss_ellipse(&g);
            bk = bound_k(&g, K);
        }
        if (!(bk <= rel * est))
            return 0; /* cannot pass */
        const double sk = tier_sum(a, b, bt, m, scale2, inv_s2, K);
        if (!accept(sk, bk, rel) && g.rho2 == 0) {
            radi_ff_gauss_ellipse(&g);
            bk = bound_k(&g, K);
        }
        if (accept(sk, bk, rel)) {
            *s = sk;
            *e = bk;
            return 1;
        }
        est = sk - bk; /* S is at least this */
    }
    return 0;
}

/* The tiers; short_log (a constant after inlining) chooses the log: the
 * short one where its error (LOG_SHORT_ERR) is far below the tolerance
 * (default mode), the full one otherwise. */
static inline __attribute__((always_inline)) int
tiers(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, double gap2, double dplane,
      double tol, double rel, double *s, double *e, const int short_log)
{
    if (!(scale2 > DBL_MIN && scale2 < DBL_MAX))
        return 0;
    const rad_vec3 sep = v3_sub(b->centroid, a->centroid);
    const double sep2 = v3_dot(sep, sep), inv_s2 = 1 / scale2;
    pair_batch bt;
    int m = 0;
    double pp, px = 0;
    const int one_batch = a->nedges * b->nedges <= BATCH;
    if (one_batch) {
        double acf = 0;
        int pos = 0;
        m = fill_pairs(a, b, sep, &bt, &pos, &acf, NULL, &px);
        pp = 8 * acf; /* sum |e_p . e_q| lp lq */
    } else {
        pp = sum_ll(a, b, &px);
    }
    if (!(pp > 0))
        return 0; /* every edge pair perpendicular: the general path */
    px += 4 * DBL_EPSILON * (1 + 1e-12) * a->perimeter * b->perimeter; /* X (the top) */
    /* The fast path: D from the caller's distances alone, D^2 = x less
     * their round-off (tol, far below D here: (x - tol)^2 >= x (1 - 2e-6)
     * once x >= (1e6 tol)^2), and no division until a result passes. */
    const double x = gap2 > dplane * dplane || dplane < 0 ? gap2 : dplane * dplane;
    if (one_batch && x >= 1e12 * tol * tol) {
        const double ra = a->radius, rb = b->radius;
        const double lmax = a->lmax > b->lmax ? a->lmax : b->lmax;
        const double d = x * (1 - 2e-6) * inv_s2, mu = lmax * lmax * inv_s2;
        /* R^2 <= 2 c^2 + 2 (ra + rb)^2 */
        const double rr = 2 * (sep2 + (ra + rb) * (ra + rb)) * (1 + 1e-12) * inv_s2;
        const double z = (rr * d > 1 ? rr * d : 1) + 2 * rr + 2 * mu;
        if (d > 1e-30 && d <= 1 && rr < 1e300) {
            double tk[4], dk[4];
            fast_bounds(d, mu, z, pp, px, short_log ? LOG_SHORT_ERR : 0, tk, dk);
            /* the guess at S (as in tiers_general), times sep^4 */
            const double sep4 = sep2 * sep2, G = guess_g(a, b, sep);
            const double rg = rel * G;
            int t = tk[0] * sep4 <= rg * dk[0]   ? 0
                    : tk[1] * sep4 <= rg * dk[1] ? 1
                    : tk[2] * sep4 <= rg * dk[2] ? 2
                                                 : 3;
            double est = 8 * G / sep4;
            for (; t < 4; t++) {
                if (!(tk[t] <= rel * est * dk[t]))
                    break; /* cannot pass: the general bounds */
                const double sk = quad_eval_k(&bt, m, inv_s2, tier_k[t], short_log);
                if (sk > 0 && tk[t] <= rel * sk * dk[t]) {
                    *s = sk;
                    *e = tk[t] / dk[t];
                    return 1;
                }
                est = sk - tk[t] / dk[t];
            }
        }
    }
    const double dmin = (sqrt(gap2) > dplane ? sqrt(gap2) : dplane) - tol;
    return tiers_general(a, b, one_batch ? &bt : NULL, m, pp, px, scale2, dmin, rel, s, e);
}

RAD_KERNEL_CLONES
static int tiers_short(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, double gap2,
                       double dplane, double tol, double rel, double *s, double *e)
{
    return tiers(a, b, scale2, gap2, dplane, tol, rel, s, e, 1);
}

RAD_KERNEL_CLONES
static int tiers_full(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, double gap2,
                      double dplane, double tol, double rel, double *s, double *e)
{
    return tiers(a, b, scale2, gap2, dplane, tol, rel, s, e, 0);
}

int radi_ff_gauss_tiers(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, double gap2,
                       double dplane, double tol, double rel, double *s, double *e)
{
    return rel > 1e-8 ? tiers_short(a, b, scale2, gap2, dplane, tol, rel, s, e)
                      : tiers_full(a, b, scale2, gap2, dplane, tol, rel, s, e);
}

#else /* without vector extensions these paths are not used */

double radi_ff_nine_point(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, int touch)
{
    (void)a, (void)b, (void)scale2, (void)touch;
    return NAN;
}

double radi_ff_gauss_sum(const rad_ff_poly *a, const rad_ff_poly *b, int k, double scale2,
                        double *pp)
{
    (void)a, (void)b, (void)k, (void)scale2, (void)pp;
    return NAN;
}

int radi_ff_gauss_tiers(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, double gap2,
                       double dplane, double tol, double rel, double *s, double *e)
{
    (void)a, (void)b, (void)scale2, (void)gap2, (void)dplane, (void)tol, (void)rel, (void)s,
        (void)e;
    return 0;
}
#endif
