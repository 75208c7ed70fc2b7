/* reported.c -- the rows of the reported form factors, and F reduced to
 * them (radiosity/mesh.h: rad_mesh_reported, rad_mesh_reduce).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The program reports one row and column per element, except for View3D
 * input (NISTIR 6925, "View3D User Manual"; View3D 3.2's v3main.c), whose
 * output has none for obstruction-only surfaces (O lines) and one for each
 * combination of surfaces (an S line's CMB names the earlier surface it
 * joins): View3D's Combine (viewpp.c) adds the interchange areas A F of
 * the joining surface into the row and column of the one it joins, the
 * self-exchange included, adds the areas, and drops the joiner.  That is
 * the additivity of form factors (Siegel & Howell, "Thermal Radiation Heat
 * Transfer", the factor from and to a sum of areas), which is what is
 * computed here for any mesh: each element maps to a row, and the element
 * matrix is summed into the rows' matrix with area weights.
 *
 * The reduction works in place.  Rows are numbered in element order and a
 * row is never after its first element (row[e] <= e), so output column J
 * (k doubles from J*k) lies before input column j (n doubles from j*n)
 * for every member j of a later group: columns are reduced in order, each
 * into a scratch column first, and nothing still to be read is
 * overwritten (tests/commands/combine.sh checks the results against
 * closed forms).
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/scene.h"
#include "util/util.h"

/* The surface whose row surface s joins (View3D's CMB), or -1. */
static int joins(const rad_scene *scene, int s)
{
    const rad_surface *f = &scene->surfaces[s];
    const int t = f->combine;
    if (f->obstruction || t < 0 || t >= s)
        return -1;
    const rad_surface *g = &scene->surfaces[t];
    return g->obstruction || g->combine >= 0 ? -1 : t;
}

/* Set the elements of surface s to row r. */
static void rows_of(const rad_mesh *mesh, int s, int r, int *row)
{
    for (int e = mesh->surface_first[s]; e < mesh->surface_first[s + 1]; e++)
        row[e] = r;
}

int rad_mesh_reported(const rad_scene *scene, const rad_mesh *mesh, int *row)
{
    const int ns = mesh->nsurfaces;
    int k = 0;
    /* first pass: 1 at the first element of each group's own surface
     * (every surface has an element: rad_mesh_build makes at least one) */
    memset(row, 0, sizeof *row * (size_t)mesh->nelements);
    for (int s = 0; s < ns; s++) {
        const int t = joins(scene, s);
        if (t >= 0)
            row[mesh->surface_first[t]] = 1;
    }
    /* second pass, in order: a group's row is made at its first element */
    for (int s = 0; s < ns; s++) {
        const int first = mesh->surface_first[s], end = mesh->surface_first[s + 1];
        const int t = joins(scene, s);
        if (first == end)
            continue;
        if (scene->surfaces[s].obstruction)
            rows_of(mesh, s, -1, row);
        else if (t >= 0)
            rows_of(mesh, s, row[mesh->surface_first[t]], row);
        else if (row[first] == 1)
            rows_of(mesh, s, k++, row);
        else
            for (int e = first; e < end; e++)
                row[e] = k++;
    }
    return k;
}

/* Column by column, X (n x n) into its first k x k doubles: w[i] the
 * weight of element i (A_i, or 1 alone in its row), d[I] row I's divisor
 * (A_I, or 1), col k doubles of scratch. */
static void reduce_matrix(const int *row, size_t n, size_t k, const double *w,
                          const double *d, double *X, double *col)
{
    for (size_t J = 0; J < k; J++) {
        memset(col, 0, sizeof *col * k);
        for (size_t j = J; j < n; j++) {
            if (row[j] != (int)J)
                continue;
            const double *x = X + j * n;
            for (size_t i = 0; i < n; i++)
                if (row[i] >= 0)
                    col[row[i]] += w[i] * x[i];
        }
        for (size_t I = 0; I < k; I++)
            X[I + J * k] = col[I] / d[I];
    }
}

rad_status rad_mesh_reduce(const rad_mesh *mesh, const int *row, int k, double *F, double *E,
                           double *area, rad_error *err)
{
    const size_t n = (size_t)mesh->nelements, kk = k > 0 ? (size_t)k : 0;
    double *w = malloc(sizeof *w * (n + 2 * kk + 1));
    int *count = calloc(kk + 1, sizeof *count);
    if (!w || !count) {
        free(w);
        free(count);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory reducing %zu x %zu form factors",
                         n, n);
    }
    double *d = w + n, *col = d + kk;
    for (size_t I = 0; I < kk; I++)
        area[I] = 0;
    for (size_t i = 0; i < n; i++)
        if (row[i] >= 0) {
            area[row[i]] += mesh->elements[i].area;
            count[row[i]]++;
        }
    for (size_t I = 0; I < kk; I++)
        d[I] = count[I] > 1 ? area[I] : 1;
    for (size_t i = 0; i < n; i++)
        w[i] = row[i] >= 0 && count[row[i]] > 1 ? mesh->elements[i].area : 1;
    reduce_matrix(row, n, kk, w, d, F, col);
    if (E)
        reduce_matrix(row, n, kk, w, d, E, col);
    free(w);
    free(count);
    return RAD_OK;
}
