/* ffcontour.c -- the contour integral by closed forms and adaptive
 * quadrature, in double and, where double cancels, in long double.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The contour sum S = sum_pq (e_p . e_q) I_pq (formfactor.c) with
 * I_pq = integral over edge p and edge q of ln(r/s):
 *
 *   parallel edges, d apart: the closed form
 *     I = H(a2-b1) + H(a1-b2) - H(a1-b1) - H(a2-b2),  H'' = ln sqrt(u^2 + d^2),
 *     H(u) = (u^2 - d^2)/4 ln(u^2 + d^2) - 3u^2/4 + d u atan(u/d)
 *   (integrating ln sqrt(u^2 + d^2) twice: Gradshteyn & Ryzhik 2.733.1 and
 *   2.822.1; d = 0, the colinear case, is the limit H(u) = u^2/2 ln|u| -
 *   3u^2/4).  The code uses H~ = H + d^2/4 ln d^2, which the second
 *   difference does not see and which has no d^2 ln d term:
 *     H~(u) = u^2/4 ln(u^2 + d^2) - d^2/4 log1p(u^2/d^2) - 3u^2/4 + d u atan(u/d),
 *   so lines far apart against the edges (d >> u) do not cancel;
 *
 *   skew edges: the inner integral over q in closed form,
 *     G(v) = integral of ln sqrt(v^2 + h^2) dv = v ln sqrt(v^2 + h^2) - v + h atan(v/h)
 *   (G&R 2.733.1), for the point of p at distance h from q's line, and the
 *   outer one over p by globally adaptive Gauss-Kronrod 7-15 (Piessens et
 *   al., QUADPACK, 1983, routines QK15 and QAG): the panel with the largest
 *   error above its round-off floor is bisected until the errors sum to the
 *   tolerance, or every panel is down to its floor (64 eps times the size
 *   of the closed-form terms it sums: G of a far point and a short edge is
 *   a small difference of large values), or ADAPT_MAX_PANELS panels are
 *   used; the estimate returned (errors and floors summed) says what was
 *   reached, so a caller never waits long and never gets a false claim.
 *
 * Near-singular points.  The Kronrod-Gauss difference is an estimate of
 * the 7-point rule's error, an overestimate of the 15-point one's only
 * where the integrand is smooth on the panel.  The integrand over p is
 * not smooth near a point of p that nearly meets q: where p passes within
 * h of q's line above q (its projection crosses q), the h atan term of G
 * makes a kink of slope pi sin(theta), rounded over a width h / sin(theta);
 * where p passes near an end of q, x ln|x| does the same.  With the kink
 * inside a panel both rules err alike and their difference does not show
 * it: two facing polygons 5e-10 apart, edges crossing, gave S off by 7e-8
 * of itself under an estimate of 1.2e-9 (tests/geomfuzz.py, seed 36
 * scene 223).
 * In the complex plane of p's parameter these are singularities of the
 * integrand at s0 +- i d: the lines' nearest approach (s0 there, d their
 * distance over sin(theta)) when the foot on q's line is on q, and the
 * feet of q's ends (d their distance from p's line).  Each one nearer to
 * the edge than a quarter of its length starts a panel, and its rounding,
 * which the rules then still miss, is bounded by
 * 4 d^2 (ln(L/d) + 2) (the integral of sqrt(d^2 + x^2) - |x| over
 * |x| < L is d^2 (ln(2L/d) + 1/2) + O(d^4), the atan step's as much, times
 * the slopes, at most pi); below 1/16 of the tolerance that is added to
 * the estimate, above it panels graded at d, 2d, 4d, ... from s0 resolve
 * the singularity, which then lies at least a panel's width away from
 * every panel (a Bernstein ellipse of rho > 4: the 15-point rule far
 * better than the 7-point one, as the estimate assumes).
 *
 * Edge pairs within 1e-14 of perpendicular are left out (exactly
 * perpendicular ones contribute nothing); what they would add is bounded
 * and added to the estimate: with s^2 >= the centroid distance squared
 * plus both sizes squared, every distance r <= sqrt(3) s, so
 * ln(r/s) < 0.55, and r >= |t - t0| along q gives
 * integral of ln(s/r) dt <= lq (ln(2s/lq) + 1) <= 2s (ln x <= x - 1):
 * |I_pq| <= 2 s min(lp, lq).  Near-coplanar pairs need it: an element pair
 * of a 179.9-degree hinge had such pairs, e_p . e_q = 8e-15, worth 1.5e-8
 * of S (fuzzed scene 36:91).
 *
 * Edge pairs within about 1e-13 of parallel (sin(theta) from the unit
 * directions) take the parallel closed form, at the mean distance dm of
 * q's ends from p's line.  Let a0, a1 be those two distances, D the
 * length of q's component across p's line (sin(theta) lq), and a(t) the
 * distance of q's point t; a(t) lies below the chord l(t) between a0 and
 * a1 by at most min(D/2, D^2 / (4 min(a0, a1))) (l^2 - a^2 = t(1 - t)
 * (D^2 - (a1 - a0)^2) for t in [0, 1]), and |l(t) - dm| = |t - 1/2|
 * |a1 - a0|, so the integral of |a - dm| along q is at most
 *     lq (|a1 - a0| / 4 + min(D/2, D^2 / (4 min(a0, a1)))).
 * A point of q errs by the integral over p of |ln sqrt(u^2 + a^2) -
 * ln sqrt(u^2 + dm^2)| du <= |a - dm| K, with K = pi (over p's whole
 * line the integral is exactly pi |a - dm|: the integrand keeps its sign,
 * and integral of ln(1 + a^2/u^2) du is 2 pi a) or K = lp / c where every
 * distance between is at least c = min(a0, a1) - D/2 > 0 (the derivative
 * in a is a / (u^2 + a^2) <= 1/a).  The pair's bound is then
 *     |e_p . e_q| lq (|a1 - a0| / 4 + min(D/2, D^2 / (4 min(a0, a1)))) K  (P)
 * (the projection of q onto p's line is shorter by a factor cos(theta),
 * an error below eps).  Where (P) is within a quarter of the pair's share
 * of the tolerance, or the unit directions agree exactly (D is then
 * round-off, and the caller may have no scale for a tolerance: formfactor.c
 * counts any other pair as skew), it is added to the estimate; otherwise
 * the pair goes to the adaptive quadrature like a skew one (the lines'
 * nearest approach is then out of reach, the feet of q's ends are not).
 * Strips meeting
 * end to end along a 32-degree hinge, 700 from the origin, had three such
 * pairs with sin(theta) near 4e-14: default was 5.4e-9 off under an
 * estimate of 4.3e-10 of itself (fuzzed scene 39:150).  Exactly parallel
 * edges (D = 0, as between axis-aligned walls) add nothing.
 *
 * The error estimate of S is the quadrature's plus 16 eps times the sum of
 * the magnitudes of the terms, plus those two bounds.  For long thin pairs
 * (two slivers side by side, a long strip and a small patch) the terms
 * exceed S by 1e8 and more, and double's 16 eps of them is more than the
 * tolerance; the long double version (64-bit significand on x86-64,
 * eps = 2^-63, 2048 times smaller) then gets below it.  Inputs are
 * doubles and convert exactly.
 */
