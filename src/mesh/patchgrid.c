/* patchgrid.c -- shooting patches: a coarse P x Q grid over each surface.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * See patchgrid.h for the layout.  Two passes over the elements: count
 * the members of each patch, then place them (a counting sort, so each
 * patch lists its elements in mesh order).
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"
#include "mesh/patchgrid.h"
#include "util/util.h"

void radi_patch_grid_free(rad_patch_grid *g)
{
    free(g->first);
    free(g->member);
    free(g->patch_of);
    free(g->surface);
    free(g->area);
    free(g->cfirst);
    free(g->corner);
    memset(g, 0, sizeof *g);
}

/* Patches of surface s along each side: P x Q cut down to its mesh. */
static void surface_grid(const rad_mesh *m, int s, int P, int Q, int *p, int *q)
{
    const int ne = m->surface_first[s + 1] - m->surface_first[s];
    const int one = ne == 1 || radi_mesh_is_fan(m, s); /* a polygon: one patch */
    *p = one ? 1 : P < m->surface_n[s] ? P : m->surface_n[s];
    *q = one ? 1 : Q < m->surface_m[s] ? Q : m->surface_m[s];
}

/* The patch column (row) of grid index g among N cells cut into P parts:
 * the largest k with k N / P <= g. */
static int cell_of(int g, int N, int P)
{
    int k = (int)(((long long)g * P + P - 1) / N);
    while (k > 0 && (long long)k * N / P > g)
        k--;
    while (k + 1 < P && (long long)(k + 1) * N / P <= g)
        k++;
    return k;
}

/* Patch outlines: four grid vertices, or the polygon's own outline. */
static void corners(rad_patch_grid *g, const rad_mesh *m, int s, int p0, int P, int Q)
{
    if (m->surface_first[s + 1] - m->surface_first[s] == 1 || radi_mesh_is_fan(m, s)) {
        radi_mesh_outline(m, s, g->corner + g->cfirst[p0]);
        return;
    }
    const int N = m->surface_n[s], M = m->surface_m[s], v0 = m->surface_vfirst[s];
    for (int pj = 0; pj < Q; pj++)
        for (int pi = 0; pi < P; pi++) {
            const int a0 = pi * N / P, a1 = (pi + 1) * N / P;
            const int b0 = pj * M / Q, b1 = (pj + 1) * M / Q;
            rad_vec3 *c = g->corner + g->cfirst[p0 + pj * P + pi];
            c[0] = m->vertices[v0 + b0 * (N + 1) + a0];
            c[1] = m->vertices[v0 + b0 * (N + 1) + a1];
            c[2] = m->vertices[v0 + b1 * (N + 1) + a1];
            c[3] = m->vertices[v0 + b1 * (N + 1) + a0];
        }
}

static int count_patches(const rad_mesh *m, int P, int Q, int *ncorners)
{
    int np = 0;
    *ncorners = 0;
    for (int s = 0; s < m->nsurfaces; s++) {
        int p, q;
        surface_grid(m, s, P, Q, &p, &q);
        const int e0 = m->surface_first[s];
        const int ne = m->surface_first[s + 1] - e0;
        np += ne > 0 ? p * q : 0;
        *ncorners += ne == 1 || radi_mesh_is_fan(m, s) ? radi_mesh_outline(m, s, NULL)
                     : ne > 1                                ? 4 * p * q
                                                             : 0;
    }
    return np;
}

rad_status radi_patch_grid_build(rad_patch_grid *g, const rad_mesh *m, int P, int Q,
                                rad_error *err)
{
    int nc;
    memset(g, 0, sizeof *g);
    if (P < 1 || Q < 1)
        return radi_fail(err, RAD_ERR_INVALID, "a patch grid needs P, Q >= 1");
    const int np = count_patches(m, P, Q, &nc), n = m->nelements;
    g->npatches = np;
    g->nelements = n;
    g->first = calloc((size_t)np + 1, sizeof *g->first);
    g->member = malloc(sizeof *g->member * (size_t)(n ? n : 1));
    g->patch_of = malloc(sizeof *g->patch_of * (size_t)(n ? n : 1));
    g->surface = malloc(sizeof *g->surface * (size_t)(np ? np : 1));
    g->area = calloc((size_t)(np ? np : 1), sizeof *g->area);
    g->cfirst = malloc(sizeof *g->cfirst * ((size_t)np + 1));
    g->corner = malloc(sizeof *g->corner * (size_t)(nc ? nc : 1));
    if (!g->first || !g->member || !g->patch_of || !g->surface || !g->area || !g->cfirst ||
        !g->corner) {
        radi_patch_grid_free(g);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d patches", np);
    }
    int p0 = 0, c0 = 0;
    for (int s = 0; s < m->nsurfaces; s++) {
        int p, q;
        surface_grid(m, s, P, Q, &p, &q);
        const int e0 = m->surface_first[s], ne = m->surface_first[s + 1] - e0;
        if (ne < 1)
            continue;
        const int one = ne == 1 || radi_mesh_is_fan(m, s);
        for (int k = 0; k < p * q; k++) {
            g->surface[p0 + k] = s;
            g->cfirst[p0 + k] = c0;
            c0 += one ? radi_mesh_outline(m, s, NULL) : 4;
        }
        for (int e = e0; e < e0 + ne; e++) {
            const rad_element *el = &m->elements[e];
            const int k = one ? 0
                                  : cell_of(el->gj, m->surface_m[s], q) * p +
                                        cell_of(el->gi, m->surface_n[s], p);
            g->patch_of[e] = p0 + k;
            g->first[p0 + k + 1]++;
            g->area[p0 + k] += el->area;
        }
        g->cfirst[p0 + p * q] = c0;
        corners(g, m, s, p0, p, q);
        p0 += p * q;
    }
    g->cfirst[np] = c0;
    for (int k = 0; k < np; k++)
        g->first[k + 1] += g->first[k];
    int *fill = malloc(sizeof *fill * (size_t)(np ? np : 1));
    if (!fill) {
        radi_patch_grid_free(g);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %d patches", np);
    }
    memcpy(fill, g->first, sizeof *fill * (size_t)np);
    for (int e = 0; e < n; e++)
        g->member[fill[g->patch_of[e]]++] = e;
    free(fill);
    return RAD_OK;
}
