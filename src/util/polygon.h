/* polygon.h -- convex polygons in space: signed distances from a plane,
 * clipping by a half-space, area, mean, twist, distance from a point.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * One toolkit for the form factors (formfactor.c: each element clipped to
 * the front of the other's plane), the hidden-surface code (occlusion
 * pieces cut by shaft, cone and event planes) and the renderer (faces
 * clipped to the near plane).  A polygon is an array of n vertices in
 * order round its boundary; "convex" and "planar" hold to the callers'
 * tolerances, never exactly, and those tolerances belong to the callers:
 * every function here takes them as arguments and has none of its own.
 *
 * Clipping (Sutherland & Hodgman, "Reentrant polygon clipping", CACM 17,
 * 1974) works from signed distances d[k] of the vertices, which the
 * caller computes (poly_distances, snapping to 0 within its tolerance, or
 * its own) so that what counts as "on the plane" is the caller's.  The
 * part where sign * d >= 0 is kept; an edge whose ends lie strictly on
 * opposite sides is cut at a + t (b - a), t = d_a / (d_a - d_b), unless the
 * caller supplies its own crossing.  A convex K-gon meets a plane in at
 * most two sign changes, so its clip has at most K + 1 vertices (each
 * crossing adds a vertex and at most one crossing per side fails to drop
 * one).  Distances that round-off has made noisy can show more changes;
 * poly_settle_signs reduces them to "on the plane" first.  Buffers are
 * sized by contract: the caller states the capacity of `out`, and the
 * clipper never writes past it; it returns -1 instead of a count when
 * the clip would not fit (no polygon: every caller then treats the piece
 * as gone, since it was not convex as far as its distances could tell).
 *
 * The hot primitives (the distances and the clip) are inline here: the
 * occlusion code calls them once per cutting plane and piece, millions of
 * times a fill.
 */
#ifndef RAD_POLYGON_H
#define RAD_POLYGON_H

#include <math.h>

#include "radiosity/base.h"
#include "util/vec.h"

/* How a vertex on the plane (d == 0 once the caller has snapped) is cut. */
typedef enum poly_touch {
    POLY_TOUCH_KEEPS = 0,   /* kept, and an edge is cut only where the sign
                               changes strictly: a polygon that touches the
                               plane loses nothing and gains no vertex (form
                               factors and occlusion, whose distances are
                               snapped to 0 within their tolerance) */
    POLY_TOUCH_CUTS         /* kept, and an edge from it to a vertex behind
                               (or back) is cut too, at the vertex itself: a
                               repeated vertex, up to 2 n in all (the
                               renderer's near plane, where d = z - znear
                               is exact and nothing is snapped) */
} poly_touch;

/* The point where edge a -> b crosses the plane, da and db the ends'
 * signed distances (of opposite sides, or one 0 under POLY_TOUCH_CUTS). */
typedef rad_vec3 poly_crossing(rad_vec3 a, rad_vec3 b, double da, double db, const void *ctx);

/* What side of the plane a clip keeps and how it cuts. */
typedef struct poly_cut {
    double sign;            /* keep sign * d >= 0 (+1 or -1) */
    poly_touch touch;
    poly_crossing *crossing;/* NULL: a + t (b - a), t = d_a / (d_a - d_b) */
    const void *ctx;        /* handed to crossing */
} poly_cut;

/* Signed distances d[k] = nrm . (p[k] - a), snapped to 0 within tol; the
 * smallest and largest go to *lo, *hi (n >= 1). */
static inline void poly_distances(const rad_vec3 *p, int n, rad_vec3 nrm, rad_vec3 a,
                                  double tol, double *d, double *lo, double *hi)
{
    double mn = HUGE_VAL, mx = -HUGE_VAL;
    for (int k = 0; k < n; k++) {
        double s = v3_dot(nrm, v3_sub(p[k], a));
        if (fabs(s) <= tol)
            s = 0;
        d[k] = s;
        mn = s < mn ? s : mn; /* not fmin: a libm call in the hottest loop */
        mx = s > mx ? s : mx;
    }
    *lo = mn;
    *hi = mx;
}

