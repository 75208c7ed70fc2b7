/* occeee.c -- the events of three edges: where, seen from a point x of
 * the outer element, the corner where the shadows of two blockers' edges
 * cross passes an edge of the inner element.  occdomain.c cuts the domain
 * along these curves too (by chords).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * An edge e1 of blocker a, an edge e2 of blocker b and an edge e3 of the
 * inner element lie on lines L_k = a_k + s u_k.  From x, the shadows of
 * e1 and e2 on the inner plane cross at the point where the one line
 * through x that meets L1 and L2 (their transversal) meets that plane; the
 * union of the two shadows, and so hidden(x), changes its corner
 * structure where that point crosses e3: where the transversal also meets
 * L3 (an EEE event: Gigus, Canny & Seidel, IEEE PAMI 13, 1991; Heckbert
 * 1992 lists them among the discontinuities of the illumination, of
 * second order like the edge-vertex events).  The lines that meet three
 * skew lines sweep a ruled quadric (a regulus), so on the outer plane the
 * event is a conic, not a line: no plane cuts it.
 *
 * With n_k = (a_k - x) x u_k the normal of the plane through x and L_k,
 * the transversal's direction is d = n1 x n2, and it meets L3 when
 *     g(x) = [a3 - x, d, u3] = 0                                        (1)
 * ([p, q, r] the triple product).  By (A x B) x (C x D) = [A, B, D] C -
 * [A, B, C] D,
 *     d = [a1 - x, u1, u2] (a2 - x) - [a1 - x, u1, a2 - x] u2,
 * and the terms [a1 - x, u1, a2 - x], [a3 - x, a2 - x, u3] are linear in
 * x (the x-x term vanishes), so g is a product of linear forms less
 * another: a quadratic.  Along an edge of a piece it is a quadratic in
 * the edge's parameter, found exactly from three values; its roots are
 * where the conic crosses the piece's boundary.
 *
 * A piece that the conic crosses is cut along the chord between the first
 * two crossings (the plane through the chord at right angles to the outer
 * element).  The kink is then left in the thin lens between chord and
 * arc: the arc's sagitta is L^2 k / 8 for a chord of length L on a conic
 * of curvature k, and a second-order kink inside a strip of width w costs
 * a rule of order p an error of order w^3 instead of the slow convergence
 * of a kink across the middle of a piece (on the Cornell box, pairs whose
 * three rules of occhidden.c (2) agreed to 1e-14 were 2e-5 off).
 *
 * Only events that happen are cut: somewhere along the arc the transversal
 * must meet the segments themselves (within a tenth of their length: when
 * in doubt, cut) and the two blocker edges must lie between x and the
 * inner edge (happens).  Edges that share an end meet
 * there, and their event is the plane through that vertex and e3,
 * which occdomain.c's vertex-edge cuts already follow; two edges in one
 * plane make the quadric a pair of planes (coplanar_lines).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "occ/occspace.h"
#include "util/util.h"

/* One line of an event: a point and a direction, in the event's own
 * units: x in the pair's frame is x * inv there (inv a power of two, the
 * same for the three lines, so the scaling is exact), so that g and its
 * tolerances do not depend on the scene's scale (g is a product of six
 * lengths: at a scale of 1e-100 it underflowed, and the cuts moved). */
typedef struct line3 {
    rad_vec3 a, u;
    double inv;
} line3;

static rad_vec3 to_event(const line3 *l, rad_vec3 x)
{
    return v3_scale(x, l->inv);
}

static double triple(rad_vec3 p, rad_vec3 q, rad_vec3 r)
{
    return v3_dot(p, v3_cross(q, r));
}

/* The transversal's direction d(x) of (1). */
static rad_vec3 transversal(const line3 *l, rad_vec3 x)
{
    rad_vec3 w1 = v3_sub(l[0].a, x), w2 = v3_sub(l[1].a, x);
    return v3_sub(v3_scale(w2, triple(w1, l[0].u, l[1].u)),
                  v3_scale(l[1].u, triple(w1, l[0].u, w2)));
}

/* g(x) of (1), x in the pair's frame. */
static double g_at(const line3 *l, rad_vec3 x)
{
    x = to_event(l, x);
    return triple(v3_sub(l[2].a, x), transversal(l, x), l[2].u);
}

/* Where the line x + lambda d comes nearest line q: *lambda and the
 * parameter *mu on q (0 and 1 at its segment's ends).  0 when parallel. */
static int meet(rad_vec3 x, rad_vec3 d, const line3 *q, double *lambda, double *mu)
{
    rad_vec3 w0 = v3_sub(x, q->a);
    double A = v3_dot(d, d), B = v3_dot(d, q->u), C = v3_dot(q->u, q->u);
    double D = v3_dot(d, w0), E = v3_dot(q->u, w0), den = A * C - B * B;
    if (!(den > 1e-24 * A * C))
        return 0;
    *lambda = (B * E - C * D) / den;
    *mu = (A * E - B * D) / den;
    return 1;
}

