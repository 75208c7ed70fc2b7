/* animator.c -- the changes asked for from the page, run frame by frame by
 * the redistribution engine (George, Sillion & Greenberg 1990; animate.h)
 * in a thread of its own.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The thread builds the animation of the scene (rad_anim_create: every
 * surface meshed, F filled, frame 0 converged) when the session starts,
 * while the methods race on the page, and then waits for frames.  A
 * request's changes are checked against the session's change file
 * (history.c) and appended to it under the lock; the thread runs each new
 * frame with rad_anim_next on the whole text, so the frames run exactly as
 * `radiosity animate` runs the same file.  Before a frame runs, the frame
 * that undoes it is written from the scene as it then is and pushed on
 * the undo stack; an undo appends the top of that stack as a frame of its
 * own.  From the first frame on, the picture is the animation's: each
 * shot (at most VIEW_ANIM_HZ a second, the first of a frame, the last of
 * its direct light's stage, which a pause for the rest of the form
 * factors follows, and the frame's last) publishes the radiosity of
 * every element (absent ones 0, not drawn), and each frame
 * publishes its moved geometry once, raising `geometry` so that the page
 * fetches it again.  When a frame has converged, element_now holds its B
 * numbered as a fresh solve of its scene numbers it
 * (rad_anim_present_result), for a client that compares the two.
 *
 * A frame that fails as it runs (not converged within the options'
 * max_shots, or out of memory) leaves the engine half changed.  So the
 * engine's state is kept before each frame, as its change log
 * (rad_anim_log_write, in memory: B, dB, H and the pending amounts to 17
 * digits, which read back to the same doubles).  When the frame fails,
 * it and the frames queued after it leave the change file, and
 * rad_anim_resume builds the animation again at the frame before, from
 * that log and the shortened file (frame_back): F filled again as a fresh
 * solve fills it, the radiosity as it was, bit for bit.  The session's
 * changes end only when that fails too.
 */
#include <config.h>

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "view/viewint.h"
#include "radiosity/animate.h"
#include "radiosity/mesh.h"
#include "util/util.h"

#define VIEW_ANIM_HZ 40.0       /* pictures a second at most */
#define VIEW_MAX_QUEUED 64      /* frames waiting at most */

typedef struct anim_pub {
    view_session *s;
    double last;                /* when the last picture was published */
    int frame;                  /* the frame whose geometry was published */
    double *Bv;                 /* vertex scratch of the animation's mesh */
    double emitted;             /* frame 0's emitted power: the unit of unshot */
} anim_pub;

/* The animation's geometry as the scene to draw (lock held). */
static int publish_geometry(view_session *s, const rad_anim *a)
{
    jbuf b;
    jb_init(&b);
    s->geometry++; /* the number the JSON carries */
    if (view_scene_json(s, rad_anim_mesh(a), rad_anim_scene(a), rad_anim_present(a), &b)) {
        jb_free(&b);
        s->geometry--;
        return -1;
    }
    free(s->scene_json);
    s->scene_json = b.s;
    s->scene_len = b.len;
    return 0;
}

/* The animation's radiosity to the page (takes the lock). */
static int publish_anim(anim_pub *p, const rad_anim *a, long shots, double unshot, int stage)
{
    view_session *s = p->s;
    const rad_mesh *m = rad_anim_mesh(a);
    const size_t n = (size_t)m->nelements, nv = (size_t)m->nvertices;
    const double *B = rad_anim_radiosity(a);
    rad_error err;
    rad_smooth_vertices_rule(m, B, p->Bv, s->opt.vertex_rule);
    if (rad_smooth_across(rad_anim_scene(a), m, s->opt.crease, p->Bv, &err) != RAD_OK)
        return -1;
    pthread_mutex_lock(&s->lock);
    int bad = view_reserve(s, n, nv);
    if (!bad && p->frame != rad_anim_frame(a)) {
        bad = publish_geometry(s, a);
        p->frame = rad_anim_frame(a);
    }
    if (!bad) {
        for (size_t i = 0; i < n; i++)
            for (int k = 0; k < RAD_BANDS; k++)
                s->element_b[3 * i + (size_t)k] = B[i + (size_t)k * n];
        for (size_t v = 0; v < nv; v++)
            for (int k = 0; k < RAD_BANDS; k++)
                s->vertex_b[3 * v + (size_t)k] = p->Bv[v + (size_t)k * nv];
        s->shown_elements = (int)n;
        s->shown_vertices = (int)nv;
        if (!s->animate) /* a method waiting for its next step ends */
            pthread_cond_broadcast(&s->wake);
        s->animate = 1;
        s->leaves_shown = 0; /* the animation's mesh is drawn */
        s->running = s->pending = 0; /* the race stops: its F is frame 0's */
        s->frame_shots = (int)shots;
        s->frame_stage = stage;
        s->unshot = unshot;
        s->rms = NAN;
        s->shooter = -1;
        s->version++;
        pthread_cond_broadcast(&s->changed);
    }
    pthread_mutex_unlock(&s->lock);
    return bad;
}

