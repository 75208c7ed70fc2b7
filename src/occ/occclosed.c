/* occclosed.c -- closed meshes among the surfaces, and the faces of one
 * that a pair need not take as blockers.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A model exported as triangles is often a closed surface: each edge is
 * shared by exactly two faces.  A segment that passes through the solid
 * the surface bounds crosses it at least twice, going in and going out,
 * so the faces it leaves by hide nothing the faces it enters by do not;
 * for a pair with a model between them, half the model's faces are
 * redundant, and each costs its cuts and events at every evaluation.
 * The convex blocks of occsolid.c are the special case where the solid is
 * convex (and may be open underneath); this file takes any closed one.
 *
 * A closed mesh.  Surfaces are joined across edges they share (the same
 * two vertices, bit for bit); a component is a closed mesh when each of
 * its members' edges is shared by exactly two members that run it
 * opposite ways (so their fronts agree), no member is a two-sided
 * panel's face (occshaft.c, twins) or twisted beyond the snap, and the
 * volume it bounds, (1/6) sum over its fan triangles of v0 . (v1 x v2)
 * (the divergence theorem), is positive: the fronts face out.  A room's
 * walls, facing in, are no such mesh, and neither is a convex solid of
 * occsolid.c (its rule takes one element as O for the object, this one
 * might take the other, and together they would leave out both the
 * faces a segment enters by and those it leaves by).
 *
 * The rule.  Let O be one element of the pair (x a point of O) and B a
 * member of the closed mesh M with all of O on the back (closed) side of
 * B's plane.  A segment from x that crosses B's interior goes from the
 * back of B's plane to its front: it leaves the solid there, so just
 * before B it runs inside.  If x is not inside the solid, the segment went
 * in earlier, through a face F, from F's front to its back, so x is
 * strictly in front of F's plane: F is not one of the Bs, and F blocks the
 * segment.  So every such B can be left out of the pair's blockers without
 * changing hidden(x) at any point of O.  x is not inside the solid when O
 * is a face of M (the segments that carry light leave O by its front) or
 * when O's box misses M's box by more than the snap; for any other O the
 * rule is not used.  Both elements are tried as O and the one that leaves
 * out more blockers is taken (leaving out both sets is wrong: a segment
 * may go in by one set and out by the other).  Whether O is behind B's
 * plane is judged within the round-off of the distances (SOLID_ROUND ulps
 * of their size) and B's twist.  As with the solids, a point of O within
 * the snap of an entry face's plane is taken by the kernel as seeing that
 * face edge on, so the rule lets light through a band of O about a snap
 * wide along the planes of M's faces: a share of the pair's unoccluded
 * factor of about the snap over O's size (occsolid.c discusses it).
 *
 * The rule at a point.  The same argument holds for each point x of O
 * alone: a face B of M whose plane x is behind (by more than the snap,
 * so that B is not seen edge on) can only be crossed by a segment from x
 * on its way out of the solid, and that segment went in through a face
 * whose plane x is in front of, which is kept.  So the union of the
 * shadows from x (occunion.c) leaves such faces out, for x on the element
 * taken as O here, or on either element when no face was left out for
 * the pair: a face B behind the whole of O is the case where x is behind
 * it wherever x is.  (Never on the other element once faces were left
 * out for O: those left out and those behind x could be a segment's
 * entry and its exit.)  The faces left out at a point are mostly the far
 * side of a model, whose shadows overlap those of the near side and
 * would each be tested against them: on bench/scenes.py torus 150 in
 * classic mode the fill takes 9% fewer instructions.  Where it is allowed
 * is set for each blocker of the pair in sp->xcull.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ff/formfactor.h"
#include "occ/occlusion.h"
#include "occ/occspace.h"
#include "util/util.h"
#include "radiosity/base.h"

#define CLOSED_ROUND 64 /* ulps of a distance that are its round-off */

typedef struct closed_edge {
    rad_vec3 lo, hi;
    int s, up;
} closed_edge;

static int edge_cmp(const void *pa, const void *pb)
{
    const closed_edge *a = pa, *b = pb;
    int c = occ_vec_cmp(a->lo, b->lo);
    if (!c)
        c = occ_vec_cmp(a->hi, b->hi);
    return c ? c : (a->s > b->s) - (a->s < b->s);
}

/* Join the surfaces across shared edges (parent); bad[s]: an edge of s
 * is not shared by exactly two surfaces running it opposite ways. */
