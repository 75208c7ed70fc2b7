/* animlog.c -- the change log of an animation (George et al. 1990, Fig. 5).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * When frames stop before they converge (--steps K), the changes come
 * faster than the redistribution: an object may move again while what its
 * last move called for is still pending.  The paper keeps a log: the
 * series of changes to one object since the last converged state is one
 * removal from where it was then and one addition where it is now.  Here
 * the log is
 *   - the objects changed since the last converged frame (log_obj) and
 *     that frame's number;
 *   - the pending redistribution, one amount per pair (receiver i,
 *     shooter j) per band: what i still has to gather from j.  A frame
 *     that changes F again adds dF_ij T_j to the pair's amount
 *     (animpairs.c, merge_columns) instead of applying the old amounts at
 *     once, so a pair's amount is the net of the series: with S unchanged
 *     it is (F_now - F_converged)_ij S_j, the paper's remove plus add;
 * with these, the state obeys H = F S - (pending) per element and band
 * (S = B - dB, the radiosity shot so far), exactly in exact arithmetic.
 *
 * The final pass (radi_anim_log_pass), when a frame converges after
 * unconverged ones (with --steps, the frame that --converge-last lets
 * converge, or any frame run without --steps): every present row's H is
 * compared with F S, recomputed from the F and S of now, and the
 * difference is gathered and propagated like any received radiosity.  It
 * removes what the interleaving of redistribution and propagation left in
 * floating point (each pair's amount was summed over many frames); it
 * costs one product F S, n^2 x 3 operations.
 *
 * The log file (rad_anim_log_write, `animate --log`) holds the state
 * that the next frame needs beyond the scene and the change file: the
 * frame, per element B, dB, H and the shoot-first flag, the pending
 * amounts, the log's objects.  F is not written: a resumed run
 * (rad_anim_resume) rebuilds the frame's scene from the change file and
 * fills F afresh, entry for entry the F a fresh solve computes, as the
 * animation keeps it.  Numbers are written with %.17g, which reads back
 * to the same double (IEEE 754, 17 significant digits).
 *
 * Format, line by line (text, tab-separated):
 *   radiosity-animation-log 1
 *   frame F  elements N  emitted0 X  converged_frame C  log_open 0|1
 *   changed OBJECT            (one line per object in the log)
 *   state                     then N lines: e first B0 B1 B2 dB0 dB1 dB2
 *                             H0 H1 H2
 *   pending M                 then M lines: j i a0 a1 a2 (amounts, by j)
 *   end
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "anim/animint.h"
#include "util/util.h"

#define LOG_MAGIC "radiosity-animation-log 1"

void radi_anim_log_pass(rad_anim *a)
{
    const size_t n = (size_t)a->n;
    double worst = 0;
    for (int i = 0; i < a->n; i++) {
        if (!a->present[i])
            continue;
        double x[RAD_BANDS];
        for (int b = 0; b < RAD_BANDS; b++) {
            const size_t k = (size_t)i + b * n;
            double h = 0;
            for (size_t j = 0; j < n; j++) /* H_i = sum_j F_ij S_j (Goral et al. 1984, eq. 6) */
                h += a->F[(size_t)i + j * n] * (a->B[j + b * n] - a->dB[j + b * n]);
            x[b] = h - a->H[k];
            if (fabs(h) > 0)
                worst = fmax(worst, fabs(x[b]) / fabs(h));
        }
        radi_anim_receive(a, i, x);
    }
    a->log_residual = worst;
}

/* ---- writing ------------------------------------------------------------- */

