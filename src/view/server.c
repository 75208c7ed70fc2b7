/* server.c -- the viewer's HTTP server (GNU libmicrohttpd): what is served,
 * how each request is checked, and the run until stopped.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Routes (GET also answers HEAD):
 *   GET  /, /index.html, /view.js   the page, read from the assets folder
 *                                   once, at the start (nothing else is
 *                                   ever read or written)
 *   GET  /api/scene                 the scene, once (scenejson.c)
 *   GET  /api/state                 the state with the vertex radiosity
 *   GET  /api/elements              the state with the element radiosity
 *                                   to 17 digits
 *   GET  /api/row?element=I         row I of F of the scene as loaded
 *   GET  /api/hemicube?element=I[&resolution=R]  I's hemicube (hemiview.c)
 *   GET  /api/events                the state as Server-Sent Events (the
 *                                   HTML standard's text/event-stream): an
 *                                   `event: state` message at each new
 *                                   version, a comment line every
 *                                   VIEW_KEEPALIVE seconds otherwise
 *   POST /api/control?action=A[&method=M][&steps=K][&rate=R]
 *        A: run, pause, step (K steps, then paused), reset (to B = E, of
 *        method M or the current one), stop (ends the server).
 A control request carries its parameters in the query string and no
 * body.  Every request must name this server in Host (an address of the
 * loopback, localhost, or the address bound, with the port), which keeps
 * other sites' pages out through DNS rebinding, and a request that says
 * where it comes from (Origin, which browsers send with every cross-site
 * POST) must come from this server's own page: no page of another site
 * changes the state.  Anything else is answered 400 (a bad parameter:
 * unknown, repeated, non-numeric, non-finite, out of range, with the
 * reason), 403 (Host or Origin), 404 (no such route), 405 (a route's
 * wrong method) or 413 (a body where none is taken, or a Content-Length
 * past VIEW_MAX_BODY: answered before the body is read), as JSON
 * {"error": "..."}, and changes nothing.  A body sent without its length
 * (chunked) ends the connection once past VIEW_MAX_BODY.  The daemon runs a
 * thread per connection (a stream waits on the session's condition
 * variable), at most max_connections at once, idle ones dropped after
 * VIEW_IDLE seconds.
 */
#include <config.h>

#include <arpa/inet.h>
#include <errno.h>
#include <math.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <spawn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

#include <microhttpd.h>

#include "view/viewint.h"
#include "util/util.h"

#define VIEW_MAX_BODY 65536     /* bytes of a body read before the connection ends */
#define VIEW_KEEPALIVE 10       /* seconds between a stream's comment lines */
#define VIEW_IDLE 60            /* seconds before an idle connection is dropped */
#define VIEW_SPARE 4            /* connections event streams leave to other requests */
#define VIEW_MAX_STEPS 1000000
#define VIEW_MAX_RATE 100000.0

typedef struct asset {
    const char *path, *file, *type;
    char *data;
    size_t size;
} asset;

typedef struct server {
    view_session *s;
    asset assets[3];
    char port[16], bound[64];   /* for the Host check */
} server;

typedef struct request {
    size_t body;
    jbuf data;                  /* the body of POST /api/change */
    int nul;                    /* ... held a NUL byte */
} request;

/* ---- answers ------------------------------------------------------------- */

static enum MHD_Result send_text(struct MHD_Connection *c, unsigned code, const char *type,
                                 const char *text, size_t len, int copy)
{
    /* MHD takes a void *; it reads a PERSISTENT or MUST_COPY buffer only */
    union {
        const char *in;
        void *out;
    } buf = {text};
    struct MHD_Response *r = MHD_create_response_from_buffer(
        len, buf.out, copy ? MHD_RESPMEM_MUST_COPY : MHD_RESPMEM_PERSISTENT);
    if (!r)
        return MHD_NO;
    MHD_add_response_header(r, MHD_HTTP_HEADER_CONTENT_TYPE, type);
    MHD_add_response_header(r, MHD_HTTP_HEADER_CACHE_CONTROL, "no-store");
    MHD_add_response_header(r, "X-Content-Type-Options", "nosniff");
    if (code == MHD_HTTP_METHOD_NOT_ALLOWED)
        MHD_add_response_header(r, MHD_HTTP_HEADER_ALLOW, "GET, HEAD, POST");
    const enum MHD_Result q = MHD_queue_response(c, code, r);
    MHD_destroy_response(r);
    return q;
}

