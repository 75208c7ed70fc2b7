/* animerror.c -- the error measure of George, Sillion & Greenberg 1990, eq. 7.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Eq. 7 compares an image's patches with the converged solution through
 * luminance, weighted by area and normalised by the reference:
 *     e = sum_i A_i |Y_i - Yref_i| / sum_i A_i Yref_i,
 * Y the luminance of linear RGB (ITU-R BT.709: 0.2126 R + 0.7152 G +
 * 0.0722 B).  Most of a scene does not change when one object moves, so
 * the paper also looks at the patches the change alters most: the mask
 * of rad_anim_most_changed (the top fraction by A |Y - Yprev|, Yprev the
 * converged previous frame); over them the error is normalised by the
 * change itself, sum A |Yref - Yprev| (rad_anim_error_changed): the
 * patches a change alters most are often those it shadows, whose Yref is
 * near 0, where a normalisation by Yref would blow up.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "radiosity/mesh.h"
#include "radiosity/animate.h"
#include "radiosity/animate.h"

static double luminance(const double *B, size_t n, size_t i)
{
    return 0.2126 * B[i] + 0.7152 * B[i + n] + 0.0722 * B[i + 2 * n]; /* BT.709 */
}

/* sum A |Y - Yref| over sum A w, the weight w = |Yref| (Bprev NULL: George
 * et al. 1990, eq. 7) or |Yref - Yprev| (the error relative to the change). */
static double weighted_error(const rad_mesh *m, const unsigned char *mask, const double *B,
                             const double *Bref, const double *Bprev)
{
    const size_t n = (size_t)m->nelements;
    double num = 0, den = 0;
    for (size_t i = 0; i < n; i++) {
        if (mask && !mask[i])
            continue;
        const double a = m->elements[i].area, yr = luminance(Bref, n, i);
        num += a * fabs(luminance(B, n, i) - yr); /* George et al. 1990, eq. 7 */
        den += a * fabs(Bprev ? yr - luminance(Bprev, n, i) : yr);
    }
    return den > 0 ? num / den : num > 0 ? HUGE_VAL : 0;
}

double rad_anim_error(const rad_mesh *m, const unsigned char *mask, const double *B,
                      const double *Bref)
{
    return weighted_error(m, mask, B, Bref, NULL);
}

double rad_anim_error_changed(const rad_mesh *m, const unsigned char *mask, const double *B,
                              const double *Bref, const double *Bprev)
{
    return weighted_error(m, mask, B, Bref, Bprev);
}

typedef struct ranked {
    double d;
    size_t i;
} ranked;

static int by_d_desc(const void *x, const void *y)
{
    const double a = ((const ranked *)x)->d, b = ((const ranked *)y)->d;
    return (a < b) - (a > b);
}

void rad_anim_most_changed(const rad_mesh *m, const unsigned char *present, const double *B,
                           const double *Bprev, double fraction, unsigned char *mask)
{
    const size_t n = (size_t)m->nelements;
    ranked *r = malloc(sizeof *r * (n + 1));
    size_t cnt = 0;
    for (size_t i = 0; i < n; i++) {
        mask[i] = 0;
        if (r && (!present || present[i]))
            r[cnt++] = (ranked){m->elements[i].area *
                                    fabs(luminance(B, n, i) - luminance(Bprev, n, i)),
                                i};
    }
    if (!r)
        return;
    qsort(r, cnt, sizeof *r, by_d_desc);
    size_t k = (size_t)(fraction * (double)cnt);
    k = k < 1 ? 1 : k;
    for (size_t q = 0; q < k && q < cnt; q++)
        mask[r[q].i] = 1;
    free(r);
}
