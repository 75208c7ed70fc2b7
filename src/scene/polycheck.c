/* polycheck.c -- is a polygon one the program can use?
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Every reader (scene.c, objread.c, vs3read.c) checks each surface here
 * before it adds it to the scene: planar, convex, simple, of non-zero
 * area and of a size whose areas are normal doubles.  The messages are
 * "FILE:LINE: what is wrong", naming the input line.
 *
 * Geometric tolerances, stated once (D is the polygon's bounding-box
 * diagonal, so they scale with the polygon and not with where it sits):
 *   - planar:   every vertex within RAD_PLANAR_TOL * D of the mean plane;
 *   - convex:   no turn backwards by more than RAD_TURN_TOL radians;
 *   - area:     area above RAD_AREA_TOL * D^2;
 *   - distinct: consecutive vertices more than RAD_AREA_TOL * D apart.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "radiosity/base.h"
#include "scene/polycheck.h"
#include "util/util.h"

#define RAD_PLANAR_TOL 1e-6
#define RAD_TURN_TOL 1e-9
#define RAD_AREA_TOL 1e-12
#define RAD_SELFX_MAX 4096  /* O(n^2) self-intersection diagnosis up to this n */

/* ---- polygon validation ------------------------------------------------- */

/* Do segments p0p1 and q0q1 of the plane (2-D) properly cross or touch? */
static int segments_meet_2d(const double *p0, const double *p1, const double *q0,
                            const double *q1)
{
    double d1 = (p1[0] - p0[0]) * (q0[1] - p0[1]) - (p1[1] - p0[1]) * (q0[0] - p0[0]);
    double d2 = (p1[0] - p0[0]) * (q1[1] - p0[1]) - (p1[1] - p0[1]) * (q1[0] - p0[0]);
    double d3 = (q1[0] - q0[0]) * (p0[1] - q0[1]) - (q1[1] - q0[1]) * (p0[0] - q0[0]);
    double d4 = (q1[0] - q0[0]) * (p1[1] - q0[1]) - (q1[1] - q0[1]) * (p1[0] - q0[0]);
    return ((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) &&
           ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0));
}

/* Do two non-adjacent edges of the polygon meet?  O(n^2): only called on
 * polygons that already failed the cheap convexity test. */
static int polygon_self_intersects(const rad_vec3 *p, int n, rad_vec3 nrm)
{
    rad_vec3 u = fabs(nrm.x) < 0.9 ? v3(1, 0, 0) : v3(0, 1, 0);
    u = v3_cross(nrm, u);
    rad_vec3 w = v3_cross(nrm, u);
    double *q = malloc(2 * sizeof *q * (size_t)n);
    int hit = 0;
    if (!q)
        return 0;
    for (int k = 0; k < n; k++) {
        q[2 * k] = v3_dot(v3_sub(p[k], p[0]), u);
        q[2 * k + 1] = v3_dot(v3_sub(p[k], p[0]), w);
    }
    for (int a = 0; a < n && !hit; a++)
        for (int b = a + 2; b < n && !hit; b++) {
            if (a == 0 && b == n - 1)
                continue; /* adjacent through the closing edge */
            hit = segments_meet_2d(q + 2 * a, q + 2 * ((a + 1) % n), q + 2 * b,
                                   q + 2 * ((b + 1) % n));
        }
    free(q);
    return hit;
}

/* The largest cross product of consecutive edges: a normal for polygons
 * whose Newell vector vanishes (a symmetric bow-tie). */
static rad_vec3 largest_turn_normal(const rad_vec3 *p, int n)
{
    rad_vec3 best = v3(0, 0, 0);
    for (int k = 0; k < n; k++) {
        rad_vec3 e0 = v3_sub(p[k], p[(k + n - 1) % n]);
        rad_vec3 e1 = v3_sub(p[(k + 1) % n], p[k]);
        rad_vec3 c = v3_cross(e0, e1);
        if (v3_dot(c, c) > v3_dot(best, best))
            best = c;
    }
    return best;
}

rad_status radi_polygon_check(const rad_vec3 *p, int n, const char *what,
                             const char *file, int line, rad_error *err)
{
    rad_vec3 lo, hi;
    v3_bounds(p, n, &lo, &hi);
    double diam = v3_norm(v3_sub(hi, lo));
    if (diam > 0 && !(diam >= 0x1p-510 && diam <= 0x1p510)) /* areas: normal doubles (mesh.c) */
        return radi_fail_at(err, file, line, "%s is %.3g across, outside the sizes this program accepts (%.3g to %.3g, so that areas are normal doubles); rescale the scene", what, diam, 0x1p-510, 0x1p510);
    if (!(diam > 0) || !isfinite(diam))
        return radi_fail_at(err, file, line, "%s has zero area (all vertices coincide)", what);
    for (int k = 0; k < n; k++)
        if (v3_norm(v3_sub(p[(k + 1) % n], p[k])) <= RAD_AREA_TOL * diam)
            return radi_fail_at(err, file, line, "%s has a repeated vertex (vertices %d and %d)", what,
                           k + 1, (k + 1) % n + 1);
    rad_vec3 nw = v3_newell(p, n);
    double twice_area = v3_norm(nw);
    rad_vec3 nrm = twice_area > 0 ? nw : largest_turn_normal(p, n);
    if (!(v3_norm(nrm) > RAD_AREA_TOL * diam * diam))
        return radi_fail_at(err, file, line, "%s has zero area (its vertices are colinear)", what);
    nrm = v3_scale(nrm, 1.0 / v3_norm(nrm));

    /* Planarity: distance of each vertex from the plane through the mean. */
    rad_vec3 mean = v3(0, 0, 0);
    for (int k = 0; k < n; k++)
        mean = v3_add(mean, v3_scale(v3_sub(p[k], p[0]), 1.0 / n));
    mean = v3_add(mean, p[0]);
    for (int k = 0; k < n; k++) {
        double off = fabs(v3_dot(v3_sub(p[k], mean), nrm));
        if (off > RAD_PLANAR_TOL * diam)
            return radi_fail_at(err, file, line,
                           "%s is not planar (vertex %d is %.3g off its plane; "
                           "tolerance %g of its size)",
                           what, k + 1, off, RAD_PLANAR_TOL);
    }

    /* Convexity and simplicity: every turn is to the left (about the
     * normal) and the turns add up to one full revolution. */
    double total = 0;
    int reflex = -1;
    for (int k = 0; k < n; k++) {
        rad_vec3 e0 = v3_sub(p[k], p[(k + n - 1) % n]);
        rad_vec3 e1 = v3_sub(p[(k + 1) % n], p[k]);
        double turn = atan2(v3_dot(v3_cross(e0, e1), nrm), v3_dot(e0, e1));
        if (turn < -RAD_TURN_TOL && reflex < 0)
            reflex = k;
        total += turn;
    }
    if (reflex >= 0 || total > 2 * RAD_PI + 1e-6) {
        if (n <= RAD_SELFX_MAX && polygon_self_intersects(p, n, nrm))
            return radi_fail_at(err, file, line, "%s is self-intersecting", what);
        if (reflex >= 0)
            return radi_fail_at(err, file, line, "%s is not convex (at vertex %d)", what, reflex + 1);
        return radi_fail_at(err, file, line, "%s is self-intersecting (it winds more than once)", what);
    }
    if (!(0.5 * twice_area > RAD_AREA_TOL * diam * diam))
        return radi_fail_at(err, file, line, "%s has zero area", what);
    return RAD_OK;
}
