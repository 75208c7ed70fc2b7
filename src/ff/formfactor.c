/* formfactor.c -- element-to-element form factors by the contour integral.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The form factor from polygon A to polygon B (Goral et al. 1984, eq. 13;
 * Sparrow 1963) is
 *
 *     F_AB = 1/(2 pi A_A) * sum_p sum_q (e_p . e_q) * I_pq,
 *     I_pq = integral over edge p (length s) and edge q (length t) of ln r,
 *
 * with e_p, e_q the unit directions of the edges, both polygons run
 * counter-clockwise about their own front normals (which face each other),
 * and r the distance between the two points.  The double sum
 * S = sum (e_p . e_q) I_pq is symmetric in A and B, so one S gives both
 * F_AB = S/(2 pi A_A) and F_BA = S/(2 pi A_B): reciprocity holds to
 * round-off.  Perpendicular edges contribute nothing and are skipped.
 * S does not change when a constant is added to ln r (each closed contour
 * sums its edge vectors to zero), so the code works in coordinates centred
 * on A's centroid and keeps the terms small.
 *
 * Before integrating, each polygon is clipped to the front half-space of
 * the other's plane (Sutherland & Hodgman 1974): points behind a plane
 * neither see nor are seen by its front, and the contour formula assumes
 * polygons that do not cross each other's planes.  A pair wholly behind,
 * or on one plane, has F = 0.
 *
 * How each I_pq is evaluated depends on the accuracy mode:
 *   classic    K-point Gauss-Legendre in each variable (K = 3: the paper's
 *              nine-point rule) and the closed form for colinear edges;
 *   default,   the first route that meets the tolerance by its own
 *   reference  estimate: (1) polygons apart: the K-point Gauss rule, K = 3,
 *              4, 6 or 8, under an a priori bound, accepted within half the
 *              promise (ffgauss.c, radi_ff_gauss_tiers); (2) no skew edge
 *              pair: the closed forms, vectorised
 *              (ffcontour.c); (3) a pair small against its separation (sum
 *              of the bounding diagonals below the centroid distance, or
 *              below 1/4 of it in default): area rules (ffarea.c), where
 *              nothing cancels; (4) the contour with closed forms for
 *              parallel edge pairs and adaptive Gauss-Kronrod over the
 *              closed-form inner integral for skew ones (ffcontour.c), in
 *              long double if double cancels too much, then the area rules
 *              if they do better.  Tolerances: relative 1e-8 of S (default,
 *              promising 1e-6) and 1e-11 (reference, promising 1e-9); every
 *              estimate is the method's own plus a round-off bound.
 *              A negative result (possible only within its error) is
 *              clamped to 0 and the error estimate covers the clamp; one
 *              above 1 either way is brought to 1 only when the excess is
 *              within its error bound, and counted (clamp_to_one).
 * The routes are one table, ff_methods below: each row a method, when it
 * applies, and (in its comment) what it costs and how its error is
 * tested; a pair goes down the rows until one accepts it.
 *
 * "On a plane" means within the round-off of the distances (a few ulps
 * of the coordinates, 1e-12 of the pair's size) plus the polygons' own
 * twists, never a fraction of the coordinates' magnitude (see radi_ff_pair).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ff/formfactor.h"
#include "ff/gausstab.h"
#include "util/util.h"
#include "radiosity/base.h"
#include "radiosity/formfactor.h"


/* ulps of the coordinates allowed for the rounding of a centroid */
#define FF_ROUND 16
/* how far below 2 pi min(A) a value above 1 is brought (clamp_to_one) */
#define FF_CLAMP_ULPS 8

void rad_ff_options_init(rad_ff_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->quadrature = 3;
    opt->accuracy = RAD_ACCURACY_DEFAULT;
    opt->method = RAD_FF_CONTOUR;
    opt->resolution = RAD_HEMICUBE_DEFAULT;
}

const char *rad_ff_method_name(int method)
{
    static const char *const names[] = {"contour", "hemicube"};
    return method >= 0 && method <= RAD_FF_HEMICUBE ? names[method] : NULL;
}

/* ---- quadrature of one edge pair ---------------------------------------- */

typedef rad_ff_edge ff_edge;

/* K x K Gauss-Legendre product rule for I_pq. */
static double ln_gauss(const ff_edge *p, const ff_edge *q, int k, double inv_s2)
{
    const double *x = gl_nodes(k), *w = gl_weights(k);
    double sum = 0;
    for (int a = 0; a < k; a++) {
        rad_vec3 pa = v3_add(p->p0, v3_scale(p->d, 0.5 * (1 + x[a])));
        double inner = 0;
        for (int b = 0; b < k; b++) {
            rad_vec3 qb = v3_add(q->p0, v3_scale(q->d, 0.5 * (1 + x[b])));
            rad_vec3 r = v3_sub(pa, qb);
            inner += w[b] * log(v3_dot(r, r) * inv_s2);
        }
        sum += w[a] * inner;
    }
    /* 0.5 ln (r^2/s2) = ln (r/s); (len/2)^2 maps [-1, 1]^2 to the edges. */
    return 0.125 * p->len * q->len * sum;
}

