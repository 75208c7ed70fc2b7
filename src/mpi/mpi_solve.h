/* mpi_solve.h -- the solve distributed over MPI processes with ScaLAPACK
 * (radiosity-mpi, internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Rank 0 runs the program (options, scene, outputs: cmd_solve.c) and
 * calls mpi_pipeline_run where `radiosity solve` calls rad_pipeline_run;
 * every other rank waits in mpi_serve for rank 0's jobs, takes its part
 * of each, and returns when mpi_release tells it to.
 */
#ifndef RAD_MPI_SOLVE_H
#define RAD_MPI_SOLVE_H

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/pipeline.h"
#include "radiosity/pipeline.h"

/* rad_pipeline_run's contract (pipeline.h), on rank 0, with every process
 * filling and factorising its own blocks.  memory_bytes is rank 0's
 * share; the summary's times are rank 0's wall clock. */
rad_status mpi_pipeline_run(const rad_scene *scene, const rad_pipeline_options *opt,
                            rad_result *result, rad_error *err);

/* Ranks other than 0: serve jobs until released; returns 0, or 1 when a
 * job failed on this rank (rank 0 has reported it). */
int mpi_serve(void);
/* Rank 0: release the others (once, at the end). */
void mpi_release(void);

#endif /* RAD_MPI_SOLVE_H */
