/* plyread.c -- read a solution PLY back into a render model.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The format is Greg Turk's PLY (1994), ASCII flavour: a header of
 * `element NAME COUNT` lines each followed by its `property TYPE NAME` or
 * `property list COUNT-TYPE ITEM-TYPE NAME` lines, then `end_header`, then
 * the elements' instances in header order, one per line, their values in
 * property order.  What this reader takes from it is in plyread.h.
 *
 * Robustness: lines come from the line reader the scene parser shares
 * (readfile.h), one at a time, within its limits on line and file length;
 * an element count larger than the rest of the input could hold (what is
 * left of a regular file or of text in memory, else of the file limit) is
 * refused before anything is allocated for it; outside comment and
 * obj_info lines only printable ASCII is allowed; every number must be finite and, for integer types, whole and within the
 * type's range; every vertex index must exist; every face must pass the
 * scene file's polygon check.  Errors name the file and line and leave the
 * model empty.
 */
#include <config.h>

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/render.h"
#include "radiosity/plyread.h"
#include "radiosity/plyread.h"
#include "scene/polycheck.h"
#include "util/util.h"

#define MAX_ELEMENTS 16
#define MAX_PROPERTIES 64
#define NAME_MAX_LEN 64
#define MAX_FACE_VERTICES RAD_POLYGON_MAX

typedef enum ptype {
    T_NONE = 0, T_INT8, T_UINT8, T_INT16, T_UINT16, T_INT32, T_UINT32, T_FLOAT32, T_FLOAT64
} ptype;

/* What a property means to us. */
typedef enum role {
    R_SKIP = 0, R_X, R_Y, R_Z, R_RAD, R_COLOUR, R_INDICES, R_SURFACE, R_EMITS
} role;

typedef struct ply_prop {
    char name[NAME_MAX_LEN];
    ptype type;                 /* the scalar, or a list's item type */
    ptype count_type;           /* a list's count type; T_NONE for scalars */
    role role;
    int band;                   /* R_RAD, R_COLOUR: 0, 1, 2 */
} ply_prop;

typedef struct ply_element {
    char name[NAME_MAX_LEN];
    long count;
    int line;                   /* of its header line */
    int nprops;
    ply_prop props[MAX_PROPERTIES];
} ply_element;

/* Where each band's radiosity comes from. */
typedef enum source { SRC_NONE = 0, SRC_RAD, SRC_COLOUR } source;

/* The reader's current line is all the parse needs of it. */
typedef rad_lines reader;

/* Everything the parse builds. */
typedef struct ply_state {
    ply_element elem[MAX_ELEMENTS];
    int nelem;
    int have_format;
    int vertex, face;           /* indices into elem, -1 absent */
    source vsrc, fsrc;
    int have_emits;             /* the faces carry `emitting` */
    rad_render_model m;
    size_t nindex, capindex;
    int *face_line;             /* input line of each face */
    size_t vcap, fcap;          /* vertices and faces the arrays hold so far */
    double *vband, *fband;      /* radiosity as read, interleaved: [3 * i + band] */
    rad_camera camera;
} ply_state;

