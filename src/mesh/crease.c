/* crease.c -- vertex radiosity across surfaces that meet smoothly.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Goral et al. 1984 smooth inside each surface only: walls of different
 * colours meet at a crease, and a vertex keeps one value per surface.  A
 * model from a modelling tool is another matter: a curved or flat face is
 * many triangles, each its own surface, and shading that stops at every
 * triangle's edge shows the facets.  Renderers smooth across faces whose
 * normals differ by less than a crease angle (Gouraud 1971; the "auto
 * smooth" angle of modelling tools, 30 degrees in Blender).  Here: mesh
 * vertices at one point on surfaces of one object (the scene's `object`,
 * an OBJ file's o or g; the surfaces outside every object are one more),
 * of the same material (reflectance and emission), whose unit normals
 * make an angle of less than the crease angle (so never the two sides of
 * a sheet) take the mean of their values, each weighted by the area of
 * its surface's elements that meet there.  Faces of one OBJ object that
 * share a vertex meet at its point, so they are smoothed across; so are
 * faces of the object that touch without sharing one (a vertex written
 * twice), as a modelling tool's "merge by distance" would join them.
 * Separate objects never mix: a box standing on a floor of its colour
 * keeps its own edge.  Where two such surfaces share an edge cut into
 * different parts (--max-element-size cuts each face by its own size),
 * the points one side lacks then follow the points both have
 * (creaseedge.c), so the two sides agree all along the edge.
 *
 * One point: the same cell of a grid 2^-30 of the scene's size, far
 * above the rounding of a point computed along an edge from either end
 * (an ulp) and far below any element (a point within a few ulps of a
 * cell's side may fall on the other; at 1e-7 of a scene's size that is
 * left to chance).  The angle test is made for each vertex against each
 * other one, so a fan of faces turning gradually round a point is
 * smoothed pairwise, never across a sharp edge.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "util/util.h"

typedef struct vkey {
    long long q[3];             /* the point on a grid of cells 2^-30 of the scene */
    int v, surface;
} vkey;

static int by_point(const void *a, const void *b)
{
    const vkey *x = a, *y = b;
    for (int k = 0; k < 3; k++)
        if (x->q[k] != y->q[k])
            return x->q[k] < y->q[k] ? -1 : 1;
    return x->v - y->v;
}

static int same_point(const vkey *a, const vkey *b)
{
    return a->q[0] == b->q[0] && a->q[1] == b->q[1] && a->q[2] == b->q[2];
}

/* Are surfaces a and b (their first elements) of one object and one
 * material? */
static int same_kind(const rad_scene *scene, const rad_mesh *m, int a, int b)
{
    const rad_element *x = &m->elements[m->surface_first[a]];
    const rad_element *y = &m->elements[m->surface_first[b]];
    return scene->surfaces[a].object == scene->surfaces[b].object &&
           memcmp(x->reflect, y->reflect, sizeof x->reflect) == 0 &&
           memcmp(x->emit, y->emit, sizeof x->emit) == 0;
}

/* The unit normal of surface s (its first element's). */
static rad_vec3 normal_of(const rad_mesh *m, int s)
{
    return m->elements[m->surface_first[s]].normal;
}

/* May surfaces a and b be smoothed across: one object, one material,
 * normals less than the crease angle apart? */
static int smooth_pair(const rad_scene *scene, const rad_mesh *m, int a, int b,
                       double cos_crease)
{
    return same_kind(scene, m, a, b) && v3_dot(normal_of(m, a), normal_of(m, b)) > cos_crease;
}

/* Does every pair of the k vertices at one point pass smooth_pair?  Then
 * each takes the mean of all k, in O(k) rather than the O(k^2) of testing
 * the pairs (a fan of thousands of faces round one point).  A sufficient
 * test: one object and material, and every normal less than half the
 * crease angle from their mean direction u, since the angle between two
 * normals is at most the sum of their angles to u (the triangle
 * inequality on the sphere; a pair within rounding of the crease angle
 * may go either way, as it may in the pairwise test).  When it fails the
 * pairs are tested. */