/* The part of p (n vertices, signed distances d) that `cut` keeps, into
 * out (room for cap vertices; n + 1 suffices under POLY_TOUCH_KEEPS with
 * at most two sign changes, 2 n always).  Returns the vertex count, or -1
 * when it would exceed cap (nothing past out[cap - 1] is written). */
static inline int poly_clip(const rad_vec3 *p, const double *d, int n, const poly_cut *cut,
                            rad_vec3 *out, int cap)
{
    int m = 0;
    for (int k = 0; k < n; k++) {
        const int k1 = k + 1 < n ? k + 1 : 0;
        const double a = cut->sign * d[k], b = cut->sign * d[k1];
        const int cross = cut->touch == POLY_TOUCH_CUTS ? (a >= 0) != (b >= 0)
                                                        : (a > 0 && b < 0) || (a < 0 && b > 0);
        if (m + (a >= 0) + cross > cap)
            return -1;
        if (a >= 0)
            out[m++] = p[k];
        if (cross)
            out[m++] = cut->crossing ? cut->crossing(p[k], p[k1], d[k], d[k1], cut->ctx)
                                     : v3_lerp(p[k], p[k1], a / (a - b));
    }
    return m;
}

/* Keep sign * d >= 0, vertices on the plane kept and not cut (the common
 * cut of the form factors and the occlusion code). */
static inline int poly_clip_side(const rad_vec3 *p, const double *d, int n, double sign,
                                 rad_vec3 *out, int cap)
{
    const poly_cut cut = {sign, POLY_TOUCH_KEEPS, NULL, NULL};
    return poly_clip(p, d, n, &cut, out, cap);
}

/* The plane through edge k of p (from p[k] to p[k + 1], n vertices) and
 * the point q: its unit normal e x w / |e x w| (e the edge, w = q - p[k])
 * into *nrm, and 1; 0 when q is on the edge's line as far as round-off
 * can tell (|e x w| <= 1e-12 |e| |w|).  The face planes of the hull of two
 * convex polygons, and the planes where what one hides of the other
 * changes, are all of this kind. */
static inline int poly_edge_plane(const rad_vec3 *p, int n, int k, rad_vec3 q, rad_vec3 *nrm)
{
    const rad_vec3 a = p[k], e = v3_sub(p[(k + 1) % n], a), w = v3_sub(q, a);
    const rad_vec3 c = v3_cross(e, w);
    const double len = v3_norm(c);
    if (!(len > 1e-12 * v3_norm(e) * v3_norm(w)))
        return 0;
    *nrm = v3_scale(c, 1.0 / len);
    return 1;
}

/* When the distances d (n of them, smallest *lo, largest *hi) change sign
 * more than twice round the polygon, they are round-off: all are set to 0
 * and *lo = *hi = 0 (the polygon is on the plane as far as they can
 * tell), so that a clip under POLY_TOUCH_KEEPS has at most n + 1 vertices. */
void poly_settle_signs_both(double *d, int n, double *lo, double *hi);
static inline void poly_settle_signs(double *d, int n, double *lo, double *hi)
{
    if (*lo >= 0 || *hi <= 0)
        return; /* one side: no change of sign at all (inline: the usual
                   case in the occlusion code's hottest loops) */
    poly_settle_signs_both(d, n, lo, hi);
}

/* Area (half the length of Newell's vector, vec.h). */
double poly_area(const rad_vec3 *p, int n);
/* The mean of the vertices (n >= 1). */
rad_vec3 poly_mean(const rad_vec3 *p, int n);
/* Largest distance of the vertices from the plane with unit normal nrm
 * through their mean (0 for a planar polygon). */
double poly_twist(const rad_vec3 *p, int n, rad_vec3 nrm);
/* Distance from point c to the convex polygon p (unit normal nrm). */
double poly_point_distance(rad_vec3 c, const rad_vec3 *p, int n, rad_vec3 nrm);

#endif /* RAD_POLYGON_H */
