/* adaptmesh.c -- the adaptive mesh as the outputs see it: conforming leaves.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * See adaptmesh.h for the rules.  Four passes over the leaves: mark the
 * lattice points that are corners (the vertices), number them, write each
 * leaf's polygon walking its boundary counter-clockwise and taking every
 * vertex met, then the vertex radiosity (means at corners, then the
 * hanging vertices by level, largest leaves first).  Work is linear in
 * the leaves' perimeters in lattice units.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adapt/adaptmesh.h"
#include "util/util.h"

#define NB RAD_BANDS

typedef struct lattice {
    const rad_adapt_nodes *a;
    const unsigned char *leaf;
    int *vnum;                  /* lattice point -> output vertex, or -1 */
} lattice;

/* Lattice point (x, y) of quad surface s, as an index into a->mesh.vertices. */
static int lat(const rad_adapt_nodes *a, int s, int x, int y)
{
    return a->mesh.surface_vfirst[s] + y * (a->mesh.surface_n[s] + 1) + x;
}

/* The k-th point (0 <= k < 4w) of the boundary walk of the box (x0, y0, w),
 * counter-clockwise from (x0, y0): bottom, right, top, left. */
static void walk(int x0, int y0, int w, int k, int *x, int *y)
{
    const int side = k / w, t = k % w;
    *x = side == 0 ? x0 + t : side == 1 ? x0 + w : side == 2 ? x0 + w - t : x0;
    *y = side == 0 ? y0 : side == 1 ? y0 + t : side == 2 ? y0 + w : y0 + w - t;
}

/* How many vertices the leaf's polygon has (and, with idx, write them). */
static int leaf_polygon(const lattice *L, int node, int *idx)
{
    const rad_adapt_nodes *a = L->a;
    const rad_element *el = &a->mesh.elements[node];
    int n = 0;
    if (!a->splits[el->surface]) {
        for (int k = 0; k < el->nverts; k++, n++)
            if (idx)
                idx[n] = L->vnum[a->mesh.vindex[el->first + k]];
        return n;
    }
    int x0, y0, w;
    radi_adapt_box(a, node, &x0, &y0, &w);
    for (int k = 0; k < 4 * w; k++) {
        int x, y;
        walk(x0, y0, w, k, &x, &y);
        const int v = L->vnum[lat(a, el->surface, x, y)];
        if (v >= 0 && idx)
            idx[n] = v;
        n += v >= 0;
    }
    return n;
}

/* Number the corners of the leaves, surface by surface. */
static int number_vertices(lattice *L, rad_mesh *out)
{
    const rad_adapt_nodes *a = L->a;
    const rad_mesh *t = &a->mesh;
    int nv = 0;
    for (int v = 0; v < t->nvertices; v++)
        L->vnum[v] = -1;
    for (int e = 0; e < t->nelements; e++)
        if (L->leaf[e])
            for (int k = 0; k < t->elements[e].nverts; k++)
                L->vnum[t->vindex[t->elements[e].first + k]] = 0;
    for (int s = 0; s < t->nsurfaces; s++) {
        out->surface_vfirst[s] = nv;
        for (int v = t->surface_vfirst[s]; v < t->surface_vfirst[s + 1]; v++)
            if (L->vnum[v] == 0)
                L->vnum[v] = nv++;
    }
    out->surface_vfirst[t->nsurfaces] = nv;
    return nv;
}

static rad_status alloc_out(rad_mesh *o, int ns, int ne, int nv, size_t ni, rad_error *err)
{
    o->elements = malloc(sizeof *o->elements * (size_t)(ne ? ne : 1));
    o->vertices = malloc(sizeof *o->vertices * (size_t)(nv ? nv : 1));
    o->vindex = malloc(sizeof *o->vindex * (ni ? ni : 1));
    o->surface_first = calloc((size_t)ns + 1, sizeof(int));
    o->surface_n = calloc((size_t)ns + 1, sizeof(int));
    o->surface_m = calloc((size_t)ns + 1, sizeof(int));
    if (!o->elements || !o->vertices || !o->vindex || !o->surface_first || !o->surface_n ||
        !o->surface_m)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the adaptive mesh");
    return RAD_OK;
}

/* Elements, vertex lists, vertices and the leaves' B and levels. */
static rad_status fill_mesh(const lattice *L, const double *Bn, rad_mesh *o, double *B,
                            int *level, rad_error *err)
{
    const rad_adapt_nodes *a = L->a;
    const rad_mesh *t = &a->mesh;
    const size_t nn = (size_t)t->nelements;
    int ne = 0;
    size_t ni = 0;
    for (int e = 0; e < t->nelements; e++)
        if (L->leaf[e]) {
            ne++;
            ni += (size_t)leaf_polygon(L, e, NULL);
        }
    rad_status st = alloc_out(o, t->nsurfaces, ne, o->nvertices, ni, err);
    if (st != RAD_OK)
        return st;
    for (int v = 0; v < t->nvertices; v++)
        if (L->vnum[v] >= 0)
            o->vertices[L->vnum[v]] = t->vertices[v];
    int k = 0, f = 0;
    for (int s = 0; s < t->nsurfaces; s++) {
        o->surface_first[s] = k;
        o->surface_n[s] = t->surface_n[s];
        o->surface_m[s] = t->surface_m[s];
        for (int e = t->surface_first[s]; e < t->surface_first[s + 1]; e++) {
            if (!L->leaf[e])
                continue;
            rad_element *el = &o->elements[k];
            *el = t->elements[e];
            el->first = f;
            el->nverts = leaf_polygon(L, e, o->vindex + f);
            f += el->nverts;
            level[k] = a->level[e];
            for (int b = 0; b < NB; b++)
                B[(size_t)k + (size_t)b * (size_t)ne] = Bn[(size_t)e + (size_t)b * nn];
            k++;
        }
    }
    o->surface_first[t->nsurfaces] = k;
    o->nelements = ne;
    return RAD_OK;
}

