/* occspace.c -- the occlusion code's per-thread work space: growable
 * arrays, lists of convex pieces (polysets), and the two cuts the rest is
 * made of (clip a polygon into a list; cut a piece by a set of planes).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Everything grows on demand and is kept between pairs, so that a fill
 * allocates only while its pairs still grow.  Every function that can
 * allocate returns -1 when memory runs out, and the callers pass that up
 * to radi_occ_pair.  The cuts work on polygon.h's distances and clip, with
 * the pair's tolerance (snap) and after poly_settle_signs, so a clip
 * of an n-gon never has more than n + 1 vertices.
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


/* The capacity to grow to for `need` elements. */
static int new_cap(int cap, int need)
{
    int c = cap > 16 ? cap : 16;
    while (c < need)
        c *= 2;
    return c;
}

/* The array p (capacity *cap elements of `size` bytes) reallocated for
 * `need`; NULL when memory ran out (then p and *cap are untouched). */
void *occ_realloc(void *p, int *cap, int need, size_t size)
{
    int c = new_cap(*cap, need);
    void *q = realloc(p, size * (size_t)c);
    if (q)
        *cap = c;
    return q;
}

/* Room for one more polygon of up to n vertices at s->v + s->nv. */
static int ps_reserve(polyset *s, int n)
{
    if (occ_grow_v3(&s->v, &s->capv, s->nv + n) ||
        occ_grow_i(&s->first, &s->capp, s->np + 2))
        return -1;
    s->first[s->np] = s->nv;
    return 0;
}

/* Close the polygon written at s->v + s->nv with n vertices. */
static void ps_commit(polyset *s, int n)
{
    s->nv += n;
    s->np++;
    s->first[s->np] = s->nv;
}

int occ_ps_push(polyset *s, const rad_vec3 *p, int n)
{
    if (ps_reserve(s, n))
        return -1;
    memcpy(s->v + s->nv, p, sizeof *p * (size_t)n);
    ps_commit(s, n);
    return 0;
}

/* ps_push of p less `origin` (into the pair's local frame). */
int occ_ps_push_shifted(polyset *s, const rad_vec3 *p, int n, rad_vec3 origin)
{
    if (ps_reserve(s, n))
        return -1;
    for (int k = 0; k < n; k++)
        s->v[s->nv + k] = v3_sub(p[k], origin);
    ps_commit(s, n);
    return 0;
}

/* Drop the last polygon of s. */
void occ_ps_pop(polyset *s)
{
    s->np--;
    s->nv = s->first[s->np];
}

static void ps_free(polyset *s)
{
    free(s->v);
    free(s->first);
    memset(s, 0, sizeof *s);
}

void occ_space_free(occ_space *sp)
{
    ps_free(&sp->loc);
    ps_free(&sp->elem);
    ps_free(&sp->blk);
    ps_free(&sp->blkc);
    ps_free(&sp->cur);
    ps_free(&sp->next);
    free(sp->bid);
    free(sp->xcull);
    free(sp->bx);
    free(sp->bn);
    free(sp->bc);
    free(sp->br);
    free(sp->rem);
    free(sp->tmp);
    free(sp->tmp2);
    free(sp->d);
    free(sp->cone);
    free(sp->conep);
    free(sp->sn);
    free(sp->sa);
    free(sp->sfirst);
    free(sp->empty);
    free(sp->tw);
    free(sp->pn);
    free(sp->pa);
    free(sp->pfirst);
    free(sp->clist);
    ps_free(&sp->da);
    ps_free(&sp->db);
    ps_free(&sp->dom);
    free(sp->pcen);
    free(sp->qcen);
    free(sp->prad);
    free(sp->qrad);
    ps_free(&sp->umb);
    ps_free(&sp->arc);
    ps_free(&sp->arc2);
    free(sp->pj0);
    free(sp->pj1);
    free(sp->hn);
    free(sp->ha);
    free(sp->node);
    occ_leaves_free(&sp->leaves);
    ps_free(&sp->sh);
    free(sp->box);
    free(sp->nbr);
    free(sp->nbr_off);
    free(sp->fill);
    free(sp->sweep);
    free(sp->uv);
    free(sp->tuv);
    free(sp->upl);
    free(sp->iv);
    free(sp->inner);
    free(sp->ehash);
    free(sp->ccut);
    free(sp->seg);
    free(sp->mflag);
    free(sp->mside);
    free(sp->medge);
    free(sp->mends);
    memset(sp, 0, sizeof *sp);
}

