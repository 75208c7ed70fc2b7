/* objrepair.c -- the faces an OBJ file may hold that importers accept and
 * the native format refuses, repaired and counted.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * OBJ is a foreign format: modelling tools write faces that
 * radi_polygon_check refuses (a quad whose fourth corner is 2.5e-6 off the
 * plane of the other three, a concave outline of 66 corners, a corner
 * written twice, a face whose corners all coincide), and mainstream
 * importers take them.  So, unless the caller asks for RAD_SCENE_STRICT
 * (objread.c), a face is repaired here, and every repair is counted in
 * rad_scene_repairs for the caller to say:
 *
 *   - a face outside the sizes the program accepts is refused, as the
 *     check says (no repair rescales a scene);
 *   - corners repeated one after the other are merged; a face left with
 *     fewer than 3 corners, or with all its corners on a line (within
 *     1e-12 of its length), is left out; one whose area vanishes otherwise
 *     (|Newell vector| / 2 at most 1e-14 of its diameter squared: loops of
 *     opposite turn, a symmetric bow tie) crosses itself and is refused;
 *   - a face that radi_polygon_check still refuses (not planar, not
 *     convex, or a corner merged) is cut into triangles by ear clipping
 *     (Meisters, "Polygons have ears", Amer. Math. Monthly 82, 1975) in the
 *     plane that its Newell vector is most normal to, keeping its corners'
 *     order, so every triangle faces as the face did.  Each triangle is
 *     planar whatever the face was.  An outline two of whose edges cross
 *     properly in that plane (corners written twice may touch: the cut to
 *     a hole) is refused with the check's own message, as is one that
 *     clipping cannot consume;
 *   - an outline that runs round the same corners again ("f 1 2 3 4 1 2 3
 *     4 ...", a test of long lines) is taken once, and cut as above.  Triangles without area (three corners on a line) are
 *     left out: they carry nothing.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/objrepair.h"
#include "scene/polycheck.h"

void radi_obj_note(rad_scene_repairs *rep, int kind, int line)
{
    int *count[4] = {&rep->undefined_materials, &rep->spaced_names, &rep->degenerate_faces,
                     &rep->split_faces};
    if (++*count[kind] == 1 || rep->first_line[kind] == 0)
        rep->first_line[kind] = line;
}

/* Merge corners repeated one after the other (and the last with the
 * first): the count left. */
static int merge_repeats(rad_vec3 *v, int n)
{
    int m = 0;
    for (int k = 0; k < n; k++)
        if (m == 0 || memcmp(&v[k], &v[m - 1], sizeof *v) != 0)
            v[m++] = v[k];
    while (m > 1 && memcmp(&v[0], &v[m - 1], sizeof *v) == 0)
        m--;
    return m;
}

static double diameter2(const rad_vec3 *v, int n)
{
    double d = 0;
    for (int k = 0; k < n; k++)
        for (int l = k + 1; l < n; l++) {
            const rad_vec3 e = v3_sub(v[k], v[l]);
            d = fmax(d, v3_dot(e, e));
        }
    return d;
}

/* 2-D coordinates of v, relative to v[0] (so that round-off does not
 * depend on where the face sits), in the plane most normal to N, turned
 * so that the outline runs counter-clockwise (positive area). */
static void project(const rad_vec3 *v, int n, rad_vec3 N, double (*p)[2])
{
    const double ax = fabs(N.x), ay = fabs(N.y), az = fabs(N.z);
    const int drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    const double sign = (drop == 0 ? N.x : drop == 1 ? N.y : N.z) < 0 ? -1 : 1;
    for (int k = 0; k < n; k++) {
        const rad_vec3 d = v3_sub(v[k], v[0]);
        const double c[3] = {d.x, d.y, d.z};
        /* (u, w) right-handed about the dropped axis */
        p[k][0] = c[(drop + 1) % 3];
        p[k][1] = sign * c[(drop + 2) % 3];
    }
}

static double cross2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static int same2(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1];
}

/* Is q inside or on triangle a b c (counter-clockwise)?  A corner at one
 * of a, b, c is not: an outline joined to a hole by a cut runs through
 * the cut's corners twice. */
static int in_triangle(const double *q, const double *a, const double *b, const double *c)
{
    return cross2(a, b, q) >= 0 && cross2(b, c, q) >= 0 && cross2(c, a, q) >= 0;
}