static enum MHD_Result send_json(struct MHD_Connection *c, unsigned code, jbuf *b)
{
    if (b->failed) {
        jb_free(b);
        static const char nomem[] = "{\"error\":\"out of memory\"}";
        return send_text(c, MHD_HTTP_INTERNAL_SERVER_ERROR, "application/json", nomem,
                         sizeof nomem - 1, 0);
    }
    const enum MHD_Result q = send_text(c, code, "application/json", b->s, b->len, 1);
    jb_free(b);
    return q;
}

static enum MHD_Result send_error(struct MHD_Connection *c, unsigned code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static enum MHD_Result send_error(struct MHD_Connection *c, unsigned code, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    jbuf b;
    jb_init(&b);
    jb_printf(&b, "{\"error\":");
    jb_str(&b, msg);
    jb_printf(&b, "}");
    return send_json(c, code, &b);
}

static enum MHD_Result send_state(server *sv, struct MHD_Connection *c, int elements)
{
    jbuf b;
    jb_init(&b);
    pthread_mutex_lock(&sv->s->lock);
    view_state_json(sv->s, &b, !elements, elements);
    pthread_mutex_unlock(&sv->s->lock);
    return send_json(c, MHD_HTTP_OK, &b);
}

static enum MHD_Result send_scene(server *sv, struct MHD_Connection *c)
{
    pthread_mutex_lock(&sv->s->lock);
    const enum MHD_Result q =
        send_text(c, MHD_HTTP_OK, "application/json", sv->s->scene_json, sv->s->scene_len, 1);
    pthread_mutex_unlock(&sv->s->lock);
    return q;
}

/* POST /api/change: the body's change lines (text, or JSON: jsonread.c)
 * checked and queued for the animation (animator.c). */
static enum MHD_Result do_change(server *sv, struct MHD_Connection *c, request *rq)
{
    char why[512];
    jbuf text;
    if (MHD_get_connection_values(c, MHD_GET_ARGUMENT_KIND, NULL, NULL) > 0)
        return send_error(c, MHD_HTTP_BAD_REQUEST,
                          "/api/change takes no parameters: the changes are its body");
    if (rq->nul)
        return send_error(c, MHD_HTTP_BAD_REQUEST, "the body holds a NUL byte");
    if (rq->body == 0)
        return send_error(c, MHD_HTTP_BAD_REQUEST,
                          "no changes: the body holds a change file's lines (move, rotate, "
                          "remove, add, material, frame)");
    const char *type = MHD_lookup_connection_value(c, MHD_HEADER_KIND,
                                                   MHD_HTTP_HEADER_CONTENT_TYPE);
    jb_init(&text);
    if (type && !strncasecmp(type, "application/json", 16)) {
        if (view_json_changes(rq->data.s, rq->data.len, &text, why, sizeof why) != 0) {
            jb_free(&text);
            return send_error(c, MHD_HTTP_BAD_REQUEST, "%s", why);
        }
    } else {
        jb_printf(&text, "%.*s", (int)rq->data.len, rq->data.s);
    }
    if (text.failed) {
        jb_free(&text);
        return send_error(c, MHD_HTTP_INTERNAL_SERVER_ERROR, "out of memory");
    }
    const int code = view_queue_changes(sv->s, text.s ? text.s : "", text.len, 1, why, sizeof why);
    jb_free(&text);
    if (code)
        return send_error(c, (unsigned)code, "%s", why);
    jbuf b;
    jb_init(&b);
    pthread_mutex_lock(&sv->s->lock);
    jb_printf(&b, "{\"ok\":true,\"frames\":%d,\"applied\":%d}", sv->s->frames,
              sv->s->applied);
    pthread_mutex_unlock(&sv->s->lock);
    return send_json(c, MHD_HTTP_OK, &b);
}

/* GET /api/row?element=I: row I of F (F_Ij for every j, 17 digits) of the
 * scene as loaded, for the page's heat map of what element I sees. */
/* Rows of F and hemicubes are the mesh's as loaded: refused (409) while
 * the adaptive method's leaves are drawn, whose numbers are not its. */
static int leaves_drawn(server *sv)
{
    pthread_mutex_lock(&sv->s->lock);
    const int leaves = sv->s->leaves_shown;
    pthread_mutex_unlock(&sv->s->lock);
    return leaves;
}

static enum MHD_Result send_row(server *sv, struct MHD_Connection *c)
{
    const view_session *s = sv->s;
    if (leaves_drawn(sv))
        return send_error(c, MHD_HTTP_CONFLICT, "the adaptive mesh is drawn: rows of F are "
                          "the mesh's as loaded (choose another method)");
    const int n = s->mesh->nelements;
    const char *arg = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "element");
    char *end = NULL;
    const long i = arg ? strtol(arg, &end, 10) : -1;
    if (MHD_get_connection_values(c, MHD_GET_ARGUMENT_KIND, NULL, NULL) != 1 || !arg ||
        end == arg || *end || i < 0 || i >= n)
        return send_error(c, MHD_HTTP_BAD_REQUEST,
                          "/api/row takes element=I alone, I a whole number from 0 to %d", n - 1);
    jbuf b;
    jb_init(&b);
    jb_printf(&b, "{\"element\":%ld,\"row\":[", i);
    for (int j = 0; j < n; j++) { /* F is column-major: F_ij at i + j n */
        jb_printf(&b, "%s", j ? "," : "");
        jb_num(&b, s->F[(size_t)i + (size_t)j * (size_t)n], 1);
    }
    jb_printf(&b, "]}");
    return send_json(c, MHD_HTTP_OK, &b);
}

