/* elmatch.c -- another solver's elements matched to ours by centroid
 * (elmatch.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The header line gives the columns by name, so tables with more or fewer
 * columns than ours read alike.  Each row is matched as it is read, by a
 * scan over all of the scene's centroids: O(n^2) distance tests, 5.8
 * million for the 20 x 20 cube (milliseconds), no spatial index to get
 * wrong.  The tolerance (elmatch.h) is relative to the scene so that the
 * units do not matter; 1e-6 of the diagonal lets a table printed with
 * seven significant digits match, and is far below any element's size in
 * a mesh this program can solve.  taken[p] remembers the line that
 * claimed our element p, for the message when another claims it too.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compare/elmatch.h"
#include "util/util.h"

enum { COL_ELEMENT, COL_CX, COL_CY, COL_CZ, NCOLS };

/* Columns by name from the header: col[c] = token index, or a failure. */
static rad_status header(const rad_lines *r, int col[NCOLS])
{
    static const char *const names[NCOLS] = {"element", "cx", "cy", "cz"};
    for (int c = 0; c < NCOLS; c++) {
        col[c] = -1;
        for (int t = 0; t < r->ntok; t++)
            if (strcmp(r->tok[t], names[c]) == 0)
                col[c] = t;
        if (col[c] < 0)
            return radi_lines_fail(r, "an element table needs the columns element, cx, cy "
                                     "and cz; '%s' is missing", names[c]);
    }
    return RAD_OK;
}

/* The scene's size: the diagonal of its vertices' bounding box. */
static double scene_size(const rad_mesh *m)
{
    rad_vec3 lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
    for (int v = 0; v < m->nvertices; v++) {
        const rad_vec3 p = m->vertices[v];
        lo = (rad_vec3){fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z)};
        hi = (rad_vec3){fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z)};
    }
    return m->nvertices > 0 ? hypot(hypot(hi.x - lo.x, hi.y - lo.y), hi.z - lo.z) : 0;
}

static double dist(rad_vec3 a, rad_vec3 b)
{
    return hypot(hypot(a.x - b.x, a.y - b.y), a.z - b.z);
}

/* The one scene element within tol of c: its index, or a failure. */
static rad_status nearest(const rad_lines *r, const rad_mesh *m, long k, rad_vec3 c,
                          double tol, int *out)
{
    int best = -1, second = -1;
    double d1 = INFINITY, d2 = INFINITY;
    for (int p = 0; p < m->nelements; p++) {
        const double d = dist(m->elements[p].centroid, c);
        if (d < d1)
            second = best, d2 = d1, best = p, d1 = d;
        else if (d < d2)
            second = p, d2 = d;
    }
    if (!(d1 <= tol))
        return radi_lines_fail(r, "element %ld at (%g, %g, %g): no element of the scene "
                                 "within %.3g (the nearest, %d, is %.3g away)",
                              k, c.x, c.y, c.z, tol, best, d1);
    if (d2 <= tol)
        return radi_lines_fail(r, "element %ld at (%g, %g, %g) is within %.3g of the "
                                 "scene's elements %d and %d: ambiguous",
                              k, c.x, c.y, c.z, tol, best, second);
    *out = best;
    return RAD_OK;
}

/* One row: element k at centroid c, matched and recorded. */
static rad_status row(const rad_lines *r, const rad_mesh *m, const int col[NCOLS], double tol,
                      int *perm, int *taken)
{
    long k;
    rad_vec3 c;
    int p = -1;
    rad_status st;
    for (int t = 0; t < NCOLS; t++)
        if (col[t] >= r->ntok)
            return radi_lines_fail(r, "%d fields; the header names more", r->ntok);
    if ((st = radi_tok_long(r, r->tok[col[COL_ELEMENT]], "element", 0, m->nelements - 1L,
                           &k)) ||
        (st = radi_tok_number(r, col[COL_CX], "cx", &c.x)) ||
        (st = radi_tok_number(r, col[COL_CY], "cy", &c.y)) ||
        (st = radi_tok_number(r, col[COL_CZ], "cz", &c.z)))
        return st;
    if (perm[k] >= 0)
        return radi_lines_fail(r, "element %ld is listed twice", k);
    if ((st = nearest(r, m, k, c, tol, &p)))
        return st;
    if (taken[p])
        return radi_lines_fail(r, "element %ld matches the scene's element %d, as the "
                                 "element of line %d does", k, p, taken[p]);
    taken[p] = r->line;
    perm[k] = p;
    return RAD_OK;
}

rad_status radi_elements_match(const char *path, const rad_mesh *mesh, int *perm,
                              rad_error *err)
{
    const int n = mesh->nelements;
    const double tol = RAD_MATCH_TOL * scene_size(mesh);
    int *taken = calloc((size_t)n + 1, sizeof *taken), col[NCOLS], k, rows = 0;
    rad_lines r;
    if (!taken)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory matching %d elements", n);
    for (int i = 0; i < n; i++)
        perm[i] = -1;
    rad_status st = radi_lines_open(&r, path, '#', err);
    while (st == RAD_OK && (k = radi_lines_next(&r)) == 1 && r.ntok == 0)
        ;
    if (st == RAD_OK)
        st = k < 0 ? r.status : k == 0 ? radi_lines_fail(&r, "empty element table")
                                       : header(&r, col);
    while (st == RAD_OK && (k = radi_lines_next(&r)) != 0) {
        if (k < 0)
            st = r.status;
        else if (r.ntok > 0 && ++rows > n)
            st = radi_lines_fail(&r, "more than the scene's %d elements", n);
        else if (r.ntok > 0)
            st = row(&r, mesh, col, tol, perm, taken);
    }
    if (st == RAD_OK && rows < n)
        st = radi_lines_fail(&r, "%d elements; the scene has %d", rows, n);
    radi_lines_close(&r);
    free(taken);
    return st;
}