/* Do two edges of the outline cross properly (each one's ends strictly
 * on the two sides of the other's line)?  Edges that share a corner, or
 * meet at a corner written twice (the cut to a hole), only touch. */
static int crosses_itself(double (*p)[2], int n)
{
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            const double *a = p[i], *b = p[(i + 1) % n], *c = p[j], *d = p[(j + 1) % n];
            if (same2(a, c) || same2(a, d) || same2(b, c) || same2(b, d))
                continue;
            const double d1 = cross2(a, b, c), d2 = cross2(a, b, d);
            const double d3 = cross2(c, d, a), d4 = cross2(c, d, b);
            if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
                ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
                return 1;
        }
    return 0;
}

/* Ear clipping of the counter-clockwise outline p[0..n): triangles as
 * index triples into tri (n - 2 of them); 0, or -1 when no ear is left
 * (the outline crosses itself). */
static int clip_ears(double (*p)[2], int n, int *tri)
{
    int *idx = malloc(sizeof *idx * (size_t)n), m = n, t = 0;
    if (!idx)
        return -2;
    for (int k = 0; k < n; k++)
        idx[k] = k;
    while (m > 3) {
        int found = -1;
        for (int k = 0; k < m && found < 0; k++) {
            const int a = idx[(k + m - 1) % m], b = idx[k], c = idx[(k + 1) % m];
            if (!(cross2(p[a], p[b], p[c]) > 0))
                continue; /* reflex or flat: no ear */
            int clear = 1;
            for (int l = 0; l < m && clear; l++) {
                const int q = idx[l];
                if (q != a && q != b && q != c && !same2(p[q], p[a]) && !same2(p[q], p[b]) &&
                    !same2(p[q], p[c]) && in_triangle(p[q], p[a], p[b], p[c]))
                    clear = 0;
            }
            if (clear)
                found = k;
        }
        if (found < 0) {
            free(idx);
            return -1;
        }
        tri[3 * t] = idx[(found + m - 1) % m];
        tri[3 * t + 1] = idx[found];
        tri[3 * t + 2] = idx[(found + 1) % m];
        t++;
        memmove(idx + found, idx + found + 1, sizeof *idx * (size_t)(m - found - 1));
        m--;
    }
    tri[3 * t] = idx[0];
    tri[3 * t + 1] = idx[1];
    tri[3 * t + 2] = idx[2];
    free(idx);
    /* the last three turn the right way too, or the outline was no simple
     * one (a bow tie's second loop turns the other way) */
    return cross2(p[tri[3 * t]], p[tri[3 * t + 1]], p[tri[3 * t + 2]]) >= 0 ? 0 : -1;
}

/* Add the triangles tri[0..3 (n - 2)) of v; their count into *added. */
static rad_status add_triangles(rad_scene_build *b, rad_lines *r, const rad_vec3 *v,
                                const int *tri, int ntri, int mat, int object, int *added)
{
    *added = 0;
    for (int t = 0; t < ntri; t++) {
        rad_vec3 *w = malloc(sizeof *w * 3);
        if (!w)
            return radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory", r->name, r->line);
        for (int k = 0; k < 3; k++)
            w[k] = v[tri[3 * t + k]];
        rad_error scratch;
        if (radi_polygon_check(w, 3, "face", r->name, r->line, &scratch) != RAD_OK) {
            free(w); /* three corners on a line: no area, nothing lost */
            continue;
        }
        rad_status st = radi_build_add_surface(b, r->line, RAD_SURFACE_POLYGON, mat, object, w,
                                               3, 1, 1);
        if (st)
            return st;
        ++*added;
    }
    return RAD_OK;
}

/* Cut v[0..n) (normal N) into triangles and add them; RAD_ERR_PARSE with
 * `why` (the check's message) when it cannot be cut. */
