/* history.c -- the session's change file: every frame asked for so far, a
 * request checked against it, and the frame that undoes one.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The session keeps its changes as the text of a change file
 * (radiosity-scene(5), CHANGE FILES): a `frame` line, then that frame's
 * changes, frame after frame, in the order they were asked for (undo
 * frames included).  `radiosity animate SCENE FILE` replays the text as
 * the session ran it.  A request is checked by reading the whole text
 * with the request after it (rad_changes_parse), so that what the parser
 * follows from frame to frame (whether an object is in the scene) is
 * checked as the frames will run; its line numbers are then those of the
 * request's own text.  Each new frame's scene is then meshed as the
 * engine will mesh it (radi_anim_check_frames), so that a frame that
 * could not even be meshed is refused with the request, in the words the
 * engine would use, rather than failing when it runs.
 *
 * Undo is a frame of the inverse changes in the reverse order, written
 * from the scene as it is just before the frame runs (inverse_frame):
 *   move NAME D           ->  move NAME -D
 *   rotate NAME A T [about C]  ->  rotate NAME A -T [about C]
 *                         (about the centroid when none is given: a
 *                         rotation about the centroid keeps it in place)
 *   remove NAME <-> add NAME
 *   material M ...        ->  material M reflect (as it was) emit (as it was)
 * Numbers are written with 17 digits, so that the inverse is exact where
 * the arithmetic is (a move), and within rounding where it is not.
 */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "anim/anim.h"
#include "view/viewint.h"
#include "radiosity/changes.h"

/* The line number in a parser message "NAME:LINE: ..." moved back by
 * `shift` (lines of the history before the request), into out. */
static void shift_line(const char *msg, const char *name, int shift, char *out, size_t cap)
{
    const size_t k = strlen(name);
    char *end;
    if (!strncmp(msg, name, k) && msg[k] == ':') {
        const long line = strtol(msg + k + 1, &end, 10);
        if (end != msg + k + 1 && *end == ':' && line > shift) {
            snprintf(out, cap, "%s:%ld:%s", name, line - shift, end + 1);
            return;
        }
    }
    snprintf(out, cap, "%s", msg);
}

/* Is the first token of text[0..n), after blank and comment lines, the
 * line `frame`?  The change reader's blanks: space, \t, \r, \f, \v. */
static int starts_frame(const char *s, size_t n)
{
    static const char blank[] = " \t\r\f\v\n";
    size_t i = 0;
    while (i < n && s[i] && (strchr(blank, s[i]) || s[i] == '#'))
        if (s[i++] == '#')
            while (i < n && s[i] != '\n' && s[i] != '\r')
                i++;
    return n - i >= 5 && !strncmp(s + i, "frame", 5) &&
           (n - i == 5 || (s[i + 5] && (strchr(blank, s[i + 5]) || s[i + 5] == '#')));
}

/* Is the line at s (to its '\n' or n) a `frame` line: its first word
 * "frame", then the line's end, a blank or a comment? */
