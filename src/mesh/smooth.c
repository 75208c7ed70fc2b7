/* smooth.c -- element radiosity to vertex radiosity.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Goral et al. 1984, section 3 ("linear smoothing"), for Gouraud (1971)
 * shading.  Inside each scene surface, on its N x M grid of elements:
 *   - an interior vertex takes the mean of the four elements around it;
 *   - a vertex on the boundary (not a corner) between elements 1 and 2,
 *     whose neighbours one row inwards are 3 and 4, is extrapolated
 *     linearly:  B = (3 B1 + 3 B2 - B3 - B4) / 4;
 *   - a corner vertex is extrapolated along the diagonal from its element
 *     c and the diagonal neighbour d:  B = 1.5 B_c - 0.5 B_d.
 * Both extrapolations reproduce a field linear over the surface exactly
 * (element values sampled at the centres of a uniform grid).  Where the
 * grid is one element thick in a direction, extrapolation across that
 * direction is impossible and the formula degrades to the one-dimensional
 * rule (mean of 1 and 2; 1.5 B_c - 0.5 B_next) or the element's own value.
 * Results are clamped at 0, and never mix surfaces: walls of different
 * colours meet at a crease.  A polygon (one element) gives every vertex its
 * element's value.  A polygon cut into triangles (meshtri.c) gives each
 * vertex the area-weighted mean of the triangles around it: on the
 * uniform lattice of a triangle an inner vertex is the centre of its six
 * triangles' centroids, so the mean reproduces a linear field there; on
 * the outline it is the mean of the elements inside (no extrapolation).
 *
 * The corner rule (RAD_VERTEX_CORNER) is the one of the SIGGRAPH course
 * notes on radiosity (Cohen & Wallace, Radiosity and Realistic Image
 * Synthesis, 1993, section 9.2.2): a boundary vertex b takes the value for
 * which the mean of b and its nearest interior vertex I equals the mean
 * of the elements meeting at b,  (B_b + B_I) / 2 = mean(elements at b).
 * On an edge, with I the interior vertex inwards (the mean of 1, 2, 3, 4),
 * that is B_b = B1 + B2 - B_I = (3 B1 + 3 B2 - B3 - B4) / 4, the paper's
 * extrapolation again; at a corner, with I the diagonal vertex (the mean
 * of c, its neighbours u and v, and d),
 *     B = 2 B_c - (B_c + B_u + B_v + B_d) / 4 = (7 B_c - B_u - B_v - B_d) / 4,
 * which equals 1.5 B_c - 0.5 B_d on a linear field (B_u + B_v = B_c + B_d)
 * and weighs the corner's own element more otherwise.  A grid one element
 * thick has no interior vertex: both rules are the same there.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "radiosity/base.h"
#include "mesh/mesh.h"
#include "radiosity/mesh.h"

/* B of element (gi, gj) of surface s, band b (indices clamped to the grid). */
static double el(const rad_mesh *m, const double *B, int s, int gi, int gj, int b)
{
    const int n = m->surface_n[s], mm = m->surface_m[s];
    gi = gi < 0 ? 0 : gi >= n ? n - 1 : gi;
    gj = gj < 0 ? 0 : gj >= mm ? mm - 1 : gj;
    return B[(size_t)(m->surface_first[s] + gj * n + gi) + (size_t)b * m->nelements];
}

/* One coordinate direction of the rule: the two elements touching the
 * vertex along it (lo, hi), or, at the boundary, the element and the one
 * behind it for extrapolation. Returns weights w0 for the touching row and
 * w1 for the row behind: interior (0.5, 0 of each), boundary (1.5, -0.5). */
static void axis_rule(int g, int count, int *i0, int *i1, double *w0, double *w1)
{
    if (g > 0 && g < count) { /* interior along this axis: the two neighbours */
        *i0 = g - 1;
        *i1 = g;
        *w0 = 0.5;
        *w1 = 0.5;
    } else if (count == 1) { /* one element thick: its own value */
        *i0 = *i1 = 0;
        *w0 = 1;
        *w1 = 0;
    } else if (g == 0) { /* extrapolate from elements 0 and 1 */
        *i0 = 0;
        *i1 = 1;
        *w0 = 1.5;
        *w1 = -0.5;
    } else {
        *i0 = count - 1;
        *i1 = count - 2;
        *w0 = 1.5;
        *w1 = -0.5;
    }
}

/* The rule is the tensor product of the per-axis rules: interior x interior
 * is the 4-element mean; boundary x interior is (3B1 + 3B2 - B3 - B4)/4;
 * boundary x boundary is 2.25 B_c - 0.75 B_u - 0.75 B_v + 0.25 B_d, which on
 * a linear field equals 1.5 B_c - 0.5 B_d.  The paper's corner formula is
 * used as printed instead (it needs only the diagonal). */