static int all_pairs(const rad_scene *scene, const rad_mesh *m, const vkey *key, size_t k,
                     double cos_crease)
{
    const double cos_half = sqrt(0.5 * (1 + cos_crease)); /* cos(a/2), a <= 180 */
    rad_vec3 u = {0, 0, 0};
    for (size_t j = 0; j < k; j++) {
        if (!same_kind(scene, m, key[0].surface, key[j].surface))
            return 0;
        u = v3_add(u, normal_of(m, key[j].surface));
    }
    const double len = sqrt(v3_dot(u, u));
    if (!(len > 0))
        return 0;
    for (size_t j = 0; j < k; j++) {
        if (!(v3_dot(normal_of(m, key[j].surface), u) / len > cos_half))
            return 0;
    }
    return 1;
}

/* Every vertex of the point takes the weighted mean of all k, summed in
 * the order the pairwise loop sums them, so where every pair passes the
 * two routes agree to the bit. */
static void mean_all(const vkey *key, size_t k, const double *w, const double *Bv, size_t nv,
                     double *out)
{
    double sum[RAD_BANDS] = {0}, wsum = 0;
    for (size_t j = 0; j < k; j++) {
        wsum += w[key[j].v];
        for (int b = 0; b < RAD_BANDS; b++)
            sum[b] += w[key[j].v] * Bv[(size_t)key[j].v + (size_t)b * nv];
    }
    for (size_t i = 0; wsum > 0 && i < k; i++)
        for (int b = 0; b < RAD_BANDS; b++)
            out[(size_t)key[i].v + (size_t)b * nv] = sum[b] / wsum;
}

/* The keys of the vertices of surfaces with elements and finite points;
 * returns how many. */
static size_t make_keys(const rad_mesh *m, vkey *key, double *cell_out)
{
    rad_vec3 lo, hi;
    v3_bounds(m->vertices, m->nvertices, &lo, &hi);
    const double size = v3_maxabs(v3_sub(hi, lo));
    const double cell = size > 0 && isfinite(size) ? ldexp(size, -30) : 1;
    *cell_out = cell;
    size_t n = 0;
    for (int s = 0; s < m->nsurfaces; s++) {
        if (m->surface_first[s + 1] == m->surface_first[s])
            continue;
        for (int v = m->surface_vfirst[s]; v < m->surface_vfirst[s + 1]; v++) {
            const rad_vec3 p = v3_sub(m->vertices[v], lo);
            const double c[3] = {p.x / cell, p.y / cell, p.z / cell};
            if (!(isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2])))
                continue;
            key[n] = (vkey){{llround(c[0]), llround(c[1]), llround(c[2])}, v, s};
            n++;
        }
    }
    return n;
}

double rad_crease_default(const rad_scene *scene)
{
    return scene->format == RAD_SCENE_FORMAT_OBJ ? RAD_CREASE_OBJ : 0;
}

typedef struct join_ctx {
    const rad_scene *scene;
    const rad_mesh *m;
    double cos_crease;
} join_ctx;

static int may_join(const void *ctx, int s, int t)
{
    const join_ctx *j = ctx;
    return smooth_pair(j->scene, j->m, s, t, j->cos_crease);
}

/* The values at each point (sorted keys [0, nk)) merged into out. */
static void merge_points(const rad_scene *scene, const rad_mesh *m, const vkey *key, size_t nk,
                         double cos_crease, const double *w, const double *Bv, double *out)
{
    const size_t nv = (size_t)m->nvertices;
    for (size_t g = 0, h; g < nk; g = h) {
        for (h = g + 1; h < nk && same_point(&key[g], &key[h]); h++)
            ; /* [g, h): one point */
        if (h - g > 2 && all_pairs(scene, m, key + g, h - g, cos_crease)) {
            mean_all(key + g, h - g, w, Bv, nv, out);
            continue;
        }
        for (size_t i = g; h - g > 1 && i < h; i++) {
            double sum[RAD_BANDS] = {0}, wsum = 0;
            for (size_t j = g; j < h; j++) {
                if (j != i && !smooth_pair(scene, m, key[i].surface, key[j].surface, cos_crease))
                    continue;
                wsum += w[key[j].v];
                for (int b = 0; b < RAD_BANDS; b++)
                    sum[b] += w[key[j].v] * Bv[(size_t)key[j].v + (size_t)b * nv];
            }
            for (int b = 0; wsum > 0 && b < RAD_BANDS; b++)
                out[(size_t)key[i].v + (size_t)b * nv] = sum[b] / wsum;
        }
    }
}

