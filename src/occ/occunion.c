/* occunion.c -- hidden(x) from the boundary of the union of the blockers'
 * shadows: a cost of O(K^2) edge tests for K blockers, where cutting the
 * visible pieces by each blocker's cone in turn (occpoint.c) can leave a
 * number of pieces that grows with every blocker whose shadow overlaps
 * the others'.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * From a point x of the outer element, blocker P hides the part of the
 * inner element A_t that lies in the central projection from x of P onto
 * A_t's plane (Crow 1977's shadow volume cut by that plane).  For an inner
 * element planar to round-off (pair_ctx.flat), P is first clipped to the
 * front of that plane (occshaft.c) and to a pyramid from x over A_t
 * widened OCC_UNION_WIDEN times about its centre, so that its projection
 * S_P is finite, and the hidden part is A_t intersected with the union U
 * of the S_P.  In classic mode (pair_ctx.whole_near) a blocker that a
 * pyramid plane crosses is left whole when every vertex lies at least
 * OCC_UNION_NEAR of the way from x's level to the inner plane: its projection
 * y = x + (p - x) h / (tn . (p - x)), h = tn . (t0 - x), is then finite,
 * at most 1 / OCC_UNION_NEAR times as far from x as the blocker, and what
 * the clip would cut off lies outside the pyramid, so outside A_t.  Its
 * edges may then be long beside A_t, and a crossing on an edge is placed
 * to 2^-40 of the edge's length (orient, below): round-off far below
 * classic mode's rule, but the adaptive modes' estimates can stall on it
 * (on a block's side seen nearly edge on, 8 pairs of reference mode
 * missed their promise so, tests/accuracy/occeee.sh), and they clip.
 * The point-to-polygon form factor of eq. 6 (Baum, Rushmeier
 * & Winget 1989; Lambert 1760),
 *     F(x -> Q) = -1/(2 pi) sum_k gamma_k n_x . (R_k x R_k+1)/|R_k x R_k+1|,
 * is a sum over Q's boundary edges, each term a function of the edge's two
 * ends alone (Stokes' theorem), so it holds for any region whose boundary
 * is a set of oriented segments, holes and separate parts included.  The
 * boundary of A_t intersected with U is made of
 *   - the parts of each shadow's edges strictly inside A_t and inside no
 *     other shadow, and
 *   - the parts of A_t's own edges inside some shadow.
 * Each shadow and A_t are convex, so the part of an edge inside one of
 * them is one interval of the edge's parameter (Cyrus & Beck 1978; Liang
 * & Barsky 1984): the edges lose or keep unions of intervals, and eq. 6
 * is summed over what remains.  The widening keeps the clip's edges away
 * from A_t's, which every evaluation would otherwise meet at a grazing
 * angle.
 *
 * An edge that one other shadow has too, run the other way (two
 * triangles of one mesh that share an edge, seen from the same side), is
 * inside the union and is dropped before any test (inner_edges): what is
 * left of a mesh is its outline.  Other edges that lie on each other's
 * lines are covered as half-open sets: an edge on
 * another shadow's edge of the opposite direction is kept, and so is the
 * other's, and the two cancel in the sum (their terms are exact
 * negatives, their ends being the same projected vertices); on one of the
 * same direction only the copy of the lower-numbered shadow is kept, and
 * A_t's edge counts as the lowest of all.  The decisions are exact signs
 * of orientations in the plane's own axes (orient): with a tolerance, two
 * nearly coincident edges could each be judged inside the other's shadow
 * and both be dropped, leaving a hole in the boundary.
 *
 * What cannot reach A_t is left out before any edge test: a blocker whose
 * penumbra misses the cell of the outer element that x belongs to (found
 * once a cell: occdomain.c, occ_cell_blockers), a blocker whose ball
 * (about its centroid, through its farthest vertex) lies wholly outside
 * the widened pyramid, and a shadow, or a shadow's edge, whose box misses
 * A_t's box.  Such a shadow lies outside A_t, and so do its edges
 * and the intervals it covers of other edges: it adds no segment to the
 * boundary and removes none, and the sum is the same.  The ball also
 * spares the clip's distances where it lies wholly inside a pyramid
 * plane.  Its test is taken beyond the snap (at least 1e-11 of the
 * scene's size, occspace.h), which covers the round-off of the ball and
 * of the vertices the clips construct, rounded to the pair frame's
 * coordinates; OCC_BALL_MARGIN adds the round-off of the distance itself.
 *
 * The cost is O(K^2) edge tests for K blockers (pairs of shadows whose
 * boxes miss are skipped), where cutting the visible pieces by each
 * blocker's cone in turn (occpoint.c, hidden_at) leaves pieces whose
 * number grows with every blocker whose shadow overlaps the others'.
 * Measured against those cuts at every evaluation point of the Cornell
 * box, the cube on a table, 4 x 4 staggered squares (bench/scenes.py) and
 * a room with a box 5e-12 off its wall (classic mode): the two agree
 * within 1e-9 of hidden(x) or 3e-14 absolute.  The sum is exact to round-off, like the cuts it
 * replaces; where its terms' magnitudes could leave round-off above the
 * evaluation's noise tolerance it is summed again in long double
 * (occpoint.c's rule).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "occ/occlusion.h"
#include "occ/occspace.h"
#include "util/util.h"
#include "radiosity/base.h"


/* How far the pyramid reaches beyond the inner element, as a scale
 * about its centre: the shadows are clipped to it so that their
 * projection stays finite, and well away from the inner element's edges,
 * so that the clip's edges never lie near those edges' lines (they would
 * meet them at a grazing angle on every evaluation). */
