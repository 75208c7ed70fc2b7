/* objread.c -- Wavefront OBJ + MTL input.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A scene file whose name ends in .obj is read here (radiosity-scene(5),
 * WAVEFRONT OBJ).  The format is Wavefront's "Object Files (.obj)",
 * Advanced Visualizer 3.0, appendix B1, and "Material Library Files
 * (.mtl)", appendix B2.  What it maps:
 *   - `v X Y Z [W]` (or `v X Y Z R G B`, the vertex-colour extension) is a
 *     vertex; W and the colour are dropped;
 *   - `f` (or the old `fo`) is a face, one surface: each corner is V, V/T,
 *     V//N or V/T/N, an index from 1 or, when negative, counted back from
 *     the last vertex read (-1 is the last); T and N must name a `vt` and
 *     `vn` read before, which are otherwise ignored.  A face of 4 corners
 *     becomes a quad (so `mesh` and --mesh apply), any other a polygon;
 *     what radi_polygon_check refuses (not planar, not convex, no area)
 *     objrepair.c repairs, unless RAD_SCENE_STRICT;
 *   - `usemtl NAME` picks the material of the faces after it, from the
 *     `mtllib` files read so far (opened relative to the OBJ file); faces
 *     before any usemtl get the material "(no material)": black (Kd 0) and
 *     dark (Ke 0).  A name that no library defines gives RAD_DEFAULT_GREY
 *     (a repair); names may hold spaces and bytes beyond ASCII (repairs).
 *     Every repair is counted in rad_scene_repairs; RAD_SCENE_STRICT makes
 *     each the error it names.  An mtllib file name has at most 255 bytes, so that a
 *     message about its lines keeps their FILE:LINE;
 *   - `o NAME` and `g NAME...` start an object (the first name of a g);
 *     faces after them belong to it until the next o or g (a g without a
 *     name returns to the static environment).  Objects do not nest;
 *     naming an object again adds to it;
 *   - in the MTL: `newmtl NAME`, `Kd` (reflectance, 1 or 3 values from 0
 *     to 1), `Ke` (emission, 1 or 3 values >= 0).  A material needs Kd.
 * Ignored without error: vt, vn, vp, s, l, p and the display statements in
 * OBJ; Ka, Ks, Ns, Ni, d, Tr, Tf, illum, sharpness, map_*, bump, disp,
 * decal, refl and the PBR extension in MTL.  Refused with FILE:LINE:
 * free-form geometry (cstype, curv, surf, ...), call and csh, and every
 * other word.  Lines are read through readfile.h, so both files have the
 * scene file's limits and rules on bytes (printable ASCII outside
 * comments, except in the statements ignored).
 */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/objread.h"
#include "scene/objrepair.h"
#include "util/util.h"
#include "scene/polycheck.h"
#include "scene/scenebuild.h"

#define NO_MATERIAL "(no material)"
#define MTLLIB_NAME_MAX 255 /* bytes in an mtllib file name, as in NAME_MAX */

typedef struct obj_state {
    rad_scene_build b;
    rad_lines *r;               /* the OBJ file */
    rad_vec3 *v;                /* vertices read so far */
    long nv, vcap;
    long nvt, nvn;              /* texture and normal vertices, counted */
    int material;               /* from usemtl; -1: none yet */
    int object;                 /* from o or g; -1: the static environment */
    const char *mtl;            /* in-memory MTL text, or NULL */
    size_t mtl_len;
    int mtl_done;               /* the in-memory MTL was read */
    char **libs;                /* mtllib paths read, not read twice */
    int nlibs;
    unsigned flags;             /* RAD_SCENE_STRICT: no repairs (objrepair.c) */
    int named_at;               /* the OBJ line whose name was counted */
    int undefined;              /* the usemtl in force named no material */
} obj_state;

/* RAD_ERR_NOMEM at the current line. */
static rad_status no_memory(const rad_lines *r)
{
    return radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory", r->name, r->line);
}

/* The bytes of a line: printable ASCII, as in scene files; or, for a
 * name statement (newmtl, usemtl, o, g) read with repairs, any byte but a
 * control character (exporters write names in UTF-8 or Latin-1: they are
 * matched byte for byte), counted as a repair. */