static rad_status fail_at(const reader *r, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static rad_status fail_at(const reader *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rad_status st = radi_fail_vat(r->err, r->name, r->line, fmt, ap);
    va_end(ap);
    return st;
}

/* ---- lines and tokens ----------------------------------------------------- */

/* The next line, split into tokens.  1: a line, 0: end of file, -1: error
 * (reported, r->status).  Comments may hold any text; other lines only
 * printable ASCII. */
static int next_line(reader *r)
{
    int got = radi_lines_next(r);
    if (got <= 0 || r->ntok == 0 || strcmp(r->tok[0], "comment") == 0 ||
        strcmp(r->tok[0], "obj_info") == 0)
        return got;
    if ((r->status = radi_lines_ascii(r, 0)) != RAD_OK)
        return -1;
    return 1;
}

/* The next non-blank line; 0 at end of file. */
static int next_nonblank(reader *r)
{
    int got;
    while ((got = next_line(r)) == 1 && r->ntok == 0)
        ;
    return got;
}

/* ---- numbers ------------------------------------------------------------- */

static const struct {
    const char *name;
    ptype type;
} type_names[] = {
    {"char", T_INT8},     {"uchar", T_UINT8},   {"short", T_INT16},  {"ushort", T_UINT16},
    {"int", T_INT32},     {"uint", T_UINT32},   {"float", T_FLOAT32}, {"double", T_FLOAT64},
    {"int8", T_INT8},     {"uint8", T_UINT8},   {"int16", T_INT16},  {"uint16", T_UINT16},
    {"int32", T_INT32},   {"uint32", T_UINT32}, {"float32", T_FLOAT32}, {"float64", T_FLOAT64},
};

static ptype parse_type(const char *s)
{
    for (size_t k = 0; k < sizeof type_names / sizeof type_names[0]; k++)
        if (strcmp(s, type_names[k].name) == 0)
            return type_names[k].type;
    return T_NONE;
}

static int is_integer_type(ptype t)
{
    return t != T_NONE && t != T_FLOAT32 && t != T_FLOAT64;
}

static void type_range(ptype t, double *lo, double *hi)
{
    switch (t) {
    case T_INT8: *lo = -128; *hi = 127; break;
    case T_UINT8: *lo = 0; *hi = 255; break;
    case T_INT16: *lo = -32768; *hi = 32767; break;
    case T_UINT16: *lo = 0; *hi = 65535; break;
    case T_INT32: *lo = -2147483648.0; *hi = 2147483647.0; break;
    case T_UINT32: *lo = 0; *hi = 4294967295.0; break;
    default: *lo = -HUGE_VAL; *hi = HUGE_VAL; break;
    }
}

/* Token k of the line as a value of type t. */
static rad_status get_value(const reader *r, int k, ptype t, const char *prop,
                            const char *elem, double *out)
{
    char *end;
    double lo, hi;
    if (k >= r->ntok)
        return fail_at(r, "missing value for property '%s' of %s", prop, elem);
    errno = 0;
    double v = strtod(r->tok[k], &end);
    if (end == r->tok[k] || *end != '\0')
        return fail_at(r, "'%s' is not a number (property '%s' of %s)", r->tok[k], prop, elem);
    if (!isfinite(v))
        return fail_at(r, "property '%s' of %s must be finite, not '%s'", prop, elem,
                       r->tok[k]);
    type_range(t, &lo, &hi);
    if (is_integer_type(t) && (v != floor(v) || v < lo || v > hi))
        return fail_at(r, "'%s' is not a whole number from %.0f to %.0f (property '%s' of %s)",
                       r->tok[k], lo, hi, prop, elem);
    *out = v;
    return RAD_OK;
}

/* Step over a list property this reader does not use: its count, then its
 * items. */
static rad_status skip_list(const reader *r, int *k, const ply_prop *p, const char *what)
{
    double count;
    rad_status st = get_value(r, (*k)++, p->count_type, p->name, what, &count);
    if (st)
        return st;
    if (count < 0 || count > r->ntok - *k)
        return fail_at(r, "list '%s' of %s has %.0f items, the line fewer", p->name, what,
                       count);
    *k += (int)count;
    return RAD_OK;
}

/* ---- header ---------------------------------------------------------------- */

static rad_status parse_camera(const reader *r, rad_camera *cam)
{
    static const char *const kw[4] = {"eye", "at", "up", "fov"};
    double v[10];
    if (r->ntok != 16)
        return fail_at(r, "camera comment needs: eye X Y Z at X Y Z up X Y Z fov DEGREES");
    for (int k = 0; k < 4; k++)
        if (strcmp(r->tok[2 + 4 * k], kw[k]) != 0)
            return fail_at(r, "camera comment expects '%s' where it found '%s'", kw[k],
                           r->tok[2 + 4 * k]);
    for (int k = 0, j = 0; k < 14; k++) { /* tok[2 + k]: keyword, X, Y, Z, ... */
        if (k % 4 == 0)
            continue;
        rad_status st = get_value(r, 2 + k, T_FLOAT64, "camera", "the comment", &v[j++]);
        if (st)
            return st;
    }
    memset(cam, 0, sizeof *cam);
    cam->defined = 1;
    cam->eye = (rad_vec3){v[0], v[1], v[2]};
    cam->at = (rad_vec3){v[3], v[4], v[5]};
    cam->up = (rad_vec3){v[6], v[7], v[8]};
    cam->fov = v[9];
    rad_error e2;
    if (rad_camera_check(cam, &e2) != RAD_OK) {
        memset(cam, 0, sizeof *cam);
        return fail_at(r, "camera comment: %s", e2.message);
    }
    return RAD_OK;
}

static rad_status header_element(reader *r, ply_state *s)
{
    char *end;
    if (r->ntok != 3)
        return fail_at(r, "element needs a name and a count");
    if (s->nelem == MAX_ELEMENTS)
        return fail_at(r, "more than %d elements", MAX_ELEMENTS);
    if (strlen(r->tok[1]) >= NAME_MAX_LEN)
        return fail_at(r, "element name is longer than %d characters", NAME_MAX_LEN - 1);
    for (int k = 0; k < s->nelem; k++)
        if (strcmp(s->elem[k].name, r->tok[1]) == 0)
            return fail_at(r, "element '%s' is declared twice", r->tok[1]);
    errno = 0;
    long n = strtol(r->tok[2], &end, 10);
    if (end == r->tok[2] || *end || errno || n < 0 || n > INT_MAX / 4)
        return fail_at(r, "element count must be a whole number from 0 to %d, not '%s'",
                       INT_MAX / 4, r->tok[2]);
    ply_element *e = &s->elem[s->nelem++];
    memset(e, 0, sizeof *e);
    strcpy(e->name, r->tok[1]);
    e->count = n;
    e->line = r->line;
    return RAD_OK;
}

static rad_status header_property(reader *r, ply_state *s)
{
    ply_prop p;
    memset(&p, 0, sizeof p);
    if (s->nelem == 0)
        return fail_at(r, "property before any element");
    ply_element *e = &s->elem[s->nelem - 1];
    const int list = r->ntok >= 2 && strcmp(r->tok[1], "list") == 0;
    if (r->ntok != (list ? 5 : 3))
        return fail_at(r, list ? "property list needs: COUNT-TYPE ITEM-TYPE NAME"
                               : "property needs: TYPE NAME");
    const char *name = r->tok[r->ntok - 1];
    if (list) {
        p.count_type = parse_type(r->tok[2]);
        p.type = parse_type(r->tok[3]);
        if (!is_integer_type(p.count_type))
            return fail_at(r, "list count type must be an integer type, not '%s'", r->tok[2]);
    } else {
        p.type = parse_type(r->tok[1]);
    }
    if (p.type == T_NONE)
        return fail_at(r, "unknown property type '%s'", r->tok[list ? 3 : 1]);
    if (strlen(name) >= NAME_MAX_LEN)
        return fail_at(r, "property name is longer than %d characters", NAME_MAX_LEN - 1);
    for (int k = 0; k < e->nprops; k++)
        if (strcmp(e->props[k].name, name) == 0)
            return fail_at(r, "property '%s' of element '%s' is declared twice", name, e->name);
    if (e->nprops == MAX_PROPERTIES)
        return fail_at(r, "element '%s' has more than %d properties", e->name, MAX_PROPERTIES);
    strcpy(p.name, name);
    e->props[e->nprops++] = p;
    return RAD_OK;
}

static rad_status header_format(const reader *r, ply_state *s)
{
    if (r->ntok != 3)
        return fail_at(r, "format needs: ascii 1.0");
    if (strncmp(r->tok[1], "binary", 6) == 0)
        return fail_at(r, "%s PLY is not supported; write it as ascii", r->tok[1]);
    if (strcmp(r->tok[1], "ascii") != 0)
        return fail_at(r, "unknown PLY format '%s'", r->tok[1]);
    if (strcmp(r->tok[2], "1.0") != 0)
        return fail_at(r, "PLY version '%s' is not supported (only 1.0)", r->tok[2]);
    if (s->have_format)
        return fail_at(r, "format is given twice");
    s->have_format = 1;
    return RAD_OK;
}

static rad_status parse_header(reader *r, ply_state *s)
{
    rad_status st;
    int got = next_line(r);
    if (got < 0)
        return r->status;
    if (got == 0 || r->ntok != 1 || strcmp(r->tok[0], "ply") != 0) {
        r->line = 1;
        return fail_at(r, "not a PLY file (the first line is not 'ply')");
    }
    for (;;) {
        if ((got = next_line(r)) < 0)
            return r->status;
        if (got == 0)
            return fail_at(r, "unexpected end of file in the header (no end_header)");
        if (r->ntok == 0)
            continue;
        const char *kw = r->tok[0];
        if (strcmp(kw, "end_header") == 0) {
            if (r->ntok != 1)
                return fail_at(r, "unexpected '%s' after end_header", r->tok[1]);
            if (!s->have_format)
                return fail_at(r, "the header has no format line");
            return RAD_OK;
        }
        if (strcmp(kw, "format") == 0)
            st = header_format(r, s);
        else if (strcmp(kw, "element") == 0)
            st = header_element(r, s);
        else if (strcmp(kw, "property") == 0)
            st = header_property(r, s);
        else if (strcmp(kw, "comment") == 0)
            st = r->ntok >= 2 && strcmp(r->tok[1], "camera") == 0
                     ? parse_camera(r, &s->camera)
                     : RAD_OK;
        else if (strcmp(kw, "obj_info") == 0)
            st = RAD_OK;
        else
            st = fail_at(r, "unknown header keyword '%s'", kw);
        if (st)
            return st;
    }
}

/* ---- what the header means ----------------------------------------------- */

static int find_element(const ply_state *s, const char *name)
{
    for (int k = 0; k < s->nelem; k++)
        if (strcmp(s->elem[k].name, name) == 0)
            return k;
    return -1;
}

/* Mark radiosity and colour properties; which source has all three bands. */
static source assign_bands(ply_element *e)
{
    static const char *const rad[3] = {"radiosity_r", "radiosity_g", "radiosity_b"};
    static const char *const col[3] = {"red", "green", "blue"};
    int nrad = 0, ncol = 0;
    for (int k = 0; k < e->nprops; k++) {
        ply_prop *p = &e->props[k];
        if (p->count_type != T_NONE)
            continue;
        for (int b = 0; b < 3; b++) {
            if (strcmp(p->name, rad[b]) == 0) {
                p->role = R_RAD;
                p->band = b;
                nrad++;
            } else if (strcmp(p->name, col[b]) == 0) {
                p->role = R_COLOUR;
                p->band = b;
                ncol++;
            }
        }
    }
    source src = nrad == 3 ? SRC_RAD : ncol == 3 ? SRC_COLOUR : SRC_NONE;
    for (int k = 0; k < e->nprops; k++) { /* keep only the source used */
        ply_prop *p = &e->props[k];
        if ((p->role == R_RAD && src != SRC_RAD) || (p->role == R_COLOUR && src != SRC_COLOUR))
            p->role = R_SKIP;
    }
    return src;
}

static rad_status check_header(reader *r, ply_state *s)
{
    s->vertex = find_element(s, "vertex");
    s->face = find_element(s, "face");
    if (s->vertex < 0)
        return fail_at(r, "the PLY has no vertex element");
    ply_element *v = &s->elem[s->vertex];
    static const char *const axis[3] = {"x", "y", "z"};
    int have[3] = {0, 0, 0}, indices = 0;
    for (int k = 0; k < v->nprops; k++) {
        ply_prop *p = &v->props[k];
        for (int c = 0; c < 3; c++)
            if (p->count_type == T_NONE && strcmp(p->name, axis[c]) == 0) {
                p->role = (role)(R_X + c);
                have[c] = 1;
            }
    }
    if (!have[0] || !have[1] || !have[2]) {
        r->line = v->line;
        return fail_at(r, "element vertex needs the properties x, y and z");
    }
    if (s->face < 0)
        return fail_at(r, "the PLY has no face element");
    ply_element *f = &s->elem[s->face];
    for (int k = 0; k < f->nprops; k++) {
        ply_prop *p = &f->props[k];
        if (p->count_type != T_NONE && !indices &&
            (strcmp(p->name, "vertex_indices") == 0 || strcmp(p->name, "vertex_index") == 0)) {
            if (!is_integer_type(p->type)) {
                r->line = f->line;
                return fail_at(r, "face vertex indices must have an integer type");
            }
            p->role = R_INDICES;
            indices = 1;
        } else if (p->count_type == T_NONE && strcmp(p->name, "surface") == 0) {
            p->role = R_SURFACE;
        } else if (p->count_type == T_NONE && strcmp(p->name, "emitting") == 0) {
            p->role = R_EMITS; /* the automatic exposure leaves these out */
            s->have_emits = 1;
        }
    }
    if (!indices) {
        r->line = f->line;
        return fail_at(r, "element face needs the list property vertex_indices");
    }
    s->vsrc = assign_bands(v);
    s->fsrc = assign_bands(f);
    if (s->vsrc == SRC_NONE && s->fsrc == SRC_NONE)
        return fail_at(r, "the PLY carries no radiosity (radiosity_r/g/b) and no colour "
                          "(red/green/blue) on its vertices or faces");
    if (f->count == 0)
        return fail_at(r, "the PLY has no faces to draw");
    /* refuse counts the rest of the file cannot hold before allocating */
    size_t left = radi_lines_left(r);
    for (int k = 0; k < s->nelem; k++) {
        const ply_element *e = &s->elem[k];
        /* at least one byte per value (one per instance without any) */
        double least = (double)e->count * (e->nprops > 0 ? e->nprops : 1);
        if (least > (double)left + 1) {
            r->line = e->line;
            return fail_at(r, "element '%s' count %ld is more than the rest of the file "
                              "(%zu bytes) can hold", e->name, e->count, left);
        }
    }
    return RAD_OK;
}

/* The arrays grow with the lines actually read, never ahead of them, so
 * memory follows the input and not the counts its header claims. */
static rad_status alloc_model(const reader *r, ply_state *s)
{
    rad_render_model *m = &s->m;
    m->nvertices = (int)s->elem[s->vertex].count;
    m->nfaces = (int)s->elem[s->face].count;
    m->face_first = calloc(1, sizeof *m->face_first);
    s->capindex = 1024;
    m->face_index = malloc(sizeof *m->face_index * s->capindex);
    if (!m->face_first || !m->face_index)
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s: out of memory", r->name);
    return RAD_OK;
}

static int grow(void *pp, size_t n, size_t size)
{
    void **p = pp;
    void *g = realloc(*p, n * size);
    if (!g)
        return -1;
    *p = g;
    return 0;
}

/* Capacity for instance i: doubled, at most the declared count. */
static size_t next_cap(size_t cap, size_t i, size_t count)
{
    size_t n = cap ? 2 * cap : 1024;
    if (n < i + 1)
        n = i + 1;
    return n < count ? n : count;
}

static rad_status vertex_room(const reader *r, ply_state *s, size_t i)
{
    if (i < s->vcap)
        return RAD_OK;
    rad_render_model *m = &s->m;
    size_t n = next_cap(s->vcap, i, (size_t)m->nvertices);
    if (grow(&m->pos, n, sizeof *m->pos) || grow(&s->vband, RAD_BANDS * n, sizeof(double)))
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory for %zu vertices",
                        r->name, r->line, n);
    memset(m->pos + s->vcap, 0, (n - s->vcap) * sizeof *m->pos);
    memset(s->vband + RAD_BANDS * s->vcap, 0, RAD_BANDS * (n - s->vcap) * sizeof(double));
    s->vcap = n;
    return RAD_OK;
}

