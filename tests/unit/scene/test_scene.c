/* test_scene.c -- the scene parser: valid input, and every error message.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Each bad input must fail with RAD_ERR_PARSE and a message that starts
 * with "t.scene:LINE: " (the contract of radiosity-scene(5), DIAGNOSTICS,
 * and of doc/design.md, "Conventions") and names the reason.
 */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "util/readfile.h"
#include "scene/polycheck.h"
#include "../tap.h"

static const char *M = "material w reflect 0.5\n";

static void bad(const char *text, int line, const char *reason)
{
    rad_scene s;
    rad_error err;
    char want[64];
    memset(&err, 0, sizeof err);
    rad_status st = rad_scene_parse(&s, text, strlen(text), "t.scene", &err);
    snprintf(want, sizeof want, "t.scene:%d: ", line);
    int ok = st == RAD_ERR_PARSE && strncmp(err.message, want, strlen(want)) == 0 &&
             strstr(err.message, reason) != NULL && s.nsurfaces == 0;
    tap_ok(ok, "rejects (%s): \"%s\"", reason, ok ? err.message : err.message);
    rad_scene_free(&s);
}

static void bad_m(const char *stmt, const char *reason)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s%s\n", M, stmt);
    bad(buf, 2, reason);
}

static void valid(void)
{
    const char *text =
        "# comment line\n"
        "material light reflect 0 emit 1 2 3   # trailing comment\n"
        "material red reflect 0.8 0.1 0.1\n"
        "\n"
        "quad red 0 0 0  1 0 0  1 1 0  0 1 0 mesh 3x2\n"
        "polygon light 3  0 0 1  1 0 1  0 1 1\n"
        "disk red 0 0 5  0 0 -1  2 64\n"
        "camera eye 0 0 -3 at 0 0 0 up 0 1 0 fov 45\n";
    rad_scene s;
    rad_error err;
    rad_status st = rad_scene_parse(&s, text, strlen(text), "t.scene", &err);
    tap_ok(st == RAD_OK, "valid scene parses (%s)", st ? err.message : "ok");
    if (st)
        return;
    tap_ok(s.nmaterials == 2 && s.nsurfaces == 3, "2 materials, 3 surfaces");
    tap_ok(s.materials[0].emit[2] == 3 && s.materials[0].reflect[1] == 0 &&
               s.materials[1].reflect[0] == 0.8 && s.materials[1].emit[0] == 0,
           "material values (grey and RGB, emit defaults to 0)");
    tap_ok(s.surfaces[0].mesh_n == 3 && s.surfaces[0].mesh_m == 2 && s.surfaces[0].line == 5,
           "quad mesh 3x2 on line 5");
    tap_ok(s.surfaces[2].nverts == 64 && s.surfaces[2].kind == RAD_SURFACE_POLYGON,
           "disk becomes a 64-gon");
    /* the disk's vertices lie on the circle of radius 2 about (0,0,5) */
    double worst = 0;
    for (int k = 0; k < 64; k++) {
        rad_vec3 v = s.surfaces[2].verts[k];
        worst = fmax(worst, fabs(hypot(v.x, v.y) - 2) + fabs(v.z - 5));
    }
    tap_ok(worst < 1e-14, "disk vertices on the circle (worst %.3g)", worst);
    /* counter-clockwise about the given normal (0,0,-1): Newell z < 0 */
    double nz = 0;
    for (int k = 0; k < 64; k++) {
        rad_vec3 a = s.surfaces[2].verts[k], b = s.surfaces[2].verts[(k + 1) % 64];
        nz += a.x * b.y - a.y * b.x;
    }
    tap_ok(nz < 0, "disk runs counter-clockwise about its normal");
    tap_ok(s.camera.defined && s.camera.fov == 45 && s.camera.eye.z == -3, "camera");
    rad_scene_set_mesh(&s, 4, 5);
    tap_ok(s.surfaces[0].mesh_n == 4 && s.surfaces[0].mesh_m == 5 &&
               s.surfaces[1].mesh_n == 5 && s.surfaces[1].mesh_m == 5,
           "--mesh 4x5: quads 4 x 5, polygons 5 parts per edge of their triangles");
    rad_scene_free(&s);
}

/* Parse text of length len; the status, the message, the surfaces. */
static rad_status parse_n(const char *text, size_t len, rad_error *err, int *nsurf)
{
    rad_scene s;
    memset(err, 0, sizeof *err);
    rad_status st = rad_scene_parse(&s, text, len, "t.scene", err);
    *nsurf = s.nsurfaces;
    rad_scene_free(&s);
    return st;
}

static const char *QUAD2 = "quad w 0 0 0  1 0 0  1 1 0  0 1 0\n";

