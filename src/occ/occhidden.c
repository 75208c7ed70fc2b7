/* occhidden.c -- how much of an element pair the blockers hide: all of
 * it (one blocker between the two), or the integral of the hidden part
 * over the outer element by an adaptive rule.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Fully hidden by one blocker (hides_all): if P's plane strictly
 * separates the two elements and the 16 (or so) segments between their
 * vertices all pass through P's interior, every segment does (the
 * crossing points of the segments from A to B form the convex hull of
 * those of the vertex pairs), and F = 0.
 *
 * The hidden part.  With A_o the outer and A_t the inner element,
 *     A_o F_ot = A_t F_to = integral over x in A_o of F(x -> visible part of A_t),
 * and the integrand is computed exactly (occpoint.c: hidden(x), the form
 * factor from x to the part of A_t the blockers hide; occunion.c where
 * A_t is planar).  So
 *     S_occluded = S - 2 pi * integral over A_o of hidden(x) dx,
 * where S is the unoccluded contour sum of the kernel: the quadrature
 * error only touches the hidden part, never the (possibly singular)
 * unoccluded one.
 *
 * The integral runs over the domain of occdomain.c (the outer element's
 * part of the blockers' penumbras, cut, but in classic mode, along their
 * umbras and the event planes: orient_integral): each piece is
 * a fan of cells (quadrilaterals and at most one triangle; triangles
 * alone in classic mode), hidden(x) is integrated on each by the rules of
 * occrule.c, and the cell with the largest estimate has its rule's order
 * raised or is split into its four children, until the sum of estimates is
 * below the pair's tolerance (global adaptive subdivision as in QUADPACK's
 * QAG, Piessens et al. 1983).  The outer element is the one that looks
 * smaller from the nearest blocker (size / distance): from there the
 * blocker's shadow moves least over the inner element, so hidden(x) is
 * smoothest.  If no piece is left, S is kept as it is (bit for bit); if
 * every piece is inside an umbra, or no evaluation point sees anything of
 * the inner element from either side, F = 0.  The accuracy modes'
 * targets are in occlusion.c's header.
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


/* Is x in convex polygon p (n vertices, normal nrm), within tol? */
static int holds(const rad_vec3 *p, int n, rad_vec3 nrm, rad_vec3 x, double tol)
{
    for (int k = 0; k < n; k++) {
        const rad_vec3 a = p[k], e = v3_sub(p[(k + 1) % n], a);
        const double len = v3_norm(e);
        if (len > 0 && v3_dot(v3_cross(e, v3_sub(x, a)), nrm) < -tol * len)
            return 0;
    }
    return 1;
}

/* How much a cell's estimate is to be trusted: the rule's order times
 * less when it holds a point where a blocker touches the outer element
 * (touch_points; "holds" within 1e-9 of the pair's frame, whose
 * coordinates are of order 1).  There hidden(x) depends on the direction from that
 * point: the shadow edge the blocker's edges cast through it turns with
 * it, as a step turns around its corner.  So a product rule on the cell
 * converges algebraically, not geometrically: with an error C n^-p at n
 * points a side the last difference is about C p n^-p-1, the error n / p
 * times it, p >= 1 on a bounded integrand.  Seen: a floor tile and a wall
 * of a room, a blocker touching the tile at its corner (fuzzed scene
 * 55:159): orders 4, 5 and 6 differed by 8.6e-10 and then 3.6e-10,
 * falling fast enough, but the cell was 1.1e-9 off, and F 3.5e-7 of
 * itself off under an estimate of 3e-7.  Raised by its order, the
 * estimate has the cell split towards the point until it is small enough
 * for the error not to matter, however the rule converges on it. */
static double touch_factor(const pair_ctx *c, const tri_node *t)
{
    for (int k = 0; k < c->ntouch; k++)
        if (holds(t->p, t->nv, c->nx, c->touch[k], 1e-9))
            return t->order;
    return 1;
}

/* A node's value and error estimate from its cell (t->p, t->nv, t->area).
 * With the 3-point rule (c->order 0, classic mode): the rule on its four
 * midpoint children (qc), or on the cell alone (qc[0]) when it is smaller
 * than OCC_CLASSIC_ONCE of the outer element, the value their sum, and no
 * estimate (0: the mode makes none).  With the product rules (occrule.c):
 * the rules of orders 1, 2 and 3 (Q1, Q2, Q3), the value Q3 and the
 * estimate
 *     max(|Q3 - Q2|, |Q2 - Q1|),                                       (2)
 * and node_raise goes on from there (the three rules take 13
 * evaluations, not 14: orders 1 and 3 share their centre point, and order
 * 5 reuses it; occrule.c).  Where hidden(x) is analytic on the cell
 * the rule's error falls geometrically with the order, so each
 * difference bounds the error of the better rule; the larger of the last
 * two stands in for the case where two rules agree by chance (seen: Q2
 * and Q3 within 4e-9 of each other and both 5e-8 off, on a triangle
 * whose Q4 was right). */