static rad_status face_room(const reader *r, ply_state *s, size_t i)
{
    if (i < s->fcap)
        return RAD_OK;
    rad_render_model *m = &s->m;
    size_t n = next_cap(s->fcap, i, (size_t)m->nfaces);
    if (grow(&m->face_first, n + 1, sizeof(int)) || grow(&m->face_surface, n, sizeof(int)) ||
        grow(&m->face_gi, n, sizeof(int)) || grow(&m->face_gj, n, sizeof(int)) ||
        (s->have_emits && grow(&m->face_emits, n, 1)) ||
        grow(&s->face_line, n, sizeof(int)) || grow(&s->fband, RAD_BANDS * n, sizeof(double)))
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory for %zu faces", r->name,
                        r->line, n);
    for (size_t f = s->fcap; f < n; f++)
        m->face_surface[f] = m->face_gi[f] = m->face_gj[f] = -1;
    if (s->have_emits)
        memset(m->face_emits + s->fcap, 0, n - s->fcap);
    memset(s->fband + RAD_BANDS * s->fcap, 0, RAD_BANDS * (n - s->fcap) * sizeof(double));
    s->fcap = n;
    return RAD_OK;
}

/* Every instance is in: the model's band-major radiosity from what was read. */
static rad_status finish_model(const reader *r, ply_state *s)
{
    rad_render_model *m = &s->m;
    const size_t nv = (size_t)m->nvertices, nf = (size_t)m->nfaces;
    if (!m->pos && !(m->pos = calloc(1, sizeof *m->pos)))
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s: out of memory", r->name);
    m->vrad = calloc(RAD_BANDS * (nv ? nv : 1), sizeof *m->vrad);
    m->frad = calloc(RAD_BANDS * (nf ? nf : 1), sizeof *m->frad);
    if (!m->vrad || !m->frad)
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s: out of memory for %zu vertices and %zu "
                        "faces", r->name, nv, nf);
    for (int b = 0; b < RAD_BANDS; b++) {
        for (size_t v = 0; v < nv; v++)
            m->vrad[v + b * nv] = s->vband[RAD_BANDS * v + b];
        for (size_t f = 0; f < nf; f++)
            m->frad[f + b * nf] = s->fband[RAD_BANDS * f + b];
    }
    return RAD_OK;
}