static rad_status join(const rad_occ *o, const unsigned char *ok, int *parent, unsigned char *bad)
{
    int ne = 0;
    for (int s = 0; s < o->nsurf; s++)
        ne += ok[s] ? o->sfirst[s + 1] - o->sfirst[s] : 0;
    closed_edge *e = malloc(sizeof *e * (size_t)(ne > 0 ? ne : 1));
    if (!e)
        return RAD_ERR_NOMEM;
    ne = 0;
    for (int s = 0; s < o->nsurf; s++) {
        const rad_vec3 *p = o->sv + o->sfirst[s];
        const int n = o->sfirst[s + 1] - o->sfirst[s];
        for (int k = 0; ok[s] && k < n; k++) {
            const rad_vec3 a = p[k], b = p[(k + 1) % n];
            const int c = occ_vec_cmp(a, b);
            if (c == 0) {
                bad[s] = 1; /* a repeated vertex */
                continue;
            }
            e[ne].lo = c < 0 ? a : b;
            e[ne].hi = c < 0 ? b : a;
            e[ne].s = s;
            e[ne++].up = c < 0;
        }
    }
    qsort(e, (size_t)ne, sizeof *e, edge_cmp);
    for (int k = 0; k < ne;) {
        int l = k + 1;
        while (l < ne && !occ_vec_cmp(e[l].lo, e[k].lo) && !occ_vec_cmp(e[l].hi, e[k].hi))
            l++;
        if (l - k == 2 && e[k].s != e[k + 1].s && e[k].up != e[k + 1].up) {
            const int rs = occ_uf_find(parent, e[k].s), rt = occ_uf_find(parent, e[k + 1].s);
            parent[rs < rt ? rt : rs] = rs < rt ? rs : rt;
        } else {
            for (int m = k; m < l; m++)
                bad[e[m].s] = 1;
        }
        k = l;
    }
    free(e);
    return RAD_OK;
}

rad_status occ_find_closed(rad_occ *o)
{
    const int ns = o->nsurf;
    o->nclosed = 0;
    o->closed = malloc(sizeof *o->closed * (size_t)(ns > 0 ? ns : 1));
    int *parent = malloc(sizeof *parent * (size_t)(ns > 0 ? ns : 1));
    int *id = malloc(sizeof *id * (size_t)(ns > 0 ? ns : 1));
    double *vol = calloc((size_t)(ns > 0 ? ns : 1), sizeof *vol);
    unsigned char *ok = calloc((size_t)(ns > 0 ? ns : 1), 1);
    unsigned char *bad = calloc((size_t)(ns > 0 ? ns : 1), 1);
    unsigned char *twinned = calloc((size_t)(ns > 0 ? ns : 1), 1);
    rad_status st = o->closed && parent && id && vol && ok && bad && twinned ? RAD_OK
                                                                            : RAD_ERR_NOMEM;
    for (int s = 0; s < ns && st == RAD_OK; s++)
        if (o->twin[s] >= 0)
            twinned[o->twin[s]] = 1;
    for (int s = 0; s < ns && st == RAD_OK; s++) {
        parent[s] = s;
        o->closed[s] = -1;
        ok[s] = o->sfirst[s + 1] - o->sfirst[s] >= 3 && o->twin[s] < 0 && !twinned[s] &&
                o->stwist[s] <= o->snap;
        /* a face of a convex solid is the solids' (occsolid.c): the two
         * rules could take different elements as O for one object and
         * leave out both its entry and its exit */
        bad[s] = !ok[s] || (o->solid && o->solid[s] >= 0);
    }
    if (st == RAD_OK)
        st = join(o, ok, parent, bad);
    if (st == RAD_OK) {
        /* a root is closed when none of its members is bad; its volume */
        for (int s = 0; s < ns; s++)
            if (bad[s])
                bad[occ_uf_find(parent, s)] = 1;
        for (int s = 0; s < ns; s++) {
            const int r = occ_uf_find(parent, s);
            if (bad[r] || r == s)
                continue; /* a lone surface is no closed mesh either */
            bad[r] |= 2; /* marks: has a member besides itself */
        }
        for (int s = 0; s < ns; s++) {
            const rad_vec3 *p = o->sv + o->sfirst[s];
            const int r = occ_uf_find(parent, s), n = o->sfirst[s + 1] - o->sfirst[s];
            if (bad[r] != 2)
                continue;
            /* about the root's first vertex: the sum does not depend on
             * the point, its round-off does */
            const rad_vec3 c = o->sv[o->sfirst[r]], a = v3_sub(p[0], c);
            for (int k = 1; k + 1 < n; k++)
                vol[r] += v3_dot(a, v3_cross(v3_sub(p[k], c), v3_sub(p[k + 1], c))) / 6;
        }
        for (int s = 0; s < ns; s++)
            id[s] = -1;
        for (int s = 0; s < ns; s++) {
            const int r = occ_uf_find(parent, s);
            if (bad[r] != 2 || !(vol[r] > 0))
                continue;
            if (id[r] < 0)
                id[r] = o->nclosed++;
            o->closed[s] = id[r];
        }
        o->clo = malloc(sizeof *o->clo * (size_t)(o->nclosed > 0 ? o->nclosed : 1));
        o->chi = malloc(sizeof *o->chi * (size_t)(o->nclosed > 0 ? o->nclosed : 1));
        if (!o->clo || !o->chi)
            st = RAD_ERR_NOMEM;
        for (int c = 0; c < o->nclosed && st == RAD_OK; c++) {
            o->clo[c] = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
            o->chi[c] = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
        }
        for (int s = 0; s < ns && st == RAD_OK; s++) {
            const int c = o->closed[s];
            if (c < 0)
                continue;
            o->clo[c] = v3(fmin(o->clo[c].x, o->slo[s].x), fmin(o->clo[c].y, o->slo[s].y),
                           fmin(o->clo[c].z, o->slo[s].z));
            o->chi[c] = v3(fmax(o->chi[c].x, o->shi[s].x), fmax(o->chi[c].y, o->shi[s].y),
                           fmax(o->chi[c].z, o->shi[s].z));
        }
    }
    free(parent);
    free(id);
    free(vol);
    free(ok);
    free(bad);
    free(twinned);
    return st;
}

