/* test_mesh.c -- subdivision: areas, shared vertices, orientation.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * References are exact geometry: the elements of a surface tile it (areas
 * add up to its area, here computed independently as |cross| of the
 * parallelogram or the shoelace sum of the trapezoid); a parallelogram's
 * N x M elements are equal; an N x M grid has (N+1)(M+1) shared vertices.
 * Tolerance 1e-14 relative: sums of at most a few hundred areas of O(1)
 * computed from coordinates of O(1).
 */
#include <config.h>

#include <math.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "../tap.h"

static rad_status load(const char *text, rad_scene *s, rad_mesh *m)
{
    rad_error err;
    rad_status st = rad_scene_parse(s, text, strlen(text), "t.scene", &err);
    if (st)
        return st;
    return rad_mesh_build(m, s, &err);
}

int main(void)
{
    rad_scene s;
    rad_mesh m;
    /* a parallelogram 3 x 2 with shear, meshed 4x3, and a trapezoid 5x2 */
    const char *text = "material w reflect 0.5 emit 0.25\n"
                       "quad w 0 0 0  3 0 0  4 2 0  1 2 0 mesh 4x3\n"
                       "quad w 0 0 1  4 0 1  3 1 1  1 1 1 mesh 5x2\n"
                       "polygon w 3  0 0 5  1 0 5  0 1 5\n";
    tap_ok(load(text, &s, &m) == RAD_OK, "scene meshes");
    tap_ok(m.nelements == 12 + 10 + 1, "element count 4*3 + 5*2 + 1 = %d", m.nelements);
    tap_ok(m.nvertices == 20 + 18 + 3, "vertex count (5*4) + (6*3) + 3 = %d", m.nvertices);
    double a0 = 0, a1 = 0, worst_eq = 0;
    for (int e = 0; e < 12; e++) {
        a0 += m.elements[e].area;
        worst_eq = fmax(worst_eq, fabs(m.elements[e].area - 0.5));
    }
    for (int e = 12; e < 22; e++)
        a1 += m.elements[e].area;
    tap_close(a0, 6.0, 1e-14, "parallelogram elements add up to 3 * 2");
    tap_ok(worst_eq < 1e-14, "parallelogram elements are equal (6/12 each; worst %.3g)", worst_eq);
    tap_close(a1, 3.0, 1e-14, "trapezoid elements add up to (4 + 2)/2 * 1");
    tap_close(m.elements[22].area, 0.5, 1e-15, "triangle area");
    /* normals: unit, and the element's own vertex order agrees with them */
    int ok = 1;
    for (int e = 0; e < m.nelements; e++) {
        rad_element *el = &m.elements[e];
        rad_vec3 n = el->normal;
        double nz = 0;
        for (int k = 0; k < el->nverts; k++) {
            rad_vec3 a = rad_mesh_vertex(&m, e, k), b = rad_mesh_vertex(&m, e, (k + 1) % el->nverts);
            nz += a.x * b.y - a.y * b.x;
        }
        ok &= fabs(n.z - 1) < 1e-15 && nz > 0;
    }
    tap_ok(ok, "every element faces +z and runs counter-clockwise");
    /* shared vertices: interior vertex of the 4x3 grid used by 4 elements */
    int uses[64] = {0};
    for (int e = 0; e < 12; e++)
        for (int k = 0; k < 4; k++)
            uses[m.vindex[m.elements[e].first + k]]++;
    int interior4 = 1, corners1 = uses[0] == 1 && uses[4] == 1 && uses[15] == 1 && uses[19] == 1;
    for (int gj = 1; gj < 3; gj++)
        for (int gi = 1; gi < 4; gi++)
            interior4 &= uses[gj * 5 + gi] == 4;
    tap_ok(interior4 && corners1, "interior vertices shared by 4 elements, corners by 1");
    /* grid position and vertex (gi, gj) at the bilinear point */
    rad_element *e5 = &m.elements[1 * 4 + 2]; /* gi = 2, gj = 1 */
    rad_vec3 v = rad_mesh_vertex(&m, 1 * 4 + 2, 0);
    tap_ok(e5->gi == 2 && e5->gj == 1 && fabs(v.x - (1.5 + 1.0 / 3)) < 1e-15 &&
               fabs(v.y - 2.0 / 3) < 1e-15,
           "element (2,1) starts at the bilinear point (%.17g, %.17g)", v.x, v.y);
    tap_ok(m.surface_first[1] == 12 && m.surface_first[3] == 23 && m.surface_n[1] == 5,
           "surface ranges");
    tap_ok(m.elements[3].emit[1] == 0.25 && m.elements[3].reflect[2] == 0.5,
           "elements carry their material");
    /* centroid of the sheared parallelogram's element (0,0): (3/8 + 1/6, 1/3) */
    rad_vec3 c = m.elements[0].centroid;
    tap_ok(fabs(c.x - (0.375 + 1.0 / 6)) < 1e-15 && fabs(c.y - 1.0 / 3) < 1e-15,
           "centroid of a parallelogram element");
    rad_mesh_free(&m);
    rad_scene_free(&s);
    return tap_done();
}