/* GET /api/hemicube?element=I[&resolution=R] (hemiview.c). */
static enum MHD_Result send_hemicube(server *sv, struct MHD_Connection *c)
{
    const int n = sv->s->mesh->nelements;
    if (leaves_drawn(sv))
        return send_error(c, MHD_HTTP_CONFLICT, "the adaptive mesh is drawn: hemicubes are "
                          "the mesh's as loaded (choose another method)");
    const char *e = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "element");
    const char *r = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "resolution");
    char *end1 = NULL, *end2 = NULL;
    const long i = e ? strtol(e, &end1, 10) : -1;
    const long res = r ? strtol(r, &end2, 10) : 32;
    if (MHD_get_connection_values(c, MHD_GET_ARGUMENT_KIND, NULL, NULL) != 1 + (r != NULL) ||
        !e || end1 == e || *end1 || i < 0 || i >= n ||
        (r && (end2 == r || *end2 || res < 2 || res > VIEW_HEMI_MAX || res % 2)))
        return send_error(c, MHD_HTTP_BAD_REQUEST,
                          "/api/hemicube takes element=I (0 to %d) and resolution=R (even, "
                          "2 to %d, default 32)",
                          n - 1, VIEW_HEMI_MAX);
    jbuf b;
    rad_error err;
    jb_init(&b);
    if (view_hemicube_json(sv->s, (int)i, (int)res, &b, &err) != 0) {
        jb_free(&b);
        return send_error(c, MHD_HTTP_INTERNAL_SERVER_ERROR, "%s", err.message);
    }
    return send_json(c, MHD_HTTP_OK, &b);
}

/* ---- the event stream ---------------------------------------------------- */

typedef struct stream {
    view_session *s;
    long sent;                  /* the version last sent, -1: none */
    jbuf msg;                   /* what is left to send of the last message */
    size_t off;
} stream;

/* Wait (lock held) for a version newer than st->sent; 1 when there is
 * one, 0 after VIEW_KEEPALIVE seconds without, -1 when stopping. */
static int wait_version(stream *st)
{
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    ts.tv_sec += VIEW_KEEPALIVE;
    while (!st->s->stopping && st->s->version == st->sent)
        if (pthread_cond_timedwait(&st->s->changed, &st->s->lock, &ts) == ETIMEDOUT)
            return 0;
    return st->s->stopping ? -1 : 1;
}

/* The state of the session's version as an event, in s->event (lock
 * held): formatted by the first stream to send that version, copied by
 * the others, which then send the same bytes.  0, or -1 when memory ran
 * out. */