static int node_rules(occ_space *sp, const pair_ctx *c, tri_node *t)
{
    if (c->order >= 2) {
        double q1, q2, q3;
        t->center = NAN;
        if (occ_rule_order(sp, c, 1, t->p, t->nv, t->area, &q1, &t->center) ||
            occ_rule_order(sp, c, 2, t->p, t->nv, t->area, &q2, NULL) ||
            occ_rule_order(sp, c, 3, t->p, t->nv, t->area, &q3, &t->center))
            return -1;
        t->q = q2;
        t->qc[0] = q3;
        t->qc[1] = t->qc[2] = t->qc[3] = 0;
        t->dlast = fabs(q3 - q2);
        t->order = 3;
        t->err = fmax(t->dlast, fabs(q2 - q1)) * touch_factor(c, t);
        t->stalled = 0;
        return 0;
    }
    /* The rule on the whole cell too would give an estimate |q - sum qc|,
     * but classic mode has none to give (its kernel's is NaN:
     * radi_ff_pair), and those three evaluations were a fifth of its
     * visibility time, so they are not made. */
    t->q = NAN;
    if (t->area < OCC_CLASSIC_ONCE * c->outer_area) {
        t->qc[1] = t->qc[2] = t->qc[3] = 0;
        if (occ_rule(sp, c, t->p, t->area, &t->qc[0]))
            return -1;
    } else {
        rad_vec3 ch[4][4];
        occ_cell_children(t->p, 3, ch);
        for (int k = 0; k < 4; k++)
            if (occ_rule(sp, c, ch[k], 0.25 * t->area, &t->qc[k]))
                return -1;
    }
    t->err = 0;
    t->order = 0;
    t->stalled = 1;
    return 0;
}

/* Put node t's list of blockers in force for its evaluations (occunion.c)
 * while `on`. */
static void cell_list(occ_space *sp, const tri_node *t, int on)
{
    sp->cell_on = on;
    sp->cell_first = t->lfirst;
    sp->cell_n = t->ln;
}

/* node_rules on node t with its list of blockers: those of the list
 * sp->clist[lfirst .. lfirst + ln) (all, when lfirst < 0) that may hide
 * anything from its cell (occdomain.c, occ_cell_blockers). */
static int node_eval(occ_space *sp, const pair_ctx *c, tri_node *t, int lfirst, int ln)
{
    const int n = occ_cell_blockers(sp, c, t->p, t->nv, lfirst, ln);
    if (n < 0)
        return -1;
    t->lfirst = sp->nclist - n;
    t->ln = n;
    cell_list(sp, t, 1);
    const int r = node_rules(sp, c, t);
    cell_list(sp, t, 0);
    return r;
}

/* The estimate of a rule whose last difference d did not fall to half
 * the one before it, d1: the order is not converging geometrically as it
 * does where hidden(x) is analytic on the cell, and d, or d1, says
 * little of the error.  A geometric tail of ratio q = d / d1 sums to
 * d q / (1 - q); taken of the larger difference, with q at most
 * OCC_TAIL_QMAX (a rule that does not converge at all has no tail to
 * sum: that cap makes it nine times the larger difference, and the cell
 * the first to be split).  Seen on a light over a floor tile that a box
 * stands 1.4e-6 beside (fuzzed scene 58:71): the shadow of the box's
 * vertical edge, whose face's plane passes 3e-6 from the domain's edge,
 * moves as 1 / (y - y0) across the light; the two cells' orders 5 and 6
 * differed by 2.1e-10 and 5.1e-10 after differences of 3.1e-10 and
 * 5.5e-10, and their estimates (the larger of the two) met the pair's
 * target of 1.1e-9 while the integral was 3e-9 off, F 1.4e-6 of itself
 * off in default mode.  With the tail the two estimates are 6.8e-10 and
 * 5.5e-9, and the cells are split until the orders converge. */
static double slow_tail(double d, double d1)
{
    const double m = fmax(d, d1);
    if (!(d1 > 0))
        return m;
    const double q = fmin(d / d1, OCC_TAIL_QMAX);
    return q <= 0.5 ? m : m * (q / (1 - q));
}

/* Raise a node's order by one: the new rule's value, and the
 * estimate (2) of its last two differences.  When the new difference is
 * not at most half the one before, hidden(x) is not smooth on the
 * cell (a kink of an event that no plane cut, where the order does not
 * help, or an event just off it), the estimate is the tail of slow_tail,
 * and the node is marked to be split instead. */
static int node_raise(occ_space *sp, const pair_ctx *c, tri_node *t)
{
    double q;
    cell_list(sp, t, 1);
    const int r = occ_rule_order(sp, c, t->order + 1, t->p, t->nv, t->area, &q, &t->center);
    cell_list(sp, t, 0);
    if (r)
        return -1;
    double d = fabs(q - t->qc[0]);
    t->stalled = !(d <= 0.5 * t->dlast);
    t->q = t->qc[0];
    t->qc[0] = q;
    t->err = t->stalled ? slow_tail(d, t->dlast) : fmax(d, t->dlast);
    t->dlast = d;
    t->order++;
    t->err *= touch_factor(c, t);
    return 0;
}