/* The nine-point rule with the logs grouped by weight: the 3-point weights
 * are 5/9, 8/9, 5/9, so the nine products take three values and
 * sum w_a w_b ln r_ab^2 = (25 ln prod(corner r^2) + 40 ln prod(edge r^2)
 * + 64 ln r_centre^2) / 81: three logs instead of nine.  pa[0..2] and
 * qb[0..2] are the edges' Gauss points (qb shifted by `shift`); distances
 * are scaled by 1/s2, which keeps the products far from overflow and
 * integrates ln(r/s) instead of ln r: S does not change, since every
 * closed contour sums its edge vectors to zero (see the file header), as
 * long as every edge pair of the sum uses the same s (ln_scaled below). */
static double ln_gauss3_pts(const rad_vec3 *pa, const rad_vec3 *qb, rad_vec3 shift,
                            double lp, double lq, double inv_s2)
{
    double r2[3][3];
    for (int b = 0; b < 3; b++) {
        rad_vec3 q = v3_add(qb[b], shift);
        for (int a = 0; a < 3; a++) {
            rad_vec3 r = v3_sub(pa[a], q);
            r2[a][b] = v3_dot(r, r) * inv_s2;
        }
    }
    double corner = r2[0][0] * r2[0][2] * r2[2][0] * r2[2][2];
    double edge = r2[0][1] * r2[1][0] * r2[1][2] * r2[2][1];
    double sum = (25.0 * log(corner) + 40.0 * log(edge) + 64.0 * log(r2[1][1])) / 81.0;
    return 0.125 * lp * lq * sum;
}

/* The 3 Gauss points of an edge (A&S 25.4.29, x = 0, +-sqrt(3/5)). */
static void gauss3_points(const ff_edge *e, rad_vec3 out[3])
{
    const double x3 = gl_nodes(3)[2]; /* sqrt(3/5) */
    for (int a = 0; a < 3; a++)
        out[a] = v3_add(e->p0, v3_scale(e->d, 0.5 * (1 + (a - 1) * x3)));
}

static double ln_gauss3(const ff_edge *p, const ff_edge *q, double inv_s2)
{
    rad_vec3 pa[3], qb[3];
    gauss3_points(p, pa);
    gauss3_points(q, qb);
    return ln_gauss3_pts(pa, qb, v3(0, 0, 0), p->len, q->len, inv_s2);
}

/* ---- one polygon pair ---------------------------------------------------- */

/* Signed distances of p's vertices from the plane (n, c), snapped to 0
 * within tol; returns 1 if any is positive, sets *neg if any is negative,
 * *near to the number within ntol (>= tol) of the plane and *smin to the
 * smallest distance. */
static int plane_side(const rad_vec3 *p, int np, rad_vec3 nrm, rad_vec3 c, double tol,
                      double ntol, double *dist, int *neg, int *near, double *smin)
{
    /* (in locals: *smin and dist may alias, and stores through them
     * would be kept in every iteration) */
    int pos = 0, ng = 0, nr = 0;
    double lo = HUGE_VAL;
    for (int k = 0; k < np; k++) {
        double s = v3_dot(v3_sub(p[k], c), nrm);
        nr += fabs(s) <= ntol;
        lo = s < lo ? s : lo;
        if (fabs(s) <= tol)
            s = 0;
        dist[k] = s;
        pos |= s > 0;
        ng |= s < 0;
    }
    *neg = ng;
    *near = nr;
    *smin = lo;
    return pos;
}

void radi_ff_scratch_init(rad_ff_scratch *w)
{
    memset(w, 0, sizeof *w);
}

void radi_ff_scratch_free(rad_ff_scratch *w)
{
    free(w->buf);
    memset(w, 0, sizeof *w);
}

static int scratch_reserve(rad_ff_scratch *w, int na, int nb)
{
    int need = na + nb + 4;
    if (need <= w->cap)
        return 0;
    free(w->buf);
    /* layout: clipped a, clipped b (vec3), dist (double), edges a, edges b */
    size_t bytes = (size_t)need * (2 * sizeof(rad_vec3) + sizeof(double) + 2 * sizeof(ff_edge));
    w->buf = malloc(bytes);
    if (!w->buf) {
        w->cap = 0;
        return -1;
    }
    w->cap = need;
    return 0;
}

/* Is any edge pair neither parallel nor perpendicular?  Nearly parallel
 * pairs (directions that differ at all, though by less than the contour's
 * 1e-13) count as skew: the contour's closed form for them has an error
 * bound, held against a tolerance that needs the scale of S. */