/* Might the event of l happen on the arc from x0 to x1 (two points of
 * the conic)?  At x0, the chord's midpoint and x1 the transversal meets
 * line k at parameter mu_k (0 and 1 at the segment's ends) and at
 * lambda_k along the line from x; the event happens where every mu_k lies
 * in [0, 1] and the blocker edges lie between x and the inner edge
 * (0 < lambda_k / lambda_3 < 1, k = 1, 2).  These move continuously along
 * the arc, so a range of a quantity over the three points that misses
 * its interval by more than a tenth (when in doubt, cut) says the event
 * does not happen there; an arc whose ends are on either side of a
 * segment is cut. */
static int happens(const line3 *l, rad_vec3 x0, rad_vec3 x1)
{
    const double slack = 0.1;
    double mlo[3], mhi[3], rlo[2], rhi[2];
    for (int k = 0; k < 3; k++) {
        mlo[k] = HUGE_VAL;
        mhi[k] = -HUGE_VAL;
    }
    rlo[0] = rlo[1] = HUGE_VAL;
    rhi[0] = rhi[1] = -HUGE_VAL;
    for (int p = 0; p < 3; p++) {
        rad_vec3 x = to_event(l, p == 0 ? x0 : p == 1 ? v3_lerp(x0, x1, 0.5) : x1);
        rad_vec3 d = transversal(l, x);
        double lam[3], mu;
        if (!(v3_norm(d) > 0))
            return 1;
        for (int k = 0; k < 3; k++) {
            if (!meet(x, d, &l[k], &lam[k], &mu))
                return 1;
            mlo[k] = fmin(mlo[k], mu);
            mhi[k] = fmax(mhi[k], mu);
        }
        if (!(lam[2] != 0))
            return 1;
        for (int k = 0; k < 2; k++) {
            rlo[k] = fmin(rlo[k], lam[k] / lam[2]);
            rhi[k] = fmax(rhi[k], lam[k] / lam[2]);
        }
    }
    for (int k = 0; k < 3; k++)
        if (mhi[k] < -slack || mlo[k] > 1 + slack)
            return 0;
    for (int k = 0; k < 2; k++)
        if (rhi[k] <= 0 || rlo[k] >= 1 + slack)
            return 0;
    return 1;
}

/* The real roots of a t^2 + b t + c = 0 into r (0, 1 or 2 of them; the
 * linear equation when a is negligible), by the stable form q = -(b +
 * sign(b) sqrt(b^2 - 4 a c)) / 2, t = q / a and c / q. */
static int quad_roots(double a, double b, double c, double r[2])
{
    int nr = 0;
    if (fabs(a) <= 1e-12 * (fabs(b) + fabs(c))) {
        if (b != 0)
            r[nr++] = -c / b;
    } else {
        double disc = b * b - 4 * a * c;
        if (disc >= 0) {
            double q = -0.5 * (b + copysign(sqrt(disc), b));
            r[nr++] = q / a;
            if (q != 0)
                r[nr++] = c / q;
        }
    }
    return nr;
}

/* The crossings of the conic g = 0 with the boundary of convex piece p
 * (n vertices), at most 4, into x[]; returns their count.  On each edge
 * g(s) = g0 (1 - s)(1 - 2 s) + 4 gm s (1 - s) + g1 s (2 s - 1) (the
 * quadratic through s = 0, 1/2, 1).  `tiny` is g's round-off scale: an
 * edge where the three values are below it lies on the conic and gives no
 * crossing.  A conic through a vertex has its root there on both edges,
 * each a little inside or outside its edge by round-off: roots are taken
 * within ROOT_SLACK of [0, 1] and clamped, a root at a vertex counts only
 * where the conic crosses there (crosses_at), and a crossing within tol
 * of the one before it (or of the first) is the same one.  (Taking [0, 1)
 * lost such a crossing when both roots fell outside: the conic of a
 * Cornell box pair runs through the corner where the plane of a blocker
 * vertex and the inner edge meets the plane of that vertex and the other
 * blocker's edge, a vertex of the pieces, and a piece it crossed there
 * was left uncut, 4e-5 of the pair's value off with an estimate of
 * 1e-15.) */
#define ROOT_SLACK 1e-9

/* Does the conic cross the boundary of p at vertex v (rather than touch
 * it from outside, where a conic through the corner of two event planes
 * enters two of the four pieces and touches the other two)?  g on either
 * side of v, a millionth along each edge: of opposite signs, or either
 * within round-off (when in doubt, a crossing). */
static int crosses_at(const line3 *l, const rad_vec3 *p, int n, int v, double tiny)
{
    const rad_vec3 a = v3_lerp(p[v], p[(v + n - 1) % n], 1e-6);
    const rad_vec3 b = v3_lerp(p[v], p[(v + 1) % n], 1e-6);
    const double ga = g_at(l, a), gb = g_at(l, b);
    return fabs(ga) <= tiny || fabs(gb) <= tiny || (ga > 0) != (gb > 0);
}

