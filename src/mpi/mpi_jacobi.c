/* mpi_jacobi.c -- Jacobi sweeps on the distributed F (radiosity-mpi).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The fixed point B = E + diag(rho) F B (Goral et al. 1984, eq. 6-7) as
 * iterate.c computes it for --solver jacobi, with F in blocks over the
 * processes (mpi_layout.h): each sweep every process adds F_ij B_j over
 * its blocks into H_i, the sums meet on every process (one all-reduce of
 * 3n doubles per sweep: the only communication), and each process forms
 * the same B <- E + rho H.  F is never copied: memory per process is its
 * blocks of F, 8 n^2 / P bytes, half of what LU and Cholesky need.
 *
 * The stop is iterate.c's, on a bound of the true error: the map
 * contracts in the infinity norm by q = max_i rho_i sum_j |F_ij| (the row
 * sums of |F| are reduced once), and the iterate's error is at most
 * q / (1 - q) times the last change (Banach's fixed point theorem; Golub
 * & Van Loan, Matrix Computations, 4th ed., 11.2).  q >= 1 bounds nothing:
 * then the estimate r / (1 - r) times the change, r the ratio of
 * successive changes, decides, and the report says no bound (NaN).  The
 * decision to stop is rank 0's, broadcast, so that round-off in the sums
 * can never send the processes different ways.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpi/mpi_jacobi.h"
#include "solve/solve.h"
#include "util/util.h"

/* q per band from the reduced row sums of |F| (INFINITY when >= 1). */
static void contraction(const mpi_grid *g, const double *F, const double *rho, double *rowabs,
                        double q[RAD_BANDS], rad_solve_report *rep)
{
    const int n = g->n;
    memset(rowabs, 0, sizeof *rowabs * (size_t)n);
    for (int c = 0; c < g->nloc; c++)
        for (int r = 0; r < g->mloc; r++)
            rowabs[g->grow[r]] += fabs(F[(size_t)r + (size_t)c * g->lld]);
    MPI_Allreduce(MPI_IN_PLACE, rowabs, n, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    rep->contraction = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        double qb = 0;
        for (int i = 0; i < n; i++)
            qb = fmax(qb, rho[(size_t)i + (size_t)b * n] * rowabs[i]);
        rep->contraction = fmax(rep->contraction, qb);
        q[b] = qb < 1 ? qb : INFINITY;
    }
}

/* H = F B summed over the processes; B <- E + rho H; changes per band. */
static void sweep(const mpi_grid *g, const double *F, const double *rho, const double *E,
                  double *B, double *H, double chg[RAD_BANDS])
{
    const size_t n = (size_t)g->n;
    memset(H, 0, sizeof *H * n * RAD_BANDS);
    for (int c = 0; c < g->nloc; c++) {
        const size_t j = (size_t)g->gcol[c];
        const double *col = F + (size_t)c * g->lld;
        for (int b = 0; b < RAD_BANDS; b++) {
            const double bj = B[j + (size_t)b * n];
            double *h = H + (size_t)b * n;
            for (int r = 0; r < g->mloc; r++)
                h[g->grow[r]] += col[r] * bj;
        }
    }
    MPI_Allreduce(MPI_IN_PLACE, H, (int)(n * RAD_BANDS), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    for (int b = 0; b < RAD_BANDS; b++) {
        double ch = 0;
        for (size_t k = (size_t)b * n; k < (size_t)(b + 1) * n; k++) {
            const double v = E[k] + rho[k] * H[k];
            ch = fmax(ch, fabs(v - B[k]));
            B[k] = v;
        }
        chg[b] = ch;
    }
}

/* iterate.c's bound, or NaN; *stop_on what the stop compares. */
static double error_bound(const double q[RAD_BANDS], const double chg[RAD_BANDS], double rate,
                          double *stop_on)
{
    double bound = 0, est = 0;
    int none = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        if (q[b] < 1)
            bound = fmax(bound, q[b] / (1 - q[b]) * chg[b]);
        else
            none = 1;
        est = fmax(est, fmax(chg[b], rate > 0 && rate < 1 ? rate / (1 - rate) * chg[b]
                                                          : chg[b] > 0 ? INFINITY : 0));
    }
    *stop_on = none ? est : bound;
    return none ? NAN : bound;
}

rad_status mpi_jacobi(const mpi_grid *g, const double *F, const double *rho, const double *E,
                      double *B, double tolerance, int max_iterations, rad_solve_report *rep,
                      rad_error *err)
{
    const size_t n3 = (size_t)g->n * RAD_BANDS;
    double *H = malloc(sizeof *H * (n3 + 1)), *rowabs = malloc(sizeof *rowabs * (n3 + 1));
    double q[RAD_BANDS], chg[RAD_BANDS], change = 0, prev = 0, rate = 0, bound = NAN, stop_on;
    int k, stop = 0;
    rad_status st = H && rowabs ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (mpi_agree(st, err) != RAD_OK) {
        free(H);
        free(rowabs);
        return err->status;
    }
    contraction(g, F, rho, rowabs, q, rep);
    memcpy(B, E, sizeof *B * n3); /* B_0 = E */
    for (k = 1; k <= max_iterations && !stop; k++) {
        sweep(g, F, rho, E, B, H, chg);
        change = fmax(chg[0], fmax(chg[1], chg[2]));
        if (prev > 0 && change > 0 && change > 1e4 * DBL_EPSILON * radi_max_abs(B, n3))
            rate = change / prev;
        prev = change;
        bound = error_bound(q, chg, k > 1 ? rate : 0, &stop_on);
        stop = stop_on <= tolerance * radi_max_abs(B, n3);
        MPI_Bcast(&stop, 1, MPI_INT, 0, MPI_COMM_WORLD);
    }
    k--;
    rep->sweeps = k;
    rep->spectral_radius = rate;
    rep->error_bound = bound / fmax(radi_max_abs(B, n3), DBL_MIN);
    if (!stop)
        st = radi_fail(err, RAD_ERR_NOCONV,
                      "jacobi did not converge in %d sweeps: error bound %.3g relative, "
                      "tolerance %g (convergence factor per sweep %.6f%s)",
                      max_iterations, rep->error_bound, tolerance, rate,
                      rate >= 1 - 1e-9 ? ": the system looks singular (rho = 1 in a closed "
                                         "scene?)"
                                       : "; raise --max-iterations or use --solver gauss");
    free(H);
    free(rowabs);
    return st;
}