static int stopping(view_session *s)
{
    pthread_mutex_lock(&s->lock);
    const int stop = s->stopping;
    pthread_mutex_unlock(&s->lock);
    return stop;
}

/* The animation's fill reports here: silent (the terminal is the
 * server's), and stopped with the server. */
static int on_progress(void *user, const char *stage, double done, double total)
{
    (void)stage;
    (void)done;
    (void)total;
    return stopping(user);
}

static int on_shot(void *user, const rad_anim_shot *shot)
{
    anim_pub *p = user;
    if (shot->frame == 0)
        return stopping(p->s); /* frame 0: the race is on the page */
    const double now = radi_seconds();
    const int stage = shot->direct == 1 ? VIEW_STAGE_DIRECT
                      : shot->direct == 2 ? VIEW_STAGE_FORM_FACTORS : VIEW_STAGE_SHOOTING;
    if (now - p->last >= 1 / VIEW_ANIM_HZ || p->frame != shot->frame || shot->direct == 2) {
        if (publish_anim(p, shot->anim, shot->step, shot->unshot / p->emitted, stage) != 0)
            return 1;
        p->last = now;
    }
    return stopping(p->s);
}

/* The frame just run, numbered as a fresh solve of its scene numbers it,
 * into element_now (takes the lock). */
static int frame_done(view_session *s, const rad_anim *a, const rad_anim_report *rep)
{
    rad_mesh pm;
    double *B = NULL;
    rad_error err;
    if (rad_anim_present_result(a, &pm, &B, &err) != RAD_OK)
        return -1;
    const size_t n = (size_t)pm.nelements;
    double *now = malloc(sizeof *now * 3 * (n ? n : 1));
    for (size_t i = 0; now && i < n; i++)
        for (int k = 0; k < RAD_BANDS; k++)
            now[3 * i + (size_t)k] = B[i + (size_t)k * n];
    rad_mesh_free(&pm);
    free(B);
    if (!now)
        return -1;
    pthread_mutex_lock(&s->lock);
    free(s->element_now);
    s->element_now = now;
    s->n_now = (int)n;
    s->frame_converged = rep->converged;
    pthread_mutex_unlock(&s->lock);
    return 0;
}

/* A copy of the session's change file (lock held), so that it is parsed
 * after the lock is let go; NULL when memory ran out. */
static char *changes_copy(const view_session *s, size_t *len)
{
    *len = s->changes.len;
    char *text = malloc(*len ? *len : 1);
    if (text && *len)
        memcpy(text, s->changes.s, *len);
    return text;
}

/* That copy parsed against the scene, then freed (NULL: out of memory). */
static rad_status changes_parse(const view_session *s, char *text, size_t len, rad_changes *ch,
                                rad_error *err)
{
    const rad_status st = text ? rad_changes_parse(ch, s->scene, text, len, "session", err)
                               : radi_fail(err, RAD_ERR_NOMEM, "out of memory for the changes");
    free(text);
    return st;
}

/* The state before a frame, as the change log (rad_anim_log_write) in
 * memory: what rad_anim_resume needs to bring the animation back to it
 * when the frame fails.  NULL when memory ran out: the frame then runs
 * with no way back. */
static char *state_log(const rad_anim *a, size_t *len)
{
    char *buf = NULL;
    size_t n = 0;
    FILE *f = open_memstream(&buf, &n);
    if (!f)
        return NULL;
    const rad_status st = rad_anim_log_write(f, a);
    if (fclose(f) != 0 || st != RAD_OK) {
        free(buf);
        return NULL;
    }
    *len = n;
    return buf;
}

/* Frames k and after leave the session (lock held): the change file ends
 * before frame k, and an undo among them goes back on the stack (its
 * place there is still allocated: it was taken from it). */
static void drop_frames(view_session *s, int k)
{
    s->changes.len = s->frame_start[k];
    s->changes.s[s->changes.len] = '\0';
    if (s->undo_frame >= k) {
        s->inverse[s->ninverse++] = s->undo_running;
        jb_init(&s->undo_running);
        s->undo_frame = 0;
    }
    s->frames = k - 1;
}

