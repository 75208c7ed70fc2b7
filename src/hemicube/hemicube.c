/* hemicube.c -- one row of F by the hemicube, through the renderer's z-buffer.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen & Greenberg 1985 (and Cohen et al. 1988, section 3.1): the five
 * faces of a hemicube on element i's centre are five pictures taken from
 * there, each a perspective camera of 90 degrees (render.h): the top face
 * looks along i's normal, the side faces along +-t1 and +-t2, two tangents
 * of i's plane (t1 along i's first edge, t2 = n x t1), with the normal up,
 * and only their upper halves (the rows above i's plane) are used.  The
 * renderer's own scan conversion and z-buffer do the projection, the
 * clipping to each face's frustum and the hidden surfaces; its `face`
 * array, the face drawn at each pixel, is the item buffer of the 1985
 * paper.  F_ij is the sum of the delta form factors (hcdelta.c) of the
 * pixels whose item is j, summed in long double.
 *
 * A pixel is sampled once, at its centre (render.h), so a pixel counts
 * wholly for the element whose projection covers its centre: a receiver's
 * outline is wrong by up to half a pixel everywhere along it.  With the
 * largest delta dF_max = 4 / (pi R^2) (the top face's centre pixel) and an
 * outline crossing at most L R / 2 + 2 pixels per unit of its projected
 * length L on a face, the error of one F_ij is at most about
 * 2 L / (pi R) + O(R^-2): the aliasing error falls as 1/R
 * (tests/unit/hemicube/test_hemicube.c checks that bound against a closed form).
 *
 * Surfaces are one-sided for the renderer (back faces are culled) but
 * opaque from both sides for the contour's visibility (occlusion.h): a
 * panel seen from behind still hides what lies beyond it.  So the model
 * holds every element twice, as itself (faces 0..n-1, receivers) and
 * reversed (faces n..2n-1, the same polygon turned round): whichever side
 * faces the centre is drawn, and a back side takes its pixels from the
 * elements behind it and gives them to nobody, as light that hits the
 * back of a one-sided surface is lost in the contour's F too.  Elements
 * on i's plane (its own surface, or any coplanar one) are edge-on to the
 * centre and culled both ways: F_ij = 0, as the contour gives.
 *
 * Each row first picks the faces its hemicube can show (view_set_make):
 * of an element and its twin only the side that faces the centre, and
 * only elements reaching above i's plane.  The renderer would cull or
 * clip the rest itself, but only after setting each one up, and at 2,400
 * elements that set-up was most of the time; the pixels are the same, as
 * the faces kept are drawn in the model's order (ties keep the first).
 * Each of the five pictures then gets only the faces not wholly outside
 * its 90-degree frustum (frustum_cut), and only the vertices they use
 * (the renderer scans all of a model's vertices on every call).  The
 * near plane is hc->tol, 1e-9 of the mesh's size, the distance below
 * which an element counts as on i's plane: the renderer's own, 1e-6 of
 * the picture's extent, clipped a receiver closer than that to the
 * centre (two squares 1e-7 apart had F = 0.003, not 1).  The projection
 * is in doubles, so coordinates of up to R / tol pixels keep their
 * fraction of a pixel.  At 2,400 elements and R = 64 the whole matrix took 15 s
 * before these cuts and takes 3.6 s with them, on two busy cores.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hemicube/hemicube.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/render.h"
#include "radiosity/render.h"
#include "util/util.h"

struct rad_hemicube {
    rad_hc_table tab;
    rad_render_model model;     /* 2n faces: the elements, then turned round */
    rad_vec3 *centre, *normal, *tangent;
    double tol;                 /* "on a plane": 1e-9 of the mesh's size */
    int n;
};

/* The faces one hemicube can see, in the model's order: a sub-model
 * sharing the model's vertices, and the element each face is (-1: the
 * back of one). */
typedef struct view_set {
    rad_render_model m;
    int *item;
    rad_vec3 *pos;              /* a picture's own vertices (frustum_cut), or NULL */
    int *vmap, *vorig;          /* model vertex -> its own (-1: none), and back */
} view_set;

int radi_hemicube_elements(const rad_hemicube *hc)
{
    return hc->n;
}

double radi_hemicube_row_bytes(const rad_hemicube *hc)
{
    const double R = hc->tab.res, n = hc->n;
    /* the picture: rgb (24), depth (8), face (4), edge (1) per pixel;
     * the row: acc (16 n), two view sets (face lists, items, vertices) */
    return RAD_HEMICUBE_PIXEL_BYTES * R * R + 16.0 * n + 2.0 * (24.0 * n + 4.0 * hc->model.face_first[2 * hc->n]) +
           48.0 * hc->model.nvertices;
}