/* ---- data ------------------------------------------------------------------ */

static double band_value(source src, double v, ptype t)
{
    if (src == SRC_COLOUR) /* 8-bit (or [0,1] float) sRGB to linear */
        return rad_srgb_decode(is_integer_type(t) ? v / 255.0 : v);
    return v;
}

static rad_status read_vertex(reader *r, ply_state *s, const ply_element *e, size_t i)
{
    rad_render_model *m = &s->m;
    int k = 0;
    char what[48];
    rad_status st0 = vertex_room(r, s, i);
    if (st0)
        return st0;
    snprintf(what, sizeof what, "vertex %zu", i);
    for (int j = 0; j < e->nprops; j++) {
        const ply_prop *p = &e->props[j];
        double v;
        rad_status st;
        if (p->count_type != T_NONE) { /* a list we do not use */
            if ((st = skip_list(r, &k, p, what)))
                return st;
            continue;
        }
        if ((st = get_value(r, k++, p->type, p->name, what, &v)))
            return st;
        switch (p->role) {
        case R_X: m->pos[i].x = v; break;
        case R_Y: m->pos[i].y = v; break;
        case R_Z: m->pos[i].z = v; break;
        case R_RAD:
        case R_COLOUR:
            s->vband[RAD_BANDS * i + (size_t)p->band] = band_value(s->vsrc, v, p->type);
            break;
        default: break;
        }
    }
    if (k < r->ntok)
        return fail_at(r, "unexpected '%s' after the %d properties of %s", r->tok[k],
                       e->nprops, what);
    return RAD_OK;
}

