/* test_smooth.c -- vertex radiosity (Goral et al. 1984, section 3).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * References: a field linear over a surface, sampled at element centres,
 * must be reproduced exactly at every vertex (interior mean, boundary and
 * corner extrapolation are all exact on linear fields); interior vertices
 * are the mean of their four elements by definition; values clamp at 0;
 * surfaces never mix.  Tolerance 1e-13: a few operations on O(1) values.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "../tap.h"

static double field(rad_vec3 p, int b)
{
    return 0.5 + 0.3 * p.x - 0.2 * p.y + 0.1 * b;
}

/* The two vertex rules on a 3 x 3 grid of hand-picked values (rows gj,
 * columns gi):   9 2 3 / 4 1 6 / 7 8 10.  Hand-computed:
 *   corner (0,0), corner rule  (7*9 - 2 - 4 - 1) / 4 = 56/4 = 14;
 *                 extrapolate  1.5*9 - 0.5*1 = 13;
 *   corner (3,3), corner rule  (7*10 - 8 - 6 - 1) / 4 = 55/4 = 13.75;
 *                 extrapolate  1.5*10 - 0.5*1 = 14.5;
 *   edge (1,0), both rules     (3*9 + 3*2 - 4 - 1) / 4 = 28/4 = 7;
 *   interior (1,1), both       (9 + 2 + 4 + 1) / 4 = 4,
 * and the corner rule's defining identity at (0,0): (14 + 4) / 2 = 9, the
 * one element there. */