static double vertex_value(const rad_mesh *m, const double *B, int s, int gi, int gj, int b,
                           rad_vertex_rule rule)
{
    const int n = m->surface_n[s], mm = m->surface_m[s];
    const int corner = (gi == 0 || gi == n) && (gj == 0 || gj == mm);
    if (corner && n > 1 && mm > 1) {
        int ci = gi == 0 ? 0 : n - 1, cj = gj == 0 ? 0 : mm - 1;
        int di = gi == 0 ? 1 : n - 2, dj = gj == 0 ? 1 : mm - 2;
        const double c = el(m, B, s, ci, cj, b), d = el(m, B, s, di, dj, b);
        if (rule == RAD_VERTEX_CORNER) /* (7 B_c - B_u - B_v - B_d) / 4 */
            return (7 * c - el(m, B, s, di, cj, b) - el(m, B, s, ci, dj, b) - d) / 4;
        return 1.5 * c - 0.5 * d;
    }
    int a0, a1, c0, c1;
    double u0, u1, v0, v1;
    axis_rule(gi, n, &a0, &a1, &u0, &u1);
    axis_rule(gj, mm, &c0, &c1, &v0, &v1);
    return u0 * v0 * el(m, B, s, a0, c0, b) + u1 * v0 * el(m, B, s, a1, c0, b) +
           u0 * v1 * el(m, B, s, a0, c1, b) + u1 * v1 * el(m, B, s, a1, c1, b);
}

const char *rad_vertex_rule_name(int rule)
{
    return rule == RAD_VERTEX_EXTRAPOLATE ? "extrapolate"
           : rule == RAD_VERTEX_CORNER    ? "corner"
                                          : NULL;
}

void rad_smooth_vertices(const rad_mesh *m, const double *B, double *Bv)
{
    rad_smooth_vertices_rule(m, B, Bv, RAD_VERTEX_EXTRAPOLATE);
}

/* Surface s, a polygon cut into triangles: each vertex the area-weighted
 * mean of the elements that have it (w: one weight per vertex of s, or
 * NULL when there was no memory for it: the last element's value). */
static void smooth_fan(const rad_mesh *m, const double *B, double *Bv, int s, double *w)
{
    const int v0 = m->surface_vfirst[s], nv = m->surface_vfirst[s + 1] - v0;
    for (int v = 0; v < nv; v++) {
        if (w)
            w[v] = 0;
        for (int b = 0; b < RAD_BANDS; b++)
            Bv[(size_t)(v0 + v) + (size_t)b * m->nvertices] = 0;
    }
    for (int e = m->surface_first[s]; e < m->surface_first[s + 1]; e++) {
        const rad_element *el = &m->elements[e];
        for (int k = 0; k < el->nverts; k++) {
            const int v = m->vindex[el->first + k];
            const double a = w ? el->area : 1;
            if (w)
                w[v - v0] += a;
            for (int b = 0; b < RAD_BANDS; b++) {
                double *out = &Bv[(size_t)v + (size_t)b * m->nvertices];
                const double x = B[(size_t)e + (size_t)b * m->nelements];
                *out = w ? *out + a * x : x;
            }
        }
    }
    for (int v = 0; w && v < nv; v++)
        for (int b = 0; b < RAD_BANDS; b++)
            if (w[v] > 0)
                Bv[(size_t)(v0 + v) + (size_t)b * m->nvertices] /= w[v];
}

void rad_smooth_vertices_rule(const rad_mesh *m, const double *B, double *Bv,
                              rad_vertex_rule rule)
{
    double *w = NULL;
    for (int s = 0; s < m->nsurfaces; s++) {
        const int first = m->surface_first[s], vfirst = m->surface_vfirst[s];
        const rad_element *e0 = &m->elements[first];
        if (radi_mesh_is_fan(m, s)) {
            free(w);
            w = malloc(sizeof *w * (size_t)(m->surface_vfirst[s + 1] - vfirst));
            smooth_fan(m, B, Bv, s, w);
            continue;
        }
        if (m->surface_first[s + 1] - first == 1 && e0->nverts != 4) { /* polygon */
            for (int k = 0; k < e0->nverts; k++)
                for (int b = 0; b < RAD_BANDS; b++)
                    Bv[(size_t)m->vindex[e0->first + k] + (size_t)b * m->nvertices] =
                        B[(size_t)first + (size_t)b * m->nelements];
            continue;
        }
        const int n = m->surface_n[s], mm = m->surface_m[s];
        for (int gj = 0; gj <= mm; gj++)
            for (int gi = 0; gi <= n; gi++)
                for (int b = 0; b < RAD_BANDS; b++) {
                    double v = vertex_value(m, B, s, gi, gj, b, rule);
                    Bv[(size_t)(vfirst + gj * (n + 1) + gi) + (size_t)b * m->nvertices] =
                        v > 0 ? v : 0.0;
                }
    }
    free(w);
}
