/* anim.h -- the anim module's face to the modules after it (src/MODULES):
 * a frame's changes checked ahead of running them.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The animation itself is the installed API (include/radiosity/animate.h).
 * What is here is for a program that takes change frames one request at a
 * time (the live viewer) and must refuse a frame that the animation could
 * not run, with the message the animation would give.
 */
#ifndef RAD_ANIM_H
#define RAD_ANIM_H

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/changes.h"

/* Frames from + 1 .. ch->nframes of ch, after the frames before them,
 * meshed as the animation meshes them (animframe.c).  RAD_OK; or the
 * first refused frame's error, blamed on a line of ch as the animation
 * blames it; or RAD_ERR_NOMEM. */
rad_status radi_anim_check_frames(const rad_scene *scene, const rad_changes *ch, int from,
                                  rad_error *err);

#endif
