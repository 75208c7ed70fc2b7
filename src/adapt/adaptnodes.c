/* adaptnodes.c -- the quadtree of every element adaptive subdivision may make.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * See adaptnodes.h for the layout.  The build makes each quad surface's
 * finest lattice of vertices, then its nodes level by level; a polygon
 * surface keeps its one element and vertices as the starting mesh has
 * them.  Areas and centroids are computed from each node's own corners by
 * the mesh's own routine (radi_mesh_area_centroid), so the starting
 * elements' come out as rad_mesh_build made them, and the four children
 * of a node add up to it to round-off.
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "adapt/adaptnodes.h"
#include "mesh/mesh.h"
#include "util/util.h"

void radi_adapt_nodes_free(rad_adapt_nodes *a)
{
    rad_mesh_free(&a->mesh);
    free(a->root);
    free(a->patch);
    free(a->level);
    free(a->cn);
    free(a->cm);
    free(a->splits);
    memset(a, 0, sizeof *a);
}

/* Nodes N M (4^(l) - 1) / 3 before level l of an N x M surface. */
static long long level_offset(int n, int m, int l)
{
    return (long long)n * m * (((1LL << (2 * l)) - 1) / 3);
}

/* Nodes, vertices and vertex indices of surface s of m at depth D. */
static void surface_counts(const rad_mesh *m, int s, int D, int quad, double *ne, double *nv,
                           double *ni)
{
    const int e0 = m->surface_first[s];
    if (!quad) { /* a polygon, alone or cut into triangles: kept as it is */
        for (int e = e0; e < m->surface_first[s + 1]; e++)
            *ni += m->elements[e].nverts;
        *ne += m->surface_first[s + 1] - e0;
        *nv += m->surface_vfirst[s + 1] - m->surface_vfirst[s];
        return;
    }
    const double N = m->surface_n[s], M = m->surface_m[s], k = (double)(1LL << D);
    const double nodes = (double)level_offset((int)N, (int)M, D + 1);
    *ne += nodes;
    *nv += (N * k + 1) * (M * k + 1);
    *ni += 4 * nodes;
}

static rad_status allocate(rad_adapt_nodes *a, const rad_mesh *m, size_t ne, size_t nv,
                           size_t ni, rad_error *err)
{
    const size_t ns = (size_t)m->nsurfaces + 1;
    rad_mesh *t = &a->mesh;
    t->elements = malloc(sizeof *t->elements * (ne ? ne : 1));
    t->vertices = malloc(sizeof *t->vertices * (nv ? nv : 1));
    t->vindex = malloc(sizeof *t->vindex * (ni ? ni : 1));
    t->surface_first = calloc(ns, sizeof(int));
    t->surface_vfirst = calloc(ns, sizeof(int));
    t->surface_n = calloc(ns, sizeof(int));
    t->surface_m = calloc(ns, sizeof(int));
    a->root = malloc(sizeof *a->root * (size_t)(m->nelements ? m->nelements : 1));
    a->patch = malloc(sizeof *a->patch * (ne ? ne : 1));
    a->level = malloc(ne ? ne : 1);
    a->cn = calloc(ns, sizeof(int));
    a->cm = calloc(ns, sizeof(int));
    a->splits = calloc(ns, 1);
    if (!t->elements || !t->vertices || !t->vindex || !t->surface_first || !t->surface_vfirst ||
        !t->surface_n || !t->surface_m || !a->root || !a->patch || !a->level || !a->cn ||
        !a->cm || !a->splits)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %zu adaptive elements", ne);
    return RAD_OK;
}

/* A polygon surface: its one element and vertices, as in m. */
/* A polygon's elements (one, or the triangles it was cut into), each a
 * level-0 patch of its own, with the surface's vertices as they are. */
static void copy_polygon(rad_adapt_nodes *a, const rad_mesh *m, int s, int *ne, int *nv, int *ni)
{
    const int v0 = m->surface_vfirst[s], nverts = m->surface_vfirst[s + 1] - v0;
    for (int v = 0; v < nverts; v++)
        a->mesh.vertices[*nv + v] = m->vertices[v0 + v];
    for (int e0 = m->surface_first[s]; e0 < m->surface_first[s + 1]; e0++) {
        rad_element el = m->elements[e0];
        for (int k = 0; k < el.nverts; k++)
            a->mesh.vindex[*ni + k] = *nv + m->vindex[el.first + k] - v0;
        el.first = *ni;
        a->mesh.elements[*ne] = el;
        a->root[e0] = *ne;
        a->patch[*ne] = e0;
        a->level[*ne] = 0;
        *ni += el.nverts;
        *ne += 1;
    }
    if (radi_mesh_is_fan(m, s)) { /* smoothing and outlines know it so */
        a->mesh.surface_n[s] = m->surface_n[s];
        a->mesh.surface_m[s] = 0;
    }
    *nv += nverts;
}

