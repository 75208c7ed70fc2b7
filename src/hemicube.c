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
 * (tests/test_hemicube.c checks that bound against a closed form).
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
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hemicube.h"
#include "radiosity/render.h"
#include "status.h"
#include "vec.h"

struct rad_hemicube {
    rad_hc_table tab;
    rad_render_model model;     /* 2n faces: the elements, then turned round */
    rad_vec3 *centre, *normal, *tangent;
    int n;
};

int rad_hemicube_elements(const rad_hemicube *hc)
{
    return hc->n;
}

void rad_hemicube_free(rad_hemicube *hc)
{
    if (!hc)
        return;
    rad_hc_table_free(&hc->tab);
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

rad_status rad_hemicube_create(rad_hemicube **out, const rad_mesh *unit, int res,
                               rad_error *err)
{
    *out = NULL;
    rad_hemicube *hc = calloc(1, sizeof *hc);
    if (!hc)
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory");
    rad_status st = rad_hc_table_make(&hc->tab, res, err);
    if (st != RAD_OK) {
        free(hc);
        return st;
    }
    hc->n = unit->nelements;
    const size_t n = (size_t)(hc->n ? hc->n : 1);
    hc->centre = malloc(sizeof *hc->centre * n);
    hc->normal = malloc(sizeof *hc->normal * n);
    hc->tangent = malloc(sizeof *hc->tangent * n);
    if (!hc->centre || !hc->normal || !hc->tangent || make_model(&hc->model, unit) != 0) {
        rad_hemicube_free(hc);
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory for the hemicube of %d elements",
                        unit->nelements);
    }
    make_frames(hc, unit);
    *out = hc;
    return RAD_OK;
}

/* One face: the picture from the centre c looking along `dir` with `up`,
 * R x R pixels of 90 degrees; rows [0, rows) add their deltas d[y*R + x]
 * to the items they show. */
static rad_status one_face(const rad_hemicube *hc, int i, rad_vec3 dir, rad_vec3 up,
                           const double *d, int rows, long double *acc, rad_error *err)
{
    const int R = hc->tab.res, n = hc->n;
    rad_render_options o;
    rad_image img;
    rad_render_options_init(&o);
    o.width = o.height = R;
    o.shading = RAD_SHADING_FLAT;
    o.exposure = 1;
    o.camera.defined = 1;
    o.camera.eye = hc->centre[i];
    o.camera.at = v3_add(hc->centre[i], dir);
    o.camera.up = up;
    o.camera.fov = 90;
    rad_status st = rad_render(&hc->model, &o, &img, err);
    if (st != RAD_OK)
        return st;
    for (int y = 0; y < rows; y++)
        for (int x = 0; x < R; x++) {
            const size_t p = (size_t)y * R + (size_t)x;
            const int f = img.face[p];
            if (f >= 0 && f < n && f != i) /* f >= n: the back of a blocker */
                acc[f] += d[p];
        }
    rad_image_free(&img);
    return RAD_OK;
}

rad_status rad_hemicube_row(const rad_hemicube *hc, int i, double *row, rad_error *err)
{
    const int n = hc->n, R = hc->tab.res;
    const rad_vec3 nrm = hc->normal[i], t1 = hc->tangent[i], t2 = v3_cross(nrm, t1);
    const rad_vec3 sides[4] = {t1, v3_scale(t1, -1), t2, v3_scale(t2, -1)};
    long double *acc = calloc((size_t)(n ? n : 1), sizeof *acc);
    if (!acc)
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory for a hemicube row");
    rad_status st = one_face(hc, i, nrm, t1, hc->tab.top, R, acc, err);
    for (int s = 0; s < 4 && st == RAD_OK; s++) /* the upper half of each side */
        st = one_face(hc, i, sides[s], nrm, hc->tab.side, R / 2, acc, err);
    for (int j = 0; j < n; j++)
        row[j] = (double)acc[j];
    free(acc);
    return st;
}
