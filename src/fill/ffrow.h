/* ffrow.h -- form factors one shooter at a time, for matrix-free shooting.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Progressive refinement needs, at each shot from element i, the factors
 * F_ji from every receiver j to i (Cohen, Chen, Wallace & Greenberg 1988,
 * section 3, eq. 6: dRad_j = rho_j dB_i F_ij A_i / A_j = rho_j dB_i F_ji by
 * reciprocity).  rad_ffrow computes that column of F on demand, uses O(n)
 * memory besides the mesh and the visibility structure, and forgets it:
 * the solver's memory is O(n) instead of the dense 8 n^2 bytes.
 *
 * Contract: every value is the one the dense fill (ffmatrix.c) stores, bit
 * for bit.  The pair {a, b}, a < b, is integrated in that order by the
 * same kernel (radi_ff_pair) and the same visibility hook (radi_occ_pair),
 * with the same accuracy mode and quadrature, on the same normalized
 * geometry (radi_mesh_normalized); the entry of the dense matrix that the
 * fill derives by reciprocity is derived here by the same expression.  So
 * shooting from rows and shooting from the matrix take the same steps and
 * give the same B.  The exception is opt->method RAD_FF_HEMICUBE: a
 * hemicube gives row i from i's centre (hemicube.h), and the column is
 * F_ji = F_ij A_i / A_j from it, as Cohen et al. 1988 shoot (section
 * 3.1); the dense matrix of hemicubes holds F_ji from j's centre instead,
 * so the two converge to slightly different B.
 *
 * Patches (patchgrid.h): radi_ffrow_patch gives F_jP, from every element j
 * to patch P, integrated directly on the patch's outline, one pair per
 * receiver (n pairs per shot, not |P| n), by the additivity A_P F_Pj =
 * sum_{i in P} A_i F_ij (Goral et al. 1984, section 2) equal to the sum of
 * the element columns F_jP = sum_{i in P} F_ji up to the kernel's error.
 * Receivers on the patch's own surface get 0 (coplanar).
 *
 * Threads: each column of at least 16384 entries is split among
 * opt->threads OpenMP threads (0: the OpenMP default), each with its own
 * clipping scratch and visibility work space, made once in
 * radi_ffrow_create; shorter columns run on the calling thread (ffrow.c).  Units: F is dimensionless.
 */
#ifndef RAD_FFROW_H
#define RAD_FFROW_H

#include "ff/formfactor.h"
#include "occ/occlusion.h"
#include "mesh/mesh.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"

typedef struct rad_ffrow rad_ffrow;

/* Prepare the rows of mesh m (copied and normalized: m may go) with the
 * kernel options opt and visibility mode; P, Q > 0 add the outlines of
 * the P x Q patch grid (radi_patch_grid_build of m: the same numbering) for
 * radi_ffrow_patch; 0, 0: none. */
rad_status radi_ffrow_create(rad_ffrow **row, const rad_mesh *m, const rad_ff_options *opt,
                            rad_occ_mode mode, int P, int Q, rad_error *err);
void radi_ffrow_free(rad_ffrow *row);

/* to[j] = F_ji for every element j (to[i] = 0): column i of the dense F.
 * from (may be NULL) receives row i, from[j] = F_ij.  RAD_ERR_NOMEM when
 * the kernel's scratch runs out, RAD_ERR_INVALID for a value that is not
 * a finite double (as the dense fill). */
rad_status radi_ffrow_column(rad_ffrow *row, int i, double *to, double *from, rad_error *err);

/* to[j] = F_jP for every element j, P a patch of the grid asked for at
 * creation. */
rad_status radi_ffrow_patch(rad_ffrow *row, int p, double *to, rad_error *err);

/* to[t] = F_ji for the k receivers j = js[t] and the element i: a few
 * entries of column i (adaptive.c gathers for new elements this way).
 * The values are radi_ffrow_column's; the statistics count them. */
rad_status radi_ffrow_pairs(rad_ffrow *row, int i, const int *js, int k, double *to,
                           rad_error *err);

/* What the rows computed so far found, in the dense fill's terms: pairs
 * counts the pair integrals done (each repeat counted), extremes and error
 * estimates are over the entries computed, rows_above_one counts distinct
 * rows i (element columns asked for) whose sum_j F_ij exceeds 1 +
 * RAD_ROW_SUM_SLACK.  min_row_sum and max_row_sum (out) span those rows
 * (NaN before any). */
void radi_ffrow_stats(const rad_ffrow *row, rad_ff_stats *st, double *min_row_sum,
                     double *max_row_sum);

/* The threads one column is split among. */
int radi_ffrow_threads(const rad_ffrow *row);

#endif /* RAD_FFROW_H */