static int state_event(view_session *s)
{
    if (s->event.s && s->event_version == s->version)
        return 0;
    s->event.len = 0;
    jb_printf(&s->event, "event: state\ndata: ");
    view_state_json(s, &s->event, 1, 0);
    jb_printf(&s->event, "\n\n");
    if (s->event.failed) {
        jb_free(&s->event);
        return -1;
    }
    s->event_version = s->version;
    return 0;
}

static ssize_t stream_read(void *cls, uint64_t pos, char *buf, size_t max)
{
    stream *st = cls;
    (void)pos;
    if (st->off == st->msg.len) {
        jb_free(&st->msg);
        st->off = 0;
        pthread_mutex_lock(&st->s->lock);
        const int w = wait_version(st);
        if (w > 0) {
            if (state_event(st->s) == 0)
                jb_put(&st->msg, st->s->event.s, st->s->event.len);
            else
                st->msg.failed = 1;
            st->sent = st->s->version;
        }
        pthread_mutex_unlock(&st->s->lock);
        if (w < 0 || st->msg.failed)
            return MHD_CONTENT_READER_END_OF_STREAM;
        if (w == 0)
            jb_printf(&st->msg, ": keep-alive\n\n");
        if (st->msg.failed)
            return MHD_CONTENT_READER_END_OF_STREAM;
    }
    size_t k = st->msg.len - st->off;
    k = k < max ? k : max;
    memcpy(buf, st->msg.s + st->off, k);
    st->off += k;
    return (ssize_t)k;
}

static void stream_free(void *cls)
{
    stream *st = cls;
    pthread_mutex_lock(&st->s->lock);
    st->s->streams--;
    pthread_mutex_unlock(&st->s->lock);
    jb_free(&st->msg);
    free(st);
}

/* Event streams hold their connections; VIEW_SPARE connections are kept
 * for the short requests (a page's controls must still get through when
 * many browsers watch). */
static int stream_room(view_session *s)
{
    const int most = s->opt.max_connections > VIEW_SPARE ? s->opt.max_connections - VIEW_SPARE : 1;
    pthread_mutex_lock(&s->lock);
    const int room = s->streams < most;
    s->streams += room;
    pthread_mutex_unlock(&s->lock);
    return room;
}

static enum MHD_Result send_stream(server *sv, struct MHD_Connection *c)
{
    if (!stream_room(sv->s))
        return send_error(c, MHD_HTTP_SERVICE_UNAVAILABLE,
                          "every stream this server keeps is open (its connections less %d "
                          "for other requests): close a page, or poll /api/state",
                          VIEW_SPARE);
    stream *st = calloc(1, sizeof *st);
    if (!st) {
        pthread_mutex_lock(&sv->s->lock);
        sv->s->streams--;
        pthread_mutex_unlock(&sv->s->lock);
        return MHD_NO;
    }
    st->s = sv->s;
    st->sent = -1;
    struct MHD_Response *r =
        MHD_create_response_from_callback(MHD_SIZE_UNKNOWN, 16384, stream_read, st, stream_free);
    if (!r) {
        stream_free(st);
        return MHD_NO;
    }
    MHD_add_response_header(r, MHD_HTTP_HEADER_CONTENT_TYPE, "text/event-stream");
    MHD_add_response_header(r, MHD_HTTP_HEADER_CACHE_CONTROL, "no-store");
    const enum MHD_Result q = MHD_queue_response(c, MHD_HTTP_OK, r);
    MHD_destroy_response(r);
    return q;
}

/* ---- control ------------------------------------------------------------- */

typedef struct control {
    const char *action, *method, *steps, *rate;
    char bad[256];              /* the first thing wrong, or "" */
} control;