#define OCC_UNION_WIDEN 3.0

/* In classic mode a blocker that a plane of that pyramid crosses is not
 * clipped when its every vertex lies at least this part of the way from
 * x's level to the inner plane (header): its shadow is then at most 8
 * times as far from x as it is.  Those clips were 8% of classic mode's
 * instructions on a triangulated torus over a floor (bench/scenes.py
 * torus 60); 1/4 or 1/32 here change that by about 1%. */
#define OCC_UNION_NEAR 0.125

/* A bound, relative to the sizes involved, far above the round-off of a
 * signed distance nrm . (p - x) in double (about 3 sqrt(3) eps |p - x|):
 * in_pyramid's ball test, beyond the snap (header). */
#define OCC_BALL_MARGIN 1e-12

/* The planes through x and each edge of the inner element widened by
 * OCC_UNION_WIDEN, unit normals pointing inside, into sp->upl; returns their count, 0 when
 * some edge is seen end on from x, -1 when memory ran out. */
static int pyramid(occ_space *sp, const pair_ctx *c, rad_vec3 x)
{
    if (occ_grow_v3(&sp->upl, &sp->capupl, c->nt))
        return -1;
    const rad_vec3 mid = v3_sub(c->tmean, x);
    for (int k = 0; k < c->nt; k++) {
        const rad_vec3 a = sp->tw[k], b = sp->tw[(k + 1) % c->nt];
        rad_vec3 nrm = v3_cross(v3_sub(a, x), v3_sub(b, x));
        const double len = v3_norm(nrm);
        if (!(len > 0))
            return 0;
        nrm = v3_scale(nrm, 1.0 / len);
        sp->upl[k] = v3_dot(nrm, mid) < 0 ? v3_scale(nrm, -1.0) : nrm;
    }
    return c->nt;
}

/* Do the m vertices p all lie at least OCC_UNION_NEAR of the way from
 * x's level to the inner plane (h = tn . (t0 - x))? */
static int beyond_near(const pair_ctx *c, const rad_vec3 *p, int m, rad_vec3 x, double h)
{
    for (int l = 0; l < m; l++) {
        const double dk = v3_dot(c->tn, v3_sub(p[l], x));
        if (!(dk * h > 0 && fabs(dk) >= OCC_UNION_NEAR * fabs(h)))
            return 0;
    }
    return 1;
}

/* Blocker b's part inside the pyramid (sp->upl) into sp->pj0, or with
 * c->whole_near all of it when it reaches the pyramid's inside and lies
 * wholly beyond OCC_UNION_NEAR of the way to the inner plane; returns
 * its vertex count (0: none), -1. */
static int in_pyramid(occ_space *sp, const pair_ctx *c, int b, rad_vec3 x, double h)
{
    const rad_vec3 *p = sp->blkc.v + sp->blkc.first[b];
    int m = sp->blkc.first[b + 1] - sp->blkc.first[b];
    if (occ_grow_v3(&sp->pj0, &sp->cappj0, m + c->nt) ||
        occ_grow_v3(&sp->pj1, &sp->cappj1, m + c->nt + 1) ||
        occ_grow_d(&sp->d, &sp->capd, m + c->nt))
        return -1;
    memcpy(sp->pj0, p, sizeof *p * (size_t)m);
    /* the ball about bc of radius br holds the blocker and every part of
     * it that a clip keeps; where it lies beyond the margin (header) on
     * one side of a plane, so does every vertex, and the distances need
     * not be taken: the clip would keep all, or nothing */
    const rad_vec3 bc = sp->bc[b];
    const double br = sp->br[b],
                 margin = c->snap + OCC_BALL_MARGIN * (3 * v3_maxabs(v3_sub(bc, x)) + br);
    int whole = c->whole_near ? -1 : 0; /* left unclipped: -1 not yet known */
    for (int k = 0; k < c->nt && m >= 3; k++) {
        const double dc = v3_dot(sp->upl[k], v3_sub(bc, x));
        if (dc - br > margin)
            continue;
        if (dc + br < -margin)
            return 0;
        if (whole < 0)
            whole = beyond_near(c, p, m, x, h);
        if (whole)
            continue;
        double lo, hi;
        poly_distances(sp->pj0, m, sp->upl[k], x, c->snap, sp->d, &lo, &hi);
        poly_settle_signs(sp->d, m, &lo, &hi);
        if (hi <= 0)
            return 0;
        if (lo >= 0)
            continue;
        m = poly_clip_side(sp->pj0, sp->d, m, 1.0, sp->pj1, m + c->nt + 1);
        occ_swap_v3(&sp->pj0, &sp->cappj0, &sp->pj1, &sp->cappj1);
    }
    return m >= 3 ? m : 0;
}

