/* changeread.c -- the change file of `radiosity animate`, read and checked.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The format is in include/radiosity/changes.h and radiosity-scene(5).  It
 * is read like a scene (readfile.h: one line at a time, `#` comments,
 * bounded lines and files, printable ASCII only), and each line is checked
 * against the scene as it is read, so that the first error stops the read
 * with "FILE:LINE: what is wrong" before `animate` does any work.  Whether
 * an object is present is followed through the file, frame by frame,
 * starting from the scene's `absent` flags: `add` of a present object and
 * `remove` of an absent one are errors at their line.  Numbers use strtod
 * syntax and must be finite; a rotation axis must not be zero (nor made of
 * subnormal numbers only; any other finite axis is one: it is scaled by its
 * largest component before it is normalised, so neither the overflow of
 * 1e300 1e300 1e300 nor the underflow of 1e-300's square calls it zero).  Nothing here changes
 * the scene: the animation (animate.c) applies the changes.
 */
#include <config.h>

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/changes.h"
#include "radiosity/changes.h"
#include "util/util.h"

/* The reader's state: the changes so far and presence per object. */
typedef struct change_state {
    const rad_scene *scene;
    rad_lines *r;
    rad_changes *out;
    int cap;
    unsigned char *present;     /* per object, as of the current line */
} change_state;

