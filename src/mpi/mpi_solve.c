/* mpi_solve.c -- the solve distributed over MPI processes with ScaLAPACK.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The serial run (pipeline.c) meshes, fills F (n x n) and solves
 * (I - diag(rho) F) B = E for each set of bands that share a reflectance
 * (Goral et al. 1984, eq. 5; solve.c).  Here rank 0 meshes and sends the
 * mesh to every process; each process fills only its own blocks of F in
 * ScaLAPACK's 2-D block-cyclic layout (mpi_layout.h), to the same doubles
 * as the dense fill (ffblock.c), so that no process ever holds all of F.
 * The system of each band set is built beside F in the same layout and
 * solved with ScaLAPACK:
 *
 *   gauss     A = I - diag(rho) F by LU with partial pivoting (pdgetrf,
 *             pdgetrs), the reciprocal condition estimate in the 1-norm
 *             (pdgecon) refused below 1e-10 as in solve.c, and with the
 *             form factors' error dF the bound k / (1 - k) on B's relative
 *             error, k = rho_max ||dF||_inf ||A^-1||_inf (Higham 2002,
 *             thm. 7.2), ||A^-1||_inf from pdgecon in the infinity norm;
 *   cholesky  the symmetric form of cholesky.c, K = D^-1 A D with
 *             D = diag(sqrt(rho_i / A_i)), K_ij = delta_ij - sqrt(rho_i
 *             rho_j) sqrt(A_i / A_j) F_ij, from F's upper triangle only
 *             (pdpotrf, pdpotrs, pdpocon); a band set with some rho = 0,
 *             or a K that is not positive definite, goes to LU and the
 *             report's fallback says why.  (The serial Cholesky first
 *             checks reciprocity and moves rho = 0 elements to the right-
 *             hand side; here both cases take the LU path, which needs
 *             neither.)
 *
 * The right-hand sides live on process column 0; the solution is summed
 * onto every process (n x bands doubles), which the energy balance needs:
 * each process adds F_ij B_j over its blocks into H and the row sums of F,
 * and rank 0 receives the sums (radi_solve_balance, solve.c).  Memory per
 * process: its blocks of F and of the system, 2 x 8 n^2 / P bytes plus
 * the mesh and O(n) vectors.  Every decision (singular, not positive
 * definite, out of memory) is taken from collective results or agreed
 * (mpi_agree), so the processes never part ways.
 */
#include <config.h>

#include <limits.h>
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fill/fill.h"
#include "mpi/mpi_jacobi.h"
#include "mpi/mpi_layout.h"
#include "mpi/mpi_solve.h"
#include "mpi/scalapack.h"
#include "solve/solve.h"
#include "util/util.h"



/* What one job works on, on every process. */
typedef struct work {
    mpi_grid g;
    const rad_mesh *m;
    int n;
    double *F;                  /* this process's blocks of F */
    double *rho, *E, *area;     /* n x RAD_BANDS, n: every process */
    double *B;                  /* n x RAD_BANDS: every process, after the solve */
    double row_error_max;       /* max_i sum_j |dF_ij| (NaN in classic) */
} work;

/* ---- the form factors ---------------------------------------------------- */

