/* test_changes.c -- scene objects and the change file of `radiosity animate`.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The scene parser's `object NAME [absent] ... end` (radiosity-scene(5)),
 * the present copy of a scene, and the change reader (changeread.c): valid
 * input read as written, and every error refused with "c.changes:LINE: "
 * and its reason, before anything else happens.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/changes.h"
#include "../tap.h"

static const char *SCENE =
    "material w reflect 0.5\n"
    "material lamp reflect 0 emit 1\n"
    "quad w 0 0 0  1 0 0  1 1 0  0 1 0\n"
    "object box\n"
    "  quad w 0 0 1  1 0 1  1 1 1  0 1 1 mesh 2x2\n"
    "end\n"
    "object shade absent\n"
    "  polygon lamp 3  0 0 2  1 0 2  0 1 2\n"
    "end\n";

static void bad_scene(const char *text, int line, const char *reason)
{
    rad_scene s;
    rad_error err;
    char want[64];
    memset(&err, 0, sizeof err);
    rad_status st = rad_scene_parse(&s, text, strlen(text), "t.scene", &err);
    snprintf(want, sizeof want, "t.scene:%d: ", line);
    int ok = st == RAD_ERR_PARSE && strncmp(err.message, want, strlen(want)) == 0 &&
             strstr(err.message, reason) != NULL && s.nsurfaces == 0;
    tap_ok(ok, "scene rejects (%s): \"%s\"", reason, err.message);
    rad_scene_free(&s);
}

static void objects(const rad_scene *s)
{
    tap_ok(s->nobjects == 2 && strcmp(s->objects[0].name, "box") == 0 &&
               !s->objects[0].absent && strcmp(s->objects[1].name, "shade") == 0 &&
               s->objects[1].absent && s->objects[1].line == 7,
           "objects box (present) and shade (absent, line 7)");
    tap_ok(s->nsurfaces == 3 && s->surfaces[0].object == -1 && s->surfaces[1].object == 0 &&
               s->surfaces[2].object == 1,
           "surfaces know their object (-1: the environment)");
    tap_ok(rad_scene_has_absent(s), "the scene has an absent object");
    rad_scene p;
    rad_error err;
    tap_ok(rad_scene_present_copy(s, NULL, &p, &err) == RAD_OK && p.nsurfaces == 2 &&
               p.surfaces[1].object == 0 && p.surfaces[1].mesh_n == 2,
           "the present copy leaves the absent object out");
    rad_scene_free(&p);
    unsigned char only_shade[2] = {0, 1};
    tap_ok(rad_scene_present_copy(s, only_shade, &p, &err) == RAD_OK && p.nsurfaces == 2 &&
               p.surfaces[1].object == 1 && p.objects[0].absent && !p.objects[1].absent,
           "a presence vector picks the surfaces");
    rad_scene_free(&p);
    bad_scene("material w reflect 0.5\nobject a\nobject b\n", 3, "do not nest");
    bad_scene("material w reflect 0.5\nend\n", 2, "end without object");
    bad_scene("material w reflect 0.5\nobject a\nend\n", 3, "has no surfaces");
    bad_scene("material w reflect 0.5\nobject a\nquad w 0 0 0 1 0 0 1 1 0 0 1 0\n", 2,
              "has no end");
    bad_scene("material w reflect 0.5\nobject a hidden\n", 2, "expected absent");
    bad_scene("material w reflect 0.5\nobject\n", 2, "needs a name");
    bad_scene("material w reflect 0.5\nobject a\nquad w 0 0 0 1 0 0 1 1 0 0 1 0\nend\n"
              "object a\n", 5, "already defined (line 2)");
}

static void bad(const rad_scene *s, const char *text, int line, const char *reason)
{
    rad_changes c;
    rad_error err;
    char want[64];
    memset(&err, 0, sizeof err);
    rad_status st = rad_changes_parse(&c, s, text, strlen(text), "c.changes", &err);
    snprintf(want, sizeof want, "c.changes:%d: ", line);
    int ok = st == RAD_ERR_PARSE && strncmp(err.message, want, strlen(want)) == 0 &&
             strstr(err.message, reason) != NULL && c.nchanges == 0 && c.changes == NULL;
    tap_ok(ok, "changes reject (%s): \"%s\"", reason, err.message);
    rad_changes_free(&c);
}

static void valid(const rad_scene *s)
{
    const char *text = "# a box that moves, turns and goes; a shade comes\n"
                       "frame\n"
                       "move box 0.5 0 -1e-3   # right\n"
                       "frame\n"
                       "rotate box 0 0 2 90 about 1 2 3\n"
                       "rotate box 1 0 0 -45\n"
                       "add shade\n"
                       "frame\n"
                       "remove box\n"
                       "material lamp reflect 0.2 emit 3 2 1\n"
                       "material w reflect 0.1 0.2 0.3\n"
                       "frame\n";
    rad_changes c;
    rad_error err;
    rad_status st = rad_changes_parse(&c, s, text, strlen(text), "c.changes", &err);
    tap_ok(st == RAD_OK, "a valid change file reads (%s)", st ? err.message : "ok");
    if (st)
        return;
    tap_ok(c.nframes == 4 && c.nchanges == 7, "4 frames, 7 changes");
    const rad_change *k = c.changes;
    tap_ok(k[0].kind == RAD_CHANGE_MOVE && k[0].frame == 1 && k[0].object == 0 &&
               k[0].v.x == 0.5 && k[0].v.z == -1e-3 && k[0].line == 3,
           "move: object, displacement, frame 1, line 3");
    tap_ok(k[1].kind == RAD_CHANGE_ROTATE && k[1].frame == 2 && k[1].v.z == 1 &&
               k[1].degrees == 90 && k[1].has_center && k[1].center.y == 2,
           "rotate about a point: unit axis, angle, centre");
    tap_ok(k[2].kind == RAD_CHANGE_ROTATE && !k[2].has_center && k[2].degrees == -45,
           "rotate about the centroid by default");
    tap_ok(k[3].kind == RAD_CHANGE_ADD && k[3].object == 1 && k[4].kind == RAD_CHANGE_REMOVE &&
               k[4].frame == 3,
           "add and remove");
    tap_ok(k[5].kind == RAD_CHANGE_MATERIAL && k[5].material == 1 && k[5].has_emit &&
               k[5].reflect[2] == 0.2 && k[5].emit[0] == 3 && k[5].emit[2] == 1,
           "material with grey reflect and RGB emit");
    tap_ok(k[6].material == 0 && !k[6].has_emit && k[6].reflect[1] == 0.2,
           "material without emit keeps it");
    rad_changes_free(&c);
    tap_ok(rad_changes_parse(&c, s, "", 0, "c.changes", &err) == RAD_OK && c.nframes == 0,
           "an empty change file has no frames");
    rad_changes_free(&c);
}

/* rad_changes_apply takes the changes of the frame it is given and no
 * other, in file order: a frame without changes, frame 0 and a frame past
 * the last change nothing.  The box's first vertex is (0, 0, 1); every
 * move is a binary fraction, so each position is exact. */
