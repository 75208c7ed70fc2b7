/* commands.c -- what requests ask of the worker, and the worker's wait
 * for it.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A request never steps a method itself: view_command sets the command
 * under the lock (run, pause, a number of steps, a reset to a method,
 * stop) and wakes the worker; the worker (session.c), or the adaptive
 * solver's watcher in the worker's thread (adaptview.c), waits in
 * view_wait_for_work until there is a step to take, a reset or the end.
 * While running, the rate paces the steps; the wait is on the condition
 * variable, so pause and stop take effect at once.
 */
#include <config.h>

#include <time.h>

#include "view/viewint.h"
#include "util/util.h"

static void deadline_after(struct timespec *ts, double seconds)
{
    clock_gettime(CLOCK_REALTIME, ts);
    double t = (double)ts->tv_sec + 1e-9 * (double)ts->tv_nsec + seconds;
    ts->tv_sec = (time_t)t;
    ts->tv_nsec = (long)((t - (double)ts->tv_sec) * 1e9);
    if (ts->tv_nsec >= 1000000000L) {
        ts->tv_sec++;
        ts->tv_nsec -= 1000000000L;
    }
}

int view_wait_for_work(view_session *s, double last_step, int leave_on_change)
{
    for (;;) {
        if (s->stopping)
            return -2;
        if (s->animate) { /* the race is over: the scene changed; a reset
                             asked for just before is void */
            s->reset_method = -1;
            if (leave_on_change)
                return -3;
            pthread_cond_wait(&s->wake, &s->lock);
            continue;
        }
        if (s->reset_method >= 0) {
            const int m = s->reset_method;
            s->reset_method = -1;
            return m;
        }
        if (s->pending > 0)
            return -1;
        if (s->running && s->failure[0] == '\0') {
            const double gap = s->rate > 0 ? 1 / s->rate - (radi_seconds() - last_step) : 0;
            if (gap <= 0)
                return -1;
            struct timespec ts; /* a second at most: a rate of 1e-300 is one
                                   step in 1e300 s, past any time_t */
            deadline_after(&ts, gap < 1 ? gap : 1);
            pthread_cond_timedwait(&s->wake, &s->lock, &ts);
            continue;
        }
        pthread_cond_wait(&s->wake, &s->lock);
    }
}

int view_command(view_session *s, view_action a, int method, int steps, double rate)
{
    pthread_mutex_lock(&s->lock);
    if (s->animate && a != VIEW_STOP && a != VIEW_PAUSE) {
        pthread_mutex_unlock(&s->lock);
        return -1;
    }
    if (rate >= 0)
        s->rate = rate;
    switch (a) {
    case VIEW_RUN:
        s->running = 1;
        break;
    case VIEW_PAUSE:
        s->running = 0;
        s->pending = 0;
        break;
    case VIEW_STEP:
        s->running = 0;
        s->pending = steps;
        break;
    case VIEW_RESET:
        s->reset_method = method >= 0 ? method : s->method;
        s->pending = 0;
        s->failure[0] = '\0';
        break;
    case VIEW_STOP:
        s->stopping = 1;
        break;
    }
    if (a == VIEW_RUN && method >= 0 && method != s->method) {
        s->reset_method = method; /* run another method: from the start */
        s->pending = 0;
    }
    s->version++;               /* running/paused is state too */
    pthread_cond_broadcast(&s->wake);
    pthread_cond_broadcast(&s->changed);
    pthread_mutex_unlock(&s->lock);
    return 0;
}
