/* occlusion.c -- hidden surfaces in the form factors: which element pairs
 * can be blocked at all, and how much of each such pair is hidden.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * 1. Which pairs can be blocked (shaft culling; Haines & Wallace, "Shaft
 *    culling for efficient ray-cast radiosity", Eurographics Workshop on
 *    Rendering 1991).  The shaft of a pair is the convex hull H of the two
 *    elements, each first clipped to the front of the other's plane (only
 *    those parts exchange light).  For convex A and B, conv(A u B) is the
 *    union of the segments from A to B (Rockafellar, Convex Analysis, 1970,
 *    Thm. 3.3), so a surface can block the pair only if it meets the
 *    interior of H.  A surface polygon P is ruled out by a separating
 *    plane: either P's own plane with H on one closed side, or a face plane
 *    of H with P on its outer closed side.  The face planes of the hull of
 *    two convex polygons pass through an edge of one and a vertex of the
 *    other; they are those candidates with every vertex on one side.  The
 *    test is conservative: a pair it cannot clear goes on to step 3, which
 *    then finds nothing hidden and keeps S unchanged.  Touching counts as
 *    separated: what a surface hides through a contact of zero thickness
 *    has zero measure.  Touching means within round-off and the
 *    surfaces' own twist (OCC_SNAP below), nothing more: an element a
 *    hair above a floor, facing it, is in front of the floor.
 *    Each pair is worked in its own frame (coordinates less the centroid
 *    of element i), so that the points the cuts construct keep the
 *    digits of the pair, not those of its distance from the origin.
 *    Blockers are the scene's surfaces, not elements: a planar surface
 *    cannot block a segment that starts on it, so the surfaces of i and j
 *    are left out, and the rest is tested whole.  The test runs twice:
 *    once per pair of surfaces at setup (a CGAL AABB tree, visibility.cc,
 *    gives the surfaces that meet the bounding box of the surfaces' shaft),
 *    and per pair of elements only against that short list.  When no pair
 *    of surfaces has a candidate (a convex room seen from inside), the
 *    scene needs no visibility work and rad_occ_create says so.
 *
 * 2. Fully hidden by one blocker: if P's plane strictly separates the two
 *    elements and the 16 (or so) segments between their vertices all pass
 *    through P's interior, every segment does (the crossing points of the
 *    segments from A to B form the convex hull of those of the vertex
 *    pairs), and F = 0.
 *
 * 3. The hidden part.  With A_o the outer and A_t the inner element,
 *        A_o F_ot = A_t F_to = integral over x in A_o of F(x -> visible part of A_t),
 *    and the integrand is computed exactly: the part of A_t hidden from x
 *    by a blocker polygon P is A_t intersected with the cone from x over P
 *    (P clipped to the front of A_t's plane; the cone is bounded by the
 *    planes through x and each edge of P, the shadow volume of Crow 1977).
 *    Subtracting a convex cone from a convex piece leaves convex pieces
 *    (one cut per cone plane; Sutherland & Hodgman 1974 clipping), so the
 *    visible part stays a list of convex pieces, and each hidden piece
 *    adds its point-to-polygon form factor (Lambert 1760; as written in
 *    Baum, Rushmeier & Winget, SIGGRAPH 1989, eq. 6):
 *        F(x -> Q) = -1/(2 pi) sum_k gamma_k n_x . (R_k x R_k+1)/|R_k x R_k+1|,
 *    R_k = q_k - x, gamma_k the angle between R_k and R_k+1 (the sign is
 *    for Q counter-clockwise about a normal that faces x).  So
 *        S_occluded = S - 2 pi * integral over A_o of hidden(x) dx,
 *    where S is the unoccluded contour sum of the kernel: the quadrature
 *    error only touches the hidden part, never the (possibly singular)
 *    unoccluded one.  For the last blocker, whose visible remainder is not
 *    needed, the hidden part of a piece is found the other way round when
 *    the blocker lies between x's level and the inner plane: the cone's
 *    section by that plane is the central projection of the blocker, and
 *    clipping it by the piece's few edges costs O(K) for a K-gon where K
 *    cone cuts cost O(K^2) (hidden_last).
 *
 * 4. Where to integrate.  hidden(x) vanishes outside each blocker's
 *    penumbra region and equals the unoccluded integrand inside its umbra;
 *    both regions are convex and bounded by planes through an edge of the
 *    blocker and a vertex of the inner element or the other way round (see
 *    support_domain).  The outer element is cut along those planes into
 *    convex pieces, and only the pieces inside some penumbra are
 *    integrated: a thin penumbra, or a thin strip that still sees past a
 *    silhouette, becomes a piece of its own instead of falling between
 *    evaluation points.  On each piece's fan of triangles hidden(x) is
 *    integrated by the 3-point degree-2 rule (Strang & Fix 1973) on each
 *    triangle and on its four midpoint children; |parent - children|
 *    estimates the error, and the triangle with the largest estimate is
 *    split until the sum of estimates is below the pair's tolerance
 *    (global adaptive subdivision as in QUADPACK's QAG, Piessens et al.
 *    1983).  The outer element is the one that looks smaller from the
 *    nearest blocker (size / distance): from there the blocker's shadow
 *    moves least over the inner element, so hidden(x) is smoothest.  If
 *    no piece is left, S is kept as it is (bit for bit); if every piece is
 *    inside an umbra, or no evaluation point sees anything of the inner
 *    element from either side, F = 0.
 *
 * Accuracy modes: classic evaluates the pieces once (two levels of points
 * on each fan triangle) and stops; default refines until the estimated
 * error of A_o F_ot is below 3e-4 of its unoccluded value (so a row of F
 * moves by at most ~3e-4 times the sum of its partly hidden unoccluded
 * entries); reference also cuts the pieces along every event plane of
 * each blocker (see split_events), so that the estimate can be trusted,
 * and refines to 1e-6.  On the closed Cornell box
 * (data/cornell-box-closed.scene, 3023 elements) rows then sum to 1 within
 * 2e-5 (default) and 3e-6 (reference).  Each unordered pair is done once:
 * the result is the symmetric A_i F_ij, and reciprocity stays exact.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "formfactor.h"
#include "occlusion.h"
#include "polygon.h"
#include "radiosity.h"
#include "status.h"
#include "vec.h"
#include "visibility.h"


/* Tolerances.  A point is on a plane (and a blocker only touches a shaft)
 * within OCC_SNAP of the scene's bounding-box diagonal L, plus the
 * round-off of mesh vertices interpolated at the scene's coordinates
 * (OCC_ROUND ulps of the largest), plus the surfaces' own departures from
 * planarity (the scene accepts 1e-6 of a quad's size; scene.c): two
 * faces of one twisted panel lie on one plane as far as the data can say.
 * Nothing larger: a blocker 1e-9 of the scene's size from an element is
 * in front of it, and hides what lies behind (issue 20: a tolerance of
 * 1e-9 L let a floor's light through to an element 1e-9 above it). */
#define OCC_SNAP 1e-11
#define OCC_ROUND 16
#define OCC_SLIVER 1e-10    /* pieces below this fraction of the inner element
                               are dropped (round-off slivers of the cuts) */

/* Per-pair error targets (relative to the unoccluded A_i F_ij) and the
 * largest number of triangles the adaptive rule may use. */
#define OCC_TOL_DEFAULT 3e-4
#define OCC_TOL_REFERENCE 1e-6
#define OCC_LEAVES_DEFAULT 256
#define OCC_LEAVES_REFERENCE 16384

