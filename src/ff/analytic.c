/* analytic.c -- closed-form form factors, evaluated without cancellation.
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 * Four configurations with textbook closed forms serve as references for the
 * contour-integral kernel (formfactor.c) and for `radiosity analytic`:
 *
 *   point-disk     differential area on the axis of a coaxial parallel disk
 *   disk-disk      coaxial parallel disks of radii r1, r2, h apart
 *   parallel       directly opposed a x b rectangles, c apart
 *   perpendicular  l x w and l x h rectangles sharing the edge l at 90 deg
 *
 * Conventions (as in radiosity.h): lengths in the user's unit, form factors
 * dimensionless, F always FROM the first surface named TO the second.  Every
 * function depends only on ratios of its arguments.  An argument that is
 * zero, negative, infinite or NaN gives NaN: none of these configurations
 * has a form factor then.
 *
 * Accuracy.  The textbook expressions subtract nearly equal numbers at the
 * extremes (far apart, nearly touching, long and thin), and their squares
 * and products of ratios overflow or underflow long before the form factor
 * does.  Three devices keep every result within 1e-13 relative (in fact a
 * few units in the last place) for all positive finite arguments, as long
 * as the form factor itself is a normal double (below DBL_MIN the result
 * carries the absolute error of a subnormal):
 *
 *   1. Scale invariance.  A form factor depends only on ratios of lengths.
 *      Ratios are formed directly from the arguments (a/c, never (a/s)/(c/s)),
 *      and only ratios <= 1 are formed where the other regime could
 *      overflow: a variable beyond 2^K (K = 40) is carried as its
 *      reciprocal, which may underflow harmlessly.
 *   2. Exact rearrangement.  Each formula is rewritten by exact algebra
 *      into a sum of non-negative terms, or into a form whose only
 *      subtraction is provably mild, in the variables of its regime.  A
 *      small argument enters a term multiplied, never inside a square that
 *      would underflow before the multiplication by its reciprocal.
 *   3. Asymptotic forms past 2^K.  Where a variable exceeds 2^K = 1.1e12
 *      (or falls below 2^-K) two regimes drop terms whose relative size is
 *      bounded by 2^-78 (stated at each): far below double precision.
 *
 * The rearrangements use the auxiliary functions
 *
 *   tau(u) = u - atan(u)                ~ u^3/3 for small u,
 *   phi(p) = atan(p) - p / (1 + p^2)    ~ 2 p^3/3 for small p,
 *   lr(q)  = log1p(q) / q               ~ 1 - q/2 for small q,
 *   atanc(x) = atan(x) / x              ~ 1 - x^2/3 for small x,
 *
 * each evaluated by a short series or a half-angle step where its own
 * subtraction would cancel (switch-over points below).  tests/analytic.py
 * checks every function against the printed formulas in mpmath over
 * arguments 1e-300..1e300, tests/unit/ff/test_analytic.c against limits,
 * quadrature and identities.
 *
 * Sources:
 *   [H]  J. R. Howell, A Catalog of Radiation Heat Transfer Configuration
 *        Factors, 3rd ed., http://www.thermalradiation.net (C-11, C-14).
 *   [SH] R. Siegel and J. R. Howell, Thermal Radiation Heat Transfer, 4th
 *        ed., Taylor & Francis 2002, Appendix C.
 */
#include "ff/analytic.h"

#include <float.h>
#include <math.h>
#include "util/util.h"


/* ---- argument checks and regimes ---------------------------------------- */

static int valid_length(double x)
{
    return isfinite(x) && x > 0.0;
}

/* The regime boundary 2^K, K = 40 (1.1e12): a ratio above it is carried
 * as its reciprocal.  Below it every formula squares at most products of
 * two ratios (<= 2^160, no overflow), and past it the asymptotic forms
 * drop terms of relative size 2^-2K = 8e-25 or less. */
#define RAD_K 40

/* x > 2^K y, without forming 2^K y when that overflows (then false). */
static int far_above(double x, double y)
{
    return x > ldexp(y, RAD_K);
}

/* ---- auxiliary functions ------------------------------------------------- */

