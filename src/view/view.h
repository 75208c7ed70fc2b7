/* view/view.h -- the live viewer (internal): a session of one scene served
 * over HTTP to a browser that draws it as it converges.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The caller (cli/cmd_view.c) reads the scene and runs the pipeline once,
 * to the converged solution with the form factors kept; radi_view_serve
 * then holds that solution as the reference of the error plot, steps one
 * method of progressive refinement or gathering from B = E on the same F
 * (progressive.h, radi_stepper) in a thread of its own, and serves the
 * page, the scene and the state until it is told to stop (o->stop, or the
 * page's stop button).  server.c says what is served and how a
 * request is checked; session.c what a step publishes.
 */
#ifndef RAD_VIEW_H
#define RAD_VIEW_H

#include <stdio.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/pipeline.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"

typedef struct radi_view_options {
    const char *address;        /* numeric IPv4 address to bind (127.0.0.1) */
    int port;                   /* 0: a free one */
    const char *assets;         /* folder holding index.html and view.js */
    int method;                 /* the starting method (progressive.h) */
    int paused;                 /* 1: start paused at step 0 */
    double rate;                /* steps a second at most while running; 0: as
                                   many as the machine does */
    int max_connections;        /* connections served at once */
    long max_shots;             /* shots a frame of the animation may take
                                   before it fails (rad_anim_options); 0: the
                                   engine's default */
    rad_vertex_rule vertex_rule;  /* how vertex radiosity is smoothed, */
    double crease;              /* ... and across which surfaces (degrees) */
    FILE *announce;             /* where the URL is printed, then flushed */
    rad_ff_options ff;          /* the animation's form factors (the same as
                                   the converged solution's) */
    rad_solve_options adaptive; /* the adaptive method's threshold, depth,
                                   test, tolerance and step limit */
    const char *changes;        /* a change file's text to run first, checked
                                   by the caller, or NULL */
    size_t changes_len;
    int open_browser;           /* 1: start the desktop's browser on the URL
                                   (xdg-open; a warning when it cannot) */
    int (*stop)(void *user);    /* polled 5 times a second, may be NULL:
                                   non-zero stops the server as the page's
                                   stop button does */
    void *stop_user;
} radi_view_options;

void radi_view_options_init(radi_view_options *o);

/* Serve the scene and its converged result (mesh, F and B, as
 * rad_pipeline_run leaves them with the form factors kept) until stopped.
 * *record (may be NULL) receives the session's change file (malloc'd text,
 * "" when nothing changed), which `radiosity animate` replays.  RAD_OK
 * after a clean stop; an error when the address cannot be bound, an asset
 * cannot be read, the changes given are refused, or memory runs out. */
rad_status radi_view_serve(const rad_scene *scene, const rad_result *res,
                           const radi_view_options *o, char **record, rad_error *err);

/* The method named name ("shooting", "sorted", "sorted_ambient",
 * "gathering", "jacobi", "race": the four methods of Cohen et al. 1988's
 * figure 7 stepping side by side, one step each at a time, or "adaptive":
 * sorted shooting with adaptive subdivision, section 4, on a mesh that
 * splits as it goes), or -1; and the name of a method. */
#define RADI_VIEW_RACE 5        /* after the stepper's methods (progressive.h) */
#define RADI_VIEW_ADAPTIVE 6
int radi_view_method(const char *name);
const char *radi_view_method_name(int method);

#endif /* RAD_VIEW_H */
