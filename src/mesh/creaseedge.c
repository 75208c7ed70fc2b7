/* creaseedge.c -- smoothing across an edge that two surfaces cut differently.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * crease.c merges the values of vertices at one point.  Two faces of a
 * model that share an edge but are cut into different numbers of parts
 * (--max-element-size cuts each face by its own longest side) do not have
 * their points at the same places along it: the finer side's extra points
 * are hanging, and each side, linear between its own points, shows a
 * step along the edge.  The rule here is the one for hanging vertices in
 * a subdivided mesh (Cohen et al. 1988, section 4; Baum et al. 1991): on
 * the segment between two consecutive points that both sides share (the
 * edge's ends at least), every point of either side that the other side
 * lacks takes the linear interpolation of the shared points' values, so
 * both sides are linear there and agree.  When one side's parts divide
 * the other's (n and 2n), the shared points are the coarser side's and
 * only the finer side's extra points move, as an adaptive mesh's hanging
 * vertices do.
 *
 * Which vertices lie on an edge: a vertex of surface S lies on the
 * outline edge (c_k, c_k+1) of S when its distance from the segment is
 * within the tolerance of crease.c's points (a few cells of 2^-30 of the
 * scene); its parameter t orders the edge's points.  A point of S's edge
 * is shared with surface T when crease.c's point of it holds a vertex of
 * T and the two may be smoothed across (smooth_pair in crease.c, passed
 * in as a callback).  Only the surfaces' own corners and lattice points
 * are moved; values are interpolated from `out` (the merged values) and
 * written to it.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "mesh/mesh.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "util/util.h"

typedef struct edge_pt {
    double t;                   /* along the edge, 0 at c_k, 1 at c_k+1 */
    int v;                      /* the vertex */
} edge_pt;

static int by_t(const void *a, const void *b)
{
    const edge_pt *x = a, *y = b;
    return x->t < y->t ? -1 : x->t > y->t ? 1 : x->v - y->v;
}

/* The vertices of surface s within distance tol of the segment (a, b),
 * sorted along it; returns how many (pt has room for every vertex of s). */
static int on_edge(const rad_mesh *m, int s, rad_vec3 a, rad_vec3 b, double tol, edge_pt *pt)
{
    const rad_vec3 d = v3_sub(b, a);
    const double dd = v3_dot(d, d), slack = tol / sqrt(dd);
    int n = 0;
    if (!(dd > 0) || !(slack < 0.25))
        return 0;
    for (int v = m->surface_vfirst[s]; v < m->surface_vfirst[s + 1]; v++) {
        const rad_vec3 p = v3_sub(m->vertices[v], a);
        const double t = v3_dot(p, d) / dd;
        const rad_vec3 off = v3_sub(p, v3_scale(d, t));
        if (t >= -slack && t <= 1 + slack && v3_dot(off, off) <= tol * tol)
            pt[n++] = (edge_pt){t, v};
    }
    qsort(pt, (size_t)n, sizeof *pt, by_t);
    return n;
}

/* Does the point of vertex v hold a vertex of surface t that may be
 * smoothed with surface s? */
static int shared_with(const radi_crease_points *cp, int v, int s, int t)
{
    const int p = cp->point_of[v];
    if (p < 0)
        return 0;
    for (size_t j = cp->first[p]; j < cp->first[p + 1]; j++)
        if (cp->surface[j] == t && cp->may_join(cp->ctx, s, t))
            return 1;
    return 0;
}

/* On edge pt[0..n) of surface s, against surface t: interpolate the
 * points between consecutive shared ones. */
static void follow(const radi_crease_points *cp, int s, int t, const edge_pt *pt, int n,
                   double *out, size_t nv)
{
    int a = -1;
    for (int i = 0; i < n; i++) {
        if (!shared_with(cp, pt[i].v, s, t))
            continue;
        for (int j = a + 1; a >= 0 && j < i; j++) {
            const double u = (pt[j].t - pt[a].t) / (pt[i].t - pt[a].t);
            for (int b = 0; b < RAD_BANDS; b++) {
                const double *o = out + (size_t)b * nv;
                out[(size_t)pt[j].v + (size_t)b * nv] =
                    (1 - u) * o[pt[a].v] + u * o[pt[i].v];
            }
        }
        a = i;
    }
}

/* The surfaces other than s that share a point with edge pt[0..n) of s,
 * each once, into other; returns how many. */
static int neighbours(const radi_crease_points *cp, int s, const edge_pt *pt, int n, int *other,
                      int cap)
{
    int k = 0;
    for (int i = 0; i < n; i++) {
        const int p = cp->point_of[pt[i].v];
        for (size_t j = p < 0 ? 0 : cp->first[p]; p >= 0 && j < cp->first[p + 1]; j++) {
            const int t = cp->surface[j];
            int seen = t == s;
            for (int q = 0; q < k && !seen; q++)
                seen = other[q] == t;
            if (!seen && k < cap)
                other[k++] = t;
        }
    }
    return k;
}

rad_status radi_crease_edges(const rad_mesh *m, const radi_crease_points *cp, double tol,
                             double *out, rad_error *err)
{
    const size_t nv = (size_t)m->nvertices;
    int maxv = 0, maxk = 0;
    for (int s = 0; s < m->nsurfaces; s++) {
        const int k = m->surface_vfirst[s + 1] - m->surface_vfirst[s];
        maxv = k > maxv ? k : maxv;
        const int c = radi_mesh_outline(m, s, NULL);
        maxk = c > maxk ? c : maxk;
    }
    /* surfaces met along one edge: a model's edge has 2; past 64 (a fan
     * of fins on one line) the rest keep their merged values */
    enum { OTHERS = 64 };
    edge_pt *pt = malloc(sizeof *pt * (size_t)(maxv ? maxv : 1));
    rad_vec3 *c = malloc(sizeof *c * (size_t)(maxk ? maxk : 1));
    if (!pt || !c) {
        free(pt);
        free(c);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory to smooth across edges");
    }
    for (int s = 0; s < m->nsurfaces; s++) {
        const int K = radi_mesh_outline(m, s, c);
        for (int k = 0; k < K; k++) {
            const int n = on_edge(m, s, c[k], c[(k + 1) % K], tol, pt);
            int other[OTHERS];
            const int no = n > 2 ? neighbours(cp, s, pt, n, other, OTHERS) : 0;
            for (int q = 0; q < no; q++)
                follow(cp, s, other[q], pt, n, out, nv);
        }
    }
    free(pt);
    free(c);
    return RAD_OK;
}
