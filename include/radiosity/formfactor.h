/* radiosity/formfactor.h -- form factors of element pairs and polygons, and closed forms.
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 */
#ifndef RADIOSITY_FORMFACTOR_H
#define RADIOSITY_FORMFACTOR_H

#include "radiosity/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- form factors ------------------------------------------------------ */

typedef enum rad_accuracy {
    RAD_ACCURACY_CLASSIC = 0,   /* Goral et al. 1984: K Gauss points per edge,
                                   closed form for colinear edges, nothing else */
    RAD_ACCURACY_DEFAULT,       /* the classic rule, made safe where it fails */
    RAD_ACCURACY_REFERENCE      /* error-controlled, relative error <= 1e-9 */
} rad_accuracy;

/* Called now and then during long computations; `done` of `total` units.
 * Return non-zero to ask the computation to stop (it then returns
 * RAD_ERR_INVALID with the message "interrupted"). */
typedef int (*rad_progress_fn)(void *user, const char *stage, double done, double total);

/* How the form factors are computed. */
typedef enum rad_ff_method {
    RAD_FF_CONTOUR = 0,         /* the contour integral, element to element
                                   (Goral et al. 1984, eq. 13; the default) */
    RAD_FF_HEMICUBE             /* the hemicube at each element's centre
                                   (Cohen & Greenberg 1985): row i of F from
                                   i's centre, visibility by a z-buffer */
} rad_ff_method;

typedef struct rad_ff_options {
    int quadrature;             /* Gauss points per edge, 1..RAD_GAUSS_MAX (3) */
    rad_accuracy accuracy;
    int threads;                /* 0: OpenMP default */
    rad_progress_fn progress;   /* may be NULL */
    void *progress_user;
    rad_ff_method method;       /* contour (default) or hemicube */
    int resolution;             /* hemicube: pixels along the top face, even,
                                   2..RAD_HEMICUBE_MAX (RAD_HEMICUBE_DEFAULT) */
} rad_ff_options;

#define RAD_HEMICUBE_DEFAULT 64
#define RAD_HEMICUBE_MAX 4096
/* "contour", "hemicube", or NULL for a value out of range. */
RAD_API const char *rad_ff_method_name(int method);

#define RAD_GAUSS_MAX 20
/* A row of F may exceed 1 by this much before the fill calls it wrong:
 * the default mode's promise, summed over a row (sum_j 1e-6 F_ij <= 1e-6). */
#define RAD_ROW_SUM_SLACK 1e-6

RAD_API void rad_ff_options_init(rad_ff_options *opt);
/* An accuracy mode's name ("classic", "default", "reference"), or NULL. */
RAD_API const char *rad_accuracy_name(int accuracy);

/* Form factor from polygon a (na vertices, area computed) to polygon b, both
 * planar and convex, counter-clockwise about their fronts.  If errest is not
 * NULL it receives an estimate of the absolute error of the result.  Always
 * the contour integral (opt->method is not read: the hemicube gives rows). */
RAD_API double rad_ff_polygons(const rad_vec3 *a, int na, const rad_vec3 *b, int nb,
                       const rad_ff_options *opt, double *errest);

/* What a fill of the form-factor matrix found. */
typedef struct rad_ff_stats {
    double pairs;               /* unordered pairs of distinct elements */
    double integrated;          /* pairs that needed a contour integral */
    long negative;              /* entries below 0 (only possible in classic) */
    long above_one;             /* entries above 1 (only possible in classic) */
    double min_value, max_value;
    double max_errest;          /* largest estimated absolute error */
    double max_relerr;          /* largest estimated relative error (of a
                                   partly hidden entry: relative to the
                                   entry, or to 1e-4 of its unoccluded value
                                   when larger; radiosity-files(5)) */
    double max_row_error;       /* largest row sum of the estimated absolute
                                   errors, max_i sum_j |dF_ij| (a bound on
                                   ||dF||_inf; NaN in classic) */
    double promise;             /* the mode's promise on each entry's relative
                                   error: 1e-6 default, 1e-9 reference, NaN classic */
    long promise_unmet;         /* entries whose own error estimate exceeds
                                   promise x |F_ij| (ordered pairs; |F_ij|
                                   as in max_relerr) */
    long rows_above_one;        /* rows with sum_j F_ij > 1 + RAD_ROW_SUM_SLACK:
                                   impossible (energy from nowhere) */
    int vis_needed;             /* 0: nothing can be blocked, no visibility work */
    double vis_pairs_tested, vis_pairs_blockable, vis_pairs_blocked, vis_pairs_partial;
    double vis_seconds;         /* visibility setup + thread time */
    double clamped_to_one;      /* pairs whose value exceeded 1 one way by no more
                                   than its error bound, set to 1 */
    double vis_candidates;      /* candidate blockers summed over the blockable
                                   pairs (what the shaft test and the culls of
                                   coplanar patches, solids and closed meshes
                                   left each) */
    double vis_evaluations;     /* points at which the hidden part was computed
                                   (the integrand of the partly hidden pairs) */
} rad_ff_stats;

/* All form factors of a mesh: F is n x n column-major, F[i + j*n] = F_ij,
 * F_ii = 0.  Each unordered pair is computed once; the other entry follows
 * by reciprocity A_i F_ij = A_j F_ji.  errest (n x n, may be NULL) receives
 * the estimated absolute error of each entry; stats (may be NULL) what the
 * fill found.  With opt->method RAD_FF_HEMICUBE each row i is a hemicube
 * on element i's centre instead (no reciprocity; errest NaN). */
RAD_API rad_status rad_ff_matrix(const rad_mesh *mesh, const rad_ff_options *opt, double *F,
                         double *errest, rad_ff_stats *stats, rad_error *err);

/* Gauss-Legendre nodes on [-1, 1] and weights for k = 1..RAD_GAUSS_MAX
 * points (Abramowitz & Stegun 1964, 25.4.29 and table 25.4). */
RAD_API const double *rad_gauss_nodes(int k);
RAD_API const double *rad_gauss_weights(int k);

/* I = integral over s in [a1, a2], t in [b1, b2] of ln sqrt((s-t)^2 + d^2):
 * two parallel segments on lines a distance d >= 0 apart, parameterised by
 * the same unit direction (d = 0: colinear). */
RAD_API double rad_ln_parallel(double a1, double a2, double b1, double b2, double d);

/* ---- closed forms ------------------------------------------------------- */

/* Differential area to a coaxial parallel disk of radius r at distance h. */
RAD_API double rad_analytic_point_disk(double r, double h);
/* Disk of radius r1 to a coaxial parallel disk of radius r2, h apart. */
RAD_API double rad_analytic_disk_disk(double r1, double r2, double h);
/* Directly opposed parallel a x b rectangles, c apart. */
RAD_API double rad_analytic_parallel_rectangles(double a, double b, double c);
/* From the l x w rectangle to the l x h rectangle sharing its edge of
 * length l at a right angle. */
RAD_API double rad_analytic_perpendicular_rectangles(double l, double w, double h);

#ifdef __cplusplus
}
#endif

#endif /* RADIOSITY_FORMFACTOR_H */