/* Do boxes p and q (ulo, uhi, vlo, vhi) meet, edges included? */
static inline int boxes_meet(const double *p, const double *q)
{
    return p[0] <= q[1] && q[0] <= p[1] && p[2] <= q[3] && q[2] <= p[3];
}

/* Shadow s's vertices (sp->pj0, m of them) in the plane's axes c->ue,
 * from the inner element's first vertex, into sp->uv from f, and their
 * box into sp->box + 4 s; 0, -1. */
static int shadow_uv(occ_space *sp, const pair_ctx *c, int s, int f, int m)
{
    const rad_vec3 *e = c->ue;
    if (occ_grow_d(&sp->uv, &sp->capuv, 2 * (f + m)) ||
        occ_grow_d(&sp->box, &sp->capbox, 4 * (s + 1)))
        return -1;
    double *bx = sp->box + 4 * s;
    for (int k = 0; k < m; k++) {
        const rad_vec3 r = v3_sub(sp->pj0[k], c->t[0]);
        const double u = v3_dot(r, e[0]), v = v3_dot(r, e[1]);
        sp->uv[2 * (f + k)] = u;
        sp->uv[2 * (f + k) + 1] = v;
        if (k == 0 || u < bx[0])
            bx[0] = u;
        if (k == 0 || u > bx[1])
            bx[1] = u;
        if (k == 0 || v < bx[2])
            bx[2] = v;
        if (k == 0 || v > bx[3])
            bx[3] = v;
    }
    return 0;
}

/* Reverse the m vertices of sp->pj0 and their m points of sp->uv from f. */
static void shadow_reverse(occ_space *sp, int f, int m)
{
    for (int k = 0; k < m / 2; k++) {
        const rad_vec3 t = sp->pj0[k];
        sp->pj0[k] = sp->pj0[m - 1 - k];
        sp->pj0[m - 1 - k] = t;
        double *p = sp->uv + 2 * (f + k), *q = sp->uv + 2 * (f + m - 1 - k);
        const double u = p[0], v = p[1];
        p[0] = q[0];
        p[1] = q[1];
        q[0] = u;
        q[1] = v;
    }
}

/* The shadows of the blockers from x (h = tn . (t0 - x)) on the inner
 * plane into sp->sh, each turned like the inner element (c->usense
 * against tn), with their bounding boxes; returns 1, 0 when some blocker
 * touches x (the caller then cuts by cones), -1.  Only the blockers of
 * the cell being evaluated are taken (sp->cell_on: occdomain.c,
 * occ_cell_blockers).  A shadow whose box misses the inner element's
 * (c->tbox) is left out: it hides nothing of the inner element, its
 * edges lie outside it, and so do the intervals it covers of other edges,
 * so it adds no segment to the boundary and removes none. */
static int shadows(occ_space *sp, const pair_ctx *c, rad_vec3 x, double h)
{
    occ_ps_clear(&sp->sh);
    const int *list = sp->cell_on ? sp->clist + sp->cell_first : NULL;
    const int nlist = list ? sp->cell_n : c->nb;
    for (int i = 0; i < nlist; i++) {
        const int b = list ? list[i] : i;
        const double ahead = v3_dot(sp->bn[b], v3_sub(x, sp->bc[b]));
        if (fabs(ahead) <= c->snap)
            continue; /* seen edge on: hides nothing (occpoint.c, cone_planes) */
        if (ahead < 0 && sp->bx[b])
            continue; /* a closed mesh's face x is behind: an exit (header) */
        int m = in_pyramid(sp, c, b, x, h);
        if (m <= 0) {
            if (m < 0)
                return -1;
            continue;
        }
        for (int k = 0; k < m; k++) {
            const rad_vec3 r = v3_sub(sp->pj0[k], x);
            const double dk = v3_dot(c->tn, r);
            if (!(dk * h > 0))
                return 0;
            sp->pj0[k] = v3_add(x, v3_scale(r, h / dk));
        }
        const int s = sp->sh.np, f = sp->sh.nv;
        if (shadow_uv(sp, c, s, f, m))
            return -1;
        if (!boxes_meet(sp->box + 4 * s, c->tbox))
            continue;
        const rad_vec3 nw = v3_newell(sp->pj0, m); /* poly_area's, taken once */
        const double turn = v3_dot(nw, c->tn) * c->usense;
        if (!(0.5 * v3_norm(nw) > c->sliver))
            continue;
        if (turn < 0)
            shadow_reverse(sp, f, m);
        if (occ_ps_push(&sp->sh, sp->pj0, m))
            return -1;
    }
    return 1;
}