static rad_status split_face(rad_scene_build *b, rad_lines *r, const rad_vec3 *v, int n,
                             rad_vec3 N, int mat, int object, const rad_error *why)
{
    double (*p)[2] = malloc(sizeof *p * (size_t)n);
    int *tri = malloc(sizeof *tri * 3 * (size_t)(n - 2));
    rad_status st = RAD_OK;
    if (!p || !tri) {
        st = radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory", r->name, r->line);
        goto done;
    }
    project(v, n, N, p);
    const int c = crosses_itself(p, n) ? -1 : clip_ears(p, n, tri);
    if (c == -2)
        st = radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory", r->name, r->line);
    else if (c < 0 && why->message[0] == '\0')
        st = radi_fail(r->err, RAD_ERR_PARSE, "%s:%d: face cannot be cut into triangles",
                       r->name, r->line);
    else if (c < 0) {
        if (r->err)
            *r->err = *why; /* it crosses itself: refused as the check says */
        st = RAD_ERR_PARSE;
    } else {
        int added;
        st = add_triangles(b, r, v, tri, n - 2, mat, object, &added);
        if (st == RAD_OK && added > 0) {
            radi_obj_note(&b->s.repairs, RADI_REPAIR_SPLIT, r->line);
            b->s.repairs.split_triangles += added;
        } else if (st == RAD_OK)
            radi_obj_note(&b->s.repairs, RADI_REPAIR_DEGENERATE, r->line);
    }
done:
    free(p);
    free(tri);
    return st;
}

/* The length of the outline's period: k when v[i] = v[i mod k] for every
 * i and k divides m (k < m: it runs round more than once), else m. */
static int period(const rad_vec3 *v, int m)
{
    for (int k = 3; k < m; k++) {
        if (m % k != 0 || memcmp(&v[k], &v[0], sizeof *v) != 0)
            continue;
        int same = 1;
        for (int i = k; i < m && same; i++)
            same = memcmp(&v[i], &v[i % k], sizeof *v) == 0;
        if (same)
            return k;
    }
    return m;
}

/* Do all of v[0..m) lie on the line through the two farthest apart, within
 * 1e-12 of their distance? */
static int on_a_line(const rad_vec3 *v, int m)
{
    int a = 0, c = 0;
    double far = -1;
    for (int k = 0; k < m; k++)
        for (int l = k + 1; l < m; l++) {
            const rad_vec3 e = v3_sub(v[k], v[l]);
            if (v3_dot(e, e) > far)
                far = v3_dot(e, e), a = k, c = l;
        }
    const rad_vec3 u = v3_sub(v[c], v[a]);
    const double len = v3_norm(u);
    if (!(len > 0))
        return 1;
    for (int k = 0; k < m; k++)
        if (v3_norm(v3_cross(u, v3_sub(v[k], v[a]))) / len > 1e-12 * len)
            return 0;
    return 1;
}

/* Refuse with radi_polygon_check's own message (v freed). */
static rad_status refuse(rad_lines *r, rad_vec3 *v, int m)
{
    rad_status st = radi_polygon_check(v, m, "face", r->name, r->line, r->err);
    free(v);
    if (st == RAD_OK) /* not expected: the caller saw it fail */
        st = radi_fail(r->err, RAD_ERR_PARSE, "%s:%d: face cannot be repaired", r->name, r->line);
    return st;
}

rad_status radi_obj_repair_face(rad_scene_build *b, rad_lines *r, rad_vec3 *v, int n, int mat,
                                int object, int undefined)
{
    const int m = period(v, merge_repeats(v, n));
    const double diam = sqrt(diameter2(v, m));
    if (m >= 2 && !(diam >= 0x1p-510 && diam <= 0x1p510))
        return refuse(r, v, m); /* outside the sizes accepted: no repair of that */
    const rad_vec3 N = v3_newell(v, m);
    if (m < 3 || on_a_line(v, m)) {
        free(v);
        radi_obj_note(&b->s.repairs, RADI_REPAIR_DEGENERATE, r->line);
        return RAD_OK;
    }
    if (!(0.5 * v3_norm(N) > 1e-14 * diam * diam))
        return refuse(r, v, m); /* loops of opposite turn cancel: it crosses itself */
    if (undefined)
        radi_obj_note(&b->s.repairs, RADI_REPAIR_MATERIAL, r->line);
    rad_error why;
    memset(&why, 0, sizeof why);
    if (radi_polygon_check(v, m, "face", r->name, r->line, &why) == RAD_OK && m == n)
        return radi_build_add_surface(b, r->line, m == 4 ? RAD_SURFACE_QUAD : RAD_SURFACE_POLYGON,
                                      mat, object, v, m, 1, 1);
    /* not planar, not convex, a corner merged or an outline run round twice */
    rad_status st = split_face(b, r, v, m, N, mat, object, &why);
    free(v);
    return st;
}
