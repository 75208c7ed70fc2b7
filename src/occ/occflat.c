/* occflat.c -- coplanar neighbours merged into convex patches, and a
 * pair's blockers that belong to one patch taken as that patch.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A box written as separate quadrilaterals (a View3D file lists each
 * element as a surface) or a flat face of a model cut into triangles
 * stands between a pair as dozens of blockers where one polygon would do:
 * each adds its cuts, its shadow and its event planes to every
 * evaluation.  What a set of blockers hides depends only on the union of
 * the blockers, so coplanar surfaces that share edges are merged once, at
 * setup, into patches: convex polygons, each the union of its members.
 *
 * Members.  Two surfaces are joined when they share an edge (the same two
 * vertices, bit for bit, run opposite ways: the same side up), their
 * normals agree to 1e-12 and each one's vertices lie within the snap of
 * the other's plane; neither may be twisted beyond the snap, nor be a
 * two-sided panel's face (twins, occshaft.c).  A group is merged greedily:
 * two polygons that share an edge become one where the result is convex
 * (every turn at or above -1e-12 of its two edges' lengths' product), has
 * no vertex twice and has the area of the two (to 1e-12): two convex
 * polygons on either side of a common edge are then their union.  Merged
 * polygons keep the members' vertices while they grow, so that their
 * edges stay members' edges; at the end, vertices where the boundary
 * turns by less than that tolerance are dropped (a band of 1e-12 of the
 * patch's size, far below any promise).
 *
 * The rule (occ_flat_blockers).  A pair's blockers (after the shaft,
 * before the solids, occsolid.c, which then see one blocker a face) that
 * belong to one patch are replaced by the whole patch, where two or more
 * of them do and the patch holds neither of the pair's surfaces.  The
 * patch hides at least what they hide, and nothing more: its other
 * members were left out of the pair's list because the shaft cleared
 * them, and they meet no segment between the two elements.  A solid whose
 * faces are cut into pieces finds its corners among the patches' too
 * (occsolid.c, group_vertices).
 * A patch holding one of the pair's surfaces is left alone: that surface
 * is in the plane of an element, and the elements' own surfaces are no
 * blockers.
 */
#include <config.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "occ/occlusion.h"
#include "occ/occspace.h"
#include "util/util.h"
#include "radiosity/base.h"

#define FLAT_NORMAL 1e-12  /* 1 - n_s . n_t below this: the same plane's normal */
#define FLAT_TURN 1e-12    /* a turn below this part of its edges' product: straight */

/* A directed edge of a surface: its ends in lexicographic order, and
 * whether it runs from lo to hi. */
typedef struct flat_edge {
    rad_vec3 lo, hi;
    int s, up;
} flat_edge;

static int edge_cmp(const void *pa, const void *pb)
{
    const flat_edge *a = pa, *b = pb;
    int c = occ_vec_cmp(a->lo, b->lo);
    if (!c)
        c = occ_vec_cmp(a->hi, b->hi);
    return c ? c : (a->s > b->s) - (a->s < b->s);
}

/* May surface s join a patch? */
static int eligible(const rad_occ *o, const unsigned char *twinned, int s)
{
    return o->sfirst[s + 1] - o->sfirst[s] >= 3 && o->twin[s] < 0 && !twinned[s] &&
           o->stwist[s] <= o->snap;
}

/* Is every vertex of t within the snap of s's plane? */
static int on_plane(const rad_occ *o, int s, int t)
{
    const rad_vec3 *p = o->sv + o->sfirst[s], *q = o->sv + o->sfirst[t];
    for (int k = 0; k < o->sfirst[t + 1] - o->sfirst[t]; k++)
        if (fabs(v3_dot(o->snormal[s], v3_sub(q[k], p[0]))) > o->snap)
            return 0;
    return 1;
}

