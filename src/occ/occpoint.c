/* occpoint.c -- the hidden part seen from one point: hidden(x), the form
 * factor from a point x of the outer element to the part of the inner
 * element that the blockers hide from it.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The part of the inner element A_t hidden from x by a blocker polygon P
 * is A_t intersected with the cone from x over P (P clipped to the front
 * of A_t's plane; the cone is bounded by the planes through x and each
 * edge of P, the shadow volume of Crow 1977).  Subtracting a convex cone
 * from a convex piece leaves convex pieces (one cut per cone plane;
 * Sutherland & Hodgman 1974 clipping), so the visible part stays a list
 * of convex pieces, and each hidden piece adds its point-to-polygon form
 * factor (Lambert 1760; as written in Baum, Rushmeier & Winget, SIGGRAPH
 * 1989, eq. 6):
 *     F(x -> Q) = -1/(2 pi) sum_k gamma_k n_x . (R_k x R_k+1)/|R_k x R_k+1|,
 * R_k = q_k - x, gamma_k the angle between R_k and R_k+1 (the sign is for
 * Q counter-clockwise about a normal that faces x).
 *
 * For the last blocker, whose visible remainder is not needed, the hidden
 * part of a piece is found the other way round when the blocker lies
 * between x's level and the inner plane, and the inner element is planar
 * to round-off: the cone's section by that plane is the central
 * projection of the blocker, and clipping it by the piece's few edges
 * costs O(K) for a K-gon where K cone cuts cost O(K^2) (hidden_last).
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


/* ff_point_polygon's sum again in long double (-2 pi times the factor). */
static long double sum_long(rad_vec3 x, rad_vec3 nrm, const rad_vec3 *q, int m)
{
    long double sum = 0;
    for (int k = 0; k < m; k++)
        sum += occ_edge_term_long(q[k > 0 ? k - 1 : m - 1], q[k], x, nrm);
    return sum;
}

/* The sum of eq. 6 below (-2 pi times the factor) in double, and when
 * size is not NULL the sum of its terms' magnitudes there. */
static inline double sum_double(rad_vec3 x, rad_vec3 nrm, const rad_vec3 *q, int m, double *size)
{
    double sum = 0;
    rad_vec3 r0 = v3_sub(q[m - 1], x);
    for (int k = 0; k < m; k++) {
        rad_vec3 r1 = v3_sub(q[k], x);
        rad_vec3 c = v3_cross(r0, r1);
        double cn = v3_norm(c);
        if (cn > 0) {
            const double t = atan2(cn, v3_dot(r0, r1)) * v3_dot(nrm, c) / cn;
            sum += t;
            if (size)
                *size += fabs(t);
        }
        r0 = r1;
    }
    return sum;
}

/* Point-to-polygon form factor from a differential area at x with unit
 * normal nrm to polygon q (Lambert 1760; Baum et al. 1989, eq. 6).
 *
 * Its terms cancel where the polygon is seen nearly edge on: the
 * factor is then far smaller than its terms, and their round-off, about
 * OCC_NOISE_EPS eps times the sum of their magnitudes, is not small beside
 * it.  (Each term rounds a few times, in its atan2, cross product, norm
 * and quotient, and the sum m more, so (m + 8) eps would bound it; but the
 * roundings fall either way.  Over the 3.9e7 sums of the closed 2x2
 * Cornell box in reference mode, the double sum was off from the long
 * double one by more than eps times the magnitudes in 9.4%, 4 eps in
 * 1.9%, 8 eps in 1.0%; and with the bound the 6x6 box's fill took about
 * 11% longer than with 4 eps, median of three paired runs.)
 * Where that round-off could exceed tol, the sum is done
 * again in long double (11 more bits on x86-64; no gain where long
 * double is double), from differences q - x that are exact there.  (The
 * differences' own rounding in double, an ulp of the coordinates, is a
 * perturbation of the geometry that this model does not count.)
 * (Seen on the closed 6x6 Cornell box: a ceiling element and a side of
 * the short block, visible to 4.3e-2 of its unoccluded factor, whose
 * hidden(x) is 2.6e-9.  In double the rule's estimates stopped at the
 * round-off, 4e-11 of hidden(x) on every cell however small, and the
 * pair spent its 4e5 evaluations with an estimate of 1.25e-9 of its
 * value; in long double it meets its target in a few hundred, the
 * value moving by 1.3e-11 of itself.) */
static double ff_point_polygon(rad_vec3 x, rad_vec3 nrm, const rad_vec3 *q, int m, double tol)
{
    /* each term is at most its angle, and the angles of a convex polygon
     * seen from a point off its plane sum to less than 2 pi: from this
     * tol up, no sum needs its terms' sizes */
    if (!(OCC_NOISE_EPS * DBL_EPSILON > tol))
        return -sum_double(x, nrm, q, m, NULL) / (2 * RAD_PI);
    double size = 0;
    const double sum = sum_double(x, nrm, q, m, &size);
    if (OCC_NOISE_EPS * DBL_EPSILON * size > 2 * RAD_PI * tol)
        return (double)(-sum_long(x, nrm, q, m) / (2 * RAD_PI_LONG));
    return -sum / (2 * RAD_PI);
}