struct rad_occ {
    rad_occ_mode mode;
    rad_accuracy accuracy;
    int nsurf;
    rad_vec3 *sv;               /* surface polygons: sv[sfirst[s] .. sfirst[s+1]) */
    int *sfirst;
    rad_vec3 *snormal, *slo, *shi;
    double *stwist;             /* each surface's largest vertex distance from
                                   its plane through the vertex mean */
    int *esurf;                 /* surface of each element */
    size_t *cand_off;           /* candidates of surface pair p: cand[cand_off[p] ..) */
    int *cand;
    double snap;                /* absolute tolerance (see OCC_SNAP) */
};

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Index of the unordered surface pair a < b among ns(ns-1)/2. */
static size_t pair_index(int a, int b, int ns)
{
    return (size_t)a * (size_t)(2 * ns - a - 1) / 2 + (size_t)(b - a - 1);
}

/* ---- growable buffers ------------------------------------------------------ */

/* One triangle of the adaptive rule: its own 3-point value and those of its
 * four midpoint children. */
typedef struct tri_node {
    rad_vec3 p[3];
    double area;
    double q;                   /* the rule on the triangle */
    double qc[4];               /* the rule on each child */
    double err;                 /* |q - sum qc| */
} tri_node;

/* The capacity to grow to for `need` elements. */
static int new_cap(int cap, int need)
{
    int c = cap > 16 ? cap : 16;
    while (c < need)
        c *= 2;
    return c;
}

/* Make room for `need` elements in *p (capacity *cap); 0, or -1 when
 * memory ran out (then *p is untouched).  One per element type, so that
 * no pointer is accessed through a pointer of another type. */
static int grow_v3(rad_vec3 **p, int *cap, int need)
{
    if (need <= *cap)
        return 0;
    int c = new_cap(*cap, need);
    rad_vec3 *q = realloc(*p, sizeof *q * (size_t)c);
    if (!q)
        return -1;
    *p = q;
    *cap = c;
    return 0;
}

static int grow_d(double **p, int *cap, int need)
{
    if (need <= *cap)
        return 0;
    int c = new_cap(*cap, need);
    double *q = realloc(*p, sizeof *q * (size_t)c);
    if (!q)
        return -1;
    *p = q;
    *cap = c;
    return 0;
}

static int grow_node(tri_node **p, int *cap, int need)
{
    if (need <= *cap)
        return 0;
    int c = new_cap(*cap, need);
    tri_node *q = realloc(*p, sizeof *q * (size_t)c);
    if (!q)
        return -1;
    *p = q;
    *cap = c;
    return 0;
}

static int grow_i(int **p, int *cap, int need)
{
    if (need <= *cap)
        return 0;
    int c = new_cap(*cap, need);
    int *q = realloc(*p, sizeof *q * (size_t)c);
    if (!q)
        return -1;
    *p = q;
    *cap = c;
    return 0;
}

/* A list of polygons sharing one vertex array. */
typedef struct polyset {
    rad_vec3 *v;
    int nv, capv;
    int *first;                 /* np + 1 entries */
    int np, capp;
} polyset;

static void ps_clear(polyset *s)
{
    s->nv = s->np = 0;
}

