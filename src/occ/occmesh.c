/* occmesh.c -- which edges and vertices of a pair's blockers lie inside
 * the union of their shadows from every point of the outer element, so
 * that the events they would cause never happen (occdomain.c).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * hidden(x) is the form factor from x to the part of the inner element
 * inside the union of the blockers' shadows (occpoint.c, occunion.c).
 * Its kinks, the events that occdomain.c cuts the outer element along,
 * are where the boundary of that union changes its make-up: where the
 * shadow of a blocker's edge passes a vertex of the inner element, the
 * shadow of a blocker's vertex passes an edge of the inner element or of
 * another shadow, or three edges' shadows meet (Heckbert 1992; Gigus,
 * Canny & Seidel 1991).  An edge or a vertex whose shadow is inside the
 * union, away from its boundary, for every x of the outer element takes
 * part in no event.  Two such cases are found here, by exact comparison
 * of the clipped blockers' coordinates (sp->blkc), as a triangulated model
 * writes them:
 *
 *   an inner edge: run one way by one blocker and the other way by exactly
 *   one other, with every vertex of the outer element strictly on the same
 *   side of both blockers' planes (beyond c->snap).  The two polygons are
 *   then seen from the same side from every x: their shadows turn the same
 *   way, so they lie on the two sides of the edge's shadow and cover a
 *   neighbourhood of its inside (as occunion.c's inner_edges finds them
 *   point by point);
 *
 *   an inner vertex: every blocker edge that ends there is inner.  The
 *   polygons around it then form closed fans seen from one side, and their
 *   shadows turn about its shadow once, covering a neighbourhood of it.
 *
 * Everything else counts as boundary, which only costs cuts: an edge
 * shared with a blocker the shaft or a solid left out, an edge cut by
 * the clip to the inner plane (whose new ends two polygons round apart),
 * a fold that the outer element sees from both sides.  On a closed
 * triangulated model seen from a floor the events of the mesh's inside,
 * most of those of its blockers, go. */
#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "occ/occspace.h"
#include "radiosity/base.h"

/* One blocker edge, its ends in lexicographic order. */
struct mesh_edge {
    rad_vec3 lo, hi;
    int at;       /* its first vertex in sp->blkc.v (the edge runs from there) */
    int b;        /* its blocker */
    int forward;  /* it runs from lo to hi */
};
typedef struct mesh_edge mesh_edge;

static int cmp_edge(const void *pa, const void *pb)
{
    const mesh_edge *a = pa, *b = pb;
    int r = occ_vec_cmp(a->lo, b->lo);
    return r ? r : occ_vec_cmp(a->hi, b->hi);
}

static int cmp_vec(const void *pa, const void *pb)
{
    return occ_vec_cmp(*(const rad_vec3 *)pa, *(const rad_vec3 *)pb);
}

/* +1 (-1) when every vertex of o lies beyond tol in front of (behind)
 * polygon p's plane, its normal by Newell's sum (the polygon's own turn,
 * whatever the surface's normal says); else 0. */
static int outer_side(const rad_vec3 *p, int n, const rad_vec3 *o, int no, double tol)
{
    rad_vec3 nrm = v3_newell(p, n); /* relative to p[0]: no cancellation */
    const double len = v3_norm(nrm);
    if (!(len > 0))
        return 0;
    nrm = v3_scale(nrm, 1 / len);
    int front = 0, back = 0;
    for (int k = 0; k < no; k++) {
        const double d = v3_dot(nrm, v3_sub(o[k], p[0]));
        front += d > tol;
        back += d < -tol;
    }
    return front == no ? 1 : back == no ? -1 : 0;
}

/* Mark the edges of the group e[i .. j) inner when they are two, run
 * opposite ways, on two blockers seen from one side. */
static void mark_group(const mesh_edge *e, int i, int j, const int *side, int *flag)
{
    if (j - i == 2 && e[i].forward != e[i + 1].forward && e[i].b != e[i + 1].b &&
        side[e[i].b] != 0 && side[e[i].b] == side[e[i + 1].b]) {
        flag[e[i].at] |= OCC_MESH_EDGE;
        flag[e[i + 1].at] |= OCC_MESH_EDGE;
    }
}

/* The edges of sp->blkc, sorted by their ends, into *e; the blockers'
 * sides into sp->mside. */
static int list_edges(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no)
{
    const int nv = sp->blkc.nv;
    mesh_edge *m = occ_realloc(sp->medge, &sp->capmedge, nv, sizeof *m);
    if (!m)
        return -1;
    sp->medge = m;
    if (occ_grow_i(&sp->mside, &sp->capmside, c->nb))
        return -1;
    for (int b = 0; b < c->nb; b++) {
        const int f = sp->blkc.first[b], n = sp->blkc.first[b + 1] - f;
        const rad_vec3 *p = sp->blkc.v + f;
        sp->mside[b] = outer_side(p, n, o, no, c->snap);
        for (int k = 0; k < n; k++) {
            const rad_vec3 a = p[k], z = p[(k + 1) % n];
            const int fw = occ_vec_cmp(a, z) < 0;
            m[f + k] = (mesh_edge){fw ? a : z, fw ? z : a, f + k, b, fw};
        }
    }
    qsort(m, nv, sizeof *m, cmp_edge);
    return 0;
}

int occ_mesh_interior(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no)
{
    const int nv = sp->blkc.nv;
    if (occ_grow_i(&sp->mflag, &sp->capmflag, nv))
        return -1;
    for (int k = 0; k < nv; k++)
        sp->mflag[k] = 0;
    if (c->nb < 2)
        return 0;
    if (list_edges(sp, c, o, no) || occ_grow_v3(&sp->mends, &sp->capmends, 2 * nv))
        return -1;
    const mesh_edge *e = sp->medge;
    for (int i = 0, j; i < nv; i = j) {
        for (j = i + 1; j < nv && !cmp_edge(&e[i], &e[j]); j++)
            ;
        mark_group(e, i, j, sp->mside, sp->mflag);
    }
    /* a vertex is inner when no boundary edge ends there */
    int nends = 0;
    for (int i = 0; i < nv; i++)
        if (!(sp->mflag[e[i].at] & OCC_MESH_EDGE)) {
            sp->mends[nends++] = e[i].lo;
            sp->mends[nends++] = e[i].hi;
        }
    qsort(sp->mends, nends, sizeof *sp->mends, cmp_vec);
    for (int k = 0; k < nv; k++)
        if (!bsearch(&sp->blkc.v[k], sp->mends, nends, sizeof *sp->mends, cmp_vec))
            sp->mflag[k] |= OCC_MESH_VERTEX;
    return 0;
}
