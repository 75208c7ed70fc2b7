/* hcdelta.c -- the hemicube's delta form factors, one table per resolution.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The hemicube (Cohen & Greenberg 1985) stands on a differential area dA_i
 * with its top face at height 1 and its side faces from height 0 to 1,
 * all of half-width 1.  A pixel of area dA at the point p of a face sees,
 * through the centre, the form factor
 *
 *     dF = cos(theta_i) cos(theta_p) / (pi r^2) dA,
 *
 * theta_i the angle of p from the normal of dA_i, theta_p the angle at the
 * pixel between the ray and the face's normal, r = |p| (Cohen & Greenberg
 * 1985, the delta form factor; Goral et al. 1984, eq. 2 for one small
 * area).  On the top face p = (u, v, 1): cos(theta_i) = cos(theta_p) = 1/r,
 * r^2 = u^2 + v^2 + 1, so
 *
 *     dF_top  = dA / (pi (u^2 + v^2 + 1)^2)                       (top)
 *
 * and on a side face p = (u, 1, w), w the height above the element's
 * plane: cos(theta_i) = w/r, cos(theta_p) = 1/r, r^2 = u^2 + w^2 + 1,
 *
 *     dF_side = w dA / (pi (u^2 + w^2 + 1)^2)                     (side)
 *
 * (Cohen & Greenberg 1985, the top and side face formulas; Cohen & Wallace,
 * "Radiosity and Realistic Image Synthesis", 1993, section 4.9.2).  Each
 * pixel's delta is the kernel at its centre times its area: the midpoint
 * rule for the integral of the kernel over the five faces, which is
 * exactly 1 (all the hemisphere is seen through them, Nusselt's analogue).
 * The raw sum therefore misses 1 by the midpoint rule's error, of order
 * R^-2: measured, sum - 1 = 0.542 R^-2 (R = 64: 1.3e-4), and it falls by 4
 * per doubling (tests/unit/hemicube/test_hemicube.c checks both).
 *
 * The table divides every delta by that sum, computed in long double, so
 * that the deltas sum to 1 to round-off.  That is honest: the scale
 * changes each delta by the same factor 1 - O(R^-2), well below the
 * aliasing error of O(R^-1) that the pixels make at every edge of a
 * receiver (hemicube.c), and a closed scene's rows then sum to 1 as its
 * contour rows do, so the hemicube conserves energy as the 1985 paper's
 * scenes did.  raw_sum keeps the sum before the division for the tests.
 */
#include <config.h>

#include <stdlib.h>

#include "hemicube/hemicube.h"
#include "util/util.h"

double radi_hc_delta_top(double u, double v, double dA)
{
    /* Cohen & Greenberg 1985, top face: dA / (pi (u^2 + v^2 + 1)^2) */
    const double r2 = u * u + v * v + 1;
    return dA / (RAD_PI * r2 * r2);
}

double radi_hc_delta_side(double u, double w, double dA)
{
    /* Cohen & Greenberg 1985, side face: w dA / (pi (u^2 + w^2 + 1)^2) */
    const double r2 = u * u + w * w + 1;
    return w * dA / (RAD_PI * r2 * r2);
}

void radi_hc_table_free(rad_hc_table *t)
{
    if (!t)
        return;
    free(t->top);
    free(t->side);
    t->top = t->side = NULL;
}

/* The raw deltas into t; returns their sum over the five faces (the four
 * sides alike), in long double. */
static long double fill_raw(rad_hc_table *t)
{
    const int R = t->res, H = R / 2;
    const double dA = (2.0 / R) * (2.0 / R);
    long double sum = 0;
    for (int y = 0; y < R; y++)
        for (int x = 0; x < R; x++) {
            const double u = -1 + (2.0 * x + 1) / R, v = -1 + (2.0 * y + 1) / R;
            t->top[(size_t)y * R + x] = radi_hc_delta_top(u, v, dA);
            sum += t->top[(size_t)y * R + x];
        }
    for (int y = 0; y < H; y++)
        for (int x = 0; x < R; x++) {
            const double u = -1 + (2.0 * x + 1) / R, w = 1 - (2.0 * y + 1) / R;
            t->side[(size_t)y * R + x] = radi_hc_delta_side(u, w, dA);
            sum += 4.0L * t->side[(size_t)y * R + x];
        }
    return sum;
}

rad_status radi_hc_table_make(rad_hc_table *t, int res, rad_error *err)
{
    t->top = t->side = NULL;
    t->res = res;
    if (res < 2 || res > RAD_HEMICUBE_MAX || res % 2 != 0)
        return radi_fail(err, RAD_ERR_INVALID,
                        "the hemicube's resolution must be even, from 2 to %d, not %d",
                        RAD_HEMICUBE_MAX, res);
    const size_t R = (size_t)res;
    t->top = malloc(sizeof *t->top * R * R);
    t->side = malloc(sizeof *t->side * R * (R / 2));
    if (!t->top || !t->side) {
        radi_hc_table_free(t);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a hemicube of %d", res);
    }
    t->raw_sum = fill_raw(t);
    const long double scale = 1.0L / t->raw_sum;
    for (size_t k = 0; k < R * R; k++)
        t->top[k] = (double)(t->top[k] * scale);
    for (size_t k = 0; k < R * (R / 2); k++)
        t->side[k] = (double)(t->side[k] * scale);
    return RAD_OK;
}
