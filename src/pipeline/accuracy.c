/* accuracy.c -- how far a solution is from the truth.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Three measures, each with its own source of truth (radiosity/accuracy.h):
 * the furnace, whose B = E / (1 - rho) follows from B = E + rho F B with
 * every row of F summing to 1 (Goral et al. 1984, eq. 6, with sum_j F_ij = 1
 * in an enclosure); closure itself; and the error against a finer
 * solution of the same scene.  Nothing here prints or opens a file.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/accuracy.h"
#include "radiosity/accuracy.h"
#include "mesh/mesh.h"
#include "util/util.h"

int rad_furnace_radiosity(const rad_scene *s, double B[RAD_BANDS])
{
    if (s->nmaterials < 1 || s->nsurfaces < 1)
        return 0;
    for (int k = 1; k < s->nsurfaces; k++)
        if (s->surfaces[k].material != s->surfaces[0].material)
            return 0;
    const rad_material *m = &s->materials[s->surfaces[0].material];
    for (int b = 0; b < RAD_BANDS; b++) {
        if (!(m->reflect[b] < 1))
            return 0;
        B[b] = m->emit[b] / (1 - m->reflect[b]);
    }
    return 1;
}

double rad_closure_error(const double *F, int n)
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double r = 0;
        for (int j = 0; j < n; j++)
            r += F[i + (size_t)j * n];
        worst = fmax(worst, fabs(r - 1));
    }
    return worst;
}

rad_status rad_scene_closed(const rad_scene *scene, double tol, int *closed, double *deviation,
                            rad_error *err)
{
    rad_scene one = *scene; /* the same surfaces, one element each */
    rad_mesh mesh;
    rad_ff_options o;
    *closed = 0;
    one.surfaces = malloc(sizeof *one.surfaces * (size_t)(scene->nsurfaces ? scene->nsurfaces : 1));
    if (!one.surfaces)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    memcpy(one.surfaces, scene->surfaces, sizeof *one.surfaces * (size_t)scene->nsurfaces);
    for (int s = 0; s < one.nsurfaces; s++)
        one.surfaces[s].mesh_n = one.surfaces[s].mesh_m = 1;
    rad_status st = rad_mesh_build(&mesh, &one, err);
    free(one.surfaces);
    if (st != RAD_OK)
        return st;
    const size_t n = (size_t)mesh.nelements;
    double *F = malloc(sizeof *F * (n ? n * n : 1));
    rad_ff_options_init(&o);
    o.accuracy = RAD_ACCURACY_REFERENCE;
    st = F ? rad_ff_matrix(&mesh, &o, F, NULL, NULL, err)
           : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (st == RAD_OK) {
        double d = rad_closure_error(F, (int)n);
        *closed = n > 0 && d <= tol;
        if (deviation)
            *deviation = d;
    }
    free(F);
    rad_mesh_free(&mesh);
    return st;
}

/* How far point p lies outside element e of mesh c, along its plane: 0
 * inside, else the largest distance outside one of its edges (a convex
 * polygon, counter-clockwise about its normal). */
static double outside(const rad_mesh *c, int e, rad_vec3 p)
{
    const rad_element *el = &c->elements[e];
    double worst = 0;
    for (int k = 0; k < el->nverts; k++) {
        const rad_vec3 a = rad_mesh_vertex(c, e, k), b = rad_mesh_vertex(c, e, (k + 1) % el->nverts);
        const rad_vec3 inward = v3_cross(el->normal, v3_sub(b, a));
        const double d = -v3_dot(inward, v3_sub(p, a)) / v3_norm(inward);
        worst = fmax(worst, d);
    }
    return worst;
}

/* The element of mesh c that holds fine element f of mesh t (the same
 * scene, meshed finer): by the grids' indices, or, for a polygon cut into
 * triangles, the element of its surface (of the same triangle of its fan
 * when both are fans) that holds f's centroid (the least outside of them,
 * against rounding: every fine triangle lies inside one coarse one only
 * when the coarse count divides the fine, so else the one holding its
 * centroid). */
static int coarse_of(const rad_mesh *c, const rad_mesh *t, int f)
{
    const rad_element *el = &t->elements[f];
    const int s = el->surface;
    if (radi_mesh_is_fan(c, s) || radi_mesh_is_fan(t, s)) {
        const int both = radi_mesh_is_fan(c, s) && radi_mesh_is_fan(t, s);
        int best = c->surface_first[s];
        double least = INFINITY;
        for (int e = c->surface_first[s]; e < c->surface_first[s + 1] && least > 0; e++) {
            if (both && c->elements[e].gi != el->gi)
                continue;
            const double d = outside(c, e, el->centroid);
            if (d < least) {
                least = d;
                best = e;
            }
        }
        return best;
    }
    const int ci = (int)floor((el->gi + 0.5) * c->surface_n[s] / t->surface_n[s]);
    const int cj = (int)floor((el->gj + 0.5) * c->surface_m[s] / t->surface_m[s]);
    return c->surface_first[s] + cj * c->surface_n[s] + ci;
}

void rad_solution_error(const rad_mesh *c, const double *Bc, const rad_mesh *t,
                        const double *Bt, const double truth[RAD_BANDS], double *rms,
                        double *max)
{
    const rad_mesh *mt = t ? t : c;
    const int nt = mt->nelements, nc = c->nelements;
    double s2 = 0, area = 0;
    *max = 0;
    for (int f = 0; f < nt; f++) {
        const rad_element *el = &mt->elements[f];
        const int e = coarse_of(c, mt, f);
        for (int b = 0; b < RAD_BANDS; b++) {
            const double want = t ? Bt[f + (size_t)b * nt] : truth[b];
            const double d = Bc[e + (size_t)b * nc] - want;
            s2 += el->area * d * d;
            *max = fmax(*max, fabs(d));
        }
        area += el->area;
    }
    *rms = area > 0 ? sqrt(s2 / (area * RAD_BANDS)) : 0;
}