static rad_status read_indices(reader *r, ply_state *s, const ply_prop *p, int *k,
                               const char *what)
{
    rad_render_model *m = &s->m;
    double count, v;
    rad_status st;
    if ((st = get_value(r, (*k)++, p->count_type, p->name, what, &count)))
        return st;
    if (count < 3 || count > MAX_FACE_VERTICES)
        return fail_at(r, "%s has %.0f vertices; a face needs 3 to %d", what, count,
                       MAX_FACE_VERTICES);
    if (count > r->ntok - *k)
        return fail_at(r, "%s lists %.0f vertices but the line holds %d values", what, count,
                       r->ntok - *k);
    const size_t n = (size_t)count;
    if (s->nindex + n > (size_t)INT_MAX)
        return fail_at(r, "too many face vertices in total");
    if (s->nindex + n > s->capindex) {
        size_t cap = 2 * s->capindex > s->nindex + n ? 2 * s->capindex : s->nindex + n;
        int *g = realloc(m->face_index, sizeof *g * cap);
        if (!g)
            return radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory", r->name, r->line);
        m->face_index = g;
        s->capindex = cap;
    }
    for (size_t j = 0; j < n; j++) {
        if ((st = get_value(r, (*k)++, p->type, p->name, what, &v)))
            return st;
        if (v < 0 || v >= m->nvertices)
            return fail_at(r, "%s refers to vertex %.0f; the vertices are 0 to %d", what, v,
                           m->nvertices - 1);
        m->face_index[s->nindex++] = (int)v;
    }
    return RAD_OK;
}

