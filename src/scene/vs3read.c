/* vs3read.c -- View3D 3.x input (.vs3).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A scene file whose name ends in .vs3 is read here, so that a View3D
 * user's input runs unchanged through `radiosity formfactor`.  The format
 * is the one of G. N. Walton's View3D 3.2/3.3 (NISTIR 6925; "View3D User
 * Manual", section "Input File Format", geometry F 3): a line's kind is
 * the first character of its first word, in either case.  What it maps
 * (radiosity-scene(5), VIEW3D, says the same for users):
 *   T   title: ignored;
 *   C   control, NAME=VALUE pairs (eps maxU maxO minO row col encl emit
 *       out list prjD maxV): checked, then ignored -- the accuracy here is
 *       --accuracy's, every factor is computed, none is adjusted to close
 *       an enclosure, and factors are black (emit=1's Hottel script-F is
 *       not computed);
 *   F   geometry: 3 (vertices and surfaces); 3a (BLAST shapes) is refused;
 *   V   N X Y Z: vertex N, numbered 1, 2, ... in order;
 *   S   N V1 V2 V3 V4 BASE CMB EMIT [NAME]: surface N, a triangle when V4
 *       is 0, else a quad (so --mesh applies); counter-clockwise seen from
 *       its front, which is View3D's active side too.  EMIT, the
 *       emissivity e from 0 to 1, becomes a grey material of reflectance
 *       1 - e without emission (one material per value).  BASE must be 0:
 *       subsurfaces are refused.  CMB > 0 combines the surface with the
 *       earlier surface CMB, checked as View3D checks it (CMB < N, and CMB
 *       itself combines with none: no chains) and kept as the surface's
 *       `combine` (CMB - 1, the scene's index of S CMB; -1 for CMB = 0):
 *       the reported form factors then have one row and column for the
 *       union, as View3D's Combine (viewpp.c) makes them -- interchange
 *       areas A F added, areas summed (rad_mesh_reported, mesh.h).  The
 *       surfaces are still meshed, lit and solved apart.  NAME is not
 *       kept;
 *   O   N V1 V2 V3 V4 ...: an obstruction-only surface, after every S: a
 *       black surface (reflectance 0, no emission) that blocks like any
 *       other, flagged `obstruction`, so that `formfactor` and `compare`
 *       leave its rows and columns out as View3D does;
 *   X   coordinate transformation: ignored, as View3D 3.3 ignores it in F 3;
 *   E, *  end of data: nothing after it is read;
 *   !   a comment to the end of the line; a line whose first word starts
 *       with / is a comment too, and so is the rest of a V, S or O line
 *       from a word starting with /.
 * M and N (masking and null surfaces) are refused, and so is every other
 * first character.  Words are separated by white space, as View3D's; a
 * comma, which View3D also accepts, is refused with a word on why.
 */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "scene/vs3read.h"
#include "util/util.h"
#include "scene/polycheck.h"
#include "scene/scenebuild.h"

typedef struct vs3_state {
    rad_scene_build b;
    rad_lines *r;
    rad_vec3 *v;                /* vertices 1..nv at v[0..nv) */
    long nv, vcap;
    long nsurf;                 /* S and O surfaces so far */
    int *cmb;                   /* CMB of each S surface, for the chain test */
    long cmbcap;
    int obstructions;           /* an O surface has been read */
    int obstruction_material;   /* its index, or -1 */
} vs3_state;

/* RAD_ERR_NOMEM at the current line. */
static rad_status no_memory(const rad_lines *r)
{
    return radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory", r->name, r->line);
}

/* Tokens from k on must be absent or start a '/' comment. */
static rad_status rest_is_comment(const rad_lines *r, int k, const char *after)
{
    if (k < r->ntok && r->tok[k][0] != '/')
        return radi_lines_fail(r, "unexpected '%s' after %s", r->tok[k], after);
    return RAD_OK;
}

/* A comma in a data word: say why it is refused. */
static rad_status no_commas(const rad_lines *r)
{
    for (int k = 0; k < r->ntok && r->tok[k][0] != '/'; k++)
        if (strchr(r->tok[k], ','))
            return radi_lines_fail(r, "'%s' holds a comma; separate View3D words with blanks",
                                  r->tok[k]);
    return RAD_OK;
}

/* ---- control and geometry lines ---------------------------------------------- */

static rad_status control_value(const rad_lines *r, const char *name, const char *value)
{
    static const char *const ints[] = {"maxU", "maxO", "minO", "row", "col", "encl",
                                       "emit", "out", "list", "prjD", "maxV", NULL};
    long unused;
    if (strcasecmp(name, "eps") == 0) {
        char *end;
        double e = strtod(value, &end);
        if (end == value || *end || !(e > 0 && e < 1))
            return radi_lines_fail(r, "eps must be a number between 0 and 1, not '%s'", value);
        return RAD_OK;
    }
    for (int k = 0; ints[k]; k++)
        if (strcasecmp(name, ints[k]) == 0)
            return radi_tok_long(r, value, name, -2147483647L, 2147483647L, &unused);
    return radi_lines_fail(r, "unknown control word '%s' (eps, maxU, maxO, minO, row, col, "
                             "encl, emit, out, list, prjD or maxV)", name);
}

