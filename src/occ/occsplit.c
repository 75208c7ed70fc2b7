/* occsplit.c -- the domain's pieces split by one plane.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The domain of occhidden.c's integral (occdomain.c) is a list of
 * disjoint convex pieces, sp->dom, each with a bounding sphere about its
 * vertex mean.  Both the domain's own cuts (occdomain.c: penumbras,
 * umbras, event planes) and the chords of three-edge events (occeee.c)
 * split those pieces by planes; the splitter is here, below both, with
 * the spheres that let it pass over the pieces a plane misses.  Lengths
 * are those of the pair's frame (occlusion.h); the snap and sliver
 * tolerances are the pair's (pair_ctx).
 */
#include <config.h>

#include <math.h>

#include "occ/occlusion.h"
#include "occ/occspace.h"
#include "util/util.h"
#include "radiosity/base.h"

/* Append polygon p (n vertices) to sp->db with its bounding sphere
 * (centre cen, radius rad); 0 or -1. */
static int push_db(occ_space *sp, const rad_vec3 *p, int n, rad_vec3 cen, double rad)
{
    int k = sp->db.np;
    if (occ_grow_v3(&sp->qcen, &sp->capqc, k + 1) || occ_grow_d(&sp->qrad, &sp->capqr, k + 1) ||
        occ_ps_push(&sp->db, p, n))
        return -1;
    sp->qcen[k] = cen;
    sp->qrad[k] = rad;
    return 0;
}

/* The bounding sphere of p about its vertex mean. */
static void sphere(const rad_vec3 *p, int n, rad_vec3 *cen, double *rad)
{
    rad_vec3 c = poly_mean(p, n);
    double r2 = 0;
    for (int k = 0; k < n; k++) {
        rad_vec3 e = v3_sub(p[k], c);
        double x = v3_dot(e, e);
        r2 = x > r2 ? x : r2;
    }
    *cen = c;
    *rad = sqrt(r2);
}

/* The bounding spheres of sp->dom's pieces, for occ_split_dom. */
int occ_dom_spheres(occ_space *sp)
{
    int np = sp->dom.np;
    if (occ_grow_v3(&sp->pcen, &sp->cappc, np) || occ_grow_d(&sp->prad, &sp->cappr, np))
        return -1;
    for (int k = 0; k < np; k++)
        sphere(sp->dom.v + sp->dom.first[k], sp->dom.first[k + 1] - sp->dom.first[k],
               &sp->pcen[k], &sp->prad[k]);
    return 0;
}

/* Split every piece of sp->dom that the plane through a with unit normal
 * nrm crosses (their spheres in sp->pcen / prad, kept up to date; a
 * piece one of whose sides would have no more than `sliver` area, or
 * whose two sides would overlap, below, is left whole), but
 * with a wedge w (not NULL) and c->events OCC_SPLIT_WEDGES only where the
 * plane's chord of the piece meets w.  A
 * piece whose bounding sphere the plane misses is copied without looking
 * at its vertices: with a K-gon blocker there are O(K) planes and O(K^2)
 * pieces, most of them far from any one plane (reference mode once
 * slowed as K^4).
 *
 * A plane that is all but the piece's own plane (an event plane through
 * an edge and a vertex that both lie on the outer element's plane, but for
 * the coordinates' round-off) meets it where round-off says: the snap can
 * set two neighbouring vertices on it and let it cross an edge elsewhere
 * too, and the two sides then overlap in the triangle between.  Seen in a
 * fuzzed room turned and moved 1e6 away (tests/geomfuzz.py seed 55, scene
 * 375): the sides of 97% of a floor strip overlapped by 1.8% of it, and
 * two pairs, integrated over their pieces, came out 1.7% and 2.2% high
 * in both modes with estimates of 1.5e-7 and 5e-7 of themselves.  (The
 * penumbras' partition below cuts with occ_cut_piece, whose sides could
 * overlap the same way; not seen.)  Such a plane has no event on the
 * piece to cut; the piece stays whole when the sides' areas add up to
 * more than its own.  Returns 0 or -1. */
int occ_split_dom(occ_space *sp, const pair_ctx *c, rad_vec3 nrm, rad_vec3 a,
                     const occ_wedge *w, double sliver)
{
    occ_ps_clear(&sp->db);
    for (int k = 0; k < sp->dom.np; k++) {
        const rad_vec3 *p = sp->dom.v + sp->dom.first[k];
        int n = sp->dom.first[k + 1] - sp->dom.first[k];
        double lo, hi;
        if (fabs(v3_dot(nrm, v3_sub(sp->pcen[k], a))) > sp->prad[k] + c->snap) {
            if (push_db(sp, p, n, sp->pcen[k], sp->prad[k]))
                return -1;
            continue;
        }
        if (occ_grow_d(&sp->d, &sp->capd, n) || occ_grow_v3(&sp->tmp, &sp->captmp, n + 1))
            return -1;
        poly_distances(p, n, nrm, a, c->snap, sp->d, &lo, &hi);
        poly_settle_signs(sp->d, n, &lo, &hi);
        if (lo >= 0 || hi <= 0 ||
            (w && (c->events == OCC_SPLIT_WEDGES || w->always) && occ_event_misses(w, p, sp->d, n, c->snap))) {
            if (push_db(sp, p, n, sp->pcen[k], sp->prad[k]))
                return -1;
            continue;
        }
        if (occ_grow_v3(&sp->tmp2, &sp->captmp2, n + 1))
            return -1;
        const int m0 = poly_clip_side(p, sp->d, n, -1.0, sp->tmp, n + 1);
        const int m1 = poly_clip_side(p, sp->d, n, 1.0, sp->tmp2, n + 1);
        const double a0 = m0 >= 3 ? poly_area(sp->tmp, m0) : 0;
        const double a1 = m1 >= 3 ? poly_area(sp->tmp2, m1) : 0;
        if (!(a0 > sliver) || !(a1 > sliver) || a0 + a1 > (1 + 1e-9) * poly_area(p, n)) {
            /* a sliver is not cut off (it would be lost, and what is
             * hidden there with it: occspace.c, occ_cut_piece), and where
             * the sides overlap the plane is all but the piece's own (see
             * above): the piece stays whole */
            if (push_db(sp, p, n, sp->pcen[k], sp->prad[k]))
                return -1;
            continue;
        }
        rad_vec3 cen;
        double rad;
        sphere(sp->tmp, m0, &cen, &rad);
        if (push_db(sp, sp->tmp, m0, cen, rad))
            return -1;
        sphere(sp->tmp2, m1, &cen, &rad);
        if (push_db(sp, sp->tmp2, m1, cen, rad))
            return -1;
    }
    polyset t = sp->dom;
    sp->dom = sp->db;
    sp->db = t;
    occ_swap_v3(&sp->pcen, &sp->cappc, &sp->qcen, &sp->capqc);
    double *tr = sp->prad;
    sp->prad = sp->qrad;
    sp->qrad = tr;
    int ti = sp->cappr;
    sp->cappr = sp->capqr;
    sp->capqr = ti;
    return 0;
}

/* Split every piece of sp->dom that the plane through a with unit
 * normal nrm crosses, after occeee.c has cut pieces its own way:
 * occ_split_dom with their spheres measured again, leaving whole only the
 * pieces with a side without area, as occeee.c's chords do.  0 or -1. */
int occ_split_plane(occ_space *sp, const pair_ctx *c, rad_vec3 nrm, rad_vec3 a)
{
    return occ_dom_spheres(sp) ? -1 : occ_split_dom(sp, c, nrm, a, NULL, 0);
}
