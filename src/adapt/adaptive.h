/* adaptive.h -- progressive refinement with adaptive subdivision (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The pipeline's `--adaptive`: see adaptive.c for the method.
 */
#ifndef RAD_ADAPTIVE_H
#define RAD_ADAPTIVE_H

#include "adapt/adaptnodes.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"

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
 * radi_solve_matrix_free fills them, with the energy balance of the final
 * patch-element system (adaptive.c).  On failure out is empty. */
rad_status radi_solve_adaptive(const rad_mesh *m, const rad_ff_options *ff,
                              const rad_solve_options *opt, rad_adapt_out *out,
                              rad_solve_report *rep, rad_ff_stats *ffst, rad_error *err);
void radi_adapt_out_free(rad_adapt_out *out);

/* The state of an adaptive solve as a watcher sees it, at step 0 (B = E,
 * the starting leaves) and after each shot and its subdivision: every node
 * a run may make (adaptnodes.h; the same numbering in every run over the
 * same starting mesh and depth), which are leaves now, B of every node
 * (nodes x RAD_BANDS, column-major; meaningful on leaves), the unshot
 * power sum_P A_P |dB_P| per band, and whether the solve's convergence
 * test holds here (it then ends after this call).  Valid during the call
 * only. */
typedef struct rad_adapt_view {
    const rad_adapt_nodes *nodes;
    const unsigned char *leaf;
    const double *B;
    int step;
    double unshot[RAD_BANDS];
    int converged;
} rad_adapt_view;

/* Called with each step's view; return non-zero to end the solve there
 * (RAD_OK: the watcher keeps its own reason). */
typedef int (*rad_adapt_watch_fn)(void *user, const rad_adapt_view *view);

/* radi_solve_adaptive with a watcher (may be NULL) called at every step,
 * the way `progress` follows the non-adaptive solver step by step.  With
 * out NULL nothing is built at the end (no leaf mesh, no energy balance):
 * the watcher has seen what it wanted. */
rad_status radi_solve_adaptive_watch(const rad_mesh *m, const rad_ff_options *ff,
                                    const rad_solve_options *opt, rad_adapt_watch_fn watch,
                                    void *watch_user, rad_adapt_out *out,
                                    rad_solve_report *rep, rad_ff_stats *ffst, rad_error *err);

#endif /* RAD_ADAPTIVE_H */
