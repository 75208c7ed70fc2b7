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
 * A polygon (or disk) is one element whose vertices are its own, or, with
 * a mesh of n > 1, n^2 triangles per triangle of its fan (meshtri.c).
 *
 * Every element carries its surface's unit normal (the normalised Newell
 * vector of the whole surface), so elements of one plane share one normal
 * exactly; area and centroid are its own (polygon formulas on a fan of
 * triangles from the first vertex).
 *
 * Scale.  Lengths may be any finite doubles, but a product of two of them
 * leaves the double range when they are below 1.5e-154 or above 1.3e154:
 * a Newell vector or an area computed from the raw coordinates of a square
 * of side 1e-160 underflows to 0 and one of side 1e160 overflows to inf.
 * So normals, areas and centroids are computed on the polygon moved to its
 * first vertex and scaled by a power of two (exact) to size about 1, and
 * the area is scaled back at the end.  The area itself is an output in the
 * user's units (the element table's `area`); an element whose area is not
 * a normal double (RAD_AREA_MIN .. RAD_AREA_MAX) is refused with a message
 * that names that range: the accepted lengths are roughly its square
 * roots, 1.5e-154 to 1.3e154.
 *
 * The form factors are scale-free: radi_mesh_normalized makes a private copy
 * of the geometry, shifted by an amount that makes the subtraction exact
 * (the box's end nearer the origin when the box lies far from it, else
 * nothing) and scaled by a power of two into [-1, 1]^3: an exact image of
 * the user's geometry, with nothing rounded away, on which rad_ff_matrix
 * integrates and tests visibility.  (Moving to the box's centre instead
 * would round the coordinates of small features near the origin of a large
 * scene: 1e-12 of the width of a 0.01 strip in a scene 100 across.)  The
 * grid of a quad is re-interpolated in that frame from its four corners
 * rather than copied vertex by vertex: a quad at x = 1e12 meshed 3x3 has its
 * grid points rounded to 6e-5 (half an ulp of 1e12) in the user's
 * coordinates, while its corners, and the grid in the frame, are exact.
 */
#include <config.h>

#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "util/util.h"

#define RAD_AREA_MIN DBL_MIN /* 2.2e-308: smaller areas lose digits */
#define RAD_AREA_MAX DBL_MAX /* 1.8e308 */

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

rad_vec3 radi_mesh_bilinear(const rad_vec3 q[4], double u, double v)
{
    return bilinear(q, u, v);
}


rad_status radi_mesh_count(const rad_scene *scene, size_t *nelem, size_t *nvert,
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
        } else if (f->mesh_n > 1) {
            size_t fe, fv;
            if (n > RADI_MESH_COUNT_MAX / n) /* n^2 alone overflows the count */
                return RAD_ERR_TOOBIG;
            radi_mesh_fan_count(f->nverts, f->mesh_n, &fe, &fv);
            ne += fe;
            nv += fv;
            ni += 3 * fe;
        } else {
            ne += 1;
            nv += (size_t)f->nverts;
            ni += (size_t)f->nverts;
        }
        if (ne > RADI_MESH_COUNT_MAX || nv > RADI_MESH_COUNT_MAX || ni > RADI_MESH_COUNT_MAX)
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
    const rad_vec3 nrm = radi_mesh_unit_normal(f->verts, 4);
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
            radi_mesh_element_set(e, s, gi, gj, p, 4, *ni, nrm, mat);
            *ni += 4;
        }
}

static void mesh_polygon(rad_mesh *m, const rad_scene *scene, int s, int *ne, int *nv,
                         int *ni)
{
    const rad_surface *f = &scene->surfaces[s];
    const rad_material *mat = &scene->materials[f->material];
    rad_element *e = &m->elements[(*ne)++];
    radi_mesh_element_set(e, s, 0, 0, f->verts, f->nverts, *ni,
                          radi_mesh_unit_normal(f->verts, f->nverts), mat);
    for (int k = 0; k < f->nverts; k++) {
        m->vindex[(*ni)++] = *nv;
        m->vertices[(*nv)++] = f->verts[k];
    }
}

/* Every element's area must be a normal double: it is written in the
 * user's units, and the solver weighs by it.  Otherwise refuse, naming the
 * limit and the surface's line (an input error: the scene's scale). */
static rad_status check_areas(rad_mesh *m, const rad_scene *scene, rad_error *err)
{
    for (int e = 0; e < m->nelements; e++) {
        const double a = m->elements[e].area;
        if (a >= RAD_AREA_MIN && a <= RAD_AREA_MAX)
            continue;
        const rad_surface *f = &scene->surfaces[m->elements[e].surface];
        rad_mesh_free(m);
        return radi_fail(err, RAD_ERR_INVALID,
                        "%s:%d: an element of this %s has area %.3g, outside the range of "
                        "normal doubles [%.3g, %.3g]: element sides must lie between "
                        "about 1.5e-154 and 1.3e154, the square roots of that range; "
                        "rescale the scene or use a coarser mesh",
                        scene->filename ? scene->filename : "scene", f->line,
                        f->kind == RAD_SURFACE_QUAD ? "quad" : "polygon", a, RAD_AREA_MIN,
                        RAD_AREA_MAX);
    }
    return RAD_OK;
}