/* Room for one more polygon of up to n vertices at s->v + s->nv. */
static int ps_reserve(polyset *s, int n)
{
    if (grow_v3(&s->v, &s->capv, s->nv + n) ||
        grow_i(&s->first, &s->capp, s->np + 2))
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

static int ps_push(polyset *s, const rad_vec3 *p, int n)
{
    if (ps_reserve(s, n))
        return -1;
    memcpy(s->v + s->nv, p, sizeof *p * (size_t)n);
    ps_commit(s, n);
    return 0;
}

/* ps_push of p less `origin` (into the pair's local frame). */
static int ps_push_shifted(polyset *s, const rad_vec3 *p, int n, rad_vec3 origin)
{
    if (ps_reserve(s, n))
        return -1;
    for (int k = 0; k < n; k++)
        s->v[s->nv + k] = v3_sub(p[k], origin);
    ps_commit(s, n);
    return 0;
}

/* Drop the last polygon of s. */
static void ps_pop(polyset *s)
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

/* Per-thread space. */
typedef struct occ_space {
    polyset loc;                /* the two elements in the pair's frame: 0 = i, 1 = j */
    polyset elem;               /* the two clipped elements: 0 = i, 1 = j */
    polyset blk;                /* the pair's blockers, whole */
    polyset blkc;               /* the same, clipped to the front of the inner plane */
    int *bid;                   /* surface of each blocker of the pair */
    int capb;
    rad_vec3 *bn, *bc;          /* clipped blockers: normal, centroid */
    int capbn, capbc;
    polyset cur, next;          /* visible pieces before / after a blocker */
    rad_vec3 *rem, *tmp;        /* the piece being cut, and the cut's output */
    int caprem, captmp;
    double *d;                  /* signed distances */
    int capd;
    rad_vec3 *cone, *conep;     /* cone planes: inward normal, point */
    int capcone, capconep;
    rad_vec3 *sn, *sa;          /* penumbra or umbra planes of all blockers */
    int capsn, capsa;
    int *sfirst;                /* blocker b's planes: [sfirst[b], sfirst[b+1]) */
    int capsf;
    int *empty;                 /* blocker b's umbra has no interior */
    int capem;
    polyset da, db;             /* the support domain while it is built */
    polyset dom;                /* the support domain: disjoint convex pieces */
    rad_vec3 *pcen, *qcen;      /* bounding spheres of dom's (p) and db's (q)
                                   pieces while split_events runs */
    double *prad, *qrad;
    int cappc, capqc, cappr, capqr;
    polyset umb;                /* its pieces inside some blocker's umbra */
    rad_vec3 *pj0, *pj1;        /* a blocker's shadow on the inner plane, clipped */
    int cappj0, cappj1;
    rad_vec3 *hn, *ha;          /* hull planes: outward normal, point */
    int caphn, capha;
    tri_node *node;
    int capnode;
    double snap;                /* the pair's tolerance: o->snap plus the
                                   twists of its surfaces and candidates */
    int any_hidden, any_visible;/* over the pair's evaluations */
    double evals;
} occ_space;

/* ---- small geometry -------------------------------------------------------- */

/* Clip p to the front (nrm . (q - a) >= 0) of a plane into set s; returns
 * the vertex count kept (0 when nothing or too little is left), -1 when
 * memory ran out. */
static int clip_into(occ_space *sp, polyset *s, const rad_vec3 *p, int n, rad_vec3 nrm,
                     rad_vec3 a, double tol)
{
    double lo, hi;
    if (grow_d(&sp->d, &sp->capd, n) || ps_reserve(s, n + 1))
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

/* Point-to-polygon form factor from a differential area at x with unit
 * normal nrm to polygon q (Lambert 1760; Baum et al. 1989, eq. 6). */
static double ff_point_polygon(rad_vec3 x, rad_vec3 nrm, const rad_vec3 *q, int m)
{
    double sum = 0;
    rad_vec3 r0 = v3_sub(q[m - 1], x);
    for (int k = 0; k < m; k++) {
        rad_vec3 r1 = v3_sub(q[k], x);
        rad_vec3 c = v3_cross(r0, r1);
        double cn = v3_norm(c);
        if (cn > 0)
            sum += atan2(cn, v3_dot(r0, r1)) * v3_dot(nrm, c) / cn;
        r0 = r1;
    }
    return -sum / (2 * RAD_PI);
}

/* ---- the shaft ------------------------------------------------------------- */

/* Planes through an edge of p and a vertex of q with all of p and q on one
 * closed side: face planes of conv(p u q), appended with their outward
 * normals to sp->hn / sp->ha starting at *nh. */
static int side_planes(occ_space *sp, const rad_vec3 *p, int np, const rad_vec3 *q, int nq,
                       const rad_vec3 *all, int nall, double tol, int *nh)
{
    for (int k = 0; k < np; k++) {
        rad_vec3 a = p[k], e = v3_sub(p[(k + 1) % np], a);
        for (int l = 0; l < nq; l++) {
            rad_vec3 w = v3_sub(q[l], a), nrm = v3_cross(e, w);
            double len = v3_norm(nrm);
            if (!(len > 1e-12 * v3_norm(e) * v3_norm(w)))
                continue;
            nrm = v3_scale(nrm, 1.0 / len);
            double lo, hi;
            if (grow_d(&sp->d, &sp->capd, nall))
                return -1;
            poly_distances(all, nall, nrm, a, tol, sp->d, &lo, &hi);
            if (hi > 0 && lo < 0)
                continue;
            if (grow_v3(&sp->hn, &sp->caphn, *nh + 1) ||
                grow_v3(&sp->ha, &sp->capha, *nh + 1))
                return -1;
            sp->hn[*nh] = hi > 0 ? v3_scale(nrm, -1.0) : nrm;
            sp->ha[*nh] = a;
            ++*nh;
        }
    }
    return 0;
}

/* The face planes of the shaft conv(p u q): both polygons' own planes
 * (outward = away from the other polygon) and the side planes.  The
 * points of p and q follow each other in `all`.  Returns the count or -1. */
static int hull_planes(occ_space *sp, const rad_vec3 *all, int np, rad_vec3 pn, int nq,
                       rad_vec3 qn, double tol)
{
    const rad_vec3 *p = all, *q = all + np;
    int nh = 2;
    if (grow_v3(&sp->hn, &sp->caphn, 2) ||
        grow_v3(&sp->ha, &sp->capha, 2))
        return -1;
    sp->hn[0] = v3_scale(pn, -1.0);
    sp->ha[0] = p[0];
    sp->hn[1] = v3_scale(qn, -1.0);
    sp->ha[1] = q[0];
    if (side_planes(sp, p, np, q, nq, all, np + nq, tol, &nh) ||
        side_planes(sp, q, nq, p, np, all, np + nq, tol, &nh))
        return -1;
    return nh;
}

/* Is blocker b (nb vertices, unit normal bn) clear of the shaft with
 * points `all` and face planes sp->hn/ha (nh of them)? */
static int clear_of_shaft(const occ_space *sp, int nh, const rad_vec3 *all, int nall,
                          const rad_vec3 *b, int nb, rad_vec3 bn, double tol)
{
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < nall; k++) {
        double s = v3_dot(bn, v3_sub(all[k], b[0]));
        lo = fmin(lo, s);
        hi = fmax(hi, s);
    }
    if (lo >= -tol || hi <= tol)
        return 1; /* the shaft lies on one side of the blocker's plane */
    for (int h = 0; h < nh; h++) {
        int out = 1;
        for (int k = 0; k < nb && out; k++)
            out = v3_dot(sp->hn[h], v3_sub(b[k], sp->ha[h])) >= -tol;
        if (out)
            return 1; /* the blocker lies outside a face of the shaft */
    }
    return 0;
}

static int boxes_meet(rad_vec3 alo, rad_vec3 ahi, rad_vec3 blo, rad_vec3 bhi, double tol)
{
    return alo.x <= bhi.x + tol && blo.x <= ahi.x + tol && alo.y <= bhi.y + tol &&
           blo.y <= ahi.y + tol && alo.z <= bhi.z + tol && blo.z <= ahi.z + tol;
}

/* Clip p and q (unit normals pn, qn) each to the front of the other's plane
 * into sp->elem (polygon 0 from p, 1 from q).  Returns 1 if both keep an
 * area, 0 if not, -1 when memory ran out. */
static int clip_pair(occ_space *sp, const rad_vec3 *p, int np, rad_vec3 pn, const rad_vec3 *q,
                     int nq, rad_vec3 qn, double tol)
{
    ps_clear(&sp->elem);
    int a = clip_into(sp, &sp->elem, p, np, qn, q[0], tol);
    if (a <= 0)
        return a;
    int b = clip_into(sp, &sp->elem, q, nq, pn, p[0], tol);
    return b < 0 ? -1 : b > 0;
}

/* ---- setup: surfaces, tree, candidate blockers per surface pair ------------ */

/* The outline of surface s: a quad's grid corners, or its one element. */
static int surface_outline(const rad_mesh *m, int s, rad_vec3 *out)
{
    int e0 = m->surface_first[s], ne = m->surface_first[s + 1] - e0;
    if (ne == 1) {
        int n = m->elements[e0].nverts;
        for (int k = 0; k < n; k++)
            out[k] = rad_mesh_vertex(m, e0, k);
        return n;
    }
    const int N = m->surface_n[s], M = m->surface_m[s], v0 = m->surface_vfirst[s];
    out[0] = m->vertices[v0];
    out[1] = m->vertices[v0 + N];
    out[2] = m->vertices[v0 + M * (N + 1) + N];
    out[3] = m->vertices[v0 + M * (N + 1)];
    return 4;
}

/* The tolerance for the surfaces a and b and the candidates of their pair. */
static double pair_snap(const rad_occ *o, int a, int b, const int *cand, int ncand)
{
    double t = o->snap + o->stwist[a] + o->stwist[b], tc = 0;
    for (int k = 0; k < ncand; k++)
        tc = fmax(tc, o->stwist[cand[k]]);
    return t + tc;
}

static rad_status load_surfaces(rad_occ *o, const rad_mesh *m)
{
    const int ns = m->nsurfaces;
    int total = 0;
    for (int s = 0; s < ns; s++) {
        int e0 = m->surface_first[s], ne = m->surface_first[s + 1] - e0;
        total += ne == 1 ? m->elements[e0].nverts : ne > 1 ? 4 : 0;
    }
    o->nsurf = ns;
    o->sv = malloc(sizeof *o->sv * (size_t)(total > 0 ? total : 1));
    o->sfirst = malloc(sizeof *o->sfirst * (size_t)(ns + 1));
    o->snormal = malloc(sizeof *o->snormal * (size_t)(ns > 0 ? ns : 1));
    o->slo = malloc(sizeof *o->slo * (size_t)(ns > 0 ? ns : 1));
    o->shi = malloc(sizeof *o->shi * (size_t)(ns > 0 ? ns : 1));
    o->stwist = malloc(sizeof *o->stwist * (size_t)(ns > 0 ? ns : 1));
    o->esurf = malloc(sizeof *o->esurf * (size_t)m->nelements);
    if (!o->sv || !o->sfirst || !o->snormal || !o->slo || !o->shi || !o->stwist || !o->esurf)
        return RAD_ERR_NOMEM;
    int at = 0;
    for (int s = 0; s < ns; s++) {
        int e0 = m->surface_first[s], ne = m->surface_first[s + 1] - e0;
        o->sfirst[s] = at;
        if (ne > 0) {
            int n = surface_outline(m, s, o->sv + at);
            o->snormal[s] = m->elements[e0].normal;
            v3_bounds(o->sv + at, n, &o->slo[s], &o->shi[s]);
            o->stwist[s] = poly_twist(o->sv + at, n, o->snormal[s]);
            at += n;
        } else {
            o->snormal[s] = o->slo[s] = o->shi[s] = v3(0, 0, 0);
            o->stwist[s] = 0;
        }
    }
    o->sfirst[ns] = at;
    for (int e = 0; e < m->nelements; e++)
        o->esurf[e] = m->elements[e].surface;
    return RAD_OK;
}

/* Append to the candidate list the surfaces that may block surfaces a and
 * b.  Returns the number appended, or -1. */
static int surface_pair_candidates(rad_occ *o, const rad_vis *vis, occ_space *sp, int a, int b,
                                   int *owners, int **cand, int *ncand, int *capcand)
{
    const rad_vec3 *pa = o->sv + o->sfirst[a], *pb = o->sv + o->sfirst[b];
    int na = o->sfirst[a + 1] - o->sfirst[a], nb = o->sfirst[b + 1] - o->sfirst[b];
    if (na < 3 || nb < 3)
        return 0;
    const double snap = o->snap + o->stwist[a] + o->stwist[b];
    int r = clip_pair(sp, pa, na, o->snormal[a], pb, nb, o->snormal[b], snap);
    if (r <= 0)
        return r; /* they see nothing of each other */
    const rad_vec3 *all = sp->elem.v;
    int nca = sp->elem.first[1], nall = sp->elem.nv;
    int nc;
    if (o->mode == RAD_OCC_ALL) {
        nc = 0;
        for (int c = 0; c < o->nsurf; c++)
            owners[nc++] = c;
    } else {
        rad_vec3 lo, hi, pad = v3(snap, snap, snap);
        v3_bounds(all, nall, &lo, &hi);
        nc = rad_vis_box_polygons(vis, v3_sub(lo, pad), v3_add(hi, pad), owners);
        if (nc < 0)
            return -1;
    }
    int nh = o->mode == RAD_OCC_ALL
                 ? 0
                 : hull_planes(sp, all, nca, o->snormal[a], nall - nca, o->snormal[b], snap);
    if (nh < 0)
        return -1;
    int added = 0;
    for (int k = 0; k < nc; k++) {
        int c = owners[k], n = o->sfirst[c + 1] - o->sfirst[c];
        if (c == a || c == b || n < 3)
            continue;
        if (o->mode != RAD_OCC_ALL &&
            clear_of_shaft(sp, nh, all, nall, o->sv + o->sfirst[c], n, o->snormal[c],
                           snap + o->stwist[c]))
            continue;
        if (grow_i(cand, capcand, *ncand + 1))
            return -1;
        (*cand)[(*ncand)++] = c;
        added++;
    }
    return added;
}

static void space_free(occ_space *sp);

static rad_status candidates(rad_occ *o, const rad_vis *vis, double *blockable_pairs)
{
    const int ns = o->nsurf;
    size_t npairs = ns > 1 ? (size_t)ns * (size_t)(ns - 1) / 2 : 0;
    int *owners = malloc(sizeof *owners * (size_t)(ns > 0 ? ns : 1));
    occ_space sp;
    int ncand = 0, capcand = 0;
    rad_status st = RAD_OK;
    memset(&sp, 0, sizeof sp);
    o->cand_off = malloc(sizeof *o->cand_off * (npairs + 1));
    o->cand = NULL;
    if (!owners || !o->cand_off)
        st = RAD_ERR_NOMEM;
    *blockable_pairs = 0;
    for (int a = 0; a < ns && st == RAD_OK; a++)
        for (int b = a + 1; b < ns && st == RAD_OK; b++) {
            size_t p = pair_index(a, b, ns);
            o->cand_off[p] = (size_t)ncand;
            int r = surface_pair_candidates(o, vis, &sp, a, b, owners, &o->cand, &ncand,
                                            &capcand);
            if (r < 0)
                st = RAD_ERR_NOMEM;
            *blockable_pairs += r > 0;
        }
    if (st == RAD_OK)
        o->cand_off[npairs] = (size_t)ncand;
    free(owners);
    space_free(&sp);
    return st;
}

void rad_occ_free(rad_occ *o)
{
    if (!o)
        return;
    free(o->sv);
    free(o->sfirst);
    free(o->snormal);
    free(o->slo);
    free(o->shi);
    free(o->stwist);
    free(o->esurf);
    free(o->cand_off);
    free(o->cand);
    free(o);
}

/* The largest absolute coordinate of the mesh. */
static double scene_magnitude(const rad_mesh *m)
{
    double x = 0;
    for (int k = 0; k < m->nvertices; k++)
        x = fmax(x, v3_maxabs(m->vertices[k]));
    return x;
}

static double scene_size(const rad_mesh *m)
{
    if (m->nvertices < 1)
        return 1.0;
    rad_vec3 lo, hi;
    v3_bounds(m->vertices, m->nvertices, &lo, &hi);
    double L = v3_norm(v3_sub(hi, lo));
    return L > 0 ? L : 1.0;
}

rad_status rad_occ_create(rad_occ **out, const rad_mesh *m, rad_occ_mode mode,
                          rad_accuracy accuracy, rad_occ_stats *stats, rad_error *err)
{
    double t0 = now(), blockable = 0;
    rad_occ_stats st;
    rad_vis *vis = NULL;
    memset(&st, 0, sizeof st);
    *out = NULL;
    if (mode == RAD_OCC_OFF || m->nelements < 2 || m->nsurfaces < 3) {
        if (stats)
            *stats = st;
        return RAD_OK;
    }
    rad_occ *o = calloc(1, sizeof *o);
    if (!o)
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory for the visibility data");
    o->mode = mode;
    o->accuracy = accuracy;
    o->snap = OCC_SNAP * scene_size(m) + OCC_ROUND * DBL_EPSILON * scene_magnitude(m);
    rad_status s = load_surfaces(o, m);
    if (s == RAD_OK)
        s = rad_vis_create(&vis, o->sv, o->sfirst, o->nsurf, err);
    else
        rad_fail(err, s, "out of memory for the visibility data");
    if (s == RAD_OK) {
        st.surfaces = o->nsurf;
        st.triangles = rad_vis_triangles(vis);
        s = candidates(o, vis, &blockable);
        if (s != RAD_OK)
            rad_fail(err, s, "visibility setup failed (out of memory, or CGAL raised an "
                             "exception)");
    }
    rad_vis_free(vis);
    if (s != RAD_OK || blockable == 0) {
        rad_occ_free(o);
        o = NULL;
    }
    st.needed = o != NULL;
    st.seconds = now() - t0;
    if (stats)
        *stats = st;
    *out = o;
    return s;
}

/* ---- per-thread space -------------------------------------------------------- */

static void space_free(occ_space *sp)
{
    ps_free(&sp->loc);
    ps_free(&sp->elem);
    ps_free(&sp->blk);
    ps_free(&sp->blkc);
    ps_free(&sp->cur);
    ps_free(&sp->next);
    free(sp->bid);
    free(sp->bn);
    free(sp->bc);
    free(sp->rem);
    free(sp->tmp);
    free(sp->d);
    free(sp->cone);
    free(sp->conep);
    free(sp->sn);
    free(sp->sa);
    free(sp->sfirst);
    free(sp->empty);
    ps_free(&sp->da);
    ps_free(&sp->db);
    ps_free(&sp->dom);
    free(sp->pcen);
    free(sp->qcen);
    free(sp->prad);
    free(sp->qrad);
    ps_free(&sp->umb);
    free(sp->pj0);
    free(sp->pj1);
    free(sp->hn);
    free(sp->ha);
    free(sp->node);
    memset(sp, 0, sizeof *sp);
}

void rad_occ_work_init(rad_occ_work *w, const rad_occ *occ)
{
    memset(w, 0, sizeof *w);
    w->occ = occ;
}

void rad_occ_work_free(rad_occ_work *w)
{
    if (w->space) {
        space_free(w->space);
        free(w->space);
    }
    w->space = NULL;
}

void rad_occ_stats_add(rad_occ_stats *into, const rad_occ_stats *from)
{
    into->needed |= from->needed;
    into->pairs_tested += from->pairs_tested;
    into->pairs_blockable += from->pairs_blockable;
    into->pairs_blocked += from->pairs_blocked;
    into->pairs_partial += from->pairs_partial;
    into->evaluations += from->evaluations;
    into->max_errest = fmax(into->max_errest, from->max_errest);
    into->seconds += from->seconds;
}

/* ---- the hidden part seen from one point ------------------------------------ */

/* What an evaluation needs: the outer element's normal, the inner element
 * (clipped) and the blockers (clipped to the front of the inner plane). */
typedef struct pair_ctx {
    rad_vec3 nx;                /* outer normal */
    rad_vec3 tn;                /* inner normal */
    const rad_vec3 *t;          /* inner element */
    int nt;
    int nb;                     /* blockers in sp->blkc, sp->bn, sp->bc */
    double snap, sliver;        /* distance and area tolerances */
    int events;                 /* split the domain along every event plane */
} pair_ctx;

/* Cut the polygon in sp->rem (*n vertices) by the planes through pt[k]
 * with inward unit normals nrm[k]: the parts outside some plane go to
 * `out` (slivers below `sliver` dropped); returns 1 when a part inside all
 * planes is left in sp->rem (*n vertices), 0 when not, -1 on memory. */
static int cut_piece(occ_space *sp, const rad_vec3 *nrm, const rad_vec3 *pt, int np, double snap,
                     double sliver, polyset *out, int *n)
{
    for (int k = 0; k < np; k++) {
        double lo, hi;
        if (grow_d(&sp->d, &sp->capd, *n) || grow_v3(&sp->tmp, &sp->captmp, *n + 1))
            return -1;
        poly_distances(sp->rem, *n, nrm[k], pt[k], snap, sp->d, &lo, &hi);
        poly_settle_signs(sp->d, *n, &lo, &hi);
        if (hi <= 0)
            return ps_push(out, sp->rem, *n) ? -1 : 0; /* wholly outside */
        if (lo >= 0)
            continue; /* wholly inside this plane */
        int m = poly_clip_side(sp->rem, sp->d, *n, -1.0, sp->tmp, *n + 1);
        if (m >= 3 && poly_area(sp->tmp, m) > sliver && ps_push(out, sp->tmp, m))
            return -1;
        m = poly_clip_side(sp->rem, sp->d, *n, 1.0, sp->tmp, *n + 1);
        if (m < 3 || !(poly_area(sp->tmp, m) > sliver))
            return 0;
        rad_vec3 *t = sp->rem;
        int tc = sp->caprem;
        sp->rem = sp->tmp;
        sp->caprem = sp->captmp;
        sp->tmp = t;
        sp->captmp = tc;
        *n = m;
    }
    return 1;
}

/* Copy polygon k of set s into sp->rem; returns its vertex count or -1. */
static int load_rem(occ_space *sp, const polyset *s, int k)
{
    int n = s->first[k + 1] - s->first[k];
    if (grow_v3(&sp->rem, &sp->caprem, n))
        return -1;
    memcpy(sp->rem, s->v + s->first[k], sizeof *sp->rem * (size_t)n);
    return n;
}

/* The cone planes through x and each edge of blocker b, unit normals
 * pointing inside; returns their count (0 when x is on b's plane), -1. */
static int cone_planes(occ_space *sp, const pair_ctx *c, int b, rad_vec3 x)
{
    const rad_vec3 *p = sp->blkc.v + sp->blkc.first[b];
    int n = sp->blkc.first[b + 1] - sp->blkc.first[b];
    if (fabs(v3_dot(sp->bn[b], v3_sub(x, sp->bc[b]))) <= c->snap)
        return 0;
    if (grow_v3(&sp->cone, &sp->capcone, n) || grow_v3(&sp->conep, &sp->capconep, n))
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
    if (!(h < -c->snap) || grow_v3(&sp->pj0, &sp->cappj0, n))
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
        if (grow_d(&sp->d, &sp->capd, m) || grow_v3(&sp->pj1, &sp->cappj1, m + 1))
            return -1;
        poly_distances(sp->pj0, m, v3_scale(nrm, turn / len), q[k], c->snap, sp->d, &lo, &hi);
        poly_settle_signs(sp->d, m, &lo, &hi);
        if (hi <= 0)
            return 0;
        if (lo >= 0)
            continue;
        m = poly_clip_side(sp->pj0, sp->d, m, 1.0, sp->pj1, m + 1);
        rad_vec3 *t = sp->pj0;
        int tc = sp->cappj0;
        sp->pj0 = sp->pj1;
        sp->cappj0 = sp->cappj1;
        sp->pj1 = t;
        sp->cappj1 = tc;
    }
    return m >= 3 ? m : 0;
}