/* C NAME=VALUE ...: words split at blanks and '=', then taken in pairs. */
static rad_status vs3_control(const rad_lines *r)
{
    const char *name = NULL;
    for (int k = 1; k < r->ntok; k++) {
        char *w = r->tok[k], *eq;
        do {
            eq = strchr(w, '=');
            if (eq)
                *eq = '\0';
            if (*w) {
                if (!name) {
                    name = w;
                } else {
                    rad_status st = control_value(r, name, w);
                    if (st)
                        return st;
                    name = NULL;
                }
            }
            w = eq ? eq + 1 : NULL;
        } while (w);
    }
    if (name)
        return radi_lines_fail(r, "control word '%s' has no value", name);
    return RAD_OK;
}

static rad_status vs3_format(const rad_lines *r)
{
    if (r->ntok < 2)
        return radi_lines_fail(r, "F needs the geometry format (3)");
    if (strcasecmp(r->tok[1], "3a") == 0)
        return radi_lines_fail(r, "geometry format 3a (BLAST surfaces) is not supported; "
                                 "give vertices and surfaces (F 3)");
    if (strcmp(r->tok[1], "3") != 0)
        return radi_lines_fail(r, "geometry format '%s' is not supported (only F 3)",
                              r->tok[1]);
    return rest_is_comment(r, 2, "the geometry format");
}

static rad_status vs3_vertex(vs3_state *s)
{
    rad_lines *r = s->r;
    long n;
    rad_vec3 p;
    rad_status st;
    if (r->ntok < 2)
        return radi_lines_fail(r, "V needs a vertex number and X Y Z");
    if ((st = radi_tok_long(r, r->tok[1], "vertex number", 1, 2147483647L, &n)))
        return st;
    if (n != s->nv + 1)
        return radi_lines_fail(r, "vertex %ld out of sequence (expected %ld)", n, s->nv + 1);
    if ((st = radi_tok_vec(r, 2, "vertex", &p)) || (st = rest_is_comment(r, 5, "X Y Z")))
        return st;
    if (s->nv == s->vcap) {
        long ncap = s->vcap ? 2 * s->vcap : 256;
        rad_vec3 *g = realloc(s->v, sizeof *g * (size_t)ncap);
        if (!g)
            return no_memory(r);
        s->v = g;
        s->vcap = ncap;
    }
    s->v[s->nv++] = p;
    return RAD_OK;
}

/* ---- surfaces ---------------------------------------------------------------- */

/* The material of emissivity e (reflectance 1 - e), made on first use. */
static rad_status emissivity_material(vs3_state *s, double e, int *out)
{
    rad_material m;
    memset(&m, 0, sizeof m);
    snprintf(m.name, sizeof m.name, "emissivity %.17g", e);
    if ((*out = radi_build_find_material(&s->b, m.name)) >= 0)
        return RAD_OK;
    m.reflect[0] = m.reflect[1] = m.reflect[2] = 1.0 - e;
    m.line = s->r->line;
    *out = s->b.s.nmaterials;
    return radi_build_add_material(&s->b, &m, s->r->name, s->r->line);
}

static rad_status obstruction_material(vs3_state *s, int *out)
{
    if (s->obstruction_material < 0) {
        rad_material m;
        memset(&m, 0, sizeof m);
        strcpy(m.name, "obstruction");
        m.line = s->r->line;
        s->obstruction_material = s->b.s.nmaterials;
        rad_status st = radi_build_add_material(&s->b, &m, s->r->name, s->r->line);
        if (st)
            return st;
    }
    *out = s->obstruction_material;
    return RAD_OK;
}

/* BASE, CMB and EMIT of surface n (tokens 6, 7, 8); its material in *mat. */
static rad_status surface_data(vs3_state *s, long n, int *mat)
{
    rad_lines *r = s->r;
    long base, cmb;
    double e;
    rad_status st;
    if ((st = radi_tok_long(r, r->tok[6], "base surface", 0, n, &base)))
        return st;
    if (base != 0)
        return radi_lines_fail(r, "surface %ld is a subsurface of %ld; subsurfaces are not "
                                 "supported (give the base surface's remainder as surfaces)",
                              n, base);
    if ((st = radi_tok_long(r, r->tok[7], "combine surface", 0, n - 1, &cmb)))
        return st;
    if (cmb > 0 && s->cmb[cmb - 1] != 0)
        return radi_lines_fail(r, "surface %ld combines with %ld, which itself combines with "
                                 "%d (View3D does not chain combinations)",
                              n, cmb, s->cmb[cmb - 1]);
    s->cmb[n - 1] = (int)cmb;
    if ((st = radi_tok_number(r, 8, "emissivity", &e)))
        return st;
    if (!(e >= 0 && e <= 1))
        return radi_lines_fail(r, "emissivity must be from 0 to 1, not %s", r->tok[8]);
    if ((st = rest_is_comment(r, 10, "the surface name")))
        return st;
    return emissivity_material(s, e, mat);
}

