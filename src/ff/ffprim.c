/* ffprim.c -- the primitives of a pair: edges, polygons, doubt, promise.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * What the pair kernel (formfactor.c and the integrators below it), the
 * fills above it (ffmatrix.c, ffblock.c, ffrow.c, hcmatrix.c) and the
 * hidden-surface code all share, kept here so that each of them calls
 * down into this file and none calls up into a router or a fill:
 *   - a polygon's edges relative to an origin and the colinearity test of
 *     the paper's closed form (Goral et al. 1984, eq. 13 with colinear
 *     edges integrated exactly);
 *   - a polygon made for the kernel (normal by Newell's method, centroid,
 *     lengths) and the round-off doubt R3 of ffarea.c on its normal;
 *   - the element polygons of a mesh, as every fill must see them;
 *   - each accuracy mode's promise and the statistics of a filled F.
 * Lengths are those of the caller's frame (the fills' frame is the unit
 * box of mesh.h); form factors are dimensionless.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ff/formfactor.h"
#include "mesh/mesh.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "util/util.h"

/* Colinear (formfactor.h).  The classic rule's Gauss points would hit or
 * nearly hit r = 0 there, so the paper integrates them in closed form. */
int radi_ff_colinear(const rad_ff_edge *p, const rad_ff_edge *q)
{
    rad_vec3 w = v3_sub(q->p0, p->p0);
    rad_vec3 perp = v3_sub(w, v3_scale(p->e, v3_dot(w, p->e)));
    double lmax = p->len > q->len ? p->len : q->len;
    return v3_dot(perp, perp) <= 1e-24 * lmax * lmax;
}

int radi_ff_edges(const rad_vec3 *p, int n, rad_vec3 origin, rad_ff_edge *e)
{
    int m = 0;
    for (int k = 0; k < n; k++) {
        rad_vec3 a = v3_sub(p[k], origin), b = v3_sub(p[(k + 1) % n], origin);
        rad_ff_edge *x = &e[m];
        x->v0 = p[k];
        x->p0 = a;
        x->d = v3_sub(b, a);
        x->mid = v3_add(a, v3_scale(x->d, 0.5));
        x->len = v3_norm(x->d);
        if (!(x->len > 0))
            continue;
        x->e = v3_scale(x->d, 1.0 / x->len);
        m++;
    }
    return m;
}

/* perimeter, longest edge, radius about the centroid and twist, from the
 * edges (their starts are relative to the centroid) */
static void ff_poly_lengths(rad_ff_poly *p)
{
    p->perimeter = 0;
    p->lmax = 0;
    p->radius = 0;
    p->twist = 0;
    for (int k = 0; k < p->nedges; k++) {
        const double r = v3_norm(p->edges[k].p0);
        const double h = fabs(v3_dot(p->normal, p->edges[k].p0));
        p->twist = h > p->twist ? h : p->twist;
        p->perimeter += p->edges[k].len;
        p->lmax = p->edges[k].len > p->lmax ? p->edges[k].len : p->lmax;
        p->radius = r > p->radius ? r : p->radius;
    }
}

/* R3 of ffarea.c for a polygon of n vertices, bounding-box diagonal
 * size and Newell vector of length twice (twice its area). */
static double doubt_of(int n, double size, double twice)
{
    return twice > 0 ? DBL_EPSILON * (4 + 8.0 * (n - 2) * (size / twice) * size) : INFINITY;
}

double radi_ff_normal_doubt(const rad_vec3 *p, int n)
{
    rad_vec3 lo, hi;
    v3_bounds(p, n, &lo, &hi);
    return doubt_of(n, v3_norm(v3_sub(hi, lo)), v3_norm(v3_newell(p, n)));
}