static rad_status fail(const change_state *p, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static rad_status fail(const change_state *p, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rad_status st = radi_fail_vat(p->r->err, p->r->name, p->r->line, fmt, ap);
    va_end(ap);
    return st;
}

static rad_status number(const change_state *p, int k, const char *what, double *out)
{
    const rad_lines *r = p->r;
    char *end;
    if (k >= r->ntok)
        return fail(p, "missing number: %s", what);
    double v = strtod(r->tok[k], &end);
    if (end == r->tok[k] || *end != '\0')
        return fail(p, "'%s' is not a number (%s)", r->tok[k], what);
    if (!isfinite(v))
        return fail(p, "%s must be finite, not '%s'", what, r->tok[k]);
    *out = v;
    return RAD_OK;
}

static rad_status vector(const change_state *p, int k, const char *what, rad_vec3 *v)
{
    rad_status st;
    if ((st = number(p, k, what, &v->x)) || (st = number(p, k + 1, what, &v->y)) ||
        (st = number(p, k + 2, what, &v->z)))
        return st;
    return RAD_OK;
}

static rad_status no_more(const change_state *p, int k)
{
    if (k < p->r->ntok)
        return fail(p, "unexpected '%s' at the end of %s", p->r->tok[k], p->r->tok[0]);
    return RAD_OK;
}

/* The object named by token 1. */
static rad_status object_ref(const change_state *p, int *object)
{
    const rad_lines *r = p->r;
    if (r->ntok < 2)
        return fail(p, "%s needs an object name", r->tok[0]);
    for (int o = 0; o < p->scene->nobjects; o++)
        if (strcmp(p->scene->objects[o].name, r->tok[1]) == 0) {
            *object = o;
            return RAD_OK;
        }
    if (p->scene->nobjects == 0)
        return fail(p, "unknown object '%s' (the scene defines no objects)", r->tok[1]);
    return fail(p, "unknown object '%s'", r->tok[1]);
}

static rad_status parse_move(const change_state *p, rad_change *c)
{
    rad_status st;
    if ((st = object_ref(p, &c->object)) || (st = vector(p, 2, "displacement", &c->v)))
        return st;
    return no_more(p, 5);
}

/* rotate NAME AX AY AZ DEGREES [about CX CY CZ] */
static rad_status parse_rotate(const change_state *p, rad_change *c)
{
    const rad_lines *r = p->r;
    rad_status st;
    if ((st = object_ref(p, &c->object)) || (st = vector(p, 2, "rotation axis", &c->v)) ||
        (st = number(p, 5, "angle in degrees", &c->degrees)))
        return st;
    /* scaled by its largest component first: 1e300 1e300 1e300 (whose
     * length overflows) and 1e-200 0 0 (whose square underflows) are axes */
    const double big = fmax(fabs(c->v.x), fmax(fabs(c->v.y), fabs(c->v.z)));
    if (!(big >= 0x1p-1022)) /* zero, or subnormal components only */
        return fail(p, "the rotation axis must not be zero");
    c->v.x /= big;
    c->v.y /= big;
    c->v.z /= big;
    const double len = sqrt(c->v.x * c->v.x + c->v.y * c->v.y + c->v.z * c->v.z);
    c->v.x /= len;
    c->v.y /= len;
    c->v.z /= len;
    if (r->ntok > 6) {
        if (strcmp(r->tok[6], "about") != 0)
            return fail(p, "unexpected '%s' after the angle (expected about)", r->tok[6]);
        if ((st = vector(p, 7, "rotation centre", &c->center)))
            return st;
        c->has_center = 1;
        return no_more(p, 10);
    }
    return RAD_OK;
}

static rad_status parse_presence(change_state *p, rad_change *c, int add)
{
    rad_status st;
    if ((st = object_ref(p, &c->object)) || (st = no_more(p, 2)))
        return st;
    if (add && p->present[c->object])
        return fail(p, "cannot add object '%s': it is present at this point",
                    p->scene->objects[c->object].name);
    if (!add && !p->present[c->object])
        return fail(p, "cannot remove object '%s': it is absent at this point",
                    p->scene->objects[c->object].name);
    p->present[c->object] = (unsigned char)add;
    return RAD_OK;
}

/* One or three band values from token *k on, within [lo, hi]. */
static rad_status bands(const change_state *p, int *k, const char *what, double lo, double hi,
                        double out[RAD_BANDS])
{
    const rad_lines *r = p->r;
    int count = 0;
    char *end;
    while (*k + count < r->ntok && count < 4 &&
           (strtod(r->tok[*k + count], &end), end != r->tok[*k + count]))
        count++;
    if (count != 1 && count != RAD_BANDS)
        return fail(p, "%s takes 1 value (grey) or 3 (R G B), not %d", what, count);
    for (int b = 0; b < count; b++) {
        rad_status st = number(p, *k + b, what, &out[b]);
        if (st)
            return st;
        if (!(out[b] >= lo && out[b] <= hi))
            return fail(p, "%s must be from %g to %g, not %s", what, lo, hi, r->tok[*k + b]);
    }
    if (count == 1)
        out[1] = out[2] = out[0];
    *k += count;
    return RAD_OK;
}

/* material MATNAME reflect R G B [emit R G B] */
static rad_status parse_material(const change_state *p, rad_change *c)
{
    const rad_lines *r = p->r;
    rad_status st;
    int k = 2;
    if (r->ntok < 2)
        return fail(p, "material needs a material name");
    c->material = -1;
    for (int m = 0; m < p->scene->nmaterials; m++)
        if (strcmp(p->scene->materials[m].name, r->tok[1]) == 0)
            c->material = m;
    if (c->material < 0)
        return fail(p, "unknown material '%s'", r->tok[1]);
    if (k >= r->ntok || strcmp(r->tok[k], "reflect") != 0)
        return fail(p, "material change needs: reflect R G B [emit R G B]");
    k++;
    if ((st = bands(p, &k, "reflectance", 0.0, 1.0, c->reflect)))
        return st;
    if (k < r->ntok && strcmp(r->tok[k], "emit") == 0) {
        k++;
        if ((st = bands(p, &k, "emission", 0.0, HUGE_VAL, c->emit)))
            return st;
        c->has_emit = 1;
    }
    return no_more(p, k);
}

static rad_status append(change_state *p, const rad_change *c)
{
    rad_changes *o = p->out;
    if (o->nchanges == p->cap) {
        int cap = p->cap ? 2 * p->cap : 16;
        rad_change *g = realloc(o->changes, sizeof *g * (size_t)cap);
        if (!g)
            return fail(p, "out of memory");
        o->changes = g;
        p->cap = cap;
    }
    o->changes[o->nchanges++] = *c;
    return RAD_OK;
}

static rad_status parse_change(change_state *p)
{
    const rad_lines *r = p->r;
    const char *kw = r->tok[0];
    rad_change c;
    rad_status st;
    if (strcmp(kw, "frame") == 0) {
        p->out->nframes++;
        return no_more(p, 1);
    }
    memset(&c, 0, sizeof c);
    c.object = c.material = -1;
    c.line = r->line;
    c.frame = p->out->nframes;
    if (strcmp(kw, "move") == 0)
        c.kind = RAD_CHANGE_MOVE, st = parse_move(p, &c);
    else if (strcmp(kw, "rotate") == 0)
        c.kind = RAD_CHANGE_ROTATE, st = parse_rotate(p, &c);
    else if (strcmp(kw, "remove") == 0)
        c.kind = RAD_CHANGE_REMOVE, st = parse_presence(p, &c, 0);
    else if (strcmp(kw, "add") == 0)
        c.kind = RAD_CHANGE_ADD, st = parse_presence(p, &c, 1);
    else if (strcmp(kw, "material") == 0)
        c.kind = RAD_CHANGE_MATERIAL, st = parse_material(p, &c);
    else
        return fail(p, "unknown change '%s' (expected move, rotate, remove, add, material "
                    "or frame)", kw);
    if (st == RAD_OK && c.frame == 0)
        return fail(p, "%s before the first 'frame' line (frame 0 is the scene as given; "
                    "start frame 1 with a line 'frame')", kw);
    return st ? st : append(p, &c);
}

static rad_status read_changes(rad_changes *changes, const rad_scene *scene, rad_lines *r)
{
    change_state p = {scene, r, changes, 0, NULL};
    rad_status st = RAD_OK;
    int got;
    p.present = malloc((size_t)scene->nobjects + 1);
    changes->filename = strdup(r->name);
    if (!p.present || !changes->filename)
        st = radi_fail(r->err, RAD_ERR_NOMEM, "out of memory");
    for (int o = 0; st == RAD_OK && o < scene->nobjects; o++)
        p.present[o] = !scene->objects[o].absent;
    while (st == RAD_OK && (got = radi_lines_next(r)) != 0) {
        if (got < 0) {
            st = r->status;
            break;
        }
        if (r->ntok > 0 && !(st = radi_lines_ascii(r, 0)))
            st = parse_change(&p);
    }
    free(p.present);
    if (st != RAD_OK)
        rad_changes_free(changes);
    return st;
}

rad_status rad_changes_parse(rad_changes *changes, const rad_scene *scene, const char *text,
                             size_t len, const char *name, rad_error *err)
{
    rad_lines r;
    memset(changes, 0, sizeof *changes);
    radi_lines_mem(&r, text, len, name ? name : "-", '#', err);
    rad_status st = read_changes(changes, scene, &r);
    radi_lines_close(&r);
    return st;
}

rad_status rad_changes_load(rad_changes *changes, const rad_scene *scene, const char *path,
                            rad_error *err)
{
    rad_lines r;
    memset(changes, 0, sizeof *changes);
    rad_status st = radi_lines_open(&r, path, '#', err);
    if (st == RAD_OK)
        st = read_changes(changes, scene, &r);
    radi_lines_close(&r);
    return st;
}

void rad_changes_free(rad_changes *changes)
{
    if (!changes)
        return;
    free(changes->changes);
    free(changes->filename);
    memset(changes, 0, sizeof *changes);
}
