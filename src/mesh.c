/* mesh.c -- subdivision of the scene's surfaces into elements.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A quad v1 v2 v3 v4 with `mesh NxM` becomes N x M elements by bilinear
 * subdivision (Goral et al. 1984, section 4: equal elements for
 * parallelograms):
 *     P(u, v) = (1-u)(1-v) v1 + u(1-v) v2 + u v v3 + (1-u) v v4,
 * u = gi/N along v1->v2, v = gj/M along v2->v3.  The (N+1) x (M+1) grid
 * vertices are shared by the elements of the surface (smoothing needs
 * them) and never across surfaces (walls of different colours meet at a
 * crease).  Vertex (gi, gj) of surface s is vertices[vfirst[s] + gj*(N+1) + gi];
 * element (gi, gj) is elements[first[s] + gj*N + gi] with corners
 * (gi,gj) (gi+1,gj) (gi+1,gj+1) (gi,gj+1), counter-clockwise like the quad.
 * A polygon (or disk) is one element whose vertices are its own.
 *
 * Every element carries its surface's unit normal (the normalised Newell
 * vector of the whole surface), so elements of one plane share one normal
 * exactly; area and centroid are its own (polygon formulas on a fan of
 * triangles from the first vertex).
 */
#include <config.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "radiosity.h"
#include "status.h"
#include "vec.h"

/* Area and centroid of a planar polygon: fan of triangles from p[0]. */
static void polygon_area_centroid(const rad_vec3 *p, int n, rad_vec3 nrm, double *area,
                                  rad_vec3 *centroid)
{
    double a = 0;
    rad_vec3 c = v3(0, 0, 0);
    for (int k = 1; k + 1 < n; k++) {
        rad_vec3 e1 = v3_sub(p[k], p[0]), e2 = v3_sub(p[k + 1], p[0]);
        double t = 0.5 * v3_dot(v3_cross(e1, e2), nrm);
        a += t;
        c = v3_add(c, v3_scale(v3_add(e1, e2), t / 3.0));
    }
    *area = a;
    *centroid = a > 0 ? v3_add(p[0], v3_scale(c, 1.0 / a)) : p[0];
}

/* (1 - t) a + t b: exactly a at t = 0 and b at t = 1 (a + t (b - a)
 * rounds b - a, so the far end moves by an ulp of the larger coordinate:
 * 2e-14 of the height of an element whose corner sits just above another
 * plane), so the grid's corners are the quad's own vertices. */
static rad_vec3 lerp_ends(rad_vec3 a, rad_vec3 b, double t)
{
    return v3_add(v3_scale(a, 1 - t), v3_scale(b, t));
}

static rad_vec3 bilinear(const rad_vec3 *q, double u, double v)
{
    rad_vec3 a = lerp_ends(q[0], q[1], u);
    rad_vec3 b = lerp_ends(q[3], q[2], u);
    return lerp_ends(a, b, v);
}

rad_status rad_mesh_count(const rad_scene *scene, size_t *nelem, size_t *nvert,
                          size_t *nindex)
{
    size_t ne = 0, nv = 0, ni = 0;
    for (int s = 0; s < scene->nsurfaces; s++) {
        const rad_surface *f = &scene->surfaces[s];
        size_t n = (size_t)f->mesh_n, m = (size_t)f->mesh_m;
        if (f->kind == RAD_SURFACE_QUAD) {
            ne += n * m;
            nv += (n + 1) * (m + 1);
            ni += 4 * n * m;
        } else {
            ne += 1;
            nv += (size_t)f->nverts;
            ni += (size_t)f->nverts;
        }
        if (ne > INT32_MAX / 4 || nv > INT32_MAX / 4 || ni > INT32_MAX / 4)
            return RAD_ERR_TOOBIG;
    }
    *nelem = ne;
    *nvert = nv;
    *nindex = ni;
    return RAD_OK;
}