static int crossings(const line3 *l, const rad_vec3 *p, int n, double tiny, double tol,
                     rad_vec3 *x)
{
    int nx = 0;
    double g0 = g_at(l, p[0]), gfirst = g0;
    for (int k = 0; k < n && nx < 4; k++) {
        rad_vec3 p0 = p[k], p1 = p[k + 1 < n ? k + 1 : 0];
        double g1 = k + 1 < n ? g_at(l, p1) : gfirst;
        double gm = g_at(l, v3_lerp(p0, p1, 0.5));
        double a = 2 * g0 - 4 * gm + 2 * g1, b = -3 * g0 + 4 * gm - g1, c0 = g0;
        double g_prev = g0;
        g0 = g1;
        if (fabs(g_prev) <= tiny && fabs(gm) <= tiny && fabs(g1) <= tiny)
            continue;
        double r[2];
        const int nr = quad_roots(a, b, c0, r);
        if (nr == 2 && r[1] < r[0]) {
            double t = r[0];
            r[0] = r[1];
            r[1] = t;
        }
        for (int m = 0; m < nr && nx < 4; m++) {
            if (!(r[m] >= -ROOT_SLACK && r[m] <= 1 + ROOT_SLACK))
                continue;
            if ((r[m] <= ROOT_SLACK && !crosses_at(l, p, n, k, tiny)) ||
                (r[m] >= 1 - ROOT_SLACK && !crosses_at(l, p, n, (k + 1) % n, tiny)))
                continue; /* it touches the piece at a vertex */
            rad_vec3 q = v3_lerp(p0, p1, fmin(fmax(r[m], 0), 1));
            if (nx > 0 && (v3_norm(v3_sub(q, x[nx - 1])) <= tol ||
                           v3_norm(v3_sub(q, x[0])) <= tol))
                continue;
            x[nx++] = q;
        }
    }
    return nx;
}

/* Cut piece p (n vertices) along the chord x0 x1 into sp->db (both
 * sides; only sides without area are dropped: c->sliver is a fraction of
 * the inner element, and on the Cornell box pieces of the outer element
 * below it carried all of a hidden pair's hidden part); 0 or -1. */
static int cut_chord(occ_space *sp, const pair_ctx *c, const rad_vec3 *p, int n, rad_vec3 x0,
                     rad_vec3 x1)
{
    rad_vec3 nrm = v3_cross(v3_sub(x1, x0), c->nx);
    double len = v3_norm(nrm), lo, hi;
    if (occ_grow_d(&sp->d, &sp->capd, n) || occ_grow_v3(&sp->tmp, &sp->captmp, n + 1))
        return -1;
    if (len > 0) {
        poly_distances(p, n, v3_scale(nrm, 1.0 / len), x0, c->snap, sp->d, &lo, &hi);
        poly_settle_signs(sp->d, n, &lo, &hi);
    }
    if (!(len > 0) || lo >= 0 || hi <= 0)
        return occ_ps_push(&sp->db, p, n);
    for (int side = -1; side <= 1; side += 2) {
        int m = poly_clip_side(p, sp->d, n, side, sp->tmp, n + 1);
        if (m >= 3 && poly_area(sp->tmp, m) > 0 && occ_ps_push(&sp->db, sp->tmp, m))
            return -1;
    }
    return 0;
}

/* A chord leaves the arc's kink in a lens as wide as the arc's sagitta;
 * where that is more than c->arc_tol of the chord (OCC_ARC_TOL_*,
 * occspace.h), the piece is first cut into m strips across the chord,
 * with m^2 >= sagitta / (arc_tol chord) (at most ARC_STRIPS at a time).
 * A strip's chord is m times shorter and, the curvature being about the
 * same, its sagitta m^2 times smaller: its lens, a part of its chord, is
 * m times narrower, not m^2, so a strip may still be too bent, and is
 * measured again below.  (m as large as the ratio itself would cut fewer
 * times, but into more and thinner strips at once: on the closed Cornell
 * box at --mesh 2x2 the pieces of a pair of large elements then took
 * default mode's whole budget, and F came out 9e-6 off with an estimate
 * of 5e-2.)  A second-order kink in a lens of width w moves the integral
 * by about w^3 times the second derivative's jump: the error falls as
 * the cube of the sagitta.  Seen on the Cornell box (a floor element
 * whose visible part of a ceiling element vanishes along a conic with a
 * sagitta of 0.2 mm on a 4 mm chord): F changed by 4e-8 with the mesh
 * after a plain chord, 2e-9 with a tolerance of 1e-3, 2e-10 with 5e-4
 * and 3e-12 with 1e-4; default mode was within 2e-7 of it with 1e-2.
 * (These and the figures below were measured before strips were measured
 * again, when a strip's lens could be up to m times the tolerance.)
 *
 * The curvature is not the same all along an arc near the vertex of a
 * hyperbola: each strip's chord is measured again, and a strip still too
 * bent is cut into strips of its own, up to ARC_PIECES strips for each
 * piece of the domain that the arc crosses.
 * (Seen: a wall-to-wall pair of the 6x6 Cornell box, hidden to 7e-3
 * behind both blocks; an arc of 81 mm whose sagitta was 2e-2 of its
 * chord was cut into 7 strips, and the strip at its bent end kept a
 * sagitta of 6e-3 of its 11.7 mm chord.  The visible part of the inner
 * element lived in that lens alone, a sliver no rule point of the cell
 * saw: reference mode was 9.6e-9 off, its estimate 5e-10.)
 * ARC_PIECES was 64: on the closed 6x6 box, front-wall element 309 and
 * floor element 572, visible to 1.4e-2 past the tall block, spent them
 * before the bent end of an arc, whose last strips kept lenses of up to
 * 8e-2 of their chords; the lenses' estimate (eq. 2) was 4.5e-8 of the
 * occluded value after the second try.  With 256, no partly hidden
 * entry of that box above 1e-6 has an estimate above the promise, and
 * reference mode's fill took the same time (1.01 times).
 *
 * The rules converge on either side of a kink they cannot see, so the
 * lens's error escapes their estimates (lens_error, below, adds its
 * own), and it weighs most against the small value of a nearly hidden
 * pair.  Two pairs of the 6x6 Cornell box
 * (tests/accuracy/occeee.sh): one hidden to 1.3e-4, 1.9e-6 off with 1e-2 (the
 * same at every mesh, its estimate 0.08 of that), 3e-8 with 4e-3, 5e-10
 * with 2e-3; one hidden to 6e-4, 2.7e-7 off with 2e-3 (a lens of 1.5e-3
 * of its chord; estimate 0.2 of the error), 1e-16 with 5e-4.  Each strip
 * adds pieces to integrate, and a narrow tolerance for every pair spent
 * the budget of some pairs of large elements on the pieces alone (with
 * 2e-3, rows of the closed Cornell box at --mesh 3x3 summed to 1 only
 * within 7e-6): so the lenses are narrowed in a second try, only for
 * pairs whose value needs it (occhidden.c, narrower_arcs: by the pair's
 * visible fraction, or where the lenses' estimate takes more than its
 * share of the target) and where sp->arc_left, the widest lens a chord
 * left (a part of its chord), says that would cut more. */
