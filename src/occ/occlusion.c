/* occlusion.c -- hidden surfaces in the form factors: the pair hook
 * radi_occ_pair, its per-thread work space and its statistics.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The matrix fill (ffmatrix.c) hands each unordered pair {i, j} with its
 * unoccluded contour sum S to radi_occ_pair (occlusion.h), which leaves S
 * alone when nothing can stand between the two elements and otherwise
 * subtracts what is hidden.  The work is in four files, one job each:
 *   occshaft.c   which pairs can be blocked at all (shaft culling): the
 *                scene's setup (a walk of a tree of the surfaces' boxes,
 *                occtree.c) and each pair's short list of blockers, its
 *                coplanar neighbours taken as one patch (occflat.c), less
 *                the faces of a convex block or a closed mesh that its
 *                other faces make redundant for the pair (occsolid.c,
 *                occclosed.c);
 *   occhidden.c  how much of a pair is hidden: fully by one blocker, or the
 *                integral of the hidden part over the outer element;
 *   occdomain.c  where on the outer element anything can be hidden (the
 *                domain of that integral: penumbras, umbras, events);
 *   occpoint.c   the hidden part seen from one point (cone cuts, shadows,
 *                the point-to-polygon form factor), by occunion.c's
 *                boundary of the union of the shadows where it applies;
 * with helpers of one job each too: occrule.c (the quadrature rules on one
 * cell of that integral), occleaves.c (the cell with the largest error
 * estimate), occevent.c and occeee.c (events, for occdomain.c); all
 * on the polygon toolkit (polygon.h: distances, clipping, area) and the
 * growable lists of convex pieces of occspace.c (with the tolerances).
 *
 * Each pair is worked in its own frame (coordinates less the centroid
 * of element i), so that the points the cuts construct keep the digits
 * of the pair, not those of its distance from the origin (local_frame).
 *
 * Accuracy modes: classic evaluates the penumbras' pieces once, uncut by
 * the umbras (occdomain.c; the 3-point rule on the four midpoint children
 * of each fan triangle, or on a small triangle itself: OCC_CLASSIC_ONCE)
 * and stops.  Default and reference cut the pieces along the umbras and
 * along the event planes of each blocker (occdomain.c,
 * split_events; in default mode only where the events happen
 * (occevent.c) for a pair with few blockers, and the events of two
 * blockers only where they happen for every pair, when the pair meets
 * its target so; occhidden.c, orient_integral; never along the events
 * of a triangulated model's inside, occmesh.c), integrate with Gauss product rules of
 * rising order on quadrilateral and triangular cells (occrule.c; up to
 * OCC_ORDER_DEFAULT / OCC_ORDER_REFERENCE) and split cells where the
 * order does not help, until the estimated error is
 * below half the mode's promise (1e-6, 1e-9) of the occluded A_o F_ot
 * itself, down to pairs hidden to OCC_FLOOR = 1e-4 of their unoccluded
 * value (occhidden.c, integrate), or a pair's budget of leaves and
 * evaluations is spent.  A pair whose every point sees something hidden
 * is integrated as its visible part directly (occpoint.c, occ_hidden_at):
 * its value then owes nothing to the kernel's unoccluded S.  Otherwise,
 * when the kernel's estimate of S is too large a part of the occluded
 * value, S is computed again by the reference kernel, to a quarter of
 * the promise of the occluded value (sharper_sum).  The promise, and the
 * fill's count of entries that miss it, are relative to the occluded
 * value down to that floor, and to OCC_FLOOR of the unoccluded value
 * below it (radi_occ_pair's *scale).
 * Measured against independent references (tests/occref.py: parallel
 * rectangles with a blocker between them, centred, off-centre, near
 * either plate, hiding all but 4e-5, small elements in a penumbra):
 * default within 5e-9, reference within 5e-12, every estimate above the
 * error; hiding all but 1.5e-7, beyond the promise's floor: default
 * within 4.2e-7 of the value (6e-10 of the floor), reference 3.5e-11.
 * Each unordered pair is done once: the result is the symmetric A_i F_ij,
 * and reciprocity stays exact.
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
#include "radiosity/formfactor.h"


/* The pair in its own frame: vertices and centroids less `origin` (the
 * centroid of i), into sp->loc and *li, *lj (the rest as in pi, pj).  The
 * points the cuts construct (v3_lerp) are then rounded relative to the
 * pair's size, not to the scene's coordinates: a pair 1e-5 across at 3e5
 * from the origin keeps ten digits instead of five. */