static int has_skew(const ff_edge *ea, int na, const ff_edge *eb, int nb)
{
    for (int p = 0; p < na; p++)
        for (int q = 0; q < nb; q++) {
            rad_vec3 cr = v3_cross(ea[p].e, eb[q].e);
            if (fabs(v3_dot(ea[p].e, eb[q].e)) >= 1e-14 && v3_dot(cr, cr) > 0)
                return 1;
        }
    return 0;
}

/* The contour sum S by the paper's rule for two polygons known to face each
 * other (clipped ones, or K other than 3): K Gauss points per edge in each
 * variable, the closed form for colinear edges (Goral et al. 1984). */
static double classic_sum(const ff_edge *ea, int na, const ff_edge *eb, int nb, int k,
                          double scale2)
{
    const double inv_s2 = 1.0 / scale2, ln_s = 0.5 * log(scale2);
    double s = 0;
    /* Every I_pq is the integral of ln(r/s), s = sqrt(scale2): the same
     * constant for all edge pairs, so S is unchanged and its terms small. */
    for (int p = 0; p < na; p++)
        for (int q = 0; q < nb; q++) {
            const double dot = v3_dot(ea[p].e, eb[q].e);
            if (fabs(dot) < 1e-14)
                continue; /* perpendicular: no contribution */
            const rad_vec3 cr = v3_cross(ea[p].e, eb[q].e);
            double I;
            if (v3_dot(cr, cr) < 1e-26 && radi_ff_colinear(&ea[p], &eb[q]))
                I = radi_ff_ln_parallel_edges(&ea[p], &eb[q]) - ea[p].len * eb[q].len * ln_s;
            else
                I = k == 3 ? ln_gauss3(&ea[p], &eb[q], inv_s2)
                           : ln_gauss(&ea[p], &eb[q], k, inv_s2);
            s += dot * I;
        }
    return s;
}

/* Squared distance between the bounding boxes of a and b (0 if they meet). */
static double box_gap2(const rad_ff_poly *a, const rad_ff_poly *b)
{
    return v3_box_gap2(a->lo, a->hi, b->lo, b->hi);
}

/* A form factor is at most 1 both ways: S <= 2 pi min(A_a, A_b).  When S
 * exceeds that by no more than its error bound e (the true S lies in
 * [S - e, S + e] and below the limit), the limit is nearer the true value
 * than S is: bring S down to it and count the pair in w->clamped.  The
 * limit keeps FF_CLAMP_ULPS ulps below 2 pi min(A), so that S / (2 pi A)
 * and the fill's F_ij = F_ji A_j / A_i round to at most 1; e grows by that
 * margin.  Beyond e nothing is changed: the fill's statistics then count
 * an entry above 1, and the promise is seen to be missed (default mode
 * once gave values above 1 by up to 3.4e-9, tiny elements facing large
 * ones). */
static void clamp_to_one(const rad_ff_poly *a, const rad_ff_poly *b, rad_ff_scratch *w,
                         double *s, double *e)
{
    const double top = 2 * RAD_PI * (a->area < b->area ? a->area : b->area);
    const double lim = top * (1 - FF_CLAMP_ULPS * DBL_EPSILON);
    if (!(*s > lim) || *s - lim > *e + FF_CLAMP_ULPS * DBL_EPSILON * top)
        return;
    w->clamped += *s > top;
    *e += FF_CLAMP_ULPS * DBL_EPSILON * top;
    *s = lim;
}

/* Store S and its estimate (S brought within 1 when its bound allows);
 * F from a to b. */
static double pair_done(const rad_ff_poly *a, const rad_ff_poly *b, rad_ff_scratch *w, double s,
                        double e, double *contour, double *errest)
{
    clamp_to_one(a, b, w, &s, &e);
    *contour = s;
    if (errest)
        *errest = e;
    return s / (2 * RAD_PI * a->area);
}

/* ---- one pair: the methods in order ---------------------------------------- */

/* The layers a pair goes through (ff_pair_once, run_methods, run_bounded)
 * are inlined where the compiler allows: their calls were 1.8% of the
 * cube's unobstructed fill. */
#if defined(__GNUC__)
#define FF_INLINE static inline __attribute__((always_inline))
#else
#define FF_INLINE static inline
#endif

/* A pair on its way through the methods: the polygons as clipped, what
 * the applicability tests need, and the result so far. */
typedef struct pair_state {
    const rad_ff_poly *a, *b;
    const rad_ff_options *opt;
    rad_ff_scratch *w;
    const rad_vec3 *pa, *pb;    /* a and b, clipped to each other's front */
    int na, nb;
    int clipped;                /* either was clipped: the batched rules,
                                   which take the polygons' own edges, do
                                   not apply */
    int a_clipped;              /* a was: its precomputed edges do not either */
    int touch;                  /* both have two vertices near the other's
                                   plane: colinear edge pairs may exist */
    double tol;                 /* "on the plane" (see pair_setup) */
    int ambiguous;              /* a clip, or F = 0, that a twisted
                                   polygon's plane cannot decide (see
                                   pair_setup) */
    double dplane;              /* larger of each polygon's smallest vertex
                                   distance from the other's plane */
    double scale2;              /* s^2 of the ln(r/s) every I_pq integrates */
    double far;                 /* the pair is distant when far * (size_a +
                                   size_b) is below the centroid distance */
    double rel;                 /* target relative error of S, general path */
    double bound_rel;           /* the same for the a priori bounds
                                   (run_bounded) */
    rad_ff_edge *ea, *eb;       /* edges about a's centroid (pair_edges) */
    int mea, meb;               /* their counts; mea < 0: not yet made */
    int skew;                   /* some edge pair is skew; -1: not yet known */
    int area_tried;             /* the area rules ran on the whole pair */
    double s, e;                /* S so far and its error estimate */
} pair_state;