/* The sign of orient2d(a, b, c) = (b - a) x (c - a) in the plane, and in
 * *det its value to a relative 2^-40.  The double determinant has an
 * error below ccwerrboundA = (3 + 16 eps) eps times the magnitudes of its
 * two products (Shewchuk 1997); it is used where that bound is below
 * 2^-40 of it.  Else the differences of coordinates are split into
 * exact pairs of doubles (Knuth's two-sum) and the products' leading
 * terms taken exactly with fma (Shewchuk's stage B): what is left out or
 * rounded is below 16 u^2 (u = eps/2) times the two products'
 * magnitudes, and that value is used where that bound is below 2^-41 of
 * it (checked against binary128 on 2e7 random orientations of points
 * within 2^-60 of collinear: 99.95% decided there, every sign right, the
 * worst value 4.4e-14 off); exact differences with equal exact products
 * are a point on the line (the axis-aligned corners of a box's faces),
 * exactly 0.  Else it is done again in binary128, where the differences
 * of coordinates are exact (their exponents differ by less than 60: true
 * of points inside one element unless one is within 2^-60 of its size of
 * the origin, the element's first vertex) and so are the two products of
 * 54-bit numbers: the sign of their difference is exact and its value is
 * rounded once.  Exact signs keep the decisions of inside_interval
 * consistent (an edge is never judged inside another shadow while that
 * shadow's nearly coincident edge is judged inside the first), and
 * values accurate to 2^-40 put the crossings of two nearly parallel
 * edges, t = dp / (dp - dq), at one point from either side, so that the
 * union's boundary neither overlaps nor breaks there by more than 2^-40
 * of an edge. */
/* a - b = *s + *t exactly (Knuth's two-sum of a and -b) */
static inline void two_diff(double a, double b, double *s, double *t)
{
    *s = a - b;
    const double bv = *s - a;
    *t = (a - (*s - bv)) - (b + bv);
}

static __attribute__((noinline, cold)) int orient_exact(const double *a, const double *b,
                                                         const double *c, double *det)
{
    if ((c[0] == a[0] && c[1] == a[1]) || (c[0] == b[0] && c[1] == b[1])) {
        *det = 0; /* a shared vertex (a mesh's neighbours): exactly 0 */
        return 0;
    }
    double s1, t1, s2, t2, s3, t3, s4, t4;
    two_diff(b[0], a[0], &s1, &t1);
    two_diff(c[1], a[1], &s2, &t2);
    two_diff(b[1], a[1], &s3, &t3);
    two_diff(c[0], a[0], &s4, &t4);
    const double P = s1 * s2, p = fma(s1, s2, -P), Q = s3 * s4, q0 = fma(s3, s4, -Q);
    if (t1 == 0 && t2 == 0 && t3 == 0 && t4 == 0 && P == Q && p == q0) {
        *det = 0; /* exact differences, equal exact products: on the line */
        return 0;
    }
    const double d = (P - Q) + ((p - q0) + ((s1 * t2 + t1 * s2) - (s3 * t4 + t3 * s4)));
    if (fabs(d) > 0x1p41 * 4.0 * DBL_EPSILON * DBL_EPSILON * (fabs(P) + fabs(Q))) {
        *det = d;
        return d > 0 ? 1 : -1;
    }
    const __float128 q = ((__float128)b[0] - a[0]) * ((__float128)c[1] - a[1]) -
                         ((__float128)b[1] - a[1]) * ((__float128)c[0] - a[0]);
    *det = (double)q;
    return (q > 0) - (q < 0);
}

static inline int orient(const double *a, const double *b, const double *c, double *det)
{
    const double l = (b[0] - a[0]) * (c[1] - a[1]), r = (b[1] - a[1]) * (c[0] - a[0]);
    const double d = l - r, bound = (3.0 + 16.0 * DBL_EPSILON) * DBL_EPSILON * (fabs(l) + fabs(r));
    if (fabs(d) > 0x1p40 * bound) {
        *det = d; /* c is no vertex of a -> b: that would make d 0 */
        return d > 0 ? 1 : -1;
    }
    if ((c[0] == a[0] && c[1] == a[1]) || (c[0] == b[0] && c[1] == b[1])) {
        *det = 0; /* a shared vertex (a mesh's neighbours), the most common
                     case here: exactly 0 without the call (orient_exact's
                     first test too) */
        return 0;
    }
    return orient_exact(a, b, c, det);
}

/* The interval [*t0, *t1] of edge pu -> qu strictly inside the convex
 * polygon w (n vertices in the plane, counter-clockwise); on one of its
 * edges' lines, the edge counts as inside when `on` is set and the two run
 * the same way (the half-open rule of the header).  Returns 0 when empty. */