/* The tally of every process into rank 0's statistics. */
static void ff_stats_reduce(const work *w, rad_ff_tally *t, rad_ff_stats *st, int classic)
{
    const int n = w->n;
    double s[12] = {t->entries, t->nonzero, t->negative, t->above_one, t->unmet, t->clamped,
                    t->vis.pairs_tested, t->vis.pairs_blockable, t->vis.pairs_blocked,
                    t->vis.pairs_partial, t->vis.candidates, t->vis.evaluations};
    double mx[6] = {t->max_value, -t->min_value, t->max_errest, t->max_relerr,
                    t->vis.seconds, (double)t->vis.needed};
    double S[12], MX[6];
    MPI_Reduce(s, S, 12, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Reduce(mx, MX, 6, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    double *rs = w->g.rank == 0 ? malloc(sizeof *rs * (size_t)(n ? n : 1) * 2) : NULL;
    MPI_Reduce(t->row_sum, rs, n, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Reduce(t->row_error, rs ? rs + n : NULL, n, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    if (w->g.rank != 0)
        return;
    memset(st, 0, sizeof *st);
    /* every unordered pair was integrated twice, once per entry */
    st->pairs = 0.5 * (double)n * (n - 1);
    st->integrated = 0.5 * S[1];
    st->negative = (long)S[2];
    st->above_one = (long)S[3];
    st->promise_unmet = (long)S[4];
    st->clamped_to_one = 0.5 * S[5];
    st->vis_pairs_tested = 0.5 * S[6];
    st->vis_pairs_blockable = 0.5 * S[7];
    st->vis_pairs_blocked = 0.5 * S[8];
    st->vis_pairs_partial = 0.5 * S[9];
    st->vis_candidates = 0.5 * S[10];
    st->vis_evaluations = 0.5 * S[11];
    st->max_value = n > 1 ? MX[0] : 0;
    st->min_value = n > 1 ? -MX[1] : 0;
    st->max_errest = classic ? NAN : MX[2];
    st->max_relerr = classic ? NAN : MX[3];
    st->vis_seconds = MX[4];
    st->vis_needed = MX[5] > 0;
    st->max_row_error = classic ? NAN : 0;
    for (int i = 0; rs && i < n; i++) {
        st->rows_above_one += rs[i] > 1 + RAD_ROW_SUM_SLACK;
        if (!classic)
            st->max_row_error = fmax(st->max_row_error, rs[n + i]);
    }
    free(rs);
}

/* Fill this process's blocks of F; rank 0's stats.  Collective. */
static rad_status fill(work *w, const rad_ff_options *opt, rad_ff_stats *st, rad_error *err)
{
    const int n = w->n;
    rad_ff_block *blk = NULL;
    rad_ff_tally t = {0};
    t.row_sum = calloc((size_t)(n ? n : 1), sizeof *t.row_sum);
    t.row_error = calloc((size_t)(n ? n : 1), sizeof *t.row_error);
    rad_status s = t.row_sum && t.row_error ? RAD_OK
                                            : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (s == RAD_OK)
        s = radi_ff_block_open(&blk, w->m, opt, err);
    radi_ff_tally_clear(&t, n);
    if (s == RAD_OK)
        s = radi_ff_block_fill(blk, w->g.grow, w->g.mloc, w->g.gcol, w->g.nloc, w->F,
                              (size_t)w->g.lld, &t, err);
    radi_ff_block_close(blk);
    s = mpi_agree(s, err);
    if (s == RAD_OK) {
        ff_stats_reduce(w, &t, st, opt->accuracy == RAD_ACCURACY_CLASSIC);
        if (w->g.rank == 0)
            w->row_error_max = st->max_row_error;
        MPI_Bcast(&w->row_error_max, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    }
    free(t.row_sum);
    free(t.row_error);
    return s;
}

/* ---- one band set -------------------------------------------------------- */

/* The right-hand sides of bands[0..nb) into the local array R (process
 * column 0 holds them), each row scaled by scale[i] (NULL: 1). */
static void rhs_local(const work *w, const int *bands, int nb, const double *scale, double *R)
{
    if (w->g.mycol != 0)
        return;
    for (int k = 0; k < nb; k++)
        for (int l = 0; l < w->g.mloc; l++) {
            const int i = w->g.grow[l];
            const double e = w->E[(size_t)i + (size_t)bands[k] * w->n];
            R[(size_t)l + (size_t)k * w->g.lld] = scale ? e * scale[i] : e;
        }
}

/* Sum the solution held on process column 0 into B on every process,
 * each row scaled by scale[i] (NULL: 1). */
static int rhs_gather(work *w, const int *bands, int nb, const double *scale, const double *R)
{
    const size_t n = (size_t)w->n;
    double *x = calloc(n * (size_t)nb + 1, sizeof *x);
    if (!x)
        return -1;
    if (w->g.mycol == 0)
        for (int k = 0; k < nb; k++)
            for (int l = 0; l < w->g.mloc; l++) {
                const int i = w->g.grow[l];
                const double v = R[(size_t)l + (size_t)k * w->g.lld];
                x[(size_t)i + (size_t)k * n] = scale ? v * scale[i] : v;
            }
    MPI_Allreduce(MPI_IN_PLACE, x, (int)(n * (size_t)nb), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    for (int k = 0; k < nb; k++)
        memcpy(w->B + (size_t)bands[k] * n, x + (size_t)k * n, sizeof *x * n);
    free(x);
    return 0;
}

/* Workspace sizes of pdgecon / pdpocon (their own query). */
static int con_work(const work *w, const double *A, int chol, double **wk, int *lw, int **iw,
                    int *liw)
{
    const int one = 1, query = -1;
    double q = 0, anorm = 1, rc;
    int iq = 0, info;
    if (chol)
        pdpocon_("U", &w->n, A, &one, &one, w->g.desc, &anorm, &rc, &q, &query, &iq, &query,
                 &info);
    else
        pdgecon_("1", &w->n, A, &one, &one, w->g.desc, &anorm, &rc, &q, &query, &iq, &query,
                 &info);
    *lw = (int)q + 1;
    *liw = iq + 1;
    *wk = malloc(sizeof **wk * (size_t)*lw);
    *iw = malloc(sizeof **iw * (size_t)*liw);
    return *wk && *iw ? 0 : -1;
}

/* Work for pdlange and pdlansy: the larger of their needs (pdlansy's
 * 2 Nq0 + Np0 + LDW, LDW <= Np0 + nb; ScaLAPACK's pdlansy.f), rounded up. */
static size_t norm_work(const work *w)
{
    return 3 * ((size_t)w->g.mloc + (size_t)w->g.nloc) + 4 * (size_t)w->g.nb + 1;
}

/* K = D^-1 (I - diag(rho) F) D on the upper triangle (cholesky.c). */
static void build_k(const work *w, const double *rho, double *A)
{
    for (int c = 0; c < w->g.nloc; c++)
        for (int r = 0; r < w->g.mloc; r++) {
            const int i = w->g.grow[r], j = w->g.gcol[c];
            const size_t k = (size_t)r + (size_t)c * w->g.lld;
            A[k] = i == j  ? 1
                   : i < j ? -sqrt(rho[i] * rho[j]) * sqrt(w->area[i] / w->area[j]) * w->F[k]
                           : 0;
        }
}

static void build_a(const work *w, const double *rho, double *A)
{
    for (int c = 0; c < w->g.nloc; c++)
        for (int r = 0; r < w->g.mloc; r++) {
            const int i = w->g.grow[r], j = w->g.gcol[c];
            const size_t k = (size_t)r + (size_t)c * w->g.lld;
            A[k] = (i == j) - rho[i] * w->F[k];
        }
}

/* The symmetric form; 1 when it is not positive definite (nothing else
 * changed), 0 solved, -1 out of memory. */
static int solve_chol(work *w, const double *rho, const int *bands, int nb, double *A, double *R,
                      const int *descb, rad_solve_report *rep)
{
    const int one = 1;
    int info = 0, lw, liw, *iw = NULL;
    double *wk = NULL, rcond = 0;
    double *d = malloc(sizeof *d * (size_t)(w->n ? w->n : 1)), *dinv = malloc(sizeof *dinv *
                                                                           (size_t)(w->n ? w->n : 1));
    double *lwork = malloc(sizeof *lwork * norm_work(w));
    int st = d && dinv && lwork ? 0 : -1;
    for (int i = 0; st == 0 && i < w->n; i++) {
        d[i] = sqrt(rho[i] / w->area[i]);
        dinv[i] = 1 / d[i];
    }
    if (st == 0) {
        build_k(w, rho, A);
        const double anorm = pdlansy_("1", "U", &w->n, A, &one, &one, w->g.desc, lwork);
        pdpotrf_("U", &w->n, A, &one, &one, w->g.desc, &info);
        if (info != 0)
            st = 1;
        else if (con_work(w, A, 1, &wk, &lw, &iw, &liw) != 0)
            st = -1;
        else {
            pdpocon_("U", &w->n, A, &one, &one, w->g.desc, &anorm, &rcond, wk, &lw, iw, &liw,
                     &info);
            rhs_local(w, bands, nb, dinv, R); /* y = D^-1 E */
            pdpotrs_("U", &w->n, &nb, A, &one, &one, w->g.desc, R, &one, &one, descb, &info);
            st = rhs_gather(w, bands, nb, d, R) ? -1 : 0; /* B = D y */
            rep->rcond = rep->systems == 1 ? rcond : fmin(rep->rcond, rcond);
        }
    }
    free(d);
    free(dinv);
    free(lwork);
    free(wk);
    free(iw);
    return st;
}

/* LU; RAD_ERR_SINGULAR as in solve.c. */
static rad_status solve_lu(work *w, const double *rho, const int *bands, int nb, double *A,
                           double *R, const int *descb, rad_solve_report *rep, rad_error *err)
{
    const int one = 1;
    int info = 0, lw = 0, liw = 0, *iw = NULL;
    double *wk = NULL, rcond = 0, rinf = 0, rho_max = 0;
    int *ipiv = malloc(sizeof *ipiv * (size_t)(w->g.mloc + w->g.nb));
    double *lwork = malloc(sizeof *lwork * norm_work(w));
    for (int i = 0; i < w->n; i++)
        rho_max = fmax(rho_max, rho[i]);
    if (!ipiv || !lwork || con_work(w, A, 0, &wk, &lw, &iw, &liw) != 0) {
        free(ipiv);
        free(lwork);
        free(wk);
        free(iw);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the distributed system");
    }
    build_a(w, rho, A);
    const double anorm = pdlange_("1", &w->n, &w->n, A, &one, &one, w->g.desc, lwork);
    const double ainf = pdlange_("I", &w->n, &w->n, A, &one, &one, w->g.desc, lwork);
    pdgetrf_(&w->n, &w->n, A, &one, &one, w->g.desc, ipiv, &info);
    if (info == 0) {
        pdgecon_("1", &w->n, A, &one, &one, w->g.desc, &anorm, &rcond, wk, &lw, iw, &liw, &info);
        pdgecon_("I", &w->n, A, &one, &one, w->g.desc, &ainf, &rinf, wk, &lw, iw, &liw, &info);
    }
    rep->rcond = rep->systems == 1 ? rcond : fmin(rep->rcond, rcond);
    rad_status st = RAD_OK;
    if (!(rcond >= RAD_RCOND_MIN))
        st = radi_fail(err, RAD_ERR_SINGULAR, "the radiosity system is singular (reciprocal "
                      "condition %.3g < %g)%s", rcond, RAD_RCOND_MIN,
                      rho_max >= 1 ? ": a closed enclosure that reflects everything (rho = 1) "
                                     "never absorbs light, so no steady state exists"
                                   : "");
    if (st == RAD_OK && !isnan(w->row_error_max)) {
        const double k = rho_max * w->row_error_max / (rinf * ainf); /* Higham, thm. 7.2 */
        const double bound = k < 1 ? k / (1 - k) : INFINITY;
        rep->ff_error_bound = isnan(rep->ff_error_bound) ? bound : fmax(rep->ff_error_bound, bound);
        if (!(k < 1))
            st = radi_fail(err, RAD_ERR_SINGULAR,
                          "the radiosity system is singular within the accuracy of its form "
                          "factors (||(I - rho F)^-1|| ||rho dF|| = %.3g >= 1)", k);
    }
    if (st == RAD_OK) {
        rhs_local(w, bands, nb, NULL, R);
        pdgetrs_("N", &w->n, &nb, A, &one, &one, w->g.desc, ipiv, R, &one, &one, descb, &info);
        if (rhs_gather(w, bands, nb, NULL, R) != 0)
            st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    free(ipiv);
    free(lwork);
    free(wk);
    free(iw);
    return st;
}

/* One band set into w->B.  Collective; the status is the same on every
 * process except for memory, which is agreed. */
static rad_status solve_set(work *w, int solver, const int *bands, int nb, double *A,
                            rad_solve_report *rep, rad_error *err)
{
    const double *rho = w->rho + (size_t)bands[0] * w->n;
    const int zero = 0, ncl = mpi_grid_local_cols(&w->g, nb);
    int descb[9], info;
    double *R = calloc((size_t)w->g.lld * (size_t)(ncl > 0 ? ncl : 1), sizeof *R);
    descinit_(descb, &w->n, &nb, &w->g.nb, &w->g.nb, &zero, &zero, &w->g.ctxt, &w->g.lld, &info);
    rad_status st = R ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (mpi_agree(st, err) != RAD_OK) {
        free(R);
        return err->status;
    }
    int positive = 1;
    for (int i = 0; i < w->n; i++)
        positive &= rho[i] > 0;
    int done = 0;
    if (solver == RAD_SOLVER_CHOLESKY && positive) {
        int c = solve_chol(w, rho, bands, nb, A, R, descb, rep);
        if (c < 0)
            st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
        done = c <= 0;
        if (c == 1)
            radi_report_fallback(rep, "the symmetric form is not positive definite: LU");
    } else if (solver == RAD_SOLVER_CHOLESKY) {
        radi_report_fallback(rep, "some rho = 0: LU");
    }
    st = mpi_agree(st, err);
    if (st == RAD_OK && !done)
        st = mpi_agree(solve_lu(w, rho, bands, nb, A, R, descb, rep, err), err);
    free(R);
    return st;
}

/* Every band set by LU or Cholesky, the system beside F.  Collective. */
static rad_status solve_direct(work *w, int solver, rad_solve_report *rep, rad_error *err)
{
    double *A = malloc(sizeof *A * ((size_t)w->g.lld * (size_t)(w->g.nloc ? w->g.nloc : 1)));
    rad_status st = mpi_agree(A ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory for "
                                                    "this process's blocks of the system"),
                              err);
    int done[RAD_BANDS] = {0}, bands[RAD_BANDS], nb;
    while (st == RAD_OK && (nb = radi_next_band_set(w->n, w->rho, done, bands)) > 0) {
        rep->systems++;
        st = solve_set(w, solver, bands, nb, A, rep, err);
    }
    free(A);
    return st;
}

/* ---- the job ------------------------------------------------------------- */

static int work_alloc(work *w)
{
    const size_t n = (size_t)w->n, n3 = n * RAD_BANDS + 1;
    w->rho = malloc(sizeof *w->rho * n3);
    w->E = malloc(sizeof *w->E * n3);
    w->B = calloc(n3, sizeof *w->B);
    w->area = malloc(sizeof *w->area * (n + 1));
    w->F = malloc(sizeof *w->F * ((size_t)w->g.lld * (size_t)(w->g.nloc ? w->g.nloc : 1)));
    if (!w->rho || !w->E || !w->B || !w->area || !w->F)
        return -1;
    for (int i = 0; i < w->n; i++) {
        w->area[i] = w->m->elements[i].area;
        for (int b = 0; b < RAD_BANDS; b++) {
            w->rho[(size_t)i + (size_t)b * n] = w->m->elements[i].reflect[b];
            w->E[(size_t)i + (size_t)b * n] = w->m->elements[i].emit[b];
        }
    }
    return 0;
}

static void work_free(work *w)
{
    free(w->rho);
    free(w->E);
    free(w->B);
    free(w->area);
    free(w->F);
    mpi_grid_close(&w->g);
}

/* H = F B and the row sums of F, summed onto rank 0, which fills the
 * report's balance.  Collective. */
static rad_status balance(const work *w, rad_solve_report *rep, rad_error *err)
{
    const size_t n = (size_t)w->n;
    double *h = calloc(n * (RAD_BANDS + 1) + 1, sizeof *h);
    rad_status st = h ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (mpi_agree(st, err) != RAD_OK) {
        free(h);
        return err->status;
    }
    for (int c = 0; c < w->g.nloc; c++)
        for (int r = 0; r < w->g.mloc; r++) {
            const size_t i = (size_t)w->g.grow[r], j = (size_t)w->g.gcol[c];
            const double f = w->F[(size_t)r + (size_t)c * w->g.lld];
            for (int b = 0; b < RAD_BANDS; b++)
                h[i + (size_t)b * n] += f * w->B[j + (size_t)b * n];
            h[i + RAD_BANDS * n] += f;
        }
    const int count = (int)(n * (RAD_BANDS + 1));
    if (w->g.rank == 0)
        MPI_Reduce(MPI_IN_PLACE, h, count, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    else
        MPI_Reduce(h, NULL, count, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    if (w->g.rank == 0)
        radi_solve_balance(w->n, h, h + RAD_BANDS * n, w->rho, w->E, w->B, w->area, 0, 0, rep);
    free(h);
    return RAD_OK;
}

/* Every process's blocks of F into rank 0's dense F (--form-factors). */
static void gather_f(const work *w, double *F)
{
    for (int p = 0; p < w->g.size; p++) {
        mpi_grid pg = w->g;
        const int zero = 0;
        pg.myrow = p / w->g.pc;
        pg.mycol = p % w->g.pc;
        const int mloc = numroc_(&w->n, &w->g.nb, &pg.myrow, &zero, &w->g.pr);
        const int nloc = numroc_(&w->n, &w->g.nb, &pg.mycol, &zero, &w->g.pc);
        const size_t count = (size_t)mloc * (size_t)nloc;
        if (p != 0 && w->g.rank == p && count > 0) {
            for (int c = 0; c < nloc; c++) /* packed: leading dimension mloc */
                MPI_Send(w->F + (size_t)c * w->g.lld, mloc, MPI_DOUBLE, 0, c, MPI_COMM_WORLD);
        }
        if (w->g.rank != 0 || count == 0)
            continue;
        double *col = malloc(sizeof *col * (size_t)(mloc ? mloc : 1));
        if (!col) /* the others are sending: no way back */
            MPI_Abort(MPI_COMM_WORLD, 1);
        for (int c = 0; c < nloc; c++) {
            const int j = mpi_global_index(c, pg.mycol, w->g.pc, w->g.nb);
            if (p == 0)
                memcpy(col, w->F + (size_t)c * w->g.lld, sizeof *col * (size_t)mloc);
            else
                MPI_Recv(col, mloc, MPI_DOUBLE, p, c, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            for (int r = 0; r < mloc; r++) {
                const int i = mpi_global_index(r, pg.myrow, w->g.pr, w->g.nb);
                F[(size_t)i + (size_t)j * w->n] = col[r];
            }
        }
        free(col);
    }
}

/* The job on every process: fill, solve each band set, balance.  On rank
 * 0, r receives what the run produced (r->mesh is rank 0's own). */
static rad_status job_run(const mpi_job *job, const rad_mesh *m, rad_result *r, rad_error *err)
{
    work w = {0};
    rad_ff_options ff;
    rad_ff_stats fst;
    rad_solve_report rep;
    rad_ff_options_init(&ff);
    ff.quadrature = job->quadrature;
    ff.accuracy = (rad_accuracy)job->accuracy;
    ff.threads = job->threads;
    w.m = m;
    w.n = job->nelements;
    rad_status st = mpi_grid_open(&w.g, w.n) == 0 && work_alloc(&w) == 0
                        ? RAD_OK
                        : radi_fail(err, RAD_ERR_NOMEM, "out of memory for this process's "
                                   "blocks of the %d x %d matrix", w.n, w.n);
    st = mpi_agree(st, err);
    double t1 = radi_seconds();
    if (st == RAD_OK)
        st = fill(&w, &ff, &fst, err);
    double t2 = radi_seconds();
    if (r) {
        r->t_formfactor = t2 - t1;
        r->ff = fst;
        r->ff.promise = radi_ff_promise(ff.accuracy);
        r->ff_done = st == RAD_OK;
    }
    memset(&rep, 0, sizeof rep);
    rep.solver = (rad_solver)job->solver;
    rep.bounces = -1;
    rep.rcond = rep.ff_error_bound = rep.spectral_radius = NAN;
    rep.ferr = rep.berr = rep.error_bound = rep.contraction = NAN;
    if (st == RAD_OK && job->solver == RAD_SOLVER_JACOBI)
        st = mpi_jacobi(&w.g, w.F, w.rho, w.E, w.B, job->tolerance, job->max_iterations, &rep,
                        err);
    else if (st == RAD_OK)
        st = solve_direct(&w, job->solver, &rep, err);
    if (st == RAD_OK)
        st = balance(&w, &rep, err);
    if (r) {
        r->t_solve = radi_seconds() - t2;
        r->solve = rep;
        r->solve_done = w.F != NULL && r->ff_done;
        if (st == RAD_OK) {
            memcpy(r->B, w.B, sizeof *r->B * (size_t)w.n * RAD_BANDS);
            if (r->F)
                gather_f(&w, r->F);
        }
    } else if (st == RAD_OK && job->keep_form_factors) {
        gather_f(&w, NULL);
    }
    work_free(&w);
    return st;
}

/* The memory rank 0 needs for its blocks (F and the system), checked
 * before meshing as pipeline.c does: the largest share is rank 0's. */
static rad_status check_size(const rad_scene *scene, const rad_solve_options *so, rad_result *r,
                             int keep, rad_error *err)
{
    const int matrices = so->solver == RAD_SOLVER_JACOBI ? 1 : 2; /* F (and the system) */
    int size;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const double n = rad_scene_element_count(scene);
    if (n > INT_MAX)
        return radi_fail(err, RAD_ERR_TOOBIG, "the scene's meshes make %.0f elements, more "
                        "than %d; use a coarser --mesh", n, INT_MAX);
    int pr, pc;
    mpi_grid_shape(size, &pr, &pc);
    /* rank 0's blocks: the most rows and columns any process holds */
    const double nb = RAD_MPI_NB, rows = ceil(n / nb / pr) * nb, cols = ceil(n / nb / pc) * nb;
    r->memory_bytes = matrices * 8 * fmin(rows, n) * fmin(cols, n) + (keep ? 8 * n * n : 0);
    char what[160];
    snprintf(what, sizeof what, "%.0f elements on %d processes (%d x 8 N^2 / P bytes of "
             "matrices on rank 0 for %s%s)", n, size, matrices, rad_solver_name(so->solver),
             keep ? ", and all of F for --form-factors" : "");
    return rad_memory_check(r->memory_bytes, what, &r->memory_available, err);
}

static rad_status run_present(const rad_scene *scene, const rad_pipeline_options *opt,
                              rad_result *r, rad_error *err)
{
    memset(r, 0, sizeof *r);
    rad_status st = check_size(scene, &opt->solve, r, opt->keep_form_factors, err);
    double t0 = radi_seconds();
    if (st == RAD_OK)
        st = rad_mesh_build(&r->mesh, scene, err);
    r->t_mesh = radi_seconds() - t0;
    if (st != RAD_OK)
        return st;
    const size_t n = (size_t)r->mesh.nelements, nv = (size_t)r->mesh.nvertices;
    r->B = malloc(sizeof *r->B * (n ? n : 1) * RAD_BANDS);
    r->Bv = malloc(sizeof *r->Bv * (nv ? nv : 1) * RAD_BANDS);
    if (opt->keep_form_factors)
        r->F = calloc(n * n + 1, sizeof *r->F);
    if (!r->B || !r->Bv || (opt->keep_form_factors && !r->F))
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %zu elements", n);
    mpi_job job;
    mpi_job_make(&job, &r->mesh, &opt->ff, &opt->solve, opt->keep_form_factors);
    mpi_job_bcast(&job);
    if (mpi_mesh_bcast(&r->mesh, &job) != 0)
        return radi_fail(err, RAD_ERR_NOMEM, "the mesh could not be sent to every process");
    st = job_run(&job, &r->mesh, r, err);
    if (st == RAD_OK) {
        double t3 = radi_seconds();
        for (size_t k = 0; k < n * RAD_BANDS; k++)
            r->b_negative += r->B[k] < 0;
        rad_smooth_vertices_rule(&r->mesh, r->B, r->Bv, opt->vertex_rule);
        st = rad_smooth_across(scene, &r->mesh, opt->crease, r->Bv, err);
        r->t_smooth = radi_seconds() - t3;
    }
    return st;
}

rad_status mpi_pipeline_run(const rad_scene *scene, const rad_pipeline_options *opt,
                            rad_result *r, rad_error *err)
{
    return rad_pipeline_present(scene, opt, r, err, run_present); /* as pipeline.c */
}

int mpi_serve(void)
{
    int failed = 0;
    for (;;) {
        mpi_job job;
        rad_mesh m;
        rad_error err;
        mpi_job_bcast(&job);
        if (job.command != MPI_JOB_SOLVE)
            return failed;
        memset(&m, 0, sizeof m);
        if (mpi_mesh_bcast(&m, &job) == 0)
            failed |= job_run(&job, &m, NULL, &err) != RAD_OK;
        rad_mesh_free(&m);
    }
}

void mpi_release(void)
{
    mpi_job job;
    memset(&job, 0, sizeof job);
    job.command = MPI_JOB_QUIT;
    mpi_job_bcast(&job);
}