/* What a method did: accepted its S, left the pair to the next method, or
 * ran out of memory. */
enum { FF_NEXT, FF_DONE, FF_FAIL };

/* How a result is stored: as it is with no estimate (classic); through
 * pair_done (S brought within 1 when its bound allows); or first clamped
 * at 0 within its error, a form factor never being negative. */
enum { FIN_RAW, FIN_BOUNDED, FIN_CLAMPED };

/* The edges of the clipped polygons about a's centroid, made on first
 * use: a's precomputed ones unless clipped; b's from its vertices, each
 * rounded once, so that a vertex the two polygons share is the same point
 * in both (through b's own centroid it would differ by an ulp of the
 * coordinates, which a touching pair feels at the 1e-11 level). */
static void pair_edges(pair_state *p)
{
    if (p->mea >= 0)
        return;
    if (p->a_clipped) {
        p->mea = radi_ff_edges(p->pa, p->na, p->a->centroid, p->ea);
    } else {
        p->mea = p->a->nedges;
        memcpy(p->ea, p->a->edges, sizeof *p->ea * (size_t)p->mea);
    }
    p->meb = radi_ff_edges(p->pb, p->nb, p->a->centroid, p->eb);
}

static int is_classic(const pair_state *p)
{
    return p->opt->accuracy == RAD_ACCURACY_CLASSIC;
}

/* S still misses the general path's target. */
static int misses(pair_state *p)
{
    return !is_classic(p) && p->e > p->rel * fabs(p->s);
}

/* -- the applicability tests -- */

static int ap_nine_point(pair_state *p)
{
    return is_classic(p) && p->opt->quadrature == 3 && !p->clipped;
}

static int ap_bounded(pair_state *p)
{
    return !is_classic(p) && !p->clipped;
}

static int ap_classic(pair_state *p)
{
    return is_classic(p);
}

/* Is some edge pair skew (neither parallel nor perpendicular)?  Edges
 * made and the answer kept on first use. */
static int pair_skew(pair_state *p)
{
    pair_edges(p);
    if (p->skew < 0)
        p->skew = has_skew(p->ea, p->mea, p->eb, p->meb);
    return p->skew;
}

static int ap_no_skew(pair_state *p)
{
    return !is_classic(p) && !pair_skew(p);
}

static int ap_distant(pair_state *p)
{
    const double r = v3_norm(v3_sub(p->b->centroid, p->a->centroid));
    return !is_classic(p) && p->far * (p->a->size + p->b->size) < r;
}

static int ap_general(pair_state *p)
{
    return !is_classic(p);
}

static int ap_area_whole(pair_state *p)
{
    return misses(p) && !p->area_tried;
}

/* -- the methods -- */

/* The nine-point rule batched for SIMD (ffgauss.c; NaN without vector
 * extensions: the classic rule below then does it). */
static int run_nine_point(pair_state *p)
{
    p->s = radi_ff_nine_point(p->a, p->b, p->scale2, p->touch);
    return isnan(p->s) ? FF_NEXT : FF_DONE;
}

/* The 3 x 3 .. 8 x 8 Gauss rules under a priori bounds (ffgauss.c).  The
 * bounds are bounds (the truncation error proved, round-off with a
 * margin), not estimates: accepted within half the promise (1e-9
 * reference, 1e-6 default). */
FF_INLINE int run_bounded(pair_state *p)
{
    return radi_ff_gauss_tiers(p->a, p->b, p->scale2, box_gap2(p->a, p->b), p->dplane, p->tol,
                              p->bound_rel, &p->s, &p->e)
               ? FF_DONE
               : FF_NEXT;
}

static int run_classic(pair_state *p)
{
    pair_edges(p);
    p->s = classic_sum(p->ea, p->mea, p->eb, p->meb, p->opt->quadrature, p->scale2);
    return FF_DONE;
}

/* No skew edge pair: every I_pq in closed form (vectorised), exact but
 * for round-off. */
static int run_closed(pair_state *p)
{
    p->s = radi_ff_contour(p->ea, p->mea, p->eb, p->meb, p->scale2, 0, 0, p->a->centroid, &p->e);
    return p->s > 0 && p->e <= p->rel * p->s ? FF_DONE : FF_NEXT;
}