static enum MHD_Result one_arg(void *cls, enum MHD_ValueKind kind, const char *key,
                               size_t key_size, const char *value, size_t value_size)
{
    control *q = cls;
    (void)kind;
    if (!q->bad[0] && (strlen(key) != key_size || (value && strlen(value) != value_size)))
        snprintf(q->bad, sizeof q->bad, "a parameter holds a NUL byte (%%00)");
    const char **slot = !strcmp(key, "action")   ? &q->action
                        : !strcmp(key, "method") ? &q->method
                        : !strcmp(key, "steps")  ? &q->steps
                        : !strcmp(key, "rate")   ? &q->rate
                                                 : NULL;
    if (q->bad[0])
        return MHD_YES;
    if (!slot)
        snprintf(q->bad, sizeof q->bad, "unknown parameter '%.64s': action, method, steps, rate",
                 key);
    else if (*slot)
        snprintf(q->bad, sizeof q->bad, "parameter '%s' given twice", key);
    else
        *slot = value ? value : "";
    return MHD_YES;
}

/* A whole decimal number in [lo, hi], or a message in q->bad. */
static double number(control *q, const char *name, const char *text, double lo, double hi)
{
    char *end;
    errno = 0;
    const double x = strtod(text, &end);
    if (end == text || *end || errno == ERANGE || !isfinite(x) || strchr(text, 'x') ||
        strchr(text, 'X'))
        snprintf(q->bad, sizeof q->bad, "%s must be a finite number, not '%.64s'", name, text);
    else if (!(x >= lo && x <= hi))
        snprintf(q->bad, sizeof q->bad, "%s must be from %g to %g, not %.64s", name, lo, hi,
                 text);
    return x;
}

static enum MHD_Result do_control(server *sv, struct MHD_Connection *c)
{
    control q = {0};
    MHD_get_connection_values_n(c, MHD_GET_ARGUMENT_KIND, one_arg, &q);
    static const char *const names[] = {"run", "pause", "step", "reset", "stop", "undo"};
    int a = -1, method = -1, steps = 1;
    double rate = -1;
    for (int k = 0; k < 6 && q.action; k++)
        if (!strcmp(q.action, names[k]))
            a = k;
    if (!q.bad[0] && a < 0)
        snprintf(q.bad, sizeof q.bad,
                 "action must be run, pause, step, reset, stop or undo, not '%.64s'",
                 q.action ? q.action : "");
    if (!q.bad[0] && a == 5 && (q.method || q.steps || q.rate))
        snprintf(q.bad, sizeof q.bad, "undo takes no other parameter");
    if (!q.bad[0] && q.method && (method = radi_view_method(q.method)) < 0)
        snprintf(q.bad, sizeof q.bad,
                 "unknown method '%.64s': shooting, sorted, sorted_ambient, gathering, jacobi, "
                 "race, adaptive",
                 q.method);
    if (!q.bad[0] && q.steps) {
        const double x = number(&q, "steps", q.steps, 1, VIEW_MAX_STEPS);
        if (!q.bad[0] && x != floor(x))
            snprintf(q.bad, sizeof q.bad, "steps must be a whole number, not %.64s", q.steps);
        if (!q.bad[0]) /* a NaN or 1e99 converted would be undefined (C11 6.3.1.4) */
            steps = (int)x;
    }
    if (!q.bad[0] && q.rate)
        rate = number(&q, "rate", q.rate, 0, VIEW_MAX_RATE);
    if (q.bad[0])
        return send_error(c, MHD_HTTP_BAD_REQUEST, "%s", q.bad);
    if (a == 5) {
        char why[256];
        const int code = view_queue_undo(sv->s, why, sizeof why);
        if (code)
            return send_error(c, (unsigned)code, "%s", why);
    } else if (view_command(sv->s, (view_action)a, method, steps, rate) != 0) {
        return send_error(c, MHD_HTTP_CONFLICT,
                          "the scene has changed: the methods race on the scene as loaded "
                          "(restart the viewer to race again)");
    }
    jbuf b;
    jb_init(&b);
    jb_printf(&b, "{\"ok\":true,\"action\":\"%s\"}", names[a]);
    return send_json(c, MHD_HTTP_OK, &b);
}

/* ---- requests ------------------------------------------------------------ */

/* Does Host name this server: 127.x.y.z, localhost, [::1] or the bound
 * address, with our port? */