static rad_status line_bytes(obj_state *o, rad_lines *r, int name)
{
    if (!name || (o->flags & RAD_SCENE_STRICT))
        return radi_lines_ascii(r, 0);
    int high = 0;
    for (int k = 1; k < r->ntok; k++)
        for (const unsigned char *p = (const unsigned char *)r->tok[k]; *p; p++) {
            if (*p < 0x20 || *p == 0x7f)
                return radi_lines_ascii(r, k);
            high |= *p >= 0x80;
        }
    if (high && !(r == o->r && o->named_at == r->line)) {
        radi_obj_note(&o->b.s.repairs, RADI_REPAIR_NAME, r == o->r ? r->line : 0);
        if (r == o->r)
            o->named_at = r->line;
    }
    return RAD_OK;
}

static int is_word(const char *t, const char *const *words)
{
    for (; *words; words++)
        if (strcmp(t, *words) == 0)
            return 1;
    return 0;
}

/* ---- MTL ------------------------------------------------------------------- */

typedef struct mtl_def {
    rad_material m;
    int open, have_kd;
} mtl_def;

/* Add the material being defined, if any. */
static rad_status mtl_close(obj_state *o, rad_lines *r, mtl_def *d)
{
    if (!d->open)
        return RAD_OK;
    d->open = 0;
    if (!d->have_kd)
        return radi_fail(r->err, RAD_ERR_PARSE, "%s:%d: material '%s' has no Kd (its "
                        "reflectance)", r->name, d->m.line, d->m.name);
    return radi_build_add_material(&o->b, &d->m, r->name, r->line);
}

/* The material name of a newmtl or usemtl line into name: its one word,
 * or (a repair) its words joined by single spaces, or "" for none. */
static rad_status material_name(obj_state *o, rad_lines *r, const char *what,
                                char name[RAD_NAME_MAX])
{
    if (r->ntok != 2 && (o->flags & RAD_SCENE_STRICT))
        return radi_lines_fail(r, r->ntok == 1 ? "%s needs a name" : "%s takes one name (no spaces)",
                               what);
    size_t len = 0;
    name[0] = '\0';
    for (int k = 1; k < r->ntok; k++) {
        const size_t t = strlen(r->tok[k]) + (k > 1);
        if (len + t >= RAD_NAME_MAX)
            return radi_lines_fail(r, "material name is longer than %d characters",
                                   RAD_NAME_MAX - 1);
        if (k > 1)
            name[len++] = ' ';
        strcpy(name + len, r->tok[k]);
        len += strlen(r->tok[k]);
    }
    return RAD_OK;
}

static rad_status mtl_new(obj_state *o, rad_lines *r, mtl_def *d)
{
    rad_status st = mtl_close(o, r, d);
    char name[RAD_NAME_MAX];
    if (st || (st = material_name(o, r, "newmtl", name)))
        return st;
    if (r->ntok != 2)
        radi_obj_note(&o->b.s.repairs, RADI_REPAIR_NAME, 0);
    int prev = radi_build_find_material(&o->b, name);
    if (prev >= 0)
        return radi_lines_fail(r, "material '%s' is already defined", name);
    memset(d, 0, sizeof *d);
    strcpy(d->m.name, name);
    d->m.line = r->line;
    d->open = 1;
    return RAD_OK;
}

static rad_status mtl_colour(rad_lines *r, mtl_def *d)
{
    const int kd = strcmp(r->tok[0], "Kd") == 0;
    if (!d->open)
        return radi_lines_fail(r, "%s before any newmtl", r->tok[0]);
    if (r->ntok > 1 && (strcmp(r->tok[1], "spectral") == 0 || strcmp(r->tok[1], "xyz") == 0))
        return radi_lines_fail(r, "%s %s is not supported (give R G B)", r->tok[0], r->tok[1]);
    if (kd) {
        d->have_kd = 1;
        return radi_tok_bands(r, 1, "Kd (reflectance)", 0.0, 1.0, d->m.reflect);
    }
    return radi_tok_bands(r, 1, "Ke (emission)", 0.0, HUGE_VAL, d->m.emit);
}