/* Corner means: every output vertex the mean of the leaves it is a corner of. */
static rad_status corner_means(const lattice *L, const rad_mesh *o, const double *B, double *Bv)
{
    const size_t nv = (size_t)o->nvertices, ne = (size_t)o->nelements;
    const rad_adapt_nodes *a = L->a;
    int *cnt = calloc(nv ? nv : 1, sizeof *cnt);
    if (!cnt)
        return RAD_ERR_NOMEM;
    memset(Bv, 0, sizeof *Bv * nv * NB);
    for (size_t e = 0, k = 0; e < (size_t)a->mesh.nelements; e++) {
        if (!L->leaf[e])
            continue;
        const rad_element *el = &a->mesh.elements[e];
        for (int c = 0; c < el->nverts; c++) {
            const int v = L->vnum[a->mesh.vindex[el->first + c]];
            cnt[v]++;
            for (int b = 0; b < NB; b++)
                Bv[(size_t)v + b * nv] += B[k + b * ne];
        }
        k++;
    }
    for (size_t v = 0; v < nv; v++)
        for (int b = 0; b < NB; b++)
            Bv[v + b * nv] = cnt[v] > 0 ? fmax(Bv[v + b * nv] / cnt[v], 0) : 0;
    free(cnt);
    return RAD_OK;
}

/* Hanging vertices on the edges of the leaves of level l: interpolated
 * along the edge between its corners (adaptmesh.h). */
static void hanging(const lattice *L, int l, const rad_mesh *o, double *Bv)
{
    const rad_adapt_nodes *a = L->a;
    const size_t nv = (size_t)o->nvertices;
    for (int e = 0; e < a->mesh.nelements; e++) {
        const int s = a->mesh.elements[e].surface;
        if (!L->leaf[e] || a->level[e] != l || !a->splits[s])
            continue;
        int x0, y0, w;
        radi_adapt_box(a, e, &x0, &y0, &w);
        for (int side = 0; side < 4; side++) {
            int px, py, qx, qy;
            walk(x0, y0, w, side * w, &px, &py);
            walk(x0, y0, w, (side + 1) % 4 * w, &qx, &qy);
            const int P = L->vnum[lat(a, s, px, py)], Q = L->vnum[lat(a, s, qx, qy)];
            for (int t = 1; t < w; t++) {
                int x, y;
                walk(x0, y0, w, side * w + t, &x, &y);
                const int v = L->vnum[lat(a, s, x, y)];
                const double u = (double)t / w;
                for (int b = 0; v >= 0 && b < NB; b++)
                    Bv[(size_t)v + b * nv] = (1 - u) * Bv[(size_t)P + b * nv] +
                                             u * Bv[(size_t)Q + b * nv];
            }
        }
    }
}

rad_status radi_adapt_leaf_mesh(const rad_adapt_nodes *a, const unsigned char *leaf,
                               const double *Bn, rad_mesh *out, double **B, double **Bv,
                               int **level, rad_error *err)
{
    const rad_mesh *t = &a->mesh;
    lattice L = {a, leaf, malloc(sizeof(int) * (size_t)(t->nvertices ? t->nvertices : 1))};
    int ne = 0;
    memset(out, 0, sizeof *out);
    *B = *Bv = NULL;
    *level = NULL;
    for (int e = 0; e < t->nelements; e++)
        ne += leaf[e] != 0;
    out->nsurfaces = t->nsurfaces;
    out->surface_vfirst = calloc((size_t)t->nsurfaces + 1, sizeof(int));
    *B = malloc(sizeof **B * (size_t)(ne ? ne : 1) * NB);
    *level = malloc(sizeof **level * (size_t)(ne ? ne : 1));
    rad_status st = L.vnum && out->surface_vfirst && *B && *level ? RAD_OK : RAD_ERR_NOMEM;
    if (st == RAD_OK) {
        out->nvertices = number_vertices(&L, out);
        st = fill_mesh(&L, Bn, out, *B, *level, err);
    }
    if (st == RAD_OK && !(*Bv = malloc(sizeof **Bv * (size_t)(out->nvertices + 1) * NB)))
        st = RAD_ERR_NOMEM;
    if (st == RAD_OK)
        st = corner_means(&L, out, *B, *Bv);
    for (int l = 0; st == RAD_OK && l <= a->depth; l++)
        hanging(&L, l, out, *Bv);
    free(L.vnum);
    if (st == RAD_ERR_NOMEM)
        radi_fail(err, st, "out of memory for the adaptive mesh");
    if (st != RAD_OK) {
        rad_mesh_free(out);
        free(*B);
        free(*Bv);
        free(*level);
        *B = *Bv = NULL;
        *level = NULL;
    }
    return st;
}