/* tau(u) = u - atan(u) for 0 <= u <= 1/4 by its Maclaurin series
 * sum_{k>=1} (-1)^(k+1) u^(2k+1) / (2k+1) (Abramowitz & Stegun 4.4.42).
 * With u^2 <= 1/16 the 14 terms kept leave a remainder below
 * u^3 (1/16)^14 / 31 < 1e-18 u^3, and the alternating terms lose at most
 * a factor 1/(1 - 3/80) to cancellation. */
static double tau_series(double u)
{
    const double u2 = u * u;
    double s = 0.0;
    int k;
    for (k = 14; k >= 1; k--)
        s = 1.0 / (2 * k + 1) - u2 * s;
    return u * u2 * s;
}

/* tau(u) = u - atan(u), u >= 0.
 *   u <= 1/4:      series (tau_series); so is NaN, which must not recurse;
 *   1/4 < u < 2:   half-angle step.  With v = tan(atan(u)/2)
 *                  = u / (1 + sqrt(1 + u^2)), atan u = 2 atan v and
 *                  u - 2v = u v^2 exactly, so tau(u) = u v^2 + 2 tau(v):
 *                  two non-negative terms, and v < u/2 (at most 3 steps);
 *   u >= 2:        u - atan(u) directly; atan(u)/u < 0.56 there, so the
 *                  subtraction loses less than a factor 2.3. */
double radi_analytic_u_minus_atan(double u)
{
    double v;
    if (!(u > 0.25))
        return tau_series(u);
    if (u >= 2.0)
        return u - atan(u);
    v = u / (1.0 + sqrt(1.0 + u * u));
    return u * v * v + 2.0 * radi_analytic_u_minus_atan(v);
}

/* phi(p) = atan(p) - p / (1 + p^2), p >= 0 (the integral of
 * 2 x^2 / (1 + x^2)^2 from 0 to p, so phi >= 0).
 *   p < 1:   phi = p^3 / (1 + p^2) - tau(p), the two terms differ by a
 *            factor >= 1/(1 - 0.43) (at p = 1), loss < 1.8;
 *   p >= 1:  as written, atan(p) / phi(p) <= 2.8 (at p = 1). */
double radi_analytic_atan_minus_rational(double p)
{
    const double p2 = p * p;
    if (p < 1.0)
        return p * p2 / (1.0 + p2) - radi_analytic_u_minus_atan(p);
    return atan(p) - p / (1.0 + p2);
}

/* lr(q) = log1p(q) / q for q >= -1/2, with lr(0) = 1 (the limit): a
 * logarithm divided by its small argument, so that a product x^2 y^2 that
 * underflows never has to be formed.  log1p is accurate to an ulp (C99),
 * the quotient adds one rounding. */
static double log1p_ratio(double q)
{
    return q == 0.0 ? 1.0 : log1p(q) / q;
}

/* atanc(x) = atan(x) / x for x >= 0, atanc(0) = 1; for x < 2^-27 atan(x)
 * rounds to x and the quotient to 1 (x^2/3 below half an ulp). */
static double atan_ratio(double x)
{
    return x == 0.0 ? 1.0 : atan(x) / x;
}

/* ln(x/y) for x, y > 0: log of the quotient while the quotient is a normal
 * double (its rounding then moves the logarithm by an ulp-sized absolute
 * amount), log(x) - log(y) when it would overflow or underflow (then
 * |ln(x/y)| > 708 and the two logarithms, each within an ulp of <= 745,
 * differ by at most twice that relatively).  A plain log(x) - log(y)
 * would lose up to 25x near the 2^40 switch-over with x, y near 1e-308. */
static double log_ratio(double x, double y)
{
    const double q = x / y;
    if (q >= DBL_MIN && q <= DBL_MAX)
        return log(q);
    return log(x) - log(y);
}

/* ---- point to disk ------------------------------------------------------- */