/* Replace leaf k by its four children (appended at the end). */
static int node_split(occ_space *sp, const pair_ctx *c, int k, int *nleaf)
{
    if (occ_grow_node(&sp->node, &sp->capnode, *nleaf + 3))
        return -1;
    tri_node parent = sp->node[k];
    rad_vec3 ch[4][4];
    occ_cell_children(parent.p, parent.nv, ch);
    for (int l = 0; l < 4; l++) {
        tri_node *t = l == 0 ? &sp->node[k] : &sp->node[(*nleaf)++];
        t->nv = parent.nv;
        memcpy(t->p, ch[l], sizeof ch[l]);
        /* a triangle's midpoint children are quarters; a quadrilateral's
         * are not, unless it is a parallelogram */
        t->area = parent.nv == 4 ? poly_area(t->p, 4) : 0.25 * parent.area;
        if (node_eval(sp, c, t, parent.lfirst, parent.ln))
            return -1;
    }
    return 0;
}

/* The first leaves: the fan cells of the pieces of sp->dom and
 * sp->umb, evaluated; *nleaf their count.  0, or -1.  With c->direct the
 * integrand visible(x) is 0 on sp->umb's pieces (each inside an umbra:
 * one blocker hides all of the inner element from every point of it), so
 * they add nothing and are not evaluated; they do say that something is
 * hidden. */
static int first_leaves(occ_space *sp, const pair_ctx *c, int *nleaf)
{
    const polyset *sets[2] = {&sp->dom, &sp->umb};
    const int nsets = c->direct ? 1 : 2;
    if (c->direct && sp->umb.np > 0)
        sp->any_hidden = 1;
    sp->nclist = 0;
    if (occ_grow_node(&sp->node, &sp->capnode, sp->dom.nv + sp->umb.nv))
        return -1;
    for (int set = 0; set < nsets; set++)
        for (int k = 0; k < sets[set]->np; k++) {
            const rad_vec3 *o = sets[set]->v + sets[set]->first[k];
            int no = sets[set]->first[k + 1] - sets[set]->first[k];
            /* the piece as a fan of quadrilaterals o0 o_l o_l+1 o_l+2
             * (convex, as the piece is) and at most one triangle, or of
             * triangles alone for the 3-point rule */
            for (int l = 1; l + 1 < no;) {
                tri_node *t = &sp->node[*nleaf];
                t->nv = c->order >= 2 && l + 2 < no ? 4 : 3;
                t->p[0] = o[0];
                for (int v = 1; v < t->nv; v++)
                    t->p[v] = o[l + v - 1];
                l += t->nv - 2;
                t->area = t->nv == 4 ? poly_area(t->p, 4)
                                     : 0.5 * v3_norm(v3_cross(v3_sub(t->p[1], t->p[0]),
                                                              v3_sub(t->p[2], t->p[0])));
                if (!(t->area > 0))
                    continue;
                if (node_eval(sp, c, t, -1, 0))
                    return -1;
                ++*nleaf;
            }
        }
    return 0;
}

/* The pair's target (1) of integrate below, for the integral v so far:
 * the occluded value is v itself when c->direct, else whole less v. */
static double target_of(const pair_ctx *c, double rel, double whole, double v)
{
    return rel * fmax(c->direct ? v : whole - v, OCC_FLOOR * whole);
}

/* Integral of hidden(x) over the pieces of sp->dom and sp->umb (of area
 * dom_area): *value and its estimated error *error, the leaves'
 * estimates and the lenses' that the domain's chords left (sp->arc_err,
 * occeee.c eq. 2: no cell's rule sees them, so splitting cannot lower
 * them and they stay out of the test below; narrower_arcs acts on them).
 * When `adaptive`, the leaf with the largest estimate is split while the
 * sum of the estimates exceeds
 *     tau = rel * max(whole - value, OCC_FLOOR * whole)                 (1)
 * and the budgets are not spent: max_leaves cells and max_evals
 * evaluations of hidden(x) beyond those spent until the first leaves
 * were evaluated (the lenses' samples too), and OCC_EVALS_PER_CELL more
 * for each first leaf, up to OCC_EVALS_CELLS_MAX times max_evals (*met:
 * it ended below tau, or was not adaptive).  (The budgets once counted
 * the first leaves too: a domain cut along the events of many blockers
 * can start with more cells than that, and then no cell was ever split.
 * Seen in a closed room with two blocks standing on a floor cut around
 * them, 1x1 mesh: pairs with 6 and 8 blockers started with 957 to 1,428
 * pieces, and in default mode 6 entries missed their promise by their
 * own estimates, F(3 -> 11) of a wall to a floor strip 2.9e-6 off under
 * an estimate of 2.2e-2 of itself; none now, tests/accuracy/closure.sh.)
 * `whole` is the unoccluded integral S / (2 pi), so whole - value is the
 * visible part,
 * the occluded A_o F_ot itself, and the target is relative to it down to
 * pairs hidden to OCC_FLOOR of their unoccluded value (a target relative
 * to the unoccluded value once let a nearly hidden pair's error reach
 * 1e4 times its value).  Each point-to-polygon sum's round-off is kept
 * below OCC_NOISE_SHARE of tau spread over the domain (sp->noise_tol,
 * occpoint.c): the rules' estimates see round-off as an error that no
 * split lowers. */
