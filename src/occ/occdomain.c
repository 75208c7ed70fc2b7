/* occdomain.c -- where on the outer element anything can be hidden: the
 * domain of occhidden.c's integral, as disjoint convex pieces.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * hidden(x) vanishes outside each blocker's penumbra region and equals
 * the unoccluded integrand inside its umbra; both regions are convex and
 * bounded by planes through an edge of the blocker and a vertex of the
 * inner element or the other way round (see below).  The outer element is
 * cut along those planes into convex pieces, and only the pieces inside
 * some penumbra are integrated: a thin penumbra, or a thin strip that
 * still sees past a silhouette, becomes a piece of its own instead of
 * falling between evaluation points.  In default and reference modes
 * the pieces are cut along the umbras too, those inside one kept apart
 * (known to be fully hidden there), and along the event planes
 * (split_events), everywhere or only where their events happen
 * (occevent.c).  Classic mode takes the penumbras' pieces as they are
 * (occ_support_domain).
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


/* The penumbra region of a convex blocker P lit by a convex polygon T, the
 * points z with a segment from z to T through P, is
 *     W = union over s >= 1 of (s P - (s - 1) T),
 * a union of Minkowski sums that is convex (the midpoint of points of
 * W(s1) and W(s2) lies in W((s1 + s2)/2)).  Its support function gives
 * its faces: the planes that touch P and separate it from T (through an
 * edge of one and a vertex of the other, or P's own plane), with W on P's
 * side.  hidden(x) vanishes outside the union of the blockers' W, so the
 * integral runs over the outer element's part of that union only: no
 * evaluation point is wasted where nothing is hidden, and a thin penumbra
 * is never missed between points. */

/* The umbra of P lit by T, the points z from which every segment to T
 * passes through P, is the intersection over y in T of the shadow C(y) of
 * P from y.  The set of y whose shadow holds z is itself convex (the cone
 * from z through P, beyond P), so the intersection over T is that over
 * T's vertices y_k: each C(y_k) is bounded by the planes through y_k and
 * an edge of P (the region on P's side) and by P's plane (the region away
 * from y_k).  When T reaches P's plane the umbra has no interior.  In
 * default and reference modes the pieces of the domain are cut along the
 * umbras too: hidden(x) then has no kink across a piece there, a thin
 * strip that still sees past a blocker's silhouette becomes a piece of
 * its own with its own evaluation points, and a piece inside an umbra is
 * known to be fully hidden. */

/* Append plane (nrm, a) with the region on the side where nrm . (q - a)
 * >= 0 if it separates p (that side) from t (the other side). */
static int add_if_separating(occ_space *sp, rad_vec3 nrm, rad_vec3 a, const rad_vec3 *p, int np,
                             const rad_vec3 *t, int nt, double tol, int *ns)
{
    double plo, phi, tlo, thi;
    if (occ_grow_d(&sp->d, &sp->capd, np > nt ? np : nt))
        return -1;
    poly_distances(p, np, nrm, a, tol, sp->d, &plo, &phi);
    poly_distances(t, nt, nrm, a, tol, sp->d, &tlo, &thi);
    int up = plo >= 0 && thi <= 0, down = phi <= 0 && tlo >= 0;
    if (!(up || down) || (plo == 0 && phi == 0 && tlo == 0 && thi == 0))
        return 0;
    if (occ_grow_v3(&sp->sn, &sp->capsn, *ns + 1) || occ_grow_v3(&sp->sa, &sp->capsa, *ns + 1))
        return -1;
    sp->sn[*ns] = up ? nrm : v3_scale(nrm, -1.0);
    sp->sa[*ns] = a;
    ++*ns;
    return 0;
}

/* Planes through an edge of e and a vertex of f that separate p from t. */
static int edge_vertex_planes(occ_space *sp, const rad_vec3 *e, int ne, const rad_vec3 *f, int nf,
                              const rad_vec3 *p, int np, const rad_vec3 *t, int nt, double tol,
                              int *ns)
{
    for (int k = 0; k < ne; k++)
        for (int l = 0; l < nf; l++) {
            rad_vec3 nrm;
            if (poly_edge_plane(e, ne, k, f[l], &nrm) &&
                add_if_separating(sp, nrm, e[k], p, np, t, nt, tol, ns))
                return -1;
        }
    return 0;
}

