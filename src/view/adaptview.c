/* adaptview.c -- the adaptive mesh as it splits: the viewer's `adaptive`
 * method.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen, Chen, Wallace & Greenberg 1988, section 4: the starting elements
 * shoot as fixed patches, largest unshot power first; after each shot an
 * element whose radiosity differs from an edge neighbour's by more than
 * the threshold is split into four, and the new elements gather from
 * every patch that has shot.  The method runs the adaptive solver itself
 * (adaptive.c, as `radiosity solve --solver progressive --adaptive` runs
 * it, with the same options), in the worker's thread, through its watcher:
 * at each step the watcher publishes the leaves (their conforming mesh,
 * adaptmesh.c: the geometry, raised in version when a split changed it,
 * and the vertex radiosity by its rules) and then waits, as the worker
 * does between steps, for the next step the page asks for: run (paced by
 * the rate), step, pause.  A reset, another method, a change of the scene
 * (the animation's picture then takes over) or stop end the solve from
 * inside the watcher.  The converged run is the
 * solver's own, so its leaves and their B are those of `solve --adaptive`
 * with the same options.
 *
 * The error plot has no curve here: the converged adaptive solution is
 * not known before the run (it is this run's end), and the scene's
 * converged solution is on another mesh.  The unshot power (a fraction of
 * the emitted power, as the other methods show it) is the measure of
 * progress; the shooter is not reported by the solver's watcher.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "view/viewint.h"
#include "adapt/adapt.h"
#include "util/util.h"

#define VIEW_ADAPT_HZ 40.0      /* pictures a second at most while running */

typedef struct adapt_run {
    view_session *s;
    double emitted;             /* sum_i A_i sum_b E_ib of the starting mesh */
    double last_step, last_pub;
    int stepping;               /* 1: the step just taken was asked for */
    int leaves;                 /* leaves of the geometry published, 0: none */
    int result;                 /* what ended the run (view_adaptive_run) */
} adapt_run;

/* The leaves of view v to the page (takes the lock); 0, or -1 when memory
 * ran out. */
static int publish_leaves(adapt_run *r, const rad_adapt_view *v)
{
    view_session *s = r->s;
    rad_mesh m;
    double *B = NULL, *Bv = NULL;
    int *level = NULL, bad = 0;
    rad_error err;
    if (radi_adapt_leaf_mesh(v->nodes, v->leaf, v->B, &m, &B, &Bv, &level, &err) != RAD_OK)
        return -1;
    const size_t n = (size_t)m.nelements, nv = (size_t)m.nvertices;
    jbuf js;
    jb_init(&js);
    const int split = m.nelements != r->leaves;
    pthread_mutex_lock(&s->lock);
    if (!s->animate && view_reserve(s, n, nv) != 0)
        bad = -1;
    if (!bad && !s->animate && split) { /* the scene carries the new number */
        s->geometry++;
        if (view_scene_json(s, &m, s->scene, NULL, &js) != 0) {
            s->geometry--;
            bad = -1;
        } else {
            free(s->scene_json);
            s->scene_json = js.s;
            s->scene_len = js.len;
            js.s = NULL;
            r->leaves = m.nelements;
        }
    }
    if (!bad && !s->animate) {
        for (size_t i = 0; i < n; i++)
            for (int b = 0; b < RAD_BANDS; b++)
                s->element_b[3 * i + (size_t)b] = B[i + (size_t)b * n];
        for (size_t k = 0; k < nv; k++)
            for (int b = 0; b < RAD_BANDS; b++)
                s->vertex_b[3 * k + (size_t)b] = Bv[k + (size_t)b * nv];
        double u = 0;
        for (int b = 0; b < RAD_BANDS; b++)
            u += v->unshot[b];
        s->shown_elements = (int)n;
        s->shown_vertices = (int)nv;
        s->leaves_shown = 1;
        s->lanes = 1;
        s->method = RADI_VIEW_ADAPTIVE;
        s->step = v->step;
        s->shooter = s->lane_shooter[0] = -1;
        s->unshot = s->lane_unshot[0] = r->emitted > 0 ? u / r->emitted : NAN;
        s->rms = s->lane_rms[0] = NAN;
        s->sps = 0;
        s->ready = 1;
        s->version++;
        pthread_cond_broadcast(&s->changed);
    }
    pthread_mutex_unlock(&s->lock);
    jb_free(&js);
    rad_mesh_free(&m);
    free(B);
    free(Bv);
    free(level);
    return bad;
}

/* The solver's watcher: publish, then wait for the next step (1 ends the
 * solve: stop, a reset, or a failure to publish). */
static int on_step(void *user, const rad_adapt_view *v)
{
    adapt_run *r = user;
    view_session *s = r->s;
    const double now = radi_seconds();
    if ((r->stepping || v->step == 0 || v->converged || now - r->last_pub >= 1 / VIEW_ADAPT_HZ)) {
        if (publish_leaves(r, v) != 0) {
            r->result = VIEW_ADAPT_FAILED;
            return 1;
        }
        r->last_pub = now;
    }
    if (v->converged)
        return 0; /* the solve ends after this call */
    pthread_mutex_lock(&s->lock);
    const int w = view_wait_for_work(s, r->last_step, 1);
    r->stepping = w == -1 && s->pending > 0;
    if (r->stepping)
        s->pending--;
    pthread_mutex_unlock(&s->lock);
    r->last_step = radi_seconds();
    if (w == -1)
        return 0;
    r->result = w == -3 ? VIEW_ADAPT_DONE : w; /* the scene changed; stop; a reset */
    return 1;
}

int view_adaptive_run(view_session *s)
{
    adapt_run r;
    memset(&r, 0, sizeof r);
    r.s = s;
    r.result = VIEW_ADAPT_DONE;
    r.last_step = radi_seconds();
    const rad_mesh *m = s->mesh;
    for (int i = 0; i < m->nelements; i++)
        for (int b = 0; b < RAD_BANDS; b++)
            r.emitted += m->elements[i].area * m->elements[i].emit[b];
    rad_solve_options so = s->opt.adaptive;
    so.adaptive = 1;
    so.sort = 1;
    rad_error err;
    const rad_status st = radi_solve_adaptive_watch(m, &s->opt.ff, &so, on_step, &r, NULL, NULL,
                                                    NULL, &err);
    if (st != RAD_OK || r.result == VIEW_ADAPT_FAILED) {
        pthread_mutex_lock(&s->lock);
        snprintf(s->failure, sizeof s->failure, "%.255s",
                 st != RAD_OK ? err.message : "out of memory for the adaptive mesh");
        s->method = RADI_VIEW_ADAPTIVE; /* the failure is this method's */
        s->step = 0;
        s->unshot = s->rms = NAN;
        s->ready = 1;
        s->running = s->pending = 0;
        s->version++;
        pthread_cond_broadcast(&s->changed);
        pthread_mutex_unlock(&s->lock);
        return VIEW_ADAPT_FAILED;
    }
    return r.result;
}