/* Differential area on the axis of a coaxial parallel disk ([H] section B,
 * "plane element to plane parallel coaxial disk"; [SH] App. C):
 *     F = r^2 / (h^2 + r^2) = 1 / (1 + t^2),  t = h/r,
 *       = u (u / (1 + u^2)),                   u = r/h.
 * No subtraction.  The first form for t <= 1 (t^2 may underflow: then
 * F = 1 to double precision), the second for t > 1 (u^2 never overflows,
 * and u (u / ...) stays normal until F itself is subnormal). */
double rad_analytic_point_disk(double r, double h)
{
    double t, u;
    if (!valid_length(r) || !valid_length(h))
        return NAN;
    if (h <= r) {
        t = h / r;
        return 1.0 / (1.0 + t * t);
    }
    u = r / h;
    return u * (u / (1.0 + u * u));
}

/* ---- disk to disk -------------------------------------------------------- */

/* Disk 1 (radius r1) to coaxial parallel disk 2 (radius r2), h apart
 * ([SH] App. C; [H] section C, "disk to parallel coaxial disk of unequal
 * radius"):  R1 = r1/h, R2 = r2/h, X = 1 + (1 + R2^2) / R1^2,
 *     F = [X - sqrt(X^2 - 4 (R2/R1)^2)] / 2.
 * Multiplying through by h^2 r1^2, with S = h^2 + r1^2 + r2^2:
 *     X^2 - 4 (R2/R1)^2 = (S^2 - 4 r1^2 r2^2) / r1^4
 *                       = [(r1 - r2)^2 + h^2] [(r1 + r2)^2 + h^2] / r1^4,
 * and rationalising the difference (its two roots multiply to R2^2/R1^2):
 *     F = 2 r2^2 / (S + sqrt([(r1 - r2)^2 + h^2] [(r1 + r2)^2 + h^2])).
 * Only sums of positive terms remain (r1 - r2 is computed exactly or with
 * one rounding and then squared), so F has a relative error of a few ulps
 * everywhere: no switch-over is needed.
 *
 * Range: the arguments are first scaled by the same power of two (exact)
 * so that the largest lies in [1, 2); squares then cannot overflow, and
 * the denominator D lies in [1, 16].  An argument smaller than about
 * 1e-154 of the largest has a square that underflows; it enters S, D only
 * as a sum with a term >= 1 (relative weight < 1e-308) except through
 * r2^2 in the numerator, which is formed as 2 r2 (r2 / D) so that only
 * the final product can leave the normal range, and only when F is below
 * DBL_MIN itself. */
double rad_analytic_disk_disk(double r1, double r2, double h)
{
    double a, b, c, root, d;
    int e;
    if (!valid_length(r1) || !valid_length(r2) || !valid_length(h))
        return NAN;
    e = ilogb(fmax(fmax(r1, r2), h));
    a = ldexp(r1, -e);
    b = ldexp(r2, -e);
    c = ldexp(h, -e);
    root = hypot(a - b, c) * hypot(a + b, c);
    d = c * c + a * a + b * b + root;
    return 2.0 * b * (b / d);
}

/* ---- parallel rectangles -------------------------------------------------- */

/* Directly opposed parallel a x b rectangles, c apart ([H] C-11; [SH]
 * App. C):  X = a/c, Y = b/c,
 *     F = 2/(pi X Y) { ln sqrt[(1 + X^2)(1 + Y^2) / (1 + X^2 + Y^2)]
 *                      + X sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2))
 *                      + Y sqrt(1 + X^2) atan(Y / sqrt(1 + X^2))
 *                      - X atan X - Y atan Y }.
 * Grouping the terms that cancel,
 *     pi F = L + G(X, Y) + G(Y, X),
 *     L       = ln(1 + q) / (X Y),   1 + q = (1 + X^2)(1 + Y^2)/(1 + X^2 + Y^2),
 *                                    q = X^2 Y^2 / (1 + X^2 + Y^2) >= 0,
 *     G(x, y) = 2 g(x, y) / y,       g(x, y) = s atan(x/s) - atan(x),
 *                                    s = sqrt(1 + y^2),
 * three non-negative terms (g >= 0 because t atan(x/t) increases with t),
 * so F is as accurate as the least accurate of them.  F is symmetric in
 * a, b; below a >= b, so X >= Y.  Three regimes:
 *   X <= 2^K            pr_moderate: X, Y as they are (Y may be tiny);
 *   X > 2^K, Y < 1      pr_long_strip: u = 1/X, an asymptotic form;
 *   X > 2^K, Y >= 1     pr_near: u = 1/X, v = 1/Y, exact. */