/* Why frames k and after were dropped, into the state, published as a
 * new version (lock held). */
static void say_dropped(view_session *s, int k, int queued, const char *why, const char *then)
{
    char more[64] = "";
    if (queued > 0)
        snprintf(more, sizeof more, ", with the %d frame%s queued after it", queued,
                 queued == 1 ? "" : "s");
    snprintf(s->anim_failure, sizeof s->anim_failure,
             "frame %d failed and was dropped%s; %s frame %d: %.120s", k, more, then, k - 1,
             why);
    s->version++;
    pthread_cond_broadcast(&s->changed);
}

/* Frame k failed before it changed anything (lock held): it and the
 * frames queued after it go, and the animation stays at frame k - 1. */
static void drop_unrun(view_session *s, int k, const char *why)
{
    const int queued = s->frames - k;
    drop_frames(s, k);
    say_dropped(s, k, queued, why, "the scene is as after");
}

/* Frame k failed with `failed` after it began to change *ap: it and the
 * frames queued after it are dropped, and the animation is built again
 * at frame k - 1 from the state log taken before frame k (lock held on
 * entry and on return, not while F is filled again).  The half-changed
 * animation is freed first: two matrices F at once could fail for want
 * of memory where one did not.  0, or -1 when going back failed too (the
 * changes end) or the server stops. */
static int frame_back(view_session *s, anim_pub *p, rad_anim **ap, const rad_anim_options *opt,
                      int k, char *log, size_t loglen, const rad_error *failed)
{
    const int queued = s->frames - k;
    const double unshot = s->unshot_done;
    const int shots = s->shots_done;
    drop_frames(s, k);
    s->anim_state = 0; /* requests wait, as while the animation was built */
    say_dropped(s, k, queued, failed->message, "building the animation again at");
    size_t len;
    char *text = changes_copy(s, &len);
    pthread_mutex_unlock(&s->lock);
    rad_anim_free(*ap);
    *ap = NULL;
    rad_changes ch;
    rad_error err;
    rad_anim *b = NULL;
    rad_status st = changes_parse(s, text, len, &ch, &err);
    if (st == RAD_OK) {
        FILE *f = fmemopen(log, loglen, "r");
        st = f ? rad_anim_resume(&b, s->scene, &ch, f, "state", opt, &err)
               : radi_fail(&err, RAD_ERR_NOMEM, "out of memory for the state");
        if (f)
            fclose(f);
        rad_changes_free(&ch);
    }
    /* frame k - 1 had converged (a frame of the session runs until it
     * does, or fails): its radiosity and element table as then */
    rad_anim_report done;
    memset(&done, 0, sizeof done);
    done.converged = 1;
    if (st == RAD_OK && (publish_anim(p, b, shots, unshot, VIEW_STAGE_DONE) != 0 ||
                         frame_done(s, b, &done) != 0))
        st = radi_fail(&err, RAD_ERR_NOMEM, "out of memory publishing frame %d", k - 1);
    pthread_mutex_lock(&s->lock);
    if (st != RAD_OK) {
        rad_anim_free(b);
        if (!s->stopping) {
            s->anim_state = -1;
            snprintf(s->anim_failure, sizeof s->anim_failure,
                     "frame %d failed (%.80s), and going back to frame %d failed: %.80s", k,
                     failed->message, k - 1, err.message);
        }
        return -1;
    }
    *ap = b;
    s->anim_state = 1;
    say_dropped(s, k, queued, failed->message, "the scene is as after");
    return 0;
}

/* Room on the undo stack for one more frame (lock held), taken before a
 * frame runs so that keeping its inverse cannot fail after it ran.  0,
 * or -1 when memory ran out. */
static int reserve_undo(view_session *s)
{
    if (s->ninverse < s->cap_inverse)
        return 0;
    const int cap = s->cap_inverse ? 2 * s->cap_inverse : 16;
    jbuf *more = realloc(s->inverse, sizeof *more * (size_t)cap);
    if (!more)
        return -1;
    s->inverse = more;
    s->cap_inverse = cap;
    return 0;
}

/* Frame k has run (lock held): its undo frame on the stack (room for it
 * was reserved by reserve_undo), unless it was one. */
static void frame_kept(view_session *s, int k, int undo, jbuf *inv)
{
    if (undo) {
        jb_free(&s->undo_running);
        s->undo_frame = 0;
    } else {
        s->inverse[s->ninverse++] = *inv;
    }
    s->anim_failure[0] = '\0'; /* a frame dropped before is no longer the news */
    s->unshot_done = s->unshot;
    s->shots_done = s->frame_shots;
    s->applied = k;
    s->version++;
    pthread_cond_broadcast(&s->changed);
}