static int local_frame(occ_space *sp, const rad_ff_poly *pi, const rad_ff_poly *pj,
                       rad_vec3 origin, rad_ff_poly *li, rad_ff_poly *lj)
{
    occ_ps_clear(&sp->loc);
    if (occ_ps_push_shifted(&sp->loc, pi->v, pi->n, origin) ||
        occ_ps_push_shifted(&sp->loc, pj->v, pj->n, origin))
        return -1;
    *li = *pi;
    *lj = *pj;
    li->v = sp->loc.v;
    lj->v = sp->loc.v + sp->loc.first[1];
    li->centroid = v3_sub(pi->centroid, origin);
    lj->centroid = v3_sub(pj->centroid, origin);
    li->lo = v3_sub(pi->lo, origin);
    li->hi = v3_sub(pi->hi, origin);
    lj->lo = v3_sub(pj->lo, origin);
    lj->hi = v3_sub(pj->hi, origin);
    li->edges = lj->edges = NULL; /* relative to the centroids: not needed here */
    return 0;
}

void radi_occ_work_init(rad_occ_work *w, const rad_occ *occ)
{
    memset(w, 0, sizeof *w);
    w->occ = occ;
    radi_ff_scratch_init(&w->kernel);
}

void radi_occ_work_free(rad_occ_work *w)
{
    if (w->space) {
        occ_space_free(w->space);
        free(w->space);
    }
    w->space = NULL;
    radi_ff_scratch_free(&w->kernel);
}

/* The kernel's error estimate e0 of the unoccluded S is relative to S (the
 * default kernel aims at 5e-7 S, the reference kernel at 5e-10 S:
 * formfactor.c), but the promise is relative to the occluded value, which
 * for a pair hidden to a fraction f is f S: e0 may then be up to 5e-7 / f
 * or 5e-10 / f of it.  When e0 takes more than OCC_KERNEL_SHARE of the
 * mode's promise of the occluded value (of OCC_FLOOR S at least, the
 * promise's floor), S and e0 are computed again by the reference kernel
 * aiming at that share (radi_ff_pair_within): the difference shifts the
 * occluded value, whose hidden part does not depend on S.  Returns 0, or
 * -1 when memory ran out. */
static int sharper_sum(rad_occ_work *w, const rad_ff_poly *polys, int i, int j, double s0,
                       double *snew, double *e0)
{
    const double promise = radi_ff_promise(w->occ->accuracy);
    const double target = OCC_KERNEL_SHARE * promise * fmax(*snew, OCC_FLOOR * s0);
    if (!(*snew > 0) || !(s0 > 0) || *e0 <= target)
        return 0;
    rad_ff_options opt;
    rad_ff_options_init(&opt);
    opt.accuracy = RAD_ACCURACY_REFERENCE;
    double s, e = 0;
    if (isnan(radi_ff_pair_within(&polys[i], &polys[j], &opt, target / s0, &w->kernel, &s, &e)))
        return -1;
    if (!(e < *e0))
        return 0; /* no better than the first */
    double v = *snew + (s - s0);
    *snew = v < 0 ? 0 : v > s ? s : v;
    *e0 = e;
    return 0;
}

void radi_occ_stats_add(rad_occ_stats *into, const rad_occ_stats *from)
{
    into->needed |= from->needed;
    into->pairs_tested += from->pairs_tested;
    into->pairs_blockable += from->pairs_blockable;
    into->pairs_blocked += from->pairs_blocked;
    into->pairs_partial += from->pairs_partial;
    into->candidates += from->candidates;
    into->evaluations += from->evaluations;
    into->max_errest = fmax(into->max_errest, from->max_errest);
    into->seconds += from->seconds;
}

/* What radi_occ_pair and radi_occ_pair_route both start with (pair_start):
 * the pair's surfaces, its polygons in a frame at i's centroid, the clip
 * of each by the other's plane, and the clock when there is work. */
typedef struct pair_frame {
    int sa, sb, clip;
    rad_ff_poly li, lj;
    rad_vec3 origin;
    double t0;
} pair_frame;