#define ARC_STRIPS 16
#define ARC_PIECES 256

/* The sagitta of the arc of l's conic over chord x0 x1: along the chord's
 * perpendicular bisector (in the outer plane) g is a quadratic too, and
 * the root nearest the chord is the arc's middle, into *xa, with the
 * bisector's unit direction into *w.  0 when there is none (then *xa is
 * the chord's middle and *w not of unit length). */
static double sagitta(const line3 *l, const pair_ctx *c, rad_vec3 x0, rad_vec3 x1, rad_vec3 *xa,
                      rad_vec3 *w)
{
    rad_vec3 u = v3_sub(x1, x0), b = v3_cross(c->nx, u);
    double len = v3_norm(b), h = 0.5 * v3_norm(u);
    const rad_vec3 mid = v3_lerp(x0, x1, 0.5);
    *xa = mid;
    *w = b;
    if (!(len > 0) || !(h > 0))
        return 0;
    b = v3_scale(b, h / len);
    double gm = g_at(l, v3_sub(mid, b)), g0 = g_at(l, mid), gp = g_at(l, v3_add(mid, b));
    double r[2], best = HUGE_VAL;
    const int nr = quad_roots(0.5 * (gp + gm) - g0, 0.5 * (gp - gm), g0, r);
    for (int k = 0; k < nr; k++)
        if (fabs(r[k]) < fabs(best))
            best = r[k];
    if (!isfinite(best))
        return 0;
    *xa = v3_add(mid, v3_scale(b, best));
    *w = v3_scale(b, 1.0 / h);
    return fabs(best) * h;
}

/* How far the line x + t w (w a unit vector in the outer plane) runs
 * inside convex piece p (n vertices) either side of x: *lo <= 0 <= *hi,
 * both 0 when x is outside. */
static void extent(const pair_ctx *c, const rad_vec3 *p, int n, rad_vec3 x, rad_vec3 w,
                   double *lo, double *hi)
{
    const double turn = v3_dot(c->nx, v3_newell(p, n)); /* p's sense about the outer normal */
    *lo = -HUGE_VAL;
    *hi = HUGE_VAL;
    for (int k = 0; k < n; k++) {
        const rad_vec3 in = v3_scale(v3_cross(c->nx, v3_sub(p[(k + 1) % n], p[k])),
                                     turn >= 0 ? 1 : -1); /* toward p's inside */
        const double a = v3_dot(in, v3_sub(x, p[k])), b = v3_dot(in, w);
        if (b > 0)
            *lo = fmax(*lo, -a / b);
        else if (b < 0)
            *hi = fmin(*hi, -a / b);
        else if (a < 0)
            *lo = *hi = 0;
    }
    if (!(*lo <= 0 && *hi >= 0) || !isfinite(*lo) || !isfinite(*hi))
        *lo = *hi = 0;
}