static int frame_line(const char *s, size_t n)
{
    size_t i = 0;
    while (i < n && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\f' || s[i] == '\v'))
        i++;
    return n - i >= 5 && !strncmp(s + i, "frame", 5) &&
           (n - i == 5 || strchr(" \t\r\f\v\n#", s[i + 5]));
}

int view_history_frames(const char *s, size_t from, size_t n, size_t *starts, int cap)
{
    int k = 0;
    for (size_t i = from; i < n; i++)
        if ((i == from || s[i - 1] == '\n') && frame_line(s + i, n - i)) {
            if (k < cap)
                starts[k] = i;
            k++;
        }
    return k;
}

static int count_lines(const char *s, size_t n)
{
    int k = 0;
    for (size_t i = 0; i < n; i++)
        k += s[i] == '\n';
    return k;
}

int view_history_check(const rad_scene *scene, const char *history, size_t hlen,
                       const char *req, size_t rlen, int empty_ok, int max_frames, int *frames,
                       char *why, size_t cap)
{
    const int starts = starts_frame(req, rlen);
    static const char head[] = "frame\n";
    const size_t hk = starts ? 0 : sizeof head - 1;
    char *text = malloc(hlen + hk + rlen + 2);
    if (!text)
        return snprintf(why, cap, "out of memory"), -2;
    memcpy(text, history, hlen);
    memcpy(text + hlen, head, hk);
    memcpy(text + hlen + hk, req, rlen);
    size_t n = hlen + hk + rlen;
    if (n == 0 || text[n - 1] != '\n')
        text[n++] = '\n';
    rad_changes all, before;
    rad_error err;
    rad_status st = RAD_OK; /* of the frames' meshes */
    int ok = rad_changes_parse(&all, scene, text, n, "request", &err) == RAD_OK;
    if (!ok)
        shift_line(err.message, "request", count_lines(history, hlen) + (hk ? 1 : 0), why, cap);
    else if (rad_changes_parse(&before, scene, history, hlen, "session", &err) != RAD_OK) {
        snprintf(why, cap, "%s", err.message); /* cannot happen: it was checked */
        rad_changes_free(&all);
        ok = 0;
    } else {
        *frames = all.nframes - before.nframes;
        const int added = all.nchanges - before.nchanges;
        if (*frames < 1 || (!empty_ok && added == 0)) {
            snprintf(why, cap, "request: no change (a change file's lines: move, rotate, "
                               "remove, add, material, frame)");
            ok = 0;
        } else if (*frames <= max_frames && /* (more: the caller refuses them) */
                   (st = radi_anim_check_frames(scene, &all, before.nframes, &err)) != RAD_OK) {
            if (st == RAD_ERR_NOMEM)
                snprintf(why, cap, "out of memory");
            else
                shift_line(err.message, "request", count_lines(history, hlen) + (hk ? 1 : 0),
                           why, cap);
            ok = 0;
        }
        rad_changes_free(&before);
        rad_changes_free(&all);
    }
    free(text);
    return ok ? 0 : st == RAD_ERR_NOMEM ? -2 : -1;
}

/* Append text[0..n) to b as the frame after what b holds. */
int view_history_append(jbuf *b, const char *req, size_t rlen)
{
    if (!starts_frame(req, rlen))
        jb_printf(b, "frame\n");
    jb_printf(b, "%.*s", (int)rlen, req);
    if (rlen == 0 || req[rlen - 1] != '\n')
        jb_printf(b, "\n");
    return b->failed ? -1 : 0;
}

static void triple(jbuf *b, const double *x)
{
    jb_printf(b, " %.17g %.17g %.17g", x[0], x[1], x[2]);
}

/* The inverse of change c, as a line of b (scene: as before the frame). */
static void inverse_change(jbuf *b, const rad_scene *scene, const rad_change *c)
{
    const char *obj = c->object >= 0 ? scene->objects[c->object].name : "";
    switch (c->kind) {
    case RAD_CHANGE_MOVE:
        jb_printf(b, "move %s %.17g %.17g %.17g\n", obj, -c->v.x, -c->v.y, -c->v.z);
        break;
    case RAD_CHANGE_ROTATE:
        jb_printf(b, "rotate %s %.17g %.17g %.17g %.17g", obj, c->v.x, c->v.y, c->v.z,
                  -c->degrees);
        if (c->has_center)
            jb_printf(b, " about %.17g %.17g %.17g", c->center.x, c->center.y, c->center.z);
        jb_printf(b, "\n");
        break;
    case RAD_CHANGE_REMOVE:
        jb_printf(b, "add %s\n", obj);
        break;
    case RAD_CHANGE_ADD:
        jb_printf(b, "remove %s\n", obj);
        break;
    case RAD_CHANGE_MATERIAL: {
        const rad_material *m = &scene->materials[c->material];
        jb_printf(b, "material %s reflect", m->name);
        triple(b, m->reflect);
        jb_printf(b, " emit");
        triple(b, m->emit);
        jb_printf(b, "\n");
        break;
    }
    }
}

int view_inverse_frame(jbuf *b, const rad_scene *scene, const rad_changes *ch, int frame)
{
    jb_printf(b, "frame\n");
    for (int k = ch->nchanges - 1; k >= 0 && ch->changes[k].frame >= frame; k--)
        if (ch->changes[k].frame == frame) /* (the changes are by frame) */
            inverse_change(b, scene, &ch->changes[k]);
    return b->failed ? -1 : 0;
}
