/* test_meshtri.c -- polygons cut into equal triangles (src/mesh/meshtri.c).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * References, each independent of the code under test: a triangle cut n
 * per edge is n^2 triangles of area A/n^2 (similar triangles, ratio 1/n)
 * on (n+1)(n+2)/2 lattice points; a K-gon is K such fans around its
 * centroid; the pieces tile the polygon exactly when every inner edge is
 * used by two elements in opposite directions and the outline's edges by
 * one (a watertight, consistently oriented mesh: Euler's V - E + F = 1);
 * each piece turns as the polygon does (its Newell vector along the
 * surface normal); the mean of the six triangles around an inner lattice
 * vertex reproduces a linear field there (their centroids are symmetric
 * about it).  Tolerances 1e-14 relative: a few roundings of O(1) values.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/scene.h"
#include "util/util.h"
#include "../tap.h"

static rad_scene load(const char *text)
{
    rad_scene s;
    rad_error err;
    if (rad_scene_parse(&s, text, strlen(text), "t.scene", &err) != RAD_OK) {
        printf("# %s\n", err.message);
        exit(1);
    }
    return s;
}

/* Every edge of every element of surface s: used once in each direction
 * inside, once on the outline; returns the outline's edge count, or -1
 * when some edge breaks the rule. */
static int boundary_edges(const rad_mesh *m, int s)
{
    int nb = 0;
    for (int e = m->surface_first[s]; e < m->surface_first[s + 1]; e++) {
        const rad_element *el = &m->elements[e];
        for (int k = 0; k < el->nverts; k++) {
            const int a = m->vindex[el->first + k], b = m->vindex[el->first + (k + 1) % el->nverts];
            int same = 0, back = 0;
            for (int f = m->surface_first[s]; f < m->surface_first[s + 1]; f++) {
                const rad_element *g = &m->elements[f];
                for (int j = 0; j < g->nverts; j++) {
                    const int c = m->vindex[g->first + j], d = m->vindex[g->first + (j + 1) % g->nverts];
                    same += c == a && d == b;
                    back += c == b && d == a;
                }
            }
            if (same != 1 || back > 1)
                return -1;
            nb += back == 0;
        }
    }
    return nb;
}

static int distinct_vertices(const rad_mesh *m, int s)
{
    for (int v = m->surface_vfirst[s]; v < m->surface_vfirst[s + 1]; v++)
        for (int w = v + 1; w < m->surface_vfirst[s + 1]; w++)
            if (v3_maxabs(v3_sub(m->vertices[v], m->vertices[w])) < 1e-12)
                return 0;
    return 1;
}

static int turns_with(const rad_mesh *m, int s)
{
    for (int e = m->surface_first[s]; e < m->surface_first[s + 1]; e++) {
        rad_vec3 p[3];
        for (int k = 0; k < 3; k++)
            p[k] = rad_mesh_vertex(m, e, k);
        if (v3_dot(v3_newell(p, 3), m->elements[e].normal) <= 0)
            return 0;
    }
    return 1;
}