/* Distant: the area rules, where nothing cancels (ffarea.c). */
static int run_area_distant(pair_state *p)
{
    const rad_ff_poly *a = p->a, *b = p->b;
    const rad_ff_poly *const el[2] = {a, b};
    p->area_tried = 1;
    const int r = radi_ff_area(p->pa, p->na, p->pb, p->nb, a->centroid, el, p->rel, &p->s, &p->e);
    return r < 0 ? FF_FAIL : r == 0 ? FF_DONE : FF_NEXT;
}

/* Near: the contour, closed forms for parallel edge pairs and adaptive
 * Gauss-Kronrod for skew ones (ffcontour.c).  With skew edges, a first
 * pass with the classic rule sets the scale of S for the absolute
 * tolerance of their adaptive quadrature; parallel edges need none. */
static int run_contour(pair_state *p)
{
    const double rel = p->rel;
    double s0 = 0;
    if (pair_skew(p))
        s0 = fabs(classic_sum(p->ea, p->mea, p->eb, p->meb, 3, p->scale2));
    p->s = radi_ff_contour(p->ea, p->mea, p->eb, p->meb, p->scale2, rel * s0, 0, p->a->centroid,
                          &p->e);
    if (p->e > rel * fabs(p->s) && fabs(p->s) < 0.5 * s0) /* scale was too optimistic */
        p->s = radi_ff_contour(p->ea, p->mea, p->eb, p->meb, p->scale2, rel * fabs(p->s), 0,
                              p->a->centroid, &p->e);
    return misses(p) ? FF_NEXT : FF_DONE;
}

/* Keep (s, e) if it does better than the result so far. */
static int take_if_better(pair_state *p, double s, double e)
{
    if (e < p->e) {
        p->s = s;
        p->e = e;
    }
    return misses(p) ? FF_NEXT : FF_DONE;
}

/* The terms cancel beyond double (long thin pairs): the same in long
 * double. */
static int run_contour_long(pair_state *p)
{
    double s, e;
    s = radi_ff_contour(p->ea, p->mea, p->eb, p->meb, p->scale2, p->rel * fabs(p->s), 1,
                       p->a->centroid, &e);
    return take_if_better(p, s, e);
}

/* The area rules on the whole pair (a failure to converge, or to find
 * memory, leaves the result as it is). */
static int run_area_whole(pair_state *p)
{
    const rad_ff_poly *a = p->a, *b = p->b;
    const rad_ff_poly *const el[2] = {a, b};
    double s, e;
    if (radi_ff_area(p->pa, p->na, p->pb, p->nb, a->centroid, el, p->rel, &s, &e) != 0)
        return FF_NEXT;
    return take_if_better(p, s, e);
}

/* The area rules with both polygons cut into parts small against their
 * distance (strips end to end, a strip beside a plate). */
static int run_area_split(pair_state *p)
{
    const rad_ff_poly *a = p->a, *b = p->b;
    const rad_ff_poly *const el[2] = {a, b};
    double s, e;
    const int r =
        radi_ff_area_adaptive(p->pa, p->na, p->pb, p->nb, a->centroid, el, p->rel, &s, &e);
    if (r < 0)
        return FF_FAIL;
    return r == 0 ? take_if_better(p, s, e) : FF_NEXT;
}

/* The methods in the order they are tried: the first that applies and
 * accepts its result ends the pair; one that does not accept leaves it to
 * the rows below.  Classic mode takes rows 1 and 3 only (the paper's rule
 * and nothing else); default and reference take the rest, fastest first,
 * each accepting only what meets the mode's target (rel, 1e-8 of S in
 * default, 1e-11 in reference) by its own error estimate: the method's
 * own plus a round-off bound.  The comment above each row says when it
 * applies, what it costs, and how its error is tested. */
typedef struct ff_method {
    int (*applies)(pair_state *p);
    int (*run)(pair_state *p);
    int finish;
} ff_method;

static const ff_method ff_methods[] = {
    /* 1. classic, K = 3, neither polygon clipped: the nine-point rule,
     * batched for SIMD; the fill's common case; no error estimate */
    {ap_nine_point, run_nine_point, FIN_RAW},
    /* 2. default and reference, neither clipped: Gauss 3x3 .. 8x8, about
     * classic's cost; accepted when the proved a priori bound (truncation
     * and round-off) is within half the promise */
    {ap_bounded, run_bounded, FIN_BOUNDED},
    /* 3. classic otherwise: K Gauss points per edge, closed form for
     * colinear edges (Goral et al. 1984); always accepted, no estimate */
    {ap_classic, run_classic, FIN_RAW},
    /* 4. no skew edge pair: closed forms, vectorised; exact but for
     * round-off, accepted when the round-off bound is within rel */
    {ap_no_skew, run_closed, FIN_CLAMPED},
    /* 5. small against their distance (sum of the bounding diagonals
     * below the centroid distance, below 1/4 of it in default): area
     * rules, where nothing cancels; accepted when two orders agree */
    {ap_distant, run_area_distant, FIN_CLAMPED},
    /* 6. near: the contour, closed forms and adaptive Gauss-Kronrod 7-15
     * on skew edges; accepted on the Kronrod estimate plus round-off */
    {ap_general, run_contour, FIN_CLAMPED},
    /* 7. still short: the contour in long double (cancellation beyond
     * double, long thin pairs), kept if its estimate is smaller */
    {misses, run_contour_long, FIN_CLAMPED},
    /* 8. then the area rules in one piece, kept if better */
    {ap_area_whole, run_area_whole, FIN_CLAMPED},
    /* 9. then cut into parts small against their distance, kept if
     * better; what still misses is counted by the fill */
    {misses, run_area_split, FIN_CLAMPED},
};
#define FF_NMETHODS ((int)(sizeof ff_methods / sizeof ff_methods[0]))