static rad_status mtl_line(obj_state *o, rad_lines *r, mtl_def *d)
{
    static const char *const ignored[] = {
        "Ka", "Ks", "Ns", "Ni", "d", "Tr", "Tf", "illum", "sharpness", "bump", "disp",
        "decal", "refl", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "norm", "Km", NULL};
    const char *k = r->tok[0];
    if (is_word(k, ignored) || strncmp(k, "map_", 4) == 0)
        return RAD_OK;
    rad_status st = line_bytes(o, r, strcmp(k, "newmtl") == 0);
    if (st)
        return st;
    if (strcmp(k, "newmtl") == 0)
        return mtl_new(o, r, d);
    if (strcmp(k, "Kd") == 0 || strcmp(k, "Ke") == 0)
        return mtl_colour(r, d);
    return radi_lines_fail(r, "unknown MTL statement '%s' (newmtl, Kd and Ke are read; "
                             "radiosity-scene(5) lists what is ignored)", k);
}

static rad_status mtl_read(obj_state *o, rad_lines *r)
{
    mtl_def d;
    int got;
    memset(&d, 0, sizeof d);
    while ((got = radi_lines_next(r)) > 0) {
        if (r->ntok == 0)
            continue;
        rad_status st = mtl_line(o, r, &d);
        if (st)
            return st;
    }
    return got < 0 ? r->status : mtl_close(o, r, &d);
}

/* "DIR/name" for the OBJ file at obj_path ("name" if it has no directory
 * or name is absolute); NULL when memory runs out. */
static char *beside(const char *obj_path, const char *name)
{
    const char *slash = strrchr(obj_path, '/');
    size_t dlen = name[0] == '/' || !slash ? 0 : (size_t)(slash - obj_path) + 1;
    char *p = malloc(dlen + strlen(name) + 1);
    if (p) {
        memcpy(p, obj_path, dlen);
        strcpy(p + dlen, name);
    }
    return p;
}

static rad_status mtllib_file(obj_state *o, const char *name)
{
    rad_lines m;
    rad_error openerr;
    rad_status st;
    if (o->mtl) {
        if (o->mtl_done)
            return RAD_OK;
        o->mtl_done = 1;
        radi_lines_mem(&m, o->mtl, o->mtl_len, name, '#', o->r->err);
        st = mtl_read(o, &m);
        radi_lines_close(&m);
        return st;
    }
    char *path = beside(o->r->name, name);
    char **g = path ? realloc(o->libs, sizeof *g * (size_t)(o->nlibs + 1)) : NULL;
    if (!g) {
        free(path);
        return no_memory(o->r);
    }
    o->libs = g;
    for (int k = 0; k < o->nlibs; k++)
        if (strcmp(o->libs[k], path) == 0) {
            free(path);
            return RAD_OK;
        }
    o->libs[o->nlibs++] = path;
    memset(&openerr, 0, sizeof openerr);
    if (radi_lines_open(&m, path, '#', &openerr) != RAD_OK) {
        radi_lines_close(&m);
        return radi_lines_fail(o->r, "cannot read the material library: %s", openerr.message);
    }
    m.err = &openerr;
    st = mtl_read(o, &m);
    radi_lines_close(&m);
    if (st == RAD_ERR_IO) /* say which mtllib line led to the file */
        return radi_lines_fail(o->r, "cannot read the material library: %s", openerr.message);
    if (st && openerr.status != RAD_OK && o->r->err) /* failed in m, not in the scene */
        *o->r->err = openerr;
    return st;
}

/* ---- OBJ statements -------------------------------------------------------- */

static rad_status obj_vertex(obj_state *o)
{
    rad_lines *r = o->r;
    rad_vec3 p;
    int n = r->ntok - 1;
    if (n != 3 && n != 4 && n != 6)
        return radi_lines_fail(r, "v takes X Y Z [W] or X Y Z R G B, not %d numbers", n);
    rad_status st = radi_tok_vec(r, 1, "vertex", &p);
    for (int k = 4; st == RAD_OK && k <= n; k++) {
        double unused;
        st = radi_tok_number(r, k, n == 4 ? "vertex weight" : "vertex colour", &unused);
    }
    if (st)
        return st;
    if (o->nv == o->vcap) {
        long ncap = o->vcap ? 2 * o->vcap : 256;
        rad_vec3 *g = realloc(o->v, sizeof *g * (size_t)ncap);
        if (!g)
            return no_memory(r);
        o->v = g;
        o->vcap = ncap;
    }
    o->v[o->nv++] = p;
    return RAD_OK;
}