static int host_ok(const server *sv, const char *host)
{
    if (!host)
        return 0;
    const char *colon = strrchr(host, ':');
    if (!colon || strcmp(colon + 1, sv->port) != 0)
        return 0;
    const size_t n = (size_t)(colon - host);
    char name[64];
    if (n == 0 || n >= sizeof name)
        return 0;
    memcpy(name, host, n);
    name[n] = '\0';
    struct in_addr a;
    if (!strcmp(name, "localhost") || !strcmp(name, "[::1]") || !strcmp(name, sv->bound))
        return 1;
    return inet_pton(AF_INET, name, &a) == 1 &&
           ((ntohl(a.s_addr) >> 24) == 127 || !strcmp(sv->bound, "0.0.0.0"));
}

/* No Origin (not a browser's cross-site request), or http:// + this
 * request's Host (already accepted): the page this server served, not one
 * of another server on another loopback address or on localhost's [::1]. */
static int origin_ok(const char *origin, const char *host)
{
    static const char scheme[] = "http://";
    if (!origin)
        return 1;
    return host && !strncmp(origin, scheme, sizeof scheme - 1) &&
           !strcasecmp(origin + sizeof scheme - 1, host);
}

static const asset *asset_of(const server *sv, const char *url)
{
    for (int k = 0; k < 3; k++)
        if (!strcmp(url, sv->assets[k].path))
            return &sv->assets[k];
    return NULL;
}

static int is_post(const char *url)
{
    return !strcmp(url, "/api/control") || !strcmp(url, "/api/change");
}

static int is_api_get(const char *url)
{
    return !strcmp(url, "/api/scene") || !strcmp(url, "/api/state") ||
           !strcmp(url, "/api/elements") || !strcmp(url, "/api/events") ||
           !strcmp(url, "/api/row") || !strcmp(url, "/api/hemicube");
}

static enum MHD_Result route(server *sv, struct MHD_Connection *c, const char *url,
                             const char *method, request *rq)
{
    const int get = !strcmp(method, "GET") || !strcmp(method, "HEAD");
    const asset *a = asset_of(sv, url);
    const int post = is_post(url);
    if (!a && !post && !is_api_get(url))
        return send_error(c, MHD_HTTP_NOT_FOUND, "no such route: %.128s", url);
    if (post ? strcmp(method, "POST") != 0 : !get)
        return send_error(c, MHD_HTTP_METHOD_NOT_ALLOWED, "%.16s is not accepted on %.128s",
                          method, url);
    if (a)
        return send_text(c, MHD_HTTP_OK, a->type, a->data, a->size, 0);
    if (!strcmp(url, "/api/scene"))
        return send_scene(sv, c);
    if (!strcmp(url, "/api/change"))
        return do_change(sv, c, rq);
    if (!strcmp(url, "/api/state") || !strcmp(url, "/api/elements"))
        return send_state(sv, c, !strcmp(url, "/api/elements"));
    if (!strcmp(url, "/api/events"))
        return send_stream(sv, c);
    if (!strcmp(url, "/api/row"))
        return send_row(sv, c);
    if (!strcmp(url, "/api/hemicube"))
        return send_hemicube(sv, c);
    return do_control(sv, c);
}

static enum MHD_Result handle(void *cls, struct MHD_Connection *c, const char *url,
                              const char *method, const char *version, const char *upload,
                              size_t *upload_size, void **con_cls)
{
    server *sv = cls;
    request *rq = *con_cls;
    (void)version;
    (void)upload;
    if (!rq) { /* the headers: the body, if any, comes in the next calls */
        if (!(rq = calloc(1, sizeof *rq)))
            return MHD_NO;
        *con_cls = rq;
        const char *len = MHD_lookup_connection_value(c, MHD_HEADER_KIND,
                                                      MHD_HTTP_HEADER_CONTENT_LENGTH);
        if (len && strtod(len, NULL) > VIEW_MAX_BODY) /* answered before it is read */
            return send_error(c, MHD_HTTP_CONTENT_TOO_LARGE,
                              "a request body is limited to %d bytes", VIEW_MAX_BODY);
        return MHD_YES;
    }
    if (*upload_size > 0) { /* a body sent without its length: cut off past the limit */
        rq->body += *upload_size;
        if (rq->body <= VIEW_MAX_BODY && !strcmp(url, "/api/change")) {
            if (memchr(upload, '\0', *upload_size))
                rq->nul = 1; /* refused when the body is complete */
            jb_printf(&rq->data, "%.*s", (int)*upload_size, upload);
        }
        *upload_size = 0;
        return rq->body > VIEW_MAX_BODY || rq->data.failed ? MHD_NO : MHD_YES;
    }
    const char *host = MHD_lookup_connection_value(c, MHD_HEADER_KIND, MHD_HTTP_HEADER_HOST);
    if (!host_ok(sv, host))
        return send_error(c, MHD_HTTP_FORBIDDEN, "the Host header does not name this server");
    if (!origin_ok(MHD_lookup_connection_value(c, MHD_HEADER_KIND, "Origin"), host))
        return send_error(c, MHD_HTTP_FORBIDDEN,
                          "a request from another site's page (Origin) is not accepted");
    if (rq->body > 0 && strcmp(url, "/api/change") != 0)
        return send_error(c, MHD_HTTP_CONTENT_TOO_LARGE,
                          "%.128s takes no body: parameters go in the query string", url);
    return route(sv, c, url, method, rq);
}