/* The error a chord leaves in its lens, added to sp->arc_err.  Across the
 * arc, hidden(x) has a jump J in its second derivative (the kink of a
 * second-order event, top of the file); a rule whose points miss the
 * lens integrates there the other side's smooth continuation, and misses
 *     integral over the lens of J d^2 / 2
 * (d the distance from the arc).  With the lens's width w(s) = sag (1 -
 * (2 s / len)^2) along the chord (a parabola, |s| <= len / 2), that is
 *     J / 6 * integral of w(s)^3 ds = (8 / 105) J sag^3 len.           (2)
 * J is measured where the lens is widest: hidden(x) at the arc's middle
 * xa and at two points on either side along the bisector w, spaced by
 * 0.45 of the piece's room on that side ([lo, hi], extent above), gives
 * one-sided second differences whose difference stands for J.  Each
 * value is exact to a few ulps, or where the point-to-polygon sums cancel
 * to sp->noise_tol, the largest the pair's target allows (occpoint.c;
 * over a lens far narrower than the piece that is far below its share
 * of the target), so a difference is less its round-off, 8 eps times the
 * sum of the magnitudes.  A side with no room
 * (the arc along the piece's edge: steps of 1e-17 there met the snapping
 * of the clips, and second differences of 1e14) gives none, and the
 * other side's curvature stands for the jump; the chord's side always
 * has room, at least the sagitta.  The points lie in the piece, but
 * the piece may still hold the arc of an event cut later, or near an
 * earlier one, and the differences at h and 2 h carry the third
 * derivative too: both move J from its value at the lens (up, in the
 * measurements below, more often than down).  The evaluations count,
 * and they leave the pair's
 * any_hidden / any_visible alone.
 *
 * Lenses without an estimate: a chord with no arc found across it (no
 * sagitta), one whose arc bends more than its length (sag > len: no
 * lens, an arc that doubles back, left to the rules' estimates as
 * before), and one whose arc's middle falls outside its piece (no
 * room on either side).  Counted on the closed Cornell box at --mesh
 * 3x3 in default mode (about 125,000 chords): 59,400 arcs were straight
 * (a root at the chord's middle, or a double root there; no lens), and
 * of the 16,700 arcs whose middle fell outside the piece, the 23 printed
 * ran along an edge of the piece, bulging out of it: their lens lies in the
 * neighbouring piece, which the conic crosses at the same two points and
 * which is estimated there.  Left: about 150 chords with no arc across
 * them that is not straight, 190 arcs that bend more than their chords
 * (the strips spent), some 330 pieces the conic crosses three times
 * (the first two crossings are cut), and the second arcs of pieces it
 * crosses four times that the first arc's cuts split (6 of 222;
 * follow_two_arcs, below).  Taking the whole piece across the chord's
 * middle for the lens of those gave estimates up to 1e-5 of F on pairs
 * where default and reference agree to 1e-16: far from a bound, so they
 * are left to the rules as before.
 *
 * Measured against what narrowing the lenses changed (reference mode's
 * second try, occhidden.c, on the open 6x6 Cornell box: the 106 pairs
 * whose value moved by more than 1e-11 of the larger of itself and 1e-4
 * of its unoccluded value), (2) of the first try was 0.66 to 70 times
 * the change, its median 1.03, its 5th percentile 0.94: it is doubled
 * (LENS_SAFETY) to bound it.  0 or -1. */
#define LENS_SAFETY 2.0

static int lens_error(occ_space *sp, const pair_ctx *c, rad_vec3 xa, rad_vec3 w, double lo,
                      double hi, double sag, double len)
{
    const int hidden = sp->any_hidden, visible = sp->any_visible;
    double f0, dd[2] = {0, 0};
    if (!(hi > lo))
        return 0; /* xa outside the piece */
    if (occ_hidden_at(sp, c, xa, &f0))
        return -1;
    for (int side = 0; side < 2; side++) {
        const double h = 0.45 * (side ? hi : lo);
        double f1, f2;
        if (!(fabs(h) > 1e-3 * sag && fabs(h) > 64 * c->snap))
            continue; /* the arc runs along the piece's edge: no room */
        if (occ_hidden_at(sp, c, v3_add(xa, v3_scale(w, h)), &f1) ||
            occ_hidden_at(sp, c, v3_add(xa, v3_scale(w, 2 * h)), &f2))
            return -1;
        /* less the second difference's round-off, 8 eps (|f0| + 2 |f1| + |f2|) */
        const double noise = 8 * DBL_EPSILON * (fabs(f0) + 2 * fabs(f1) + fabs(f2));
        const double d2 = f0 - 2 * f1 + f2;
        dd[side] = fabs(d2) > noise ? copysign(fabs(d2) - noise, d2) / (h * h) : 0;
    }
    sp->any_hidden = hidden;
    sp->any_visible = visible;
    sp->arc_err += LENS_SAFETY * 8.0 / 105.0 * fabs(dd[1] - dd[0]) * sag * sag * sag * len;
    return 0;
}

/* The piece in sp->rem (n vertices), which the conic crosses at x0 and
 * x1, cut into m strips across the chord x0 x1, appended to sp->arc;
 * 0 or -1. */
static int cut_strips(occ_space *sp, const pair_ctx *c, int n, rad_vec3 x0, rad_vec3 x1, int m)
{
    const rad_vec3 u = v3_sub(x1, x0);
    const double len = v3_norm(u);
    const int cap = n + 2 * m + 4;
    double lo, hi;
    if (occ_grow_v3(&sp->pj0, &sp->cappj0, cap) || occ_grow_v3(&sp->pj1, &sp->cappj1, cap) ||
        occ_grow_v3(&sp->rem, &sp->caprem, cap) || occ_grow_d(&sp->d, &sp->capd, cap))
        return -1;
    memcpy(sp->pj0, sp->rem, sizeof *sp->rem * (size_t)n); /* what is left of the piece */
    int nr = n;
    for (int k = 1; k <= m && nr >= 3; k++) {
        int ns = nr;
        hi = 0; /* the last strip is all that is left */
        if (k < m) { /* strip k: the side of the plane across the chord toward x0 */
            poly_distances(sp->pj0, nr, v3_scale(u, 1.0 / len),
                           v3_add(x0, v3_scale(u, (double)k / m)), c->snap, sp->d, &lo, &hi);
            poly_settle_signs(sp->d, nr, &lo, &hi);
            if (lo >= 0)
                continue;
        }
        if (hi > 0) {
            ns = poly_clip_side(sp->pj0, sp->d, nr, -1.0, sp->pj1, cap);
            nr = poly_clip_side(sp->pj0, sp->d, nr, 1.0, sp->rem, cap);
            occ_swap_v3(&sp->pj0, &sp->cappj0, &sp->rem, &sp->caprem);
        } else { /* all of it on x0's side */
            occ_swap_v3(&sp->pj0, &sp->cappj0, &sp->pj1, &sp->cappj1);
            nr = 0;
        }
        if (ns >= 3 && poly_area(sp->pj1, ns) > 0 && occ_ps_push(&sp->arc, sp->pj1, ns))
            return -1;
    }
    return 0;
}

