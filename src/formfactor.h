/* formfactor.h -- the pair kernel, shared by the matrix fill and the tests.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_FORMFACTOR_H
#define RAD_FORMFACTOR_H

#include "radiosity.h"

/* One edge of a polygon, relative to the polygon's centroid. */
typedef struct rad_ff_edge {
    rad_vec3 p0;    /* start, relative to the centroid */
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
    double *gauss3;         /* the nine-point rule's 3 Gauss points per
                               edge, relative to the centroid, or NULL:
                               edge k holds x[4], y[4], z[4] at 12 k (lane
                               3 repeats lane 1), 12 n of room */
    double *gauss4;         /* 4 and 8 Gauss points per edge, as x[K],
                               y[K], z[K] (default mode's fast path), */
    double *gauss8;         /* or NULL */
    double perimeter;       /* sum of the edge lengths */
    double lmax;            /* longest edge */
    double radius;          /* largest distance from the centroid to a vertex */
    rad_vec3 normal;        /* unit front normal */
    rad_vec3 centroid;
    double area;
    double size;            /* bounding-box diagonal */
    rad_vec3 lo, hi;        /* bounding box */
} rad_ff_poly;

/* Per-thread work space for clipping; grows as needed. */
typedef struct rad_ff_scratch {
    void *buf;
    int cap;
} rad_ff_scratch;

void rad_ff_scratch_init(rad_ff_scratch *w);
void rad_ff_scratch_free(rad_ff_scratch *w);

/* Fill poly from n vertices (normal, centroid, area, size and edges
 * computed); `edges` must have room for n. */
void rad_ff_poly_make(rad_ff_poly *poly, const rad_vec3 *v, int n, rad_ff_edge *edges);
/* Store the Gauss points of poly's edges (3, 4 and 8 per edge) in g (room
 * for 48 doubles per vertex) and point poly's gauss3/4/8 at them: the
 * kernel's fast paths need them. */
void rad_ff_poly_gauss(rad_ff_poly *poly, double *g);
/* Compute the edges of p[0..n) relative to `origin` into e; returns their
 * number (zero-length edges are dropped). */
int rad_ff_edges(const rad_vec3 *p, int n, rad_vec3 origin, rad_ff_edge *e);

/* F from a to b.  *contour receives the symmetric contour sum S (so that
 * F_ba = S / (2 pi A_b)); *errest (may be NULL) an estimate of the
 * absolute error of S.  NaN only when scratch memory runs out. */
double rad_ff_pair(const rad_ff_poly *a, const rad_ff_poly *b, const rad_ff_options *opt,
                   rad_ff_scratch *w, double *contour, double *errest);

/* The three Gauss-Legendre points of an edge (nine-point rule). */
void rad_ff_gauss3_points(const rad_ff_edge *e, rad_vec3 out[3]);
/* The same, in the padded layout of rad_ff_poly.gauss3 (12 doubles). */
void rad_ff_gauss3_soa(const rad_ff_edge *e, double out[12]);

/* Default mode's fast path (ffgauss.c): Gauss product rules on all edge
 * pairs of two unclipped polygons, K = 3 (the nine-point rule, formfactor.c),
 * 4 or 8 points per edge, with a priori error bounds.
 * _apart: 1 when the polygons are apart, filling *g for the derivative
 * bound; sep2 is the squared centroid distance, dmin a lower bound on the
 * distance between the polygons (or 0).  The caller then sets g->pp, the
 * sum over edge pairs of |e_p . e_q| lp lq (perpendicular pairs, skipped
 * exactly, left out), to which the bounds are proportional.
 * _ellipse: adds the Bernstein-ellipse bound (sharper only for pairs less
 * than an edge length apart; costs a square root and a division).
 * _bound: the smaller bound on the K-point rule's error in S (K = 3, 4, 8),
 * round-off included.
 * _sum: the rule's S (K = 4, 8), and *pp (if not NULL) the sum above.
 * _soa: an edge's K points as x[K], y[K], z[K]. */
typedef struct rad_ff_gauss_bounds {
    double D, R, h, inv_s2; /* distance bounds, half the longest edge, 1/s^2 */
    double pp;              /* sum of |e_p . e_q| lp lq */
    double q2;              /* (2h / D)^2, the derivative bound */
    double rho2, M;         /* the ellipse bound (rho2 = 0: not computed) */
    double roundoff;        /* per unit pp */
} rad_ff_gauss_bounds;
void rad_ff_gauss_soa(const rad_ff_edge *e, int k, double *out);
int rad_ff_gauss_apart(const rad_ff_poly *a, const rad_ff_poly *b, double sep2,
                       double scale2, double dmin, rad_ff_gauss_bounds *g);
void rad_ff_gauss_ellipse(rad_ff_gauss_bounds *g);
double rad_ff_gauss_bound(const rad_ff_gauss_bounds *g, int k);
double rad_ff_gauss_sum(const rad_ff_poly *a, const rad_ff_poly *b, int k, double scale2,
                        double *pp);
/* The contour sum S by closed forms (parallel edge pairs) and adaptive
 * quadrature (skew ones) with absolute tolerance tol, every I_pq
 * integrating ln(r/s) with s^2 = scale2; in long double if `extended`
 * (ffcontour.c).  *errest gets its error estimate. */
double rad_ff_contour(const rad_ff_edge *ea, int na, const rad_ff_edge *eb, int nb,
                      double scale2, double tol, int extended, double *errest);
/* The closed form of the integral of ln r over two parallel edges. */
double rad_ff_ln_parallel_edges(const rad_ff_edge *p, const rad_ff_edge *q);

/* Area-area quadrature of the symmetric sum S = 2 pi A_a F_ab for polygons
 * a and b (already clipped to face each other), points relative to
 * `origin`: orders rise until two agree to rel_tol.  Returns 0 with *s and
 * *err set, 1 when it did not converge (use the contour), -1 out of memory. */
int rad_ff_area(const rad_vec3 *a, int na, rad_vec3 norm_a, const rad_vec3 *b, int nb,
                rad_vec3 norm_b, rad_vec3 origin, double rel_tol, double *s, double *err);

#endif /* RAD_FORMFACTOR_H */