static void test_triangle(void)
{
    rad_scene s = load("material w reflect 0.5\npolygon w 3  0 0 0  2 0 0  0.5 1.5 0\n");
    rad_mesh m;
    rad_error err;
    rad_scene_set_mesh(&s, 3, 2);
    tap_ok(rad_mesh_build(&m, &s, &err) == RAD_OK, "a triangle with --mesh 3x2 meshes");
    tap_ok(m.nelements == 9 && m.nvertices == 10 && rad_scene_element_count(&s) == 9,
           "3 per edge: 9 triangles on 10 lattice points (%d, %d)", m.nelements, m.nvertices);
    int equal = 1;
    for (int e = 0; e < m.nelements; e++)
        equal &= fabs(m.elements[e].area - 1.5 / 9) <= 1e-15;
    tap_ok(equal, "each of area A/9 = 1/6");
    tap_ok(distinct_vertices(&m, 0), "no lattice point made twice: the elements share them");
    tap_ok(boundary_edges(&m, 0) == 9, "watertight: inner edges used both ways, 9 outline edges");
    tap_ok(turns_with(&m, 0), "every piece turns as the triangle does");
    rad_vec3 out[8];
    tap_ok(radi_mesh_is_fan(&m, 0) && radi_mesh_outline(&m, 0, out) == 3 &&
               out[1].x == 2 && out[2].y == 1.5,
           "its outline is the triangle's three corners, in order");
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

static void test_hexagon_and_smoothing(void)
{
    /* a regular hexagon of circumradius 1: area 3 sqrt(3) / 2 */
    char text[512];
    int at = snprintf(text, sizeof text, "material w reflect 0.5\npolygon w 6");
    for (int k = 0; k < 6; k++)
        at += snprintf(text + at, sizeof text - (size_t)at, "  %.17g %.17g 0",
                       cos(k * M_PI / 3), sin(k * M_PI / 3));
    snprintf(text + at, sizeof text - (size_t)at, "\n");
    rad_scene s = load(text);
    rad_mesh m;
    rad_error err;
    rad_scene_set_mesh(&s, 4, 4);
    tap_ok(rad_mesh_build(&m, &s, &err) == RAD_OK, "a hexagon with --mesh 4x4 meshes");
    /* 6 fans of 16: V = 6 corners + centre + 6 spokes x 3 + 6 x (3 + 3) = 61 */
    tap_ok(m.nelements == 96 && m.nvertices == 61 && rad_scene_element_count(&s) == 96,
           "6 triangles around the centroid, 16 each, on 61 points (%d, %d)", m.nelements,
           m.nvertices);
    double area = 0;
    for (int e = 0; e < m.nelements; e++)
        area += m.elements[e].area;
    tap_ok(fabs(area - 1.5 * sqrt(3)) <= 1e-14, "the pieces' areas sum to 3 sqrt(3)/2 (%.17g)",
           area);
    const int nb = boundary_edges(&m, 0);
    /* Euler: V - E + F = 1 with E = (3F + nb) / 2 */
    tap_ok(nb == 24 && distinct_vertices(&m, 0) && m.nvertices - (3 * 96 + nb) / 2 + 96 == 1,
           "watertight and shared: 24 outline edges, V - E + F = 1");
    tap_ok(turns_with(&m, 0), "every piece turns as the hexagon does");
    /* a linear field at the centroids: inner vertices get it back */
    double *B = malloc(sizeof *B * (size_t)m.nelements * RAD_BANDS);
    double *Bv = malloc(sizeof *Bv * (size_t)m.nvertices * RAD_BANDS);
    for (int e = 0; e < m.nelements; e++)
        for (int b = 0; b < RAD_BANDS; b++)
            B[e + (size_t)b * m.nelements] =
                1 + 0.3 * m.elements[e].centroid.x - 0.2 * m.elements[e].centroid.y + 0.1 * b;
    rad_smooth_vertices(&m, B, Bv);
    double worst = 0;
    int inner = 0;
    for (int v = 0; v < m.nvertices; v++) {
        const rad_vec3 p = m.vertices[v];
        if (hypot(p.x, p.y) > 0.8) /* the outline's and the outer ring's */
            continue;
        inner++;
        for (int b = 0; b < RAD_BANDS; b++)
            worst = fmax(worst, fabs(Bv[v + (size_t)b * m.nvertices] -
                                     (1 + 0.3 * p.x - 0.2 * p.y + 0.1 * b)));
    }
    tap_ok(inner > 10 && worst <= 1e-14,
           "smoothing gives a linear field back at the %d inner vertices (worst %.2g)", inner,
           worst);
    free(B);
    free(Bv);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

static void test_max_size(void)
{
    rad_scene s = load("material w reflect 0.5\n"
                       "quad w 0 0 0  2 0 0  2 1 0  0 1 0\n"
                       "polygon w 3  0 0 1  1 0 1  0 1 1\n");
    rad_mesh m;
    rad_error err;
    tap_ok(rad_scene_set_max_element_size(&s, 0.3) == 2, "--max-element-size 0.3 cuts both");
    /* the quad: ceil(2/0.3) = 7 by ceil(1/0.3) = 4; the triangle: its
     * longest edge sqrt(2) in ceil(sqrt(2)/0.3) = 5 parts */
    tap_ok(s.surfaces[0].mesh_n == 7 && s.surfaces[0].mesh_m == 4 && s.surfaces[1].mesh_n == 5,
           "quad 7 x 4, triangle 5 per edge (%d x %d, %d)", s.surfaces[0].mesh_n,
           s.surfaces[0].mesh_m, s.surfaces[1].mesh_n);
    tap_ok(rad_mesh_build(&m, &s, &err) == RAD_OK, "and meshes");
    double longest = 0;
    for (int e = 0; e < m.nelements; e++)
        for (int k = 0; k < m.elements[e].nverts; k++)
            longest = fmax(longest, v3_norm(v3_sub(rad_mesh_vertex(&m, e, k),
                                                   rad_mesh_vertex(&m, e, (k + 1) %
                                                                   m.elements[e].nverts))));
    tap_ok(longest <= 0.3, "no element side is longer than 0.3 (%.4g)", longest);
    tap_ok(rad_scene_set_max_element_size(&s, 5) == 0 && s.surfaces[0].mesh_n == 7,
           "--max-element-size 5 changes nothing: a finer mesh stays");
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

int main(void)
{
    test_triangle();
    test_hexagon_and_smoothing();
    test_max_size();
    return tap_done();
}
