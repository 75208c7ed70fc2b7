/* scene.c -- the scene model and its parser; all input validation.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The format is radiosity-scene(5): one statement per line, `#` starts a
 * comment, tokens are separated by white space, numbers use C strtod
 * syntax.  Every error is reported as "FILE:LINE: what is wrong" and leaves
 * the scene empty; nothing is half-built.
 *
 * Input is read as a stream, one line at a time, through the line reader
 * the PLY reader shares (readfile.h): a line is parsed as soon as it has
 * been read, so the first error is reported at once, and the reader's
 * limits (a line of RAD_LINE_MAX bytes, a file of RAD_FILE_MAX) bound the
 * memory whatever the input.  Outside comments only printable ASCII is
 * allowed, and the reader names the first other byte.  What a scene may
 * ask for is bounded too (polycheck.h): RAD_POLYGON_MAX vertices per polygon
 * or disk, RAD_MESH_MAX parts per edge, RAD_ELEMENTS_MAX elements per
 * surface and per scene.  The scene is built through scenebuild.h, which
 * finds materials by a hash of their names, so the parse takes time linear
 * in the input.  A file whose name ends in .obj or .vs3 goes to its own
 * reader (objread.c, vs3read.c), which builds the scene the same way and
 * checks its polygons with radi_polygon_check (polycheck.c).
 */
#include <config.h>

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "scene/polycheck.h"
#include "scene/scenebuild.h"
#include "scene/objread.h"
#include "scene/vs3read.h"
#include "util/util.h"

/* One line being parsed: its tokens and where it came from. */
typedef struct line_ctx {
    const char *file;
    int line;
    char **tok;
    int ntok;
    rad_error *err;
} line_ctx;

typedef rad_scene_build parse_state;