/* Join the eligible surfaces that share an edge in one plane (parent). */
static rad_status join(const rad_occ *o, const unsigned char *twinned, int *parent)
{
    int ne = 0;
    for (int s = 0; s < o->nsurf; s++)
        ne += eligible(o, twinned, s) ? o->sfirst[s + 1] - o->sfirst[s] : 0;
    flat_edge *e = malloc(sizeof *e * (size_t)(ne > 0 ? ne : 1));
    if (!e)
        return RAD_ERR_NOMEM;
    ne = 0;
    for (int s = 0; s < o->nsurf; s++) {
        const rad_vec3 *p = o->sv + o->sfirst[s];
        const int n = o->sfirst[s + 1] - o->sfirst[s];
        for (int k = 0; k < n && eligible(o, twinned, s); k++) {
            const rad_vec3 a = p[k], b = p[(k + 1) % n];
            const int up = occ_vec_cmp(a, b) < 0;
            e[ne].lo = up ? a : b;
            e[ne].hi = up ? b : a;
            e[ne].s = s;
            e[ne++].up = up;
        }
    }
    qsort(e, (size_t)ne, sizeof *e, edge_cmp);
    for (int k = 0; k + 1 < ne; k++) {
        /* exactly two copies of the edge, run opposite ways */
        if (occ_vec_cmp(e[k].lo, e[k + 1].lo) || occ_vec_cmp(e[k].hi, e[k + 1].hi))
            continue;
        if ((k + 2 < ne && !occ_vec_cmp(e[k].lo, e[k + 2].lo) && !occ_vec_cmp(e[k].hi, e[k + 2].hi)) ||
            (k > 0 && !occ_vec_cmp(e[k].lo, e[k - 1].lo) && !occ_vec_cmp(e[k].hi, e[k - 1].hi)))
            continue;
        const int s = e[k].s, t = e[k + 1].s;
        if (s == t || e[k].up == e[k + 1].up ||
            v3_dot(o->snormal[s], o->snormal[t]) < 1 - FLAT_NORMAL || !on_plane(o, s, t) ||
            !on_plane(o, t, s))
            continue;
        const int rs = occ_uf_find(parent, s), rt = occ_uf_find(parent, t);
        parent[rs < rt ? rt : rs] = rs < rt ? rs : rt;
    }
    free(e);
    return RAD_OK;
}

/* A polygon while a group is merged: its vertices (indices into the
 * group's distinct vertices), its members. */
typedef struct flat_poly {
    int *v, n;
    int nmember;
    int alive;
} flat_poly;

/* The turn at b from a -> b to b -> c about nrm, and whether it is
 * straight within FLAT_TURN. */
static double turn(rad_vec3 a, rad_vec3 b, rad_vec3 c, rad_vec3 nrm, int *straight)
{
    const rad_vec3 u = v3_sub(b, a), w = v3_sub(c, b);
    const double t = v3_dot(nrm, v3_cross(u, w));
    *straight = fabs(t) <= FLAT_TURN * v3_norm(u) * v3_norm(w);
    return t;
}

static double area_of(const rad_vec3 *pt, const int *v, int n, rad_vec3 nrm)
{
    rad_vec3 s = v3(0, 0, 0);
    for (int k = 0; k < n; k++)
        s = v3_add(s, v3_cross(pt[v[k]], pt[v[(k + 1) % n]]));
    return 0.5 * v3_dot(s, nrm);
}

/* Merge q into p along p's edge k (p.v[k] -> p.v[k+1]), which q runs the
 * other way at its edge l; 1 when done, 0 when the union is not a convex
 * polygon, -1. */