rad_status rad_mesh_build(rad_mesh *m, const rad_scene *scene, rad_error *err)
{
    size_t ne, nv, ni;
    memset(m, 0, sizeof *m);
    if (radi_mesh_count(scene, &ne, &nv, &ni) != RAD_OK)
        return radi_fail(err, RAD_ERR_TOOBIG, "%s: the mesh has too many elements",
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
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a mesh of %zu elements", ne);
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
        } else if (f->mesh_n > 1) {
            m->surface_n[s] = f->mesh_n;
            m->surface_m[s] = 0; /* not a grid */
            radi_mesh_fan(m, scene, s, radi_mesh_unit_normal(f->verts, f->nverts), &e, &v, &k);
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
    return check_areas(m, scene, err);
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

/* ---- the normalized frame ------------------------------------------------ */

/* The shift along one axis for the interval [lo, hi]: its end nearer to 0
 * when the interval lies within a factor 2 of it (then x - shift is exact
 * for every x in it, by Sterbenz's lemma: y/2 <= x <= 2y => x - y exact;
 * Goldberg 1991, thm. 11), otherwise 0 (the interval reaches to within its
 * own length of the origin, and coordinates stay as they are). */
static double exact_shift(double lo, double hi)
{
    if (lo > 0 && hi <= 2 * lo)
        return lo;
    if (hi < 0 && lo >= 2 * hi)
        return hi;
    return 0;
}

int radi_frame_fit(rad_frame *fr, rad_vec3 lo, rad_vec3 hi)
{
    fr->shift = v3(exact_shift(lo.x, hi.x), exact_shift(lo.y, hi.y), exact_shift(lo.z, hi.z));
    fr->exponent = 0;
    const double r = fmax(v3_maxabs(v3_sub(lo, fr->shift)), v3_maxabs(v3_sub(hi, fr->shift)));
    if (!(r > 0) || !isfinite(r)) {
        fr->shift = v3(0, 0, 0);
        return -1;
    }
    frexp(r, &fr->exponent);
    return 0;
}

rad_vec3 radi_frame_apply(const rad_frame *fr, rad_vec3 p)
{
    return radi_mesh_shrink(p, fr->shift, fr->exponent);
}

rad_vec3 radi_frame_offset(const rad_frame *fr)
{
    return radi_mesh_shrink(fr->shift, v3(0, 0, 0), fr->exponent);
}

/* Is surface s's grid the bilinear subdivision of its four corners, as
 * rad_mesh_build makes it (bit for bit: the same formula on the same
 * corners)?  A mesh built otherwise keeps its own vertices. */
static int bilinear_grid(const rad_mesh *m, int s, rad_vec3 q[4])
{
    const int N = m->surface_n[s], M = m->surface_m[s], v0 = m->surface_vfirst[s];
    const int nv = m->surface_vfirst[s + 1] - v0, ne = m->surface_first[s + 1] - m->surface_first[s];
    if (N < 1 || M < 1 || nv != (N + 1) * (M + 1) || ne != N * M)
        return 0;
    for (int e = m->surface_first[s]; e < m->surface_first[s + 1]; e++)
        if (m->elements[e].nverts != 4)
            return 0;
    q[0] = m->vertices[v0];
    q[1] = m->vertices[v0 + N];
    q[2] = m->vertices[v0 + M * (N + 1) + N];
    q[3] = m->vertices[v0 + M * (N + 1)];
    for (int gj = 0; gj <= M; gj++)
        for (int gi = 0; gi <= N; gi++) {
            rad_vec3 a = m->vertices[v0 + gj * (N + 1) + gi];
            rad_vec3 b = bilinear(q, (double)gi / N, (double)gj / M);
            if (a.x != b.x || a.y != b.y || a.z != b.z)
                return 0;
        }
    return 1;
}

/* Surface s's grid re-interpolated in the frame from its corners there,
 * if it is a bilinear grid; out[] already holds every vertex moved into
 * the frame one by one, which is what any other surface keeps. */
static void regrid_surface(const rad_mesh *m, const rad_frame *fr, int s, rad_vec3 *out)
{
    const int v0 = m->surface_vfirst[s];
    rad_vec3 q[4];
    if (!bilinear_grid(m, s, q))
        return;
    const int N = m->surface_n[s], M = m->surface_m[s];
    for (int k = 0; k < 4; k++)
        q[k] = radi_frame_apply(fr, q[k]);
    for (int gj = 0; gj <= M; gj++)
        for (int gi = 0; gi <= N; gi++)
            out[v0 + gj * (N + 1) + gi] = bilinear(q, (double)gi / N, (double)gj / M);
}

static int *copy_ints(const int *a, size_t n)
{
    int *b = malloc(sizeof *b * (n ? n : 1));
    if (b && n)
        memcpy(b, a, sizeof *b * n);
    return b;
}

rad_status radi_mesh_normalized(const rad_mesh *m, rad_mesh *out, rad_frame *frame,
                               rad_error *err)
{
    const size_t ns = (size_t)m->nsurfaces + 1;
    rad_frame fr = {v3(0, 0, 0), 0};
    memset(out, 0, sizeof *out);
    if (m->nvertices > 0) {
        rad_vec3 lo, hi;
        v3_bounds(m->vertices, m->nvertices, &lo, &hi);
        if (radi_frame_fit(&fr, lo, hi) != 0)
            return radi_fail(err, RAD_ERR_INVALID,
                            "the scene's bounding box has no finite non-zero size");
    }
    *out = *m;
    out->elements = malloc(sizeof *out->elements * (size_t)(m->nelements ? m->nelements : 1));
    out->vertices = malloc(sizeof *out->vertices * (size_t)(m->nvertices ? m->nvertices : 1));
    out->vindex = NULL;
    out->surface_first = out->surface_vfirst = out->surface_n = out->surface_m = NULL;
    if (out->elements && out->vertices) {
        size_t ni = 0;
        for (int e = 0; e < m->nelements; e++)
            ni = (size_t)(m->elements[e].first + m->elements[e].nverts) > ni
                     ? (size_t)(m->elements[e].first + m->elements[e].nverts)
                     : ni;
        out->vindex = copy_ints(m->vindex, ni);
        out->surface_first = copy_ints(m->surface_first, ns);
        out->surface_vfirst = copy_ints(m->surface_vfirst, ns);
        out->surface_n = copy_ints(m->surface_n, ns);
        out->surface_m = copy_ints(m->surface_m, ns);
    }
    if (!out->elements || !out->vertices || !out->vindex || !out->surface_first ||
        !out->surface_vfirst || !out->surface_n || !out->surface_m) {
        rad_mesh_free(out);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a copy of the mesh");
    }
    if (m->nelements > 0)
        memcpy(out->elements, m->elements, sizeof *out->elements * (size_t)m->nelements);
    for (int v = 0; v < m->nvertices; v++)
        out->vertices[v] = radi_frame_apply(&fr, m->vertices[v]);
    for (int s = 0; s < m->nsurfaces; s++)
        regrid_surface(m, &fr, s, out->vertices);
    /* the same unit normals (shared exactly by a surface's elements), own
     * areas and centroids in the frame */
    for (int e = 0; e < m->nelements; e++) {
        rad_element *el = &out->elements[e];
        rad_vec3 p[4], *pp = el->nverts <= 4 ? p : malloc(sizeof *pp * (size_t)el->nverts);
        if (!pp) {
            rad_mesh_free(out);
            return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a copy of the mesh");
        }
        for (int k = 0; k < el->nverts; k++)
            pp[k] = rad_mesh_vertex(out, e, k);
        radi_mesh_area_centroid(pp, el->nverts, el->normal, &el->area, &el->centroid);
        if (pp != p)
            free(pp);
    }
    if (frame)
        *frame = fr;
    return RAD_OK;
}

double rad_scene_element_count(const rad_scene *scene)
{
    double n = 0;
    for (int s = 0; s < scene->nsurfaces; s++) {
        const rad_surface *f = &scene->surfaces[s];
        const double fan = f->nverts == 3 ? 1 : f->nverts; /* meshtri.c */
        n += f->kind == RAD_SURFACE_QUAD ? (double)f->mesh_n * (double)f->mesh_m
             : f->mesh_n > 1           ? fan * f->mesh_n * f->mesh_n
                                       : 1.0;
    }
    return n;
}

int radi_mesh_is_fan(const rad_mesh *m, int s)
{
    return m->surface_m[s] == 0 && m->surface_first[s + 1] - m->surface_first[s] > 1;
}

int radi_mesh_outline(const rad_mesh *m, int s, rad_vec3 *out)
{
    const int e0 = m->surface_first[s], ne = m->surface_first[s + 1] - e0;
    const int v0 = m->surface_vfirst[s];
    if (ne == 0)
        return 0;
    if (ne == 1) { /* the element is its surface */
        const int n = m->elements[e0].nverts;
        for (int k = 0; out && k < n; k++)
            out[k] = rad_mesh_vertex(m, e0, k);
        return n;
    }
    if (radi_mesh_is_fan(m, s)) { /* its corners come first */
        const int fan = ne / (m->surface_n[s] * m->surface_n[s]);
        const int K = fan == 1 ? 3 : fan;
        for (int k = 0; out && k < K; k++)
            out[k] = m->vertices[v0 + k];
        return K;
    }
    const int N = m->surface_n[s], M = m->surface_m[s];
    if (out) {
        out[0] = m->vertices[v0];
        out[1] = m->vertices[v0 + N];
        out[2] = m->vertices[v0 + M * (N + 1) + N];
        out[3] = m->vertices[v0 + M * (N + 1)];
    }
    return 4;
}