static void test_vertex_rules(void)
{
    const char *text = "material w reflect 0.5\nquad w 0 0 0  3 0 0  3 3 0  0 3 0 mesh 3x3\n";
    static const double vals[9] = {9, 2, 3, 4, 1, 6, 7, 8, 10};
    rad_scene s;
    rad_mesh m;
    rad_error err;
    if (rad_scene_parse(&s, text, strlen(text), "t", &err) || rad_mesh_build(&m, &s, &err)) {
        tap_ok(0, "3x3 scene");
        return;
    }
    double B[27], Bc[48], Be[48];
    for (int e = 0; e < 9; e++)
        for (int b = 0; b < 3; b++)
            B[e + 9 * b] = vals[e];
    rad_smooth_vertices_rule(&m, B, Bc, RAD_VERTEX_CORNER);
    rad_smooth_vertices_rule(&m, B, Be, RAD_VERTEX_EXTRAPOLATE);
    /* vertex (gi, gj) is gj * 4 + gi */
    tap_ok(Bc[0] == 14 && Be[0] == 13, "corner (0,0): corner rule 14, extrapolation 13 (%g, %g)",
           Bc[0], Be[0]);
    tap_ok(Bc[15] == 13.75 && Be[15] == 14.5,
           "corner (3,3): corner rule 13.75, extrapolation 14.5 (%g, %g)", Bc[15], Be[15]);
    tap_ok(Bc[1] == 7 && Be[1] == 7, "edge (1,0): both rules 7 (%g, %g)", Bc[1], Be[1]);
    tap_ok(Bc[5] == 4 && Be[5] == 4, "interior (1,1): both rules 4 (%g, %g)", Bc[5], Be[5]);
    tap_ok((Bc[0] + Bc[5]) / 2 == 9, "corner rule: (B_corner + B_interior) / 2 = its element");
    tap_ok(Bc[16 + 0] == 14 && Bc[32 + 15] == 13.75, "every band alike");
    tap_ok(strcmp(rad_vertex_rule_name(RAD_VERTEX_CORNER), "corner") == 0 &&
               strcmp(rad_vertex_rule_name(RAD_VERTEX_EXTRAPOLATE), "extrapolate") == 0 &&
               rad_vertex_rule_name(7) == NULL,
           "rule names");
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

int main(void)
{
    test_vertex_rules();
    /* a sheared parallelogram meshed 5x4, a 1x3 strip, a 1x1 quad, and a
     * triangle; all in z = 0 (they never interact: smoothing only) */
    const char *text = "material w reflect 0.5\n"
                       "quad w 0 0 0  3 0 0  4 2 0  1 2 0 mesh 5x4\n"
                       "quad w 5 0 0  6 0 0  6 3 0  5 3 0 mesh 1x3\n"
                       "quad w 7 0 0  8 0 0  8 1 0  7 1 0\n"
                       "polygon w 3  9 0 0  10 0 0  9 1 0\n";
    rad_scene s;
    rad_mesh m;
    rad_error err;
    if (rad_scene_parse(&s, text, strlen(text), "t", &err) || rad_mesh_build(&m, &s, &err)) {
        tap_ok(0, "scene");
        return tap_done();
    }
    const int n = m.nelements, nv = m.nvertices;
    double *B = malloc(sizeof *B * (size_t)n * 3), *Bv = malloc(sizeof *Bv * (size_t)nv * 3);
    for (int e = 0; e < n; e++)
        for (int b = 0; b < 3; b++)
            B[e + (size_t)b * n] = field(m.elements[e].centroid, b);
    rad_smooth_vertices(&m, B, Bv);
    double worst = 0;
    for (int v = m.surface_vfirst[0]; v < m.surface_vfirst[1]; v++)
        for (int b = 0; b < 3; b++)
            worst = fmax(worst, fabs(Bv[v + (size_t)b * nv] - field(m.vertices[v], b)));
    tap_ok(worst < 1e-13, "5x4 parallelogram: a linear field is reproduced at every vertex (%.3g)", worst);
    /* the 1x3 strip: linear along its length is reproduced there too */
    worst = 0;
    for (int v = m.surface_vfirst[1]; v < m.surface_vfirst[2]; v++) {
        /* the field varies in y (along the strip) and in x (across it,
         * where one element cannot extrapolate: the element's x is used) */
        rad_vec3 p = m.vertices[v];
        p.x = 5.5;
        worst = fmax(worst, fabs(Bv[v] - field(p, 0)));
    }
    tap_ok(worst < 1e-13, "1x3 strip: linear along the strip, constant across (%.3g)", worst);
    /* interior vertex (2, 1) of the 5x4 grid: exact mean of its 4 elements,
     * for arbitrary (non-linear) values */
    for (int e = 0; e < n; e++)
        B[e] = (double)((e * 7919) % 13);
    rad_smooth_vertices(&m, B, Bv);
    int v = 1 * 6 + 2; /* gj = 1, gi = 2 */
    double mean = (B[0 * 5 + 1] + B[0 * 5 + 2] + B[1 * 5 + 1] + B[1 * 5 + 2]) / 4;
    tap_ok(Bv[v] == mean, "interior vertex = mean of its four elements (%g = %g)", Bv[v], mean);
    /* boundary vertex (2, 0): (3 B1 + 3 B2 - B3 - B4) / 4, clamped */
    double bnd = (3 * B[1] + 3 * B[2] - B[5 + 1] - B[5 + 2]) / 4;
    tap_ok(fabs(Bv[2] - fmax(bnd, 0)) < 1e-15, "boundary vertex formula (%g, expected %g)", Bv[2], fmax(bnd, 0));
    /* corner (0, 0): 1.5 B_corner - 0.5 B_diagonal, clamped */
    double cor = 1.5 * B[0] - 0.5 * B[1 * 5 + 1];
    tap_ok(fabs(Bv[0] - fmax(cor, 0)) < 1e-15, "corner vertex formula (%g, expected %g)", Bv[0], fmax(cor, 0));
    int clamped = 1;
    for (int k = 0; k < nv; k++)
        clamped &= Bv[k] >= 0;
    tap_ok(clamped, "no negative vertex value (clamped at 0)");
    /* surfaces never mix: the 1x1 quad and the triangle keep their value */
    int last = n - 1, quad = n - 2;
    int own = 1;
    for (int k = 0; k < 4; k++)
        own &= Bv[m.vindex[m.elements[quad].first + k]] == B[quad];
    for (int k = 0; k < 3; k++)
        own &= Bv[m.vindex[m.elements[last].first + k]] == B[last];
    tap_ok(own, "single-element surfaces take their element's value");
    free(B);
    free(Bv);
    rad_mesh_free(&m);
    rad_scene_free(&s);
    return tap_done();
}