static int merge(flat_poly *p, flat_poly *q, int k, int l, const rad_vec3 *pt, rad_vec3 nrm)
{
    const int n = p->n + q->n - 2;
    int *m = malloc(sizeof *m * (size_t)n), c = 0;
    if (!m)
        return -1;
    for (int i = 0; i < p->n; i++) /* p from v[k+1] round to v[k] */
        m[c++] = p->v[(k + 1 + i) % p->n];
    for (int i = 2; i < q->n; i++) /* q after its copy of v[k] round to before v[k+1] */
        m[c++] = q->v[(l + i) % q->n];
    /* the edges the two share run there and back (x, y, x): drop them */
    for (int again = 1; again && c >= 3;) {
        again = 0;
        for (int i = 0; i < c && c >= 3; i++)
            if (m[i] == m[(i + 2) % c]) {
                const int a = (i + 1) % c, b = (i + 2) % c; /* y and the second x */
                int w = 0;
                for (int j = 0; j < c; j++)
                    if (j != a && j != b)
                        m[w++] = m[j];
                c = w;
                again = 1;
                break;
            }
    }
    int ok = c >= 3;
    for (int i = 0; i < c && ok; i++)
        for (int j = i + 1; j < c && ok; j++)
            ok = m[i] != m[j];
    for (int i = 0; i < c && ok; i++) {
        int straight;
        const double t = turn(pt[m[(i + c - 1) % c]], pt[m[i]], pt[m[(i + 1) % c]], nrm, &straight);
        ok = straight || t > 0;
    }
    const double ap = area_of(pt, p->v, p->n, nrm), aq = area_of(pt, q->v, q->n, nrm);
    if (ok && fabs(area_of(pt, m, c, nrm) - (ap + aq)) > 1e-12 * (ap + aq))
        ok = 0;
    if (!ok) {
        free(m);
        return 0;
    }
    free(p->v);
    p->v = m;
    p->n = c;
    p->nmember += q->nmember;
    free(q->v);
    q->v = NULL;
    q->alive = 0;
    return 1;
}

/* An edge u -> v of the group's distinct vertices, and the polygon it
 * belongs to (u < 0: an empty slot of the table). */
typedef struct flat_key {
    int u, v, owner;
} flat_key;

static uint64_t key_hash(int u, int v, int size)
{
    uint64_t h = (uint64_t)(unsigned)u * 0x9e3779b97f4a7c15u ^ (uint64_t)(unsigned)v * 0xc2b2ae3d27d4eb4fu;
    return (h ^ h >> 31) & (uint64_t)(size - 1);
}

/* The slot of edge u -> v in the table (its own, or the empty one where it
 * would go). */
static flat_key *slot(flat_key *t, int size, int u, int v)
{
    for (uint64_t h = key_hash(u, v, size);; h = (h + 1) & (uint64_t)(size - 1))
        if (t[h].u < 0 || (t[h].u == u && t[h].v == v))
            return t + h;
}

static void own_edges(flat_key *t, int size, const flat_poly *p, int id)
{
    for (int k = 0; k < p->n; k++) {
        flat_key *e = slot(t, size, p->v[k], p->v[(k + 1) % p->n]);
        e->u = p->v[k];
        e->v = p->v[(k + 1) % p->n];
        e->owner = id;
    }
}

/* Merge the polygons of one group as far as they stay convex; into[k]:
 * the polygon that took polygon k (k itself while it is alive). */
static int merge_group(flat_poly *poly, int np, const rad_vec3 *pt, rad_vec3 nrm, flat_key *t,
                       int size, int *into)
{
    for (int i = 0; i < np; i++)
        into[i] = i;
    for (int i = 0; i < size; i++)
        t[i].u = -1;
    for (int i = 0; i < np; i++)
        own_edges(t, size, poly + i, i);
    for (int i = 0; i < np; i++) {
        flat_poly *p = poly + i;
        for (int k = 0; p->alive && k < p->n; k++) {
            const int u = p->v[k], w = p->v[(k + 1) % p->n];
            const flat_key *e = slot(t, size, w, u);
            if (e->u < 0 || e->owner == i || !poly[e->owner].alive)
                continue;
            flat_poly *q = poly + e->owner;
            int l = -1;
            for (int j = 0; j < q->n && l < 0; j++)
                if (q->v[j] == w && q->v[(j + 1) % q->n] == u)
                    l = j;
            if (l < 0)
                continue;
            const int qi = e->owner, r = merge(p, q, k, l, pt, nrm);
            if (r < 0)
                return -1;
            if (r > 0) {
                into[qi] = i;
                own_edges(t, size, p, i);
                k = -1; /* p changed: its edges again */
            }
        }
    }
    return 0;
}

static int vid_cmp(const void *pa, const void *pb)
{
    return occ_vec_cmp(*(const rad_vec3 *)pa, *(const rad_vec3 *)pb);
}

