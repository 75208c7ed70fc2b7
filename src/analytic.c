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
 * extremes (far apart, nearly touching, long and thin): evaluated as printed
 * they lose up to all 16 digits for ratios in 1e-8..1e8.  Each formula below
 * is rearranged by exact algebra into a sum of non-negative terms (or into a
 * form whose only subtraction is provably mild), so that the result carries
 * a relative error of a few units in the last place, about 1e-15, for every
 * ratio of arguments between 1e-8 and 1e8 (parameters 1e-4..1e4).  The
 * rearrangements use two auxiliary functions,
 *
 *   tau(u) = u - atan(u)                ~ u^3/3 for small u,
 *   phi(p) = atan(p) - p / (1 + p^2)    ~ 2 p^3/3 for small p,
 *
 * each evaluated by a short series or a half-angle step where its own
 * subtraction would cancel (switch-over points below).  For ratios beyond
 * about 1e-70..1e70 intermediate squares overflow or underflow and the
 * result may be 0, inf or NaN.  tests/test_analytic.c checks all of this
 * against independent references.
 *
 * Sources:
 *   [H]  J. R. Howell, A Catalog of Radiation Heat Transfer Configuration
 *        Factors, 3rd ed., http://www.thermalradiation.net (C-11, C-14).
 *   [SH] R. Siegel and J. R. Howell, Thermal Radiation Heat Transfer, 4th
 *        ed., Taylor & Francis 2002, Appendix C.
 */
#include "analytic.h"

#include <float.h>
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---- argument checks ---------------------------------------------------- */

static int valid_length(double x)
{
    return isfinite(x) && x > 0.0;
}

/* 2^-e with 2^e the binade of the largest argument: scaling by it is exact
 * and keeps squares of the arguments far from overflow and underflow. */