/* Store the result as method `finish` says; F from a to b. */
static double pair_finish(pair_state *p, int finish, double *contour, double *errest)
{
    if (finish == FIN_RAW) {
        *contour = p->s;
        if (errest)
            *errest = NAN;
        /* With both contours counter-clockwise about their own fronts,
         * facing polygons give S > 0 (checked on two facing unit squares). */
        return p->s / (2 * RAD_PI * p->a->area);
    }
    if (finish == FIN_CLAMPED && p->s < 0) { /* clamp within its error */
        p->e = fmax(p->e, -p->s);
        p->s = 0;
    }
    return pair_done(p->a, p->b, p->w, p->s, p->e, contour, errest);
}

/* How far a twisted polygon's plane is uncertain at the other polygon's
 * vertices (see pair_setup): 2 twist (1 + reach radius / area) for each,
 * reach the farthest the other's vertices can be from its centroid. */
static double plane_doubt(const rad_ff_poly *a, const rad_ff_poly *b)
{
    const double c = v3_norm(v3_sub(b->centroid, a->centroid));
    const double da = a->area > 0 ? a->radius / a->area : 0;
    const double db = b->area > 0 ? b->radius / b->area : 0;
    return 2 * a->twist * (1 + (c + b->radius) * da) + 2 * b->twist * (1 + (c + a->radius) * db);
}

/* Clip each polygon to the front of the other's plane and fill p for the
 * methods; 1 to go on, 0 when F = 0 (one wholly behind the other's plane,
 * or both on one plane), -1 when scratch memory ran out.  wide: take
 * every vertex within the twisted planes' doubt as on the plane (the
 * second look at an ambiguous pair, ff_pair_once). */