static int inside_interval(const double *w, int n, int on, const double *pu, const double *qu,
                           double *t0, double *t1)
{
    double lo = 0, hi = 1;
    for (int k = 0; k < n; k++) {
        const double *v0 = w + 2 * k, *v1 = w + 2 * (k + 1 < n ? k + 1 : 0);
        double dp, dq;
        const int sp = orient(v0, v1, pu, &dp), sq = orient(v0, v1, qu, &dq);
        if (sp == 0 && sq == 0) {
            const double dot = (v1[0] - v0[0]) * (qu[0] - pu[0]) + (v1[1] - v0[1]) * (qu[1] - pu[1]);
            if (!(dot > 0 && on))
                return 0;
            continue;
        }
        if (sp <= 0 && sq <= 0)
            return 0;
        if (sp >= 0 && sq >= 0)
            continue;
        double t = dp / (dp - dq);
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        if (sp < 0)
            lo = t > lo ? t : lo;
        else
            hi = t < hi ? t : hi;
        if (!(lo < hi))
            return 0;
    }
    *t0 = lo;
    *t1 = hi;
    return 1;
}

static int cmp_interval(const void *x, const void *y)
{
    const double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* Lists at most this long are sorted in place by insertion: most of an
 * evaluation's lists (a few shadows, a few intervals of an edge), where
 * qsort's set-up and copies cost more than the sort.  Insertion is stable,
 * as glibc's qsort is (a merge sort), so equal keys keep their order
 * either way and the union's segments come out in the same order. */
#define OCC_INSERTION_SORT 32

/* The n intervals (t0, t1) of iv in order of t0, stably. */
static void sort_intervals(double *iv, int n)
{
    if (n > OCC_INSERTION_SORT) {
        qsort(iv, (size_t)n, 2 * sizeof *iv, cmp_interval);
        return;
    }
    for (int i = 1; i < n; i++) {
        const double t0 = iv[2 * i], t1 = iv[2 * i + 1];
        int j = i;
        for (; j > 0 && iv[2 * j - 2] > t0; j--) {
            iv[2 * j] = iv[2 * j - 2];
            iv[2 * j + 1] = iv[2 * j - 1];
        }
        iv[2 * j] = t0;
        iv[2 * j + 1] = t1;
    }
}

typedef struct sweep_key {
    double ulo;
    int i;
} sweep_key;

static int cmp_sweep(const void *x, const void *y)
{
    const double a = ((const sweep_key *)x)->ulo, b = ((const sweep_key *)y)->ulo;
    return (a > b) - (a < b);
}

/* The n keys in order of ulo, stably (OCC_INSERTION_SORT). */
static void sort_sweep(sweep_key *key, int n)
{
    if (n > OCC_INSERTION_SORT) {
        qsort(key, (size_t)n, sizeof *key, cmp_sweep);
        return;
    }
    for (int i = 1; i < n; i++) {
        const sweep_key x = key[i];
        int j = i;
        for (; j > 0 && key[j - 1].ulo > x.ulo; j--)
            key[j] = key[j - 1];
        key[j] = x;
    }
}

/* For each shadow, the others whose boxes meet its box, into
 * sp->nbr[sp->nbr_off[a] .. sp->nbr_off[a + 1]): sweep and prune (the
 * boxes in order of their lowest u, each against those that start before
 * it ends), so that the edge tests cost O(K log K) plus the pairs that
 * overlap, not K^2.  Boxes are compared exactly, edges included: a
 * shadow left out of another's list cannot touch it.  Returns 0, -1. */
static int neighbours(occ_space *sp)
{
    const int k = sp->sh.np;
    if (k == 0)
        return 0;
    if (occ_grow_i(&sp->nbr_off, &sp->capnoff, k + 1))
        return -1;
    if (k > sp->capsweep) {
        sweep_key *q = occ_realloc(sp->sweep, &sp->capsweep, k, sizeof *q);
        if (!q)
            return -1;
        sp->sweep = q;
    }
    sweep_key *key = sp->sweep;
    for (int i = 0; i < k; i++) {
        key[i].ulo = sp->box[4 * i];
        key[i].i = i;
        sp->nbr_off[i + 1] = 0;
    }
    sort_sweep(key, k);
    for (int pass = 0; pass < 2; pass++) {
        for (int p = 0; p < k; p++) {
            const int i = key[p].i;
            const double *bi = sp->box + 4 * i;
            for (int q = p + 1; q < k && key[q].ulo <= bi[1]; q++) {
                const int j = key[q].i;
                if (!boxes_meet(bi, sp->box + 4 * j))
                    continue;
                if (pass == 0) {
                    sp->nbr_off[i + 1]++;
                    sp->nbr_off[j + 1]++;
                } else {
                    sp->nbr[sp->fill[i]++] = j;
                    sp->nbr[sp->fill[j]++] = i;
                }
            }
        }
        if (pass == 0) {
            sp->nbr_off[0] = 0;
            for (int i = 0; i < k; i++)
                sp->nbr_off[i + 1] += sp->nbr_off[i];
            if (occ_grow_i(&sp->nbr, &sp->capnbr, sp->nbr_off[k] + 1) ||
                occ_grow_i(&sp->fill, &sp->capfill, k))
                return -1;
            for (int i = 0; i < k; i++)
                sp->fill[i] = sp->nbr_off[i];
        }
    }
    return 0;
}

/* A hash of an unordered pair of points of the plane, a and b in
 * lexicographic order (-0 and +0 alike). */
static uint64_t edge_hash(const double *a, const double *b)
{
    const double w[4] = {a[0] + 0.0, a[1] + 0.0, b[0] + 0.0, b[1] + 0.0};
    uint64_t u[4];
    memcpy(u, w, sizeof u);
    /* four independent products (no chain), then the high bits folded down */
    const uint64_t h = u[0] * 0x9e3779b97f4a7c15u ^ u[1] * 0xff51afd7ed558ccdu ^
                       u[2] * 0xc4ceb9fe1a85ec53u ^ u[3] * 0xd6e8feb86659fd93u;
    return h ^ h >> 29 ^ h >> 47;
}

static inline int point_less(const double *a, const double *b)
{
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

static inline int point_same(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1];
}

/* The shadows' edges that are interior to their union, into
 * sp->inner[0 .. E) (E = sp->sh.nv, the edges numbered like their first
 * vertices): an edge that exactly one other shadow has too, run the other
 * way.  Both shadows run counter-clockwise, so one lies left of the edge
 * and the other right of it: every point of the edge but its ends is
 * inside the union, and the edge is no part of its boundary.  This is
 * what two triangles of one mesh that share an edge and are seen from the
 * same side make (their shared vertices project to the same numbers), and
 * it leaves to the edge tests only the outline of what a mesh hides: its
 * silhouette and free edges.  Their terms of eq. 6 were exact negatives
 * before; now neither is computed.  An edge found more than twice (faces
 * over each other, three faces on one edge) keeps the rule of the header.
 * Returns 0, -1. */
static int inner_edges(occ_space *sp)
{
    const int ne = sp->sh.nv;
    int size = 16;
    while (size < 2 * ne)
        size *= 2;
    /* inner: [0, E) the answer, [E, 2E) how often each edge's first copy
     * was found, [2E, 3E) its second copy, [3E, 4E) each edge's shadow */
    if (occ_grow_i(&sp->inner, &sp->capinner, 4 * ne))
        return -1;
    int *inner = sp->inner, *count = inner + ne, *mate = inner + 2 * ne, *owner = inner + 3 * ne;
    if (sp->sh.np < 2) { /* no other shadow to share an edge with */
        memset(inner, 0, sizeof *inner * (size_t)ne);
        return 0;
    }
    if (occ_grow_i(&sp->ehash, &sp->capehash, size))
        return -1;
    for (int i = 0; i < size; i++)
        sp->ehash[i] = -1;
    for (int a = 0; a < sp->sh.np; a++)
        for (int k = sp->sh.first[a]; k < sp->sh.first[a + 1]; k++)
            owner[k] = a;
    for (int e = 0; e < ne; e++) {
        const int a = owner[e], nx = e + 1 < sp->sh.first[a + 1] ? e + 1 : sp->sh.first[a];
        const double *p = sp->uv + 2 * e, *q = sp->uv + 2 * nx;
        inner[e] = 0;
        count[e] = 0;
        if (point_same(p, q))
            continue;
        const double *lo = point_less(p, q) ? p : q, *hi = lo == p ? q : p;
        uint64_t h = edge_hash(lo, hi);
        for (;; h++) {
            const int f = sp->ehash[h & (uint64_t)(size - 1)];
            if (f < 0) {
                sp->ehash[h & (uint64_t)(size - 1)] = e;
                count[e] = 1;
                break;
            }
            const int fa = owner[f], fn = f + 1 < sp->sh.first[fa + 1] ? f + 1 : sp->sh.first[fa];
            const double *fp = sp->uv + 2 * f, *fq = sp->uv + 2 * fn;
            if ((point_same(fp, p) && point_same(fq, q)) ||
                (point_same(fp, q) && point_same(fq, p))) {
                if (++count[f] == 2)
                    mate[f] = e;
                break;
            }
        }
    }
    for (int f = 0; f < ne; f++) {
        if (count[f] != 2 || owner[f] == owner[mate[f]])
            continue;
        const int fa = owner[f], fn = f + 1 < sp->sh.first[fa + 1] ? f + 1 : sp->sh.first[fa];
        if (point_same(sp->uv + 2 * fn, sp->uv + 2 * mate[f]))
            inner[f] = inner[mate[f]] = 1; /* run the other way */
    }
    return 0;
}

/* Add segment p + t0 (q - p) -> p + t1 (q - p) to sp->seg; 0, -1. */
static int add_seg(occ_space *sp, rad_vec3 p, rad_vec3 q, double t0, double t1)
{
    if (occ_grow_v3(&sp->seg, &sp->capseg, 2 * sp->nseg + 2))
        return -1;
    sp->seg[2 * sp->nseg] = t0 <= 0 ? p : v3_lerp(p, q, t0);
    sp->seg[2 * sp->nseg + 1] = t1 >= 1 ? q : v3_lerp(p, q, t1);
    sp->nseg++;
    return 0;
}

/* The parts of an edge p -> q (2-D pu -> qu; of shadow a, or of the inner
 * element when a < 0) that lie on the boundary of the hidden part, into
 * sp->seg: of a shadow's edge, what lies strictly inside the inner
 * element and inside no other shadow; of the inner element's edge, what
 * lies inside some shadow.  Returns 0, -1. */
static int edge_boundary(occ_space *sp, const pair_ctx *c, int a, rad_vec3 p, rad_vec3 q,
                         const double *pu, const double *qu)
{
    double in0 = 0, in1 = 1;
    const double ebox[4] = {pu[0] < qu[0] ? pu[0] : qu[0], pu[0] < qu[0] ? qu[0] : pu[0],
                            pu[1] < qu[1] ? pu[1] : qu[1], pu[1] < qu[1] ? qu[1] : pu[1]};
    /* a shadow's edge whose box misses the inner element's is outside it */
    if (a >= 0 && (!boxes_meet(ebox, c->tbox) ||
                   !inside_interval(sp->tuv, c->nt, 0, pu, qu, &in0, &in1)))
        return 0;
    int ni = 0;
    /* a shadow's edge meets only its neighbours; the element's, any */
    const int n0 = a >= 0 ? sp->nbr_off[a] : 0, n1 = a >= 0 ? sp->nbr_off[a + 1] : sp->sh.np;
    for (int l = n0; l < n1; l++) {
        const int b = a >= 0 ? sp->nbr[l] : l;
        if (!boxes_meet(ebox, sp->box + 4 * b))
            continue;
        double t0, t1;
        const int f = sp->sh.first[b];
        if (!inside_interval(sp->uv + 2 * f, sp->sh.first[b + 1] - f, a < 0 || b < a, pu, qu,
                             &t0, &t1))
            continue;
        if (a >= 0 && t0 <= in0 && t1 >= in1)
            return 0; /* all of it covered */
        if (occ_grow_d(&sp->iv, &sp->capiv, 2 * ni + 2))
            return -1;
        sp->iv[2 * ni] = t0;
        sp->iv[2 * ni + 1] = t1;
        ni++;
    }
    if (ni > 1)
        sort_intervals(sp->iv, ni);
    /* walk the covered intervals in order: a shadow's edge keeps the gaps
     * between them within [in0, in1], the inner element's the intervals */
    double t = in0;
    for (int k = 0; k < ni && t < in1; k++) {
        const double s0 = sp->iv[2 * k] > t ? sp->iv[2 * k] : t;
        const double s1 = sp->iv[2 * k + 1] < in1 ? sp->iv[2 * k + 1] : in1;
        if (a >= 0 && s0 > t && add_seg(sp, p, q, t, s0 < in1 ? s0 : in1))
            return -1;
        if (a < 0 && s1 > s0 && add_seg(sp, p, q, s0, s1))
            return -1;
        if (s1 > t)
            t = s1;
    }
    if (a >= 0 && t < in1 && add_seg(sp, p, q, t, in1))
        return -1;
    return 0;
}

/* Eq. 6 over the segments of sp->seg (-2 pi times the factor), with the
 * sum of its terms' magnitudes in *size; and in long double. */
static double seg_sum(const occ_space *sp, rad_vec3 x, rad_vec3 nrm, double *size)
{
    double sum = 0;
    for (int k = 0; k < sp->nseg; k++) {
        const rad_vec3 r0 = v3_sub(sp->seg[2 * k], x), r1 = v3_sub(sp->seg[2 * k + 1], x);
        const rad_vec3 cr = v3_cross(r0, r1);
        const double cn = v3_norm(cr);
        if (cn > 0) {
            const double t = atan2(cn, v3_dot(r0, r1)) * v3_dot(nrm, cr) / cn;
            sum += t;
            *size += fabs(t);
        }
    }
    return sum;
}

static long double seg_sum_long(const occ_space *sp, rad_vec3 x, rad_vec3 nrm)
{
    long double sum = 0;
    for (int k = 0; k < sp->nseg; k++)
        sum += occ_edge_term_long(sp->seg[2 * k], sp->seg[2 * k + 1], x, nrm);
    return sum;
}

/* The union's area, from its boundary: half the sum of tn . (a x b) over
 * its segments, taken about the inner element's first vertex, turned by
 * c->usense. */
static double seg_area(const occ_space *sp, const pair_ctx *c)
{
    double s = 0;
    for (int k = 0; k < sp->nseg; k++)
        s += v3_dot(c->tn, v3_cross(v3_sub(sp->seg[2 * k], c->t[0]),
                                    v3_sub(sp->seg[2 * k + 1], c->t[0])));
    return 0.5 * s * c->usense;
}

/* What occ_hidden_union takes of the inner element at every point, set
 * once for the pair c: the plane's axes (the first edge's direction, and
 * up x it, so that the shadows, turned about up = sense tn, run
 * counter-clockwise in (u, v)), the element's vertices in them (sp->tuv)
 * and their box, its turn, mean and area, and its vertices widened
 * OCC_UNION_WIDEN times about their mean (sp->tw: the pyramid's edges).
 * 0, or -1 when memory ran out. */
int occ_union_frame(occ_space *sp, pair_ctx *c)
{
    c->uframe = 0;
    if (!c->flat)
        return 0;
    if (occ_grow_d(&sp->tuv, &sp->captuv, 2 * c->nt) || occ_grow_v3(&sp->tw, &sp->captw, c->nt))
        return -1;
    c->tmean = poly_mean(c->t, c->nt);
    for (int k = 0; k < c->nt; k++)
        sp->tw[k] = v3_add(c->tmean, v3_scale(v3_sub(c->t[k], c->tmean), OCC_UNION_WIDEN));
    c->tarea = poly_area(c->t, c->nt);
    c->usense = v3_dot(v3_newell(c->t, c->nt), c->tn) < 0 ? -1.0 : 1.0;
    rad_vec3 *e = c->ue;
    e[0] = v3_sub(c->t[1], c->t[0]);
    const double len = v3_norm(e[0]);
    if (!(len > 0))
        return 0;
    e[0] = v3_scale(e[0], 1.0 / len);
    e[1] = v3_cross(v3_scale(c->tn, c->usense), e[0]);
    double *tbox = c->tbox;
    tbox[0] = tbox[2] = HUGE_VAL;
    tbox[1] = tbox[3] = -HUGE_VAL;
    for (int k = 0; k < c->nt; k++) {
        const rad_vec3 d = v3_sub(c->t[k], c->t[0]);
        const double u = v3_dot(d, e[0]), v = v3_dot(d, e[1]);
        sp->tuv[2 * k] = u;
        sp->tuv[2 * k + 1] = v;
        tbox[0] = u < tbox[0] ? u : tbox[0];
        tbox[1] = u > tbox[1] ? u : tbox[1];
        tbox[2] = v < tbox[2] ? v : tbox[2];
        tbox[3] = v > tbox[3] ? v : tbox[3];
    }
    c->uframe = 1;
    return 0;
}

int occ_hidden_union(occ_space *sp, const pair_ctx *c, rad_vec3 x, double *out)
{
    const double h = v3_dot(c->tn, v3_sub(c->t[0], x));
    if (!c->uframe || !(fabs(h) > c->snap))
        return 0;
    int r = pyramid(sp, c, x);
    if (r <= 0)
        return r;
    if ((r = shadows(sp, c, x, h)) <= 0)
        return r;
    sp->nseg = 0;
    if (neighbours(sp) || inner_edges(sp))
        return -1;
    for (int a = 0; a < sp->sh.np; a++) {
        const int f = sp->sh.first[a], n = sp->sh.first[a + 1] - f;
        for (int k = 0; k < n; k++) {
            const int k0 = f + k, k1 = f + (k + 1) % n;
            if (sp->inner[k0])
                continue;
            if (edge_boundary(sp, c, a, sp->sh.v[k0], sp->sh.v[k1], sp->uv + 2 * k0,
                              sp->uv + 2 * k1))
                return -1;
        }
    }
    for (int k = 0; k < c->nt && sp->sh.np > 0; k++) {
        const int k1 = (k + 1) % c->nt;
        if (edge_boundary(sp, c, -1, c->t[k], c->t[k1], sp->tuv + 2 * k, sp->tuv + 2 * k1))
            return -1;
    }
    sp->evals++;
    double size = 0, sum = seg_sum(sp, x, c->nx, &size);
    if (OCC_NOISE_EPS * DBL_EPSILON * size > 2 * RAD_PI * sp->noise_tol)
        sum = (double)(seg_sum_long(sp, x, c->nx) / (2 * RAD_PI_LONG)) * (2 * RAD_PI);
    const double au = seg_area(sp, c);
    if (au > c->sliver)
        sp->any_hidden = 1;
    if (c->tarea - au > c->sliver)
        sp->any_visible = 1;
    *out = fabs(sum) / (2 * RAD_PI);
    return 1;
}