/* The last blocker's share of hidden(x), when its shadow is a polygon:
 * each visible piece q loses q intersected with the shadow.  That is
 * the same set as q cut by the cone planes, but it costs O(nq K) for a
 * K-gon blocker instead of O(K^2): the cuts of cut_piece make the piece a
 * K-gon one plane at a time (issue 20: reference mode slowed as K^4).
 * The visible remainder is not built, since no blocker follows; only
 * whether some is left.  Returns 1 when done (*h increased), 0 when the
 * shadow is no polygon, -1. */
static int hidden_last(occ_space *sp, const pair_ctx *c, int b, rad_vec3 x, double *h)
{
    int n = shadow_polygon(sp, c, b, x);
    if (n <= 0)
        return n;
    if (grow_v3(&sp->tmp, &sp->captmp, n))
        return -1;
    memcpy(sp->tmp, sp->pj0, sizeof *sp->tmp * (size_t)n); /* the whole shadow */
    int visible = 0;
    for (int k = 0; k < sp->cur.np; k++) {
        const rad_vec3 *q = sp->cur.v + sp->cur.first[k];
        int nq = sp->cur.first[k + 1] - sp->cur.first[k];
        if (grow_v3(&sp->pj0, &sp->cappj0, n))
            return -1;
        memcpy(sp->pj0, sp->tmp, sizeof *sp->pj0 * (size_t)n);
        int m = shadow_in_piece(sp, c, q, nq, n);
        if (m < 0)
            return -1;
        double aq = poly_area(q, nq), am = m ? poly_area(sp->pj0, m) : 0;
        if (am > c->sliver) {
            *h += fabs(ff_point_polygon(x, c->nx, sp->pj0, m));
            sp->any_hidden = 1;
        } else {
            am = 0;
        }
        visible |= aq - am > c->sliver;
    }
    if (visible)
        sp->any_visible = 1;
    ps_clear(&sp->cur); /* the caller's test for anything visible is done */
    return 1;
}