static void mesh_quad(rad_mesh *m, const rad_scene *scene, int s, int *ne, int *nv, int *ni)
{
    const rad_surface *f = &scene->surfaces[s];
    const rad_material *mat = &scene->materials[f->material];
    const int N = f->mesh_n, M = f->mesh_m, v0 = *nv;
    rad_vec3 nrm = v3_newell(f->verts, 4);
    nrm = v3_scale(nrm, 1.0 / v3_norm(nrm));
    for (int gj = 0; gj <= M; gj++)
        for (int gi = 0; gi <= N; gi++)
            m->vertices[(*nv)++] = bilinear(f->verts, (double)gi / N, (double)gj / M);
    for (int gj = 0; gj < M; gj++)
        for (int gi = 0; gi < N; gi++) {
            rad_element *e = &m->elements[(*ne)++];
            rad_vec3 p[4];
            int *idx = &m->vindex[*ni];
            idx[0] = v0 + gj * (N + 1) + gi;
            idx[1] = idx[0] + 1;
            idx[2] = idx[1] + (N + 1);
            idx[3] = idx[0] + (N + 1);
            for (int k = 0; k < 4; k++)
                p[k] = m->vertices[idx[k]];
            e->surface = s;
            e->gi = gi;
            e->gj = gj;
            e->nverts = 4;
            e->first = *ni;
            e->normal = nrm;
            polygon_area_centroid(p, 4, nrm, &e->area, &e->centroid);
            memcpy(e->reflect, mat->reflect, sizeof e->reflect);
            memcpy(e->emit, mat->emit, sizeof e->emit);
            *ni += 4;
        }
}

static void mesh_polygon(rad_mesh *m, const rad_scene *scene, int s, int *ne, int *nv,
                         int *ni)
{
    const rad_surface *f = &scene->surfaces[s];
    const rad_material *mat = &scene->materials[f->material];
    rad_element *e = &m->elements[(*ne)++];
    rad_vec3 nrm = v3_newell(f->verts, f->nverts);
    nrm = v3_scale(nrm, 1.0 / v3_norm(nrm));
    e->surface = s;
    e->gi = e->gj = 0;
    e->nverts = f->nverts;
    e->first = *ni;
    e->normal = nrm;
    for (int k = 0; k < f->nverts; k++) {
        m->vindex[(*ni)++] = *nv;
        m->vertices[(*nv)++] = f->verts[k];
    }
    polygon_area_centroid(f->verts, f->nverts, nrm, &e->area, &e->centroid);
    memcpy(e->reflect, mat->reflect, sizeof e->reflect);
    memcpy(e->emit, mat->emit, sizeof e->emit);
}

rad_status rad_mesh_build(rad_mesh *m, const rad_scene *scene, rad_error *err)
{
    size_t ne, nv, ni;
    memset(m, 0, sizeof *m);
    if (rad_mesh_count(scene, &ne, &nv, &ni) != RAD_OK)
        return rad_fail(err, RAD_ERR_TOOBIG, "%s: the mesh has too many elements",
                        scene->filename ? scene->filename : "scene");
    int ns = scene->nsurfaces;
    m->elements = calloc(ne ? ne : 1, sizeof *m->elements);
    m->vertices = calloc(nv ? nv : 1, sizeof *m->vertices);
    m->vindex = calloc(ni ? ni : 1, sizeof *m->vindex);
    m->surface_first = calloc((size_t)ns + 1, sizeof(int));
    m->surface_vfirst = calloc((size_t)ns + 1, sizeof(int));
    m->surface_n = calloc((size_t)ns + 1, sizeof(int));
    m->surface_m = calloc((size_t)ns + 1, sizeof(int));
    if (!m->elements || !m->vertices || !m->vindex || !m->surface_first ||
        !m->surface_vfirst || !m->surface_n || !m->surface_m) {
        rad_mesh_free(m);
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory for a mesh of %zu elements", ne);
    }
    int e = 0, v = 0, k = 0;
    for (int s = 0; s < ns; s++) {
        const rad_surface *f = &scene->surfaces[s];
        m->surface_first[s] = e;
        m->surface_vfirst[s] = v;
        if (f->kind == RAD_SURFACE_QUAD) {
            m->surface_n[s] = f->mesh_n;
            m->surface_m[s] = f->mesh_m;
            mesh_quad(m, scene, s, &e, &v, &k);
        } else {
            m->surface_n[s] = m->surface_m[s] = 1;
            mesh_polygon(m, scene, s, &e, &v, &k);
        }
    }
    m->surface_first[ns] = e;
    m->surface_vfirst[ns] = v;
    m->nelements = e;
    m->nvertices = v;
    m->nsurfaces = ns;
    return RAD_OK;
}

void rad_mesh_free(rad_mesh *m)
{
    if (!m)
        return;
    free(m->elements);
    free(m->vertices);
    free(m->vindex);
    free(m->surface_first);
    free(m->surface_vfirst);
    free(m->surface_n);
    free(m->surface_m);
    memset(m, 0, sizeof *m);
}

rad_vec3 rad_mesh_vertex(const rad_mesh *m, int e, int v)
{
    return m->vertices[m->vindex[m->elements[e].first + v]];
}
