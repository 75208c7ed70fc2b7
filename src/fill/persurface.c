/* persurface.c -- surface-to-surface form factors (persurface.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The quantity thermal engineers tabulate: the fraction of what leaves
 * surface S that arrives on surface K, whatever the mesh.  Sums run column
 * by column (F is column-major, so each column is read once, in order):
 * for element j of surface K and each surface S, the partial sum over the
 * elements i of S of A_i F_ij is formed apart and then added to F_SK, so
 * each result carries the round-off of n_S + n_K additions, not n_S n_K.
 * The closed forms of the unit cube (opposite walls 0.1998..., adjacent
 * 0.2000...) and the closure sum_K F_SK = 1 test it (tests/commands/persurface.sh).
 */
#include <config.h>

#include <string.h>

#include "fill/persurface.h"

/* sum_{i in S} A_i x_i over the elements of surface S, for one column x. */
static double weighted(const rad_mesh *m, int S, const double *x)
{
    double s = 0;
    for (int i = m->surface_first[S]; i < m->surface_first[S + 1]; i++)
        s += m->elements[i].area * x[i];
    return s;
}

/* M_SK = sum_{i in S} sum_{j in K} A_i X_ij, then row S divided by A_S. */
static void sums(const rad_mesh *m, const double *X, double *MS, const double *AS)
{
    const size_t n = (size_t)m->nelements, ns = (size_t)m->nsurfaces;
    memset(MS, 0, ns * ns * sizeof *MS);
    for (size_t j = 0; j < n; j++) {
        const size_t K = (size_t)m->elements[j].surface;
        for (size_t S = 0; S < ns; S++)
            MS[S + K * ns] += weighted(m, (int)S, X + j * n);
    }
    for (size_t S = 0; S < ns; S++)
        for (size_t K = 0; K < ns; K++)
            MS[S + K * ns] = AS[S] > 0 ? MS[S + K * ns] / AS[S] : 0;
}

void radi_ff_surfaces(const rad_mesh *m, const double *F, const double *E, double *FS,
                     double *ES, double *AS)
{
    for (int S = 0; S < m->nsurfaces; S++) {
        AS[S] = 0;
        for (int i = m->surface_first[S]; i < m->surface_first[S + 1]; i++)
            AS[S] += m->elements[i].area;
    }
    sums(m, F, FS, AS);
    if (E && ES)
        sums(m, E, ES, AS);
}