/* The cone planes through x and each edge of blocker b, unit normals
 * pointing inside; returns their count (0 when x is on b's plane), -1. */
static int cone_planes(occ_space *sp, const pair_ctx *c, int b, rad_vec3 x)
{
    const rad_vec3 *p = sp->blkc.v + sp->blkc.first[b];
    int n = sp->blkc.first[b + 1] - sp->blkc.first[b];
    if (fabs(v3_dot(sp->bn[b], v3_sub(x, sp->bc[b]))) <= c->snap)
        return 0;
    if (occ_grow_v3(&sp->cone, &sp->capcone, n) || occ_grow_v3(&sp->conep, &sp->capconep, n))
        return -1;
    int m = 0;
    rad_vec3 inner = v3_sub(sp->bc[b], x);
    for (int k = 0; k < n; k++) {
        rad_vec3 nrm = v3_cross(v3_sub(p[k], x), v3_sub(p[(k + 1) % n], x));
        double len = v3_norm(nrm);
        if (!(len > 0))
            continue;
        nrm = v3_scale(nrm, 1.0 / len);
        sp->conep[m] = x;
        sp->cone[m++] = v3_dot(nrm, inner) < 0 ? v3_scale(nrm, -1.0) : nrm;
    }
    return m;
}

/* The shadow of blocker b from x on the inner plane: the central
 * projection of its vertices, y = x + (p - x) h / (tn . (p - x)) with
 * h = tn . (t0 - x), into sp->pj0.  It is the cone's section by the plane
 * only when every vertex lies strictly between x's level and the plane
 * (all denominators of h's sign, away from 0); returns the vertex count,
 * 0 when not so (the caller then cuts by the cone planes), -1. */
static int shadow_polygon(occ_space *sp, const pair_ctx *c, int b, rad_vec3 x)
{
    const rad_vec3 *p = sp->blkc.v + sp->blkc.first[b];
    int n = sp->blkc.first[b + 1] - sp->blkc.first[b];
    double h = v3_dot(c->tn, v3_sub(c->t[0], x));
    if (!(h < -c->snap) || occ_grow_v3(&sp->pj0, &sp->cappj0, n))
        return h < -c->snap ? -1 : 0;
    for (int k = 0; k < n; k++) {
        rad_vec3 r = v3_sub(p[k], x);
        double dk = v3_dot(c->tn, r);
        if (!(dk < -c->snap))
            return 0;
        sp->pj0[k] = v3_add(x, v3_scale(r, h / dk));
    }
    return n;
}

/* The part of the shadow (sp->pj0, m vertices) inside the convex piece q
 * (nq vertices, on the inner plane): the shadow clipped by q's edges
 * (Sutherland & Hodgman 1974), left in sp->pj0; returns its vertex count
 * (0: nothing), -1. */
static int shadow_in_piece(occ_space *sp, const pair_ctx *c, const rad_vec3 *q, int nq, int m)
{
    double turn = v3_dot(v3_newell(q, nq), c->tn) < 0 ? -1.0 : 1.0;
    for (int k = 0; k < nq && m >= 3; k++) {
        rad_vec3 e = v3_sub(q[(k + 1) % nq], q[k]), nrm = v3_cross(c->tn, e);
        double len = v3_norm(nrm), lo, hi;
        if (!(len > 0))
            continue;
        if (occ_grow_d(&sp->d, &sp->capd, m) || occ_grow_v3(&sp->pj1, &sp->cappj1, m + 1))
            return -1;
        poly_distances(sp->pj0, m, v3_scale(nrm, turn / len), q[k], c->snap, sp->d, &lo, &hi);
        poly_settle_signs(sp->d, m, &lo, &hi);
        if (hi <= 0)
            return 0;
        if (lo >= 0)
            continue;
        m = poly_clip_side(sp->pj0, sp->d, m, 1.0, sp->pj1, m + 1);
        occ_swap_v3(&sp->pj0, &sp->cappj0, &sp->pj1, &sp->cappj1);
    }
    return m >= 3 ? m : 0;
}

/* The last blocker's share of hidden(x), when its shadow is a polygon:
 * each visible piece q loses q intersected with the shadow.  That is
 * the same set as q cut by the cone planes, but it costs O(nq K) for a
 * K-gon blocker instead of O(K^2): the cuts of cut_piece make the piece a
 * K-gon one plane at a time (reference mode once slowed as K^4).
 * The visible remainder is not built, since no blocker follows; only
 * whether some is left.  Returns 1 when done (*h increased), 0 when the
 * shadow is no polygon, -1.
 * Only for an inner element planar to round-off (c->flat): the shadow
 * lies on the plane through its first vertex, and where a twisted
 * element's edges leave that plane, the contours of q and of its hidden
 * part no longer share those edges, and hidden(x) gains the flux through
 * the ribbon between them.  The cone cuts keep the element's own edges.
 * (Fuzzed scene 62:871, F(9 -> 35), an inner tile twisted 6e-13 over
 * 0.0058 beside a box, visible to 1.35e-4 of its unoccluded factor: this
 * way both modes were 8e-9 of the value high, under estimates of 3e-10
 * (tests/accuracy/occsolid.sh).  At points of the outer element, against
 * tests/pairref.py's computation in 40 digits (the tile as its bilinear
 * surface), the cone cuts are within 3e-12 of visible(x); this way was
 * 9e-9 off where the tile is partly seen, and saw 1e-15 where all of it
 * is hidden.) */