/* G(x, y) / 2 = g(x, y) / y for 0 < x, y <= 2^K (either the larger).  With
 * d = s - 1 = y^2 / (s + 1), p = x / s and the exact identities
 *     atan(x) - atan(p) = atan(z),   z = x d / (s + x^2) = d p / (1 + p^2 s),
 *     atan(p) - p / (1 + p^2 s) = phi(p) + p^3 d / ((1 + p^2)(1 + p^2 s)),
 * g becomes
 *     g = d atan(p) - atan(z) = d [atan(p) - z/d] + tau(z)
 *       = d [phi(p) + p^3 d / ((1 + p^2)(1 + p^2 s))] + tau(z),
 * a sum of non-negative terms with the relative error of phi and tau, a
 * few ulps.  Divided by y: d/y = y/(s + 1) is formed without squaring y.
 * Against pi F (>= L of pr_moderate) the last term tau(z)/y is at most
 * about m^2, m = min(X, Y), and tau(z) underflows only for z < 1e-103,
 * which with X, Y <= 2^K needs m < 1e-30: what its underflow drops is
 * then below 1e-60 of F. */
static double pr_half_g(double x, double y)
{
    const double s = hypot(1.0, y);
    const double d_y = y / (s + 1.0);
    const double d = d_y * y;
    const double p = x / s;
    const double p2 = p * p;
    const double q = 1.0 + p2 * s;
    const double z = d * p / q;
    const double inner = radi_analytic_atan_minus_rational(p)
                         + p * p2 * d / ((1.0 + p2) * q);
    return d_y * inner + radi_analytic_u_minus_atan(z) / y;
}

/* X = a/c <= 2^K, 0 < Y = b/c <= X.  L = [X Y / (1 + X^2 + Y^2)] lr(q):
 * the product X Y is never squared on its own, so L is exact to an ulp
 * or two until it is subnormal.  Sum of three non-negative terms. */
static double pr_moderate(double x, double y)
{
    const double den = 1.0 + x * x + y * y;
    const double xy = x * y;
    const double l = x / den * y * log1p_ratio(xy * (xy / den));
    return (l + 2.0 * pr_half_g(x, y) + 2.0 * pr_half_g(y, x)) / RAD_PI;
}

/* X > 2^K, Y < 1, u = 1/X < 2^-K (may have underflowed to 0):
 *   L exactly:  q = Y^2 / (1 + u^2 (1 + Y^2)) <= 1,
 *               L = u Y / (1 + u^2 (1 + Y^2)) lr(q).
 *   G(X, Y):    atan(X/s) = pi/2 - atan(s u), atan(X) = pi/2 - atan(u), so
 *               g(X, Y) = (s - 1) pi/2 - [s atan(s u) - atan(u)], and the
 *               alternating series in u (s u < 1) gives
 *               s atan(s u) - atan(u) = Y^2 u [1 - (s^2 + 1) u^2/3 + ...]
 *               = Y^2 u (1 - e1), 0 <= e1 <= u^2 (s^2 <= 2).  So
 *               G(X, Y) = pi Y/(s + 1) - 2 Y u (1 - e1).
 *   G(Y, X):    with S = sqrt(1 + X^2) > 2^K, S atan(Y/S) = Y (1 - e2),
 *               0 <= e2 <= Y^2/(3 S^2), so g(Y, X) = tau(Y) - Y e2 and
 *               G(Y, X) = 2 u g(Y, X) = 2 u tau(Y) (1 - e3),
 *               e3 = Y e2 / tau(Y) <= 2.5 u^2 (tau(Y) >= 2 Y^3/15 for Y <= 1).
 * Dropping e1 and e3 (and using Y - tau(Y) = atan(Y)):
 *     pi F = L + pi Y/(s + 1) - 2 u atan(Y),
 * with an absolute error below 5 Y u^3, relative to pi F >= 1.3 Y below
 * 4 u^3 < 2^-118.  The subtraction is harmless: 2 u atan(Y) <= 2 u Y.
 * This is Hottel's crossed-strings factor of two infinite strips,
 * (sqrt(1 + Y^2) - 1)/Y, with its first end correction. */