/* Fill f and the pair's snap (sp->snap).  Returns 1 so, 0 when no
 * surface can block the pair, -1 when memory ran out. */
static int pair_start(rad_occ_work *w, const rad_ff_poly *polys, int i, int j, pair_frame *f)
{
    const rad_occ *o = w->occ;
    f->sa = o->esurf[i];
    f->sb = o->esurf[j];
    if (f->sa == f->sb)
        return 0;
    int a = f->sa < f->sb ? f->sa : f->sb, b = f->sa < f->sb ? f->sb : f->sa;
    size_t p = pair_index(a, b, o->nsurf);
    if (o->cand_off[p + 1] == o->cand_off[p])
        return 0;
    f->t0 = radi_seconds(); /* the work's time starts here (stats.seconds) */
    if (!w->space && !(w->space = calloc(1, sizeof(occ_space))))
        return -1;
    occ_space *sp = w->space;
    f->origin = polys[i].centroid;
    if (local_frame(sp, &polys[i], &polys[j], f->origin, &f->li, &f->lj))
        return -1;
    sp->snap = occ_pair_snap(o, f->sa, f->sb, o->cand + o->cand_off[p],
                             (int)(o->cand_off[p + 1] - o->cand_off[p]));
    f->clip = occ_clip_pair(sp, f->li.v, f->li.n, f->li.normal, f->lj.v, f->lj.n, f->lj.normal,
                            sp->snap);
    return 1;
}

int radi_occ_pair(rad_occ_work *w, const rad_ff_poly *polys, int i, int j, double *s,
                 double *errest, double *scale)
{
    const rad_occ *o = w->occ;
    const double s0 = *s;
    if (scale)
        *scale = fabs(s0);
    if (!o || !(*s > 0))
        return 0;
    w->stats.pairs_tested++;
    pair_frame f;
    const int go = pair_start(w, polys, i, j, &f);
    if (go <= 0)
        return go;
    occ_space *sp = w->space;
    const rad_ff_poly *pi = &f.li, *pj = &f.lj;
    int nb = f.clip > 0 ? occ_pair_blockers(o, sp, f.sa, f.sb, pi, pj, f.origin) : f.clip;
    double snew = *s, e0 = errest ? *errest : 0, eocc = 0;
    if (nb > 0) {
        w->stats.pairs_blockable++;
        w->stats.candidates += nb;
        int direct = 0;
        if (occ_occluded_sum(o, sp, &w->stats, nb, pi, pj, *s, &snew, &eocc, &direct))
            nb = -1;
        else if (direct)
            e0 = 0; /* the value does not depend on S (occhidden.c) */
        else if (errest && snew != *s && sharper_sum(w, polys, i, j, *s, &snew, &e0))
            nb = -1;
        if (errest)
            *errest = e0 + eocc;
    }
    *s = snew;
    if (scale)
        *scale = fmax(fabs(snew), OCC_FLOOR * s0);
    w->stats.seconds += radi_seconds() - f.t0;
    return nb < 0 ? -1 : 0;
}

int radi_occ_pair_route(rad_occ_work *w, const rad_ff_poly *polys, int i, int j, int *ids,
                       int cap, double *snap)
{
    *snap = 0;
    if (!w->occ)
        return 0;
    pair_frame f;
    const int go = pair_start(w, polys, i, j, &f);
    if (go <= 0)
        return go;
    occ_space *sp = w->space;
    *snap = sp->snap;
    const int nb =
        f.clip > 0 ? occ_pair_shaft(w->occ, sp, f.sa, f.sb, &f.li, &f.lj, f.origin) : f.clip;
    if (nb > cap)
        return -2;
    for (int k = 0; k < nb; k++)
        ids[k] = sp->bid[k];
    return nb;
}

void radi_occ_stats_to_ff(const rad_occ_stats *v, rad_ff_stats *st)
{
    st->vis_needed = v->needed;
    st->vis_pairs_tested = v->pairs_tested;
    st->vis_pairs_blockable = v->pairs_blockable;
    st->vis_pairs_blocked = v->pairs_blocked;
    st->vis_pairs_partial = v->pairs_partial;
    st->vis_seconds = v->seconds;
    st->vis_candidates = v->candidates;
    st->vis_evaluations = v->evaluations;
}