/* hidden(x): the form factor from x to the part of the inner element that
 * the blockers hide.  Sets sp->any_hidden / any_visible. */
static int hidden_at(occ_space *sp, const pair_ctx *c, rad_vec3 x, double *out)
{
    double h = 0;
    ps_clear(&sp->cur);
    if (ps_push(&sp->cur, c->t, c->nt))
        return -1;
    sp->evals++;
    for (int b = 0; b < c->nb && sp->cur.np > 0; b++) {
        if (b == c->nb - 1 &&
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
        ps_clear(&sp->next);
        for (int k = 0; k < sp->cur.np; k++) {
            int n = load_rem(sp, &sp->cur, k);
            int r = n < 0 ? -1
                          : cut_piece(sp, sp->cone, sp->conep, ncone, c->snap, c->sliver,
                                      &sp->next, &n);
            if (r < 0)
                return -1;
            if (r > 0) {
                h += ff_point_polygon(x, c->nx, sp->rem, n);
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

/* ---- where anything can be hidden: the support of hidden(x) ------------------ */

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
 * from y_k).  When T reaches P's plane the umbra has no interior.  The
 * pieces of the domain are cut along the umbras too: hidden(x) then has
 * no kink across a piece there, a thin strip that still sees past a
 * blocker's silhouette becomes a piece of its own with its own evaluation
 * points, and a piece inside an umbra is known to be fully hidden. */

/* Append plane (nrm, a) with the region on the side where nrm . (q - a)
 * >= 0 if it separates p (that side) from t (the other side). */
static int add_if_separating(occ_space *sp, rad_vec3 nrm, rad_vec3 a, const rad_vec3 *p, int np,
                             const rad_vec3 *t, int nt, double tol, int *ns)
{
    double plo, phi, tlo, thi;
    if (grow_d(&sp->d, &sp->capd, np > nt ? np : nt))
        return -1;
    poly_distances(p, np, nrm, a, tol, sp->d, &plo, &phi);
    poly_distances(t, nt, nrm, a, tol, sp->d, &tlo, &thi);
    int up = plo >= 0 && thi <= 0, down = phi <= 0 && tlo >= 0;
    if (!(up || down) || (plo == 0 && phi == 0 && tlo == 0 && thi == 0))
        return 0;
    if (grow_v3(&sp->sn, &sp->capsn, *ns + 1) || grow_v3(&sp->sa, &sp->capsa, *ns + 1))
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
    for (int k = 0; k < ne; k++) {
        rad_vec3 a = e[k], ed = v3_sub(e[(k + 1) % ne], a);
        for (int l = 0; l < nf; l++) {
            rad_vec3 w = v3_sub(f[l], a), nrm = v3_cross(ed, w);
            double len = v3_norm(nrm);
            if (!(len > 1e-12 * v3_norm(ed) * v3_norm(w)))
                continue;
            if (add_if_separating(sp, v3_scale(nrm, 1.0 / len), a, p, np, t, nt, tol, ns))
                return -1;
        }
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
    if (grow_v3(&sp->sn, &sp->capsn, *ns + 1) || grow_v3(&sp->sa, &sp->capsa, *ns + 1))
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
    if (grow_i(&sp->sfirst, &sp->capsf, c->nb + 1) || grow_i(&sp->empty, &sp->capem, c->nb))
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
 * sp->db, inside parts to `inside` (or dropped when NULL); then swap. */
static int cut_set(occ_space *sp, const pair_ctx *c, int e, polyset *inside)
{
    int g = sp->sfirst[e], ng = sp->sfirst[e + 1] - g;
    ps_clear(&sp->db);
    for (int k = 0; k < sp->da.np; k++) {
        int n = load_rem(sp, &sp->da, k);
        int r = n < 0 ? -1
                      : cut_piece(sp, sp->sn + g, sp->sa + g, ng, c->snap, c->sliver, &sp->db, &n);
        if (r < 0 || (r > 0 && inside && ps_push(inside, sp->rem, n)))
            return -1;
    }
    polyset t = sp->da;
    sp->da = sp->db;
    sp->db = t;
    return 0;
}

/* Append polygon p (n vertices) to sp->db with its bounding sphere
 * (centre cen, radius rad); 0 or -1. */
static int push_db(occ_space *sp, const rad_vec3 *p, int n, rad_vec3 cen, double rad)
{
    int k = sp->db.np;
    if (grow_v3(&sp->qcen, &sp->capqc, k + 1) || grow_d(&sp->qrad, &sp->capqr, k + 1) ||
        ps_push(&sp->db, p, n))
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

/* The bounding spheres of sp->dom's pieces, for split_dom. */
static int dom_spheres(occ_space *sp)
{
    int np = sp->dom.np;
    if (grow_v3(&sp->pcen, &sp->cappc, np) || grow_d(&sp->prad, &sp->cappr, np))
        return -1;
    for (int k = 0; k < np; k++)
        sphere(sp->dom.v + sp->dom.first[k], sp->dom.first[k + 1] - sp->dom.first[k],
               &sp->pcen[k], &sp->prad[k]);
    return 0;
}

/* Split every piece of sp->dom that the plane through a with unit normal
 * nrm crosses (their spheres in sp->pcen / prad, kept up to date).  A
 * piece whose bounding sphere the plane misses is copied without looking
 * at its vertices: with a K-gon blocker there are O(K) planes and O(K^2)
 * pieces, most of them far from any one plane (issue 20: reference mode
 * slowed as K^4).  Returns 0 or -1. */
static int split_dom(occ_space *sp, const pair_ctx *c, rad_vec3 nrm, rad_vec3 a)
{
    ps_clear(&sp->db);
    for (int k = 0; k < sp->dom.np; k++) {
        const rad_vec3 *p = sp->dom.v + sp->dom.first[k];
        int n = sp->dom.first[k + 1] - sp->dom.first[k];
        double lo, hi;
        if (fabs(v3_dot(nrm, v3_sub(sp->pcen[k], a))) > sp->prad[k] + c->snap) {
            if (push_db(sp, p, n, sp->pcen[k], sp->prad[k]))
                return -1;
            continue;
        }
        if (grow_d(&sp->d, &sp->capd, n) || grow_v3(&sp->tmp, &sp->captmp, n + 1))
            return -1;
        poly_distances(p, n, nrm, a, c->snap, sp->d, &lo, &hi);
        poly_settle_signs(sp->d, n, &lo, &hi);
        if (lo >= 0 || hi <= 0) {
            if (push_db(sp, p, n, sp->pcen[k], sp->prad[k]))
                return -1;
            continue;
        }
        for (int side = -1; side <= 1; side += 2) {
            int m = poly_clip_side(p, sp->d, n, side, sp->tmp, n + 1);
            rad_vec3 cen;
            double rad;
            if (m < 3 || !(poly_area(sp->tmp, m) > c->sliver))
                continue;
            sphere(sp->tmp, m, &cen, &rad);
            if (push_db(sp, sp->tmp, m, cen, rad))
                return -1;
        }
    }
    polyset t = sp->dom;
    sp->dom = sp->db;
    sp->db = t;
    rad_vec3 *tc = sp->pcen;
    sp->pcen = sp->qcen;
    sp->qcen = tc;
    double *tr = sp->prad;
    sp->prad = sp->qrad;
    sp->qrad = tr;
    int ti = sp->cappc;
    sp->cappc = sp->capqc;
    sp->capqc = ti;
    ti = sp->cappr;
    sp->cappr = sp->capqr;
    sp->capqr = ti;
    return 0;
}

/* Split sp->dom along the planes through an edge of e and a vertex of f. */
static int split_edge_vertex(occ_space *sp, const pair_ctx *c, const rad_vec3 *e, int ne,
                             const rad_vec3 *f, int nf)
{
    for (int k = 0; k < ne; k++) {
        rad_vec3 a = e[k], ed = v3_sub(e[(k + 1) % ne], a);
        for (int l = 0; l < nf && sp->dom.np > 0; l++) {
            rad_vec3 w = v3_sub(f[l], a), nrm = v3_cross(ed, w);
            double len = v3_norm(nrm);
            if (len > 1e-12 * v3_norm(ed) * v3_norm(w) &&
                split_dom(sp, c, v3_scale(nrm, 1.0 / len), a))
                return -1;
        }
    }
    return 0;
}

/* Reference mode: split the pieces not known to be hidden along every
 * plane where a blocker's edge passes a vertex of the inner element, or a
 * blocker's vertex one of its edges (the first-derivative discontinuities
 * of hidden(x) that one blocker causes; Heckbert, "Discontinuity meshing
 * for radiosity", Eurographics Workshop on Rendering 1992).  Inside the
 * pieces hidden(x) is then smooth but for events that involve two
 * blockers, and the adaptive rule's error estimate can be trusted; a
 * penumbra narrower than the spacing of the points no longer hides
 * between them. */
static int split_events(occ_space *sp, const pair_ctx *c)
{
    if (dom_spheres(sp))
        return -1;
    for (int b = 0; b < c->nb && sp->dom.np > 0; b++) {
        const rad_vec3 *p = sp->blkc.v + sp->blkc.first[b];
        int np = sp->blkc.first[b + 1] - sp->blkc.first[b];
        if (split_edge_vertex(sp, c, p, np, c->t, c->nt) ||
            split_edge_vertex(sp, c, c->t, c->nt, p, np))
            return -1;
    }
    return 0;
}

/* The domain of integration: the outer polygon o cut to the union of the
 * blockers' penumbras, as disjoint convex pieces (W_b minus the earlier
 * W's), then cut along every umbra, the pieces inside one going to
 * sp->umb.  Pieces not known to be hidden end in sp->dom. */
static int support_domain(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no)
{
    ps_clear(&sp->dom);
    ps_clear(&sp->umb);
    if (all_region_planes(sp, c, PENUMBRA))
        return -1;
    for (int b = 0; b < c->nb; b++) {
        ps_clear(&sp->da);
        ps_clear(&sp->db);
        if (grow_v3(&sp->rem, &sp->caprem, no))
            return -1;
        memcpy(sp->rem, o, sizeof *o * (size_t)no);
        int n = no, f = sp->sfirst[b], nf = sp->sfirst[b + 1] - f;
        int r = cut_piece(sp, sp->sn + f, sp->sa + f, nf, c->snap, c->sliver, &sp->db, &n);
        if (r < 0 || (r > 0 && ps_push(&sp->da, sp->rem, n)))
            return -1;
        for (int e = 0; e < b && sp->da.np > 0; e++)
            if (cut_set(sp, c, e, NULL))
                return -1;
        for (int k = 0; k < sp->da.np; k++)
            if (ps_push(&sp->dom, sp->da.v + sp->da.first[k], sp->da.first[k + 1] - sp->da.first[k]))
                return -1;
    }
    if (sp->dom.np == 0)
        return 0;
    if (all_region_planes(sp, c, UMBRA))
        return -1;
    polyset t = sp->da;
    sp->da = sp->dom;
    sp->dom = t;
    for (int b = 0; b < c->nb && sp->da.np > 0; b++)
        if (!sp->empty[b] && cut_set(sp, c, b, &sp->umb))
            return -1;
    t = sp->dom;
    sp->dom = sp->da;
    sp->da = t;
    return c->events ? split_events(sp, c) : 0;
}

/* ---- the adaptive rule --------------------------------------------------------- */

/* The 3-point degree-2 rule on triangle p (Strang & Fix 1973): points at
 * barycentric (2/3, 1/6, 1/6) and its permutations, weights area / 3. */
static int rule3(occ_space *sp, const pair_ctx *c, const rad_vec3 *p, double area, double *q)
{
    double sum = 0;
    for (int k = 0; k < 3; k++) {
        rad_vec3 x = v3_add(v3_scale(p[k], 2.0 / 3.0),
                            v3_scale(v3_add(p[(k + 1) % 3], p[(k + 2) % 3]), 1.0 / 6.0));
        double h;
        if (hidden_at(sp, c, x, &h))
            return -1;
        sum += h;
    }
    *q = area / 3.0 * sum;
    return 0;
}

/* The four midpoint children of triangle p. */
static void children(const rad_vec3 *p, rad_vec3 ch[4][3])
{
    rad_vec3 m01 = v3_lerp(p[0], p[1], 0.5), m12 = v3_lerp(p[1], p[2], 0.5),
             m20 = v3_lerp(p[2], p[0], 0.5);
    rad_vec3 t[4][3] = {{p[0], m01, m20}, {m01, p[1], m12}, {m20, m12, p[2]}, {m12, m20, m01}};
    memcpy(ch, t, sizeof t);
}

/* Fill in a node's children values and error; its q must be set. */
static int node_eval(occ_space *sp, const pair_ctx *c, tri_node *t)
{
    rad_vec3 ch[4][3];
    children(t->p, ch);
    double sum = 0;
    for (int k = 0; k < 4; k++) {
        if (rule3(sp, c, ch[k], 0.25 * t->area, &t->qc[k]))
            return -1;
        sum += t->qc[k];
    }
    t->err = fabs(t->q - sum);
    return 0;
}

/* Replace leaf k by its four children (appended at the end). */
static int node_split(occ_space *sp, const pair_ctx *c, int k, int *nleaf)
{
    if (grow_node(&sp->node, &sp->capnode, *nleaf + 3))
        return -1;
    tri_node parent = sp->node[k];
    rad_vec3 ch[4][3];
    children(parent.p, ch);
    for (int l = 0; l < 4; l++) {
        tri_node *t = l == 0 ? &sp->node[k] : &sp->node[(*nleaf)++];
        memcpy(t->p, ch[l], sizeof t->p);
        t->area = 0.25 * parent.area;
        t->q = parent.qc[l];
        if (node_eval(sp, c, t))
            return -1;
    }
    return 0;
}

static double leaf_value(const tri_node *t)
{
    return t->qc[0] + t->qc[1] + t->qc[2] + t->qc[3];
}

/* Integral of hidden(x) over the pieces of sp->dom and sp->umb: *value and its
 * estimated error *error; refined while the error exceeds tau (when
 * `adaptive`) and fewer than max_leaves triangles are in use. */
static int integrate(occ_space *sp, const pair_ctx *c, int adaptive, double tau, int max_leaves,
                     double *value, double *error)
{
    int nleaf = 0;
    const polyset *sets[2] = {&sp->dom, &sp->umb};
    if (grow_node(&sp->node, &sp->capnode, sp->dom.nv + sp->umb.nv))
        return -1;
    for (int set = 0; set < 2; set++)
        for (int k = 0; k < sets[set]->np; k++) {
            const rad_vec3 *o = sets[set]->v + sets[set]->first[k];
            int no = sets[set]->first[k + 1] - sets[set]->first[k];
            for (int l = 1; l + 1 < no; l++) {
                tri_node *t = &sp->node[nleaf];
                t->p[0] = o[0];
                t->p[1] = o[l];
                t->p[2] = o[l + 1];
                t->area = 0.5 * v3_norm(v3_cross(v3_sub(o[l], o[0]), v3_sub(o[l + 1], o[0])));
                if (!(t->area > 0))
                    continue;
                if (rule3(sp, c, t->p, t->area, &t->q) || node_eval(sp, c, t))
                    return -1;
                nleaf++;
            }
        }
    double err = 0;
    for (int k = 0; k < nleaf; k++)
        err += sp->node[k].err;
    while (adaptive && sp->any_hidden && sp->any_visible && err > tau &&
           nleaf + 3 <= max_leaves) {
        int worst = 0;
        for (int k = 1; k < nleaf; k++)
            if (sp->node[k].err > sp->node[worst].err)
                worst = k;
        if (node_split(sp, c, worst, &nleaf))
            return -1;
        err = 0;
        for (int k = 0; k < nleaf; k++)
            err += sp->node[k].err;
    }
    double v = 0;
    for (int k = 0; k < nleaf; k++)
        v += leaf_value(&sp->node[k]);
    *value = v;
    *error = err;
    return 0;
}

/* ---- one pair ------------------------------------------------------------------ */

/* Collect the blockers of the pair: the surface pair's candidates that the
 * element shaft does not clear.  Returns their count, or -1. */
static int pair_blockers(const rad_occ *o, occ_space *sp, int sa, int sb, const rad_ff_poly *pi,
                         const rad_ff_poly *pj, rad_vec3 origin)
{
    int a = sa < sb ? sa : sb, b = sa < sb ? sb : sa;
    size_t p = pair_index(a, b, o->nsurf);
    const int *cand = o->cand + o->cand_off[p];
    int ncand = (int)(o->cand_off[p + 1] - o->cand_off[p]);
    const rad_vec3 *all = sp->elem.v;
    int ni = sp->elem.first[1], nall = sp->elem.nv;
    int nh = 0;
    if (o->mode != RAD_OCC_ALL) {
        nh = hull_planes(sp, all, ni, pi->normal, nall - ni, pj->normal, sp->snap);
        if (nh < 0)
            return -1;
    }
    rad_vec3 lo, hi;
    v3_bounds(all, nall, &lo, &hi);
    lo = v3_add(lo, origin); /* the boxes are in scene coordinates */
    hi = v3_add(hi, origin);
    ps_clear(&sp->blk);
    int nb = 0;
    for (int k = 0; k < ncand; k++) {
        int c = cand[k], n = o->sfirst[c + 1] - o->sfirst[c];
        if (o->mode != RAD_OCC_ALL && !boxes_meet(lo, hi, o->slo[c], o->shi[c], sp->snap))
            continue;
        if (grow_i(&sp->bid, &sp->capb, nb + 1) ||
            ps_push_shifted(&sp->blk, o->sv + o->sfirst[c], n, origin))
            return -1;
        if (o->mode != RAD_OCC_ALL &&
            clear_of_shaft(sp, nh, all, nall, sp->blk.v + sp->blk.first[nb], n, o->snormal[c],
                           sp->snap)) {
            ps_pop(&sp->blk);
            continue;
        }
        sp->bid[nb++] = c;
    }
    return nb;
}

/* Does blocker b alone hide all of p from all of q?  (Step 2 above.) */
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
 * through tp), dropping those with nothing in front; fill normals and
 * centroids.  Returns the number kept, or -1. */
static int clip_blockers(const rad_occ *o, occ_space *sp, int nb, rad_vec3 tn, rad_vec3 tp)
{
    if (grow_v3(&sp->bn, &sp->capbn, nb) || grow_v3(&sp->bc, &sp->capbc, nb))
        return -1;
    ps_clear(&sp->blkc);
    int kept = 0;
    for (int b = 0; b < nb; b++) {
        int n = sp->blk.first[b + 1] - sp->blk.first[b];
        int m = clip_into(sp, &sp->blkc, sp->blk.v + sp->blk.first[b], n, tn, tp, sp->snap);
        if (m < 0)
            return -1;
        if (m == 0)
            continue;
        sp->bn[kept] = o->snormal[sp->bid[b]];
        sp->bc[kept] = poly_mean(sp->blkc.v + sp->blkc.first[kept], m);
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

/* What integrating in one orientation found. */
typedef struct orient_result {
    double value, error;        /* integral of hidden(x) over the outer element */
    int hidden, visible;        /* some point saw something hidden / visible */
} orient_result;

/* Step 3 with element i (outer_i) or j as the outer element. */
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
    int kept = clip_blockers(o, sp, nb, pt->normal, ct[0]);
    if (kept < 0)
        return -1;
    pair_ctx c;
    c.nx = po->normal;
    c.tn = pt->normal;
    c.t = ct;
    c.nt = nt;
    c.nb = kept;
    c.snap = sp->snap;
    c.sliver = OCC_SLIVER * poly_area(ct, nt);
    c.events = o->accuracy == RAD_ACCURACY_REFERENCE;
    sp->any_hidden = sp->any_visible = 0;
    if (support_domain(sp, &c, co, no))
        return -1;
    if (sp->dom.np == 0 && sp->umb.np == 0)
        return 0; /* no point of the outer element sees anything hidden */
    double dom_area = 0;
    for (int k = 0; k < sp->dom.np; k++)
        dom_area += poly_area(sp->dom.v + sp->dom.first[k], sp->dom.first[k + 1] - sp->dom.first[k]);
    for (int k = 0; k < sp->umb.np; k++)
        dom_area += poly_area(sp->umb.v + sp->umb.first[k], sp->umb.first[k + 1] - sp->umb.first[k]);
    if (dom_area < (1 - 1e-9) * poly_area(co, no))
        sp->any_visible = 1; /* points outside the domain see all of the inner one */
    else if (sp->dom.np == 0) {
        res->hidden = 1; /* every point is in some blocker's umbra */
        res->value = s / (2 * RAD_PI);
        return 0;
    }
    const int adaptive = o->accuracy != RAD_ACCURACY_CLASSIC;
    const int leaves =
        o->accuracy == RAD_ACCURACY_REFERENCE ? OCC_LEAVES_REFERENCE : OCC_LEAVES_DEFAULT;
    if (integrate(sp, &c, adaptive, rel * s / (2 * RAD_PI), leaves, &res->value, &res->error))
        return -1;
    res->hidden = sp->any_hidden;
    res->visible = sp->any_visible;
    if (res->hidden && !res->visible)
        res->value = s / (2 * RAD_PI);
    return 0;
}

/* Steps 2 and 3 for a pair with nb blockers in sp->blk: the new S. */
static int occluded_sum(const rad_occ *o, occ_space *sp, rad_occ_stats *st, int nb,
                        const rad_ff_poly *pi, const rad_ff_poly *pj, double s, double *snew,
                        double *errest)
{
    const rad_vec3 *ci = sp->elem.v, *cj = sp->elem.v + sp->elem.first[1];
    int ni = sp->elem.first[1], nj = sp->elem.nv - ni;
    *snew = s;
    for (int b = 0; b < nb; b++) {
        const rad_vec3 *v = sp->blk.v + sp->blk.first[b];
        int n = sp->blk.first[b + 1] - sp->blk.first[b];
        if (hides_all(ci, ni, cj, nj, v, n, o->snormal[sp->bid[b]], sp->snap)) {
            st->pairs_blocked++;
            *snew = 0;
            return 0;
        }
    }
    /* outer: the element that looks smaller from the nearest blocker */
    int outer_i = apparent_size(o, sp, nb, pi) <= apparent_size(o, sp, nb, pj);
    const double rel =
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
    double v = s - 2 * RAD_PI * r.value;
    *snew = v < 0 ? 0 : v > s ? s : v;
    if (errest)
        *errest += 2 * RAD_PI * r.error;
    st->max_errest = fmax(st->max_errest, r.error / fmin(pi->area, pj->area));
    return 0;
}

/* The pair in its own frame: vertices and centroids less `origin` (the
 * centroid of i), into sp->loc and *li, *lj (the rest as in pi, pj).  The
 * points the cuts construct (v3_lerp) are then rounded relative to the
 * pair's size, not to the scene's coordinates: a pair 1e-5 across at 3e5
 * from the origin keeps ten digits instead of five. */
static int local_frame(occ_space *sp, const rad_ff_poly *pi, const rad_ff_poly *pj,
                       rad_vec3 origin, rad_ff_poly *li, rad_ff_poly *lj)
{
    ps_clear(&sp->loc);
    if (ps_push_shifted(&sp->loc, pi->v, pi->n, origin) ||
        ps_push_shifted(&sp->loc, pj->v, pj->n, origin))
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

int rad_occ_pair(rad_occ_work *w, const rad_ff_poly *polys, int i, int j, double *s,
                 double *errest)
{
    const rad_occ *o = w->occ;
    if (!o || !(*s > 0))
        return 0;
    int sa = o->esurf[i], sb = o->esurf[j];
    w->stats.pairs_tested++;
    if (sa == sb)
        return 0;
    int a = sa < sb ? sa : sb, b = sa < sb ? sb : sa;
    size_t p = pair_index(a, b, o->nsurf);
    if (o->cand_off[p + 1] == o->cand_off[p])
        return 0;
    double t0 = now();
    if (!w->space && !(w->space = calloc(1, sizeof(occ_space))))
        return -1;
    occ_space *sp = w->space;
    rad_ff_poly li, lj;
    rad_vec3 origin = polys[i].centroid;
    if (local_frame(sp, &polys[i], &polys[j], origin, &li, &lj))
        return -1;
    const rad_ff_poly *pi = &li, *pj = &lj;
    sp->snap = pair_snap(o, sa, sb, o->cand + o->cand_off[p],
                         (int)(o->cand_off[p + 1] - o->cand_off[p]));
    int r = clip_pair(sp, pi->v, pi->n, pi->normal, pj->v, pj->n, pj->normal, sp->snap);
    int nb = r > 0 ? pair_blockers(o, sp, sa, sb, pi, pj, origin) : r;
    double snew = *s;
    if (nb > 0) {
        w->stats.pairs_blockable++;
        if (occluded_sum(o, sp, &w->stats, nb, pi, pj, *s, &snew, errest))
            nb = -1;
    }
    *s = snew;
    w->stats.seconds += now() - t0;
    return nb < 0 ? -1 : 0;
}
