/* session.c -- the viewer's state: one method stepping on the scene's F in
 * a thread of its own, and what each step publishes to the page.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The worker owns the stepper (progressive.h).  Requests never touch it:
 * they set a command under the lock and wake the worker (view_command),
 * so a request cannot race a step, and a step never waits for a slow
 * browser.  After a step the worker smooths the displayed radiosity to the
 * vertices as `radiosity solve` does (rad_smooth_vertices_rule, then
 * rad_smooth_across with the same crease), takes the area-weighted RMS
 * error against the converged solution (Cohen et al. 1988, eq. 14, of the
 * band-averaged radiosity: rmserror.c), and publishes the lot under the
 * lock, at most VIEW_PUBLISH_HZ times a second while running (every step
 * when stepping or paused), raising `version` and waking the streams.
 * Between steps it waits for the page's commands (commands.c).  The
 * adaptive method has no stepper: the worker runs it whole, and its
 * watcher publishes and waits (adaptview.c).
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "view/viewint.h"
#include "solve/solve.h"
#include "compare/compare.h"
#include "util/util.h"
#include "radiosity/mesh.h"
#include "radiosity/render.h"

#define VIEW_PUBLISH_HZ 40.0    /* pictures a second at most while running */
#define NB RAD_BANDS

void radi_view_options_init(radi_view_options *o)
{
    memset(o, 0, sizeof *o);
    o->address = "127.0.0.1";
    o->method = RAD_RACE_SORTED_AMBIENT;
    o->rate = 30;
    o->max_connections = 16;
    o->crease = 0;
    o->announce = stdout;
    rad_solve_options_init(&o->adaptive);
}

int view_session_init(view_session *s, const rad_scene *scene, const rad_result *res,
                      const radi_view_options *o, rad_error *err)
{
    const rad_mesh *m = &res->mesh;
    const size_t n = (size_t)m->nelements, nv = (size_t)m->nvertices;
    memset(s, 0, sizeof *s);
    s->scene = scene;
    s->mesh = m;
    s->F = res->F;
    s->Bref = res->B;
    s->opt = *o;
    s->rate = o->rate;
    s->method = o->method;
    s->reset_method = -1;
    s->running = !o->paused;
    s->shooter = -1;
    s->area = malloc(sizeof *s->area * (n ? n : 1));
    s->rho = malloc(sizeof *s->rho * (n ? n : 1) * NB);
    s->Bv = malloc(sizeof *s->Bv * (nv ? nv : 1) * NB * VIEW_LANES);
    s->vertex_b = calloc((nv ? nv : 1) * NB * VIEW_LANES, sizeof *s->vertex_b);
    s->element_b = calloc((n ? n : 1) * NB, sizeof *s->element_b);
    if (!s->area || !s->rho || !s->Bv || !s->vertex_b || !s->element_b) {
        view_session_free(s);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the view"), -1;
    }
    s->cap_elements = n;
    s->cap_vertices = nv * VIEW_LANES;
    s->shown_elements = (int)n;
    s->shown_vertices = (int)nv;
    s->exposure = rad_mesh_auto_exposure(m, res->B, RAD_EXPOSURE_REFLECTORS);
    rad_anim_options_init(&s->anim_opt);
    s->anim_opt.ff = o->ff;
    if (o->max_shots > 0)
        s->anim_opt.max_shots = o->max_shots;
    jb_init(&s->changes);
    jbuf js;
    jb_init(&js);
    if (view_scene_json(s, m, scene, NULL, &js) != 0) {
        jb_free(&js);
        view_session_free(s);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the view"), -1;
    }
    s->scene_json = js.s;
    s->scene_len = js.len;
    for (size_t i = 0; i < n; i++) {
        s->area[i] = m->elements[i].area;
        s->total_area += s->area[i];
        for (int b = 0; b < NB; b++)
            s->rho[i + b * n] = m->elements[i].reflect[b];
    }
    pthread_mutex_init(&s->lock, NULL);
    pthread_cond_init(&s->wake, NULL);
    pthread_cond_init(&s->changed, NULL);
    pthread_cond_init(&s->anim_wake, NULL);
    return 0;
}

void view_session_free(view_session *s)
{
    free(s->area);
    free(s->rho);
    free(s->Bv);
    free(s->vertex_b);
    free(s->element_b);
    free(s->element_now);
    free(s->scene_json);
    free(s->is_undo);
    free(s->frame_start);
    for (int k = 0; k < s->ninverse; k++)
        jb_free(&s->inverse[k]);
    free(s->inverse);
    jb_free(&s->undo_running);
    jb_free(&s->event);
    jb_free(&s->changes);
    s->area = s->rho = s->Bv = s->vertex_b = s->element_b = s->element_now = NULL;
    s->scene_json = NULL;
    s->is_undo = NULL;
    s->frame_start = NULL;
    s->inverse = NULL;
    s->ninverse = 0;
}

/* The methods stepping together: one, or the race's four. */
typedef struct lanes {
    int n, method;
    radi_stepper *st[VIEW_LANES];
} lanes;