/* The faces of blocker b's penumbra, appended to sp->sn / sp->sa. */
static int penumbra_planes(occ_space *sp, const pair_ctx *c, int b, int *ns)
{
    const rad_vec3 *p = sp->blkc.v + sp->blkc.first[b];
    int np = sp->blkc.first[b + 1] - sp->blkc.first[b];
    if (add_if_separating(sp, sp->bn[b], p[0], p, np, c->t, c->nt, c->snap, ns) ||
        add_if_separating(sp, v3_scale(sp->bn[b], -1.0), p[0], p, np, c->t, c->nt, c->snap,
                          ns) ||
        edge_vertex_planes(sp, p, np, c->t, c->nt, p, np, c->t, c->nt, c->snap, ns) ||
        edge_vertex_planes(sp, c->t, c->nt, p, np, p, np, c->t, c->nt, c->snap, ns))
        return -1;
    return 0;
}

static int push_plane(occ_space *sp, rad_vec3 nrm, rad_vec3 a, int *ns)
{
    if (occ_grow_v3(&sp->sn, &sp->capsn, *ns + 1) || occ_grow_v3(&sp->sa, &sp->capsa, *ns + 1))
        return -1;
    sp->sn[*ns] = nrm;
    sp->sa[*ns] = a;
    ++*ns;
    return 0;
}

/* The faces of blocker b's umbra (the shadow cones from the inner
 * element's vertices), appended to sp->sn / sp->sa; returns 1 when the
 * umbra has no interior (no planes appended), 0, or -1. */
static int umbra_planes(occ_space *sp, const pair_ctx *c, int b, int *ns)
{
    const rad_vec3 *p = sp->blkc.v + sp->blkc.first[b];
    int np = sp->blkc.first[b + 1] - sp->blkc.first[b];
    rad_vec3 n = sp->bn[b], cen = sp->bc[b];
    double side = 0;
    for (int k = 0; k < c->nt; k++) {
        double h = v3_dot(n, v3_sub(c->t[k], cen));
        if (fabs(h) <= c->snap || h * side < 0)
            return 1; /* T touches or straddles P's plane */
        side = h;
    }
    if (push_plane(sp, side > 0 ? v3_scale(n, -1.0) : n, cen, ns))
        return -1;
    for (int k = 0; k < c->nt; k++)
        for (int e = 0; e < np; e++) {
            rad_vec3 y = c->t[k];
            rad_vec3 nrm = v3_cross(v3_sub(p[e], y), v3_sub(p[(e + 1) % np], y));
            double len = v3_norm(nrm);
            if (!(len > 0))
                continue;
            nrm = v3_scale(nrm, 1.0 / len);
            if (push_plane(sp, v3_dot(nrm, v3_sub(cen, y)) < 0 ? v3_scale(nrm, -1.0) : nrm, y,
                           ns))
                return -1;
        }
    return 0;
}

enum { PENUMBRA, UMBRA };

/* Every blocker's penumbra or umbra planes: blocker b's are
 * [sp->sfirst[b], sp->sfirst[b+1]); an umbra without interior has none
 * and sp->empty[b] set. */
static int all_region_planes(occ_space *sp, const pair_ctx *c, int kind)
{
    int ns = 0;
    if (occ_grow_i(&sp->sfirst, &sp->capsf, c->nb + 1) || occ_grow_i(&sp->empty, &sp->capem, c->nb))
        return -1;
    for (int b = 0; b < c->nb; b++) {
        sp->sfirst[b] = ns;
        int r = kind == PENUMBRA ? penumbra_planes(sp, c, b, &ns) : umbra_planes(sp, c, b, &ns);
        if (r < 0)
            return -1;
        sp->empty[b] = r;
    }
    sp->sfirst[c->nb] = ns;
    return 0;
}

