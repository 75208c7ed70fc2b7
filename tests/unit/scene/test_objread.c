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

static rad_status parse(rad_scene *s, const char *obj, const char *mtl, rad_error *err)
{
    rad_lines r;
    memset(err, 0, sizeof *err);
    radi_lines_mem(&r, obj, strlen(obj), "t.obj", '#', err);
    rad_status st = radi_obj_read(s, &r, mtl, strlen(mtl));
    radi_lines_close(&r);
    return st;
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
               s.surfaces[0].mesh_n == 1 && s.surfaces[2].mesh_n == 1,
           "--mesh applies to the quad face only");
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
    bad(WITH("usemtl\n"), 7, "usemtl takes one material name");
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

int main(void)
{
    index_forms();
    relative_indices();
    materials_and_kinds();
    groups();
    mtllib_once();
    errors();
    return tap_done();
}
