/* test_vs3read.c -- the View3D 3.x reader: what it maps, and every error
 * message.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Inputs are parsed from memory with rad_scene_parse under a name ending
 * in .vs3, so this also checks the dispatch by name.  Expected values are
 * those written in the input (vertices are copied bit for bit; the
 * reflectance of emissivity e is 1 - e, computed here the same way), and
 * each bad input must fail with RAD_ERR_PARSE, a message starting
 * "t.vs3:LINE: " and an empty scene.  tests/commands/readers.sh checks the factors.
 */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "../tap.h"

/* The unit cube's eight corners and a triangle's, as View3D numbers them. */
static const char *HEAD = "T cube, walls inward\n"
                          "C eps=1.e-4 maxU=8 maxO = 8 minO= 0 encl =1 emit=0 list=2 out=1\n"
                          "F 3\n"
                          "V 1 0 0 0\nV 2 1 0 0\nV 3 1 1 0\nV 4 0 1 0\n"
                          "V 5 0 0 1\nV 6 1 0 1\nV 7 1 1 1\nV 8 0 1 1\n";
/* HEAD is lines 1-11: the first line after it is 12. */

static rad_status parse(rad_scene *s, const char *text, rad_error *err)
{
    memset(err, 0, sizeof *err);
    return rad_scene_parse(s, text, strlen(text), "t.vs3", err);
}

static void bad(const char *tail, int line, const char *reason)
{
    char text[2048];
    rad_scene s;
    rad_error err;
    char want[64];
    snprintf(text, sizeof text, "%s%s", HEAD, tail);
    rad_status st = parse(&s, text, &err);
    snprintf(want, sizeof want, "t.vs3:%d: ", line);
    int ok = st == RAD_ERR_PARSE && strncmp(err.message, want, strlen(want)) == 0 &&
             strstr(err.message, reason) != NULL && s.nsurfaces == 0 && s.materials == NULL;
    tap_ok(ok, "rejects (%s): \"%s\"", reason, err.message);
    rad_scene_free(&s);
}

static int same(rad_vec3 a, double x, double y, double z)
{
    return a.x == x && a.y == y && a.z == z;
}

static void mapping(void)
{
    char text[2048];
    rad_scene s;
    rad_error err;
    snprintf(text, sizeof text,
             "%s"
             "! number v1 v2 v3 v4 base cmb emit name\n"
             "S 1  1 4 3 2  0 0 0.9 floor   ! a comment\n"
             "s 2  5 6 7 8  0 0 0.25 ceiling / another\n"
             "S 3  1 2 6 0  0 1 0.9\n"
             "/ a comment line\n"
             "X a coordinate transformation, ignored\n"
             "O 4  1 5 8 4\n"
             "o 5  2 3 7 6  0 0 0.5 wall\n"
             "End of data\n"
             "anything at all: \001\002 V 9 S 9\n",
             HEAD);
    rad_status st = parse(&s, text, &err);
    int ok = st == RAD_OK && s.nsurfaces == 5;
    tap_ok(ok, "three S and two O surfaces, nothing after End (%s)", st ? err.message : "ok");
    if (!ok) {
        rad_scene_free(&s);
        return;
    }
    tap_ok(s.surfaces[0].kind == RAD_SURFACE_QUAD && s.surfaces[0].nverts == 4 &&
               same(s.surfaces[0].verts[0], 0, 0, 0) && same(s.surfaces[0].verts[1], 0, 1, 0) &&
               same(s.surfaces[0].verts[2], 1, 1, 0) && same(s.surfaces[0].verts[3], 1, 0, 0),
           "S with four vertices is a quad with V1..V4 in order");
    tap_ok(s.surfaces[2].kind == RAD_SURFACE_POLYGON && s.surfaces[2].nverts == 3 &&
               same(s.surfaces[2].verts[2], 1, 0, 1),
           "S with V4 = 0 is a triangle");
    const rad_material *m0 = &s.materials[s.surfaces[0].material];
    const rad_material *m1 = &s.materials[s.surfaces[1].material];
    tap_ok(m0->reflect[0] == 1 - 0.9 && m0->reflect[2] == 1 - 0.9 && m0->emit[0] == 0 &&
               m1->reflect[1] == 1 - 0.25 && s.surfaces[2].material == s.surfaces[0].material,
           "emissivity e is a grey reflectance 1 - e without emission, one material per e");
    const rad_material *o = &s.materials[s.surfaces[3].material];
    tap_ok(s.surfaces[3].material == s.surfaces[4].material && o->reflect[0] == 0 &&
               o->reflect[1] == 0 && o->emit[2] == 0 && strcmp(o->name, "obstruction") == 0,
           "O surfaces are black, dark surfaces (material '%s')", o->name);
    tap_ok(s.surfaces[0].line == 13 && s.surfaces[4].line == 19 && s.surfaces[0].object == -1,
           "lines kept (%d, %d); no objects", s.surfaces[0].line, s.surfaces[4].line);
    tap_ok(s.surfaces[2].combine == 0 && s.surfaces[0].combine == -1 &&
               s.surfaces[1].combine == -1 && s.surfaces[3].combine == -1 &&
               s.surfaces[4].combine == -1,
           "CMB 1 is kept as combine 0 (the scene's index of S 1), CMB 0 and O as -1");
    rad_scene_set_mesh(&s, 2, 3);
    tap_ok(s.surfaces[0].mesh_n == 2 && s.surfaces[0].mesh_m == 3 &&
               s.surfaces[2].mesh_n == 3 && s.surfaces[3].mesh_m == 3,
           "--mesh applies to every surface, S and O alike (the triangle 3 per edge)");
    rad_scene_free(&s);
}

