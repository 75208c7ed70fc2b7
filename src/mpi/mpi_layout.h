/* mpi_layout.h -- processes, the block-cyclic layout and what rank 0
 * sends the others (radiosity-mpi, internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The P processes of MPI_COMM_WORLD form a pr x pc BLACS grid, as square
 * as P allows (pr <= pc, pr the largest divisor of P not above sqrt P),
 * row-major: rank = prow * pc + pcol.  An n x n matrix is cut into nb x nb
 * blocks dealt cyclically over the grid (ScaLAPACK Users' Guide, 1997,
 * section 4.3.2): global row i (0-based) lives on process row
 * (i / nb) mod pr, at local row (i / (nb pr)) nb + i mod nb.  Each process
 * keeps the global numbers of its local rows and columns, which is all a
 * fill needs (ffblock.h).
 */
#ifndef RAD_MPI_LAYOUT_H
#define RAD_MPI_LAYOUT_H

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"

/* ScaLAPACK's block size: 64 keeps DGEMM efficient inside the
 * factorisations and leaves enough blocks for balance at n of a few
 * thousand. */
#define RAD_MPI_NB 64

typedef struct mpi_grid {
    int ctxt;                   /* BLACS context */
    int rank, size;             /* in MPI_COMM_WORLD */
    int pr, pc, myrow, mycol;
    int n, nb;
    int mloc, nloc, lld;        /* local rows, columns, leading dimension */
    int *grow, *gcol;           /* global index of each local row, column */
    int desc[9];                /* the n x n matrix */
} mpi_grid;

/* The global index of local row (or column) l of process row (column) p
 * of np, blocks of nb (the layout above). */
int mpi_global_index(int l, int p, int np, int nb);

/* pr x pc = size with pr <= pc and pr as large as possible. */
void mpi_grid_shape(int size, int *pr, int *pc);

/* The grid for an n x n matrix (collective).  0, or -1 when memory ran
 * out (on this process; the caller agrees with the others). */
int mpi_grid_open(mpi_grid *g, int n);
void mpi_grid_close(mpi_grid *g);
/* Local elements of a matrix with `cols` columns on the grid's rows,
 * columns dealt from process column 0 (the right-hand sides). */
int mpi_grid_local_cols(const mpi_grid *g, int cols);

/* Make one status out of every process's (collective): RAD_OK when all
 * succeeded, else the status and message of the lowest failing rank,
 * copied into every process's err. */
rad_status mpi_agree(rad_status st, rad_error *err);

/* What rank 0 asks of the others. */
typedef struct mpi_job {
    int command;                /* MPI_JOB_QUIT or MPI_JOB_SOLVE */
    int nelements, nvertices, nvindex, nsurfaces;
    int quadrature, accuracy, threads;
    int solver;                 /* RAD_SOLVER_GAUSS, _CHOLESKY or _JACOBI */
    int keep_form_factors;
    int max_iterations;         /* jacobi */
    double tolerance;
} mpi_job;

enum { MPI_JOB_QUIT = 0, MPI_JOB_SOLVE = 1 };

/* Rank 0's job and mesh to everyone (collective).  On the other ranks the
 * mesh is allocated here (free it with rad_mesh_free).  0, or -1 when a
 * process ran out of memory (agreed). */
void mpi_job_bcast(mpi_job *job);
int mpi_mesh_bcast(rad_mesh *m, const mpi_job *job);
/* The job's numbers for the mesh m and options (rank 0). */
void mpi_job_make(mpi_job *job, const rad_mesh *m, const rad_ff_options *ff,
                  const rad_solve_options *so, int keep_form_factors);

#endif /* RAD_MPI_LAYOUT_H */
