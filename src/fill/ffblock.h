/* ffblock.h -- any set of entries of the form-factor matrix (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The dense fill (ffmatrix.c) computes all of F at once.  A distributed
 * solve (ScaLAPACK's 2-D block-cyclic layout, mpi_solve.c) holds only some
 * rows and columns of F on each process, and must fill exactly those, to
 * the same values: F_ij from one rank and from the dense fill are the same
 * double.  A block is the cross product of a list of global rows and a
 * list of global columns, stored column-major with a leading dimension.
 */
#ifndef RAD_FFBLOCK_H
#define RAD_FFBLOCK_H

#include <stddef.h>

#include "ff/formfactor.h"
#include "occ/occlusion.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"

/* The geometry of one mesh, made ready once (the normalized copy, its
 * polygons, the visibility data) and read by any number of fills. */
typedef struct rad_ff_block rad_ff_block;

/* What a fill found, summed over calls.  Counts are per entry, where the
 * dense fill counts per unordered pair: a block of every entry counts
 * each pair twice (vis.* and clamped too). */
typedef struct rad_ff_tally {
    double entries;             /* off-diagonal entries filled */
    double nonzero, negative, above_one;
    double min_value, max_value;
    double max_errest;          /* largest estimated absolute error of an entry */
    double max_relerr;          /* largest estimated relative error */
    double unmet;               /* entries whose estimate misses the promise */
    double clamped;             /* evaluations clamped by radi_ff_pair */
    double *row_sum;            /* n: sum_j F_ij over the filled j (may be NULL) */
    double *row_error;          /* n: sum of the entries' estimates (may be NULL;
                                   not filled in classic mode) */
    rad_occ_stats vis;
} rad_ff_tally;

/* Clear t (keeping its row arrays, which are zeroed: n entries). */
void radi_ff_tally_clear(rad_ff_tally *t, int n);

rad_status radi_ff_block_open(rad_ff_block **b, const rad_mesh *mesh, const rad_ff_options *opt,
                             rad_error *err);
void radi_ff_block_close(rad_ff_block *b);

/* out[r + c*ld] = F_{rows[r], cols[c]} for r < nr, c < nc (0 on the
 * diagonal), in parallel over columns, each value computed as the dense
 * fill computes it: the pair {i, j}, i < j, gives S once, F_ji = S / (2 pi
 * A_j) and F_ij = F_ji A_j / A_i (ffmatrix.c).  Non-finite values are
 * refused as there.  t (may be NULL) accumulates. */
rad_status radi_ff_block_fill(rad_ff_block *b, const int *rows, int nr, const int *cols, int nc,
                             double *out, size_t ld, rad_ff_tally *t, rad_error *err);

/* For k < np, the pair (pi[k] < pj[k]): fij[k] = F_{pi pj}, fji[k] =
 * F_{pj pi}, each pair integrated once (radi_ff_pairs, ffpairs.h, opens a
 * block for one such call). */
rad_status radi_ff_block_pairs(rad_ff_block *b, const int *pi, const int *pj, size_t np,
                              double *fij, double *fji, rad_error *err);

#endif /* RAD_FFBLOCK_H */