/* Cut every piece of sp->da by blocker e's planes: outside parts to
 * sp->db, inside parts to `inside`; then swap.  `slivers` as for
 * occ_cut_piece: no cut loses area (occ_support_domain). */
static int cut_set(occ_space *sp, const pair_ctx *c, int e, int slivers, polyset *inside)
{
    int g = sp->sfirst[e], ng = sp->sfirst[e + 1] - g;
    occ_ps_clear(&sp->db);
    for (int k = 0; k < sp->da.np; k++) {
        int n = occ_load_rem(sp, &sp->da, k);
        int r = n < 0 ? -1
                      : occ_cut_piece(sp, sp->sn + g, sp->sa + g, ng, c->snap, c->sliver, slivers,
                                      &sp->db, &n);
        if (r < 0 || (r > 0 && occ_ps_push(inside, sp->rem, n)))
            return -1;
    }
    polyset t = sp->da;
    sp->da = sp->db;
    sp->db = t;
    return 0;
}

/* Split sp->dom along the planes through an edge of e and a vertex of f
 * (kind OCC_EVENT_EV when e is the blocker, OCC_EVENT_VE when e is the
 * inner element: their wedges, occevent.c), but for the blocker's edges
 * or vertices that `flag` (its sp->mflag) puts inside the union of the
 * shadows. */
static int split_edge_vertex(occ_space *sp, const pair_ctx *c, const rad_vec3 *e, int ne,
                             const rad_vec3 *f, int nf, int kind, int whole, const int *flag)
{
    for (int k = 0; k < ne; k++)
        for (int l = 0; l < nf && sp->dom.np > 0; l++) {
            rad_vec3 nrm;
            if (flag && (kind == OCC_EVENT_EV ? flag[k] & OCC_MESH_EDGE
                                              : flag[l] & OCC_MESH_VERTEX))
                continue; /* inside the union of the shadows (occmesh.c) */
            occ_wedge w;
            if (!poly_edge_plane(e, ne, k, f[l], &nrm))
                continue;
            occ_event_wedge(&w, kind, nrm, e[k], e[(k + 1) % ne], f[l]);
            if (occ_split_dom(sp, c, nrm, e[k], whole ? NULL : &w, c->sliver))
                return -1;
        }
    return 0;
}

/* Does blocker p (n vertices) come within tol of the outer plane (normal
 * c->nx, through o0)?  The wedges of occevent.c assume a
 * blocker strictly between the two elements.  A blocker vertex v on the
 * outer plane breaks that: seen from x in that plane, v's shadow runs
 * along the line where the two planes meet, and crosses the inner
 * element's edges where the line x v meets their feet there, on both
 * sides of v, where the wedge (the vertical angle at v) has one.  Seen
 * in the fuzzed scene 41:454, a triangle from a corner of the outer
 * element to a corner of the inner one: default was 2.8e-9 off under an
 * estimate of 1.65e-9 (the same with the vertex 1e-6 of the triangle
 * above the outer plane; 1e-3 above, the wedges held).  Such a blocker's
 * planes are cut whole (split_events: tol is OCC_NEAR_OUTER of the outer
 * element's size). */
static int near_outer(const pair_ctx *c, const rad_vec3 *p, int n, rad_vec3 o0, double tol)
{
    for (int k = 0; k < n; k++)
        if (fabs(v3_dot(c->nx, v3_sub(p[k], o0))) <= tol)
            return 1;
    return 0;
}

