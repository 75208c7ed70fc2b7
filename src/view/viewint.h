/* view/viewint.h -- what the viewer's files share (private to view/).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Arrays sent to the page interleave the bands (r, g, b of vertex 0, then
 * of vertex 1, ...); the library's arrays are column-major (band after
 * band), and the copies here turn one into the other.  Radiosity is linear
 * (W m^-2 in the scene's units, as B everywhere); the page applies the
 * exposure and the sRGB curve as `radiosity render` does.
 */
#ifndef RAD_VIEWINT_H
#define RAD_VIEWINT_H

#include <pthread.h>
#include <stddef.h>

#include "view/view.h"
#include "radiosity/mesh.h"
#include "radiosity/animate.h"
#include "radiosity/changes.h"

/* A growable text buffer; failed is set when memory ran out (then every
 * later write is ignored and the text must not be sent). */
typedef struct jbuf {
    char *s;
    size_t len, cap;
    int failed;
} jbuf;

void jb_init(jbuf *b);
void jb_free(jbuf *b);
void jb_printf(jbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Append n bytes of s. */
void jb_put(jbuf *b, const char *s, size_t n);
/* A number with 9 digits (float32 needs 9 for the round trip), with 17
 * when exact, or null for a NaN or an infinity (JSON has neither). */
void jb_num(jbuf *b, double x, int exact);
/* A JSON string: quotes, and the escapes RFC 8259 (section 7) requires. */
void jb_str(jbuf *b, const char *s);

#define VIEW_HISTORY 512        /* points of the error plot kept */
#define VIEW_LANES 4            /* the race's methods: gathering, shooting,
                                   sorted, sorted_ambient (progressive.h) */

/* Where the frame running is (rad_anim_options.direct_first): none
 * running; shooting its direct light's change; that shown while the rest
 * of its form factors are computed; shooting the rest. */
enum { VIEW_STAGE_DONE = 0, VIEW_STAGE_DIRECT, VIEW_STAGE_FORM_FACTORS, VIEW_STAGE_SHOOTING };

typedef struct view_session {
    const rad_scene *scene;
    const rad_mesh *mesh;
    const double *F, *Bref;     /* the converged solution: the error's reference */
    radi_view_options opt;
    double *area, total_area, *rho;
    double *Bv;                 /* the worker's vertex scratch (column-major) */
    pthread_mutex_t lock;
    pthread_cond_t wake;        /* the worker: a command came */
    pthread_cond_t changed;     /* the streams: a new state was published */
    pthread_t worker;
    int worker_started;
    /* commands, under lock */
    int running, stopping, pending, reset_method;
    int streams;                /* event streams open (server.c) */
    double rate;
    /* published, under lock */
    long version;
    int method, shooter;
    long step;
    double unshot, rms, sps;
    double *vertex_b;           /* nvertices x 3, interleaved (lane after
                                   lane in the race) */
    double *element_b;         /* nelements x 3, interleaved */
    int lanes;                  /* 1, or VIEW_LANES in the race */
    int lane_shooter[VIEW_LANES];
    double lane_unshot[VIEW_LANES], lane_rms[VIEW_LANES];
    double history[VIEW_HISTORY][1 + VIEW_LANES]; /* step, each lane's rms */
    int nhistory;
    char failure[256];          /* a step that failed: the worker stops */
    jbuf event;                 /* the state as an event of the streams,
                                   formatted once for version event_version
                                   (server.c, state_event) */
    long event_version;
    double exposure;            /* the converged solution's, fixed */
    /* changes (animator.c), under lock */
    rad_anim_options anim_opt;
    pthread_t animator;
    pthread_cond_t anim_wake;   /* the animator: a frame was queued */
    int animator_started;
    int anim_state;             /* 0: being built, 1: ready, -1: failed */
    char anim_failure[256];
    int animate;                /* 1: the picture is the animation's */
    jbuf changes;               /* the session's change file (history.c) */
    int frames, applied;        /* frames asked for, frames run */
    unsigned char *is_undo;     /* per frame (1-based, room for frames + 1) */
    size_t *frame_start;        /* per frame (1-based): its offset in changes */
    jbuf *inverse;              /* undo: the inverse of frames run, a stack */
    int ninverse, cap_inverse;
    jbuf undo_running;          /* the inverse taken off the stack for frame
                                   undo_frame (0: none), until it has run */
    int undo_frame;
    double unshot_done;         /* unshot and shots of the last frame run */
    int shots_done;
    int frame_shots, frame_converged;
    int frame_stage;            /* of the frame running: VIEW_STAGE_* */
    long geometry;              /* the version of scene_json */
    char *scene_json;           /* the scene as drawn now */
    size_t scene_len;
    size_t cap_elements, cap_vertices; /* of element_b and vertex_b */
    int shown_elements, shown_vertices; /* of the mesh drawn now */
    int ready;                  /* 1: the worker has published its first
                                   state (or its failure) */
    int leaves_shown;           /* 1: the adaptive method's leaves are drawn
                                   (adaptview.c), not the mesh as loaded */
    double *element_now;        /* animate: the last converged frame, in the
                                   order a fresh solve numbers its elements */
    int n_now;
} view_session;

/* Set up the session (nothing runs yet); 0, or -1 with err set. */
int view_session_init(view_session *s, const rad_scene *scene, const rad_result *res,
                      const radi_view_options *o, rad_error *err);
/* Start and stop the worker thread (the animator is stopped apart:
 * view_animator_stop); free everything. */
int view_session_start(view_session *s, rad_error *err);
void view_session_stop(view_session *s);
void view_session_free(view_session *s);

/* The state as JSON (under the caller's lock): with the vertex radiosity
 * (vertices), or with the element radiosity to 17 digits (elements). */
void view_state_json(const view_session *s, jbuf *b, int vertices, int elements);
/* The scene as drawn: geometry (mesh m of scene sc, with each element's
 * presence, or NULL: all present), camera, picture size, exposure,
 * methods.  0, or -1 when memory ran out. */
int view_scene_json(const view_session *s, const rad_mesh *m, const rad_scene *sc,
                    const unsigned char *present, jbuf *b);

/* history.c: check a request's change lines against the session's change
 * file (frames: how many it adds; lines with no change are refused unless
 * empty_ok: an undo's frame may be empty) and mesh the scene of each new
 * frame that moves or turns something, unless the request adds more than
 * max_frames frames (which the caller refuses); append them; and write the
 * frame that undoes frame `frame` of ch, from the scene as it is before
 * that frame.  0, or -1 with the reason in why (check) or when memory ran
 * out; the check gives -2 when memory ran out. */
int view_history_check(const rad_scene *scene, const char *history, size_t hlen,
                       const char *req, size_t rlen, int empty_ok, int max_frames, int *frames,
                       char *why, size_t cap);
int view_history_append(jbuf *b, const char *req, size_t rlen);
/* The offsets of the `frame` lines of s[from..n) (the lines begin at
 * from and after each '\n'), at most cap of them stored; their count. */
int view_history_frames(const char *s, size_t from, size_t n, size_t *starts, int cap);
int view_inverse_frame(jbuf *b, const rad_scene *scene, const rad_changes *ch, int frame);

/* hemiview.c: the hemicube of element i at resolution res (even) on the
 * scene as loaded, as JSON (items: each pixel's element, top face then
 * sides; row: F_ij by the hemicube); 0, or -1 with err set. */
#define VIEW_HEMI_MAX 256
int view_hemicube_json(const view_session *s, int i, int res, jbuf *b, rad_error *err);

/* jsonread.c: the change lines of a JSON body (a string, an array of
 * strings, or an object {"changes": either}) appended to out; 0, or -1
 * with the reason in why. */
int view_json_changes(const char *s, size_t n, jbuf *out, char *why, size_t cap);

/* animator.c: the thread that runs the frames (rad_anim_next), started
 * with the session; and a request's changes or an undo queued for it
 * (0, or an HTTP status with the reason in why; limited: at most
 * VIEW_MAX_QUEUED frames may wait, as for a request). */
int view_animator_start(view_session *s, rad_error *err);
void view_animator_stop(view_session *s);
int view_queue_changes(view_session *s, const char *req, size_t len, int limited, char *why,
                       size_t cap);
int view_queue_undo(view_session *s, char *why, size_t cap);


/* commands.c: wait (lock held) until there is a step to take (-1; the
 * rate paces a run from `last_step`), a reset (the method to reset to,
 * >= 0) or the end (-2); once the scene has changed, -3 with
 * leave_on_change, else wait for the end. */
int view_wait_for_work(view_session *s, double last_step, int leave_on_change);
/* shown.c: the published buffers made room for this many elements and
 * vertices (lock held); 0, or -1 when memory ran out. */
int view_reserve(view_session *s, size_t elements, size_t vertices);

/* adaptview.c: the adaptive method, run by the worker (lock not held) from
 * step 0 to its end: VIEW_ADAPT_DONE when it converged, VIEW_ADAPT_FAILED
 * (the failure published), -2 when told to stop, or the method a reset
 * asked for (>= 0). */
enum { VIEW_ADAPT_DONE = -1, VIEW_ADAPT_FAILED = -3 };
int view_adaptive_run(view_session *s);

/* commands.c: a command from a request, already checked: action is one of run,
 * pause, step, reset, stop; method -1 or a method; steps >= 1; rate < 0:
 * unchanged.  Applies it under the lock and wakes the worker; -1 (nothing
 * done) for run, step or reset once the scene has changed (the race runs
 * on the F of the scene as loaded). */
typedef enum view_action { VIEW_RUN, VIEW_PAUSE, VIEW_STEP, VIEW_RESET, VIEW_STOP } view_action;
int view_command(view_session *s, view_action a, int method, int steps, double rate);

#endif /* RAD_VIEWINT_H */