static double pr_long_strip(double u, double y)
{
    const double s = hypot(1.0, y);
    const double w = 1.0 + u * u * (1.0 + y * y);
    const double l = u * y / w * log1p_ratio(y * y / w);
    return (l + RAD_PI * y / (s + 1.0) - 2.0 * u * atan(y)) / RAD_PI;
}

/* X >= Y >= 1, X > 2^K, in u = 1/X = c/a, v = 1/Y = c/b, r = u/v = b/a
 * (all <= 1, formed directly from the arguments).  Exactly, with
 * su = sqrt(1 + u^2), sv = sqrt(1 + v^2):
 *   G(X, Y) = 2 v g(X, Y), s = sv/v, X/s = 1/(r sv), and
 *     atan(X/s) = pi/2 - atan(r sv), atan(X) = pi/2 - atan(u):
 *     G(X, Y) = pi/(sv + v) - 2 sv atan(r sv) + 2 v atan(u)
 *     (pi (sv - v) = pi / (sv + v) without cancellation);
 *   G(Y, X) = 2 u g(Y, X), S = su/u, Y/S = r/su, atan(Y) = pi/2 - atan(v):
 *     G(Y, X) = 2 su atan(r/su) - pi u + 2 u atan(v);
 *   L = u v ln(1 + q), multiplying (1 + X^2)(1 + Y^2)/(1 + X^2 + Y^2) by
 *     u^2 v^2 / u^2 v^2 and using u^2 v^2 + u^2 + v^2 = v^2 (1 + r^2 (1 + v^2)):
 *     ln(1 + q) = log1p(u^2) + log1p(v^2) - 2 ln(v) - log1p(r^2 (1 + v^2)).
 * Here pi F >= pi F(2^K, 1) > 1.3, and the terms that partly cancel
 * (the two atan(r ...) terms, pi u) sum to at most 3 pi in magnitude:
 * a loss of at most 8 ulps.  ln(v) is log_ratio(c, b), finite when c/b
 * underflows. */
static double pr_near(double a, double b, double c)
{
    const double u = c / a, v = c / b, r = b / a;
    const double su = hypot(1.0, u), sv = hypot(1.0, v);
    const double ln_v = log_ratio(c, b);
    const double ln1q = log1p(u * u) + log1p(v * v) - 2.0 * ln_v
                        - log1p(r * r * (1.0 + v * v));
    const double g1 = RAD_PI / (sv + v) - 2.0 * sv * atan(r * sv)
                      + 2.0 * v * atan(u);
    const double g2 = 2.0 * su * atan(r / su) - RAD_PI * u + 2.0 * u * atan(v);
    return (u * v * ln1q + g1 + g2) / RAD_PI;
}

double rad_analytic_parallel_rectangles(double a, double b, double c)
{
    double y;
    if (!valid_length(a) || !valid_length(b) || !valid_length(c))
        return NAN;
    if (a < b) {
        const double t = a;
        a = b;
        b = t;
    }
    if (far_above(a, c)) {
        if (b >= c)
            return pr_near(a, b, c);
        return pr_long_strip(c / a, b / c);
    }
    y = b / c;
    /* F <= Y/2 (the infinite strips' factor bounds it): 0 when Y is 0 */
    if (y == 0.0)
        return 0.0;
    return pr_moderate(a / c, y);
}

/* ---- perpendicular rectangles --------------------------------------------- */