static rad_status fail_at(const line_ctx *c, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static rad_status fail_at(const line_ctx *c, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rad_status st = radi_fail_vat(c->err, c->file, c->line, fmt, ap);
    va_end(ap);
    return st;
}

/* ---- numbers ------------------------------------------------------------ */

static rad_status get_number(const line_ctx *c, int k, const char *what, double *out)
{
    char *end;
    if (k >= c->ntok)
        return fail_at(c, "missing number: %s", what);
    errno = 0;
    double v = strtod(c->tok[k], &end);
    if (end == c->tok[k] || *end != '\0')
        return fail_at(c, "'%s' is not a number (%s)", c->tok[k], what);
    if (!isfinite(v))
        return fail_at(c, "%s must be finite, not '%s'", what, c->tok[k]);
    *out = v;
    return RAD_OK;
}

static rad_status get_int(const line_ctx *c, int k, const char *what, long lo,
                          long hi, int *out)
{
    char *end;
    if (k >= c->ntok)
        return fail_at(c, "missing integer: %s", what);
    errno = 0;
    long v = strtol(c->tok[k], &end, 10);
    if (end == c->tok[k] || *end != '\0')
        return fail_at(c, "'%s' is not an integer (%s)", c->tok[k], what);
    if (errno == ERANGE || v < lo || v > hi)
        return fail_at(c, "%s must be from %ld to %ld, not '%s'", what, lo, hi, c->tok[k]);
    *out = (int)v;
    return RAD_OK;
}

static rad_status get_vec(const line_ctx *c, int k, const char *what, rad_vec3 *out)
{
    rad_status s;
    if ((s = get_number(c, k, what, &out->x)) || (s = get_number(c, k + 1, what, &out->y)) ||
        (s = get_number(c, k + 2, what, &out->z)))
        return s;
    return RAD_OK;
}

static int is_number(const char *t)
{
    char *end;
    (void)strtod(t, &end);
    return end != t && *end == '\0';
}

/* Does t start like a number ("0.5abc", "1,5"), so that a message should
 * say it is not one rather than that it is an unexpected word? */
static int looks_numeric(const char *t)
{
    char *end;
    (void)strtod(t, &end);
    return end != t;
}

/* ---- statements --------------------------------------------------------- */

/* One or three band values starting at token *k; advances *k. */
static rad_status get_bands(const line_ctx *c, int *k, const char *what, double lo,
                            double hi, double out[RAD_BANDS])
{
    int count = 0;
    while (*k + count < c->ntok && count < 4 && is_number(c->tok[*k + count]))
        count++;
    if (count < RAD_BANDS && *k + count < c->ntok && looks_numeric(c->tok[*k + count]))
        return fail_at(c, "'%s' is not a number (%s)", c->tok[*k + count], what);
    if (count == 0 && *k < c->ntok)
        return fail_at(c, "%s needs 1 value (grey) or 3 (R G B), found '%s'", what,
                       c->tok[*k]);
    if (count == 0)
        return fail_at(c, "%s needs 1 value (grey) or 3 (R G B)", what);
    if (count != 1 && count != RAD_BANDS)
        return fail_at(c, "%s takes 1 value (grey) or 3 (R G B), not %d", what, count);
    for (int b = 0; b < count; b++) {
        rad_status s = get_number(c, *k + b, what, &out[b]);
        if (s)
            return s;
        if (out[b] < lo || out[b] > hi) {
            if (hi < HUGE_VAL)
                return fail_at(c, "%s must be from %g to %g, not %s", what, lo, hi,
                               c->tok[*k + b]);
            return fail_at(c, "%s must not be negative, not %s", what, c->tok[*k + b]);
        }
    }
    if (count == 1)
        out[1] = out[2] = out[0];
    *k += count;
    return RAD_OK;
}

static rad_status parse_material(parse_state *p, const line_ctx *c)
{
    rad_material m;
    int k = 2, have_reflect = 0, have_emit = 0;
    rad_status st;
    memset(&m, 0, sizeof m);
    if (c->ntok < 2)
        return fail_at(c, "material needs a name");
    if (strlen(c->tok[1]) >= RAD_NAME_MAX)
        return fail_at(c, "material name is longer than %d characters", RAD_NAME_MAX - 1);
    if (is_number(c->tok[1]))
        return fail_at(c, "material name '%s' looks like a number", c->tok[1]);
    int prev = radi_build_find_material(p, c->tok[1]);
    if (prev >= 0)
        return fail_at(c, "material '%s' is already defined (line %d)", c->tok[1],
                       p->s.materials[prev].line);
    strcpy(m.name, c->tok[1]);
    while (k < c->ntok) {
        const char *kw = c->tok[k++];
        if (strcmp(kw, "reflect") == 0 && !have_reflect) {
            if ((st = get_bands(c, &k, "reflectance", 0.0, 1.0, m.reflect)))
                return st;
            have_reflect = 1;
        } else if (strcmp(kw, "emit") == 0 && !have_emit) {
            if ((st = get_bands(c, &k, "emission", 0.0, HUGE_VAL, m.emit)))
                return st;
            have_emit = 1;
        } else if (strcmp(kw, "reflect") == 0 || strcmp(kw, "emit") == 0) {
            return fail_at(c, "'%s' is given twice", kw);
        } else {
            return fail_at(c, "unexpected '%s' in material (expected reflect or emit)", kw);
        }
    }
    if (!have_reflect)
        return fail_at(c, "material '%s' has no reflect values", m.name);
    m.line = c->line;
    return radi_build_add_material(p, &m, c->file, c->line);
}

/* Append a surface that owns `verts` (freed on failure): to the object
 * being read, or to the static environment outside every object. */
static rad_status add_surface(parse_state *p, const line_ctx *c, rad_surface_kind kind,
                              int material, rad_vec3 *verts, int n, int mn, int mm)
{
    return radi_build_add_surface(p, c->line, kind, material, p->object, verts, n, mn, mm);
}

static rad_status get_material_ref(const parse_state *p, const line_ctx *c, int *out)
{
    if (c->ntok < 2)
        return fail_at(c, "%s needs a material", c->tok[0]);
    *out = radi_build_find_material(p, c->tok[1]);
    if (*out < 0)
        return fail_at(c, "undefined material '%s'", c->tok[1]);
    return RAD_OK;
}

/* "NxM" with positive integers. */
static rad_status parse_mesh_spec(const line_ctx *c, const char *t, int *n, int *m)
{
    char *end;
    errno = 0;
    long a = strtol(t, &end, 10);
    if (end == t || (*end != 'x' && *end != 'X') || a < 1 || a > RAD_MESH_MAX || errno)
        goto bad;
    const char *t2 = end + 1;
    long b = strtol(t2, &end, 10);
    if (end == t2 || *end != '\0' || b < 1 || b > RAD_MESH_MAX || errno)
        goto bad;
    if (*t == '+' || *t2 == '+' || *t2 == ' ')
        goto bad;
    if ((double)a * (double)b > RAD_ELEMENTS_MAX)
        return fail_at(c, "mesh %s has %.0f elements; at most %d per surface", t,
                       (double)a * (double)b, RAD_ELEMENTS_MAX);
    *n = (int)a;
    *m = (int)b;
    return RAD_OK;
bad:
    return fail_at(c, "mesh must be NxM with whole numbers from 1 to %d, not '%s'",
                   RAD_MESH_MAX, t);
}

static rad_status parse_quad(parse_state *p, const line_ctx *c)
{
    int mat, mn = 1, mm = 1;
    rad_status st;
    rad_vec3 v[4];
    if ((st = get_material_ref(p, c, &mat)))
        return st;
    for (int k = 0; k < 4; k++) {
        char what[32];
        snprintf(what, sizeof what, "vertex %d", k + 1);
        if ((st = get_vec(c, 2 + 3 * k, what, &v[k])))
            return st;
    }
    if (c->ntok > 14) {
        if (strcmp(c->tok[14], "mesh") != 0)
            return fail_at(c, "unexpected '%s' after the quad's 4 vertices", c->tok[14]);
        if (c->ntok < 16)
            return fail_at(c, "mesh needs NxM");
        if ((st = parse_mesh_spec(c, c->tok[15], &mn, &mm)))
            return st;
        if (c->ntok > 16)
            return fail_at(c, "unexpected '%s' after mesh", c->tok[16]);
    }
    if ((st = radi_polygon_check(v, 4, "quad", c->file, c->line, c->err)))
        return st;
    rad_vec3 *verts = malloc(sizeof v);
    if (!verts)
        return radi_fail(c->err, RAD_ERR_NOMEM, "%s:%d: out of memory", c->file, c->line);
    memcpy(verts, v, sizeof v);
    return add_surface(p, c, RAD_SURFACE_QUAD, mat, verts, 4, mn, mm);
}

static rad_status parse_polygon(parse_state *p, const line_ctx *c)
{
    int mat, n;
    rad_status st;
    if ((st = get_material_ref(p, c, &mat)) ||
        (st = get_int(c, 2, "polygon vertex count", 3, RAD_POLYGON_MAX, &n)))
        return st;
    if (c->ntok != 3 + 3 * n) {
        if (c->ntok < 3 + 3 * n)
            return fail_at(c, "polygon of %d vertices needs %d numbers, found %d", n,
                           3 * n, c->ntok - 3);
        return fail_at(c, "unexpected '%s' after the polygon's %d vertices",
                       c->tok[3 + 3 * n], n);
    }
    rad_vec3 *v = malloc(sizeof *v * (size_t)n);
    if (!v)
        return radi_fail(c->err, RAD_ERR_NOMEM, "%s:%d: out of memory", c->file, c->line);
    for (int k = 0; k < n; k++) {
        char what[32];
        snprintf(what, sizeof what, "vertex %d", k + 1);
        if ((st = get_vec(c, 3 + 3 * k, what, &v[k]))) {
            free(v);
            return st;
        }
    }
    if ((st = radi_polygon_check(v, n, "polygon", c->file, c->line, c->err))) {
        free(v);
        return st;
    }
    return add_surface(p, c, RAD_SURFACE_POLYGON, mat, v, n, 1, 1);
}

/* disk MATERIAL CX CY CZ NX NY NZ R K: the regular K-gon inscribed in the
 * disk, counter-clockwise about the normal N. */
static rad_status parse_disk(parse_state *p, const line_ctx *c)
{
    int mat, n;
    double r;
    rad_vec3 ctr, nrm;
    rad_status st;
    if ((st = get_material_ref(p, c, &mat)) || (st = get_vec(c, 2, "centre", &ctr)) ||
        (st = get_vec(c, 5, "normal", &nrm)) || (st = get_number(c, 8, "radius", &r)) ||
        (st = get_int(c, 9, "disk vertex count", 3, RAD_POLYGON_MAX, &n)))
        return st;
    if (c->ntok > 10)
        return fail_at(c, "unexpected '%s' after the disk's vertex count", c->tok[10]);
    if (!(r > 0))
        return fail_at(c, "disk radius must be positive, not %s", c->tok[8]);
    double len = v3_norm(nrm);
    if (!(len > 0) || !isfinite(len))
        return fail_at(c, "disk normal must not be zero");
    nrm = v3_scale(nrm, 1.0 / len);
    /* (u, w, n) right-handed, so increasing angle runs counter-clockwise. */
    rad_vec3 axis = fabs(nrm.x) <= fabs(nrm.y) && fabs(nrm.x) <= fabs(nrm.z) ? v3(1, 0, 0)
                    : fabs(nrm.y) <= fabs(nrm.z)                          ? v3(0, 1, 0)
                                                                           : v3(0, 0, 1);
    rad_vec3 u = v3_cross(axis, nrm);
    u = v3_scale(u, 1.0 / v3_norm(u));
    rad_vec3 w = v3_cross(nrm, u);
    rad_vec3 *v = malloc(sizeof *v * (size_t)n);
    if (!v)
        return radi_fail(c->err, RAD_ERR_NOMEM, "%s:%d: out of memory", c->file, c->line);
    for (int k = 0; k < n; k++) {
        double t = 2 * RAD_PI * k / n;
        v[k] = v3_add(ctr, v3_add(v3_scale(u, r * cos(t)), v3_scale(w, r * sin(t))));
    }
    if ((st = radi_polygon_check(v, n, "disk", c->file, c->line, c->err))) {
        free(v);
        return st;
    }
    return add_surface(p, c, RAD_SURFACE_POLYGON, mat, v, n, 1, 1);
}

static rad_status parse_camera(parse_state *p, const line_ctx *c)
{
    rad_scene *s = &p->s;
    static const char *const kw[4] = {"eye", "at", "up", "fov"};
    rad_camera cam;
    rad_status st;
    memset(&cam, 0, sizeof cam);
    if (c->ntok != 15) {
        if (c->ntok > 15)
            return fail_at(c, "unexpected '%s' at the end of camera", c->tok[15]);
        return fail_at(c, "camera needs: eye X Y Z at X Y Z up X Y Z fov DEGREES");
    }
    for (int k = 0; k < 4; k++)
        if (strcmp(c->tok[1 + 4 * k], kw[k]) != 0)
            return fail_at(c, "camera expects '%s' where it found '%s'", kw[k],
                           c->tok[1 + 4 * k]);
    if ((st = get_vec(c, 2, "eye", &cam.eye)) || (st = get_vec(c, 6, "at", &cam.at)) ||
        (st = get_vec(c, 10, "up", &cam.up)) || (st = get_number(c, 14, "fov", &cam.fov)))
        return st;
    if (!(cam.fov > 0 && cam.fov < 180))
        return fail_at(c, "fov must be between 0 and 180 degrees, not %s", c->tok[14]);
    rad_vec3 view = v3_sub(cam.at, cam.eye);
    if (!(v3_norm(view) > 0))
        return fail_at(c, "camera eye and at must differ");
    rad_vec3 side = v3_cross(view, cam.up);
    if (!(v3_norm(side) > 1e-12 * v3_norm(view) * v3_norm(cam.up)))
        return fail_at(c, "camera up must not be zero or parallel to the view direction");
    if (s->camera.defined)
        return fail_at(c, "camera is given twice");
    cam.defined = 1;
    s->camera = cam;
    return RAD_OK;
}

/* object NAME [absent]: the surfaces up to `end` form the object NAME
 * (objects do not nest; names are unique; an absent object joins the scene
 * only when a change adds it, radiosity-scene(5)). */
static rad_status parse_object(parse_state *p, const line_ctx *c)
{
    int index;
    rad_status st;
    if (p->object >= 0)
        return fail_at(c, "object '%s' (line %d) has no end: objects do not nest",
                       p->s.objects[p->object].name, p->s.objects[p->object].line);
    if (c->ntok < 2)
        return fail_at(c, "object needs a name");
    if (c->ntok > 3 || (c->ntok == 3 && strcmp(c->tok[2], "absent") != 0))
        return fail_at(c, "unexpected '%s' after the object's name (expected absent)",
                       c->tok[2]);
    if (is_number(c->tok[1]))
        return fail_at(c, "object name '%s' looks like a number", c->tok[1]);
    int prev = radi_build_find_object(p, c->tok[1]);
    if (prev >= 0)
        return fail_at(c, "object '%s' is already defined (line %d)", c->tok[1],
                       p->s.objects[prev].line);
    if ((st = radi_build_object(p, c->tok[1], c->line, &index)))
        return st;
    p->s.objects[index].absent = c->ntok == 3;
    p->object = index;
    return RAD_OK;
}

/* end: closes the object being read, which must have a surface. */
static rad_status parse_end(parse_state *p, const line_ctx *c)
{
    if (p->object < 0)
        return fail_at(c, "end without object");
    if (c->ntok > 1)
        return fail_at(c, "unexpected '%s' after end", c->tok[1]);
    const rad_scene *s = &p->s;
    if (s->nsurfaces == 0 || s->surfaces[s->nsurfaces - 1].object != p->object)
        return fail_at(c, "object '%s' has no surfaces", s->objects[p->object].name);
    p->object = -1;
    return RAD_OK;
}

/* ---- lines and files ---------------------------------------------------- */

static rad_status parse_statement(parse_state *p, const line_ctx *c)
{
    const char *k = c->tok[0];
    if (strcmp(k, "material") == 0)
        return parse_material(p, c);
    if (strcmp(k, "quad") == 0)
        return parse_quad(p, c);
    if (strcmp(k, "polygon") == 0)
        return parse_polygon(p, c);
    if (strcmp(k, "disk") == 0)
        return parse_disk(p, c);
    if (strcmp(k, "camera") == 0)
        return parse_camera(p, c);
    if (strcmp(k, "object") == 0)
        return parse_object(p, c);
    if (strcmp(k, "end") == 0)
        return parse_end(p, c);
    return fail_at(c, "unknown keyword '%s' (expected material, quad, polygon, disk, camera, "
                   "object or end)", k);
}

/* Parse every line r gives into *scene; on failure leave it empty. */
static rad_status parse_lines(rad_scene *scene, rad_lines *r, const char *name)
{
    parse_state p;
    int got;
    rad_status st = radi_build_start(&p, name, r->err);

    while (st == RAD_OK && (got = radi_lines_next(r)) != 0) {
        if (got < 0) {
            st = r->status;
            break;
        }
        if (r->ntok == 0)
            continue;
        line_ctx c = {p.s.filename, r->line, r->tok, r->ntok, r->err};
        if (!(st = radi_lines_ascii(r, 0)))
            st = parse_statement(&p, &c);
    }
    if (st == RAD_OK && p.object >= 0)
        st = radi_fail(r->err, RAD_ERR_PARSE, "%s:%d: object '%s' has no end",
                      p.s.filename, p.s.objects[p.object].line, p.s.objects[p.object].name);
    if (st == RAD_OK && p.s.nsurfaces == 0)
        st = radi_lines_fail(r, "the scene has no surfaces (quad, polygon or disk)");
    return radi_build_finish(&p, st, scene);
}

/* The format a file name asks for, by its ending (case-insensitive). */
typedef enum scene_format { FORMAT_SCENE, FORMAT_OBJ, FORMAT_VS3 } scene_format;

static int ends_with(const char *name, const char *suffix)
{
    size_t n = strlen(name), k = strlen(suffix);
    return n > k && strcasecmp(name + n - k, suffix) == 0;
}

static scene_format format_of(const char *name)
{
    return ends_with(name, ".obj") ? FORMAT_OBJ : ends_with(name, ".vs3") ? FORMAT_VS3
                                                                         : FORMAT_SCENE;
}

/* View3D comments start with '!', the others' with '#'. */
static char comment_of(scene_format f)
{
    return f == FORMAT_VS3 ? '!' : '#';
}

static rad_status read_format(rad_scene *scene, rad_lines *r, const char *name,
                              scene_format f, unsigned flags)
{
    rad_status st;
    switch (f) {
    case FORMAT_OBJ:
        st = radi_obj_read(scene, r, NULL, 0, flags);
        break;
    case FORMAT_VS3:
        st = radi_vs3_read(scene, r);
        break;
    default:
        st = parse_lines(scene, r, name);
    }
    if (st == RAD_OK)
        scene->format = f == FORMAT_OBJ   ? RAD_SCENE_FORMAT_OBJ
                        : f == FORMAT_VS3 ? RAD_SCENE_FORMAT_VS3
                                          : RAD_SCENE_FORMAT_SCENE;
    return st;
}

rad_status rad_scene_parse(rad_scene *scene, const char *text, size_t len,
                           const char *name, rad_error *err)
{
    rad_lines r;
    name = name ? name : "-";
    scene_format f = format_of(name);
    radi_lines_mem(&r, text, len, name, comment_of(f), err);
    rad_status st = read_format(scene, &r, name, f, 0);
    radi_lines_close(&r);
    return st;
}

rad_status rad_scene_load(rad_scene *scene, const char *path, rad_error *err)
{
    return rad_scene_load_format(scene, path, RAD_SCENE_FORMAT_AUTO, 0, err);
}

rad_status rad_scene_load_format(rad_scene *scene, const char *path, rad_scene_format format,
                                 unsigned flags, rad_error *err)
{
    rad_lines r;
    scene_format f = format == RAD_SCENE_FORMAT_OBJ     ? FORMAT_OBJ
                     : format == RAD_SCENE_FORMAT_VS3   ? FORMAT_VS3
                     : format == RAD_SCENE_FORMAT_SCENE ? FORMAT_SCENE
                                                        : format_of(path);
    memset(scene, 0, sizeof *scene);
    rad_status st = radi_lines_open(&r, path, comment_of(f), err);
    if (st == RAD_OK)
        st = read_format(scene, &r, path, f, flags);
    radi_lines_close(&r);
    return st;
}

void rad_scene_set_mesh(rad_scene *scene, int n, int m)
{
    for (int k = 0; k < scene->nsurfaces; k++) {
        rad_surface *f = &scene->surfaces[k];
        const int quad = f->kind == RAD_SURFACE_QUAD;
        f->mesh_n = quad ? n : n > m ? n : m;
        f->mesh_m = quad ? m : f->mesh_n;
    }
}

/* Parts of a side of length d so that each is at most `size` long
 * (capped: a count beyond the element limit is refused when meshing). */
static int parts(double d, double size)
{
    const double k = ceil(d / size);
    return !(k >= 1) ? 1 : k > RAD_ELEMENTS_MAX ? RAD_ELEMENTS_MAX : (int)k;
}

static double dist(rad_vec3 a, rad_vec3 b)
{
    return v3_norm(v3_sub(a, b));
}

/* The area centroid of a convex polygon (the apex of its fan, meshtri.c):
 * its triangles from v[0] weighted by their areas. */
static rad_vec3 area_centroid(const rad_vec3 *v, int n)
{
    rad_vec3 c = v3(0, 0, 0);
    double a = 0;
    for (int k = 1; k + 1 < n; k++) {
        const double t = v3_norm(v3_cross(v3_sub(v[k], v[0]), v3_sub(v[k + 1], v[0])));
        c = v3_add(c, v3_scale(v3_add(v3_add(v[0], v[k]), v[k + 1]), t / 3));
        a += t;
    }
    return a > 0 ? v3_scale(c, 1 / a) : v[0];
}

int rad_scene_set_max_element_size(rad_scene *scene, double size)
{
    int cut = 0;
    for (int k = 0; k < scene->nsurfaces; k++) {
        rad_surface *f = &scene->surfaces[k];
        const rad_vec3 *v = f->verts;
        int n, m; /* each side of an element at most size */
        if (f->kind == RAD_SURFACE_QUAD) {
            n = parts(fmax(dist(v[0], v[1]), dist(v[3], v[2])), size);
            m = parts(fmax(dist(v[1], v[2]), dist(v[0], v[3])), size);
        } else { /* every edge of its fan's triangles (meshtri.c): outline and spokes */
            const rad_vec3 apex = f->nverts == 3 ? v[0] : area_centroid(v, f->nverts);
            double d = 0;
            for (int j = 0; j < f->nverts; j++)
                d = fmax(d, fmax(dist(v[j], v[(j + 1) % f->nverts]), dist(apex, v[j])));
            n = m = parts(d, size);
        }
        /* a finer mesh of the scene's own stays */
        cut += n > f->mesh_n || m > f->mesh_m;
        f->mesh_n = n > f->mesh_n ? n : f->mesh_n;
        f->mesh_m = m > f->mesh_m ? m : f->mesh_m;
    }
    return cut;
}