static int pair_setup(pair_state *p, const rad_ff_poly *a, const rad_ff_poly *b,
                      const rad_ff_options *opt, double within, rad_ff_scratch *w, int wide)
{
    if (scratch_reserve(w, a->n, b->n) != 0)
        return -1;
    rad_vec3 *ca = (rad_vec3 *)w->buf;
    rad_vec3 *cb = ca + a->n + 2;
    double *dist = (double *)(cb + b->n + 2);
    p->ea = (ff_edge *)(dist + (a->n > b->n ? a->n : b->n) + 2);
    p->eb = p->ea + a->n + 2;
    /* Tolerance for "on the plane": the round-off of the
     * distances, nothing more, plus the polygons' own twists.  The
     * distance n . (p - c) is off by the rounding of the centroid c (a few
     * ulps of the coordinates, FF_ROUND of them allowed) and by that of the
     * product (1e-12 of the pair's size, generous).  It used to be 1e-12 of
     * the coordinates' magnitude: two plates 1e-7 apart at 1e6 from the
     * origin were one plane (F = 0), at the origin they see each other
     * fully.  A twisted polygon (the scene accepts a vertex 1e-6 of a
     * quad's size off its plane) is planar only to within its twist, so
     * two faces of one twisted panel lie on one plane and see nothing of
     * each other (they used to give F = 2/9 both ways).
     *
     * That plane is the Newell normal's through the centroid, and a
     * twisted polygon's plane is uncertain: the planes through three of
     * its vertices (its fan's triangles, which the contour's Stokes value
     * integrates over) tilt from it by up to about 2 twist / width, width
     * >= area / radius, so at the other polygon's vertices they part from
     * it by up to plane_doubt.  A clip whose vertices behind the plane all
     * lie within that doubt, or an F = 0 for a polygon wholly behind it
     * within the doubt, is ambiguous: ff_pair_once adds to the estimate
     * what taking those vertices as on the plane changes.  A pentagon
     * twisted by 3.5e-7 of its size 0.05 from a plate hinged at 179.9
     * degrees lost a sliver of the plate this way: both modes 1e-6 of F
     * off the contour integral of the pair, under estimates of 1e-16
     * (tests/accuracy/twisted.sh).  A planar polygon has no doubt beyond
     * round-off, which rtol holds.
     *
     * Deciding what is on the plane allows for as much as visibility
     * does (the scene's snap, radi_occ_scene_snap: OCC_SNAP of its size and
     * OCC_ROUND ulps of its coordinates as the user gave them, which the
     * frame of mesh.h keeps), so that a surface visibility takes as on a
     * plane, and lets light pass, is on it here too and sees nothing
     * there.  A box face pressed against a wall of a room 7e5 from the
     * origin lay up to 5.5e-12 off the wall's plane in the frame, beyond
     * the frame's round-off and twists: it saw the wall fully (F = 1)
     * where visibility let the wall see past it, and the wall's row
     * summed to 1.016 in both modes (fuzzed scene 57:119); the same with
     * the face 5e-12 off the wall of the room at the origin
     * (tests/accuracy/occfar.sh, rooms c and d).  Only the decision allows for it:
     * the bounds that follow (p->tol) are on the geometry as given, which
     * the frame holds exactly, so a scene moved by an exact amount keeps
     * its F bit for bit unless a vertex lies within the snap of a plane. */
    const double ca_max = v3_maxabs(a->centroid), cb_max = v3_maxabs(b->centroid);
    const double rtol = FF_ROUND * DBL_EPSILON * (ca_max > cb_max ? ca_max : cb_max) +
                         1e-12 * (a->size + b->size);
    const double snap = a->snap > b->snap ? a->snap : b->snap;
    /* (plane_doubt is 0 for planar polygons, most pairs: not computed) */
    const double wtol = rtol + (a->twist > 0 || b->twist > 0 ? plane_doubt(a, b) : 0);
    const double tol = wide ? wtol : rtol + a->twist + b->twist;
    const double ctol = tol + snap, cwtol = wtol + snap; /* for the decision */
    p->ambiguous = 0;
    /* A colinear edge pair lies on both planes: each polygon then has two
     * vertices near the other's plane, allowing for non-planar polygons
     * (the scene's 1e-6 of a quad's size, less for its elements). */
    const double ntol = ctol + 1e-5 * (a->size + b->size);
    int nega, negb, neara, nearb;
    double mina, minb;
    if (!plane_side(b->v, b->n, a->normal, a->centroid, ctol, ntol, dist, &negb, &nearb, &minb)) {
        p->ambiguous = cwtol > ctol && minb < -ctol && minb >= -cwtol;
        return 0; /* B wholly behind A's plane, or on it */
    }
    p->pb = negb ? cb : b->v;
    p->nb = negb ? poly_clip_side(b->v, dist, b->n, 1.0, cb, b->n + 1) : b->n;
    if (!plane_side(a->v, a->n, b->normal, b->centroid, ctol, ntol, dist, &nega, &neara, &mina)) {
        p->ambiguous = cwtol > ctol && mina < -ctol && mina >= -cwtol;
        return 0;
    }
    p->ambiguous = cwtol > ctol && (negb || nega) && (!negb || minb >= -cwtol) &&
                   (!nega || mina >= -cwtol);
    p->pa = nega ? ca : a->v;
    p->na = nega ? poly_clip_side(a->v, dist, a->n, 1.0, ca, a->n + 1) : a->n;
    /* (a clip that would not fit in n + 1 vertices returns -1: its
     * distances changed sign more than twice beyond the tolerance, which a
     * convex polygon within its twist cannot do; it is on the plane as far
     * as they can tell) */
    if (p->na < 3 || p->nb < 3)
        return 0;
    const rad_vec3 sep = v3_sub(b->centroid, a->centroid);
    const int ref = opt->accuracy == RAD_ACCURACY_REFERENCE;
    p->a = a;
    p->b = b;
    p->opt = opt;
    p->w = w;
    p->clipped = nega || negb;
    p->a_clipped = nega;
    p->touch = neara >= 2 && nearb >= 2;
    p->tol = tol;
    /* for a lower bound on their distance: each polygon's nearest vertex
     * from the other's plane (and, in run_bounded, the box gap) */
    p->dplane = mina > minb ? mina : minb;
    p->scale2 = v3_dot(sep, sep) + a->size * a->size + b->size * b->size;
    /* The contour's closed forms lose about eps (r/L)^4 to cancellation:
     * default (1e-8 internally) can afford r/L up to ~10, reference
     * (1e-11) moves to the area form as soon as the pair is apart.  The
     * targets are 1e-9 (reference) and 1e-6 (default) with a margin of
     * 100 for the estimates, and of 2 for the a priori bounds.  A caller
     * that needs S within `within` of S (radi_ff_pair_within) tightens
     * both in the same ratio, the bounds' down to FF_WITHIN_FLOOR and the
     * general path's down to FF_GENERAL_FLOOR (formfactor.h). */
    p->far = ref ? 1 : 4;
    p->bound_rel = ref ? 5e-10 : 5e-7;
    p->rel = ref ? 1e-11 : 1e-8;
    if (within > 0 && within < p->bound_rel) {
        const double t = within > FF_WITHIN_FLOOR ? within : FF_WITHIN_FLOOR;
        p->rel = fmax(p->rel * (t / p->bound_rel), FF_GENERAL_FLOOR);
        p->bound_rel = t;
    }
    p->mea = p->meb = -1;
    p->skew = -1;
    p->area_tried = 0;
    p->s = p->e = 0;
    return 1;
}

