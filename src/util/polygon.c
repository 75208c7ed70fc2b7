/* polygon.c -- the polygon toolkit's measures and its guard against noisy
 * distances (polygon.h holds the plan, the distances and the clip).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include <math.h>

#include "util/polygon.h"
#include "util/vec.h"

/* A convex polygon meets a plane in at most two sign changes of its
 * vertices' distances (walking round it, zeros skipped).  Round-off in the
 * distances of a polygon thinner than it (a sliver, or a piece far from the
 * origin) can show more; then the distances are noise: the polygon is on
 * the plane as far as they can tell, and all are set to 0 (*lo = *hi = 0).
 * Every polygon the occlusion code clips goes through this first, so that
 * its output has at most n + 1 vertices and vertex counts cannot grow with
 * each cut (a noisy polygon once grew past its n + 1 buffer).
 * poly_settle_signs (polygon.h) calls this when the distances have both
 * signs. */
void poly_settle_signs_both(double *d, int n, double *lo, double *hi)
{
    int changes = 0, first = 0, last = 0;
    for (int k = 0; k < n; k++) {
        int s = d[k] > 0 ? 1 : d[k] < 0 ? -1 : 0;
        if (s == 0)
            continue;
        if (!first)
            first = s;
        else if (s != last)
            changes++;
        last = s;
    }
    changes += first != last; /* the wrap from the last vertex to the first */
    if (changes <= 2)
        return;
    for (int k = 0; k < n; k++)
        d[k] = 0;
    *lo = *hi = 0;
}

double poly_area(const rad_vec3 *p, int n)
{
    return 0.5 * v3_norm(v3_newell(p, n));
}

rad_vec3 poly_mean(const rad_vec3 *p, int n)
{
    rad_vec3 c = v3(0, 0, 0);
    for (int k = 0; k < n; k++)
        c = v3_add(c, p[k]);
    return v3_scale(c, 1.0 / n);
}

/* Differences from p[0] first: exact for nearby vertices far from the
 * origin. */
double poly_twist(const rad_vec3 *p, int n, rad_vec3 nrm)
{
    rad_vec3 c = v3(0, 0, 0);
    for (int k = 1; k < n; k++)
        c = v3_add(c, v3_sub(p[k], p[0]));
    c = v3_scale(c, 1.0 / n);
    double t = 0;
    for (int k = 0; k < n; k++)
        t = fmax(t, fabs(v3_dot(nrm, v3_sub(v3_sub(p[k], p[0]), c))));
    return t;
}

/* The foot f of c on the plane is inside when it is left of every edge
 * (counter-clockwise about nrm); then the distance is the height,
 * otherwise the nearest point of the boundary. */
double poly_point_distance(rad_vec3 c, const rad_vec3 *p, int n, rad_vec3 nrm)
{
    double h = v3_dot(nrm, v3_sub(c, p[0]));
    rad_vec3 f = v3_sub(c, v3_scale(nrm, h));
    int inside = 1;
    double best = HUGE_VAL;
    for (int k = 0; k < n; k++) {
        rad_vec3 a = p[k], b = p[(k + 1) % n], e = v3_sub(b, a);
        if (v3_dot(v3_cross(e, v3_sub(f, a)), nrm) < 0)
            inside = 0;
        double ee = v3_dot(e, e);
        double t = ee > 0 ? fmin(1.0, fmax(0.0, v3_dot(v3_sub(c, a), e) / ee)) : 0.0;
        best = fmin(best, v3_norm(v3_sub(c, v3_add(a, v3_scale(e, t)))));
    }
    return inside ? fabs(h) : best;
}
