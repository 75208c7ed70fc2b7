/* test_adaptive.c -- the quadtree of adaptive subdivision and its
 * conforming mesh (adaptnodes.c, adaptmesh.c).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * References: a node's four children tile it, so their areas add up to its
 * own (exactly here: areas 1, 1/4, 1/16 are dyadic); level 0 is the
 * starting mesh, vertex for vertex (the lattice is made by the same
 * bilinear formula); and a hand-computed mesh of one split element beside
 * a whole one, whose vertex radiosities follow from the rules of
 * adaptmesh.h by hand (below).  Comparisons are exact: every value is a
 * mean of a few small integers or halves.  That mesh, taken as a converged
 * solution, projected onto every node (adaptproject.c): the split
 * element's node takes the mean of its children's 1..4 (equal areas:
 * 2.5), the whole one's children its 10; leaves that leave a hole are
 * refused.
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "adapt/adaptmesh.h"
#include "adapt/adaptnodes.h"
#include "adapt/adaptproject.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "../tap.h"

/* Two unit squares side by side: elements 0 (x in [0,1]) and 1 ([1,2]). */
static int two_squares(rad_mesh *m)
{
    const char *text = "material w reflect 0.5\nquad w 0 0 0  2 0 0  2 1 0  0 1 0 mesh 2x1\n";
    rad_scene s;
    rad_error err;
    if (rad_scene_parse(&s, text, strlen(text), "t", &err) != RAD_OK)
        return -1;
    const int r = rad_mesh_build(m, &s, &err) != RAD_OK ? -1 : 0;
    rad_scene_free(&s);
    return r;
}