void radi_hemicube_free(rad_hemicube *hc)
{
    if (!hc)
        return;
    radi_hc_table_free(&hc->tab);
    rad_render_model_free(&hc->model);
    free(hc->centre);
    free(hc->normal);
    free(hc->tangent);
    free(hc);
}

/* The render model: every element as itself and reversed, radiosity 0
 * (only the item buffer is read). */
static int make_model(rad_render_model *md, const rad_mesh *m)
{
    const int n = m->nelements;
    size_t ni = 0;
    for (int e = 0; e < n; e++)
        ni += (size_t)m->elements[e].nverts;
    memset(md, 0, sizeof *md);
    md->pos = malloc(sizeof *md->pos * (size_t)(m->nvertices ? m->nvertices : 1));
    md->face_first = malloc(sizeof *md->face_first * (2 * (size_t)n + 1));
    md->face_index = malloc(sizeof *md->face_index * (2 * ni + 1));
    md->frad = calloc(2 * (size_t)n * RAD_BANDS + 1, sizeof *md->frad);
    if (!md->pos || !md->face_first || !md->face_index || !md->frad)
        return -1;
    md->nvertices = m->nvertices;
    md->nfaces = 2 * n;
    memcpy(md->pos, m->vertices, sizeof *md->pos * (size_t)m->nvertices);
    int k = 0;
    for (int twin = 0; twin < 2; twin++)
        for (int e = 0; e < n; e++) {
            const rad_element *el = &m->elements[e];
            md->face_first[twin * n + e] = k;
            for (int v = 0; v < el->nverts; v++)
                md->face_index[k++] = m->vindex[el->first + (twin ? el->nverts - 1 - v : v)];
        }
    md->face_first[2 * n] = k;
    return 0;
}

/* The faces that element i's hemicube can show: of each element and its
 * turned-round twin only the one whose front faces i's centre (both when
 * edge-on within tol: the renderer then decides), and only elements with
 * a vertex above i's plane (nothing below it shows in the upper half of a
 * face, or hides what does).  The renderer would cull or clip the others
 * itself, at the cost of setting each one up; this halves the faces or
 * better.  0, or -1 out of memory. */
static int view_set_make(const rad_hemicube *hc, int i, view_set *vs)
{
    const rad_render_model *md = &hc->model;
    const int n = hc->n;
    const rad_vec3 c = hc->centre[i], ni = hc->normal[i];
    vs->m = *md;
    vs->m.face_first = malloc(sizeof(int) * (2 * (size_t)n + 1));
    vs->m.face_index = malloc(sizeof(int) * ((size_t)md->face_first[2 * n] + 1));
    vs->item = malloc(sizeof(int) * (2 * (size_t)n + 1));
    if (!vs->m.face_first || !vs->m.face_index || !vs->item)
        return -1;
    int nf = 0, k = 0;
    for (int twin = 0; twin < 2; twin++)
        for (int e = 0; e < n; e++) {
            const int f = twin * n + e, a = md->face_first[f], b = md->face_first[f + 1];
            const double side = v3_dot(hc->normal[e], v3_sub(c, hc->centre[e]));
            if (e == i || (twin ? side > hc->tol : side < -hc->tol))
                continue;
            int above = 0;
            for (int v = a; v < b && !above; v++)
                above = v3_dot(ni, v3_sub(md->pos[md->face_index[v]], c)) > hc->tol;
            if (!above)
                continue;
            vs->m.face_first[nf] = k;
            for (int v = a; v < b; v++)
                vs->m.face_index[k++] = md->face_index[v];
            vs->item[nf++] = twin ? -1 : e;
        }
    vs->m.face_first[nf] = k;
    vs->m.nfaces = nf;
    return 0;
}

static void view_set_free(view_set *vs)
{
    free(vs->m.face_first);
    free(vs->m.face_index);
    free(vs->item);
    free(vs->pos);
    free(vs->vmap);
    free(vs->vorig);
}

/* Room in cam for any subset of row's faces (cam's arrays freed by
 * view_set_free).  0, or -1 out of memory. */
static int view_set_room(const view_set *row, view_set *cam)
{
    const int nf = row->m.nfaces;
    cam->m = row->m;
    cam->m.face_first = malloc(sizeof(int) * ((size_t)nf + 1));
    cam->m.face_index = malloc(sizeof(int) * ((size_t)row->m.face_first[nf] + 1));
    cam->item = malloc(sizeof(int) * ((size_t)nf + 1));
    const size_t nv = (size_t)row->m.nvertices + 1;
    cam->pos = malloc(sizeof *cam->pos * nv);
    cam->vmap = malloc(sizeof *cam->vmap * nv);
    cam->vorig = malloc(sizeof *cam->vorig * nv);
    if (!cam->m.face_first || !cam->m.face_index || !cam->item || !cam->pos || !cam->vmap ||
        !cam->vorig)
        return -1;
    for (size_t v = 0; v < nv; v++)
        cam->vmap[v] = -1;
    return 0;
}

