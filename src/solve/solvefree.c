/* solvefree.c -- progressive refinement without a stored matrix.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen, Chen, Wallace & Greenberg 1988, abstract and section 3: "form
 * factors computed on the fly ... O(n) storage".  Each shot computes the
 * shooter's column F_ji (or a patch's F_jP) with the dense fill's own
 * kernel and visibility (ffrow.h), uses it and forgets it.  Memory: the
 * mesh, its normalized copy and polygons, the visibility structure, and
 * O(n) vectors (B, dB, rho, E, one column): no n x n array anywhere.
 *
 * The run mirrors rad_solve's progressive branch (solve.c) so that the
 * steps and the radiosities are those of the dense path bit for bit: E is
 * scaled by the same power of two before shooting (after it when traced:
 * the trace reports powers in the user's units), and B scaled back.
 *
 * The report: what needs the whole of F is not computed (residual, energy
 * balance, spectral radius: NaN; they would cost a full n^2 pass, the very
 * thing avoided); the row sums of F span the rows of the shooters that
 * shot, and the emitted power is exact.  The convergence test itself,
 * unshot power <= tolerance x emitted power, is the paper's and needs no
 * matrix.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fill/fill.h"
#include "solve/progressive.h"
#include "solve/solvefree.h"
#include "solve/solvers.h"
#include "util/util.h"

void radi_report_init_shooting(rad_solve_report *rep)
{
    memset(rep, 0, sizeof *rep);
    rep->solver = RAD_SOLVER_PROGRESSIVE;
    rep->bounces = -1;
    rep->residual = rep->rcond = rep->ff_error_bound = NAN;
    rep->ferr = rep->berr = rep->spectral_radius = NAN;
    rep->error_bound = rep->contraction = NAN;
    rep->row_sum_min = rep->row_sum_max = NAN;
    for (int b = 0; b < RAD_BANDS; b++)
        rep->absorbed[b] = rep->escaped[b] = rep->balance[b] = NAN;
}

/* B = B' 2^ke, refusing what leaves the double range. */
static rad_status unscale(double *B, size_t n3, int ke, rad_error *err)
{
    for (size_t k = 0; k < n3; k++)
        if (!isfinite(B[k]) || !isfinite(ldexp(B[k], ke)))
            return radi_fail(err, RAD_ERR_INVALID,
                            "the radiosity overflows: it exceeds the largest double (%.3g); "
                            "scale the emission down",
                            DBL_MAX);
    radi_scale_by(B, n3, ke);
    return RAD_OK;
}

rad_status radi_solve_matrix_free(const rad_mesh *m, const rad_ff_options *ff,
                                 const rad_solve_options *opt, double *B,
                                 rad_solve_report *rep, rad_ff_stats *ffst, rad_error *err)
{
    const int n = m->nelements;
    const size_t n3 = (size_t)n * RAD_BANDS;
    rad_solve_report local;
    rad_ffrow *row = NULL;
    if (!rep)
        rep = &local;
    radi_report_init_shooting(rep);
    if (opt->bounces >= 0 || opt->solver != RAD_SOLVER_PROGRESSIVE)
        return radi_fail(err, RAD_ERR_INVALID,
                        "without a stored matrix only progressive refinement can solve");
    double *rho = malloc(sizeof *rho * (n3 ? n3 : 1)), *E = calloc(n3 ? n3 : 1, sizeof *E);
    rad_status st = !rho || !E ? radi_fail(err, RAD_ERR_NOMEM, "out of memory") : RAD_OK;
    for (int i = 0; i < n && st == RAD_OK; i++)
        for (int b = 0; b < RAD_BANDS; b++) {
            rho[(size_t)i + (size_t)b * n] = m->elements[i].reflect[b];
            E[(size_t)i + (size_t)b * n] = m->elements[i].emit[b];
            rep->emitted[b] += m->elements[i].area * m->elements[i].emit[b];
        }
    const int ke = st == RAD_OK ? radi_scale_exponent(E, n3) : 0, late = opt->on_shot != NULL;
    if (st == RAD_OK && !late)
        radi_scale_by(E, n3, -ke);
    if (st == RAD_OK)
        st = radi_ffrow_create(&row, m, ff, RAD_OCC_AUTO, opt->patch_p, opt->patch_q, err);
    if (st == RAD_OK) {
        const rad_shoot_source src = {NULL, row};
        st = radi_progressive_run(m, &src, rho, E, opt, B, rep, err);
        if (ffst)
            radi_ffrow_stats(row, ffst, &rep->row_sum_min, &rep->row_sum_max);
    }
    if (late && (st == RAD_OK || st == RAD_ERR_NOCONV))
        radi_scale_by(B, n3, -ke);
    if (st == RAD_OK)
        st = unscale(B, n3, ke, err);
    else if (st == RAD_ERR_NOCONV)
        radi_scale_by(B, n3, ke);
    radi_ffrow_free(row);
    free(rho);
    free(E);
    return st;
}

double radi_matrix_free_bytes(double n, double nvertices, double npatches)
{
    /* the mesh and its normalized copy (elements, vertices, indices), the
     * kernel's polygons (a rad_ff_poly and four edges each), the solver's
     * vectors (B, dB, rho, E, areas, a column: 16 doubles), the per-element
     * visibility index, and the same again per patch */
    const double per_element = 2.0 * (sizeof(rad_element) + 4 * sizeof(int)) +
                               sizeof(rad_ff_poly) + 4.0 * sizeof(rad_ff_edge) +
                               4.0 * sizeof(rad_vec3) + 16.0 * sizeof(double) + 2 * sizeof(int);
    return n * per_element + 2.0 * nvertices * sizeof(rad_vec3) +
           npatches * (per_element + 4 * sizeof(double)) + 64.0 * 1048576.0;
}