/* Store p (of the group's points pt) as patch o->npatch, its straight
 * vertices dropped; rep: one of its members (for the normal). */
static rad_status add_patch(rad_occ *o, const flat_poly *p, const rad_vec3 *pt, rad_vec3 nrm,
                            int rep, int *capv)
{
    const int at = o->pfirst[o->npatch];
    if (at + p->n > *capv) {
        rad_vec3 *q = occ_realloc(o->pv, capv, at + p->n, sizeof *q);
        if (!q)
            return RAD_ERR_NOMEM;
        o->pv = q;
    }
    int c = 0;
    for (int k = 0; k < p->n; k++) {
        int straight;
        turn(pt[p->v[(k + p->n - 1) % p->n]], pt[p->v[k]], pt[p->v[(k + 1) % p->n]], nrm,
             &straight);
        if (!straight)
            o->pv[at + c++] = pt[p->v[k]];
    }
    o->prep[o->npatch] = rep;
    o->pfirst[++o->npatch] = at + c;
    return RAD_OK;
}

/* One group, the surfaces members[0 .. nm): its polygons merged, and
 * each merged one of two or more members a patch.  Returns RAD_OK,
 * RAD_ERR_NOMEM. */
static rad_status patch_group(rad_occ *o, const int *members, int nm, int *capv)
{
    int total = 0;
    for (int k = 0; k < nm; k++)
        total += o->sfirst[members[k] + 1] - o->sfirst[members[k]];
    rad_vec3 *pt = malloc(sizeof *pt * (size_t)total);
    flat_poly *poly = calloc((size_t)nm, sizeof *poly);
    int size = 16;
    while (size < 4 * total)
        size *= 2;
    flat_key *t = malloc(sizeof *t * (size_t)size);
    int *owner = malloc(sizeof *owner * (size_t)nm);
    rad_status st = pt && poly && t && owner ? RAD_OK : RAD_ERR_NOMEM;
    int npt = 0;
    for (int k = 0; k < nm && st == RAD_OK; k++)
        for (int i = o->sfirst[members[k]]; i < o->sfirst[members[k] + 1]; i++)
            pt[npt++] = o->sv[i];
    if (st == RAD_OK) {
        qsort(pt, (size_t)npt, sizeof *pt, vid_cmp);
        int w = 0;
        for (int i = 0; i < npt; i++)
            if (w == 0 || occ_vec_cmp(pt[w - 1], pt[i]))
                pt[w++] = pt[i];
        npt = w;
    }
    for (int k = 0; k < nm && st == RAD_OK; k++) {
        const int s = members[k], n = o->sfirst[s + 1] - o->sfirst[s];
        if (!(poly[k].v = malloc(sizeof *poly[k].v * (size_t)n))) {
            st = RAD_ERR_NOMEM;
            break;
        }
        for (int i = 0; i < n; i++) {
            const rad_vec3 *f = bsearch(o->sv + o->sfirst[s] + i, pt, (size_t)npt, sizeof *pt,
                                        vid_cmp);
            poly[k].v[i] = (int)(f - pt);
        }
        poly[k].n = n;
        poly[k].nmember = 1;
        poly[k].alive = 1;
    }
    const rad_vec3 nrm = o->snormal[members[0]];
    if (st == RAD_OK && merge_group(poly, nm, pt, nrm, t, size, owner))
        st = RAD_ERR_NOMEM;
    for (int i = 0; i < nm && st == RAD_OK; i++) {
        if (!poly[i].alive || poly[i].nmember < 2)
            continue;
        if ((st = add_patch(o, poly + i, pt, nrm, members[i], capv)) != RAD_OK)
            break;
        for (int k = 0; k < nm; k++) { /* the members it took, directly or not */
            int r = k;
            while (owner[r] != r)
                r = owner[r];
            if (r == i)
                o->patch[members[k]] = o->npatch - 1;
        }
    }
    for (int k = 0; k < nm; k++)
        free(poly[k].v);
    free(poly);
    free(pt);
    free(t);
    free(owner);
    return st;
}