static rad_status read_face(reader *r, ply_state *s, const ply_element *e, size_t i)
{
    rad_render_model *m = &s->m;
    int k = 0, have_indices = 0;
    char what[48];
    rad_status st0 = face_room(r, s, i);
    if (st0)
        return st0;
    snprintf(what, sizeof what, "face %zu", i);
    m->face_first[i] = (int)s->nindex;
    s->face_line[i] = r->line;
    for (int j = 0; j < e->nprops; j++) {
        const ply_prop *p = &e->props[j];
        double v;
        rad_status st;
        if (p->role == R_INDICES && !have_indices) {
            if ((st = read_indices(r, s, p, &k, what)))
                return st;
            have_indices = 1;
            continue;
        }
        if (p->count_type != T_NONE) {
            if ((st = skip_list(r, &k, p, what)))
                return st;
            continue;
        }
        if ((st = get_value(r, k++, p->type, p->name, what, &v)))
            return st;
        if (p->role == R_SURFACE)
            m->face_surface[i] = v >= 0 && v <= INT_MAX ? (int)v : -1;
        else if (p->role == R_EMITS)
            m->face_emits[i] = v != 0;
        else if (p->role == R_RAD || p->role == R_COLOUR)
            s->fband[RAD_BANDS * i + (size_t)p->band] = band_value(s->fsrc, v, p->type);
    }
    if (k < r->ntok)
        return fail_at(r, "unexpected '%s' after the %d properties of %s", r->tok[k],
                       e->nprops, what);
    m->face_first[i + 1] = (int)s->nindex;
    return RAD_OK;
}