/* Run frame k of the session's change file (lock held on entry and on
 * return, not while the frame runs).  A frame that fails is dropped, with
 * the frames queued after it, and the animation goes back to the frame
 * before (frame_back); 0 then too.  -1 when the changes end (the failure
 * set) or the server stops. */
static int run_frame(view_session *s, anim_pub *p, rad_anim **ap, const rad_anim_options *opt,
                     int k)
{
    const int undo = s->is_undo[k];
    if (!undo && reserve_undo(s) != 0) {
        drop_unrun(s, k, "out of memory for its undo frame");
        return 0;
    }
    size_t len;
    char *text = changes_copy(s, &len);
    pthread_mutex_unlock(&s->lock);
    rad_changes ch;
    rad_anim_report rep;
    rad_error err;
    jbuf inv;
    jb_init(&inv);
    size_t loglen = 0;
    char *log = NULL;
    int ran = 0; /* rad_anim_next was called: the animation may be half changed */
    rad_status st = changes_parse(s, text, len, &ch, &err);
    if (st == RAD_OK) {
        if (!undo && view_inverse_frame(&inv, rad_anim_scene(*ap), &ch, k) != 0)
            st = radi_fail(&err, RAD_ERR_NOMEM, "out of memory for the undo frame");
        if (st == RAD_OK) {
            log = state_log(*ap, &loglen);
            ran = 1;
            st = rad_anim_next(*ap, &ch, &rep, &err);
        }
        rad_changes_free(&ch);
    }
    if (st == RAD_OK &&
        (publish_anim(p, *ap, rep.shots, rep.unshot / p->emitted, VIEW_STAGE_DONE) != 0 ||
         frame_done(s, *ap, &rep) != 0))
        st = radi_fail(&err, RAD_ERR_NOMEM, "out of memory publishing frame %d", k);
    pthread_mutex_lock(&s->lock);
    int r = 0;
    if (st == RAD_OK) {
        frame_kept(s, k, undo, &inv);
    } else {
        jb_free(&inv);
        if (s->stopping) {
            r = -1;
        } else if (!ran) {
            drop_unrun(s, k, err.message);
        } else if (log) {
            r = frame_back(s, p, ap, opt, k, log, loglen, &err);
        } else {
            s->anim_state = -1;
            snprintf(s->anim_failure, sizeof s->anim_failure, "%.250s", err.message);
            r = -1;
        }
    }
    free(log);
    return r;
}

static void *animator(void *arg)
{
    view_session *s = arg;
    anim_pub p = {s, 0, 0, NULL, 1};
    rad_anim *a = NULL;
    rad_anim_report rep;
    rad_error err;
    rad_anim_options opt = s->anim_opt;
    opt.on_shot = on_shot;
    opt.shot_user = &p;
    opt.ff.progress = on_progress;
    opt.ff.progress_user = s;
    rad_status st = rad_anim_create(&a, s->scene, &opt, &rep, &err);
    if (st == RAD_OK &&
        !(p.Bv = malloc(sizeof *p.Bv * RAD_BANDS * (size_t)(rad_anim_mesh(a)->nvertices + 1))))
        st = radi_fail(&err, RAD_ERR_NOMEM, "out of memory for the animation");
    pthread_mutex_lock(&s->lock);
    if (st != RAD_OK && !s->stopping) {
        s->anim_state = -1;
        snprintf(s->anim_failure, sizeof s->anim_failure, "%.250s", err.message);
    } else if (st == RAD_OK) {
        s->anim_state = 1;
        p.emitted = rep.emitted > 0 ? rep.emitted : 1;
        s->unshot_done = rep.unshot / p.emitted;
        s->shots_done = (int)rep.shots;
    }
    s->version++;
    pthread_cond_broadcast(&s->changed);
    while (st == RAD_OK && !s->stopping) {
        if (s->applied == s->frames) {
            pthread_cond_wait(&s->anim_wake, &s->lock);
            continue;
        }
        if (run_frame(s, &p, &a, &opt, s->applied + 1) != 0)
            break;
    }
    pthread_mutex_unlock(&s->lock);
    rad_anim_free(a);
    free(p.Bv);
    return NULL;
}

