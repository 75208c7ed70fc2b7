/* vec.h -- small inline 3-vector arithmetic shared by the numerical modules.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 * Also the home of RAD_PI.
 */
#ifndef RAD_VEC_H
#define RAD_VEC_H

#include <math.h>

#include "radiosity/base.h"

/* pi, to more digits than a double holds (RAD_PI_LONG: than a long
 * double on x86-64, 64 bits of mantissa): the one definition every
 * numerical module uses (M_PI is not ISO C). */
#define RAD_PI 3.14159265358979323846
#define RAD_PI_LONG 3.141592653589793238462643383279502884L

static inline rad_vec3 v3(double x, double y, double z)
{
    rad_vec3 r = {x, y, z};
    return r;
}
static inline rad_vec3 v3_add(rad_vec3 a, rad_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline rad_vec3 v3_sub(rad_vec3 a, rad_vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline rad_vec3 v3_scale(rad_vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline double v3_dot(rad_vec3 a, rad_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline rad_vec3 v3_cross(rad_vec3 a, rad_vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double v3_maxabs(rad_vec3 a)
{
    /* comparisons, not fmax: this sits in the pair kernel's hot path and
     * fmax is a libm call unless NaNs are excluded */
    double x = fabs(a.x), y = fabs(a.y), z = fabs(a.z);
    double m = x > y ? x : y;
    return m > z ? m : z;
}
/* Euclidean length, finite for every finite vector: the squares of
 * components beyond 1.3e154 overflow and those below 1.5e-154 underflow
 * (a square of side 1e-150 has a Newell vector 2e-300 long, whose square
 * is 0 in doubles), so
 * outside the range where |a|^2 is a normal double the vector is first
 * scaled by its largest component (as hypot does; Blue 1978, ACM TOMS 4).
 * The common case costs two comparisons. */
static inline double v3_norm(rad_vec3 a)
{
    const double d = v3_dot(a, a);
    if (d >= 0x1p-1000 && d <= 0x1p1000)
        return sqrt(d);
    const double m = v3_maxabs(a);
    if (!(m > 0) || isinf(m))
        return d == d ? m : d; /* 0, inf, or NaN as it is */
    const rad_vec3 u = v3(a.x / m, a.y / m, a.z / m);
    return m * sqrt(v3_dot(u, u));
}
/* Bounding box of p[0..n), n >= 1. */
static inline void v3_bounds(const rad_vec3 *p, int n, rad_vec3 *lo, rad_vec3 *hi)
{
    *lo = *hi = p[0];
    for (int k = 1; k < n; k++) {
        *lo = v3(fmin(lo->x, p[k].x), fmin(lo->y, p[k].y), fmin(lo->z, p[k].z));
        *hi = v3(fmax(hi->x, p[k].x), fmax(hi->y, p[k].y), fmax(hi->z, p[k].z));
    }
}
/* Squared distance between two boxes (0 if they meet).  Comparisons, not
 * fmax: the pair kernel calls it for every pair. */
static inline double v3_box_gap2(rad_vec3 alo, rad_vec3 ahi, rad_vec3 blo, rad_vec3 bhi)
{
    const double lo[3] = {blo.x - ahi.x, blo.y - ahi.y, blo.z - ahi.z};
    const double hi[3] = {alo.x - bhi.x, alo.y - bhi.y, alo.z - bhi.z};
    double g2 = 0;
    for (int k = 0; k < 3; k++) {
        const double g = lo[k] > hi[k] ? lo[k] : hi[k];
        g2 += g > 0 ? g * g : 0;
    }
    return g2;
}
/* a + t (b - a) */
static inline rad_vec3 v3_lerp(rad_vec3 a, rad_vec3 b, double t)
{
    return v3(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z));
}

/* Newell's vector of a polygon: twice its area times its unit normal
 * (Newell's method, e.g. Sutherland, Sproull & Schumacher 1974).  Computed
 * relative to the first vertex to keep round-off independent of where the
 * polygon sits. */
static inline rad_vec3 v3_newell(const rad_vec3 *p, int n)
{
    rad_vec3 s = v3(0, 0, 0);
    for (int k = 1; k + 1 < n; k++)
        s = v3_add(s, v3_cross(v3_sub(p[k], p[0]), v3_sub(p[k + 1], p[0])));
    return s;
}

#endif /* RAD_VEC_H */
