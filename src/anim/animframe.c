/* animframe.c -- a frame's scene: the animation's copy of the scene, the
 * line blamed when a frame's changes make a mesh the scene's checks
 * refuse, and that check made ahead of running the frames.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The animation keeps every surface of the scene, present or not, and
 * meshes them all each frame: an absent object keeps its elements, so
 * that adding it back changes presence, not the element count
 * (animate.c).  A move the change parser takes can still carry an element
 * out of double's range (by 1e300: an element's area is then NaN); the
 * mesh refuses that frame, and the animation with it.  A frame that moves
 * or turns nothing keeps the geometry of the frame before, so only frames
 * with a move or a rotation need the check ahead.
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "anim/anim.h"
#include "anim/animint.h"
#include "util/util.h"

rad_status radi_anim_copy_scene(rad_scene *out, const rad_scene *in, rad_error *err)
{
    unsigned char *all = malloc((size_t)in->nobjects + 1);
    if (!all)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    memset(all, 1, (size_t)in->nobjects + 1);
    rad_status st = rad_scene_present_copy(in, all, out, err);
    for (int o = 0; st == RAD_OK && o < in->nobjects; o++)
        out->objects[o].absent = in->objects[o].absent;
    free(all);
    return st;
}

/* (animint.h) */
void radi_anim_blame_changes(const rad_changes *ch, int frame, rad_error *err)
{
    int line = 0;
    for (int k = 0; k < ch->nchanges; k++) {
        const rad_change *c = &ch->changes[k];
        if (c->frame == frame &&
            (!line || c->kind == RAD_CHANGE_MOVE || c->kind == RAD_CHANGE_ROTATE))
            line = c->line;
    }
    char was[RAD_ERRMSG_MAX];
    memcpy(was, err->message, sizeof was);
    was[sizeof was - 1] = '\0';
    radi_fail(err, err->status, "%s:%d: frame %d: after its changes, %s", ch->filename, line,
              frame, was);
}

rad_status radi_anim_check_frames(const rad_scene *scene, const rad_changes *ch, int from,
                                  rad_error *err)
{
    rad_scene sc;
    rad_status st = radi_anim_copy_scene(&sc, scene, err);
    if (st != RAD_OK)
        return st;
    int k = 0; /* the changes are by frame (changes.h): one pass finds each frame's */
    for (int f = 1; st == RAD_OK && f <= ch->nframes; f++) {
        rad_changes_apply(&sc, ch, f, NULL);
        int moves = 0;
        for (; k < ch->nchanges && ch->changes[k].frame <= f; k++)
            moves |= ch->changes[k].frame == f && (ch->changes[k].kind == RAD_CHANGE_MOVE ||
                                                   ch->changes[k].kind == RAD_CHANGE_ROTATE);
        rad_mesh m;
        if (f <= from || !moves)
            continue;
        if ((st = rad_mesh_build(&m, &sc, err)) == RAD_OK)
            rad_mesh_free(&m);
        else if (st != RAD_ERR_NOMEM)
            radi_anim_blame_changes(ch, f, err);
    }
    rad_scene_free(&sc);
    return st;
}
