/* meshtri.c -- a polygon cut into equal triangles.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A triangle (a, B, C) with `n` parts per edge becomes n^2 triangles of
 * equal area, similar to it: the lattice points
 *     P(i, j) = (1 - j/r) A_r + (j/r) C_r,   A_r = a + (r/n)(B - a),
 *                                             C_r = a + (r/n)(C - a),
 * r = i + j <= n, each computed with the ends exact (lerp_ends), and the
 * triangles (i, j) (i+1, j) (i, j+1) for i + j < n and (i+1, j) (i+1, j+1)
 * (i, j+1) for i + j < n - 1, counter-clockwise as (a, B, C) is.  Goral
 * et al. 1984 meshed quadrilaterals into equal elements; this is the same
 * for the triangles of a modelling tool's export.
 *
 * A convex polygon of K > 3 vertices is first cut into the K triangles
 * (c, v_k, v_k+1) around its centroid c (for a disk, K equal sectors),
 * a triangle is its own fan (a = v_0, one triangle (v_0, v_1, v_2)).  The
 * edges from the apex (spokes) are shared by two triangles of the fan:
 * their points are made once, by the same formula from the same ends, so
 * that the elements of the surface share their vertices (smoothing needs
 * them) and the surface has no cracks.
 *
 * Vertex layout of the surface: its K corners, in order (the surface's
 * outline: radi_mesh_outline), the apex when it is the centroid, the
 * inner points of each spoke, then per triangle the inner points of its
 * outer edge and its interior points.  Element (gi, gj) is triangle gj of
 * fan triangle gi.  The surface's grid size is (n, 0): 0 says that it is
 * not a grid of quadrilaterals (radi_mesh_is_fan).
 */
#include <config.h>

#include <string.h>

#include "mesh/mesh.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/scene.h"
#include "util/util.h"

/* Fan triangles and spokes of a K-gon: K = 3 is one triangle with two
 * spokes (from v_0), K > 3 is K triangles around the centroid with K
 * spokes (the last triangle's second spoke is the first's). */
static int fan_triangles(int K)
{
    return K == 3 ? 1 : K;
}

static int fan_spokes(int K)
{
    return K == 3 ? 2 : K;
}

void radi_mesh_fan_count(int K, int n, size_t *ne, size_t *nv)
{
    const size_t T = (size_t)fan_triangles(K), N = (size_t)n;
    *ne = T * N * N;
    *nv = (size_t)K + (K > 3) + (size_t)fan_spokes(K) * (N - 1) +
          T * ((N - 1) + (N - 1) * (N - 2) / 2);
}

/* (1 - t) a + t b with both ends exact (as mesh.c's lerp_ends). */
static rad_vec3 lerp(rad_vec3 a, rad_vec3 b, double t)
{
    return v3_add(v3_scale(a, 1 - t), v3_scale(b, t));
}

typedef struct fan {
    int K, n, T;
    int corner0;    /* index of corner 0 (the surface's first vertex) */
    int apex;       /* index of the apex */
    int spoke0;     /* first inner point of spoke 0 */
    int tri0;       /* first point of triangle 0's own block */
    int per_tri;    /* points in a triangle's own block */
} fan;

/* Index of corner k of the fan's spoke s (its outer end). */
static int spoke_end(const fan *f, int s)
{
    return f->corner0 + (f->K == 3 ? s + 1 : s % f->K);
}

/* Index of lattice point (i, j) of fan triangle t (spokes t, t + 1). */
static int point(const fan *f, int t, int i, int j)
{
    const int n = f->n, r = i + j;
    if (r == 0)
        return f->apex;
    if (j == 0 && i == n)
        return spoke_end(f, t);
    if (i == 0 && j == n)
        return spoke_end(f, t + 1);
    if (j == 0) /* on spoke t */
        return f->spoke0 + (t % fan_spokes(f->K)) * (n - 1) + (i - 1);
    if (i == 0) /* on spoke t + 1 */
        return f->spoke0 + ((t + 1) % fan_spokes(f->K)) * (n - 1) + (j - 1);
    const int own = f->tri0 + t * f->per_tri;
    if (r == n) /* the outer edge, 0 < j < n */
        return own + (j - 1);
    /* interior: rows r = 2 .. n-1, j = 1 .. r-1 */
    return own + (n - 1) + (r - 2) * (r - 1) / 2 + (j - 1);
}

static rad_vec3 lattice(rad_vec3 a, rad_vec3 B, rad_vec3 C, int n, int i, int j)
{
    const int r = i + j;
    if (r == 0)
        return a;
    const rad_vec3 Ar = lerp(a, B, (double)r / n), Cr = lerp(a, C, (double)r / n);
    return lerp(Ar, Cr, (double)j / r);
}

void radi_mesh_fan(rad_mesh *m, const rad_scene *scene, int s, rad_vec3 nrm, int *ne, int *nv,
                   int *ni)
{
    const rad_surface *f = &scene->surfaces[s];
    const rad_material *mat = &scene->materials[f->material];
    const int K = f->nverts, n = f->mesh_n;
    fan fn = {K, n, fan_triangles(K), *nv, 0, 0, 0, (n - 1) + (n - 1) * (n - 2) / 2};
    for (int k = 0; k < K; k++)
        m->vertices[*nv + k] = f->verts[k];
    rad_vec3 apex = f->verts[0];
    if (K > 3) {
        double area;
        radi_mesh_area_centroid(f->verts, K, nrm, &area, &apex);
        m->vertices[*nv + K] = apex;
    }
    fn.apex = K > 3 ? *nv + K : *nv;
    fn.spoke0 = *nv + K + (K > 3);
    fn.tri0 = fn.spoke0 + fan_spokes(K) * (n - 1);
    /* every lattice point, written where point() files it (shared points
     * are written again with the same bits) */
    for (int t = 0; t < fn.T; t++) {
        const rad_vec3 B = m->vertices[spoke_end(&fn, t)], C = m->vertices[spoke_end(&fn, t + 1)];
        for (int r = 1; r <= n; r++)
            for (int j = 0; j <= r; j++)
                m->vertices[point(&fn, t, r - j, j)] = lattice(apex, B, C, n, r - j, j);
    }
    for (int t = 0; t < fn.T; t++)
        for (int r = 0, local = 0; r < n; r++)
            for (int j = 0; j <= r; j++) {
                const int i = r - j;
                int tri[2][3] = {{point(&fn, t, i, j), point(&fn, t, i + 1, j),
                                  point(&fn, t, i, j + 1)},
                                 {point(&fn, t, i + 1, j), point(&fn, t, i + 1, j + 1),
                                  point(&fn, t, i, j + 1)}};
                for (int h = 0; h < (r + 1 < n ? 2 : 1); h++) {
                    rad_element *e = &m->elements[(*ne)++];
                    rad_vec3 p[3];
                    for (int k = 0; k < 3; k++) {
                        m->vindex[*ni + k] = tri[h][k];
                        p[k] = m->vertices[tri[h][k]];
                    }
                    radi_mesh_element_set(e, s, t, local++, p, 3, *ni, nrm, mat);
                    *ni += 3;
                }
            }
    size_t cne, cnv;
    radi_mesh_fan_count(K, n, &cne, &cnv);
    *nv += (int)cnv;
}
