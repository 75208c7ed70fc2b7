/* formfactor.h -- the pair kernel, shared by the matrix fill and the tests.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_FORMFACTOR_H
#define RAD_FORMFACTOR_H

#include "radiosity.h"

/* A planar convex polygon ready for the kernel. */
typedef struct rad_ff_poly {
    const rad_vec3 *v;      /* n vertices, counter-clockwise about normal */
    int n;
    rad_vec3 normal;        /* unit front normal */
    rad_vec3 centroid;
    double area;
    double size;            /* bounding-box diagonal */
} rad_ff_poly;

/* Per-thread work space for clipping; grows as needed. */
typedef struct rad_ff_scratch {
    void *buf;
    int cap;
} rad_ff_scratch;

void rad_ff_scratch_init(rad_ff_scratch *w);
void rad_ff_scratch_free(rad_ff_scratch *w);

/* Fill poly from n vertices (normal, centroid, area, size computed). */
void rad_ff_poly_make(rad_ff_poly *poly, const rad_vec3 *v, int n);

/* F from a to b.  *contour receives the symmetric contour sum S (so that
 * F_ba = S / (2 pi A_b)); *errest (may be NULL) an estimate of the
 * absolute error of S.  NaN only when scratch memory runs out. */
double rad_ff_pair(const rad_ff_poly *a, const rad_ff_poly *b, const rad_ff_options *opt,
                   rad_ff_scratch *w, double *contour, double *errest);

#endif /* RAD_FORMFACTOR_H */
