/* test_objread.c -- the Wavefront OBJ + MTL reader: what it maps, and every
 * error message.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Inputs are parsed from memory through radi_obj_read with the MTL text
 * given beside them (the reader's test and fuzzing path), so nothing is
 * read from disk; tests/commands/readers.sh runs mtllib files on disk.  Expected
 * values are those written in the input (vertices are copied, not
 * computed, so they must come back bit for bit), and each bad input must
 * fail with RAD_ERR_PARSE, a message starting "FILE:LINE: " for the file
 * and line at fault, and an empty scene.
 */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "scene/objread.h"
#include "util/readfile.h"
#include "../tap.h"

static const char *MTL = "# materials\n"
                         "newmtl white\nKd 0.5\nKa 1 1 1\nKs 0 0 0\nNs 10\nillum 2\n"
                         "map_Kd white.png\nd 1\n\n"
                         "newmtl lamp\nKd 0.25 0.5 0.75\nKe 1 2 3\n";

static const char *SQUARE = "mtllib t.mtl\n"
                            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

/* Read obj (its mtllib reading mtl) with `flags`; the checks below that
 * expect refusals read strictly (RAD_SCENE_STRICT refuses every repair),
 * repairs() reads as the program does by default. */
static rad_status parse_flags(rad_scene *s, const char *obj, const char *mtl, unsigned flags,
                              rad_error *err)
{
    rad_lines r;
    memset(err, 0, sizeof *err);
    radi_lines_mem(&r, obj, strlen(obj), "t.obj", '#', err);
    rad_status st = radi_obj_read(s, &r, mtl, strlen(mtl), flags);
    radi_lines_close(&r);
    return st;
}

static rad_status parse(rad_scene *s, const char *obj, const char *mtl, rad_error *err)
{
    return parse_flags(s, obj, mtl, RAD_SCENE_STRICT, err);
}

static void bad_in(const char *obj, const char *mtl, const char *file, int line,
                   const char *reason)
{
    rad_scene s;
    rad_error err;
    char want[64];
    rad_status st = parse(&s, obj, mtl, &err);
    snprintf(want, sizeof want, "%s:%d: ", file, line);
    int ok = st == RAD_ERR_PARSE && strncmp(err.message, want, strlen(want)) == 0 &&
             strstr(err.message, reason) != NULL && s.nsurfaces == 0 && s.nobjects == 0 &&
             s.materials == NULL;
    tap_ok(ok, "rejects (%s): \"%s\"", reason, err.message);
    rad_scene_free(&s);
}

static void bad(const char *obj, int line, const char *reason)
{
    bad_in(obj, MTL, "t.obj", line, reason);
}

static void bad_mtl(const char *mtl, int line, const char *reason)
{
    char obj[256];
    snprintf(obj, sizeof obj, "%susemtl white\nf 1 2 3 4\n", SQUARE);
    bad_in(obj, mtl, "t.mtl", line, reason);
}

static int same(rad_vec3 a, double x, double y, double z)
{
    return a.x == x && a.y == y && a.z == z;
}