/* Two blockers a and b cause events of their own: where, seen from x, a
 * vertex of one passes an edge of the other, the two shadows on the
 * inner plane start or stop overlapping at that corner, and the area of
 * their union has a kink (Heckbert 1992 lists these vertex-edge events
 * among the discontinuities; Gigus, Canny & Seidel, IEEE PAMI 13, 1991,
 * call them EV events).  The x where that happens lie on the plane
 * through the edge of one and the vertex of the other, and the event can
 * change what the inner element loses only where the line of sight runs
 * on into it: planes that leave the inner element on one side are
 * skipped.  Without these cuts the rules of occrule.c converge slowly on
 * such a kink and their estimate (2) of occhidden.c does not see it: in
 * the closed Cornell box, where the two blocks' shadows overlap, factors
 * from the floor to the walls were off by up to 2e-7 with estimates of
 * 1e-9, and rows of F missed 1 by up to 8e-6 in default mode (mesh 4x4)
 * and 4e-7 in reference mode (mesh 2x2).  Events of three
 * edges (one of each blocker and one of the inner element: the lines
 * through three edges form a ruled quadric, not a plane) trace conics on
 * the outer element; occeee.c cuts them by chords. */
/* The planes through an edge of blocker a and a vertex of blocker b that
 * cross the inner element (sp->d holds c->nt distances), but where the
 * edge or the vertex is inside the union of the shadows (occmesh.c): the
 * other's shadow passing it changes nothing of the union's boundary.
 * With c->pair_wedges a piece is cut only where the event happens (the
 * BB wedges of occevent.c). */
static int split_blocker_pair(occ_space *sp, const pair_ctx *c, int a, int b)
{
    const rad_vec3 *pa = sp->blkc.v + sp->blkc.first[a];
    const rad_vec3 *pb = sp->blkc.v + sp->blkc.first[b];
    const int na = sp->blkc.first[a + 1] - sp->blkc.first[a];
    const int nb = sp->blkc.first[b + 1] - sp->blkc.first[b];
    const int *fa = sp->mflag + sp->blkc.first[a], *fb = sp->mflag + sp->blkc.first[b];
    for (int k = 0; k < na; k++)
        for (int l = 0; l < nb && sp->dom.np > 0; l++) {
            rad_vec3 nrm;
            double lo, hi;
            if ((fa[k] & OCC_MESH_EDGE) || (fb[l] & OCC_MESH_VERTEX) ||
                !poly_edge_plane(pa, na, k, pb[l], &nrm))
                continue;
            poly_distances(c->t, c->nt, nrm, pa[k], c->snap, sp->d, &lo, &hi);
            occ_wedge w;
            occ_event_wedge(&w, OCC_EVENT_BB, nrm, pa[k], pa[(k + 1) % na], pb[l]);
            w.always = c->pair_wedges;
            if (lo < 0 && hi > 0 && occ_split_dom(sp, c, nrm, pa[k], &w, c->sliver))
                return -1;
        }
    return 0;
}

static int split_two_blockers(occ_space *sp, const pair_ctx *c)
{
    if (occ_grow_d(&sp->d, &sp->capd, c->nt))
        return -1;
    for (int a = 0; a < c->nb && sp->dom.np > 0; a++)
        for (int b = 0; b < c->nb && sp->dom.np > 0; b++)
            if (a != b && split_blocker_pair(sp, c, a, b))
                return -1;
    return 0;
}

/* Default and reference modes: split the pieces not known to be hidden
 * along every plane where a blocker's edge passes a vertex of the inner
 * element, or a blocker's vertex one of its edges (the first-derivative
 * discontinuities of hidden(x) that one blocker causes; Heckbert,
 * "Discontinuity meshing for radiosity", Eurographics Workshop on
 * Rendering 1992), and along each blocker's own plane (where the blocker
 * is seen edge on, and a closed solid's silhouette changes from one set
 * of edges to another: the shadow's area has a kink there too), and
 * along the planes where one blocker's vertex passes another's edge
 * (split_two_blockers), and by chords along the conics of the events of
 * three edges (occeee.c).  Inside the pieces hidden(x) is then smooth
 * (but in the thin lens between a chord and its arc), the high-order
 * rules of occrule.c converge fast, and their error estimate can be
 * trusted; a penumbra narrower than the spacing of the points no longer
 * hides between them.  With
 * c->events OCC_SPLIT_WEDGES a piece is cut only where the plane's event
 * of a blocker and the inner element happens (occevent.c); with
 * c->pair_wedges the two-blocker planes are cut only where theirs does;
 * the blocker's own plane is always cut.  The events of
 * blocker edges and vertices inside the union of the shadows from the
 * whole outer element (the inside of a triangulated model: occmesh.c)
 * never happen, and are not cut. */
