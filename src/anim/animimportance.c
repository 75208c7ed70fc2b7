/* animimportance.c -- the paper's estimate of a shooter's importance.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * George, Sillion & Greenberg 1990, section 4 ("Ordering"): patches
 * shoot their redistribution in order of decreasing importance, the
 * energy they send toward the changed object, estimated from sample
 * points on it and summed; emitters on the object shoot first.  The
 * paper estimates because it has no dF before a patch shoots; here dF is
 * known (animpairs.c) and the default order uses the exact pending power
 * (animshoot.c); `--importance paper` uses this estimate instead.
 *
 * Samples: the centroids (with normal and area) of the elements of the
 * objects the frame changed, where they were before the frame (if they
 * were present) and where they are now (if they are): the removal and
 * the addition of the change log (animlog.c).
 *
 * Estimate for a shooter j (not on a changed object), in the units of the
 * exact power (area x radiosity summed over the bands):
 *     I_j = A_j sum_b |S_j,b| sum_p cos t_j cos t_p A_p / (pi r^2 + A_p),
 * S_j = B_j - dB_j what j has shot so far (the T_j its redistribution
 * carries), the sum over samples p with both cosines positive (p faces
 * j, j faces p): the form factor from j's centroid to a disk of the
 * sample's area facing it (Wallace, Elmquist & Haines, "A Ray Tracing
 * Algorithm for Progressive Radiosity", SIGGRAPH 1989, the disk
 * approximation), without visibility, as the paper's estimate.  A shooter on a changed object sends all it shoots
 * along changed form factors: I_j = A_j sum_b |S_j,b|; an emitter there
 * shoots first (I_j = infinity).
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "anim/animint.h"
#include "util/util.h"

/* The estimated power j sends toward the samples (the header's I_j). */
static double toward_samples(const rad_element *ej, const rad_anim_sample *s, int ns)
{
    double sum = 0;
    for (int p = 0; p < ns; p++) {
        const rad_vec3 d = v3_sub(s[p].centroid, ej->centroid);
        const double r2 = v3_dot(d, d);
        if (!(r2 > 0))
            continue;
        const double r = sqrt(r2);
        const double cj = v3_dot(ej->normal, d) / r, cp = -v3_dot(s[p].normal, d) / r;
        if (cj > 0 && cp > 0) /* Wallace et al. 1989, the disk approximation */
            sum += cj * cp * s[p].area / (M_PI * r2 + s[p].area);
    }
    return sum;
}

void radi_anim_importance(rad_anim *a, const unsigned char *dirty, const rad_anim_sample *s,
                         int ns)
{
    const size_t n = (size_t)a->n;
    for (int j = 0; j < a->n; j++) {
        const rad_element *ej = &a->mesh.elements[j];
        double shot = 0, emits = 0;
        for (int b = 0; b < RAD_BANDS; b++) {
            shot += fabs(a->B[j + b * n] - a->dB[j + b * n]);
            emits += a->E[j + b * n];
        }
        const int o = a->elem_object[j];
        if (o >= 0 && dirty[o])
            a->imp[j] = emits > 0 ? HUGE_VAL : ej->area * shot;
        else
            a->imp[j] = ej->area * shot * toward_samples(ej, s, ns);
    }
}