static void request_done(void *cls, struct MHD_Connection *c, void **con_cls,
                         enum MHD_RequestTerminationCode why)
{
    request *rq = *con_cls;
    (void)cls;
    (void)c;
    (void)why;
    if (rq)
        jb_free(&rq->data);
    free(rq);
    *con_cls = NULL;
}

/* ---- the run ------------------------------------------------------------- */

static int read_asset(const char *dir, asset *a, rad_error *err)
{
    char path[4096];
    if (snprintf(path, sizeof path, "%s/%s", dir, a->file) >= (int)sizeof path)
        return radi_fail(err, RAD_ERR_INVALID, "%s: the assets folder's name is too long", dir),
               -1;
    FILE *f = fopen(path, "rb");
    if (!f)
        return radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno)), -1;
    size_t cap = 65536;
    a->data = malloc(cap);
    a->size = 0;
    while (a->data) {
        a->size += fread(a->data + a->size, 1, cap - a->size, f);
        if (a->size < cap)
            break;
        char *more = realloc(a->data, cap *= 2);
        if (!more)
            free(a->data);
        a->data = more;
    }
    const int bad = ferror(f);
    fclose(f);
    if (!a->data || bad)
        return radi_fail(err, bad ? RAD_ERR_IO : RAD_ERR_NOMEM, "%s: cannot read it", path), -1;
    return 0;
}

static void server_free(server *sv)
{
    for (int k = 0; k < 3; k++)
        free(sv->assets[k].data);
}

static int server_init(server *sv, view_session *s, rad_error *err)
{
    static const asset list[3] = {{"/", "index.html", "text/html; charset=utf-8", NULL, 0},
                                  {"/index.html", "index.html", "text/html; charset=utf-8", NULL, 0},
                                  {"/view.js", "view.js", "text/javascript; charset=utf-8", NULL, 0}};
    memset(sv, 0, sizeof *sv);
    sv->s = s;
    memcpy(sv->assets, list, sizeof list);
    for (int k = 0; k < 3; k++)
        if (read_asset(s->opt.assets, &sv->assets[k], err) != 0)
            return -1;
    return 0;
}

/* A socket listening on o's address and port, sv->port and sv->bound
 * set (before any request can read them); -1 with err set. */
static int listen_on(server *sv, const radi_view_options *o, rad_error *err)
{
    struct sockaddr_in addr;
    socklen_t len = sizeof addr;
    const int one = 1;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)o->port);
    if (inet_pton(AF_INET, o->address, &addr.sin_addr) != 1)
        return radi_fail(err, RAD_ERR_INVALID, "'%s' is not an IPv4 address", o->address), -1;
    const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0 || setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one) != 0 ||
        bind(fd, (struct sockaddr *)&addr, sizeof addr) != 0 || listen(fd, 64) != 0 ||
        getsockname(fd, (struct sockaddr *)&addr, &len) != 0) {
        radi_fail(err, RAD_ERR_IO, "cannot listen on %s:%d: %s", o->address, o->port,
                  strerror(errno));
        if (fd >= 0)
            close(fd);
        return -1;
    }
    snprintf(sv->port, sizeof sv->port, "%u", (unsigned)ntohs(addr.sin_port));
    snprintf(sv->bound, sizeof sv->bound, "%s", o->address);
    return fd;
}

