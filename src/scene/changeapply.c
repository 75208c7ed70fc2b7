/* changeapply.c -- a frame's changes applied to a scene.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The changes of changes.h, in file order, on the scene in place: `move`
 * adds the displacement to every vertex of the object's surfaces;
 * `rotate` turns them by DEGREES counter-clockwise about the unit axis
 * (right-hand rule) through the given centre, or through the
 * area-weighted centroid of the object's surfaces as they are at that
 * line (Rodrigues' formula); `add` and `remove` set the object's absent
 * flag; `material` replaces the reflectances (and the emission, when
 * given) of a material, so every surface made of it changes.  The mesh
 * (N x M per quad) is not touched: an element keeps its index.  Units are
 * the scene's; angles are degrees.  The animation (animate.c) and
 * `radiosity animate --reference` both use it, so the scene of a frame is
 * built the same way for the redistribution and for a fresh solve.
 */
#include <config.h>

#include <math.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/changes.h"
#include "radiosity/changes.h"
#include "util/util.h"

/* Area-weighted centroid of object o's surfaces (Newell's vector gives
 * each polygon's area; its centroid by the triangle fan). */
static rad_vec3 object_centroid(const rad_scene *s, int o)
{
    rad_vec3 c = v3(0, 0, 0);
    double total = 0;
    for (int k = 0; k < s->nsurfaces; k++) {
        const rad_surface *f = &s->surfaces[k];
        if (f->object != o)
            continue;
        rad_vec3 nw = v3_newell(f->verts, f->nverts);
        double len = v3_norm(nw);
        if (!(len > 0))
            continue;
        rad_vec3 nrm = v3_scale(nw, 1 / len);
        for (int t = 1; t + 1 < f->nverts; t++) {
            rad_vec3 p = f->verts[0], q = f->verts[t], r = f->verts[t + 1];
            double a = 0.5 * v3_dot(v3_cross(v3_sub(q, p), v3_sub(r, p)), nrm);
            c = v3_add(c, v3_scale(v3_add(p, v3_add(q, r)), a / 3));
            total += a;
        }
    }
    return total > 0 ? v3_scale(c, 1 / total) : c;
}

/* Rodrigues' rotation of p about the unit axis k through c by theta:
 * v cos + (k x v) sin + k (k . v)(1 - cos), v = p - c. */
static rad_vec3 rotate_point(rad_vec3 p, rad_vec3 k, rad_vec3 c, double cs, double sn)
{
    rad_vec3 v = v3_sub(p, c);
    rad_vec3 r = v3_add(v3_scale(v, cs), v3_scale(v3_cross(k, v), sn));
    r = v3_add(r, v3_scale(k, v3_dot(k, v) * (1 - cs)));
    return v3_add(c, r);
}

static void apply_geometry(rad_scene *s, const rad_change *c)
{
    rad_vec3 ctr = c->has_center ? c->center : object_centroid(s, c->object);
    double th = c->degrees * (RAD_PI / 180);
    double cs = cos(th), sn = sin(th);
    for (int k = 0; k < s->nsurfaces; k++) {
        rad_surface *f = &s->surfaces[k];
        if (f->object != c->object)
            continue;
        for (int v = 0; v < f->nverts; v++)
            f->verts[v] = c->kind == RAD_CHANGE_MOVE ? v3_add(f->verts[v], c->v)
                                                     : rotate_point(f->verts[v], c->v, ctr, cs, sn);
    }
}

static void apply_change(rad_scene *s, const rad_change *c, unsigned char *dirty)
{
    switch (c->kind) {
    case RAD_CHANGE_MOVE:
    case RAD_CHANGE_ROTATE:
        apply_geometry(s, c);
        if (dirty)
            dirty[c->object] = 1;
        break;
    case RAD_CHANGE_ADD:
    case RAD_CHANGE_REMOVE:
        s->objects[c->object].absent = c->kind != RAD_CHANGE_ADD;
        if (dirty)
            dirty[c->object] = 1;
        break;
    case RAD_CHANGE_MATERIAL: {
        rad_material *m = &s->materials[c->material];
        memcpy(m->reflect, c->reflect, sizeof m->reflect);
        if (c->has_emit)
            memcpy(m->emit, c->emit, sizeof m->emit);
        break;
    }
    }
}

/* The index of the first change of frame `frame` or a later one, by
 * bisection: the changes are in file order, so by frame (changes.h).  A
 * session of the live viewer applies each of its frames again for every
 * request it checks; a scan of all the changes for each frame made that
 * check's cost grow as the square of the frames (10,000 frames of one
 * move each: 0.44 s a request). */
static int first_of_frame(const rad_changes *ch, int frame)
{
    int lo = 0, hi = ch->nchanges;
    while (lo < hi) {
        const int mid = lo + (hi - lo) / 2;
        if (ch->changes[mid].frame < frame)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

void rad_changes_apply(rad_scene *scene, const rad_changes *changes, int frame,
                       unsigned char *dirty)
{
    for (int k = first_of_frame(changes, frame);
         k < changes->nchanges && changes->changes[k].frame == frame; k++)
        apply_change(scene, &changes->changes[k], dirty);
}