static void apply_frames(const rad_scene *s)
{
    const char *text = "frame\nmove box 1 0 0\n"
                       "frame\n"
                       "frame\nmove box 0 2 0\nmove box 0 0 4\n"
                       "frame\nremove box\n"
                       "frame\nadd box\nmove box 0.5 0 0\n"
                       "frame\n";
    rad_changes c;
    rad_scene p;
    rad_error err;
    if (rad_changes_parse(&c, s, text, strlen(text), "c.changes", &err) != RAD_OK ||
        rad_scene_present_copy(s, (const unsigned char *)"\1\1", &p, &err) != RAD_OK) {
        tap_ok(0, "a change file to apply reads (%s)", err.message);
        return;
    }
    /* where the box's first vertex is, and whether the box is there, after
     * frames 0 .. 6 (0 and 6: no change) */
    static const double want[7][4] = {{0, 0, 1, 1}, {1, 0, 1, 1}, {1, 0, 1, 1}, {1, 2, 5, 1},
                                      {1, 2, 5, 0}, {1.5, 2, 5, 1}, {1.5, 2, 5, 1}};
    int ok = 1;
    for (int f = 0; f <= 6; f++) {
        rad_changes_apply(&p, &c, f, NULL);
        const rad_vec3 v = p.surfaces[1].verts[0];
        ok &= v.x == want[f][0] && v.y == want[f][1] && v.z == want[f][2] &&
              !p.objects[0].absent == (want[f][3] != 0);
    }
    tap_ok(ok, "each frame applies its own changes only, empty frames none");
    unsigned char dirty[2] = {0, 0};
    rad_changes_apply(&p, &c, 3, dirty);
    tap_ok(p.surfaces[1].verts[0].y == 4 && p.surfaces[1].verts[0].z == 9 && dirty[0] &&
               !dirty[1],
           "a frame applied again moves again, and marks what it moved");
    rad_scene_free(&p);
    rad_changes_free(&c);
}