int view_animator_start(view_session *s, rad_error *err)
{
    if (pthread_create(&s->animator, NULL, animator, s) != 0)
        return radi_fail(err, RAD_ERR_NOMEM, "cannot start the animation's thread"), -1;
    s->animator_started = 1;
    return 0;
}

void view_animator_stop(view_session *s)
{
    pthread_mutex_lock(&s->lock);
    s->stopping = 1;
    pthread_cond_broadcast(&s->anim_wake);
    pthread_mutex_unlock(&s->lock);
    if (s->animator_started)
        pthread_join(s->animator, NULL);
    s->animator_started = 0;
}

/* Room for frame k's undo mark and offset (lock held). */
static int reserve_frames(view_session *s, int k)
{
    unsigned char *u = realloc(s->is_undo, (size_t)k + 2);
    if (u) {
        memset(u + s->frames + 1, 0, (size_t)(k - s->frames) + 1);
        s->is_undo = u;
    }
    size_t *f = u ? realloc(s->frame_start, sizeof *f * ((size_t)k + 2)) : NULL;
    if (f)
        s->frame_start = f;
    return u && f ? 0 : -1;
}

/* Append req (nf frames, checked) to the session (lock held). */
static int append(view_session *s, const char *req, size_t len, int nf, int undo)
{
    const size_t from = s->changes.len;
    if (reserve_frames(s, s->frames + nf) != 0 || view_history_append(&s->changes, req, len))
        return -1;
    if (view_history_frames(s->changes.s, from, s->changes.len, s->frame_start + s->frames + 1,
                            nf) != nf) {
        s->changes.len = from; /* cannot happen: the parser counted nf */
        return -1;
    }
    for (int k = 1; k <= nf; k++)
        s->is_undo[s->frames + k] = (unsigned char)undo;
    s->frames += nf;
    s->version++;
    pthread_cond_broadcast(&s->anim_wake);
    pthread_cond_broadcast(&s->changed);
    return 0;
}

int view_queue_changes(view_session *s, const char *req, size_t len, int limited, char *why,
                       size_t cap)
{
    int nf = 0, code = 0, checked;
    pthread_mutex_lock(&s->lock);
    /* frames past the queue's room are refused below, not meshed first */
    const int room = limited ? VIEW_MAX_QUEUED - (s->frames - s->applied) : INT_MAX;
    if (s->anim_state < 0) {
        snprintf(why, cap, "the animation failed: %s", s->anim_failure);
        code = 503;
    } else if (limited && s->frames - s->applied >= VIEW_MAX_QUEUED) {
        snprintf(why, cap, "%d frames are waiting to run: try again when they have",
                 s->frames - s->applied);
        code = 429;
    } else if ((checked = view_history_check(s->scene, s->changes.s ? s->changes.s : "",
                                             s->changes.len, req, len, !limited, room, &nf, why,
                                             cap)) != 0) {
        code = checked == -2 ? 500 : 400;
    } else if (limited && s->frames - s->applied + nf > VIEW_MAX_QUEUED) {
        snprintf(why, cap, "%d frames at once: at most %d may wait", nf, VIEW_MAX_QUEUED);
        code = 429;
    } else if (append(s, req, len, nf, 0) != 0) {
        snprintf(why, cap, "out of memory for the changes");
        code = 500;
    }
    pthread_mutex_unlock(&s->lock);
    return code;
}

int view_queue_undo(view_session *s, char *why, size_t cap)
{
    int code = 0, nf = 0;
    pthread_mutex_lock(&s->lock);
    if (s->anim_state <= 0 || s->frames != s->applied) {
        snprintf(why, cap, "%s", s->anim_state < 0    ? "the animation failed"
                                 : s->anim_state == 0 ? "the animation is still being built"
                                                      : "frames are still running: undo when "
                                                        "they are done");
        code = 409;
    } else if (s->ninverse == 0) {
        snprintf(why, cap, "nothing to undo");
        code = 409;
    } else {
        jbuf *inv = &s->inverse[s->ninverse - 1];
        if (view_history_check(s->scene, s->changes.s ? s->changes.s : "", s->changes.len,
                               inv->s, inv->len, 1, INT_MAX, &nf, why, cap) != 0)
            code = 500; /* the inverse of a frame that ran: cannot fail */
        else if (append(s, inv->s, inv->len, nf, 1) != 0) {
            snprintf(why, cap, "out of memory for the changes");
            code = 500;
        } else { /* kept until its frame has run: a frame dropped gives it back */
            s->undo_running = *inv;
            s->undo_frame = s->frames;
            s->ninverse--;
        }
    }
    pthread_mutex_unlock(&s->lock);
    return code;
}
