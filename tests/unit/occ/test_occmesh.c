/* test_occmesh.c -- which blocker edges and vertices lie inside the union
 * of the shadows from the whole outer element (src/occ/occmesh.c,
 * occ_mesh_interior), on small meshes whose answer is known by
 * construction.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A tent: eight triangles about an apex raised a little over a square,
 * turned one way (each spoke run one way by one triangle and the other
 * way by the next).  Seen from a square below, its eight spokes are
 * inner and so is the apex; its rim is not, nor are the rim's vertices.
 * Turning one triangle over makes its two spokes, and so the apex,
 * boundary; an outer element that straddles the triangles' planes makes
 * every edge boundary; a spoke that three triangles share is boundary,
 * and so is the edge of a fold (two triangles on one side of it).
 * The flags are exact: every check compares counts, no tolerance.
 */
#include <config.h>

#include <string.h>

#include "occ/occspace.h"
#include "../tap.h"

enum { RIM = 8 };

/* The tent's triangles into sp->blkc: apex a, rim on the square of half
 * side 1 about the origin in the plane z = 0; triangle `flip` (or none
 * when -1) turned over. */
static int tent(occ_space *sp, rad_vec3 apex, int flip)
{
    static const double ring[RIM][2] = {{-1, -1}, {0, -1}, {1, -1}, {1, 0},
                                        {1, 1},   {0, 1},  {-1, 1}, {-1, 0}};
    occ_ps_clear(&sp->blkc);
    for (int k = 0; k < RIM; k++) {
        rad_vec3 t[3] = {apex, {ring[k][0], ring[k][1], 0},
                         {ring[(k + 1) % RIM][0], ring[(k + 1) % RIM][1], 0}};
        if (k == flip) {
            const rad_vec3 s = t[1];
            t[1] = t[2];
            t[2] = s;
        }
        if (occ_ps_push(&sp->blkc, t, 3))
            return -1;
    }
    return 0;
}

/* Count the flags: spokes (edge 0 -> 1 or 2 -> 0 of a triangle, the ones
 * at the apex), rim edges (1 -> 2), the apex's copies, the rim's. */
typedef struct counts {
    int spokes, rim_edges, apex, rim_vertices;
} counts;

static counts count(const occ_space *sp)
{
    counts n = {0, 0, 0, 0};
    for (int b = 0; b < sp->blkc.np; b++) {
        const int *f = sp->mflag + sp->blkc.first[b];
        n.spokes += ((f[0] & OCC_MESH_EDGE) != 0) + ((f[2] & OCC_MESH_EDGE) != 0);
        n.rim_edges += (f[1] & OCC_MESH_EDGE) != 0;
        n.apex += (f[0] & OCC_MESH_VERTEX) != 0;
        n.rim_vertices += ((f[1] & OCC_MESH_VERTEX) != 0) + ((f[2] & OCC_MESH_VERTEX) != 0);
    }
    return n;
}

int main(void)
{
    occ_space sp;
    memset(&sp, 0, sizeof sp);
    pair_ctx c;
    memset(&c, 0, sizeof c);
    c.snap = 1e-12;
    const rad_vec3 apex = {0.2, -0.1, 0.15};
    const rad_vec3 below[4] = {{-2, -2, -3}, {2, -2, -3}, {2, 2, -3}, {-2, 2, -3}};
    const rad_vec3 across[4] = {{5, -1, -4}, {5, 1, -4}, {5, 1, 4}, {5, -1, 4}};

    if (tent(&sp, apex, -1))
        return 1;
    c.nb = sp.blkc.np;
    if (occ_mesh_interior(&sp, &c, below, 4))
        return 1;
    counts n = count(&sp);
    tap_ok(n.spokes == 16 && n.rim_edges == 0,
           "tent seen from below: its 8 spokes inner from both sides (%d of 16), no rim edge (%d)",
           n.spokes, n.rim_edges);
    tap_ok(n.apex == 8 && n.rim_vertices == 0,
           "tent seen from below: the apex inner in all 8 triangles (%d), no rim vertex (%d)",
           n.apex, n.rim_vertices);

    if (tent(&sp, apex, 3) || occ_mesh_interior(&sp, &c, below, 4))
        return 1;
    n = count(&sp);
    tap_ok(n.spokes == 12 && n.apex == 0,
           "one triangle turned over: its two spokes are boundary (%d of 16 inner, want 12), "
           "and so the apex (%d)", n.spokes, n.apex);

    if (tent(&sp, apex, -1) || occ_mesh_interior(&sp, &c, across, 4))
        return 1;
    n = count(&sp);
    tap_ok(n.spokes == 0 && n.apex == 0,
           "an outer element across the triangles' planes: nothing inner (%d spokes, apex %d)",
           n.spokes, n.apex);

    /* a third triangle on spoke apex -> (0, -1, 0), below the tent */
    if (tent(&sp, apex, -1))
        return 1;
    const rad_vec3 extra[3] = {apex, {0, -1, 0}, {0.1, -0.5, -0.4}};
    if (occ_ps_push(&sp.blkc, extra, 3))
        return 1;
    c.nb = sp.blkc.np;
    if (occ_mesh_interior(&sp, &c, below, 4))
        return 1;
    n = count(&sp);
    tap_ok(n.spokes == 14 && n.apex == 0,
           "a spoke shared by three triangles is boundary (%d of 16 inner, want 14; apex %d)",
           n.spokes, n.apex);

    /* a fold: two triangles on one side of their common edge, run the
     * same way, seen from below (both turned away): their shadows overlap
     * on one side of the edge's, which is on the union's boundary */
    const rad_vec3 fold[2][3] = {{{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}},
                                 {{0, 0, 0}, {1, 0, 0}, {0.5, 0.8, 0.3}}};
    occ_ps_clear(&sp.blkc);
    if (occ_ps_push(&sp.blkc, fold[0], 3) || occ_ps_push(&sp.blkc, fold[1], 3))
        return 1;
    c.nb = 2;
    if (occ_mesh_interior(&sp, &c, below, 4))
        return 1;
    tap_ok(!(sp.mflag[0] & OCC_MESH_EDGE) && !(sp.mflag[3] & OCC_MESH_EDGE),
           "a fold (the common edge run the same way by both, one side seen): boundary");

    if (tent(&sp, apex, -1))
        return 1;
    c.nb = 1;
    if (occ_mesh_interior(&sp, &c, below, 4))
        return 1;
    int any = 0;
    for (int k = 0; k < sp.blkc.nv; k++)
        any |= sp.mflag[k];
    tap_ok(!any, "a single blocker: nothing inner");

    occ_space_free(&sp);
    return tap_done();
}