/* An index of a corner into a list of `count` items: from 1, or negative
 * from the end; 0-based in *out. */
static rad_status corner_index(const obj_state *o, const char *t, const char *what,
                               long count, long *out)
{
    long i;
    rad_status st = radi_tok_long(o->r, t, what, -2147483647L, 2147483647L, &i);
    if (st)
        return st;
    if (i == 0)
        return radi_lines_fail(o->r, "%s index 0 (OBJ counts from 1, or from -1 backwards)",
                              what);
    *out = i > 0 ? i - 1 : count + i;
    if (*out < 0 || *out >= count)
        return radi_lines_fail(o->r, "%s index %ld, but %ld %s been read", what, i, count,
                              count == 1 ? "has" : "have");
    return RAD_OK;
}

/* One corner "V", "V/T", "V//N" or "V/T/N" (token text, split in place). */
static rad_status face_corner(obj_state *o, char *t, rad_vec3 *out)
{
    char *parts[3] = {t, NULL, NULL};
    int n = 1;
    for (char *p = t; *p; p++)
        if (*p == '/') {
            if (n == 3)
                return radi_lines_fail(o->r, "face corner has more than 3 parts (V/T/N)");
            *p = '\0';
            parts[n++] = p + 1;
        }
    long v, unused;
    rad_status st = corner_index(o, parts[0], "vertex", o->nv, &v);
    if (!st && n >= 2 && (n == 2 || parts[1][0]))
        st = corner_index(o, parts[1], "texture vertex", o->nvt, &unused);
    if (!st && n == 3)
        st = corner_index(o, parts[2], "normal", o->nvn, &unused);
    if (!st)
        *out = o->v[v];
    return st;
}

/* The material of a face: the usemtl one, or "(no material)". */
static rad_status face_material(obj_state *o, int *out)
{
    if (o->material >= 0) {
        *out = o->material;
        return RAD_OK;
    }
    *out = radi_build_find_material(&o->b, NO_MATERIAL);
    if (*out >= 0)
        return RAD_OK;
    rad_material m;
    memset(&m, 0, sizeof m);
    strcpy(m.name, NO_MATERIAL);
    m.line = o->r->line;
    *out = o->b.s.nmaterials;
    return radi_build_add_material(&o->b, &m, o->r->name, o->r->line);
}

static rad_status obj_face(obj_state *o)
{
    rad_lines *r = o->r;
    int n = r->ntok - 1, mat;
    if (n < 3)
        return radi_lines_fail(r, "a face needs at least 3 corners, not %d", n);
    if (n > RAD_POLYGON_MAX)
        return radi_lines_fail(r, "a face has at most %d corners, not %d", RAD_POLYGON_MAX, n);
    rad_vec3 *v = malloc(sizeof *v * (size_t)n);
    if (!v)
        return no_memory(r);
    rad_status st = RAD_OK;
    for (int k = 0; k < n && st == RAD_OK; k++)
        st = face_corner(o, r->tok[k + 1], &v[k]);
    if (!st)
        st = face_material(o, &mat);
    if (st) {
        free(v);
        return st;
    }
    if (!(o->flags & RAD_SCENE_STRICT))
        return radi_obj_repair_face(&o->b, r, v, n, mat, o->object, o->undefined);
    if ((st = radi_polygon_check(v, n, "face", r->name, r->line, r->err))) {
        free(v);
        return st;
    }
    return radi_build_add_surface(&o->b, r->line, n == 4 ? RAD_SURFACE_QUAD : RAD_SURFACE_POLYGON,
                                 mat, o->object, v, n, 1, 1);
}

static rad_status obj_usemtl(obj_state *o)
{
    rad_lines *r = o->r;
    char name[RAD_NAME_MAX];
    rad_status st = material_name(o, r, "usemtl", name);
    if (st)
        return st;
    if (r->ntok != 2 && o->named_at != r->line) {
        radi_obj_note(&o->b.s.repairs, RADI_REPAIR_NAME, r->line);
        o->named_at = r->line;
    }
    o->material = radi_build_find_material(&o->b, name);
    o->undefined = o->material < 0;
    if (o->material >= 0)
        return RAD_OK;
    if (o->flags & RAD_SCENE_STRICT)
        return radi_lines_fail(r, "undefined material '%s' (no mtllib read so far defines it)",
                              name);
    /* a repair: the faces after it are grey (counted as they come) */
    o->material = radi_build_find_material(&o->b, RAD_DEFAULT_GREY);
    if (o->material >= 0)
        return RAD_OK;
    rad_material m;
    memset(&m, 0, sizeof m);
    strcpy(m.name, RAD_DEFAULT_GREY);
    m.reflect[0] = m.reflect[1] = m.reflect[2] = 0.5;
    m.line = r->line;
    o->material = o->b.s.nmaterials;
    return radi_build_add_material(&o->b, &m, r->name, r->line);
}

