/* radiosity/accuracy.h -- how far a solution is from the truth.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * What `radiosity sweep` measures, as library calls a validator can use:
 * the closed-form solution of a furnace, the closure of a scene, and the
 * area-weighted error of a solution against a finer one.
 */
#ifndef RADIOSITY_ACCURACY_H
#define RADIOSITY_ACCURACY_H

#include "radiosity/solve.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The furnace: in a closed scene whose surfaces all share one material,
 * B = E / (1 - rho) on every element, per band.  Returns 1 and fills B
 * when the scene's materials qualify (one material, rho < 1 in every
 * band), 0 otherwise; closure is rad_scene_closed's to say. */
RAD_API int rad_furnace_radiosity(const rad_scene *scene, double B[RAD_BANDS]);

/* max_i |sum_j F_ij - 1| of an n x n form-factor matrix (column-major):
 * 0 for a closed scene, up to F's error. */
RAD_API double rad_closure_error(const double *F, int n);

/* Is the scene closed?  Its reference-mode form factors with one element
 * per surface (quads unmeshed) are computed and *closed is set when every
 * row sums to 1 within tol; *deviation (may be NULL) receives
 * rad_closure_error of that matrix. */
RAD_API rad_status rad_scene_closed(const rad_scene *scene, double tol, int *closed,
                                    double *deviation, rad_error *err);

/* The error of the piecewise-constant solution Bc on mesh c against the
 * truth: Bt on mesh t, a mesh of the same scene that is equal or finer on
 * every surface, or, when t is NULL, the constant truth[RAD_BANDS].  Fine
 * element (gi, gj) of an N x M surface lies in coarse element
 * (floor((gi + 1/2) n / N), floor((gj + 1/2) m / M)); the error is
 * area-weighted over the truth's elements,
 *     rms = sqrt( sum_f A_f sum_b (B_c(f) - B_f)^2 / (3 sum_f A_f) ),
 * the band-averaged mean square (Cohen et al. 1988, eq. 14, per band and
 * pooled; `radiosity progress` averages the bands' radiosity first and
 * then takes eq. 14: the two agree on grey scenes), and *max is
 * the largest |B_c(f) - B_f| over elements and bands. */
RAD_API void rad_solution_error(const rad_mesh *c, const double *Bc, const rad_mesh *t,
                                const double *Bt, const double truth[RAD_BANDS], double *rms,
                                double *max);

#ifdef __cplusplus
}
#endif

#endif /* RADIOSITY_ACCURACY_H */