static rad_status read_data(reader *r, ply_state *s)
{
    for (int k = 0; k < s->nelem; k++) {
        const ply_element *e = &s->elem[k];
        for (long i = 0; i < e->count; i++) {
            int got = next_nonblank(r);
            if (got < 0)
                return r->status;
            if (got == 0)
                return fail_at(r, "unexpected end of file: element '%s' has %ld of its %ld "
                                  "lines", e->name, i, e->count);
            rad_status st = RAD_OK;
            if (k == s->vertex)
                st = read_vertex(r, s, e, (size_t)i);
            else if (k == s->face)
                st = read_face(r, s, e, (size_t)i);
            if (st)
                return st;
        }
    }
    int got = next_nonblank(r);
    if (got < 0)
        return r->status;
    if (got > 0)
        return fail_at(r, "unexpected data after the last element");
    return RAD_OK;
}

/* ---- after the data -------------------------------------------------------- */

static rad_status check_faces(reader *r, ply_state *s)
{
    const rad_render_model *m = &s->m;
    int maxn = 3;
    for (int f = 0; f < m->nfaces; f++)
        if (m->face_first[f + 1] - m->face_first[f] > maxn)
            maxn = m->face_first[f + 1] - m->face_first[f];
    rad_vec3 *p = malloc(sizeof *p * (size_t)maxn);
    if (!p)
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s: out of memory", r->name);
    rad_status st = RAD_OK;
    for (int f = 0; f < m->nfaces && st == RAD_OK; f++) {
        const int n = m->face_first[f + 1] - m->face_first[f];
        char what[48];
        for (int k = 0; k < n; k++)
            p[k] = m->pos[m->face_index[m->face_first[f] + k]];
        snprintf(what, sizeof what, "face %d", f);
        st = radi_polygon_check(p, n, what, r->name, s->face_line[f], r->err);
    }
    free(p);
    return st;
}