rad_status rad_anim_log_write(FILE *out, const rad_anim *a)
{
    const size_t n = (size_t)a->n;
    const rad_redist *rd = &a->rd;
    fprintf(out, LOG_MAGIC "\nframe\t%d\nelements\t%d\nemitted0\t%.17g\nconverged_frame\t%d\n"
            "log_open\t%d\n", a->frame, a->n, a->emitted0, a->converged_frame, a->log_open);
    for (int o = 0; o < a->scene.nobjects; o++)
        if (a->log_obj[o])
            fprintf(out, "changed\t%s\n", a->scene.objects[o].name);
    fputs("state\n", out);
    for (size_t e = 0; e < n; e++) {
        fprintf(out, "%zu\t%d", e, a->first[e]);
        const double *arr[3] = {a->B, a->dB, a->H};
        for (int q = 0; q < 3; q++)
            for (int b = 0; b < RAD_BANDS; b++)
                fprintf(out, "\t%.17g", arr[q][e + b * n]);
        fputc('\n', out);
    }
    fprintf(out, "pending\t%zu\n", rd->start ? rd->npending : 0);
    for (size_t j = 0; rd->start && j < n; j++)
        for (size_t k = rd->start[j]; k < rd->start[j + 1]; k++)
            if (!rd->done[k])
                fprintf(out, "%zu\t%d\t%.17g\t%.17g\t%.17g\n", j, rd->recv[k], rd->amt[3 * k],
                        rd->amt[3 * k + 1], rd->amt[3 * k + 2]);
    fputs("end\n", out);
    return ferror(out) ? RAD_ERR_IO : RAD_OK;
}

/* ---- reading ------------------------------------------------------------- */

/* The next line into buf (without its newline); 0 at the end (the line
 * number then names the line that is missing). */
static int next_line(FILE *in, char *buf, size_t size, int *line)
{
    (*line)++;
    if (!fgets(buf, (int)size, in)) {
        buf[0] = 0;
        return 0;
    }
    buf[strcspn(buf, "\r\n")] = 0;
    return 1;
}

static rad_status bad(rad_error *err, const char *name, int line, const char *what)
{
    return radi_fail(err, RAD_ERR_PARSE, "%s:%d: %s", name, line, what);
}

/* "KEY\tVALUE" with an integer VALUE. */
static int keyed_int(const char *buf, const char *key, int *v)
{
    const size_t k = strlen(key);
    char *end;
    if (strncmp(buf, key, k) != 0 || buf[k] != '\t')
        return 0;
    long x = strtol(buf + k + 1, &end, 10);
    if (*end || end == buf + k + 1 || x < -1 || x > 2000000000L)
        return 0;
    *v = (int)x;
    return 1;
}

rad_status radi_anim_log_header(FILE *in, const char *name, int *line, int *frame, int *n,
                               rad_error *err)
{
    char buf[256];
    if (!next_line(in, buf, sizeof buf, line) || strcmp(buf, LOG_MAGIC) != 0)
        return bad(err, name, *line, "not an animation log (" LOG_MAGIC ")");
    if (!next_line(in, buf, sizeof buf, line) || !keyed_int(buf, "frame", frame) || *frame < 0)
        return bad(err, name, *line, "expected 'frame F'");
    if (!next_line(in, buf, sizeof buf, line) || !keyed_int(buf, "elements", n) || *n < 0)
        return bad(err, name, *line, "expected 'elements N'");
    return RAD_OK;
}

/* count doubles from s into v; 0 when the line holds anything else. */
static int doubles(const char *s, double *v, int count)
{
    char *end;
    for (int k = 0; k < count; k++) {
        v[k] = strtod(s, &end);
        if (end == s)
            return 0;
        s = end;
    }
    while (*s == ' ' || *s == '\t')
        s++;
    return *s == 0;
}

static rad_status read_state(rad_anim *a, FILE *in, const char *name, int *line, char *buf,
                             size_t size, rad_error *err)
{
    const size_t n = (size_t)a->n;
    for (size_t e = 0; e < n; e++) {
        char *end;
        double v[9];
        if (!next_line(in, buf, size, line))
            return bad(err, name, *line, "the state ends early");
        unsigned long idx = strtoul(buf, &end, 10);
        long first = strtol(end, &end, 10);
        if (idx != e || (first != 0 && first != 1) || !doubles(end, v, 9))
            return bad(err, name, *line, "expected 'e first' and nine numbers");
        a->first[e] = (unsigned char)first;
        for (int b = 0; b < RAD_BANDS; b++) {
            a->B[e + b * n] = v[b];
            a->dB[e + b * n] = v[3 + b];
            a->H[e + b * n] = v[6 + b];
        }
    }
    return RAD_OK;
}