/* Piece p (n vertices), which the conic crosses at x0 and x1, cut along
 * the chord, or first into strips across it (above), each strip again
 * until its chord is straight enough, and each along its own chord; the
 * pieces go to sp->db.  The strips are taken in the order they are made
 * (breadth first), so that a spent budget (ARC_PIECES strips for the
 * piece) leaves the last level's chords, not one end of the arc uncut;
 * the last cut takes only as many strips as the budget has left.  0 or
 * -1. */
static int follow_arc(occ_space *sp, const pair_ctx *c, const line3 *l, double tiny,
                      const rad_vec3 *p, int n, rad_vec3 x0, rad_vec3 x1)
{
    occ_ps_clear(&sp->arc);
    if (occ_ps_push(&sp->arc, p, n))
        return -1;
    int pieces = 1;
    for (int k = 0; k < sp->arc.np; k++) {
        n = occ_load_rem(sp, &sp->arc, k);
        if (n < 0)
            return -1;
        if (k > 0) {
            rad_vec3 xs[4];
            if (crossings(l, sp->rem, n, tiny, c->snap, xs) < 2) {
                if (occ_ps_push(&sp->db, sp->rem, n))
                    return -1;
                continue;
            }
            x0 = xs[0];
            x1 = xs[1];
        }
        rad_vec3 xa, w;
        const double len = v3_norm(v3_sub(x1, x0)), sag = sagitta(l, c, x0, x1, &xa, &w);
        const double tol = c->arc_tol;
        int m = len > 0 && sag > tol * len && sag <= len ? (int)ceil(sqrt(sag / (tol * len))) : 1;
        m = m > ARC_STRIPS ? ARC_STRIPS : m;
        m = m > ARC_PIECES - pieces + 1 ? ARC_PIECES - pieces + 1 : m; /* what is left */
        if (m <= 1) {
            const int lens = len > 0 && sag > 0 && sag <= len;
            double lo = 0, hi = 0;
            if (lens) {
                sp->arc_left = fmax(sp->arc_left, sag / len);
                extent(c, sp->rem, n, xa, w, &lo, &hi);
            }
            if (cut_chord(sp, c, sp->rem, n, x0, x1) ||
                (lens && lens_error(sp, c, xa, w, lo, hi, sag, len)))
                return -1;
            continue;
        }
        pieces += m - 1;
        if (cut_strips(sp, c, n, x0, x1, m))
            return -1;
    }
    return 0;
}

/* Does the arc of l's conic from xa to xb (two crossings of piece p's
 * boundary) run inside p: does the chord's bisector meet the conic in p? */
static int arc_inside(const line3 *l, const pair_ctx *c, const rad_vec3 *p, int n, rad_vec3 xa,
                      rad_vec3 xb)
{
    rad_vec3 mid, w;
    double lo, hi;
    if (!(sagitta(l, c, xa, xb, &mid, &w) > 0))
        return 1; /* straight: the chord is the arc */
    extent(c, p, n, mid, w, &lo, &hi);
    return hi > lo;
}

/* Piece p (n vertices), which the conic crosses four times (x, in order
 * along the boundary): two arcs, from x[0] to x[1] and x[2] to x[3], or
 * from x[1] to x[2] and x[3] to x[0] (a conic has no inflection, and two
 * of its arcs do not cross inside a convex piece unless it is a pair of
 * lines).  The pairing is the one whose first arc runs inside p; that arc
 * is followed, and then the second in the piece that holds both its ends
 * (if the first arc's cuts split the second, those pieces are left as
 * they are, as before).  Before, the first two crossings were taken as
 * one arc whatever the pairing, and the second arc was left uncut.  0 or
 * -1. */
