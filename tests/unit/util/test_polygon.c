/* test_polygon.c -- the polygon toolkit (src/util/polygon.h): clipping by a
 * half-space under both on-plane rules, the capacity contract, the guard
 * against noisy distances, and the measures.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * References are worked by hand on unit squares and a regular hexagon
 * (exact in binary: the expected points are sums of halves), so the
 * comparisons are exact unless stated.
 */
#include <config.h>

#include <math.h>
#include <string.h>

#include "util/polygon.h"
#include "../tap.h"
#include "util/vec.h"

static const rad_vec3 SQUARE[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

static int same(rad_vec3 a, rad_vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* The square cut by x = 0.5 keeps its right half, both ways round. */
static void test_halves(void)
{
    double d[4], lo, hi;
    rad_vec3 out[5];
    poly_distances(SQUARE, 4, v3(1, 0, 0), v3(0.5, 0, 0), 0, d, &lo, &hi);
    tap_ok(lo == -0.5 && hi == 0.5, "distances from x = 0.5: -0.5 .. 0.5");
    int m = poly_clip_side(SQUARE, d, 4, 1.0, out, 5);
    tap_ok(m == 4 && fabs(poly_area(out, m) - 0.5) <= 1e-15 && same(out[0], v3(0.5, 0, 0)) &&
               same(out[3], v3(0.5, 1, 0)),
           "the right half: 4 vertices, area 0.5 (m = %d)", m);
    m = poly_clip_side(SQUARE, d, 4, -1.0, out, 5);
    tap_ok(m == 4 && same(out[0], v3(0, 0, 0)) && fabs(poly_area(out, m) - 0.5) <= 1e-15,
           "sign -1: the left half (m = %d)", m);
}

/* A vertex on the plane: kept and not cut under POLY_TOUCH_KEEPS, kept
 * and cut again (a repeated vertex) under POLY_TOUCH_CUTS. */
static void test_touch(void)
{
    /* the plane x + y = 1 through vertices 1 and 3; keep x + y <= 1 */
    const double d[4] = {1, 0, -1, 0};
    rad_vec3 out[8];
    int m = poly_clip_side(SQUARE, d, 4, 1.0, out, 5);
    tap_ok(m == 3 && same(out[0], SQUARE[0]) && same(out[1], SQUARE[1]) &&
               same(out[2], SQUARE[3]),
           "touch keeps: the triangle 0, 1, 3 (m = %d)", m);
    const poly_cut cut = {1.0, POLY_TOUCH_CUTS, NULL, NULL};
    m = poly_clip(SQUARE, d, 4, &cut, out, 8);
    tap_ok(m == 5 && same(out[1], SQUARE[1]) && same(out[2], SQUARE[1]),
           "touch cuts: vertex 1 repeated (m = %d)", m);
}

/* A hexagon whose distances change sign six times (noise): the clip
 * would have 9 vertices, more than n + 1 = 7; with room for 7 it returns
 * -1 and writes nothing past out[6].  poly_settle_signs makes the
 * distances 0, and the clip keeps the hexagon whole. */
static void test_capacity(void)
{
    rad_vec3 hex[6], out[10];
    for (int k = 0; k < 6; k++)
        hex[k] = v3(cos(k * RAD_PI / 3), sin(k * RAD_PI / 3), 0);
    double d[6] = {1e-17, -1e-17, 1e-17, -1e-17, 1e-17, -1e-17}, lo = -1e-17, hi = 1e-17;
    const rad_vec3 canary = v3(7, 7, 7);
    for (int k = 0; k < 10; k++)
        out[k] = canary;
    int m = poly_clip_side(hex, d, 6, 1.0, out, 7);
    int clean = 1;
    for (int k = 7; k < 10; k++)
        clean &= same(out[k], canary);
    tap_ok(m == -1 && clean, "6 sign changes, room for 7: -1, nothing written past (m = %d)", m);
    m = poly_clip_side(hex, d, 6, 1.0, out, 10);
    tap_ok(m == 9, "with room for 9 the noisy clip has 9 vertices (m = %d)", m);
    poly_settle_signs(d, 6, &lo, &hi);
    m = poly_clip_side(hex, d, 6, 1.0, out, 7);
    tap_ok(lo == 0 && hi == 0 && m == 6, "settled: all on the plane, the hexagon kept (m = %d)", m);
    double d2[4] = {1, 1, -1, -1};
    lo = -1;
    hi = 1;
    poly_settle_signs(d2, 4, &lo, &hi);
    tap_ok(d2[0] == 1 && d2[3] == -1 && lo == -1, "two sign changes are left alone");
}

static void test_measures(void)
{
    rad_vec3 twisted[4] = {{0, 0, 0}, {1, 0, 1e-6}, {1, 1, 0}, {0, 1, 1e-6}};
    tap_ok(poly_twist(SQUARE, 4, v3(0, 0, 1)) == 0 &&
               fabs(poly_twist(twisted, 4, v3(0, 0, 1)) - 5e-7) <= 1e-18,
           "twist: 0 for the square, 5e-7 for corners 1e-6 off alternately");
    rad_vec3 c = poly_mean(SQUARE, 4);
    tap_ok(same(c, v3(0.5, 0.5, 0)), "mean of the square");
    tap_ok(poly_point_distance(v3(0.5, 0.5, 2), SQUARE, 4, v3(0, 0, 1)) == 2 &&
               fabs(poly_point_distance(v3(2, 0.5, 0), SQUARE, 4, v3(0, 0, 1)) - 1) <= 1e-15,
           "point distance: above the inside, beside an edge");
    rad_vec3 n;
    tap_ok(poly_edge_plane(SQUARE, 4, 0, v3(0, 0, 1), &n) && same(n, v3(0, -1, 0)) &&
               !poly_edge_plane(SQUARE, 4, 0, v3(3, 0, 0), &n),
           "edge plane: through edge 0 and a point; none for a point on its line");
}

int main(void)
{
    test_halves();
    test_touch();
    test_capacity();
    test_measures();
    return tap_done();
}