#include <config.h>

#include <float.h>
#include <math.h>

#include "ff/formfactor.h"
#include "util/util.h"

/* Kronrod 15-point nodes and weights and the embedded 7-point Gauss
 * weights (QUADPACK QK15). */
static const double gk_x[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
static const double gk_wk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double gk_wg[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

#define ADAPT_MAX_PANELS 400
#define ADAPT_MAX_BREAKS 200 /* panel ends to start from (ffcontour_tmpl.h) */

/* Parallel edge pairs in double, batched so that the compiler vectorises
 * H~ (vecmath.h: log and atan that vectorise): the four arguments of
 * every pair side by side.  Distances must keep d^2 and u^2 + d^2 normal
 * (others go one by one). */
#define PAR_BATCH 32
#define PAR_OK(u, d)                                                                        \
    ((d) > 1e-150 && (d) < 1e150 && fabs((u)[0]) < 1e150 && fabs((u)[1]) < 1e150 &&          \
     fabs((u)[2]) < 1e150 && fabs((u)[3]) < 1e150 &&                                        \
     fabs((u)[0]) + fabs((u)[1]) + fabs((u)[2]) + fabs((u)[3]) < 1e150 * (d))
#define PAR_FLUSH par_flush

RAD_KERNEL_CLONES
static void par_flush(const double *u, const double *d, const double *dot, int m, double *s,
                      double *mag)
{
    double h[4 * PAR_BATCH], hm[4 * PAR_BATCH];
#pragma omp simd
    for (int i = 0; i < 4 * m; i++) {
        const double dd = d[i / 4], uu = u[i];
        const double u2 = uu * uu, d2 = dd * dd, v = u2 / d2, w = 1 + v;
        const double l1 = rad_log_core(u2 + d2);                /* ln(u^2 + d^2) */
        const double l2 = rad_log_core(w) - ((w - 1) - v) / w; /* log1p(v) */
        const double t1 = 0.25 * u2 * l1, t2 = 0.25 * d2 * l2, t3 = 0.75 * u2;
        const double t4 = dd * uu * rad_atan_core(uu, dd);
        h[i] = t1 - t2 - t3 + t4;
        hm[i] = fabs(t1) + fabs(t2) + t3 + fabs(t4);
    }
    for (int k = 0; k < m; k++) {
        const double *hk = h + 4 * k, *mk = hm + 4 * k;
        *s += dot[k] * ((hk[0] + hk[1]) - (hk[2] + hk[3]));
        *mag += fabs(dot[k]) * (mk[0] + mk[1] + mk[2] + mk[3]);
    }
}

/* double */
#define R double
#define SUF(name) name##_d
#define R_LOG log
#define R_LOG1P log1p
#define R_ATAN2 atan2
#define R_SQRT sqrt
#define R_FABS fabs
#define R_EPS DBL_EPSILON
#include "ff/ffcontour_tmpl.h"
#undef PAR_FLUSH
#undef R
#undef SUF
#undef R_LOG
#undef R_LOG1P
#undef R_ATAN2
#undef R_SQRT
#undef R_FABS
#undef R_EPS

/* long double, the edges exact from the vertices */
#define EXACT_EDGES
#define R long double
#define SUF(name) name##_ld
#define R_LOG logl
#define R_LOG1P log1pl
#define R_ATAN2 atan2l
#define R_SQRT sqrtl
#define R_FABS fabsl
#define R_EPS LDBL_EPSILON
#include "ff/ffcontour_tmpl.h"

double radi_ff_contour(const rad_ff_edge *ea, int na, const rad_ff_edge *eb, int nb,
                      double scale2, double tol, int extended, rad_vec3 origin,
                      double *errest)
{
    return extended ? contour_ld(ea, na, eb, nb, scale2, tol, origin, errest)
                    : contour_d(ea, na, eb, nb, scale2, tol, origin, errest);
}

double radi_ff_ln_parallel_edges(const rad_ff_edge *p, const rad_ff_edge *q)
{
    edge_d ep, eq; /* single edges: their own d */
    ep.p0 = vec_of_d(p->p0);
    ep.d = vec_of_d(p->d);
    ep.len = p->len;
    ep.e = vec_of_d(p->e);
    eq.p0 = vec_of_d(q->p0);
    eq.d = vec_of_d(q->d);
    eq.len = q->len;
    eq.e = vec_of_d(q->e);
    double u[4], d, a[2], mag;
    parallel_setup_d(&ep, &eq, u, &d, a);
    return ln_parallel_u_d(u, d, &mag);
}

double rad_ln_parallel(double a1, double a2, double b1, double b2, double d)
{
    /* integral_a1^a2 integral_b1^b2 f(s - t) dt ds with f = H'' is
     * H(a2-b1) + H(a1-b2) - H(a1-b1) - H(a2-b2). */
    d = fabs(d);
    return h_parallel_d(a2 - b1, d) + h_parallel_d(a1 - b2, d) - h_parallel_d(a1 - b1, d) -
           h_parallel_d(a2 - b2, d);
}