static struct MHD_Daemon *start_daemon(server *sv, const radi_view_options *o, rad_error *err)
{
    const int fd = listen_on(sv, o, err);
    if (fd < 0)
        return NULL;
    struct MHD_Daemon *d = MHD_start_daemon(
        MHD_USE_THREAD_PER_CONNECTION | MHD_USE_INTERNAL_POLLING_THREAD, 0, NULL, NULL, handle,
        sv, MHD_OPTION_LISTEN_SOCKET, fd, MHD_OPTION_CONNECTION_LIMIT,
        (unsigned)o->max_connections, MHD_OPTION_CONNECTION_TIMEOUT, (unsigned)VIEW_IDLE,
        MHD_OPTION_CONNECTION_MEMORY_LIMIT, (size_t)65536, MHD_OPTION_NOTIFY_COMPLETED,
        request_done, NULL, MHD_OPTION_END);
    if (!d) {
        close(fd);
        return radi_fail(err, RAD_ERR_IO, "cannot serve on %s:%s", o->address, sv->port), NULL;
    }
    return d;
}

/* The desktop's browser on url (xdg-open, from the PATH), or a warning. */
static void open_browser(const char *url)
{
    char prog[] = "xdg-open", where[128];
    snprintf(where, sizeof where, "%s", url);
    char *argv[] = {prog, where, NULL};
    pid_t pid;
    const int e = posix_spawnp(&pid, "xdg-open", NULL, NULL, argv, environ);
    if (e != 0)
        fprintf(stderr, "radiosity: warning: cannot start a browser (xdg-open: %s); open %s\n",
                strerror(e), url);
}

/* Until the stop action, or the caller's o->stop (the program's signals,
 * which the library leaves to it). */
static void wait_for_stop(view_session *s, const radi_view_options *o)
{
    const struct timespec tick = {0, 200000000L};
    for (;;) {
        pthread_mutex_lock(&s->lock);
        const int stop = s->stopping;
        pthread_mutex_unlock(&s->lock);
        if (stop || (o->stop && o->stop(o->stop_user)))
            return;
        nanosleep(&tick, NULL);
    }
}

rad_status radi_view_serve(const rad_scene *scene, const rad_result *res,
                           const radi_view_options *o, char **record, rad_error *err)
{
    view_session s;
    server sv = {0};
    if (!res->F || !res->B)
        return radi_fail(err, RAD_ERR_INVALID, "the view needs the form factors and B");
    if (view_session_init(&s, scene, res, o, err) != 0)
        return err->status;
    char why[512];
    const int code = o->changes ? view_queue_changes(&s, o->changes, o->changes_len, 0, why,
                                                     sizeof why)
                                : 0;
    if (code || server_init(&sv, &s, err) != 0) {
        if (code)
            radi_fail(err, code == 400 ? RAD_ERR_PARSE : RAD_ERR_INVALID, "%s", why);
        server_free(&sv);
        view_session_free(&s);
        return err->status;
    }
    struct MHD_Daemon *d = start_daemon(&sv, o, err);
    rad_status st = d ? RAD_OK : err->status;
    if (d && (view_session_start(&s, err) != 0 || view_animator_start(&s, err) != 0))
        st = err->status;
    if (st == RAD_OK) {
        char url[128];
        snprintf(url, sizeof url, "http://%s:%s/", sv.bound, sv.port);
        fprintf(o->announce, "%s\n", url);
        fflush(o->announce);
        if (o->open_browser)
            open_browser(url);
        wait_for_stop(&s, o);
    }
    view_session_stop(&s);
    view_animator_stop(&s);
    if (d)
        MHD_stop_daemon(d);
    if (record && st == RAD_OK) { /* the frames that ran: the rest never did */
        if (s.changes.s && s.applied < s.frames)
            s.changes.s[s.frame_start[s.applied + 1]] = '\0';
        *record = s.changes.s ? s.changes.s : calloc(1, 1);
        s.changes.s = NULL;
        s.changes.len = 0;
        if (!*record)
            st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for the changes");
    }
    server_free(&sv);
    view_session_free(&s);
    return st;
}