int main(void)
{
    rad_scene s;
    rad_error err;
    rad_status st = rad_scene_parse(&s, SCENE, strlen(SCENE), "t.scene", &err);
    tap_ok(st == RAD_OK, "a scene with objects parses (%s)", st ? err.message : "ok");
    if (st)
        return tap_done();
    objects(&s);
    valid(&s);
    apply_frames(&s);
    bad(&s, "move box 1 0 0\n", 1, "before the first 'frame'");
    bad(&s, "frame\nmove crate 1 0 0\n", 2, "unknown object 'crate'");
    bad(&s, "frame\nmaterial glass reflect 0.5\n", 2, "unknown material 'glass'");
    bad(&s, "frame\nadd box\n", 2, "cannot add object 'box': it is present");
    bad(&s, "frame\nremove shade\n", 2, "cannot remove object 'shade': it is absent");
    bad(&s, "frame\nremove box\nframe\nadd box\nframe\nadd box\n", 6, "cannot add");
    bad(&s, "frame\nadd shade\nremove shade\nremove shade\n", 4, "cannot remove");
    bad(&s, "frame\nrotate box 0 0 0 30\n", 2, "axis must not be zero");
    bad(&s, "frame\nrotate box 0 1e-320 0 30\n", 2, "axis must not be zero");
    bad(&s, "frame\nrotate box 0 1 0\n", 2, "missing number: angle");
    bad(&s, "frame\nrotate box 0 1 0 30 around 1 2 3\n", 2, "expected about");
    bad(&s, "frame\nrotate box 0 1 0 30 about 1 2\n", 2, "missing number: rotation centre");
    bad(&s, "frame\nmove box 1 x 0\n", 2, "'x' is not a number");
    bad(&s, "frame\nmove box 1 inf 0\n", 2, "must be finite");
    bad(&s, "frame\nmove box 1 0\n", 2, "missing number");
    bad(&s, "frame\nmove box 1 0 0 0\n", 2, "unexpected '0'");
    bad(&s, "frame\nmove\n", 2, "needs an object name");
    bad(&s, "frame\nmaterial w reflect 1.5\n", 2, "reflectance must be from 0 to 1");
    bad(&s, "frame\nmaterial w reflect 0.5 emit -1\n", 2, "emission must be from 0");
    bad(&s, "frame\nmaterial w reflect 0.5 0.5\n", 2, "1 value (grey) or 3");
    bad(&s, "frame\nmaterial w emit 1\n", 2, "needs: reflect");
    bad(&s, "frame\nmaterial w reflect 0.5 glow\n", 2, "unexpected 'glow'");
    bad(&s, "frame 2\n", 1, "unexpected '2'");
    bad(&s, "frame\nteleport box\n", 2, "unknown change 'teleport'");
    bad(&s, "frame\nmove box 1 0 0\xc3\xa9\n", 2, "");
    rad_scene_free(&s);
    return tap_done();
}