/* From the l x w rectangle to the l x h rectangle sharing the edge of
 * length l at a right angle ([H] C-14; [SH] App. C):  W = w/l, H = h/l,
 * R^2 = W^2 + H^2, psi(t) = t atan(1/t),
 *     F = B(W, H) / (pi W),
 *     B = psi(W) + psi(H) - psi(R)
 *         + 1/4 ln{ (1 + W^2)(1 + H^2) / (1 + R^2)
 *                   [W^2 (1 + R^2) / ((1 + W^2) R^2)]^(W^2)
 *                   [H^2 (1 + R^2) / ((1 + H^2) R^2)]^(H^2) }.
 * B is symmetric in W, H, so reciprocity l w F(l,w,h) = l h F(l,h,w)
 * holds to rounding.  Below m = min(W, H), M = max(W, H), s = m/M (from
 * the arguments: min(w,h)/max(w,h)), and the three logarithms are
 *     L1 = ln[(1 + m^2)(1 + M^2)/(1 + R^2)] = log1p(m^2 M^2 / (1 + R^2)),
 *     Lm = m^2 ln[m^2 (1 + R^2) / ((1 + m^2) R^2)],   LM likewise,
 * B = psi(m) + psi(M) - psi(R) + (L1 + Lm + LM)/4.  Each regime computes
 * B/m or B (whichever does not need a division by a subnormal m), then
 * F = (B/m)/pi when W = m, (B/m) s/pi when W = M.  Regimes:
 *   2^-K <= M <= 2^K   pp_moderate (m may be tiny), B/m;
 *   M < 2^-K           pp_long_strips: l >> w, h, asymptotic, F;
 *   M > 2^K >= m       pp_tall: asymptotic, B/m;
 *   m > 2^K            pp_wide: l << w, h, exact, B. */

/* psi(r) - psi(M), divided by m, for r = sqrt(M^2 + m^2), without
 * forming psi(r) - psi(M): with delta = r - M = m^2 / (r + M) and
 * atan(1/M) - atan(1/r) = atan(delta / (1 + M r)),
 *     psi(r) - psi(M) = delta atan(1/r) - M atan(delta / (1 + M r)).
 * The two terms cancel only when M >> 1, where the difference is
 * O(m^2/M^4) and both terms are O(m^2/M^2): the absolute error stays
 * below a few ulps of delta atan(1/r) <= psi(m), negligible against B,
 * which exceeds 0.58 psi(m). */
static double pp_psi_diff_over_m(double m, double M, double r)
{
    const double delta_m = m / (r + M);
    const double x = delta_m * m / (1.0 + M * r);
    return delta_m * atan2(1.0, r)
           - M * delta_m / (1.0 + M * r) * atan_ratio(x);
}

/* B/m for 2^-K <= M <= 2^K, 0 < m <= M, ln_m = ln(m) (log_ratio of the
 * arguments, finite even when m underflows).  Written as
 *   B/m = atan(1/m) - [psi(R) - psi(M)]/m
 *         + 1/4 [ L1/m + m ln(1 - tm) + (M^2/m) ln(1 - tM) ],
 *   tm = M^2 / (R^2 (1 + m^2)),  tM = m^2 / (R^2 (1 + M^2)) <= 1/2,
 * using (1 + m^2)(1 + M^2) = 1 + R^2 + m^2 M^2 and
 * m^2 (1 + R^2) = (1 + m^2) R^2 - M^2 (and the same with m, M swapped).
 *   L1/m = [m M^2 / (1 + R^2)] lr(m^2 M^2 / (1 + R^2));
 *   ln(1 - tm) = log1p(-tm) for tm <= 1/2, else
 *                2 ln(m) + ln[(1 + R^2) / ((1 + m^2) R^2)] (>= ln 2 in
 *                magnitude, so the quotient's rounding is harmless, and
 *                finite when m^2 underflows);
 *   (M^2/m) ln(1 - tM) = -M^2 (tM/m) lr(-tM),  tM/m = m / (R^2 (1 + M^2)).
 * The pieces partly cancel, but the sum of their magnitudes never exceeds
 * 2.5 B/m (the largest loss, 1 + sqrt 2, is at W = H -> 0), and
 * B >= 0.58 psi(m). */