/* Fill the band values the file did not give, from the other kind. */
static rad_status fill_missing(reader *r, ply_state *s)
{
    rad_render_model *m = &s->m;
    const size_t nv = (size_t)m->nvertices, nf = (size_t)m->nfaces;
    if (s->fsrc == SRC_NONE) /* face: mean of its vertices */
        for (size_t f = 0; f < nf; f++) {
            const int a = m->face_first[f], n = m->face_first[f + 1] - a;
            for (int b = 0; b < RAD_BANDS; b++) {
                double sum = 0;
                for (int k = 0; k < n; k++)
                    sum += m->vrad[(size_t)m->face_index[a + k] + b * nv];
                m->frad[f + b * nf] = sum / n;
            }
        }
    if (s->vsrc == SRC_NONE) { /* vertex: mean of its faces */
        int *count = calloc(nv ? nv : 1, sizeof *count);
        if (!count)
            return radi_fail(r->err, RAD_ERR_NOMEM, "%s: out of memory", r->name);
        for (size_t f = 0; f < nf; f++)
            for (int k = m->face_first[f]; k < m->face_first[f + 1]; k++) {
                const size_t v = (size_t)m->face_index[k];
                count[v]++;
                for (int b = 0; b < RAD_BANDS; b++)
                    m->vrad[v + b * nv] += m->frad[f + b * nf];
            }
        for (size_t v = 0; v < nv; v++)
            for (int b = 0; b < RAD_BANDS; b++)
                m->vrad[v + b * nv] /= count[v] > 0 ? count[v] : 1;
        free(count);
    }
    return RAD_OK;
}

/* Parse what r reads into *model (and *camera); on failure both empty. */
static rad_status parse_ply(rad_render_model *model, rad_camera *camera, reader *r)
{
    ply_state *s = calloc(1, sizeof *s);
    rad_status st;
    memset(model, 0, sizeof *model);
    if (camera)
        memset(camera, 0, sizeof *camera);
    if (!s)
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s: out of memory", r->name);
    if (!(st = parse_header(r, s)) && !(st = check_header(r, s)) &&
        !(st = alloc_model(r, s)) && !(st = read_data(r, s)) && !(st = finish_model(r, s)) &&
        !(st = check_faces(r, s)))
        st = fill_missing(r, s);
    free(s->face_line);
    free(s->vband);
    free(s->fband);
    if (st) {
        rad_render_model_free(&s->m);
    } else {
        *model = s->m;
        if (camera)
            *camera = s->camera;
    }
    free(s);
    return st;
}

rad_status rad_ply_parse(rad_render_model *model, rad_camera *camera, const char *text,
                         size_t len, const char *name, rad_error *err)
{
    reader r;
    radi_lines_mem(&r, text, len, name ? name : "-", '\0', err);
    rad_status st = parse_ply(model, camera, &r);
    radi_lines_close(&r);
    return st;
}

rad_status rad_ply_read(rad_render_model *model, rad_camera *camera, const char *path,
                        rad_error *err)
{
    reader r;
    memset(model, 0, sizeof *model);
    if (camera)
        memset(camera, 0, sizeof *camera);
    rad_status st = radi_lines_open(&r, path, '\0', err);
    if (st == RAD_OK)
        st = parse_ply(model, camera, &r);
    radi_lines_close(&r);
    return st;
}