rad_status occ_find_patches(rad_occ *o)
{
    const int ns = o->nsurf;
    o->npatch = 0;
    o->patch = malloc(sizeof *o->patch * (size_t)(ns > 0 ? ns : 1));
    o->pfirst = malloc(sizeof *o->pfirst * (size_t)(ns + 1));
    o->prep = malloc(sizeof *o->prep * (size_t)(ns > 0 ? ns : 1));
    int *parent = malloc(sizeof *parent * (size_t)(ns > 0 ? ns : 1));
    int *order = malloc(sizeof *order * (size_t)(ns > 0 ? ns : 1));
    unsigned char *twinned = calloc((size_t)(ns > 0 ? ns : 1), 1);
    rad_status st = o->patch && o->pfirst && o->prep && parent && order && twinned
                        ? RAD_OK
                        : RAD_ERR_NOMEM;
    int capv = 0;
    if (st == RAD_OK) {
        o->pfirst[0] = 0;
        for (int s = 0; s < ns; s++) {
            o->patch[s] = -1;
            parent[s] = s;
            if (o->twin[s] >= 0)
                twinned[o->twin[s]] = 1;
        }
        st = join(o, twinned, parent);
    }
    if (st == RAD_OK) {
        /* the members of each root, together: surfaces in order of root */
        int *count = calloc((size_t)ns + 1, sizeof *count);
        if (!count)
            st = RAD_ERR_NOMEM;
        for (int s = 0; s < ns && count; s++)
            count[occ_uf_find(parent, s) + 1]++;
        for (int s = 0; s < ns && count; s++)
            count[s + 1] += count[s];
        for (int s = 0; s < ns && count; s++)
            order[count[occ_uf_find(parent, s)]++] = s;
        free(count);
        for (int a = 0; a < ns && st == RAD_OK;) {
            int b = a + 1;
            while (b < ns && occ_uf_find(parent, order[b]) == occ_uf_find(parent, order[a]))
                b++;
            if (b - a >= 2)
                st = patch_group(o, order + a, b - a, &capv);
            a = b;
        }
    }
    free(parent);
    free(order);
    free(twinned);
    return st;
}

/* The pair's blockers sp->bid[0 .. nb), sp->blk, with those of one patch
 * replaced by the patch (the rule of the header); sa, sb: the pair's
 * surfaces.  Returns the new count, -1. */
int occ_flat_blockers(const rad_occ *o, occ_space *sp, int nb, int sa, int sb, rad_vec3 origin)
{
    if (o->npatch == 0 || nb < 2)
        return nb;
    const int pa = o->patch[sa], pb = o->patch[sb];
    int any = 0;
    for (int k = 0; k < nb && !any; k++) {
        const int g = o->patch[sp->bid[k]];
        for (int l = k + 1; l < nb && g >= 0 && g != pa && g != pb && !any; l++)
            any = o->patch[sp->bid[l]] == g;
    }
    if (!any)
        return nb;
    /* build the new list in sp->blkc (free until the blockers are clipped) */
    occ_ps_clear(&sp->blkc);
    int w = 0;
    for (int k = 0; k < nb; k++) {
        const int c = sp->bid[k], g = o->patch[c];
        int many = 0, first = 1;
        if (g >= 0 && g != pa && g != pb)
            for (int l = 0; l < nb; l++)
                if (l != k && o->patch[sp->bid[l]] == g) {
                    many = 1;
                    first = first && l > k;
                }
        if (many && !first)
            continue; /* the patch is there already */
        int r;
        if (many)
            r = occ_ps_push_shifted(&sp->blkc, o->pv + o->pfirst[g], o->pfirst[g + 1] - o->pfirst[g],
                                    origin);
        else
            r = occ_ps_push(&sp->blkc, sp->blk.v + sp->blk.first[k], sp->blk.first[k + 1] - sp->blk.first[k]);
        if (r)
            return -1;
        sp->bid[w++] = many ? o->prep[g] : c;
    }
    polyset t = sp->blk;
    sp->blk = sp->blkc;
    sp->blkc = t;
    return w;
}
