/* mpi_jacobi.h -- Jacobi sweeps on the distributed F (radiosity-mpi,
 * internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_MPI_JACOBI_H
#define RAD_MPI_JACOBI_H

#include "mpi/mpi_layout.h"
#include "radiosity/base.h"
#include "radiosity/solve.h"

/* B = E + diag(rho) F B by Jacobi sweeps from B = E, F this process's
 * blocks on grid g; rho, E, B n x RAD_BANDS on every process.  Stops when
 * the bound on B's error falls below tolerance ||B||_inf (mpi_jacobi.c);
 * fills the report's sweeps, contraction, error_bound and
 * spectral_radius.  Collective; RAD_ERR_NOCONV after max_iterations. */
rad_status mpi_jacobi(const mpi_grid *g, const double *F, const double *rho, const double *E,
                      double *B, double tolerance, int max_iterations, rad_solve_report *rep,
                      rad_error *err);

#endif /* RAD_MPI_JACOBI_H */