static void lanes_free(lanes *l)
{
    for (int k = 0; k < l->n; k++)
        radi_stepper_free(l->st[k]);
    l->n = 0;
}

/* Under the lock: history row (step, each lane's rms), halved when full
 * (every other point kept: the plot's whole run). */
static void remember(view_session *s)
{
    if (s->nhistory == VIEW_HISTORY) {
        for (int k = 0; k < VIEW_HISTORY / 2; k++)
            memcpy(s->history[k], s->history[2 * k + 1], sizeof s->history[k]);
        s->nhistory = VIEW_HISTORY / 2;
    }
    if (s->nhistory == 0 || s->history[s->nhistory - 1][0] != s->step) {
        s->history[s->nhistory][0] = s->step;
        for (int k = 0; k < s->lanes; k++)
            s->history[s->nhistory][1 + k] = s->lane_rms[k];
        s->nhistory++;
    }
}

/* Under the lock: the lanes' state into the published copy (the first
 * lane's element radiosity; every lane's vertex radiosity, smoothed into
 * s->Bv by smooth()). */
static void publish(view_session *s, const lanes *l, double sps)
{
    if (s->animate)
        return; /* the picture is the animation's now (animator.c) */
    const size_t n = (size_t)s->mesh->nelements, nv = (size_t)s->mesh->nvertices;
    const double *B = radi_stepper_shown(l->st[0]);
    for (size_t i = 0; i < n; i++)
        for (int b = 0; b < NB; b++)
            s->element_b[3 * i + (size_t)b] = B[i + (size_t)b * n];
    for (int k = 0; k < l->n; k++) {
        const double *Bv = s->Bv + (size_t)k * nv * NB;
        double *out = s->vertex_b + (size_t)k * nv * 3;
        for (size_t v = 0; v < nv; v++)
            for (int b = 0; b < NB; b++)
                out[3 * v + (size_t)b] = Bv[v + (size_t)b * nv];
        const rad_rms_input in = {(int)n, s->area, s->total_area, s->rho, NULL,
                                  radi_stepper_shown(l->st[k]), s->Bref};
        s->lane_rms[k] = radi_rms_eq14(&in);
        s->lane_shooter[k] = radi_stepper_last(l->st[k]);
        s->lane_unshot[k] = radi_stepper_unshot(l->st[k]);
    }
    s->lanes = l->n;
    s->method = l->method;
    s->step = radi_stepper_steps(l->st[0]);
    s->shooter = s->lane_shooter[0];
    s->unshot = s->lane_unshot[0];
    s->rms = s->lane_rms[0];
    s->sps = sps;
    remember(s);
    s->version++;
    pthread_cond_broadcast(&s->changed);
}

/* The displayed radiosity of each lane to the vertices (outside the lock). */
static int smooth(view_session *s, const lanes *l)
{
    rad_error err;
    const size_t nv = (size_t)s->mesh->nvertices;
    for (int k = 0; k < l->n; k++) {
        double *Bv = s->Bv + (size_t)k * nv * NB;
        rad_smooth_vertices_rule(s->mesh, radi_stepper_shown(l->st[k]), Bv, s->opt.vertex_rule);
        if (rad_smooth_across(s->scene, s->mesh, s->opt.crease, Bv, &err) != RAD_OK)
            return -1;
    }
    return 0;
}

static rad_status lanes_step(lanes *l, rad_error *err)
{
    for (int k = 0; k < l->n; k++) {
        const rad_status st = radi_stepper_step(l->st[k], err);
        if (st != RAD_OK)
            return st;
    }
    return RAD_OK;
}

/* After the adaptive method (lock held): the mesh as loaded drawn again;
 * 0, or -1 when memory ran out. */
static int loaded_mesh(view_session *s)
{
    jbuf js;
    jb_init(&js);
    if (!s->leaves_shown)
        return 0;
    s->geometry++; /* the scene carries the new number */
    if (view_scene_json(s, s->mesh, s->scene, NULL, &js) != 0) {
        s->geometry--;
        jb_free(&js);
        return -1;
    }
    free(s->scene_json);
    s->scene_json = js.s;
    s->scene_len = js.len;
    s->leaves_shown = 0;
    s->shown_elements = s->mesh->nelements;
    s->shown_vertices = s->mesh->nvertices;
    return 0;
}

/* Fresh lanes of method m (the race: four), published at step 0; 0, or
 * -1 with the failure set.  The adaptive method has no lanes: its run
 * publishes its own step 0 (adaptview.c). */