/* The picture's own copy of the vertices its faces use (the renderer
 * scans every vertex of a model on each call), face_index renumbered. */
static void own_vertices(const rad_render_model *md, view_set *cam)
{
    int nv = 0;
    for (int k = 0; k < cam->m.face_first[cam->m.nfaces]; k++) {
        const int v = cam->m.face_index[k];
        if (cam->vmap[v] < 0) {
            cam->vmap[v] = nv;
            cam->vorig[nv] = v;
            cam->pos[nv++] = md->pos[v];
        }
        cam->m.face_index[k] = cam->vmap[v];
    }
    for (int k = 0; k < nv; k++) /* ready for the next picture */
        cam->vmap[cam->vorig[k]] = -1;
    cam->m.pos = cam->pos;
    cam->m.nvertices = nv;
}

/* Of row's faces, those not wholly outside the 90-degree frustum from c
 * along the unit dir with `up` (the renderer's camera frame, render.c:
 * right = dir x up, up' = right x dir): in camera coordinates (x, y, z)
 * the frustum is |x| <= z, |y| <= z, and a face wholly beyond one of
 * its five planes by more than tol shows in no pixel (pixel centres lie
 * half a pixel inside it).  Same order as row's. */
static void frustum_cut(const view_set *row, rad_vec3 c, rad_vec3 dir, rad_vec3 up, double tol,
                        view_set *cam)
{
    const rad_render_model *md = &row->m;
    const rad_vec3 right = v3_cross(dir, up), upc = v3_cross(right, dir);
    int nf = 0, k = 0;
    for (int f = 0; f < md->nfaces; f++) {
        const int a = md->face_first[f], b = md->face_first[f + 1];
        int in[5] = {0, 0, 0, 0, 0}; /* some vertex inside plane p (with tol) */
        for (int v = a; v < b; v++) {
            const rad_vec3 d = v3_sub(md->pos[md->face_index[v]], c);
            const double x = v3_dot(d, right), y = v3_dot(d, upc), z = v3_dot(d, dir);
            in[0] |= z > -tol;
            in[1] |= x - z <= tol;
            in[2] |= -x - z <= tol;
            in[3] |= y - z <= tol;
            in[4] |= -y - z <= tol;
        }
        if (!(in[0] && in[1] && in[2] && in[3] && in[4]))
            continue;
        cam->m.face_first[nf] = k;
        for (int v = a; v < b; v++)
            cam->m.face_index[k++] = md->face_index[v];
        cam->item[nf++] = row->item[f];
    }
    cam->m.face_first[nf] = k;
    cam->m.nfaces = nf;
    own_vertices(md, cam);
}

/* Centre, normal and first tangent of every element. */
static void make_frames(rad_hemicube *hc, const rad_mesh *m)
{
    for (int e = 0; e < hc->n; e++) {
        const rad_element *el = &m->elements[e];
        const rad_vec3 nrm = el->normal;
        rad_vec3 t = v3_sub(rad_mesh_vertex(m, e, 1), rad_mesh_vertex(m, e, 0));
        t = v3_sub(t, v3_scale(nrm, v3_dot(t, nrm))); /* into the plane */
        hc->centre[e] = el->centroid;
        hc->normal[e] = nrm;
        hc->tangent[e] = v3_scale(t, 1.0 / v3_norm(t));
    }
}

