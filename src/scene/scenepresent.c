/* scenepresent.c -- the scene as one frame shows it: absent objects left out.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A scene may declare objects `absent` (radiosity-scene(5)): their surfaces
 * are read and checked with the rest, but they are not in the scene until a
 * change of `radiosity animate` adds them.  Everything that solves one
 * scene (rad_pipeline_run, and the animation's form factors of a frame)
 * works on a copy that holds only the present surfaces, in file order, so
 * that element and surface numbers are those of the scene file with the
 * absent objects deleted.  Materials, objects and the camera are copied
 * whole; surface k of the copy keeps its object index.
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "util/util.h"

/* Is surface s present: outside every object, or in a present one? */
static int surface_present(const rad_scene *in, const unsigned char *present, int s)
{
    int o = in->surfaces[s].object;
    if (o < 0 || o >= in->nobjects)
        return 1;
    return present ? present[o] != 0 : !in->objects[o].absent;
}

int rad_scene_has_absent(const rad_scene *scene)
{
    for (int s = 0; s < scene->nsurfaces; s++)
        if (!surface_present(scene, NULL, s))
            return 1;
    return 0;
}

/* The copy's index of the surface that surface s combines with (-1: none,
 * or that surface is absent); index[] maps the surfaces before s. */
static int renumbered(const rad_scene *in, const unsigned char *present, const int *index,
                      int s)
{
    const int c = in->surfaces[s].combine;
    if (c < 0 || c >= s || !surface_present(in, present, c))
        return -1;
    return index[c];
}

static void *dup_bytes(const void *p, size_t n)
{
    void *q = malloc(n ? n : 1);
    if (q && n)
        memcpy(q, p, n);
    return q;
}

rad_status rad_scene_present_copy(const rad_scene *in, const unsigned char *present,
                                  rad_scene *out, rad_error *err)
{
    memset(out, 0, sizeof *out);
    out->camera = in->camera;
    out->format = in->format;
    out->filename = strdup(in->filename ? in->filename : "-");
    out->materials = dup_bytes(in->materials, sizeof *in->materials * (size_t)in->nmaterials);
    out->objects = dup_bytes(in->objects, sizeof *in->objects * (size_t)in->nobjects);
    out->surfaces = calloc((size_t)in->nsurfaces + 1, sizeof *out->surfaces);
    int *index = malloc(sizeof *index * ((size_t)in->nsurfaces + 1)); /* in's -> out's */
    int ok = out->filename && out->materials && out->objects && out->surfaces && index;
    out->nmaterials = in->nmaterials;
    out->nobjects = in->nobjects;
    for (int o = 0; ok && present && o < in->nobjects; o++)
        out->objects[o].absent = !present[o];
    for (int s = 0; ok && s < in->nsurfaces; s++) {
        if (!surface_present(in, present, s))
            continue;
        rad_surface *f = &out->surfaces[out->nsurfaces];
        *f = in->surfaces[s];
        f->verts = dup_bytes(in->surfaces[s].verts, sizeof *f->verts * (size_t)f->nverts);
        f->combine = renumbered(in, present, index, s);
        ok = f->verts != NULL;
        index[s] = out->nsurfaces;
        out->nsurfaces += ok;
    }
    free(index);
    if (!ok) {
        rad_scene_free(out);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory copying the scene");
    }
    return RAD_OK;
}