static int hidden_last(occ_space *sp, const pair_ctx *c, int b, rad_vec3 x, double *h)
{
    int n = shadow_polygon(sp, c, b, x);
    if (n <= 0)
        return n;
    if (occ_grow_v3(&sp->tmp, &sp->captmp, n))
        return -1;
    memcpy(sp->tmp, sp->pj0, sizeof *sp->tmp * (size_t)n); /* the whole shadow */
    int visible = 0;
    for (int k = 0; k < sp->cur.np; k++) {
        const rad_vec3 *q = sp->cur.v + sp->cur.first[k];
        int nq = sp->cur.first[k + 1] - sp->cur.first[k];
        if (occ_grow_v3(&sp->pj0, &sp->cappj0, n))
            return -1;
        memcpy(sp->pj0, sp->tmp, sizeof *sp->pj0 * (size_t)n);
        int m = shadow_in_piece(sp, c, q, nq, n);
        if (m < 0)
            return -1;
        double am = m ? poly_area(sp->pj0, m) : 0;
        if (am > c->sliver) {
            *h += fabs(ff_point_polygon(x, c->nx, sp->pj0, m, sp->noise_tol));
            sp->any_hidden = 1;
        } else {
            am = 0;
        }
        /* q's area only while nothing visible has been seen (the flag
         * stays for the pair: an area per piece and point was a tenth of
         * the evaluations' time) */
        if (!visible && !sp->any_visible)
            visible = poly_area(q, nq) - am > c->sliver;
    }
    if (visible)
        sp->any_visible = 1;
    occ_ps_clear(&sp->cur); /* the caller's test for anything visible is done */
    return 1;
}

/* hidden(x): the form factor from x to the part of the inner element that
 * the blockers hide.  Sets sp->any_hidden / any_visible. */
static int hidden_at(occ_space *sp, const pair_ctx *c, rad_vec3 x, double *out)
{
    double h = 0;
    occ_ps_clear(&sp->cur);
    if (occ_ps_push(&sp->cur, c->t, c->nt))
        return -1;
    sp->evals++;
    for (int b = 0; b < c->nb && sp->cur.np > 0; b++) {
        if (b == c->nb - 1 && c->flat &&
            fabs(v3_dot(sp->bn[b], v3_sub(x, sp->bc[b]))) > c->snap) {
            int r = hidden_last(sp, c, b, x, &h);
            if (r < 0)
                return -1;
            if (r > 0) {
                *out = h;
                return 0;
            }
        }
        int ncone = cone_planes(sp, c, b, x);
        if (ncone < 0)
            return -1;
        if (ncone < 3)
            continue;
        occ_ps_clear(&sp->next);
        for (int k = 0; k < sp->cur.np; k++) {
            int n = occ_load_rem(sp, &sp->cur, k);
            int r = n < 0 ? -1
                          : occ_cut_piece(sp, sp->cone, sp->conep, ncone, c->snap, c->sliver,
                                          OCC_SLIVERS_DROP, &sp->next, &n);
            if (r < 0)
                return -1;
            if (r > 0) {
                h += ff_point_polygon(x, c->nx, sp->rem, n, sp->noise_tol);
                sp->any_hidden = 1;
            }
        }
        polyset t = sp->cur;
        sp->cur = sp->next;
        sp->next = t;
    }
    if (sp->cur.np > 0)
        sp->any_visible = 1;
    *out = h;
    return 0;
}

/* hidden(x) (occunion.c where the inner element is planar and x off its
 * plane, else the cuts above), or with c->direct the visible part's factor
 *     visible(x) = F(x -> A_t) - hidden(x)
 * (occhidden.c integrates it for pairs whose domain is the whole outer
 * element).  Both terms are exact to round-off, so visible(x) is too, to
 * a few ulps of F(x -> A_t): no error of the unoccluded contour sum S enters
 * a nearly hidden pair's value. */
int occ_hidden_at(occ_space *sp, const pair_ctx *c, rad_vec3 x, double *out)
{
    const int r = occ_hidden_union(sp, c, x, out);
    if (r < 0 || (r == 0 && hidden_at(sp, c, x, out)))
        return -1;
    if (c->direct)
        *out = fabs(ff_point_polygon(x, c->nx, c->t, c->nt, sp->noise_tol)) - *out;
    return 0;
}