double radi_ff_element_doubt(const rad_mesh *m, int e)
{
    const rad_element *el = &m->elements[e];
    const int s = el->surface, v0 = m->surface_vfirst[s];
    const int n = m->surface_n[s], mm = m->surface_m[s];
    rad_vec3 c[4];
    if (radi_mesh_is_fan(m, s)) /* a polygon cut into triangles: its corners first */
        return radi_ff_normal_doubt(m->vertices + v0, radi_mesh_outline(m, s, NULL));
    if (n == 1 && mm == 1 && el->nverts != 4) /* a polygon, its vertices in order */
        return radi_ff_normal_doubt(m->vertices + v0, m->surface_vfirst[s + 1] - v0);
    if (n == 1 && mm == 1) { /* the element is its surface */
        for (int k = 0; k < 4; k++)
            c[k] = rad_mesh_vertex(m, e, k);
        return radi_ff_normal_doubt(c, 4);
    }
    /* a quad's grid, row-major: its corners */
    c[0] = m->vertices[v0];
    c[1] = m->vertices[v0 + n];
    c[2] = m->vertices[v0 + mm * (n + 1) + n];
    c[3] = m->vertices[v0 + mm * (n + 1)];
    return radi_ff_normal_doubt(c, 4);
}

void radi_ff_poly_make(rad_ff_poly *poly, const rad_vec3 *v, int n, rad_ff_edge *edges)
{
    rad_vec3 nw = v3_newell(v, n), lo = v[0], hi = v[0], c = v3(0, 0, 0);
    double a = 0.5 * v3_norm(nw);
    rad_vec3 nrm = a > 0 ? v3_scale(nw, 0.5 / a) : v3(0, 0, 1);
    for (int k = 1; k + 1 < n; k++) {
        rad_vec3 e1 = v3_sub(v[k], v[0]), e2 = v3_sub(v[k + 1], v[0]);
        double t = 0.5 * v3_dot(v3_cross(e1, e2), nrm);
        c = v3_add(c, v3_scale(v3_add(e1, e2), t / 3.0));
    }
    v3_bounds(v, n, &lo, &hi);
    poly->v = v;
    poly->n = n;
    poly->normal = nrm;
    poly->area = a;
    poly->centroid = a > 0 ? v3_add(v[0], v3_scale(c, 1.0 / a)) : v[0];
    poly->size = v3_norm(v3_sub(hi, lo));
    poly->nu = doubt_of(n, poly->size, 2 * a);
    poly->lo = lo;
    poly->hi = hi;
    poly->edges = edges;
    poly->nedges = radi_ff_edges(v, n, poly->centroid, edges);
    ff_poly_lengths(poly);
    poly->snap = 0;
}

/* Element polygons with contiguous vertices, as the kernel wants them
 * (ffblock.h; also the per-shot rows of ffrow.c, which must see the same
 * polygons), each with the scene's snap (radi_occ_scene_snap). */
rad_status radi_ff_mesh_polys(const rad_mesh *m, double snap, rad_ff_poly **polys,
                             rad_vec3 **pts, rad_ff_edge **edges)
{
    size_t total = 0, ne = m->nelements > 0 ? (size_t)m->nelements : 1;
    for (int e = 0; e < m->nelements; e++)
        total += (size_t)m->elements[e].nverts;
    *polys = malloc(sizeof **polys * ne);
    *pts = malloc(sizeof **pts * (total ? total : 1));
    *edges = malloc(sizeof **edges * (total ? total : 1));
    if (!*polys || !*pts || !*edges)
        return RAD_ERR_NOMEM;
    size_t at = 0;
    for (int e = 0; e < m->nelements; e++) {
        const rad_element *el = &m->elements[e];
        rad_ff_poly *p = &(*polys)[e];
        for (int k = 0; k < el->nverts; k++)
            (*pts)[at + (size_t)k] = rad_mesh_vertex(m, e, k);
        radi_ff_poly_make(p, *pts + at, el->nverts, *edges + at);
        /* the mesh's own normal (shared by a surface), centroid and area */
        p->normal = el->normal;
        p->nu = radi_ff_element_doubt(m, e);
        p->centroid = el->centroid;
        p->area = el->area;
        p->nedges = radi_ff_edges(p->v, p->n, p->centroid, p->edges);
        ff_poly_lengths(p);
        p->snap = snap;
        at += (size_t)el->nverts;
    }
    return RAD_OK;
}

/* The promise of each mode on an entry's relative error (README,
 * radiosity.h; ffblock.h). */
double radi_ff_promise(rad_accuracy a)
{
    return a == RAD_ACCURACY_REFERENCE ? 1e-9 : a == RAD_ACCURACY_DEFAULT ? 1e-6 : NAN;
}

