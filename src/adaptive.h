/* adaptive.h -- progressive refinement with adaptive subdivision (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The pipeline's `--adaptive`: see adaptive.c for the method.
 */
#ifndef RAD_ADAPTIVE_H
#define RAD_ADAPTIVE_H

#include "radiosity.h"

/* What an adaptive solve hands back: the conforming mesh of its leaves
 * (adaptmesh.h), their radiosity B (nelements x RAD_BANDS), the vertex
 * radiosity Bv (nvertices x RAD_BANDS) and each leaf's level (0: a
 * starting element). */
typedef struct rad_adapt_out {
    rad_mesh mesh;
    double *B, *Bv;
    int *level;
    int splits;                 /* elements split during the run */
} rad_adapt_out;

/* Progressive refinement of the starting mesh m (its elements shoot as
 * fixed patches) with subdivision by opt->subdivide_threshold down to
 * opt->max_depth levels; form factors computed on the fly by ff's kernel
 * with the visibility the scene needs.  rep and ffst (may be NULL) as
 * rad_solve_matrix_free fills them, with the energy balance of the final
 * patch-element system (adaptive.c).  On failure out is empty. */
rad_status rad_solve_adaptive(const rad_mesh *m, const rad_ff_options *ff,
                              const rad_solve_options *opt, rad_adapt_out *out,
                              rad_solve_report *rep, rad_ff_stats *ffst, rad_error *err);
void rad_adapt_out_free(rad_adapt_out *out);

#endif /* RAD_ADAPTIVE_H */