/* Line ends, a byte order mark, bytes outside ASCII (radiosity-scene(5), DESCRIPTION). */
static void encodings(void)
{
    char buf[512];
    rad_error err;
    int n;
    snprintf(buf, sizeof buf, "\xEF\xBB\xBF%s%s", M, QUAD2);
    tap_ok(parse_n(buf, strlen(buf), &err, &n) == RAD_OK && n == 1,
           "a UTF-8 byte order mark at the start is skipped (%s)", err.message);
    bad("\xEF\xBB\xBFmaterial w reflect 0.5\nfrob\n", 2, "unknown keyword 'frob'");
    bad("material w reflect 0.5\n\xEF\xBB\xBFquad\n", 2, "non-ASCII character (byte 0xEF");
    const char *crlf = "material w reflect 0.5\r\nquad w 0 0 0  1 0 0  1 1 0  0 1 0\r\n";
    tap_ok(parse_n(crlf, strlen(crlf), &err, &n) == RAD_OK && n == 1, "CR LF line ends (%s)",
           err.message);
    const char *cr = "material w reflect 0.5\rquad w 0 0 0  1 0 0  1 1 0  0 1 0\r"
                     "quad w 0 0 1  0 1 1  1 1 1  1 0 1";
    tap_ok(parse_n(cr, strlen(cr), &err, &n) == RAD_OK && n == 2,
           "CR-only (old Mac OS) line ends (%s)", err.message);
    bad("material w reflect 0.5\r\rfrob\r", 3, "unknown keyword 'frob'");
    bad("material w reflect 0.5\r\n\r\nfrob\r\n", 3, "unknown keyword 'frob'");
    bad("material w reflect 0.5\n\r\r\nfrob\n", 4, "unknown keyword 'frob'");
    bad_m("quad w 0 0 0\xC2\xA0 1 0 0  1 1 0  0 1 0",
          "non-ASCII character (byte 0xC2 at column 13, a UTF-8 no-break space U+00A0?)");
    bad("material caf\xC3\xA9 reflect 0.5\n", 1, "non-ASCII character (byte 0xC3 at column 13)");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 \x1B[31m0", "control character (byte 0x1B");
    snprintf(buf, sizeof buf, "%s# caf\xC3\xA9 \xC2\xA0 \x1B comment\n%s", M, QUAD2);
    tap_ok(parse_n(buf, strlen(buf), &err, &n) == RAD_OK && n == 1,
           "comments may hold any byte but NUL (%s)", err.message);
    static const char nul[] = "material w reflect 0.5\n\n\0";
    tap_ok(parse_n(nul, sizeof nul - 1, &err, &n) == RAD_ERR_PARSE &&
               strcmp(err.message, "t.scene:3: line contains a NUL character (byte 0x00 at "
                                   "column 1)") == 0,
           "a NUL byte is named with its line and column (%s)", err.message);
}

/* Values that are not numbers, and the scene's size limits. */
static void values_and_limits(void)
{
    bad("material w reflect 0.5abc\n", 1, "'0.5abc' is not a number (reflectance)");
    bad("material w reflect 0.5 0.5 0.5x\n", 1, "'0.5x' is not a number (reflectance)");
    bad("material w reflect 0.5 emit 1,5\n", 1, "'1,5' is not a number (emission)");
    bad("material w reflect\n", 1, "reflectance needs 1 value (grey) or 3");
    bad("material w reflect emit 1\n", 1, "reflectance needs 1 value (grey) or 3 (R G B), found 'emit'");
    bad("material w reflect 0.5 shiny\n", 1, "unexpected 'shiny'");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 100000x100000",
          "mesh 100000x100000 has 10000000000 elements; at most 100000000 per surface");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 100001x1", "mesh must be NxM");
    {
        char buf[512];
        snprintf(buf, sizeof buf, "%squad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 10000x10000\n"
                                  "polygon w 3  0 0 1  1 0 1  0 1 1\n", M);
        bad(buf, 3, "the scene would have 100000001 elements; at most 100000000");
        rad_error err;
        int n;
        snprintf(buf, sizeof buf, "%squad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 10000x10000\n", M);
        tap_ok(parse_n(buf, strlen(buf), &err, &n) == RAD_OK && n == 1,
               "exactly %d elements are allowed (%s)", RAD_ELEMENTS_MAX, err.message);
    }
    bad_m("polygon w 4097 0 0 0", "polygon vertex count must be from 3 to 4096");
    bad_m("disk w 0 0 0  0 0 1  1 65536", "disk vertex count must be from 3 to 4096");
}

/* The line reader's limits, lowered so the tests stay small. */
static void reader_limits(void)
{
    rad_lines r;
    rad_error err;
    const char text[] = "ab\ncdefg\nh\n";
    radi_lines_mem(&r, text, sizeof text - 1, "t", '#', &err);
    r.line_max = 4;
    int a = radi_lines_next(&r), b = radi_lines_next(&r), c = radi_lines_next(&r);
    tap_ok(a == 1 && b == -1 && c == -1 && r.status == RAD_ERR_PARSE &&
               strcmp(err.message, "t:2: line longer than 4 bytes (the limit)") == 0,
           "a line over the limit fails on its line, and stays failed (%s)", err.message);
    radi_lines_close(&r);

    radi_lines_mem(&r, text, sizeof text - 1, "t", '#', &err);
    r.file_max = 7;
    a = radi_lines_next(&r);
    b = radi_lines_next(&r);
    tap_ok(a == 1 && b == -1 && strcmp(err.message, "t:2: the input is longer than 7 bytes "
                                                    "(the limit)") == 0,
           "an input over the file limit fails at the line that crosses it (%s)", err.message);
    radi_lines_close(&r);

    radi_lines_mem(&r, text, sizeof text - 1, "t", '#', &err);
    r.file_max = sizeof text - 1;
    int lines = 0;
    while (radi_lines_next(&r) == 1)
        lines++;
    tap_ok(lines == 3 && !r.failed, "an input of exactly the file limit is read whole");
    radi_lines_close(&r);

    const char toks[] = "\xEF\xBB\xBF a\tb  # c d\r\n\f\v\r";
    radi_lines_mem(&r, toks, sizeof toks - 1, "t", '#', &err);
    a = radi_lines_next(&r);
    tap_ok(a == 1 && r.ntok == 2 && strcmp(r.tok[0], "a") == 0 && strcmp(r.tok[1], "b") == 0,
           "one tokenizer: blanks separate, # ends the text, the BOM is skipped");
    b = radi_lines_next(&r);
    c = radi_lines_next(&r);
    tap_ok(b == 1 && r.ntok == 0 && r.line == 2 && c == 0, "blank line, then end of input");
    radi_lines_close(&r);

    rad_status st = radi_lines_open(&r, "/", '#', &err);
    if (st == RAD_OK) {
        a = radi_lines_next(&r);
        st = r.status;
    }
    tap_ok(st == RAD_ERR_IO && strstr(err.message, "/: ") == err.message,
           "a directory fails as a read error (%s)", err.message);
    radi_lines_close(&r);
}

/* Thousands of materials: found by hash, duplicates named with their line. */
static void many_materials(void)
{
    const int n = 20000;
    size_t cap = (size_t)n * 80 + 256, len = 0;
    char *buf = malloc(cap);
    for (int k = 0; k < n; k++)
        len += (size_t)snprintf(buf + len, cap - len, "material m%d reflect 0.5\n", k);
    for (int k = 0; k < n; k += 997)
        len += (size_t)snprintf(buf + len, cap - len, "polygon m%d 3 0 0 %d 1 0 %d 0 1 %d\n",
                                k, k, k, k);
    rad_scene s;
    rad_error err;
    rad_status st = rad_scene_parse(&s, buf, len, "t.scene", &err);
    int right = st == RAD_OK && s.nmaterials == n && s.nsurfaces == (n + 996) / 997;
    for (int k = 0; right && k < s.nsurfaces; k++)
        right = s.surfaces[k].material == 997 * k;
    tap_ok(right, "%d materials, each surface finds its own (%s)", n, st ? err.message : "ok");
    rad_scene_free(&s);
    len += (size_t)snprintf(buf + len, cap - len, "material m12345 reflect 0.1\n");
    st = rad_scene_parse(&s, buf, len, "t.scene", &err);
    char want[128];
    snprintf(want, sizeof want, "t.scene:%d: material 'm12345' is already defined (line 12346)",
             n + (n + 996) / 997 + 1);
    tap_ok(st == RAD_ERR_PARSE && strcmp(err.message, want) == 0, "duplicate found: %s",
           err.message);
    free(buf);
}

int main(void)
{
    encodings();
    values_and_limits();
    reader_limits();
    many_materials();
    valid();
    bad("frobnicate 1 2 3\n", 1, "unknown keyword 'frobnicate'");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1\n", "missing number");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 0 7\n", "unexpected '7'");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 zero\n", "'zero' is not a number");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 nan\n", "must be finite");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 inf\n", "must be finite");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 1e999\n", "must be finite");
    bad("material w reflect 1.5\nquad w 0 0 0 1 0 0 1 1 0 0 1 0\n", 1, "reflectance must be from 0 to 1");
    bad("material w reflect -0.1 0 0\n", 1, "reflectance must be from 0 to 1");
    bad("material w reflect 0.5 emit 1 -1 1\n", 1, "emission must not be negative");
    bad("material w reflect 0.5 0.5\n", 1, "takes 1 value (grey) or 3");
    bad("material w emit 1\n", 1, "has no reflect");
    bad("material w reflect 0.5 shiny\n", 1, "unexpected 'shiny'");
    bad("material w reflect 0.5\nmaterial w reflect 0.2\n", 2, "already defined (line 1)");
    bad("quad x 0 0 0  1 0 0  1 1 0  0 1 0\n", 1, "undefined material 'x'");
    bad("quad w 0 0 0  1 0 0  1 1 0  0 1 0\nmaterial w reflect 0.5\n", 1, "undefined material 'w'");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 0x3\n", "mesh must be NxM");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 3\n", "mesh must be NxM");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh -2x3\n", "mesh must be NxM");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 2x3.5\n", "mesh must be NxM");
    bad_m("quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh\n", "mesh needs NxM");
    bad_m("quad w 0 0 0  1 0 0  1 1 0.1  0 1 0\n", "not planar");
    bad_m("quad w 0 0 0  1 0 0  0.2 0.2 0  0 1 0\n", "not convex");
    bad_m("quad w 0 0 0  1 1 0  1 0 0  0 1 0\n", "self-intersecting");
    bad_m("quad w 0 0 0  1 0 0  2 0 0  3 0 0\n", "zero area");
    bad_m("quad w 0 0 0  0 0 0  0 0 0  0 0 0\n", "zero area");
    bad_m("quad w 0 0 0  1 0 0  1 0 0  0 1 0\n", "repeated vertex");
    bad_m("polygon w 2  0 0 0  1 0 0\n", "polygon vertex count must be from 3");
    bad_m("polygon w 3  0 0 0  1 0 0\n", "needs 9 numbers");
    bad_m("polygon w 3  0 0 0  1 0 0  0 1 0  5\n", "unexpected '5'");
    bad_m("polygon w 5  0 0 0  2 1 0  0 1 0  2 0 0  1 2 0\n", "self-intersecting");
    bad_m("polygon w 4  0 0 0  1 0 0  1 1 0  0 1 1\n", "not planar");
    bad_m("disk w 0 0 0  0 0 1  -1 32\n", "radius must be positive");
    bad_m("disk w 0 0 0  0 0 0  1 32\n", "normal must not be zero");
    bad_m("disk w 0 0 0  0 0 1  1 2\n", "vertex count must be from 3");
    bad_m("camera eye 0 0 0 at 0 0 0 up 0 1 0 fov 45\n", "eye and at must differ");
    bad_m("camera eye 0 0 0 at 0 0 1 up 0 0 1 fov 45\n", "parallel to the view");
    bad_m("camera eye 0 0 0 at 0 0 1 up 0 1 0 fov 180\n", "fov must be between");
    bad_m("camera eye 0 0 0 at 0 0 1 up 0 1 0\n", "camera needs");
    bad_m("camera eye 0 0 0 look 0 0 1 up 0 1 0 fov 4\n", "expects 'at'");
    bad("", 1, "no surfaces");
    bad("# only a comment\nmaterial w reflect 0.5\n", 2, "no surfaces");
    {
        static const char nul[] = "material w reflect 0.5\nquad w 0 0 0\0 1 0 0 1 1 0 0 1 0\n";
        rad_scene s;
        rad_error err;
        rad_status st = rad_scene_parse(&s, nul, sizeof nul - 1, "t.scene", &err);
        tap_ok(st == RAD_ERR_PARSE && strstr(err.message, "t.scene:2: ") == err.message,
               "NUL byte rejected with its line (%s)", err.message);
    }
    {
        /* a disk of 4096 vertices is accepted and stays convex */
        const char *t = "material w reflect 0.5\ndisk w 1e6 1e6 1e6  1 2 3  1e-3 4096\n";
        rad_scene s;
        rad_error err;
        rad_status st = rad_scene_parse(&s, t, strlen(t), "t.scene", &err);
        tap_ok(st == RAD_OK && s.surfaces[0].nverts == 4096,
               "4096-gon disk far from the origin is accepted (%s)", st ? err.message : "ok");
        rad_scene_free(&s);
    }
    {
        rad_scene s;
        rad_error err;
        rad_status st = rad_scene_load(&s, "/nonexistent/x.scene", &err);
        tap_ok(st == RAD_ERR_IO && strstr(err.message, "/nonexistent/x.scene") != NULL,
               "missing file: %s", err.message);
    }
    return tap_done();
}