static rad_status obj_group(obj_state *o)
{
    rad_lines *r = o->r;
    if (r->ntok == 1) {
        o->object = -1;
        return RAD_OK;
    }
    if (r->tok[0][0] == 'o' && r->ntok > 2)
        return radi_lines_fail(r, "o takes one object name (no spaces)");
    return radi_build_object(&o->b, r->tok[1], r->line, &o->object);
}

static rad_status obj_mtllib(obj_state *o)
{
    if (o->r->ntok < 2)
        return radi_lines_fail(o->r, "mtllib needs a file name");
    for (int k = 1; k < o->r->ntok; k++) {
        /* a longer name would crowd FILE:LINE out of RAD_ERRMSG_MAX */
        if (strlen(o->r->tok[k]) > MTLLIB_NAME_MAX)
            return radi_lines_fail(o->r, "mtllib file name is longer than %d bytes",
                                  MTLLIB_NAME_MAX);
        rad_status st = mtllib_file(o, o->r->tok[k]);
        if (st)
            return st;
    }
    return RAD_OK;
}

static rad_status obj_line(obj_state *o)
{
    static const char *const ignored[] = {
        "vp", "s", "l", "p", "mg", "lod", "bevel", "c_interp", "d_interp", "trace_obj",
        "shadow_obj", "usemap", "maplib", "ctech", "stech", NULL};
    static const char *const freeform[] = {
        "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole",
        "scrv", "sp", "end", "con", NULL};
    rad_lines *r = o->r;
    const char *k = r->tok[0];
    if (strcmp(k, "vt") == 0 || strcmp(k, "vn") == 0) {
        ++*(k[1] == 't' ? &o->nvt : &o->nvn);
        return RAD_OK;
    }
    if (is_word(k, ignored))
        return RAD_OK;
    rad_status st = line_bytes(o, r, strcmp(k, "usemtl") == 0 || strcmp(k, "o") == 0 ||
                                         strcmp(k, "g") == 0);
    if (st)
        return st;
    if (strcmp(k, "v") == 0)
        return obj_vertex(o);
    if (strcmp(k, "f") == 0 || strcmp(k, "fo") == 0)
        return obj_face(o);
    if (strcmp(k, "usemtl") == 0)
        return obj_usemtl(o);
    if (strcmp(k, "o") == 0 || strcmp(k, "g") == 0)
        return obj_group(o);
    if (strcmp(k, "mtllib") == 0)
        return obj_mtllib(o);
    if (is_word(k, freeform))
        return radi_lines_fail(r, "free-form geometry ('%s') is not supported; export "
                                 "polygons", k);
    return radi_lines_fail(r, "unknown OBJ statement '%s' (v, f, o, g, usemtl and mtllib are "
                             "read; radiosity-scene(5) lists what is ignored)", k);
}

rad_status radi_obj_read(rad_scene *scene, rad_lines *r, const char *mtl, size_t mtl_len,
                         unsigned flags)
{
    obj_state o;
    int got;
    memset(&o, 0, sizeof o);
    o.r = r;
    o.flags = flags;
    o.material = o.object = -1;
    o.mtl = mtl;
    o.mtl_len = mtl_len;
    rad_status st = radi_build_start(&o.b, r->name, r->err);
    while (st == RAD_OK && (got = radi_lines_next(r)) != 0) {
        if (got < 0)
            st = r->status;
        else if (r->ntok > 0)
            st = obj_line(&o);
    }
    if (st == RAD_OK && o.b.s.nsurfaces == 0)
        st = radi_lines_fail(r, "the OBJ file has no faces");
    free(o.v);
    for (int k = 0; k < o.nlibs; k++)
        free(o.libs[k]);
    free(o.libs);
    return radi_build_finish(&o.b, st, scene);
}