static int split_events(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no)
{
    if (occ_dom_spheres(sp))
        return -1;
    double size = 0; /* of the outer element, from its first vertex */
    for (int k = 1; k < no; k++)
        size = fmax(size, v3_norm(v3_sub(o[k], o[0])));
    if (occ_mesh_interior(sp, c, o, no))
        return -1;
    for (int b = 0; b < c->nb && sp->dom.np > 0; b++) {
        const rad_vec3 *p = sp->blkc.v + sp->blkc.first[b];
        int np = sp->blkc.first[b + 1] - sp->blkc.first[b];
        const int *flag = sp->mflag + sp->blkc.first[b];
        const int whole = c->events == OCC_SPLIT_WEDGES &&
                          near_outer(c, p, np, o[0], OCC_NEAR_OUTER * size);
        if (occ_split_dom(sp, c, sp->bn[b], p[0], NULL, c->sliver) ||
            split_edge_vertex(sp, c, p, np, c->t, c->nt, OCC_EVENT_EV, whole, flag) ||
            split_edge_vertex(sp, c, c->t, c->nt, p, np, OCC_EVENT_VE, whole, flag))
            return -1;
    }
    if (split_two_blockers(sp, c))
        return -1;
    return occ_split_three_edges(sp, c, o, no);
}

/* Keep the penumbra planes (sp->sn, sa, sfirst) for occ_cell_blockers
 * in sp->pn, pa, pfirst, before the umbras' take their place. */
static void keep_penumbras(occ_space *sp)
{
    occ_swap_v3(&sp->pn, &sp->cappn, &sp->sn, &sp->capsn);
    occ_swap_v3(&sp->pa, &sp->cappa, &sp->sa, &sp->capsa);
    int *f = sp->pfirst, cap = sp->cappf;
    sp->pfirst = sp->sfirst;
    sp->cappf = sp->capsf;
    sp->sfirst = f;
    sp->capsf = cap;
}

/* The blockers of the list sp->clist[lfirst .. lfirst + ln) (all c->nb
 * when lfirst < 0) that may hide anything from some point of the convex
 * cell p (nv vertices on the outer element), appended to sp->clist;
 * returns their count, or -1.  Blocker b is left out when every vertex
 * of the cell, and so every point of it, lies more than the snap outside
 * one plane of b's penumbra region W_b (kept by occ_support_domain):
 * from such a point no segment to the inner element passes through b,
 * its shadow misses the inner element, and the union of the shadows
 * (occunion.c) has the same boundary inside it without b.  So is a face
 * of a closed mesh that every vertex lies more than the snap behind,
 * when its points may leave it out (sp->bx: the exit rule of
 * occclosed.c, which occunion.c applies point by point).  A cell of a
 * piece cut from W_b keeps b; the others are mostly left out here once
 * instead of at each of the cell's evaluation points. */
int occ_cell_blockers(occ_space *sp, const pair_ctx *c, const rad_vec3 *p, int nv, int lfirst,
                      int ln)
{
    const int n = lfirst >= 0 ? ln : c->nb;
    if (occ_grow_i(&sp->clist, &sp->capclist, sp->nclist + n))
        return -1;
    const int *from = lfirst >= 0 ? sp->clist + lfirst : NULL;
    int kept = 0;
    for (int i = 0; i < n; i++) {
        const int b = from ? from[i] : i;
        int out = 0;
        if (sp->bx[b]) {
            out = 1;
            for (int k = 0; k < nv && out; k++)
                out = v3_dot(sp->bn[b], v3_sub(p[k], sp->bc[b])) < -c->snap;
        }
        for (int g = sp->pfirst[b]; g < sp->pfirst[b + 1] && !out; g++) {
            out = 1;
            for (int k = 0; k < nv && out; k++)
                out = v3_dot(sp->pn[g], v3_sub(p[k], sp->pa[g])) < -c->snap;
        }
        if (!out)
            sp->clist[sp->nclist + kept++] = b;
    }
    sp->nclist += kept;
    return kept;
}

