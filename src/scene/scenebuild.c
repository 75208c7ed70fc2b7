/* scenebuild.c -- a scene under construction, shared by the readers.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Arrays grow by doubling; names are found through FNV-1a hashes with
 * linear probing, kept at most half full, so each lookup and each append
 * takes constant expected time whatever the order of the input.  A hash
 * holds indices, not pointers, because the arrays it indexes move when
 * they grow: the name of entry k is read at base + k * stride.  Every
 * failure leaves the scene as it was, for radi_build_finish to free.
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "scene/scenebuild.h"
#include "scene/polycheck.h"
#include "util/util.h"

/* ---- names ------------------------------------------------------------------ */

static size_t name_hash(const char *name)
{
    size_t h = 2166136261u; /* FNV-1a, its 32-bit constants */
    for (const unsigned char *p = (const unsigned char *)name; *p; p++)
        h = (h ^ *p) * 16777619u;
    return h;
}

/* Where `name` is, or the empty slot where it would go. */
static size_t name_slot(const rad_name_index *t, const char *base, size_t stride,
                        const char *name)
{
    size_t k = name_hash(name) & (t->nslot - 1);
    while (t->slot[k] && strcmp(base + (size_t)(t->slot[k] - 1) * stride, name) != 0)
        k = (k + 1) & (t->nslot - 1);
    return k;
}

static int name_find(const rad_name_index *t, const char *base, size_t stride,
                     const char *name)
{
    return t->nslot ? t->slot[name_slot(t, base, stride, name)] - 1 : -1;
}

/* Room in the hash for entry `count` (0-based), rehashing the ones before. */
static int name_reserve(rad_name_index *t, const char *base, size_t stride, int count)
{
    if (2 * (size_t)(count + 1) <= t->nslot)
        return 0;
    size_t n = t->nslot ? 2 * t->nslot : 64;
    int *old = t->slot, *g = calloc(n, sizeof *g);
    if (!g)
        return -1;
    t->slot = g;
    t->nslot = n;
    for (int k = 0; k < count; k++)
        t->slot[name_slot(t, base, stride, base + (size_t)k * stride)] = k + 1;
    free(old);
    return 0;
}

/* The array p (of *cap elements of `size` bytes) with room for element
 * `count`: p itself, p moved and grown, or NULL (p untouched) when memory
 * runs out. */
static void *grown(void *p, int *cap, int count, size_t size)
{
    if (count < *cap)
        return p;
    int ncap = *cap ? 2 * *cap : 16;
    void *g = realloc(p, size * (size_t)ncap);
    if (g)
        *cap = ncap;
    return g;
}

#define MAT_BASE(b) ((const char *)(b)->s.materials[0].name)
#define OBJ_BASE(b) ((const char *)(b)->s.objects[0].name)

/* ---- the scene ------------------------------------------------------------------ */

rad_status radi_build_start(rad_scene_build *b, const char *filename, rad_error *err)
{
    memset(b, 0, sizeof *b);
    b->err = err;
    b->object = -1;
    b->s.filename = strdup(filename);
    if (!b->s.filename)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    return RAD_OK;
}

rad_status radi_build_finish(rad_scene_build *b, rad_status st, rad_scene *out)
{
    free(b->materials.slot);
    free(b->objects.slot);
    if (st != RAD_OK) {
        rad_scene_free(&b->s);
        memset(out, 0, sizeof *out);
    } else {
        *out = b->s;
    }
    memset(b, 0, sizeof *b);
    return st;
}

int radi_build_find_material(const rad_scene_build *b, const char *name)
{
    return b->s.nmaterials ? name_find(&b->materials, MAT_BASE(b), sizeof(rad_material), name)
                           : -1;
}

int radi_build_find_object(const rad_scene_build *b, const char *name)
{
    return b->s.nobjects ? name_find(&b->objects, OBJ_BASE(b), sizeof(rad_object), name) : -1;
}

static rad_status out_of_memory(const rad_scene_build *b, const char *file, int line)
{
    return radi_fail(b->err, RAD_ERR_NOMEM, "%s:%d: out of memory", file, line);
}

rad_status radi_build_add_material(rad_scene_build *b, const rad_material *m,
                                  const char *file, int line)
{
    rad_scene *s = &b->s;
    rad_material *g = grown(s->materials, &b->matcap, s->nmaterials, sizeof *g);
    if (!g)
        return out_of_memory(b, file, line);
    s->materials = g;
    s->materials[s->nmaterials] = *m;
    if (name_reserve(&b->materials, MAT_BASE(b), sizeof(rad_material), s->nmaterials))
        return out_of_memory(b, file, line);
    b->materials.slot[name_slot(&b->materials, MAT_BASE(b), sizeof(rad_material), m->name)] =
        ++s->nmaterials;
    return RAD_OK;
}

rad_status radi_build_object(rad_scene_build *b, const char *name, int line, int *index)
{
    rad_scene *s = &b->s;
    if ((*index = radi_build_find_object(b, name)) >= 0)
        return RAD_OK;
    if (strlen(name) >= RAD_NAME_MAX)
        return radi_fail(b->err, RAD_ERR_PARSE, "%s:%d: object name is longer than %d characters",
                        s->filename, line, RAD_NAME_MAX - 1);
    rad_object *g = grown(s->objects, &b->objcap, s->nobjects, sizeof *g);
    if (!g)
        return out_of_memory(b, s->filename, line);
    s->objects = g;
    rad_object *o = &s->objects[s->nobjects];
    memset(o, 0, sizeof *o);
    strcpy(o->name, name);
    o->line = line;
    if (name_reserve(&b->objects, OBJ_BASE(b), sizeof(rad_object), s->nobjects))
        return out_of_memory(b, s->filename, line);
    b->objects.slot[name_slot(&b->objects, OBJ_BASE(b), sizeof(rad_object), name)] =
        ++s->nobjects;
    *index = s->nobjects - 1;
    return RAD_OK;
}

rad_status radi_build_add_surface(rad_scene_build *b, int line, rad_surface_kind kind,
                                 int material, int object, rad_vec3 *verts, int n,
                                 int mesh_n, int mesh_m)
{
    rad_scene *s = &b->s;
    double count = (double)mesh_n * mesh_m;
    if (b->elements + count > RAD_ELEMENTS_MAX) {
        free(verts);
        return radi_fail(b->err, RAD_ERR_PARSE,
                        "%s:%d: the scene would have %.0f elements; at most %d are allowed",
                        s->filename, line, b->elements + count, RAD_ELEMENTS_MAX);
    }
    rad_surface *g = grown(s->surfaces, &b->surfcap, s->nsurfaces, sizeof *g);
    if (!g) {
        free(verts);
        return out_of_memory(b, s->filename, line);
    }
    s->surfaces = g;
    b->elements += count;
    rad_surface *f = &s->surfaces[s->nsurfaces++];
    memset(f, 0, sizeof *f);
    f->kind = kind;
    f->material = material;
    f->object = object;
    f->nverts = n;
    f->verts = verts;
    f->mesh_n = mesh_n;
    f->mesh_m = mesh_m;
    f->line = line;
    f->combine = -1;
    return RAD_OK;
}

void rad_scene_free(rad_scene *scene)
{
    if (!scene)
        return;
    for (int k = 0; k < scene->nsurfaces; k++)
        free(scene->surfaces[k].verts);
    free(scene->surfaces);
    free(scene->materials);
    free(scene->objects);
    free(scene->filename);
    memset(scene, 0, sizeof *scene);
}