static double pp_moderate(double m, double M, double ln_m)
{
    const double m2 = m * m, M2 = M * M;
    const double r2 = m2 + M2, r = hypot(m, M);
    const double one_r2 = 1.0 + r2;
    const double q = m * M2 / one_r2;
    const double l1 = q * log1p_ratio(q * m);
    const double tm = M2 / (r2 * (1.0 + m2));
    const double lm = tm <= 0.5 ? log1p(-tm)
                                : 2.0 * ln_m + log(one_r2 / ((1.0 + m2) * r2));
    const double tM_m = m / (r2 * (1.0 + M2));
    const double lM = -M2 * tM_m * log1p_ratio(-tM_m * m);
    return atan2(1.0, m) - pp_psi_diff_over_m(m, M, r)
           + 0.25 * (l1 + m * lm + lM);
}

/* M = max(W, H) < 2^-K (l >> w, h): the expansion of C-14 for small W, H
 * (psi(t) = pi t/2 - t^2 + t^4/3 - t^6/5 + ..., log1p to second order):
 *   B = pi/2 (m + M - R) + [m^2 ln(m^2/R^2) + M^2 ln(M^2/R^2)]/4
 *       + m^2 M^2/12 + O(m^2 M^2 R^2),
 * every neglected term carrying the factor m^2 M^2 (B vanishes at m = 0).
 * As B >= pi m M/(m + M + R) >= 0.9 m, the relative remainder is below
 * 3 M^4 < 2^-158.  In M and s = m/M, with m + M - R = 2 m M/(m + M + R)
 * and ln(R^2/M^2) = log1p(s^2):
 *   B = M { pi s/(1 + s + sr) - M [(1 + s^2) log1p(s^2) - 2 s^2 ln s]/4
 *           + M^3 s^2/12 },      sr = sqrt(1 + s^2),
 * where the first term is Hottel's crossed strings (two infinite strips
 * meeting at a right angle) and the rest the end correction: the bracket
 * of the second term is at most 2 s + 2/e <= 2.8, the first at least
 * 0.92 s, so the subtraction removes less than 0.8 M < 2^-40 of it.  Returned: F = B/(pi W), i.e.
 * the braces over pi (W = M) or over pi s (W = m), divided analytically. */
static double pp_long_strips(double M, double s, int w_is_min)
{
    const double sr = hypot(1.0, s);
    const double s_ln_s = s == 0.0 ? 0.0 : s * log(s);
    /* [(1 + s^2) log1p(s^2) - 2 s^2 ln s] / s, non-negative terms */
    const double ends_s = (1.0 + s * s) * s * log1p_ratio(s * s) - 2.0 * s_ln_s;
    const double cross = RAD_PI / (1.0 + s + sr);
    double b_s = cross - 0.25 * M * ends_s + M * M * M * s / 12.0;
    if (!w_is_min)
        b_s *= s;
    return b_s / RAD_PI;
}

/* M > 2^K >= m (w << l << h or h << l << w, and the tall or deep
 * neighbours of that), mu = 1/M < 2^-K, s = m/M = m mu.
 * psi(M) - psi(R) lies in [-m^2 mu^4/3, 0] (psi'(t) = phi(1/t) <=
 * 2/(3 t^3), R - M <= m^2/(2M)): relative to B >= 0.78 min(m, 1) it is
 * below mu^2 < 2^-80, and it is dropped.  The rest is exact:
 *   L1 = log1p(m^2) - log1p(s^2/(1 + mu^2))   (1 + R^2 = (1 + M^2)(1 + ...));
 *   LM = M^2 ln[(1 + 1/R^2)/(1 + mu^2)] = -y lr(mu^2 y),
 *        y = s^2/(1 + s^2 + mu^2), from mu^2 - 1/R^2 = mu^2 m^2/R^2;
 *   Lm = m^2 [ln(m^2/(1 + m^2)) + log1p(1/R^2)],  1/R^2 = mu^2/(1 + s^2),
 *        ln(m^2/(1 + m^2)) = 2 ln m - log1p(m^2) (m < 1) or -log1p(1/m^2),
 *        the two terms of Lm differ by a factor >= 2 (1/R^2 <= 1/(2 m^2)).
 * B/m = atan(1/m) + (L1 + LM + Lm)/(4m), each term divided analytically
 * (L1/m = m lr(m^2) - (s mu/(1 + mu^2)) lr(...), LM/m = -(y/m) lr(...) with
 * y/m = s mu/(1 + s^2 + mu^2)).  L1 >= 0 >= LM, Lm; the sum loses at most
 * a factor 2 (the limit B_inf(m) = psi(m) + [ln(1 + m^2) - m^2 ln(1 +
 * 1/m^2)]/4 of a tall receiver, whose bracket is 0 at m = 1). */