/* Clip p to the front (nrm . (q - a) >= 0) of a plane into set s; returns
 * the vertex count kept (0 when nothing or too little is left), -1 when
 * memory ran out. */
int occ_clip_into(occ_space *sp, polyset *s, const rad_vec3 *p, int n, rad_vec3 nrm,
                  rad_vec3 a, double tol)
{
    double lo, hi;
    if (occ_grow_d(&sp->d, &sp->capd, n) || ps_reserve(s, n + 1))
        return -1;
    poly_distances(p, n, nrm, a, tol, sp->d, &lo, &hi);
    poly_settle_signs(sp->d, n, &lo, &hi);
    if (hi <= 0)
        return 0;
    int m = poly_clip_side(p, sp->d, n, 1.0, s->v + s->nv, n + 1);
    if (m < 3)
        return 0;
    ps_commit(s, m);
    return m;
}

/* Cut the polygon in sp->rem (*n vertices) by the planes through pt[k]
 * with inward unit normals nrm[k]: the parts outside some plane go to
 * `out`; returns 1 when a part inside all planes is left in sp->rem (*n
 * vertices), 0 when not, -1 on memory.  A side of no more than `sliver`
 * area is handled by `slivers`:
 *   OCC_SLIVERS_DROP   dropped, on either side;
 *   OCC_SLIVERS_KEEP   kept, a piece like any other (only a side without
 *                      area is dropped);
 *   OCC_SLIVERS_MERGE  an outside sliver stays with the inside part (the
 *                      plane does not cut), an inside one is kept.
 * Dropping loses the sliver's area, and whatever is hidden there.  For a
 * piece of the inner element seen from one point (occpoint.c) that is
 * about 1e-10 of F(x -> A_t) per piece dropped: far below the promise,
 * but for a pair hidden to OCC_FLOOR up to 1e-6 of its visible value (no
 * such case seen).  For the outer element's domain
 * (occdomain.c) it is wrong: a cut repeated along many planes adds up.
 * Seen in a fuzzed room with a box standing 1.5e-4 of the room's size in
 * front of a wall (tests/geomfuzz.py seed 62, scene 1231;
 * tests/accuracy/closure.sh): the planes of the box's near face cut the domain on
 * a wall element into 95,000 pieces, the slivers dropped lost 6.8e-9 of
 * the element's area where four fifths of the floor was hidden, and the
 * element's reference row of F summed to 1 + 2.3e-9 under estimates of
 * 5e-10. */
int occ_cut_piece(occ_space *sp, const rad_vec3 *nrm, const rad_vec3 *pt, int np, double snap,
                  double sliver, int slivers, polyset *out, int *n)
{
    const double drop = slivers == OCC_SLIVERS_DROP ? sliver : 0;
    for (int k = 0; k < np; k++) {
        double lo, hi;
        if (occ_grow_d(&sp->d, &sp->capd, *n) || occ_grow_v3(&sp->tmp, &sp->captmp, *n + 1))
            return -1;
        poly_distances(sp->rem, *n, nrm[k], pt[k], snap, sp->d, &lo, &hi);
        poly_settle_signs(sp->d, *n, &lo, &hi);
        if (hi <= 0)
            return occ_ps_push(out, sp->rem, *n) ? -1 : 0; /* wholly outside */
        if (lo >= 0)
            continue; /* wholly inside this plane */
        int m = poly_clip_side(sp->rem, sp->d, *n, -1.0, sp->tmp, *n + 1);
        const double a = m >= 3 ? poly_area(sp->tmp, m) : 0;
        if (slivers == OCC_SLIVERS_MERGE && !(a > sliver))
            continue; /* the outside sliver stays with the inside part */
        if (a > drop && occ_ps_push(out, sp->tmp, m))
            return -1;
        m = poly_clip_side(sp->rem, sp->d, *n, 1.0, sp->tmp, *n + 1);
        if (m < 3 || !(poly_area(sp->tmp, m) > drop))
            return 0;
        occ_swap_v3(&sp->rem, &sp->caprem, &sp->tmp, &sp->captmp);
        *n = m;
    }
    return 1;
}

/* Copy polygon k of set s into sp->rem; returns its vertex count or -1. */
int occ_load_rem(occ_space *sp, const polyset *s, int k)
{
    int n = s->first[k + 1] - s->first[k];
    if (occ_grow_v3(&sp->rem, &sp->caprem, n))
        return -1;
    memcpy(sp->rem, s->v + s->first[k], sizeof *sp->rem * (size_t)n);
    return n;
}