static int follow_two_arcs(occ_space *sp, const pair_ctx *c, const line3 *l, double tiny,
                           const rad_vec3 *p, int n, const rad_vec3 *x)
{
    const int r = arc_inside(l, c, p, n, x[0], x[1]) ? 0 : 1;
    const rad_vec3 a0 = x[r], a1 = x[r + 1], b0 = x[(r + 2) % 4], b1 = x[(r + 3) % 4];
    const int start = sp->db.np;
    if (happens(l, a0, a1) ? follow_arc(sp, c, l, tiny, p, n, a0, a1)
                           : occ_ps_push(&sp->db, p, n))
        return -1;
    if (!happens(l, b0, b1))
        return 0;
    occ_ps_clear(&sp->arc2);
    for (int k = start; k < sp->db.np; k++)
        if (occ_ps_push(&sp->arc2, sp->db.v + sp->db.first[k],
                        sp->db.first[k + 1] - sp->db.first[k]))
            return -1;
    while (sp->db.np > start)
        occ_ps_pop(&sp->db);
    int done = 0;
    for (int k = 0; k < sp->arc2.np; k++) {
        const rad_vec3 *q = sp->arc2.v + sp->arc2.first[k];
        const int m = sp->arc2.first[k + 1] - sp->arc2.first[k];
        rad_vec3 xs[4];
        int has0 = 0, has1 = 0;
        const int nxs = done ? 0 : crossings(l, q, m, tiny, c->snap, xs);
        for (int i = 0; i < nxs; i++) {
            has0 |= v3_norm(v3_sub(xs[i], b0)) <= c->snap;
            has1 |= v3_norm(v3_sub(xs[i], b1)) <= c->snap;
        }
        if (has0 && has1) {
            done = 1;
            if (follow_arc(sp, c, l, tiny, q, m, b0, b1))
                return -1;
        } else if (occ_ps_push(&sp->db, q, m))
            return -1;
    }
    return 0;
}

/* Cut every piece of sp->dom that the conic of l crosses where its event
 * happens; 0 or -1. */
static int cut_event(occ_space *sp, const pair_ctx *c, const line3 *l, double tiny)
{
    occ_ps_clear(&sp->db);
    for (int k = 0; k < sp->dom.np; k++) {
        const rad_vec3 *p = sp->dom.v + sp->dom.first[k];
        int n = sp->dom.first[k + 1] - sp->dom.first[k];
        rad_vec3 x[4];
        int nx = crossings(l, p, n, tiny, c->snap, x);
        if (nx == 4) {
            if (follow_two_arcs(sp, c, l, tiny, p, n, x))
                return -1;
            continue;
        }
        int cut = nx >= 2 && happens(l, x[0], x[1]);
        if (cut ? follow_arc(sp, c, l, tiny, p, n, x[0], x[1]) : occ_ps_push(&sp->db, p, n))
            return -1;
    }
    polyset t = sp->dom;
    sp->dom = sp->db;
    sp->db = t;
    return 0;
}

/* Do segments p0 p1 and q0 q1 share an end (within tol)? */
static int share_end(rad_vec3 p0, rad_vec3 p1, rad_vec3 q0, rad_vec3 q1, double tol)
{
    return v3_norm(v3_sub(p0, q0)) <= tol || v3_norm(v3_sub(p0, q1)) <= tol ||
           v3_norm(v3_sub(p1, q0)) <= tol || v3_norm(v3_sub(p1, q1)) <= tol;
}

/* Are two of the three lines parallel?  Then no conic: the shadows of
 * two parallel edges cross at the direction's vanishing point on the inner
 * plane, which x does not move, and the events left are the planes
 * through one edge and the other (or the inner edge) that occdomain.c
 * cuts already. */
static int any_parallel(const line3 *l)
{
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (v3_norm(v3_cross(l[i].u, l[j].u)) <= 1e-9 * v3_norm(l[i].u) * v3_norm(l[j].u))
                return 1;
    return 0;
}

/* Two of the three lines in one plane (within tol, event units: lines i
 * and j, k the third).  The lines that meet all three then lie in that
 * plane or pass through the point P where lines i and j cross, so the
 * quadric of (1) is a pair of planes and its conic a pair of lines; and
 * computed from rounded vertices (a scene turned and scaled) it is a
 * hyperbola hugging them, whose sharp turn near P follow_arc cut into
 * strips until its budget ran out, for each such triple, each strip then
 * cut again by the next events: a room with a box pushed against a wall
 * grew domains of 158,161 pieces for one pair and ran out of memory at
 * 2.5 GB, where the same room unturned took 1.4 s (tests/accuracy/occturned.sh).
 * The plane of i and j holds an edge and the ends of the other, and is
 * cut by occdomain.c as a vertex-edge event; the plane through P and
 * line k is one too when P is an end of either segment.  Only when P lies
 * inside both segments (two edges crossing like an X) is it an event of
 * its own, and then it is cut whole (when in doubt, cut).  The first
 * such pair is enough: if two pairs lie in planes, they share a line, and
 * the plane through one pair's crossing and its third line is the other
 * pair's plane; three lines through one point leave no plane.  1 when two
 * lines lie in one plane (their triple is done: *err -1 on memory), 0 when
 * not. */
static int coplanar_lines(occ_space *sp, const pair_ctx *c, const line3 *l, double tol, int *err)
{
    *err = 0;
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++) {
            const rad_vec3 w = v3_cross(l[i].u, l[j].u);
            const double wn = v3_norm(w);
            if (!(fabs(v3_dot(v3_sub(l[j].a, l[i].a), w)) <= tol * wn))
                continue;
            /* P = a_i + s u_i = a_j + t u_j, in the plane of the two */
            const rad_vec3 d = v3_sub(l[j].a, l[i].a);
            const double si = v3_dot(v3_cross(d, l[j].u), w) / (wn * wn);
            const double tj = v3_dot(v3_cross(d, l[i].u), w) / (wn * wn);
            const double ei = tol / v3_norm(l[i].u), ej = tol / v3_norm(l[j].u);
            if (!(si > ei && si < 1 - ei && tj > ej && tj < 1 - ej))
                return 1;
            const line3 *lk = &l[3 - i - j];
            const rad_vec3 pp = v3_add(l[i].a, v3_scale(l[i].u, si));
            rad_vec3 nrm = v3_cross(v3_sub(lk->a, pp), lk->u);
            const double len = v3_norm(nrm);
            if (len > 0)
                *err = occ_split_plane(sp, c, v3_scale(nrm, 1.0 / len),
                                       v3_scale(pp, 1.0 / l[i].inv));
            return 1;
        }
    return 0;
}

