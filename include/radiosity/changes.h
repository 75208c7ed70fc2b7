/* changes.h -- the change file of `radiosity animate`.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A change file (radiosity-scene(5), "CHANGE FILES") says how a scene with
 * objects changes from frame to frame (George, Sillion & Greenberg 1990):
 *
 *     move NAME DX DY DZ
 *     rotate NAME AX AY AZ DEGREES [about CX CY CZ]
 *     remove NAME
 *     add NAME
 *     material MATNAME reflect R G B [emit R G B]     (one value: grey)
 *     frame
 *
 * Frame 0 is the scene as given; each `frame` line starts the next frame,
 * so changes stand after a `frame` line.  The reader checks every line
 * against the scene before any work: unknown objects and materials, adding
 * an object that is present or removing one that is absent at that point
 * of the file (presence is followed frame by frame from the scene's
 * `absent` flags), a zero rotation axis, numbers that are not finite,
 * reflectances outside [0, 1], negative emission; each error reads
 * "FILE:LINE: what is wrong".  Lengths are the scene's, angles degrees,
 * rotations counter-clockwise about the axis (right-hand rule).
 */
#ifndef RAD_CHANGES_H
#define RAD_CHANGES_H

#include "radiosity/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rad_change_kind {
    RAD_CHANGE_MOVE = 0,        /* translate the object by v */
    RAD_CHANGE_ROTATE,          /* rotate it by degrees about the unit axis v
                                   through center (default: its centroid) */
    RAD_CHANGE_REMOVE,
    RAD_CHANGE_ADD,
    RAD_CHANGE_MATERIAL         /* new reflect (and emit, if has_emit) */
} rad_change_kind;

typedef struct rad_change {
    rad_change_kind kind;
    int frame;                  /* 1, 2, ...: the frame it belongs to */
    int object;                 /* index into the scene's objects, or -1 */
    int material;               /* MATERIAL: index into the scene's materials */
    rad_vec3 v;                 /* MOVE: displacement; ROTATE: unit axis */
    double degrees;             /* ROTATE */
    int has_center;             /* ROTATE: 1 when `about` was given */
    rad_vec3 center;
    double reflect[RAD_BANDS];  /* MATERIAL */
    int has_emit;               /* MATERIAL: 0 keeps the material's emission */
    double emit[RAD_BANDS];
    int line;                   /* in the change file */
} rad_change;

typedef struct rad_changes {
    char *filename;
    rad_change *changes;        /* in file order (so by frame) */
    int nchanges;
    int nframes;                /* frames after frame 0 (the `frame` lines) */
} rad_changes;

/* Read a change file ("-": standard input) for `scene`.  On failure
 * *changes is left empty and err says FILE:LINE: why. */
RAD_API rad_status rad_changes_load(rad_changes *changes, const rad_scene *scene,
                                    const char *path, rad_error *err);
/* The same from text in memory; `name` is used in messages. */
RAD_API rad_status rad_changes_parse(rad_changes *changes, const rad_scene *scene,
                                     const char *text, size_t len, const char *name,
                                     rad_error *err);
RAD_API void rad_changes_free(rad_changes *changes);

/* Apply the changes of frame `frame` to `scene` in place, in file order:
 * vertices moved or turned, objects' absent flags set, materials
 * replaced.  dirty (nobjects entries, may be NULL) gets 1 for
 * each object moved, turned, added or removed.  The frame's changes are
 * found by bisection, so `changes` must be by frame, as the reader makes
 * it. */
RAD_API void rad_changes_apply(rad_scene *scene, const rad_changes *changes, int frame,
                               unsigned char *dirty);

#ifdef __cplusplus
}
#endif

#endif /* RAD_CHANGES_H */
