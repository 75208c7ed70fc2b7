/* mpi_main.c -- radiosity-mpi: `radiosity solve` distributed with
 * ScaLAPACK over MPI.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Run as `mpirun -np P radiosity-mpi solve [OPTIONS] SCENE`.  Rank 0 is
 * the program a user knows: it parses the options (those of `radiosity
 * solve`, cmd_solve.c), checks the outputs, reads the scene, prints the
 * summary and writes every file; the other ranks print nothing and write
 * nothing, and only take their part of the work (mpi_solve.c).  A usage
 * or input error is rank 0's alone: it releases the others, which exit 0,
 * and exits with the status `radiosity solve` would give.
 */
#include <config.h>

#include <mpi.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "util/util.h"
#include "mpi/mpi_solve.h"
#include "mpi/scalapack.h"

static void help(void)
{
    printf("Usage: mpirun -np P radiosity-mpi solve [OPTIONS] SCENE\n"
           "The solve of 'radiosity solve' distributed over P MPI processes: each\n"
           "process fills only its own blocks of the form-factor matrix in\n"
           "ScaLAPACK's 2-D block-cyclic layout (64 x 64 blocks on a grid of\n"
           "processes as square as P allows), and the radiosity system of each\n"
           "colour band is solved with ScaLAPACK's LU (gauss) or Cholesky on the\n"
           "symmetric form (cholesky), or by Jacobi sweeps on the distributed F\n"
           "(jacobi: F alone, half the memory).  Rank 0 reads the scene, prints the\n"
           "summary and writes every output; B is the same as a serial solve's to\n"
           "round-off (jacobi: within its tolerance).\n"
           "\n"
           "Options (those of 'radiosity solve' that a distributed solve has):\n"
           "  -o, --output FILE       the solution as PLY; '-' is stdout\n"
           "      --solver NAME       gauss (ScaLAPACK's LU; default), cholesky (the\n"
           "                          symmetric form diag(A/rho)(I - rho F), ScaLAPACK's\n"
           "                          Cholesky; LU where it is not positive definite)\n"
           "                          or jacobi (sweeps on the distributed F)\n"
           "      --tolerance T       jacobi: stop when a bound on the relative error\n"
           "                          of B is below T (q/(1-q) times the last change,\n"
           "                          q the contraction factor; default 1e-12)\n"
           "      --max-iterations N  jacobi: give up after N sweeps (default 100000)\n"
           CLI_SOLVE_HELP_FILES
           CLI_COMMON_HELP
           "\n"
           "The contour integral fills F (no --form-factors-method hemicube); the\n"
           "serial program's other solvers, --bounces, --error-bounds and the\n"
           "progressive options are refused.\n"
           "\n"
           "Each process takes about 2 x 8 N^2 / P bytes for its blocks of F and of\n"
           "the system (N elements; jacobi 8 N^2 / P), plus the mesh; --form-factors\n"
           "gathers all of F\n"
           "on rank 0 (8 N^2 bytes more there).  --threads sets the OpenMP threads of\n"
           "each process's fill: with several processes per machine, keep processes\n"
           "times threads at or below its cores.  A pair of elements whose two\n"
           "entries live on different processes is integrated on both, so the fill\n"
           "does up to twice the serial fill's work, spread over the P processes.\n"
           "\n"
           "Examples:\n"
           "  mpirun -np 4 radiosity-mpi solve --threads 1 \\\n"
           "      data/goral1984-cube.scene --elements B.tsv\n"
           "  mpirun -np 16 --hostfile hosts radiosity-mpi solve --solver cholesky \\\n"
           "      --mesh 100x100 data/goral1984-cube.scene -o cube.ply\n"
           "\n"
           "See radiosity-mpi(1) for running on a cluster.  Exit status: as for\n"
           "'radiosity solve'.\n"
           "\n" CLI_BUG_HELP);
}

static int check(const cli_solve *s)
{
    const rad_solver v = s->solve.solver;
    if (s->given_bounces ||
        (v != RAD_SOLVER_GAUSS && v != RAD_SOLVER_CHOLESKY && v != RAD_SOLVER_JACOBI)) {
        cli_error("the distributed solve takes --solver gauss, cholesky (ScaLAPACK) or jacobi, "
                  "not %s",
                  s->given_bounces ? "--bounces" : rad_solver_name(v));
        return 2;
    }
    if (s->solve.error_bounds) {
        cli_error("--error-bounds (LAPACK's dgesvx) has no distributed counterpart here");
        return 2;
    }
    if (s->common.ff.method != RAD_FF_CONTOUR) {
        cli_error("the distributed fill takes its blocks of F from the contour integral; the "
                  "hemicube gives whole rows (use radiosity solve)");
        return 2;
    }
    return 0;
}

static int usage(FILE *out)
{
    fprintf(out, "Usage: mpirun -np P radiosity-mpi solve [OPTIONS] SCENE\n"
                 "       radiosity-mpi --help | --version\n");
    return out == stdout ? 0 : EXIT_USAGE;
}

/* Rank 0: the command line. */
static int run(int argc, char **argv)
{
    static const cli_solve_variant variant = {help, check, mpi_pipeline_run,
                                                "radiosity-mpi"};
    if (argc < 2)
        return usage(stderr);
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        help();
        return 0;
    }
    if (strcmp(argv[1], "--version") == 0 || strcmp(argv[1], "-V") == 0) {
        cli_version("radiosity-mpi");
        return 0;
    }
    if (strcmp(argv[1], "solve") != 0) {
        cli_error("one command, solve, not '%s'", argv[1]);
        return usage(stderr);
    }
    char name[] = "radiosity-mpi solve";
    argv[1] = name;
    return cmd_solve_variant(argc - 1, argv + 1, &variant);
}

int main(int argc, char **argv)
{
    int provided, rank, rc;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    radi_blas_park_threads(); /* see blasthreads.c */
    if (rank != 0) {
        rc = mpi_serve();
    } else {
        cli_signals_install(); /* outputs are never left half-written */
        rc = run(argc, argv);
        mpi_release();
        rc = cli_finish_stdout(rc);
    }
    Cblacs_exit(1);
    MPI_Finalize();
    return rank == 0 ? rc : 0;
}
