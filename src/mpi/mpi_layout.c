/* mpi_layout.c -- processes, the block-cyclic layout and what rank 0
 * sends the others (radiosity-mpi).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Conventions in mpi_layout.h.  The mesh travels as raw bytes: the
 * processes of one run are assumed to share the data representation
 * (the same build on machines of one architecture), as ScaLAPACK's own
 * MPI_DOUBLE traffic between them assumes too.
 */
#include <config.h>

#include <math.h>
#include <mpi.h>
#include <stdlib.h>
#include <string.h>

#include "mpi/mpi_layout.h"
#include "mpi/scalapack.h"
#include "util/util.h"

void mpi_grid_shape(int size, int *pr, int *pc)
{
    int r = (int)sqrt((double)size);
    while (r > 1 && size % r != 0)
        r--;
    *pr = r > 0 ? r : 1;
    *pc = size / *pr;
}

int mpi_global_index(int l, int p, int np, int nb)
{
    return ((l / nb) * np + p) * nb + l % nb;
}

int mpi_grid_open(mpi_grid *g, int n)
{
    const int zero = 0;
    int info;
    memset(g, 0, sizeof *g);
    MPI_Comm_rank(MPI_COMM_WORLD, &g->rank);
    MPI_Comm_size(MPI_COMM_WORLD, &g->size);
    mpi_grid_shape(g->size, &g->pr, &g->pc);
    Cblacs_get(-1, 0, &g->ctxt);
    Cblacs_gridinit(&g->ctxt, "R", g->pr, g->pc);
    Cblacs_gridinfo(g->ctxt, &g->pr, &g->pc, &g->myrow, &g->mycol);
    g->n = n;
    g->nb = RAD_MPI_NB;
    g->mloc = numroc_(&n, &g->nb, &g->myrow, &zero, &g->pr);
    g->nloc = numroc_(&n, &g->nb, &g->mycol, &zero, &g->pc);
    g->lld = g->mloc > 1 ? g->mloc : 1;
    descinit_(g->desc, &n, &n, &g->nb, &g->nb, &zero, &zero, &g->ctxt, &g->lld, &info);
    g->grow = malloc(sizeof *g->grow * (size_t)(g->mloc > 0 ? g->mloc : 1));
    g->gcol = malloc(sizeof *g->gcol * (size_t)(g->nloc > 0 ? g->nloc : 1));
    if (!g->grow || !g->gcol)
        return -1;
    for (int l = 0; l < g->mloc; l++)
        g->grow[l] = mpi_global_index(l, g->myrow, g->pr, g->nb);
    for (int l = 0; l < g->nloc; l++)
        g->gcol[l] = mpi_global_index(l, g->mycol, g->pc, g->nb);
    return 0;
}

void mpi_grid_close(mpi_grid *g)
{
    free(g->grow);
    free(g->gcol);
    Cblacs_gridexit(g->ctxt);
    memset(g, 0, sizeof *g);
}

int mpi_grid_local_cols(const mpi_grid *g, int cols)
{
    const int zero = 0;
    return numroc_(&cols, &g->nb, &g->mycol, &zero, &g->pc);
}

rad_status mpi_agree(rad_status st, rad_error *err)
{
    int rank, first;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    int mine = st != RAD_OK ? rank : 1 << 30;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == 1 << 30)
        return RAD_OK;
    rad_error e;
    if (rank == first)
        e = *err;
    MPI_Bcast(&e, (int)sizeof e, MPI_BYTE, first, MPI_COMM_WORLD);
    *err = e;
    return e.status;
}

void mpi_job_bcast(mpi_job *job)
{
    MPI_Bcast(job, (int)sizeof *job, MPI_BYTE, 0, MPI_COMM_WORLD);
}

void mpi_job_make(mpi_job *job, const rad_mesh *m, const rad_ff_options *ff,
                  const rad_solve_options *so, int keep_form_factors)
{
    memset(job, 0, sizeof *job);
    job->command = MPI_JOB_SOLVE;
    job->nelements = m->nelements;
    job->nvertices = m->nvertices;
    for (int e = 0; e < m->nelements; e++) {
        const int end = m->elements[e].first + m->elements[e].nverts;
        job->nvindex = end > job->nvindex ? end : job->nvindex;
    }
    job->nsurfaces = m->nsurfaces;
    job->quadrature = ff->quadrature;
    job->accuracy = (int)ff->accuracy;
    job->threads = ff->threads;
    job->solver = (int)so->solver;
    job->keep_form_factors = keep_form_factors;
    job->max_iterations = so->max_iterations;
    job->tolerance = so->tolerance;
}

/* Bytes of an array of count items of size `size`, for MPI_Bcast: the
 * mesh's arrays stay below 2^31 bytes (checked by the caller's memory
 * estimate long before: a mesh that large has no room for its F). */
static int bcast_bytes(void *p, size_t count, size_t size)
{
    const size_t bytes = count * size;
    if (bytes > (size_t)1 << 30)
        return -1;
    MPI_Bcast(p, (int)bytes, MPI_BYTE, 0, MPI_COMM_WORLD);
    return 0;
}

static int mesh_alloc(rad_mesh *m, const mpi_job *job)
{
    const size_t ns = (size_t)job->nsurfaces + 1;
    memset(m, 0, sizeof *m);
    m->nelements = job->nelements;
    m->nvertices = job->nvertices;
    m->nsurfaces = job->nsurfaces;
    m->elements = calloc((size_t)(job->nelements ? job->nelements : 1), sizeof *m->elements);
    m->vertices = calloc((size_t)(job->nvertices ? job->nvertices : 1), sizeof *m->vertices);
    m->vindex = calloc((size_t)(job->nvindex ? job->nvindex : 1), sizeof *m->vindex);
    m->surface_first = calloc(ns, sizeof(int));
    m->surface_vfirst = calloc(ns, sizeof(int));
    m->surface_n = calloc(ns, sizeof(int));
    m->surface_m = calloc(ns, sizeof(int));
    return m->elements && m->vertices && m->vindex && m->surface_first && m->surface_vfirst &&
                   m->surface_n && m->surface_m
               ? 0
               : -1;
}

int mpi_mesh_bcast(rad_mesh *m, const mpi_job *job)
{
    int rank;
    rad_error err;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    rad_status st = RAD_OK;
    if (rank != 0 && mesh_alloc(m, job) != 0)
        st = radi_fail(&err, RAD_ERR_NOMEM, "out of memory for the mesh");
    if (mpi_agree(st, &err) != RAD_OK)
        return -1;
    const size_t ns = (size_t)job->nsurfaces + 1;
    int bad = bcast_bytes(m->elements, (size_t)job->nelements, sizeof *m->elements);
    bad |= bcast_bytes(m->vertices, (size_t)job->nvertices, sizeof *m->vertices);
    bad |= bcast_bytes(m->vindex, (size_t)job->nvindex, sizeof *m->vindex);
    bad |= bcast_bytes(m->surface_first, ns, sizeof(int));
    bad |= bcast_bytes(m->surface_vfirst, ns, sizeof(int));
    bad |= bcast_bytes(m->surface_n, ns, sizeof(int));
    bad |= bcast_bytes(m->surface_m, ns, sizeof(int));
    return bad ? -1 : 0;
}