static int integrate(occ_space *sp, const pair_ctx *c, int adaptive, double rel, double whole,
                     double dom_area, int max_leaves, double max_evals, double *value,
                     double *error, int *met)
{
    occ_leaves *lt = &sp->leaves;
    int nleaf = 0;
    if (first_leaves(sp, c, &nleaf) || occ_leaves_build(lt, sp->node, nleaf))
        return -1;
    double v = lt->val[1], err = lt->err[1], tau = target_of(c, rel, whole, v);
    max_leaves += nleaf; /* the budgets count from here */
    max_evals += sp->evals + fmin(OCC_EVALS_PER_CELL * nleaf, OCC_EVALS_CELLS_MAX * max_evals);
    while (adaptive && sp->any_hidden && sp->any_visible && err > tau &&
           nleaf + 3 <= max_leaves && sp->evals < max_evals && lt->best[1] >= 0) {
        const int worst = lt->best[1];
        tri_node *t = &sp->node[worst];
        sp->noise_tol = OCC_NOISE_SHARE * tau / dom_area;
        if (t->order >= 2 && t->order < c->order && !t->stalled) {
            if (node_raise(sp, c, t) || occ_leaves_set(lt, sp->node, worst, nleaf))
                return -1;
        } else {
            if (node_split(sp, c, worst, &nleaf))
                return -1;
            for (int k = nleaf - 3; k < nleaf; k++)
                if (occ_leaves_set(lt, sp->node, k, nleaf))
                    return -1;
            if (occ_leaves_set(lt, sp->node, worst, nleaf))
                return -1;
        }
        v = lt->val[1];
        err = lt->err[1];
        tau = target_of(c, rel, whole, v);
    }
    *value = v;
    *error = err + sp->arc_err;
    *met = !(adaptive && sp->any_hidden && sp->any_visible && err > tau);
    return 0;
}

/* Does blocker b alone hide all of p from all of q?  (Fully hidden, at
 * the top of the file.) */
static int hides_all(const rad_vec3 *p, int np, const rad_vec3 *q, int nq, const rad_vec3 *b,
                     int nb, rad_vec3 bn, double tol)
{
    double plo = HUGE_VAL, phi = -HUGE_VAL, qlo = HUGE_VAL, qhi = -HUGE_VAL;
    for (int k = 0; k < np; k++) {
        double s = v3_dot(bn, v3_sub(p[k], b[0]));
        plo = fmin(plo, s);
        phi = fmax(phi, s);
    }
    for (int k = 0; k < nq; k++) {
        double s = v3_dot(bn, v3_sub(q[k], b[0]));
        qlo = fmin(qlo, s);
        qhi = fmax(qhi, s);
    }
    if (!((plo > tol && qhi < -tol) || (phi < -tol && qlo > tol)))
        return 0;
    for (int k = 0; k < np; k++)
        for (int l = 0; l < nq; l++) {
            double dp = v3_dot(bn, v3_sub(p[k], b[0])), dq = v3_dot(bn, v3_sub(q[l], b[0]));
            rad_vec3 z = v3_lerp(p[k], q[l], dp / (dp - dq));
            for (int e = 0; e < nb; e++) {
                rad_vec3 a = b[e], ed = v3_sub(b[(e + 1) % nb], a);
                if (v3_dot(v3_cross(ed, v3_sub(z, a)), bn) < tol * v3_norm(ed))
                    return 0;
            }
        }
    return 1;
}

/* Clip the pair's blockers to the front of the inner plane (normal tn
 * through tp), dropping those with nothing in front; fill their normals,
 * their centroids, the radius of a ball about each centroid that holds
 * its blocker (sp->br, occunion.c), and whether a point of the outer
 * element (side 0: element i, 1: j) behind a blocker's plane may leave it
 * out (sp->bx, occclosed.c).  Returns the number kept, or -1. */