static rad_status read_pending(rad_anim *a, FILE *in, const char *name, int *line, char *buf,
                               size_t size, size_t m, rad_error *err)
{
    rad_redist *rd = &a->rd;
    const size_t n = (size_t)a->n;
    radi_redist_free(rd);
    rd->start = calloc(n + 1, sizeof *rd->start);
    rd->recv = malloc(sizeof *rd->recv * (m + 1));
    rd->amt = malloc(sizeof *rd->amt * RAD_BANDS * (m + 1));
    if (!rd->start || !rd->recv || !rd->amt)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the log's entries");
    size_t col = 0;
    for (size_t k = 0; k < m; k++) {
        char *end;
        if (!next_line(in, buf, size, line))
            return bad(err, name, *line, "the pending entries end early");
        unsigned long j = strtoul(buf, &end, 10), i = strtoul(end, &end, 10);
        if (j >= n || i >= n || j < col || !a->present[i] || !doubles(end, &rd->amt[3 * k], 3))
            return bad(err, name, *line, "expected 'j i' (present receiver, shooters in "
                       "order) and three numbers");
        for (; col < j; col++)
            rd->start[col + 1] = k;
        rd->recv[k] = (int)i;
    }
    for (; col < n; col++)
        rd->start[col + 1] = m;
    return radi_anim_redist_index(a, err);
}

rad_status radi_anim_log_body(rad_anim *a, FILE *in, const char *name, int *line,
                             rad_error *err)
{
    char buf[1024];
    int lo = 0;
    if (!next_line(in, buf, sizeof buf, line) || strncmp(buf, "emitted0\t", 9) != 0 ||
        !doubles(buf + 9, &a->emitted0, 1))
        return bad(err, name, *line, "expected 'emitted0 X'");
    if (!next_line(in, buf, sizeof buf, line) || !keyed_int(buf, "converged_frame",
                                                            &a->converged_frame))
        return bad(err, name, *line, "expected 'converged_frame C'");
    if (!next_line(in, buf, sizeof buf, line) || !keyed_int(buf, "log_open", &lo))
        return bad(err, name, *line, "expected 'log_open 0|1'");
    a->log_open = lo != 0;
    while (next_line(in, buf, sizeof buf, line) && strncmp(buf, "changed\t", 8) == 0) {
        int o = 0;
        while (o < a->scene.nobjects && strcmp(a->scene.objects[o].name, buf + 8) != 0)
            o++;
        if (o == a->scene.nobjects)
            return bad(err, name, *line, "unknown object");
        a->log_obj[o] = 1;
    }
    if (strcmp(buf, "state") != 0)
        return bad(err, name, *line, "expected 'state'");
    rad_status st = read_state(a, in, name, line, buf, sizeof buf, err);
    if (st != RAD_OK)
        return st;
    char *end;
    if (!next_line(in, buf, sizeof buf, line) || strncmp(buf, "pending\t", 8) != 0)
        return bad(err, name, *line, "expected 'pending M'");
    unsigned long m = strtoul(buf + 8, &end, 10);
    if (*end || m > (unsigned long)a->n * (unsigned long)a->n)
        return bad(err, name, *line, "expected 'pending M'");
    st = read_pending(a, in, name, line, buf, sizeof buf, m, err);
    if (st == RAD_OK && (!next_line(in, buf, sizeof buf, line) || strcmp(buf, "end") != 0))
        st = bad(err, name, *line, "expected 'end'");
    return st;
}

double rad_anim_log_residual(const rad_anim *a)
{
    return a->log_residual;
}