static int same(rad_vec3 a, rad_vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

static void test_nodes(const rad_mesh *m)
{
    rad_adapt_nodes a;
    rad_error err;
    if (radi_adapt_nodes_build(&a, m, 2, &err) != RAD_OK) {
        tap_ok(0, "nodes of depth 2: %s", err.message);
        return;
    }
    tap_ok(a.mesh.nelements == 2 * (1 + 4 + 16), "2 x (1 + 4 + 16) nodes (%d)", a.mesh.nelements);
    int same_roots = 1, tiles = 1, sums = 1;
    for (int p = 0; p < 2; p++)
        for (int k = 0; k < 4; k++)
            same_roots &= same(rad_mesh_vertex(&a.mesh, a.root[p], k), rad_mesh_vertex(m, p, k));
    for (int e = 0; e < a.mesh.nelements; e++) {
        if (a.level[e] == a.depth)
            continue;
        int x0, y0, w;
        double area = 0;
        radi_adapt_box(&a, e, &x0, &y0, &w);
        for (int k = 0; k < 4; k++) {
            const int c = radi_adapt_child(&a, e, k);
            int cx, cy, cw;
            radi_adapt_box(&a, c, &cx, &cy, &cw);
            tiles &= cw * 2 == w && cx == x0 + (k & 1) * cw && cy == y0 + (k >> 1) * cw &&
                     a.patch[c] == a.patch[e] && a.level[c] == a.level[e] + 1;
            area += a.mesh.elements[c].area;
        }
        sums &= area == a.mesh.elements[e].area;
    }
    tap_ok(same_roots, "level 0 is the starting mesh, vertex for vertex");
    tap_ok(tiles, "each node's four children tile its square, on its patch, one level down");
    tap_ok(sums, "children's areas add up to their parent's exactly");
    radi_adapt_nodes_free(&a);
}

/* Depth 1: element 0 split (children B 1 2 / 3 4, rows bottom to top),
 * element 1 whole (B 10).  Lattice points (x, y), spacing 1/2, x 0..4:
 *   corners, the mean of the leaves at them:
 *     (0,0) 1; (1,0) (1+2)/2 = 1.5; (2,0) (2+10)/2 = 6; (0,1) (1+3)/2 = 2;
 *     (1,1) (1+2+3+4)/4 = 2.5; (0,2) 3; (1,2) 3.5; (2,2) (4+10)/2 = 7;
 *     (4,0) = (4,2) = 10;
 *   hanging (2,1), halfway along element 1's left side: (6 + 7)/2 = 6.5. */
/* The leaf mesh o (B, level) of test_leaf_mesh as a converged solution. */
static void test_project(const rad_adapt_nodes *a, const rad_mesh *o, const double *B,
                         const int *level, const int kids[4])
{
    const int n = a->mesh.nelements;
    double Rn[30];
    rad_error err;
    if (radi_adapt_project(a, o, B, level, Rn, &err) != RAD_OK) {
        tap_ok(0, "project: %s", err.message);
        return;
    }
    int ok = Rn[0] == 2.5 && Rn[1] == 10;
    for (int k = 0; k < 4; k++) {
        ok &= Rn[kids[k]] == k + 1;
        ok &= Rn[radi_adapt_child(a, 1, k)] == 10; /* below a final leaf */
    }
    for (int b = 1; b < 3; b++)
        for (int j = 0; j < n; j++)
            ok &= Rn[j + b * n] == Rn[j];
    tap_ok(ok, "projected: the split node the mean of its children (2.5), the whole "
               "one's children its value (10), the leaves their own");
    rad_mesh holed = *o; /* the last child missing: a hole */
    holed.nelements = o->nelements - 1;
    tap_ok(radi_adapt_project(a, &holed, B, level, Rn, &err) == RAD_ERR_INVALID,
           "leaves with a hole are refused: %s", err.message);
}

static void test_leaf_mesh(const rad_mesh *m)
{
    rad_adapt_nodes a;
    rad_error err;
    if (radi_adapt_nodes_build(&a, m, 1, &err) != RAD_OK) {
        tap_ok(0, "nodes of depth 1: %s", err.message);
        return;
    }
    const int n = a.mesh.nelements; /* 2 + 8 */
    unsigned char leaf[10] = {0};
    double Bn[30] = {0};
    const int kids[4] = {radi_adapt_child(&a, 0, 0), radi_adapt_child(&a, 0, 1),
                         radi_adapt_child(&a, 0, 2), radi_adapt_child(&a, 0, 3)};
    leaf[1] = 1;
    for (int b = 0; b < 3; b++)
        Bn[1 + b * n] = 10;
    for (int k = 0; k < 4; k++) {
        leaf[kids[k]] = 1;
        for (int b = 0; b < 3; b++)
            Bn[kids[k] + b * n] = k + 1;
    }
    rad_mesh o;
    double *B, *Bv;
    int *level;
    if (n != 10 || radi_adapt_leaf_mesh(&a, leaf, Bn, &o, &B, &Bv, &level, &err) != RAD_OK) {
        tap_ok(0, "leaf mesh: %s", err.message);
        radi_adapt_nodes_free(&a);
        return;
    }
    tap_ok(o.nelements == 5 && o.nvertices == 11, "5 leaves, 9 + 2 vertices (%d, %d)", o.nelements,
           o.nvertices);
    tap_ok(level[0] == 0 && level[1] == 1 && level[4] == 1 && B[0] == 10 && B[1] == 1 &&
               B[4] == 4,
           "the whole element first (level 0, B 10), then the children (level 1, B 1..4)");
    tap_ok(o.elements[0].nverts == 5, "the whole element lists the hanging vertex: 5 vertices (%d)",
           o.elements[0].nverts);
    /* find vertices by position */
    static const double want[][3] = {{0, 0, 1},     {0.5, 0, 1.5}, {1, 0, 6},   {0, 0.5, 2},
                                     {0.5, 0.5, 2.5}, {0, 1, 3},   {0.5, 1, 3.5}, {1, 1, 7},
                                     {2, 0, 10},    {2, 1, 10},    {1, 0.5, 6.5}};
    int all = 1;
    for (size_t k = 0; k < sizeof want / sizeof want[0]; k++) {
        int found = 0;
        for (int v = 0; v < o.nvertices; v++)
            if (o.vertices[v].x == want[k][0] && o.vertices[v].y == want[k][1]) {
                found = 1;
                for (int b = 0; b < 3; b++)
                    all &= Bv[v + b * o.nvertices] == want[k][2];
            }
        all &= found;
    }
    tap_ok(all, "vertex radiosity by hand: corner means, and the hanging vertex (1, 0.5) = 6.5");
    const int *idx = o.vindex + o.elements[0].first;
    tap_ok(o.vertices[idx[4]].x == 1 && o.vertices[idx[4]].y == 0.5 &&
               o.vertices[idx[0]].x == 1 && o.vertices[idx[0]].y == 0,
           "counter-clockwise from its first corner, the hanging vertex last (on the left side)");
    test_project(&a, &o, B, level, kids);
    free(B);
    free(Bv);
    free(level);
    rad_mesh_free(&o);
    radi_adapt_nodes_free(&a);
}

int main(void)
{
    rad_mesh m;
    if (two_squares(&m) != 0) {
        tap_ok(0, "two squares");
        return tap_done();
    }
    test_nodes(&m);
    test_leaf_mesh(&m);
    rad_mesh_free(&m);
    return tap_done();
}