/* The four index forms, and negative indices, name the same corners. */
static void index_forms(void)
{
    static const char *const faces[] = {
        "f 1 2 3 4\n", "f 1/1 2/2 3/3 4/4\n", "f 1//1 2//1 3//1 4//1\n",
        "f 1/1/1 2/2/1 3/3/1 4/4/1\n", "f -4 -3 -2 -1\n", "f -4/-4/-1 2/-3 3//-1 -1\n"};
    for (size_t k = 0; k < sizeof faces / sizeof *faces; k++) {
        char obj[512];
        rad_scene s;
        rad_error err;
        snprintf(obj, sizeof obj, "%svt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                 "usemtl white\n%s", SQUARE, faces[k]);
        rad_status st = parse(&s, obj, MTL, &err);
        int ok = st == RAD_OK && s.nsurfaces == 1 && s.surfaces[0].nverts == 4 &&
                 s.surfaces[0].kind == RAD_SURFACE_QUAD &&
                 same(s.surfaces[0].verts[0], 0, 0, 0) && same(s.surfaces[0].verts[1], 1, 0, 0) &&
                 same(s.surfaces[0].verts[2], 1, 1, 0) && same(s.surfaces[0].verts[3], 0, 1, 0);
        tap_ok(ok, "face '%.*s' is the unit square, a quad (%s)", (int)strlen(faces[k]) - 1,
               faces[k], st ? err.message : "ok");
        rad_scene_free(&s);
    }
}

/* Negative indices count back from the last vertex read at that line. */
static void relative_indices(void)
{
    const char *obj = "mtllib t.mtl\nusemtl white\n"
                      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
                      "v 0 0 1\nv 0 1 1\nv 1 0 1\nf -3 -2 -1\n";
    rad_scene s;
    rad_error err;
    rad_status st = parse(&s, obj, MTL, &err);
    tap_ok(st == RAD_OK && s.nsurfaces == 2 && s.surfaces[0].kind == RAD_SURFACE_POLYGON &&
               same(s.surfaces[0].verts[2], 0, 1, 0) && same(s.surfaces[1].verts[0], 0, 0, 1) &&
               same(s.surfaces[1].verts[2], 1, 0, 1),
           "negative indices are relative to the vertices read so far (%s)",
           st ? err.message : "ok");
    rad_scene_free(&s);
}

/* Materials: Kd grey and RGB, Ke, the default; kinds and the mesh. */
static void materials_and_kinds(void)
{
    char obj[1024];
    rad_scene s;
    rad_error err;
    snprintf(obj, sizeof obj,
             "%sf 1 2 3\nusemtl lamp\nf 1 2 3 4\nusemtl white\ns 1\n"
             "v 2 0 0\nv 3 0 0\nv 3.5 1 0\nv 2.5 2 0\nv 1.5 1 0\nf 5 6 7 8 9\n"
             "l 1 2\np 1\nvp 0.5\n", SQUARE);
    rad_status st = parse(&s, obj, MTL, &err);
    tap_ok(st == RAD_OK && s.nsurfaces == 3, "triangle, quad and pentagon read (%s)",
           st ? err.message : "ok");
    if (st)
        return;
    const rad_material *m0 = &s.materials[s.surfaces[0].material];
    const rad_material *m1 = &s.materials[s.surfaces[1].material];
    const rad_material *m2 = &s.materials[s.surfaces[2].material];
    tap_ok(strcmp(m0->name, "(no material)") == 0 && m0->reflect[0] == 0 &&
               m0->reflect[2] == 0 && m0->emit[1] == 0,
           "a face before any usemtl is black and dark ('%s')", m0->name);
    tap_ok(strcmp(m1->name, "lamp") == 0 && m1->reflect[0] == 0.25 && m1->reflect[1] == 0.5 &&
               m1->reflect[2] == 0.75 && m1->emit[0] == 1 && m1->emit[1] == 2 &&
               m1->emit[2] == 3,
           "Kd R G B is the reflectance and Ke R G B the emission");
    tap_ok(strcmp(m2->name, "white") == 0 && m2->reflect[0] == 0.5 && m2->reflect[1] == 0.5 &&
               m2->reflect[2] == 0.5 && m2->emit[0] == 0,
           "Kd V is grey; no Ke is no emission; Ka, Ks, Ns, illum, map_Kd, d ignored");
    tap_ok(s.surfaces[0].kind == RAD_SURFACE_POLYGON && s.surfaces[0].nverts == 3 &&
               s.surfaces[1].kind == RAD_SURFACE_QUAD &&
               s.surfaces[2].kind == RAD_SURFACE_POLYGON && s.surfaces[2].nverts == 5,
           "4 corners make a quad, 3 and 5 a polygon");
    tap_ok(s.surfaces[0].line == 6 && s.surfaces[1].line == 8 && s.surfaces[2].line == 16,
           "surfaces remember their lines (%d %d %d)", s.surfaces[0].line, s.surfaces[1].line,
           s.surfaces[2].line);
    rad_scene_set_mesh(&s, 3, 2);
    tap_ok(s.surfaces[1].mesh_n == 3 && s.surfaces[1].mesh_m == 2 &&
               s.surfaces[0].mesh_n == 3 && s.surfaces[0].mesh_m == 3 &&
               s.surfaces[2].mesh_n == 3 && s.surfaces[2].mesh_m == 3,
           "--mesh 3x2 applies to every face: the quad 3 x 2, triangle and 5-gon 3 per edge");
    rad_scene_free(&s);
}

/* o and g make objects; g without a name returns to the environment. */
static void groups(void)
{
    char obj[1024];
    rad_scene s;
    rad_error err;
    snprintf(obj, sizeof obj,
             "%susemtl white\nf 1 2 3\no box\nf 1 2 3\ng side top\nf 1 2 3\n"
             "g\nf 1 2 3\ng box\nf 1 2 3\n", SQUARE);
    rad_status st = parse(&s, obj, MTL, &err);
    int ok = st == RAD_OK && s.nsurfaces == 5 && s.nobjects == 2;
    tap_ok(ok, "two objects (%s)", st ? err.message : "ok");
    if (!ok) {
        rad_scene_free(&s);
        return;
    }
    tap_ok(strcmp(s.objects[0].name, "box") == 0 && s.objects[0].line == 8 &&
               !s.objects[0].absent && strcmp(s.objects[1].name, "side") == 0,
           "o box, then g side top: objects 'box' (line 8) and 'side' (first name)");
    tap_ok(s.surfaces[0].object == -1 && s.surfaces[1].object == 0 &&
               s.surfaces[2].object == 1 && s.surfaces[3].object == -1 &&
               s.surfaces[4].object == 0,
           "faces before any group and after a bare g are the environment; a name again "
           "adds to its object");
    rad_scene_free(&s);
}

/* mtllib: the in-memory library is read once, whatever the names. */
static void mtllib_once(void)
{
    char obj[512];
    rad_scene s;
    rad_error err;
    snprintf(obj, sizeof obj, "%smtllib t.mtl other.mtl\nusemtl lamp\nf 1 2 3 4\n", SQUARE);
    rad_status st = parse(&s, obj, MTL, &err);
    tap_ok(st == RAD_OK && s.nmaterials == 2, "a second mtllib defines nothing twice (%s)",
           st ? err.message : "ok");
    rad_scene_free(&s);
}

static void errors(void)
{
    char buf[1024];
#define WITH(tail) (snprintf(buf, sizeof buf, "%susemtl white\n%s", SQUARE, tail), buf)
    bad(WITH("f 1 2\n"), 7, "a face needs at least 3 corners, not 2");
    bad(WITH("f 0 1 2\n"), 7, "vertex index 0");
    bad(WITH("f 1 2 5\n"), 7, "vertex index 5, but 4 have been read");
    bad(WITH("f 1 2 -5\n"), 7, "vertex index -5, but 4 have been read");
    bad(WITH("f 1/1 2/1 3/1\n"), 7, "texture vertex index 1, but 0 have been read");
    bad(WITH("vn 0 0 1\nf 1//2 2//1 3//1\n"), 8, "normal index 2, but 1 has been read");
    bad(WITH("f 1/ 2 3\n"), 7, "'' is not a whole number (texture vertex)");
    bad(WITH("f 1/1/1/1 2 3\n"), 7, "more than 3 parts");
    bad(WITH("f 1 2 x\n"), 7, "'x' is not a whole number (vertex)");
    bad(WITH("f 1 2 3 4 1\n"), 7, "face has a repeated vertex");
    bad(WITH("f 1 3 2 4\n"), 7, "face is self-intersecting");
    bad(WITH("v 0.5 0.2 0\nf 1 2 5 3 4\n"), 8, "face is not convex");
    bad(WITH("v 0 1 1\nf 1 2 3 5\n"), 8, "face is not planar");
    bad(WITH("f 1 2 2\n"), 7, "repeated vertex");
    bad(WITH("v 1 2\n"), 7, "v takes X Y Z [W] or X Y Z R G B, not 2 numbers");
    bad(WITH("v 1 2 nan\n"), 7, "vertex must be finite");
    bad(WITH("v 1 2 3abc\n"), 7, "'3abc' is not a number (vertex)");
    bad(WITH("usemtl brass\n"), 7, "undefined material 'brass'");
    bad(WITH("usemtl\n"), 7, "usemtl needs a name");
    bad(WITH("o two words\n"), 7, "o takes one object name");
    bad(WITH("surf 0 1 0 1 1 2 3\n"), 7, "free-form geometry ('surf')");
    bad(WITH("call other.obj\n"), 7, "unknown OBJ statement 'call'");
    bad(WITH("F 1 2 3\n"), 7, "unknown OBJ statement 'F'");
    bad(WITH("mtllib\n"), 7, "mtllib needs a file name");
    snprintf(buf, sizeof buf, "%smtllib %0256d\n", SQUARE, 0);
    bad(buf, 6, "mtllib file name is longer than 255 bytes");
    bad(WITH("f 1 2 3 \033\n"), 7, "control character");
    bad("# nothing\n", 1, "the OBJ file has no faces");
    bad("v 0 0 0\n\n", 2, "the OBJ file has no faces");
    snprintf(buf, sizeof buf, "%susemtl white\no %064d\nf 1 2 3\n", SQUARE, 0);
    bad(buf, 7, "object name is longer than 63 characters");
#undef WITH
    bad_mtl("newmtl white\nKd 1.5\n", 2, "Kd (reflectance) must be from 0 to 1, not 1.5");
    bad_mtl("newmtl white\nKd 0.5 0.5\n", 2, "Kd (reflectance) takes 1 value (grey) or 3");
    bad_mtl("newmtl white\nKd 0.5\nKe -1\n", 3, "Ke (emission) must not be negative");
    bad_mtl("newmtl white\nKd spectral white.rfl\n", 2, "Kd spectral is not supported");
    bad_mtl("newmtl white\nKe 1\n", 1, "material 'white' has no Kd");
    bad_mtl("Kd 0.5\nnewmtl white\n", 1, "Kd before any newmtl");
    bad_mtl("newmtl white\nKd 0.5\nnewmtl white\nKd 0.5\n", 3, "'white' is already defined");
    bad_mtl("newmtl white\nKd 0.5\nglow 1\n", 3, "unknown MTL statement 'glow'");
    bad_mtl("newmtl a b\n", 1, "newmtl takes one name");
}

/* The sum of the surfaces' areas (Newell), for the cut faces. */
static double total_area(const rad_scene *s)
{
    double a = 0;
    for (int k = 0; k < s->nsurfaces; k++) {
        const rad_surface *f = &s->surfaces[k];
        rad_vec3 n = {0, 0, 0};
        for (int v = 0; v < f->nverts; v++) {
            const rad_vec3 p = f->verts[v], q = f->verts[(v + 1) % f->nverts];
            n.x += p.y * q.z - p.z * q.y;
            n.y += p.z * q.x - p.x * q.z;
            n.z += p.x * q.y - p.y * q.x;
        }
        a += 0.5 * sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    }
    return a;
}

/* Read without RAD_SCENE_STRICT: the repairs importers make, each
 * counted; what is not repairable still refused. */
static void repairs(void)
{
    rad_scene s;
    rad_error err;
    const char *mtl = "newmtl Hard Shiny  White\nKd 0.8\nnewmtl Terrain\xe6k\nKd 0.3\n";
    /* an undefined material, names with spaces and Latin-1, a face whose
     * corners coincide, a corner written twice in a row */
    const char *obj = "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                      "usemtl Default\nf 1 2 3 4\nusemtl  Hard Shiny White \nf 1 2 3\n"
                      "usemtl Terrain\xe6k\nf 1 3 4\nf 1 1 1\nf 1 2 2 3 4\n";
    rad_status st = parse_flags(&s, obj, mtl, 0, &err);
    const rad_scene_repairs *p = &s.repairs;
    int grey = st == RAD_OK ? s.surfaces[0].material : -1;
    tap_ok(st == RAD_OK && s.nsurfaces == 5 && grey >= 0 &&
               strcmp(s.materials[grey].name, RAD_DEFAULT_GREY) == 0 &&
               s.materials[grey].reflect[1] == 0.5 && p->undefined_materials == 1 &&
               p->first_line[0] == 7 && p->spaced_names == 4 && p->degenerate_faces == 1 &&
               p->first_line[2] == 12 && p->split_faces == 1 && p->split_triangles == 2,
           "repairs: default grey for 'Default' (line %d), %d names taken as written, %d face "
           "left out (line %d), %d face with a repeated corner cut into %d triangles (%s)",
           p->first_line[0], p->spaced_names, p->degenerate_faces, p->first_line[2],
           p->split_faces, p->split_triangles, st ? err.message : "ok");
    tap_ok(st == RAD_OK && s.nsurfaces == 5 &&
               strcmp(s.materials[s.surfaces[1].material].name, "Hard Shiny White") == 0 &&
               strcmp(s.materials[s.surfaces[2].material].name, "Terrain\xe6k") == 0,
           "names with spaces match their newmtl, runs of spaces as one; Latin-1 byte for byte");
    rad_scene_free(&s);

    /* not planar (a quad folded by 0.01), not convex (an L of area 3), an
     * outline run round twice: cut into triangles of the same area, in
     * the plane of the cut */
    const char *cut = "mtllib t.mtl\nusemtl white\n"
                      "v 0 0 0\nv 1 0 0\nv 1 1 0.01\nv 0 1 0\nf 1 2 3 4\n"
                      "v 0 0 1\nv 2 0 1\nv 2 1 1\nv 1 1 1\nv 1 2 1\nv 0 2 1\n"
                      "f 5 6 7 8 9 10\n"
                      "f 1 2 4 1 2 4\n";
    st = parse_flags(&s, cut, MTL, 0, &err);
    /* the folded quad: two triangles of areas 0.5 * sqrt(1 + 0.01^2) and 0.5 (one holds the
     * fold, one is flat: which depends on the diagonal), or both tilted */
    double fold = 0;
    for (int k = 0; st == RAD_OK && k < 2; k++) {
        rad_scene one = s;
        one.surfaces = s.surfaces + k;
        one.nsurfaces = 1;
        fold += total_area(&one);
    }
    const double l_area = st == RAD_OK ? total_area(&s) - fold - 0.5 : 0;
    tap_ok(st == RAD_OK && s.repairs.split_faces == 3 && s.nsurfaces == 2 + 4 + 1 &&
               fabs(l_area - 3) < 1e-12 && fold > 1 - 1e-12 && fold < 1 + 1e-4,
           "a folded quad (2 triangles, area %.12g), an L (4 triangles, area %.15g, 3 by "
           "its sides), a face run round twice (once: area 0.5): all cut (%s)", fold, l_area,
           st ? err.message : "ok");
    for (int k = 0; st == RAD_OK && k < s.nsurfaces; k++) {
        const rad_surface *f = &s.surfaces[k];
        const rad_vec3 a = f->verts[0], b = f->verts[1], c = f->verts[2];
        const double nz = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (!(f->nverts == 3 && nz > 0)) {
            tap_ok(0, "triangle %d faces as its face did (+z)", k);
            st = RAD_ERR_INVALID;
        }
    }
    tap_ok(st == RAD_OK, "every triangle faces as its face did (+z)");
    rad_scene_free(&s);

    /* a bow tie of unequal loops crosses itself (at (2/3, 2/3)): no
     * triangles cover it, refused */
    const char *tie = "mtllib t.mtl\nusemtl white\nv 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 2 0\n"
                      "f 1 2 3 4\n";
    st = parse_flags(&s, tie, MTL, 0, &err);
    tap_ok(st == RAD_ERR_PARSE && strstr(err.message, "t.obj:7: face is self-intersecting"),
           "a bow tie is refused even with repairs: %s", err.message);
    rad_scene_free(&s);

    /* what cannot be repaired, still refused: a 5-gon whose edges cross
     * (not a bow tie: its area does not cancel), a symmetric bow tie (its
     * loops cancel), a square 1e-160 across (outside the sizes accepted);
     * and an L 0.02 across at (1000, 1000), which is repaired: the cut
     * works in coordinates relative to a corner */
    static const struct {
        const char *obj, *want;
    } hard[] = {
        {"v 2 5 0\nv 2 3 0\nv 5 6 0\nv 1 4 0\nv 4 5 0\nf 1 2 3 4 5\n", "self-intersecting"},
        {"v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n", "self-intersecting"},
        {"v 0 0 0\nv 1e-160 0 0\nv 1e-160 1e-160 0\nv 0 1e-160 0\nf 1 2 3 4\n", "outside the sizes"},
    };
    for (size_t k = 0; k < sizeof hard / sizeof *hard; k++) {
        char text[512];
        snprintf(text, sizeof text, "mtllib t.mtl\nusemtl white\n%s", hard[k].obj);
        st = parse_flags(&s, text, MTL, 0, &err);
        tap_ok(st == RAD_ERR_PARSE && strstr(err.message, hard[k].want),
               "not repairable, refused (%s): %s", hard[k].want, err.message);
        rad_scene_free(&s);
    }
    const char *far = "mtllib t.mtl\nusemtl white\nv 1000 1000 0\nv 1000.02 1000 0\n"
                      "v 1000.02 1000.01 0\nv 1000.01 1000.01 0\nv 1000.01 1000.02 0\n"
                      "v 1000 1000.02 0\nf 1 2 3 4 5 6\n";
    st = parse_flags(&s, far, MTL, 0, &err);
    tap_ok(st == RAD_OK && s.nsurfaces == 4 && s.repairs.split_faces == 1 &&
               fabs(total_area(&s) - 3e-4) < 1e-9, /* round-off of areas at 1000: 1e-10 */
           "an L 0.02 across at (1000, 1000): 4 triangles of area %.6g (3e-4 by its sides) (%s)",
           st == RAD_OK ? total_area(&s) : 0.0, st ? err.message : "ok");
    rad_scene_free(&s);

    /* strict: each of the repairs above is the error it names */
    st = parse_flags(&s, obj, mtl, RAD_SCENE_STRICT, &err);
    tap_ok(st == RAD_ERR_PARSE, "RAD_SCENE_STRICT refuses the file repaired above: %s",
           err.message);
    rad_scene_free(&s);
}

int main(void)
{
    index_forms();
    relative_indices();
    repairs();
    materials_and_kinds();
    groups();
    mtllib_once();
    errors();
    return tap_done();
}