/* Is the conic of l crossed by outer polygon o's boundary where its event
 * happens?  (The test before the pieces are looked at.) */
static int crosses_outer(const line3 *l, const rad_vec3 *o, int no, double tiny, double tol)
{
    rad_vec3 x[4];
    int nx = crossings(l, o, no, tiny, tol, x);
    for (int k = 0; k + 1 < nx; k++)
        if (happens(l, x[k], x[k + 1]))
            return 1;
    return 0;
}

/* The event of blocker edges a0 a1, b0 b1 and inner edge t0 t1: cut
 * sp->dom along its conic where it crosses the outer polygon o and
 * happens; 0 or -1. */
static int cut_triple(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no, rad_vec3 a0,
                      rad_vec3 a1, rad_vec3 b0, rad_vec3 b1, rad_vec3 t0, rad_vec3 t1)
{
    /* the event's units: about the distance to the inner edge, a power
     * of two */
    const double len = v3_norm(v3_sub(t0, o[0]));
    if (!(len > 0) || !isfinite(len))
        return 0;
    const double inv = ldexp(1.0, -ilogb(len));
    line3 l[3] = {{v3_scale(a0, inv), v3_scale(v3_sub(a1, a0), inv), inv},
                  {v3_scale(b0, inv), v3_scale(v3_sub(b1, b0), inv), inv},
                  {v3_scale(t0, inv), v3_scale(v3_sub(t1, t0), inv), inv}};
    if (any_parallel(l))
        return 0;
    int err;
    if (coplanar_lines(sp, c, l, c->snap * inv, &err))
        return err;
    /* g's round-off scale: its terms' sizes at o[0] */
    const rad_vec3 oo = v3_scale(o[0], inv);
    double s = v3_norm(v3_sub(l[0].a, oo)) * v3_norm(v3_sub(l[1].a, oo)) *
               v3_norm(v3_sub(l[2].a, oo)) * v3_norm(l[0].u) * v3_norm(l[1].u) * v3_norm(l[2].u);
    double tiny = 1e-12 * s;
    return crosses_outer(l, o, no, tiny, c->snap) ? cut_event(sp, c, l, tiny) : 0;
}

/* Might blocker edge p0 p1 hold a point of an event?  The transversal
 * runs from x on the outer element through the edge to the inner one, so
 * that point lies in the pair's shaft conv(outer u inner) (occshaft.c's
 * face planes sp->hn/ha, outward normals): an edge whose two ends lie
 * beyond one face plane, by more than c->snap even when it is lengthened
 * by happens()'s slack at each end, holds none. */
static int edge_in_shaft(const occ_space *sp, const pair_ctx *c, rad_vec3 p0, rad_vec3 p1)
{
    const rad_vec3 u = v3_scale(v3_sub(p1, p0), 0.1);
    const rad_vec3 a = v3_sub(p0, u), b = v3_add(p1, u);
    for (int h = 0; h < sp->nhull; h++)
        if (v3_dot(sp->hn[h], v3_sub(a, sp->ha[h])) > c->snap &&
            v3_dot(sp->hn[h], v3_sub(b, sp->ha[h])) > c->snap)
            return 0;
    return 1;
}

int occ_split_three_edges(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no)
{
    if (c->nb > OCC_EEE_BLOCKERS)
        return 0;
    for (int a = 0; a < c->nb; a++)
        for (int b = a + 1; b < c->nb; b++) {
            const rad_vec3 *pa = sp->blkc.v + sp->blkc.first[a];
            const rad_vec3 *pb = sp->blkc.v + sp->blkc.first[b];
            const int na = sp->blkc.first[a + 1] - sp->blkc.first[a];
            const int nb = sp->blkc.first[b + 1] - sp->blkc.first[b];
            const int *fa = sp->mflag + sp->blkc.first[a], *fb = sp->mflag + sp->blkc.first[b];
            for (int i = 0; i < na; i++) {
                const rad_vec3 a0 = pa[i], a1 = pa[(i + 1) % na];
                if ((fa[i] & OCC_MESH_EDGE) || !edge_in_shaft(sp, c, a0, a1))
                    continue;
                for (int j = 0; j < nb; j++) {
                    const rad_vec3 b0 = pb[j], b1 = pb[(j + 1) % nb];
                    if ((fb[j] & OCC_MESH_EDGE) || share_end(a0, a1, b0, b1, c->snap) ||
                        !edge_in_shaft(sp, c, b0, b1))
                        continue;
                    for (int k = 0; k < c->nt && sp->dom.np > 0; k++)
                        if (cut_triple(sp, c, o, no, a0, a1, b0, b1, c->t[k],
                                       c->t[(k + 1) % c->nt]))
                            return -1;
                }
            }
        }
    return 0;
}