static int clip_blockers(const rad_occ *o, occ_space *sp, int nb, rad_vec3 tn, rad_vec3 tp,
                         int side)
{
    if (occ_grow_v3(&sp->bn, &sp->capbn, nb) || occ_grow_v3(&sp->bc, &sp->capbc, nb) ||
        occ_grow_d(&sp->br, &sp->capbr, nb) || occ_grow_i(&sp->bx, &sp->capbx, nb))
        return -1;
    occ_ps_clear(&sp->blkc);
    int kept = 0;
    for (int b = 0; b < nb; b++) {
        int n = sp->blk.first[b + 1] - sp->blk.first[b];
        int m = occ_clip_into(sp, &sp->blkc, sp->blk.v + sp->blk.first[b], n, tn, tp, sp->snap);
        if (m < 0)
            return -1;
        if (m == 0)
            continue;
        sp->bn[kept] = o->snormal[sp->bid[b]];
        sp->bc[kept] = poly_mean(sp->blkc.v + sp->blkc.first[kept], m);
        double r = 0;
        for (int k = 0; k < m; k++)
            r = fmax(r, v3_norm(v3_sub(sp->blkc.v[sp->blkc.first[kept] + k], sp->bc[kept])));
        sp->br[kept] = r;
        sp->bx[kept] = sp->nxcull == nb && sp->xcull[2 * b + side];
        kept++;
    }
    return kept;
}

/* size / distance to the nearest blocker, for the choice of outer element. */
static double apparent_size(const rad_occ *o, const occ_space *sp, int nb, const rad_ff_poly *e)
{
    double d = HUGE_VAL;
    for (int b = 0; b < nb; b++)
        d = fmin(d, poly_point_distance(e->centroid, sp->blk.v + sp->blk.first[b],
                                           sp->blk.first[b + 1] - sp->blk.first[b],
                                           o->snormal[sp->bid[b]]));
    return e->size / fmax(d, 1e-300);
}

/* Is the inner element pt (vertices ct in the pair's frame, nt of them)
 * planar to the round-off of those coordinates: its twist (formfactor.h)
 * within 64 eps of their largest, as ffarea.c (side_of) judges a twisted
 * quadrilateral? */
static int inner_flat(const rad_ff_poly *pt, const rad_vec3 *ct, int nt)
{
    double big = 0;
    for (int k = 0; k < nt; k++)
        big = fmax(big, v3_maxabs(ct[k]));
    return pt->twist <= 64 * DBL_EPSILON * big;
}

/* What integrating in one orientation found. */
typedef struct orient_result {
    double value, error;        /* integral of hidden(x) over the outer element,
                                   or of visible(x) when `direct` */
    int hidden, visible;        /* some point saw something hidden / visible */
    int direct;
} orient_result;

/* The vertices of the pair's blockers (sp->blkc) that lie on the outer
 * element co (no vertices, normal nx) within the snap: the points where
 * hidden(x) is not smooth however the domain is cut (touch_factor).  At
 * most OCC_TOUCH_MAX are kept, the first found. */
static void touch_points(const occ_space *sp, pair_ctx *c, const rad_vec3 *co, int no)
{
    c->ntouch = 0;
    for (int k = 0; k < sp->blkc.nv && c->ntouch < OCC_TOUCH_MAX; k++) {
        const rad_vec3 v = sp->blkc.v[k];
        if (!(fabs(v3_dot(c->nx, v3_sub(v, co[0]))) <= c->snap) ||
            !holds(co, no, c->nx, v, c->snap))
            continue;
        int seen = 0;
        for (int l = 0; l < c->ntouch && !seen; l++)
            seen = v3_norm(v3_sub(c->touch[l], v)) <= c->snap;
        if (!seen)
            c->touch[c->ntouch++] = v;
    }
}

/* The integral over c's domain (occdomain.c) of the outer element co (no
 * vertices) into res, with `budget` times the mode's budgets of leaves
 * and evaluations; *met as for integrate. */
static int domain_integral(const rad_occ *o, occ_space *sp, pair_ctx *c, const rad_vec3 *co,
                           int no, double s, double rel, double budget, orient_result *res,
                           int *met)
{
    *met = 1;
    sp->any_hidden = sp->any_visible = 0;
    sp->arc_err = 0;
    c->direct = 0;
    const double area_o = c->outer_area;
    /* until the integral is under way: the largest target, for the
     * lenses' samples (occeee.c) and the first leaves */
    sp->noise_tol = rel * fabs(s) / (2 * RAD_PI) / area_o;
    if (occ_support_domain(sp, c, co, no))
        return -1;
    if (sp->dom.np == 0 && sp->umb.np == 0)
        return 0; /* no point of the outer element sees anything hidden */
    double dom_area = 0;
    for (int k = 0; k < sp->dom.np; k++)
        dom_area += poly_area(sp->dom.v + sp->dom.first[k], sp->dom.first[k + 1] - sp->dom.first[k]);
    for (int k = 0; k < sp->umb.np; k++)
        dom_area += poly_area(sp->umb.v + sp->umb.first[k], sp->umb.first[k + 1] - sp->umb.first[k]);
    if (dom_area < (1 - 1e-9) * area_o)
        sp->any_visible = 1; /* points outside the domain see all of the inner one */
    else if (sp->dom.np > 0 && o->accuracy != RAD_ACCURACY_CLASSIC)
        c->direct = res->direct = 1; /* the domain is all of it: integrate visible(x) */
    else if (sp->dom.np == 0) {
        res->hidden = 1; /* every point is in some blocker's umbra */
        res->value = s / (2 * RAD_PI);
        return 0;
    }
    const int adaptive = o->accuracy != RAD_ACCURACY_CLASSIC;
    const int leaves =
        o->accuracy == RAD_ACCURACY_REFERENCE ? OCC_LEAVES_REFERENCE : OCC_LEAVES_DEFAULT;
    const double evals =
        o->accuracy == RAD_ACCURACY_REFERENCE ? OCC_EVALS_REFERENCE : OCC_EVALS_DEFAULT;
    return integrate(sp, c, adaptive, rel, s / (2 * RAD_PI), dom_area, (int)(budget * leaves),
                     budget * evals, &res->value, &res->error, met);
}