/* Counts and extremes of the entries i0 <= i < i1 of one column. */
typedef struct fill_tally {
    double lo, hi;
    size_t neg, above, nonzero;
} fill_tally;

/* One entry into the tally: as fmin and fmax, a NaN is passed over. */
static inline void tally_one(double f, double *lo, double *hi, size_t *neg, size_t *above,
                             size_t *nonzero)
{
    *neg += f < 0;
    *above += f > 1;
    *nonzero += f != 0;
    *lo = f < *lo ? f : *lo;
    *hi = f > *hi ? f : *hi;
}

/* The entries four at a time where vector extensions exist (a quarter of
 * the instructions: the tally was 2.5% of the cube's unobstructed fill),
 * each lane as tally_one, the lanes then tallied in order; the rest one
 * at a time.  Of +0 and -0 either may be kept as an extreme (the sign of
 * a zero extreme only). */
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
RAD_KERNEL_CLONES
static void tally_run(const double *col, size_t i0, size_t i1, fill_tally *t)
{
    double lo = t->lo, hi = t->hi;
    size_t neg = 0, above = 0, nonzero = 0, i = i0;
#if defined(__GNUC__)
    if (i1 - i0 >= 8) {
        rad_v4d lo4 = {lo, lo, lo, lo}, hi4 = {hi, hi, hi, hi};
        rad_v4i neg4 = {0}, above4 = {0}, nz4 = {0};
        for (; i + 4 <= i1; i += 4) {
            rad_v4d f;
            memcpy(&f, col + i, sizeof f);
            neg4 -= f < 0; /* a comparison is -1 in a lane where it holds */
            above4 -= f > 1;
            nz4 -= f != 0;
            const rad_v4i l = f < lo4, h = f > hi4;
            lo4 = (rad_v4d)((l & (rad_v4i)f) | (~l & (rad_v4i)lo4));
            hi4 = (rad_v4d)((h & (rad_v4i)f) | (~h & (rad_v4i)hi4));
        }
        for (int k = 0; k < 4; k++) {
            neg += (size_t)neg4[k];
            above += (size_t)above4[k];
            nonzero += (size_t)nz4[k];
            lo = lo4[k] < lo ? lo4[k] : lo;
            hi = hi4[k] > hi ? hi4[k] : hi;
        }
    }
#endif
    for (; i < i1; i++)
        tally_one(col[i], &lo, &hi, &neg, &above, &nonzero);
    t->lo = lo;
    t->hi = hi;
    t->neg += neg;
    t->above += above;
    t->nonzero += nonzero;
}
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

/* One pass down F's columns (F is column-major) for the off-diagonal
 * entries' counts and extremes; each row's sum is taken over j in
 * ascending order, in a second pass that adds whole columns to the n sums
 * when memory allows and walks each row across the columns otherwise:
 * the same order, so the same sums bit for bit. */
void radi_ff_fill_stats(const double *F, int n, rad_ff_stats *st)
{
    const size_t nn = n > 0 ? (size_t)n : 0;
    fill_tally t = {HUGE_VAL, -HUGE_VAL, 0, 0, 0};
    st->pairs = 0.5 * (double)n * (n - 1);
    for (size_t j = 0; j < nn; j++) {
        tally_run(F + j * nn, 0, j, &t);
        tally_run(F + j * nn, j + 1, nn, &t);
    }
    st->negative += (long)t.neg;
    st->above_one += (long)t.above;
    st->integrated += 0.5 * (double)t.nonzero;
    st->min_value = n < 2 ? 0 : t.lo;
    st->max_value = n < 2 ? 0 : t.hi;
    double *row = calloc(nn ? nn : 1, sizeof *row);
    for (size_t j = 0; row && j < nn; j++)
        for (size_t i = 0; i < nn; i++)
            row[i] += F[i + j * nn];
    for (size_t i = 0; i < nn; i++) {
        double r = 0;
        if (row)
            r = row[i];
        else
            for (size_t j = 0; j < nn; j++)
                r += F[i + j * nn];
        st->rows_above_one += r > 1 + RAD_ROW_SUM_SLACK;
    }
    free(row);
}
