/* meshgeom.c -- the geometry of one planar polygon, at any scale: unit
 * normal, area and centroid.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Computed on the polygon moved to its first vertex and scaled by a power
 * of two (exact) to size about 1, so that neither a side of 1e-160 nor
 * one of 1e160 leaves the double range on the way (mesh.c, "Scale"). */
#include <config.h>

#include <math.h>
#include <string.h>

#include "mesh/mesh.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/scene.h"
#include "util/util.h"

/* 2^e with 2^(e-1) <= the largest |coordinate| of p[k] - p[0] < 2^e, or 0
 * when every vertex is p[0]: scaling by 2^-e is exact and brings the
 * polygon to size about 1 whatever its size in the user's units. */
static int local_exponent(const rad_vec3 *p, int n)
{
    double m = 0;
    int e = 0;
    for (int k = 1; k < n; k++) {
        double a = v3_maxabs(v3_sub(p[k], p[0]));
        m = a > m ? a : m;
    }
    if (m > 0 && isfinite(m))
        frexp(m, &e);
    return e;
}

/* (p - o) 2^-e, exactly unless the result is subnormal */
rad_vec3 radi_mesh_shrink(rad_vec3 p, rad_vec3 o, int e)
{
    rad_vec3 d = v3_sub(p, o);
    return v3(ldexp(d.x, -e), ldexp(d.y, -e), ldexp(d.z, -e));
}

/* Unit normal of a planar polygon: Newell's vector of the polygon scaled
 * to size about 1 (so it neither overflows nor underflows), normalised. */
rad_vec3 radi_mesh_unit_normal(const rad_vec3 *p, int n)
{
    const int e = local_exponent(p, n);
    rad_vec3 s = v3(0, 0, 0);
    for (int k = 1; k + 1 < n; k++)
        s = v3_add(s, v3_cross(radi_mesh_shrink(p[k], p[0], e),
                               radi_mesh_shrink(p[k + 1], p[0], e)));
    return v3_scale(s, 1.0 / v3_norm(s));
}

/* Area and centroid of a planar polygon: fan of triangles from p[0], on
 * the polygon scaled by 2^-e; the area is scaled back by 2^2e (inf or
 * subnormal when it is out of the double range: the caller refuses it). */
void radi_mesh_element_set(rad_element *e, int s, int gi, int gj, const rad_vec3 *p, int n,
                           int first, rad_vec3 nrm, const rad_material *mat)
{
    e->surface = s;
    e->gi = gi;
    e->gj = gj;
    e->nverts = n;
    e->first = first;
    e->normal = nrm;
    radi_mesh_area_centroid(p, n, nrm, &e->area, &e->centroid);
    memcpy(e->reflect, mat->reflect, sizeof e->reflect);
    memcpy(e->emit, mat->emit, sizeof e->emit);
}

void radi_mesh_area_centroid(const rad_vec3 *p, int n, rad_vec3 nrm, double *area,
                             rad_vec3 *centroid)
{
    const int e = local_exponent(p, n);
    double a = 0;
    rad_vec3 c = v3(0, 0, 0);
    for (int k = 1; k + 1 < n; k++) {
        rad_vec3 e1 = radi_mesh_shrink(p[k], p[0], e), e2 = radi_mesh_shrink(p[k + 1], p[0], e);
        double t = 0.5 * v3_dot(v3_cross(e1, e2), nrm);
        a += t;
        c = v3_add(c, v3_scale(v3_add(e1, e2), t / 3.0));
    }
    *area = ldexp(a, 2 * e);
    c = v3_scale(c, 1.0 / a); /* the centroid relative to p[0], scaled by 2^-e */
    *centroid = a > 0 ? v3_add(p[0], v3(ldexp(c.x, e), ldexp(c.y, e), ldexp(c.z, e))) : p[0];
}