/* domain_integral again, on c's new domain, from scratch and with
 * `budget` times the whole budget (before: sp->evals when the pair's
 * first try began; the count keeps every try). */
static int try_again(const rad_occ *o, occ_space *sp, pair_ctx *c, const rad_vec3 *co, int no,
                     double s, double rel, double before, double budget, orient_result *res,
                     int *met)
{
    const double spent = sp->evals - before;
    sp->evals = before;
    memset(res, 0, sizeof *res);
    if (domain_integral(o, sp, c, co, no, s, rel, budget, res, met))
        return -1;
    sp->evals += spent;
    return 0;
}

/* The occluded value A_o F_ot of res, whole the unoccluded one (S /
 * (2 pi)): the integral itself when direct, else whole less it. */
static double occluded_of(const orient_result *res, double whole)
{
    return res->direct ? res->value : whole - res->value;
}

/* Is the occluded value below OCC_NEAR_HIDDEN of the unoccluded one (S /
 * (2 pi)), with something hidden and something visible? */
static int nearly_hidden(const occ_space *sp, const orient_result *res, double s)
{
    const double whole = s / (2 * RAD_PI);
    return sp->any_hidden && sp->any_visible && occluded_of(res, whole) < OCC_NEAR_HIDDEN * whole;
}

/* The widest lens (a part of its chord) a partly hidden pair may keep
 * after its first try (occspace.h, OCC_ARC_TOL_*), or HUGE_VAL, by its
 * visible fraction (occluded over unoccluded value).  In default mode a
 * nearly hidden pair's is OCC_ARC_TOL_HIDDEN.  In reference mode the
 * lens error of a pair visible to less than OCC_PARTLY_HIDDEN, about the
 * cube of the lens's width, is scaled to its occluded value by the cube
 * root of its visible fraction.  (Seen on the 6x6 Cornell box: a
 * floor-to-ceiling pair visible to 6.6e-3 kept a chord of 21 mm whose
 * lens was 3.8e-4 of it, and was 3.5e-9 off, its estimate 5e-10.
 * Against a variant with every lens five times narrower: with lenses
 * narrowed for nearly hidden pairs alone, 6 entries above 1e-6 moved by
 * more than 1e-9, the worst a floor-to-wall pair visible to 0.18 by
 * 1.4e-8; with this rule 4 do, by up to 4.4e-9; with every partly
 * hidden pair, none, but a fuzzed scene of blocks took twice its time,
 * over a minute under AddressSanitizer.) */
static double arcs_by_fraction(const rad_occ *o, const occ_space *sp, const orient_result *res,
                               double s)
{
    if (o->accuracy == RAD_ACCURACY_DEFAULT)
        return nearly_hidden(sp, res, s) ? OCC_ARC_TOL_HIDDEN : HUGE_VAL;
    if (o->accuracy != RAD_ACCURACY_REFERENCE || !sp->any_hidden || !sp->any_visible)
        return HUGE_VAL;
    const double whole = s / (2 * RAD_PI), occluded = occluded_of(res, whole);
    if (!(occluded < OCC_PARTLY_HIDDEN * whole))
        return HUGE_VAL;
    return fmax(OCC_ARC_TOL_FINEST,
                OCC_ARC_TOL_REFERENCE * cbrt(fmin(fmax(occluded, 0) / whole, 1)));
}

/* The same by the lenses' error estimate (occeee.c, eq. 2: sp->arc_err):
 * where it is above OCC_ARC_SHARE of the pair's target (integrate, eq. 1),
 * the widest lens is narrowed so that, its error falling as the cube of
 * its width (eq. 2 for one chord; the measurements above occeee.c's
 * ARC_STRIPS fell about so), a lens as wide would leave a tenth of that
 * share; else HUGE_VAL.  (With strips the fall is faster, so this errs
 * toward narrower lenses.)  The rule's estimate alone does not see a
 * lens (top of occeee.c), so this is what keeps the two together within
 * the target. */