/* The domain of integration: the outer polygon o cut to the union of the
 * blockers' penumbras, as disjoint convex pieces (each in the W_b of one
 * blocker b and in no earlier W), then, but in classic mode, cut along
 * every umbra, the pieces inside one going to sp->umb.  Pieces not known
 * to be hidden end in sp->dom.
 *
 * Classic mode does not cut along the umbras.  Each cut leaves the
 * piece's part inside the umbra and up to one piece more for each of the
 * umbra's planes around it, thin strips between umbra and penumbra, and
 * each piece takes at least the 3 points of its fan triangles (occhidden.c):
 * on a 250-triangle torus over a floor (bench/scenes.py torus 250) the
 * cuts doubled classic's evaluations (942,495 against 503,454) and its
 * time (2.64 s against 1.16 s).  Against default mode's F on the partly
 * hidden entries there, the median error went from 1.7e-4 to 2.5e-4 of
 * the entry, the 90th percentile from 2.7e-3 to 1e-2, the sum of the
 * errors from 0.0172 to 0.0189 (View3D 3.2 at eps 1e-6: a median of
 * 6.1e-3 and a 90th percentile of 1, setting 1,441 of those 7,070
 * entries to 0).  A pair fully hidden by several blockers' umbras
 * together still comes out 0 exactly: no evaluation point sees anything
 * of the inner element (occhidden.c, orient_integral).
 *
 * The union is taken as a partition of o, blocker by blocker: each piece
 * not yet in a penumbra is cut by W_b's planes, its part inside goes to
 * the domain and its parts outside on to the next blocker.  Every cut
 * hands on all of its piece, whatever the snap decides: a sliver is not
 * cut off a penumbra's piece (occ_cut_piece, OCC_SLIVERS_MERGE; the
 * integrand there is hidden(x) all the same), nor dropped from an umbra's
 * cut (OCC_SLIVERS_KEEP: a piece there is taken as fully hidden).
 * (It used to take o's part inside W_b, then cut out the earlier W's
 * from that part.  A plane of W_e that a small piece has within the snap
 * counts the piece as inside, while the whole of o is cut by it; so a
 * part could be cut out of W_b's piece as inside W_e although W_e's own
 * pass had left it out.  Seen in a fuzzed room turned and moved 2e10
 * away (tests/geomfuzz.py seed 51, scene 79): two floor pieces beside
 * the receiver, out of its plane by the coordinates' round-off, had
 * penumbras of that kind; 8% of the domain was lost and F(7, 13) came
 * out 5% high, with an estimate of 3.5e-7 of itself.) */
int occ_support_domain(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no)
{
    occ_ps_clear(&sp->dom);
    occ_ps_clear(&sp->umb);
    if (all_region_planes(sp, c, PENUMBRA))
        return -1;
    occ_ps_clear(&sp->da);
    if (occ_ps_push(&sp->da, o, no))
        return -1;
    for (int b = 0; b < c->nb && sp->da.np > 0; b++)
        if (cut_set(sp, c, b, OCC_SLIVERS_MERGE, &sp->dom))
            return -1;
    keep_penumbras(sp);
    if (sp->dom.np == 0 || !c->events)
        return 0; /* nothing hidden, or classic mode (above) */
    if (all_region_planes(sp, c, UMBRA))
        return -1;
    polyset t = sp->da;
    sp->da = sp->dom;
    sp->dom = t;
    for (int b = 0; b < c->nb && sp->da.np > 0; b++)
        if (!sp->empty[b] && cut_set(sp, c, b, OCC_SLIVERS_KEEP, &sp->umb))
            return -1;
    t = sp->dom;
    sp->dom = sp->da;
    sp->da = t;
    return split_events(sp, c, o, no);
}
