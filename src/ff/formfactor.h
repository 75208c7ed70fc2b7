/* formfactor.h -- the pair kernel, shared by the matrix fill and the tests.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_FORMFACTOR_H
#define RAD_FORMFACTOR_H

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "ff/gausstab.h"

/* One edge of a polygon, relative to the polygon's centroid. */
typedef struct rad_ff_edge {
    rad_vec3 v0;    /* start, as given (absolute) */
    rad_vec3 p0;    /* start, relative to the centroid */
    rad_vec3 mid;   /* midpoint, relative to the centroid */
    rad_vec3 d;     /* end - start */
    rad_vec3 e;     /* unit direction */
    double len;
} rad_ff_edge;

/* A planar convex polygon ready for the kernel. */
typedef struct rad_ff_poly {
    const rad_vec3 *v;      /* n vertices, counter-clockwise about normal */
    int n;
    rad_ff_edge *edges;     /* its non-degenerate edges (n of room) */
    int nedges;
    double perimeter;       /* sum of the edge lengths */
    double lmax;            /* longest edge */
    double radius;          /* largest distance from the centroid to a vertex */
    rad_vec3 normal;        /* unit front normal */
    rad_vec3 centroid;
    double area;
    double size;            /* bounding-box diagonal */
    double nu;              /* bound on normal's error, radians (ffarea.c, R3) */
    double twist;           /* largest vertex distance from the plane through
                               the centroid (0 for a planar polygon; the scene
                               accepts 1e-6 of a quad's size) */
    rad_vec3 lo, hi;        /* bounding box */
    double snap;            /* its scene's on-plane tolerance beyond the
                               pair's round-off and twists, in its own
                               units (radi_occ_scene_snap; 0 unless set) */
} rad_ff_poly;

/* R3 of ffarea.c: the bound on the error of the unit normal of the
 * Newell vector of polygon p (n vertices). */
double radi_ff_normal_doubt(const rad_vec3 *p, int n);
/* The same for the normal of mesh element e (its surface's). */
double radi_ff_element_doubt(const rad_mesh *m, int e);

/* Per-thread work space for clipping; grows as needed. */
typedef struct rad_ff_scratch {
    void *buf;
    int cap;
    double clamped;         /* pairs whose S was brought down to 2 pi min(A)
                               within its error bound (radi_ff_pair) */
} rad_ff_scratch;

void radi_ff_scratch_init(rad_ff_scratch *w);
void radi_ff_scratch_free(rad_ff_scratch *w);

/* Fill poly from n vertices (normal, centroid, area, size and edges
 * computed); `edges` must have room for n. */
void radi_ff_poly_make(rad_ff_poly *poly, const rad_vec3 *v, int n, rad_ff_edge *edges);
/* Compute the edges of p[0..n) relative to `origin` into e; returns their
 * number (zero-length edges are dropped). */
int radi_ff_edges(const rad_vec3 *p, int n, rad_vec3 origin, rad_ff_edge *e);

/* Each accuracy mode's promise on an entry's relative error: 1e-6
 * default, 1e-9 reference, NaN classic (ffprim.c, as the rest of this
 * group). */
double radi_ff_promise(rad_accuracy a);

/* The element polygons of a (normalized) mesh as the kernel wants them,
 * with contiguous vertices, each given the scene's snap
 * (radi_occ_scene_snap, occlusion.h): every fill (ffmatrix.c, ffblock.c,
 * ffrow.c) must see the same polygons. */
rad_status radi_ff_mesh_polys(const rad_mesh *m, double snap, rad_ff_poly **polys,
                             rad_vec3 **pts, rad_ff_edge **edges);
/* The fill's statistics of a dense F (n x n): pairs, extremes, the
 * classic rule's faults, rows summing above 1 + RAD_ROW_SUM_SLACK; the
 * error fields are left to the caller (also the hemicube's, hcmatrix.c). */
void radi_ff_fill_stats(const double *F, int n, rad_ff_stats *st);

/* F from a to b.  *contour receives the symmetric contour sum S (so that
 * F_ba = S / (2 pi A_b)); *errest (may be NULL) an estimate of the
 * absolute error of S.  NaN only when scratch memory runs out. */
double radi_ff_pair(const rad_ff_poly *a, const rad_ff_poly *b, const rad_ff_options *opt,
                   rad_ff_scratch *w, double *contour, double *errest);
/* The same, aiming at an estimate within `within` of S where that is
 * below the mode's own target; 0 for the mode's target.  (occlusion.c,
 * whose promise is relative to a part of S, asks in reference mode; a
 * default-mode pair still goes on to reference's methods by default's
 * own 1e-6.)  Targets below FF_WITHIN_FLOOR are taken as it: the
 * round-off of S is near it.  The general path's
 * own target (formfactor.c, pair_setup) stops at FF_GENERAL_FLOOR: its
 * round-off bound alone reached 6.6e-14 of S on a pair of the Cornell
 * box, and a target no method can meet sends a pair through every slower
 * one (long double, the area rules, cut into parts). */
#define FF_WITHIN_FLOOR 1e-14
#define FF_GENERAL_FLOOR 1e-13
double radi_ff_pair_within(const rad_ff_poly *a, const rad_ff_poly *b,
                          const rad_ff_options *opt, double within, rad_ff_scratch *w,
                          double *contour, double *errest);

/* Colinear: parallel edges on one line (distance between the lines below
 * 1e-12 of the longer edge), where the Gauss points would hit r = 0. */
int radi_ff_colinear(const rad_ff_edge *p, const rad_ff_edge *q);