static double arcs_by_estimate(const rad_occ *o, const occ_space *sp, const orient_result *res,
                               double s, double rel)
{
    if (o->accuracy == RAD_ACCURACY_CLASSIC || !sp->any_hidden || !sp->any_visible ||
        !(sp->arc_left > 0))
        return HUGE_VAL;
    const double whole = s / (2 * RAD_PI);
    const double share = OCC_ARC_SHARE * rel * fmax(occluded_of(res, whole), OCC_FLOOR * whole);
    if (!(sp->arc_err > share))
        return HUGE_VAL;
    return fmax(OCC_ARC_TOL_FINEST, sp->arc_left * cbrt(0.1 * share / sp->arc_err));
}

/* The narrower of the two: the widest lens a pair may keep after its
 * first try, or HUGE_VAL. */
static double narrower_arcs(const rad_occ *o, const occ_space *sp, const orient_result *res,
                            double s, double rel)
{
    return fmin(arcs_by_fraction(o, sp, res, s), arcs_by_estimate(o, sp, res, s, rel));
}

/* try_again on c's domain cut along every event plane (OCC_SPLIT_ALL),
 * the planes of two blockers' events still only where they happen when
 * `pair_wedges`, with the whole budget and the lenses of that domain. */
static int every_plane(const rad_occ *o, occ_space *sp, pair_ctx *c, const rad_vec3 *co, int no,
                       double s, double rel, double before, int pair_wedges, orient_result *res,
                       int *met)
{
    c->events = OCC_SPLIT_ALL;
    c->pair_wedges = pair_wedges;
    sp->arc_left = 0;
    return try_again(o, sp, c, co, no, s, rel, before, 1, res, met);
}

/* The integral of the hidden part with element i (outer_i) or j as the
 * outer element.  In default mode a pair is first integrated, on
 * OCC_WEDGE_BUDGET of the budget, on a domain cut only where each event
 * happens (OCC_SPLIT_WEDGES, occevent.c: a third of the pieces on the
 * Cornell box, each with its own evaluations), the planes of two
 * blockers' events included (c.pair_wedges, occevent.c's BB wedges: most
 * of a triangulated model's pieces).  A pair that misses its target there
 * is done again, with the whole budget, on the domain cut along every
 * event plane (OCC_SPLIT_ALL: every_plane), a pair with more than
 * OCC_WEDGE_BLOCKERS blockers first with the two blockers' planes still
 * cut only where their events happen.  The extra cuts are no events of
 * one blocker, but they refine the domain where kinks may be left inside
 * a piece (the lens between a chord of occeee.c and its arc; events its
 * filter judged not to happen).  Reference mode always cuts every plane:
 * before occeee.c cut the events of three edges, 38 entries of the 6x6
 * closed Cornell box moved by more than both runs' estimates with the
 * wedges only.  A pair whose chords of occeee.c left lenses wider than its
 * value needs (narrower_arcs) is done once more with narrower ones. */
static int orient_integral(const rad_occ *o, occ_space *sp, int nb, const rad_ff_poly *pi,
                           const rad_ff_poly *pj, int outer_i, double s, double rel,
                           orient_result *res)
{
    const rad_vec3 *ci = sp->elem.v, *cj = sp->elem.v + sp->elem.first[1];
    int ni = sp->elem.first[1], nj = sp->elem.nv - ni;
    const rad_ff_poly *po = outer_i ? pi : pj, *pt = outer_i ? pj : pi;
    const rad_vec3 *co = outer_i ? ci : cj, *ct = outer_i ? cj : ci;
    int no = outer_i ? ni : nj, nt = outer_i ? nj : ni;
    memset(res, 0, sizeof *res);
    int kept = clip_blockers(o, sp, nb, pt->normal, ct[0], !outer_i);
    if (kept < 0)
        return -1;
    pair_ctx c;
    c.nx = po->normal;
    c.tn = pt->normal;
    c.t = ct;
    c.nt = nt;
    c.flat = inner_flat(pt, ct, nt);
    c.nb = kept;
    c.snap = sp->snap;
    c.sliver = OCC_SLIVER * poly_area(ct, nt);
    c.outer_area = poly_area(co, no);
    c.events = o->accuracy == RAD_ACCURACY_CLASSIC   ? 0
               : o->accuracy == RAD_ACCURACY_DEFAULT ? OCC_SPLIT_WEDGES
                                                     : OCC_SPLIT_ALL;
    c.pair_wedges = o->accuracy == RAD_ACCURACY_DEFAULT;
    c.order = o->accuracy == RAD_ACCURACY_REFERENCE ? OCC_ORDER_REFERENCE
              : o->accuracy == RAD_ACCURACY_DEFAULT ? OCC_ORDER_DEFAULT
                                                    : 0;
    c.arc_tol = o->accuracy == RAD_ACCURACY_REFERENCE ? OCC_ARC_TOL_REFERENCE : OCC_ARC_TOL_DEFAULT;
    c.whole_near = o->accuracy == RAD_ACCURACY_CLASSIC;
    touch_points(sp, &c, co, no);
    if (occ_union_frame(sp, &c))
        return -1;
    int met;
    const double before = sp->evals;
    double budget = c.events == OCC_SPLIT_WEDGES ? OCC_WEDGE_BUDGET : 1;
    sp->arc_left = 0;
    if (domain_integral(o, sp, &c, co, no, s, rel, budget, res, &met))
        return -1;
    /* more than OCC_WEDGE_BLOCKERS blockers: every plane, but the two
     * blockers' still where they happen; then every plane */
    if (!met && c.events == OCC_SPLIT_WEDGES && kept > OCC_WEDGE_BLOCKERS &&
        every_plane(o, sp, &c, co, no, s, rel, before, 1, res, &met))
        return -1;
    if (!met && (c.events == OCC_SPLIT_WEDGES || c.pair_wedges) &&
        every_plane(o, sp, &c, co, no, s, rel, before, 0, res, &met))
        return -1;
    const double arc_tol = narrower_arcs(o, sp, res, s, rel);
    if (sp->arc_left > arc_tol) {
        /* the narrower lenses add pieces, so default mode's budget is
         * larger (OCC_LENS_BUDGET); if they miss the target with a larger
         * estimate all the same, the first try stays.
         * (Where the strips' budget, occeee.c's ARC_PIECES, runs out, a
         * chord or two may keep a lens wider than the first try's; the
         * second try stays all the same: keeping the first on that
         * ground put a pair of tests/accuracy/occeee.sh hidden to 1.3e-4 back by
         * the 5e-8 that narrower lenses everywhere had removed.) */
        const orient_result first = *res;
        const int hidden = sp->any_hidden, visible = sp->any_visible;
        const double lens_budget = o->accuracy == RAD_ACCURACY_DEFAULT ? OCC_LENS_BUDGET : 1;
        c.arc_tol = arc_tol;
        sp->arc_left = 0;
        if (try_again(o, sp, &c, co, no, s, rel, before, lens_budget, res, &met))
            return -1;
        if (!met && res->error > first.error) {
            *res = first;
            sp->any_hidden = hidden;
            sp->any_visible = visible;
        }
    }
    res->hidden |= sp->any_hidden;
    res->visible |= sp->any_visible;
    if (res->hidden && !res->visible)
        res->value = s / (2 * RAD_PI);
    return 0;
}