/* The case of the line's letter, and the optional F and C lines. */
static void lenient(void)
{
    const char *text = "v 1 0 0 0\nv 2 1 0 0\nv 3 0 1 0\ns 1 1 2 3 0 0 0 1\n";
    rad_scene s;
    rad_error err;
    rad_status st = parse(&s, text, &err);
    tap_ok(st == RAD_OK && s.nsurfaces == 1 && s.materials[0].reflect[0] == 0,
           "lower-case letters, no T, C, F or End, no name (%s)", st ? err.message : "ok");
    rad_scene_free(&s);
    text = "V 1 0 0 0\nV 2 1 0 0\nV 3 0 1 0\nS 1 1 2 3 0 0 0 1\n";
    st = rad_scene_parse(&s, text, strlen(text), "dir.x/T.VS3", &err);
    tap_ok(st == RAD_OK && s.nsurfaces == 1, "the suffix .VS3 in capitals (%s)",
           st ? err.message : "ok");
    rad_scene_free(&s);
}

static void errors(void)
{
    const char *S1 = "S 1 1 2 3 4 0 0 0.5 a\n";
    char buf[512];
    bad("F 3a\n", 12, "geometry format 3a (BLAST surfaces) is not supported");
    bad("F 2\n", 12, "geometry format '2' is not supported");
    bad("F\n", 12, "F needs the geometry format");
    bad("C eps\n", 12, "control word 'eps' has no value");
    bad("C eps=2\n", 12, "eps must be a number between 0 and 1");
    bad("C maxU=x\n", 12, "'x' is not a whole number (maxU)");
    bad("C frob=1\n", 12, "unknown control word 'frob'");
    bad("V 10 0 0 0\n", 12, "vertex 10 out of sequence (expected 9)");
    bad("V 9 0 0\n", 12, "missing number: vertex");
    bad("V 9 0 0 0 0\n", 12, "unexpected '0' after X Y Z");
    bad("V 9 0,0,0\n", 12, "holds a comma; separate View3D words with blanks");
    bad("V 9 0 0 1e999\n", 12, "vertex must be finite");
    bad("S 2 1 2 3 4 0 0 0.5\n", 12, "surface 2 out of sequence (expected 1)");
    bad("S 1 1 2 3 9 0 0 0.5\n", 12, "vertex 4 of the surface must be from 0 to 8");
    bad("S 1 0 2 3 4 0 0 0.5\n", 12, "vertex 1 of the surface must be from 1 to 8");
    bad("S 1 1 2 3 4 0 0\n", 12, "S needs N V1 V2 V3 V4 BASE CMB EMIT");
    bad("S 1 1 2 3 4 0 0 1.5\n", 12, "emissivity must be from 0 to 1");
    bad("S 1 1 2 3 4 0 0 -0.1\n", 12, "emissivity must be from 0 to 1");
    bad("S 1 1 2 3 4 0 0 0.5 a b\n", 12, "unexpected 'b' after the surface name");
    bad("S 1 1 2 3 4 0 1 0.5\n", 12, "combine surface must be from 0 to 0");
    snprintf(buf, sizeof buf, "%sS 2 5 6 7 8 1 0 0.5 b\n", S1);
    bad(buf, 13, "surface 2 is a subsurface of 1; subsurfaces are not supported");
    snprintf(buf, sizeof buf, "%sS 2 5 6 7 8 0 1 0.5 b\nS 3 1 2 6 5 0 2 0.5 c\n", S1);
    bad(buf, 14, "does not chain combinations");
    snprintf(buf, sizeof buf, "%sO 2 5 6 7 8\nS 3 1 2 6 5 0 0 0.5 c\n", S1);
    bad(buf, 14, "every S comes before the O surfaces");
    bad("O 1 1 2 3\n", 12, "O needs N V1 V2 V3 V4");
    bad("M 1 1 2 3 4 0 0 0.5\n", 12, "masking surfaces (M) are not supported");
    bad("N 1 1 2 3 4 0 0 0.5\n", 12, "null surfaces (N) are not supported");
    bad("Q 1\n", 12, "unknown View3D line 'Q'");
    bad("S 1 1 2 3 8 0 0 0.5\n", 12, "surface is not planar");
    bad("S 1 1 3 2 4 0 0 0.5\n", 12, "surface is self-intersecting");
    bad("S 1 1 2 2 4 0 0 0.5\n", 12, "surface has a repeated vertex");
    bad("O 1 1 2 3 1\n", 12, "obstruction surface has a repeated vertex");
    bad("S 1 1 2 3 4 0 0 0.5 caf\303\251\n", 12, "non-ASCII character");
    bad("", 11, "the View3D file has no surfaces");
    bad("End\nS 1 1 2 3 4 0 0 0.5\n", 12, "the View3D file has no surfaces");
}

int main(void)
{
    mapping();
    lenient();
    errors();
    return tap_done();
}