/* S or O: the surface's number and vertices, then its data. */
static rad_status vs3_surface(vs3_state *s, int obstruction)
{
    rad_lines *r = s->r;
    long n, idx[4];
    int mat = -1, nv;
    rad_status st;
    if (r->ntok < (obstruction ? 6 : 9))
        return radi_lines_fail(r, "%c needs N V1 V2 V3 V4%s", obstruction ? 'O' : 'S',
                              obstruction ? "" : " BASE CMB EMIT");
    if ((st = radi_tok_long(r, r->tok[1], "surface number", 1, 2147483647L, &n)))
        return st;
    if (n != s->nsurf + 1)
        return radi_lines_fail(r, "surface %ld out of sequence (expected %ld)", n, s->nsurf + 1);
    if (!obstruction && s->obstructions)
        return radi_lines_fail(r, "surface %ld follows an obstruction surface; every S comes "
                                 "before the O surfaces", n);
    for (int k = 0; k < 4; k++) {
        char what[32];
        snprintf(what, sizeof what, "vertex %d of the surface", k + 1);
        if ((st = radi_tok_long(r, r->tok[2 + k], what, k == 3 ? 0 : 1, s->nv, &idx[k])))
            return s->nv == 0 ? radi_lines_fail(r, "surface %ld before any vertex", n) : st;
    }
    nv = idx[3] == 0 ? 3 : 4;
    if (!obstruction) {
        if (n > s->cmbcap) {
            long ncap = s->cmbcap ? 2 * s->cmbcap : 256;
            int *g = realloc(s->cmb, sizeof *g * (size_t)ncap);
            if (!g)
                return no_memory(r);
            s->cmb = g;
            s->cmbcap = ncap;
        }
        st = surface_data(s, n, &mat);
    } else {
        s->obstructions = 1;
        st = obstruction_material(s, &mat);
    }
    if (st)
        return st;
    rad_vec3 *v = malloc(sizeof *v * 4);
    if (!v)
        return no_memory(r);
    for (int k = 0; k < nv; k++)
        v[k] = s->v[idx[k] - 1];
    if ((st = radi_polygon_check(v, nv, obstruction ? "obstruction surface" : "surface",
                                r->name, r->line, r->err))) {
        free(v);
        return st;
    }
    s->nsurf = n;
    st = radi_build_add_surface(&s->b, r->line, nv == 4 ? RAD_SURFACE_QUAD : RAD_SURFACE_POLYGON,
                                mat, -1, v, nv, 1, 1);
    if (st == RAD_OK) {
        rad_surface *f = &s->b.s.surfaces[s->b.s.nsurfaces - 1];
        f->obstruction = obstruction;
        /* S surfaces are the scene's first, in order: S k is surface k - 1 */
        f->combine = obstruction || s->cmb[n - 1] == 0 ? -1 : s->cmb[n - 1] - 1;
    }
    return st;
}

/* ---- lines --------------------------------------------------------------------- */

/* One line; 1 at the end of data. */
static rad_status vs3_line(vs3_state *s, int *end)
{
    rad_lines *r = s->r;
    const char c = r->tok[0][0];
    rad_status st;
    switch (c) {
    case '/': case 'T': case 't': case 'X': case 'x':
        return RAD_OK;
    case 'E': case 'e': case '*':
        *end = 1;
        return RAD_OK;
    default:
        break;
    }
    if ((st = radi_lines_ascii(r, 0)) || (st = no_commas(r)))
        return st;
    switch (c) {
    case 'C': case 'c':
        return vs3_control(r);
    case 'F': case 'f':
        return vs3_format(r);
    case 'V': case 'v':
        return vs3_vertex(s);
    case 'S': case 's':
        return vs3_surface(s, 0);
    case 'O': case 'o':
        return vs3_surface(s, 1);
    case 'M': case 'm': case 'N': case 'n':
        return radi_lines_fail(r, "%s surfaces (%c) are not supported",
                              c == 'M' || c == 'm' ? "masking" : "null", c);
    default:
        return radi_lines_fail(r, "unknown View3D line '%s' (expected T, C, F, V, S, O or "
                                 "End)", r->tok[0]);
    }
}

rad_status radi_vs3_read(rad_scene *scene, rad_lines *r)
{
    vs3_state s;
    int got, end = 0;
    memset(&s, 0, sizeof s);
    s.r = r;
    s.obstruction_material = -1;
    rad_status st = radi_build_start(&s.b, r->name, r->err);
    while (st == RAD_OK && !end && (got = radi_lines_next(r)) != 0) {
        if (got < 0)
            st = r->status;
        else if (r->ntok > 0)
            st = vs3_line(&s, &end);
    }
    if (st == RAD_OK && s.b.s.nsurfaces == 0)
        st = radi_lines_fail(r, "the View3D file has no surfaces (S lines)");
    free(s.v);
    free(s.cmb);
    return radi_build_finish(&s.b, st, scene);
}