/* The new S of a pair with nb blockers in sp->blk: 0 when one blocker
 * hides all, else S less 2 pi times the integral of the hidden part.
 * *direct: the new S does not depend on S, so S's error does not pass to
 * it (the visible part was integrated itself, or one blocker hides all:
 * the value is then 0 exactly, not S's estimate). */
int occ_occluded_sum(const rad_occ *o, occ_space *sp, rad_occ_stats *st, int nb,
                     const rad_ff_poly *pi, const rad_ff_poly *pj, double s, double *snew,
                     double *errest, int *direct)
{
    const rad_vec3 *ci = sp->elem.v, *cj = sp->elem.v + sp->elem.first[1];
    int ni = sp->elem.first[1], nj = sp->elem.nv - ni;
    *snew = s;
    *direct = 0;
    for (int b = 0; b < nb; b++) {
        const rad_vec3 *v = sp->blk.v + sp->blk.first[b];
        int n = sp->blk.first[b + 1] - sp->blk.first[b];
        if (hides_all(ci, ni, cj, nj, v, n, o->snormal[sp->bid[b]], sp->snap)) {
            st->pairs_blocked++;
            *snew = 0;
            *direct = 1;
            return 0;
        }
    }
    /* outer: the element that looks smaller from the nearest blocker */
    int outer_i = apparent_size(o, sp, nb, pi) <= apparent_size(o, sp, nb, pj);
    double rel =
        o->accuracy == RAD_ACCURACY_REFERENCE ? OCC_TOL_REFERENCE : OCC_TOL_DEFAULT;
    orient_result r;
    sp->evals = 0;
    if (orient_integral(o, sp, nb, pi, pj, outer_i, s, rel, &r))
        return -1;
    if (r.hidden && !r.visible) {
        /* Everything looked hidden from the outer element's points: a
         * visible part may hide in a thin strip between them.  Look from
         * the other element; keep its answer if it sees something. */
        orient_result r2;
        if (orient_integral(o, sp, nb, pi, pj, !outer_i, s, rel, &r2))
            return -1;
        if (r2.visible)
            r = r2;
    }
    st->evaluations += sp->evals;
    if (!r.hidden)
        return 0; /* nothing hidden anywhere: the kernel's value, bit for bit */
    if (!r.visible) {
        st->pairs_blocked++;
        *snew = 0;
        return 0;
    }
    st->pairs_partial++;
    double v = r.direct ? 2 * RAD_PI * r.value : s - 2 * RAD_PI * r.value;
    *snew = v < 0 ? 0 : v > s && !r.direct ? s : v;
    *direct = r.direct;
    if (errest)
        *errest += 2 * RAD_PI * r.error;
    st->max_errest = fmax(st->max_errest, r.error / fmin(pi->area, pj->area));
    return 0;
}