static double scale_of(double m)
{
    return ldexp(1.0, -ilogb(m));
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
 *   u <= 1/4:      series (tau_series);
 *   1/4 < u < 2:   half-angle step.  With v = tan(atan(u)/2)
 *                  = u / (1 + sqrt(1 + u^2)), atan u = 2 atan v and
 *                  u - 2v = u v^2 exactly, so tau(u) = u v^2 + 2 tau(v):
 *                  two non-negative terms, and v < u/2 (at most 3 steps);
 *   u >= 2:        u - atan(u) directly; atan(u)/u < 0.56 there, so the
 *                  subtraction loses less than a factor 2.3. */
double rad_analytic_u_minus_atan(double u)
{
    double v;
    if (u <= 0.25)
        return tau_series(u);
    if (u >= 2.0)
        return u - atan(u);
    v = u / (1.0 + sqrt(1.0 + u * u));
    return u * v * v + 2.0 * rad_analytic_u_minus_atan(v);
}

/* phi(p) = atan(p) - p / (1 + p^2), p >= 0 (the integral of
 * 2 x^2 / (1 + x^2)^2 from 0 to p, so phi >= 0).
 *   p < 1:   phi = p^3 / (1 + p^2) - tau(p), the two terms differ by a
 *            factor >= 1/(1 - 0.43) (at p = 1), loss < 1.8;
 *   p >= 1:  as written, atan(p) / phi(p) <= 2.8 (at p = 1). */
double rad_analytic_atan_minus_rational(double p)
{
    const double p2 = p * p;
    if (p < 1.0)
        return p * p2 / (1.0 + p2) - rad_analytic_u_minus_atan(p);
    return atan(p) - p / (1.0 + p2);
}

/* ---- point to disk ------------------------------------------------------- */

/* Differential area on the axis of a coaxial parallel disk ([H] section B,
 * "plane element to plane parallel coaxial disk"; [SH] App. C):
 *     F = r^2 / (h^2 + r^2) = 1 / (1 + (h/r)^2).
 * No subtraction; the second form cannot overflow. */
double rad_analytic_point_disk(double r, double h)
{
    double t;
    if (!valid_length(r) || !valid_length(h))
        return NAN;
    t = h / r;
    return 1.0 / (1.0 + t * t);
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
 * everywhere: no switch-over is needed.  The arguments are first scaled by
 * a power of two (exact) to keep the squares in range. */
double rad_analytic_disk_disk(double r1, double r2, double h)
{
    double s, a, b, c, root;
    if (!valid_length(r1) || !valid_length(r2) || !valid_length(h))
        return NAN;
    s = scale_of(fmax(fmax(r1, r2), h));
    a = r1 * s;
    b = r2 * s;
    c = h * s;
    root = hypot(a - b, c) * hypot(a + b, c);
    return 2.0 * b * b / (c * c + a * a + b * b + root);
}

/* ---- parallel rectangles -------------------------------------------------- */

/* g(x, y) = sqrt(1 + y^2) atan(x / sqrt(1 + y^2)) - atan(x), x, y > 0: the
 * pair of terms of C-11 that cancel.  With s = sqrt(1 + y^2), d = s - 1
 * = y^2 / (s + 1), p = x / s and the exact identities
 *     atan(x) - atan(p) = atan(z),   z = x d / (s + x^2) = d p / (1 + p^2 s),
 *     atan(p) - p / (1 + p^2 s) = phi(p) + p^3 d / ((1 + p^2)(1 + p^2 s)),
 * it becomes
 *     g = d atan(p) - atan(z) = d [atan(p) - z/d] + tau(z)
 *       = d [phi(p) + p^3 d / ((1 + p^2)(1 + p^2 s))] + tau(z),
 * a sum of non-negative terms (g >= 0 because t atan(x/t) increases with
 * t).  Its relative error is that of phi and tau, a few ulps. */
static double pr_pair(double x, double y)
{
    const double s = hypot(1.0, y);
    const double d = y * y / (s + 1.0);
    const double p = x / s;
    const double p2 = p * p;
    const double q = 1.0 + p2 * s;
    const double z = d * p / q;
    const double inner = rad_analytic_atan_minus_rational(p)
                         + p * p2 * d / ((1.0 + p2) * q);
    return d * inner + rad_analytic_u_minus_atan(z);
}

/* Directly opposed parallel a x b rectangles, c apart ([H] C-11; [SH]
 * App. C):  X = a/c, Y = b/c,
 *     F = 2/(pi X Y) { ln sqrt[(1 + X^2)(1 + Y^2) / (1 + X^2 + Y^2)]
 *                      + X sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2))
 *                      + Y sqrt(1 + X^2) atan(Y / sqrt(1 + X^2))
 *                      - X atan X - Y atan Y }.
 * Rearranged as
 *     F = 2/(pi X Y) { (1/2) log1p(X^2 Y^2 / (1 + X^2 + Y^2))
 *                      + X g(X, Y) + Y g(Y, X) }
 * with g (pr_pair) the cancellation-free difference above: since
 * (1 + X^2)(1 + Y^2) = (1 + X^2 + Y^2) + X^2 Y^2 the logarithm is a log1p
 * of a positive quantity, and all three terms are non-negative.  The
 * textbook form loses about 2/min(X,Y)^2 (c >> a or c >> b) digits-wise;
 * this one loses nothing. */
double rad_analytic_parallel_rectangles(double a, double b, double c)
{
    double x, y, x2, y2, sum;
    if (!valid_length(a) || !valid_length(b) || !valid_length(c))
        return NAN;
    x = a / c;
    y = b / c;
    x2 = x * x;
    y2 = y * y;
    sum = 0.5 * log1p(x2 * y2 / (1.0 + x2 + y2)) + x * pr_pair(x, y)
          + y * pr_pair(y, x);
    return 2.0 * sum / (M_PI * x * y);
}

/* ---- perpendicular rectangles --------------------------------------------- */

/* psi(r) - psi(h) for psi(t) = t atan(1/t), r = sqrt(h^2 + w^2) >= h,
 * written without forming psi(r) - psi(h):  with delta = r - h
 * = w^2 / (r + h) and atan(1/h) - atan(1/r) = atan(delta / (1 + h r)),
 *     psi(r) - psi(h) = delta atan(1/r) - h atan(delta / (1 + h r)).
 * The two terms cancel only when h >> 1, where the difference is
 * O(w^2 / h^4) and both terms are O(w^2 / h^2): the absolute error stays
 * below a few ulps of delta atan(1/r) <= psi(w) (w <= h), negligible
 * against the bracket of C-14, which exceeds 0.58 psi(w). */
static double pp_psi_diff(double w, double h, double r)
{
    const double delta = w * w / (r + h);
    return delta * atan2(1.0, r) - h * atan(delta / (1.0 + h * r));
}

/* ln(1 - t) for the quotient 1 - t = num / den with t = 1 - num/den known
 * too: log1p(-t) when t <= 1/2, else log(num/den) (then |ln| >= ln 2, so
 * the quotient's rounding is harmless). */
static double pp_log_one_minus(double t, double num, double den)
{
    return t <= 0.5 ? log1p(-t) : log(num / den);
}

/* The bracket of C-14, symmetric in (W, H); requires w <= h here:
 *   B = W atan(1/W) + H atan(1/H) - R atan(1/R)
 *       + 1/4 ln{ (1 + W^2)(1 + H^2) / (1 + R^2)
 *                 [W^2 (1 + R^2) / ((1 + W^2) R^2)]^(W^2)
 *                 [H^2 (1 + R^2) / ((1 + H^2) R^2)]^(H^2) },
 * R^2 = W^2 + H^2.  Evaluated as
 *   B = psi(W) - [psi(R) - psi(H)]
 *       + 1/4 [ log1p(W^2 H^2 / (1 + R^2))
 *               + W^2 ln(1 - H^2 / (R^2 (1 + W^2)))
 *               + H^2 ln(1 - W^2 / (R^2 (1 + H^2))) ],
 * using (1 + W^2)(1 + H^2) = 1 + R^2 + W^2 H^2 and
 * W^2 (1 + R^2) = (1 + W^2) R^2 - H^2 (and the same with W, H swapped).
 * Each piece is computed to a few ulps.  The pieces partly cancel, but
 * the sum of their magnitudes never exceeds 2.5 B (measured for W, H in
 * 1e-10..1e10; the largest loss, 1 + sqrt 2, is at W = H -> 0), and
 * B >= 0.58 psi(W). */
static double pp_bracket(double w, double h)
{
    const double w2 = w * w;
    const double h2 = h * h;
    const double r2 = w2 + h2;
    const double r = sqrt(r2);
    const double one_r2 = 1.0 + r2;
    const double tw = h2 / (r2 * (1.0 + w2));
    const double th = w2 / (r2 * (1.0 + h2));
    const double lw = pp_log_one_minus(tw, w2 * one_r2, (1.0 + w2) * r2);
    const double lh = pp_log_one_minus(th, h2 * one_r2, (1.0 + h2) * r2);
    const double logs = log1p(w2 * h2 / one_r2) + w2 * lw + h2 * lh;
    return w * atan2(1.0, w) - pp_psi_diff(w, h, r) + 0.25 * logs;
}

/* From the l x w rectangle to the l x h rectangle sharing the edge of
 * length l at a right angle ([H] C-14; [SH] App. C):  W = w/l, H = h/l,
 *     F = B(W, H) / (pi W),
 * B as in pp_bracket.  B is symmetric, so reciprocity l w F(l,w,h)
 * = l h F(l,h,w) holds to rounding. */
double rad_analytic_perpendicular_rectangles(double l, double w, double h)
{
    double x, y, b;
    if (!valid_length(l) || !valid_length(w) || !valid_length(h))
        return NAN;
    x = w / l;
    y = h / l;
    b = x <= y ? pp_bracket(x, y) : pp_bracket(y, x);
    return b / (M_PI * x);
}