/* The methods in order on a set-up pair: how to store the result
 * (FIN_*), or -1 when memory ran out. */
FF_INLINE int run_methods(pair_state *p)
{
    /* Rows 1 and 2 (one of them applies to the fill's common case,
     * neither polygon clipped) are called directly, then the table from
     * row 3 as the loop would go on: the indirect calls of the first two
     * rows were 1.4% of the unobstructed fill (the cube at 10 x 10). */
    int finish = FIN_CLAMPED, k = 0;
    const int row = ap_bounded(p); /* ff_methods[row] */
    if (row || ap_nine_point(p)) {
        finish = ff_methods[row].finish;
        if ((row ? run_bounded(p) : run_nine_point(p)) == FF_DONE)
            return finish;
        k = 2;
    }
    for (; k < FF_NMETHODS; k++) {
        const ff_method *m = &ff_methods[k];
        if (!m->applies(p))
            continue;
        const int r = m->run(p);
        if (r == FF_FAIL)
            return -1;
        finish = m->finish;
        if (r == FF_DONE)
            break;
    }
    return finish;
}

/* An ambiguous pair (pair_setup) looked at again with the vertices within
 * the planes' doubt taken as on them: twice |S_wide - s| (the wide look is
 * one reading the twist allows, not the farthest: a fan triangle's plane
 * may clip between the two) plus S_wide's own estimate, or NaN when
 * memory ran out.  (It reuses the scratch space, so the first look's
 * polygons are gone after it.) */
static double doubt_of(const rad_ff_poly *a, const rad_ff_poly *b, const rad_ff_options *opt,
                       double within, rad_ff_scratch *w, double s)
{
    pair_state q;
    const int go = pair_setup(&q, a, b, opt, within, w, 1);
    if (go <= 0)
        return go < 0 ? NAN : 2 * fabs(s);
    return run_methods(&q) < 0 ? NAN : 2 * fabs(q.s - s) + q.e;
}

FF_INLINE double ff_pair_once(const rad_ff_poly *a, const rad_ff_poly *b,
                              const rad_ff_options *opt, double within, rad_ff_scratch *w,
                              double *contour, double *errest)
{
    pair_state p;
    *contour = 0;
    if (errest)
        *errest = 0;
    const int go = pair_setup(&p, a, b, opt, within, w, 0);
    const int doubt = p.ambiguous && go >= 0 && opt->accuracy != RAD_ACCURACY_CLASSIC;
    if (go <= 0) {
        if (go < 0)
            return NAN;
        const double e = doubt ? doubt_of(a, b, opt, within, w, 0) : 0;
        if (errest)
            *errest = e;
        return isnan(e) ? NAN : 0.0;
    }
    const int finish = run_methods(&p);
    if (finish < 0)
        return NAN;
    if (doubt && finish != FIN_RAW) {
        const double e = doubt_of(a, b, opt, within, w, p.s);
        if (isnan(e))
            return NAN;
        p.e += e;
    }
    return pair_finish(&p, finish, contour, errest);
}

/* Default mode promises 1e-6 relative.  A pair whose own estimate still
 * misses that after default's methods is done again to reference mode's
 * targets (tighter tolerances, so more panels, long double and area
 * subdivision where they help), and the result with the smaller estimate
 * is kept; what misses even then is counted by the fill (promise_unmet;
 * doc/design.md, "Conventions").  A pair clamped below 1 is counted once,
 * by the result kept. */
double radi_ff_pair_within(const rad_ff_poly *a, const rad_ff_poly *b,
                          const rad_ff_options *opt, double within, rad_ff_scratch *w,
                          double *contour, double *errest)
{
    const double c0 = w->clamped;
    double f = ff_pair_once(a, b, opt, within, w, contour, errest);
    if (opt->accuracy != RAD_ACCURACY_DEFAULT || !errest || isnan(f) ||
        !(*errest > 1e-6 * fabs(*contour)))
        return f;
    const double c1 = w->clamped;
    rad_ff_options ref = *opt;
    double s2, e2;
    ref.accuracy = RAD_ACCURACY_REFERENCE;
    const double f2 = ff_pair_once(a, b, &ref, within, w, &s2, &e2);
    if (!isnan(f2) && e2 < *errest) {
        w->clamped = c0 + (w->clamped - c1);
        *contour = s2;
        *errest = e2;
        return f2;
    }
    w->clamped = c1;
    return f;
}

double radi_ff_pair(const rad_ff_poly *a, const rad_ff_poly *b, const rad_ff_options *opt,
                   rad_ff_scratch *w, double *contour, double *errest)
{
    return radi_ff_pair_within(a, b, opt, 0, w, contour, errest);
}