/* Node (l, i, j) of quad surface s: corners, area, centroid, material. */
static void make_node(rad_adapt_nodes *a, const rad_mesh *m, int s, int l, int i, int j,
                      int *ne, int *ni)
{
    const int D = a->depth, N = a->cn[s], w = 1 << (D - l), W = (N << D) + 1;
    const int v0 = a->mesh.surface_vfirst[s];
    const int e0 = m->surface_first[s] + (j >> l) * N + (i >> l); /* the starting element */
    rad_element *el = &a->mesh.elements[*ne];
    int *idx = &a->mesh.vindex[*ni];
    rad_vec3 p[4];
    *el = m->elements[e0];
    idx[0] = v0 + j * w * W + i * w;
    idx[1] = idx[0] + w;
    idx[2] = idx[1] + w * W;
    idx[3] = idx[0] + w * W;
    for (int k = 0; k < 4; k++)
        p[k] = a->mesh.vertices[idx[k]];
    el->gi = i;
    el->gj = j;
    el->nverts = 4;
    el->first = *ni;
    radi_mesh_area_centroid(p, 4, el->normal, &el->area, &el->centroid);
    a->patch[*ne] = e0;
    a->level[*ne] = (unsigned char)l;
    if (l == 0)
        a->root[e0] = *ne;
    *ni += 4;
    *ne += 1;
}

/* A quad surface: the finest lattice (from the starting mesh's corners,
 * which are the quad's own), then the nodes level by level. */
static void build_quad(rad_adapt_nodes *a, const rad_mesh *m, int s, int *ne, int *nv, int *ni)
{
    const int N = m->surface_n[s], M = m->surface_m[s], D = a->depth;
    const int NF = N << D, MF = M << D, u0 = m->surface_vfirst[s];
    const rad_vec3 q[4] = {m->vertices[u0], m->vertices[u0 + N],
                           m->vertices[u0 + M * (N + 1) + N], m->vertices[u0 + M * (N + 1)]};
    a->splits[s] = 1;
    a->mesh.surface_n[s] = NF;
    a->mesh.surface_m[s] = MF;
    for (int y = 0; y <= MF; y++)
        for (int x = 0; x <= NF; x++)
            a->mesh.vertices[(*nv)++] = radi_mesh_bilinear(q, (double)x / NF, (double)y / MF);
    for (int l = 0; l <= D; l++)
        for (int j = 0; j < M << l; j++)
            for (int i = 0; i < N << l; i++)
                make_node(a, m, s, l, i, j, ne, ni);
}

rad_status radi_adapt_nodes_build(rad_adapt_nodes *a, const rad_mesh *m, int depth,
                                 rad_error *err)
{
    double ne = 0, nv = 0, ni = 0;
    memset(a, 0, sizeof *a);
    if (depth < 0 || depth > 15)
        return radi_fail(err, RAD_ERR_INVALID, "the adaptive depth must be 0 to 15, not %d", depth);
    a->depth = depth;
    a->npatches = m->nelements;
    for (int s = 0; s < m->nsurfaces; s++) {
        const int cnt = m->surface_first[s + 1] - m->surface_first[s];
        const int quad = cnt > 0 && m->elements[m->surface_first[s]].nverts == 4 &&
                         m->surface_n[s] * m->surface_m[s] == cnt;
        surface_counts(m, s, quad ? depth : 0, quad, &ne, &nv, &ni);
    }
    if (ne > RAD_ADAPT_MAX_NODES || nv > RAD_ADAPT_MAX_NODES * 4.0)
        return radi_fail(err, RAD_ERR_TOOBIG,
                        "adaptive subdivision to depth %d of %d elements may make %.0f "
                        "elements, more than %d; use a smaller `max_depth` or a coarser `mesh`",
                        depth, m->nelements, ne, RAD_ADAPT_MAX_NODES);
    rad_status st = allocate(a, m, (size_t)ne, (size_t)nv, (size_t)ni, err);
    if (st != RAD_OK) {
        radi_adapt_nodes_free(a);
        return st;
    }
    int e = 0, v = 0, k = 0;
    a->mesh.nsurfaces = m->nsurfaces;
    for (int s = 0; s < m->nsurfaces; s++) {
        const int cnt = m->surface_first[s + 1] - m->surface_first[s];
        a->mesh.surface_first[s] = e;
        a->mesh.surface_vfirst[s] = v;
        a->cn[s] = m->surface_n[s];
        a->cm[s] = m->surface_m[s];
        a->mesh.surface_n[s] = a->mesh.surface_m[s] = 1;
        if (cnt > 0 && m->elements[m->surface_first[s]].nverts == 4 &&
            m->surface_n[s] * m->surface_m[s] == cnt)
            build_quad(a, m, s, &e, &v, &k);
        else if (cnt > 0)
            copy_polygon(a, m, s, &e, &v, &k);
    }
    a->mesh.surface_first[m->nsurfaces] = e;
    a->mesh.surface_vfirst[m->nsurfaces] = v;
    a->mesh.nelements = e;
    a->mesh.nvertices = v;
    return RAD_OK;
}

int radi_adapt_at(const rad_adapt_nodes *a, int s, int l, int x, int y)
{
    const int N = a->cn[s], M = a->cm[s], sh = a->depth - l;
    return a->mesh.surface_first[s] + (int)level_offset(N, M, l) + (y >> sh) * (N << l) +
           (x >> sh);
}

void radi_adapt_box(const rad_adapt_nodes *a, int node, int *x0, int *y0, int *w)
{
    const rad_element *el = &a->mesh.elements[node];
    *w = 1 << (a->depth - a->level[node]);
    *x0 = el->gi * *w;
    *y0 = el->gj * *w;
}

int radi_adapt_child(const rad_adapt_nodes *a, int node, int k)
{
    const rad_element *el = &a->mesh.elements[node];
    const int s = el->surface, l = a->level[node] + 1, sh = a->depth - l;
    return radi_adapt_at(a, s, l, (2 * el->gi + (k & 1)) << sh, (2 * el->gj + (k >> 1)) << sh);
}