/* Is no point of element O (surface s, polygon p in the pair's frame at
 * origin) inside closed mesh c: O one of its faces, or O's box off c's? */
static int outside(const rad_occ *o, int c, int s, const rad_ff_poly *p, rad_vec3 origin)
{
    if (o->closed[s] == c)
        return 1;
    rad_vec3 lo, hi;
    v3_bounds(p->v, p->n, &lo, &hi);
    lo = v3_add(lo, origin);
    hi = v3_add(hi, origin);
    const double t = o->snap;
    return lo.x > o->chi[c].x + t || hi.x < o->clo[c].x - t || lo.y > o->chi[c].y + t ||
           hi.y < o->clo[c].y - t || lo.z > o->chi[c].z + t || hi.z < o->clo[c].z - t;
}

/* Is all of O (p) on the back (closed) side of blocker k's plane, within
 * the round-off and the blocker's twist? */
static int behind(const rad_occ *o, const occ_space *sp, int k, const rad_ff_poly *p)
{
    const int b = sp->bid[k];
    const rad_vec3 n = o->snormal[b], a = sp->blk.v[sp->blk.first[k]];
    for (int l = 0; l < p->n; l++) {
        const rad_vec3 d = v3_sub(p->v[l], a);
        if (v3_dot(n, d) > CLOSED_ROUND * DBL_EPSILON * v3_norm(d) + o->stwist[b])
            return 0;
    }
    return 1;
}

int occ_closed_cull(const rad_occ *o, occ_space *sp, int nb, int sa, int sb,
                    const rad_ff_poly *pi, const rad_ff_poly *pj, rad_vec3 origin)
{
    sp->nxcull = 0;
    if (o->nclosed == 0 || nb < 1)
        return nb;
    /* ccut: [0, 2 nb) the cuts per side, [2 nb, 4 nb) whether the side's
     * element is outside the blocker's mesh */
    if (occ_grow_i(&sp->ccut, &sp->capccut, 4 * nb) || occ_grow_i(&sp->xcull, &sp->capxcull, 2 * nb))
        return -1;
    int *cut = sp->ccut, *out = sp->ccut + 2 * nb, count[2] = {0, 0};
    for (int side = 0; side < 2; side++) {
        const rad_ff_poly *p = side ? pj : pi;
        const int s = side ? sb : sa;
        int last = -1, ok = 0; /* the last mesh judged, and whether O is outside it */
        for (int k = 0; k < nb; k++) {
            const int c = o->closed[sp->bid[k]];
            cut[side * nb + k] = out[side * nb + k] = 0;
            if (c < 0)
                continue;
            if (c != last) {
                ok = outside(o, c, s, p, origin);
                last = c;
            }
            out[side * nb + k] = ok;
            if (ok && nb >= 2 && behind(o, sp, k, p)) {
                cut[side * nb + k] = 1;
                count[side]++;
            }
        }
    }
    /* the side whose cuts are taken (-1: none); the rule at a point
     * (header; occunion.c, shadows) holds on that side alone */
    const int taken = count[0] == 0 && count[1] == 0 ? -1 : count[1] > count[0];
    const int *f = cut + (taken > 0 ? nb : 0);
    int w = 0, at = 0;
    for (int k = 0; k < nb; k++) {
        const int first = sp->blk.first[k], n = sp->blk.first[k + 1] - first;
        if (taken >= 0 && f[k])
            continue;
        memmove(sp->blk.v + at, sp->blk.v + first, sizeof *sp->blk.v * (size_t)n);
        sp->blk.first[w] = at;
        for (int side = 0; side < 2; side++)
            sp->xcull[2 * w + side] = out[side * nb + k] && (taken < 0 || taken == side);
        sp->bid[w++] = sp->bid[k];
        at += n;
    }
    sp->blk.first[w] = at;
    sp->blk.np = w;
    sp->blk.nv = at;
    sp->nxcull = w;
    return w;
}