/* Gauss product rules on every edge pair of two unclipped polygons,
 * batched for SIMD (ffgauss.c).
 * _nine_point: the contour sum S by the nine-point rule (classic mode),
 * colinear edge pairs in closed form when `touch` says they can exist; NaN
 * without vector extensions (use the plain loop).
 * _apart: 1 when the polygons are apart, filling *g for the derivative
 * bound; sep2 is the squared centroid distance, dmin a lower bound on the
 * distance between the polygons (or 0).  The caller then sets g->pp, the
 * sum over edge pairs of |e_p . e_q| lp lq (perpendicular pairs, skipped
 * exactly, left out), to which the bounds are proportional.
 * _ellipse: adds the Bernstein-ellipse bound (sharper only for pairs less
 * than an edge length apart; costs a square root and a division).
 * _bound: the smaller bound on the K-point rule's error in S (K = 3, 4, 6, 8),
 * round-off included.
 * _sum: the K x K rule's S (K = 3, 4, 6, 8) in the quadratic form, and *pp
 * (if not NULL) the sum above.
 * _tiers: default and reference modes' fast path: the 3 x 3, 4 x 4, 6 x 6 or 8 x 8
 * rule, the first whose bound is within `rel` of its result; 1 with *s and
 * *e (the bound) set, or 0 (use the general path).  gap2 is the squared
 * distance between the bounding boxes, dplane the larger of each
 * polygon's smallest vertex distance from the other's plane, tol their
 * round-off. */
typedef struct rad_ff_gauss_bounds {
    double D, R, h, inv_s2; /* distance bounds, half the longest edge, 1/s^2 */
    double pp;              /* sum of |e_p . e_q| lp lq */
    double q2;              /* (2h / D)^2, the derivative bound */
    double rho2, M;         /* the ellipse bound (rho2 = 0: not computed) */
    double roundoff;        /* per unit pp */
    double px, lr;          /* the pairs left out as perpendicular and the
                               dots' round-off (ffgauss.c), and the bound
                               on |ln(r^2 / s^2)| that they are taken at */
} rad_ff_gauss_bounds;
/* The nodes (weights = 0) or weights (1) of ffgauss.c's K-point rules,
 * K = 3, 4, 6, 8, or NULL. */
const double *radi_ff_gauss_table(int k, int weights);
double radi_ff_nine_point(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, int touch);
int radi_ff_gauss_apart(const rad_ff_poly *a, const rad_ff_poly *b, double sep2,
                       double scale2, double dmin, rad_ff_gauss_bounds *g);
void radi_ff_gauss_ellipse(rad_ff_gauss_bounds *g);
double radi_ff_gauss_bound(const rad_ff_gauss_bounds *g, int k);
double radi_ff_gauss_sum(const rad_ff_poly *a, const rad_ff_poly *b, int k, double scale2,
                        double *pp);
int radi_ff_gauss_tiers(const rad_ff_poly *a, const rad_ff_poly *b, double scale2, double gap2,
                       double dplane, double tol, double rel, double *s, double *e);

/* The contour sum S by closed forms (parallel edge pairs) and adaptive
 * quadrature (skew ones) with absolute tolerance tol, every I_pq
 * integrating ln(r/s) with s^2 = scale2; in long double if `extended`,
 * the edges then taken from their vertices as given (v0) less `origin`,
 * the point their p0 are relative to, so that long double holds them
 * exactly (ffcontour.c).  *errest gets its error estimate. */
double radi_ff_contour(const rad_ff_edge *ea, int na, const rad_ff_edge *eb, int nb,
                      double scale2, double tol, int extended, rad_vec3 origin,
                      double *errest);
/* The closed form of the integral of ln r over two parallel edges. */
double radi_ff_ln_parallel_edges(const rad_ff_edge *p, const rad_ff_edge *q);

/* Area-area quadrature of the symmetric sum S = 2 pi A_a F_ab for polygons
 * a and b (already clipped to face each other), points relative to
 * `origin`: orders rise until two agree to rel_tol.  el: the elements a
 * and b were clipped from (their normals, and those normals' error
 * bounds, are the rules').  Returns 0 with *s and *err set (*err with the
 * round-off), 1 when it did not converge (use the contour), -1 out of
 * memory. */
int radi_ff_area(const rad_vec3 *a, int na, const rad_vec3 *b, int nb, rad_vec3 origin,
                const rad_ff_poly *const el[2], double rel_tol, double *s, double *err);
/* One polygon of an area rule: p (n vertices) cut nu x nv (a
 * quadrilateral), twisted or not (ffarea.c), and the normal of its plane
 * with the bound on that normal's error (radians). */
typedef struct rad_ff_area_part {
    const rad_vec3 *p;
    int n, nu, nv, twisted;
    rad_vec3 nrm;
    double doubt;
} rad_ff_area_part;
/* The area rule of order k over a and b, points relative to origin, in
 * long double (ffarealong.c): *s the sum S, nu the bounds on the normals'
 * error; 0, or -1 out of memory. */
int radi_ff_area_long(const rad_ff_area_part *a, const rad_ff_area_part *b, rad_vec3 origin,
                     int k, double *s, double nu[2]);
/* The same by cutting both polygons into parts until every pair of parts
 * is small against its distance (strips end to end, a strip beside a
 * plate); the same returns.  Polygons that touch are not for it. */
int radi_ff_area_adaptive(const rad_vec3 *a, int na, const rad_vec3 *b, int nb,
                         rad_vec3 origin, const rad_ff_poly *const el[2], double rel_tol,
                         double *s, double *err);

#endif /* RAD_FORMFACTOR_H */