static double pp_tall(double m, double mu, double s, double ln_m)
{
    const double m2 = m * m, mu2 = mu * mu;
    const double inv_r2 = mu2 / (1.0 + s * s);
    const double a1 = s * s / (1.0 + mu2);
    const double l1_m = m * log1p_ratio(m2)
                        - s * mu / (1.0 + mu2) * log1p_ratio(a1);
    const double y = s * s / (1.0 + s * s + mu2);
    const double lM_m = -(s * mu / (1.0 + s * s + mu2)) * log1p_ratio(mu2 * y);
    const double lnq = m < 1.0 ? 2.0 * ln_m - log1p(m2) : -log1p(1.0 / m2);
    const double lm_m = m * (lnq + log1p(inv_r2));
    return atan2(1.0, m) + 0.25 * (l1_m + lM_m + lm_m);
}

/* m > 2^K (l << w, h), nu = 1/m, mu = 1/M (<= nu < 2^-K), s = m/M, and
 * ln_nu = ln(1/m) from the arguments.  Exactly:
 *   psi(W) + psi(H) - psi(R) = atanc(nu) + atanc(mu) - atanc(1/R),
 *     1/R = mu / sqrt(1 + s^2), each term in [0.999, 1];
 *   L1 = ln(m^2 M^2/R^2) + log1p(nu^2) + log1p(mu^2) - log1p(1/R^2),
 *     ln(m^2 M^2/R^2) = ln(m^2/(1 + s^2)) = -2 ln(nu) - log1p(s^2);
 *   LM = -y lr(mu^2 y),  y = s^2/(1 + s^2 + mu^2)   (as in pp_tall);
 *   Lm = -y' lr(nu^2 y'), y' = 1/(1 + s^2 + mu^2), from
 *        nu^2 - 1/R^2 = nu^2 M^2/R^2.
 * B is returned.  B >= 3/4 + ln(m/sqrt 2)/2 > 14: the subtractions
 * (terms of size <= 1 next to L1/4 ~ ln m) lose nothing. */
static double pp_wide(double nu, double mu, double s, double ln_nu)
{
    const double inv_r = mu / hypot(1.0, s);
    const double psis = atan_ratio(nu) + atan_ratio(mu) - atan_ratio(inv_r);
    const double l1 = -2.0 * ln_nu - log1p(s * s) + log1p(nu * nu)
                      + log1p(mu * mu) - log1p(inv_r * inv_r);
    const double den = 1.0 + s * s + mu * mu;
    const double lM = -(s * s / den) * log1p_ratio(mu * mu * s * s / den);
    const double lm = -(1.0 / den) * log1p_ratio(nu * nu / den);
    return psis + 0.25 * (l1 + lM + lm);
}

double rad_analytic_perpendicular_rectangles(double l, double w, double h)
{
    double mn, mx, s, b_m;
    int w_is_min;
    if (!valid_length(l) || !valid_length(w) || !valid_length(h))
        return NAN;
    w_is_min = w <= h;
    mn = w_is_min ? w : h;
    mx = w_is_min ? h : w;
    s = mn / mx;
    if (far_above(mn, l))
        /* F = B/(pi W) = B (l/w)/pi; l/w last, as it may be subnormal */
        return pp_wide(l / mn, l / mx, s, log_ratio(l, mn)) / RAD_PI * l / w;
    if (far_above(mx, l))
        b_m = pp_tall(mn / l, l / mx, s, log_ratio(mn, l));
    else if (far_above(l, mx))
        return pp_long_strips(mx / l, s, w_is_min);
    else
        b_m = pp_moderate(mn / l, mx / l, log_ratio(mn, l));
    return (w_is_min ? b_m : b_m * s) / RAD_PI;
}