static int fresh(view_session *s, lanes *l, int m)
{
    rad_error err;
    int bad = 0;
    l->n = m == RADI_VIEW_RACE ? VIEW_LANES : m == RADI_VIEW_ADAPTIVE ? 0 : 1;
    l->method = m;
    for (int k = 0; k < l->n; k++) {
        l->st[k] = NULL;
        bad = bad || radi_stepper_new(&l->st[k], s->mesh, s->F, l->n > 1 ? k : m, &err) != RAD_OK;
    }
    bad = bad || smooth(s, l) != 0;
    pthread_mutex_lock(&s->lock);
    bad = bad || (l->n > 0 && !s->animate && loaded_mesh(s) != 0);
    s->ready |= bad || l->n > 0;
    if (bad) {
        lanes_free(l);
        snprintf(s->failure, sizeof s->failure, "%s", "out of memory for the method");
        s->version++;
        pthread_cond_broadcast(&s->changed);
    } else {
        s->nhistory = 0;
        if (l->n > 0)
            publish(s, l, 0);
    }
    pthread_mutex_unlock(&s->lock);
    return bad ? -1 : 0;
}

/* After a step (lock held): the failure, or the picture when it is due. */
static void after_step(view_session *s, const lanes *l, rad_status ok, const rad_error *err,
                       int show, double sps)
{
    if (ok != RAD_OK) {
        snprintf(s->failure, sizeof s->failure, "%.255s", err->message);
        s->running = s->pending = 0;
        s->version++;
        pthread_cond_broadcast(&s->changed);
    } else if (show) {
        publish(s, l, sps);
    }
}

/* The adaptive method's turn (lock held): its run from step 0 unless it
 * has ended (*ran), then nothing to step: run and step just pause.  -2
 * when told to stop, else 0 (a reset is left in reset_method). */
static int adaptive_turn(view_session *s, int *ran)
{
    if (*ran) {
        s->running = s->pending = 0;
        s->version++;
        pthread_cond_broadcast(&s->changed);
        return 0;
    }
    pthread_mutex_unlock(&s->lock);
    const int r = view_adaptive_run(s);
    pthread_mutex_lock(&s->lock);
    *ran = 1;
    if (r >= 0 && s->reset_method < 0)
        s->reset_method = r;
    else if (r == VIEW_ADAPT_DONE)
        s->running = s->pending = 0;
    s->version++;
    pthread_cond_broadcast(&s->changed);
    return r == -2 ? -2 : 0;
}

static void *worker(void *arg)
{
    view_session *s = arg;
    lanes l = {0, s->method, {NULL}};
    int have = fresh(s, &l, s->method) == 0, ran = 0;
    double last_step = radi_seconds(), last_pub = 0, t_rate = radi_seconds();
    int since = 0;
    pthread_mutex_lock(&s->lock);
    for (;;) {
        if (have && l.method == RADI_VIEW_ADAPTIVE && !ran && !s->animate) {
            if (adaptive_turn(s, &ran) == -2)
                break;
            continue;
        }
        const int r = view_wait_for_work(s, last_step, 0);
        if (r == -2)
            break;
        if (r >= 0 || !have) {
            pthread_mutex_unlock(&s->lock);
            const int m = r >= 0 ? r : l.method;
            lanes_free(&l);
            have = fresh(s, &l, m) == 0;
            ran = since = 0;
            t_rate = radi_seconds();
            pthread_mutex_lock(&s->lock);
            if (!have)
                s->running = s->pending = 0;
            continue;
        }
        if (l.method == RADI_VIEW_ADAPTIVE) {
            adaptive_turn(s, &ran);
            continue;
        }
        const int stepping = s->pending > 0;
        if (stepping)
            s->pending--;
        pthread_mutex_unlock(&s->lock);
        rad_error err;
        rad_status ok = lanes_step(&l, &err);
        last_step = radi_seconds();
        since++;
        const int show = stepping || last_step - last_pub >= 1 / VIEW_PUBLISH_HZ;
        if (ok == RAD_OK && show && smooth(s, &l) != 0) {
            ok = RAD_ERR_NOMEM;
            snprintf(err.message, sizeof err.message, "%s", "out of memory smoothing");
        }
        const double dt = last_step - t_rate;
        pthread_mutex_lock(&s->lock);
        after_step(s, &l, ok, &err, show, dt > 0 ? since / dt : 0);
        if (show) {
            last_pub = last_step;
            if (dt > 1) { /* the rate over the last second or so */
                since = 0;
                t_rate = last_step;
            }
        }
    }
    pthread_mutex_unlock(&s->lock);
    lanes_free(&l);
    return NULL;
}

int view_session_start(view_session *s, rad_error *err)
{
    if (pthread_create(&s->worker, NULL, worker, s) != 0)
        return radi_fail(err, RAD_ERR_NOMEM, "cannot start the solver's thread"), -1;
    s->worker_started = 1;
    pthread_mutex_lock(&s->lock); /* no request sees a state before step 0's */
    while (!s->ready)
        pthread_cond_wait(&s->changed, &s->lock);
    pthread_mutex_unlock(&s->lock);
    return 0;
}

void view_session_stop(view_session *s)
{
    pthread_mutex_lock(&s->lock);
    s->stopping = 1;
    pthread_cond_broadcast(&s->wake);
    pthread_cond_broadcast(&s->changed);
    pthread_mutex_unlock(&s->lock);
    if (s->worker_started)
        pthread_join(s->worker, NULL);
    s->worker_started = 0;
}