/* creaseedge.c on the points of the sorted keys: hanging points of edges
 * that two surfaces cut differently follow the points both have.  The
 * tolerance, 4 cells, is well above the rounding of a point computed
 * from either end of its edge and far below any element. */
static rad_status follow_edges(const rad_scene *scene, const rad_mesh *m, const vkey *key,
                               size_t nk, double cos_crease, double cell, double *out,
                               rad_error *err)
{
    const size_t nv = (size_t)m->nvertices;
    int *point_of = malloc(sizeof *point_of * nv), *surface = malloc(sizeof *surface * (nk + 1));
    size_t *first = malloc(sizeof *first * (nk + 1));
    rad_status st = RAD_OK;
    if (!point_of || !surface || !first) {
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory to smooth %zu vertices", nv);
        goto done;
    }
    for (size_t v = 0; v < nv; v++)
        point_of[v] = -1;
    size_t np = 0;
    for (size_t g = 0; g < nk; g++) {
        if (g == 0 || !same_point(&key[g - 1], &key[g]))
            first[np++] = g;
        point_of[key[g].v] = (int)(np - 1);
        surface[g] = key[g].surface;
    }
    first[np] = nk;
    const join_ctx ctx = {scene, m, cos_crease};
    const radi_crease_points cp = {point_of, first, surface, may_join, &ctx};
    st = radi_crease_edges(m, &cp, 4 * cell, out, err);
done:
    free(point_of);
    free(surface);
    free(first);
    return st;
}

rad_status rad_smooth_across(const rad_scene *scene, const rad_mesh *m, double crease_degrees,
                             double *Bv, rad_error *err)
{
    if (crease_degrees < 0) /* RAD_CREASE_AUTO */
        crease_degrees = rad_crease_default(scene);
    if (!(crease_degrees > 0) || m->nvertices == 0)
        return RAD_OK;
    if (m->nsurfaces != scene->nsurfaces)
        return radi_fail(err, RAD_ERR_INVALID, "a mesh of %d surfaces smoothed with a scene "
                                               "of %d", m->nsurfaces, scene->nsurfaces);
    const size_t nv = (size_t)m->nvertices;
    const double cos_crease = cos(fmin(crease_degrees, 180) * M_PI / 180);
    vkey *key = malloc(sizeof *key * nv);
    double *w = calloc(nv, sizeof *w), *out = malloc(sizeof *out * nv * RAD_BANDS);
    if (!key || !w || !out) {
        free(key);
        free(w);
        free(out);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory to smooth %zu vertices", nv);
    }
    for (int e = 0; e < m->nelements; e++) /* each vertex's weight: its elements' area */
        for (int k = 0; k < m->elements[e].nverts; k++)
            w[m->vindex[m->elements[e].first + k]] += m->elements[e].area;
    double cell;
    const size_t nk = make_keys(m, key, &cell);
    qsort(key, nk, sizeof *key, by_point);
    memcpy(out, Bv, sizeof *out * nv * RAD_BANDS);
    merge_points(scene, m, key, nk, cos_crease, w, Bv, out);
    rad_status st = follow_edges(scene, m, key, nk, cos_crease, cell, out, err);
    if (st == RAD_OK)
        memcpy(Bv, out, sizeof *out * nv * RAD_BANDS);
    free(key);
    free(w);
    free(out);
    return st;
}