rad_status radi_hemicube_create(rad_hemicube **out, const rad_mesh *unit, int res,
                               rad_error *err)
{
    *out = NULL;
    rad_hemicube *hc = calloc(1, sizeof *hc);
    if (!hc)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (res < 2 || res > RAD_HEMICUBE_MAX || res % 2 != 0) { /* radi_hc_table_make says so */
        rad_status st = radi_hc_table_make(&hc->tab, res, err);
        free(hc);
        return st;
    }
    hc->tab.res = res; /* the tables come after the check below */
    hc->n = unit->nelements;
    const size_t n = (size_t)(hc->n ? hc->n : 1);
    hc->centre = malloc(sizeof *hc->centre * n);
    hc->normal = malloc(sizeof *hc->normal * n);
    hc->tangent = malloc(sizeof *hc->tangent * n);
    if (!hc->centre || !hc->normal || !hc->tangent || make_model(&hc->model, unit) != 0) {
        radi_hemicube_free(hc);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the hemicube of %d elements",
                        unit->nelements);
    }
    /* one row's picture and the delta tables (R^2 and R^2 / 2 doubles):
     * refused clearly here, before the tables, not killed halfway */
    const double need = radi_hemicube_row_bytes(hc) + 12.0 * res * res;
    const double limit = rad_memory_limit();
    if (limit > 0 && need > limit) {
        radi_hemicube_free(hc);
        return radi_fail(err, RAD_ERR_TOOBIG,
                        "a hemicube of %d x %d pixels (its picture and tables) needs %.0f MiB, but only %.0f "
                        "MiB are available (the least of free memory, the process limits and "
                        "the cgroup's); use a lower `resolution`",
                        res, res, need / 1048576.0, limit / 1048576.0);
    }
    rad_status st = radi_hc_table_make(&hc->tab, res, err);
    if (st != RAD_OK) {
        radi_hemicube_free(hc);
        return st;
    }
    make_frames(hc, unit);
    rad_vec3 lo = unit->nvertices ? unit->vertices[0] : v3(0, 0, 0), hi = lo;
    for (int v = 1; v < unit->nvertices; v++) {
        const rad_vec3 p = unit->vertices[v];
        lo = v3(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
        hi = v3(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
    }
    hc->tol = 1e-9 * v3_norm(v3_sub(hi, lo));
    *out = hc;
    return RAD_OK;
}

/* One face: the picture from the centre c looking along `dir` with `up`,
 * R x R pixels of 90 degrees; rows [0, rows) add their deltas d[y*R + x]
 * to the items they show. */
static rad_status one_face(const rad_hemicube *hc, const view_set *row, view_set *vs, int i,
                           rad_vec3 dir, rad_vec3 up, const double *d, int rows,
                           long double *acc, int *items, rad_error *err)
{
    const int R = hc->tab.res;
    rad_render_options o;
    rad_image img;
    frustum_cut(row, hc->centre[i], dir, up, hc->tol, vs);
    rad_render_options_init(&o);
    o.width = o.height = R;
    o.shading = RAD_SHADING_FLAT;
    o.exposure = 1;
    o.camera.defined = 1;
    o.camera.eye = hc->centre[i];
    o.camera.at = v3_add(hc->centre[i], dir);
    o.camera.up = up;
    o.camera.fov = 90;
    o.znear = hc->tol; /* the renderer's own, 1e-6 of the scene, clipped
                          receivers closer than that: F fell to 0 */
    rad_status st = rad_render(&vs->m, &o, &img, err);
    if (st != RAD_OK)
        return st;
    for (int y = 0; y < rows; y++)
        for (int x = 0; x < R; x++) {
            const size_t p = (size_t)y * R + (size_t)x;
            const int f = img.face[p];
            if (f >= 0 && vs->item[f] >= 0) /* -1: the back of a blocker */
                acc[vs->item[f]] += d[p];
            if (items)
                items[p] = f >= 0 ? vs->item[f] : -1;
        }
    rad_image_free(&img);
    return RAD_OK;
}

rad_status radi_hemicube_row(const rad_hemicube *hc, int i, double *row, rad_error *err)
{
    return radi_hemicube_row_items(hc, i, row, NULL, err);
}

rad_status radi_hemicube_row_items(const rad_hemicube *hc, int i, double *row, int *items,
                                   rad_error *err)
{
    const int n = hc->n, R = hc->tab.res;
    const rad_vec3 nrm = hc->normal[i], t1 = hc->tangent[i], t2 = v3_cross(nrm, t1);
    const rad_vec3 sides[4] = {t1, v3_scale(t1, -1), t2, v3_scale(t2, -1)};
    long double *acc = calloc((size_t)(n ? n : 1), sizeof *acc);
    view_set vs, cam;
    memset(&vs, 0, sizeof vs);
    memset(&cam, 0, sizeof cam);
    if (!acc || view_set_make(hc, i, &vs) != 0 || view_set_room(&vs, &cam) != 0) {
        free(acc);
        view_set_free(&vs);
        view_set_free(&cam);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a hemicube row");
    }
    rad_status st = one_face(hc, &vs, &cam, i, nrm, t1, hc->tab.top, R, acc, items, err);
    for (int s = 0; s < 4 && st == RAD_OK; s++) /* the upper half of each side */
        st = one_face(hc, &vs, &cam, i, sides[s], nrm, hc->tab.side, R / 2, acc,
                      items ? items + (size_t)R * R + (size_t)s * (R / 2) * R : NULL, err);
    for (int j = 0; j < n; j++)
        row[j] = (double)acc[j];
    free(acc);
    view_set_free(&vs);
    view_set_free(&cam);
    return st;
}
