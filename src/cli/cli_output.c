/* cli_output.c -- a run's outputs: checked before the work, written
 * together after it, and never left half-done by a signal.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A command lists its outputs (path, writer, context) and calls
 *   cli_outputs_check  before any work: every path is one the program could
 *                      write (atomicfile.h, radi_afile_check), so a missing
 *                      directory is reported before an hour of solving,
 *                      and no two name one file (one would replace the
 *                      other);
 *   cli_outputs_write  after it: every temporary is opened and written
 *                      first, then all are renamed over their targets with
 *                      SIGINT, SIGTERM and SIGHUP held back, so the outputs
 *                      of one run are all old or all new.
 * Until then, a signal removes every temporary registered here and ends
 * the program with status 128 + signal.  The registry is the program's only
 * global state: a signal handler can reach nothing else.  It lives in the
 * program, not the library, which keeps none.  The handler calls only
 * unlink(2) and _exit(2), both async-signal-safe (POSIX.1-2017 2.4.3).
 *
 * Holding a signal back takes two steps.  sigprocmask(2) blocks it in the
 * calling thread only, and a signal sent to the process may go to any
 * thread that does not block it: an idle OpenMP worker, whose handler would
 * then remove the registered temporaries and exit while this thread has
 * made a temporary it has not yet registered (tests/commands/signals.sh saw one
 * left behind, once in four runs of the suite).  So a handler that finds a
 * critical section open (`holding`) only notes the signal, and the thread
 * that closes the section acts on it.
 */
#include <config.h>

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/atomicfile.h"
#include "cli/cli.h"

static const char *volatile pending[CLI_MAX_OUTPUTS];
static volatile sig_atomic_t npending;
/* cli_staged's temporaries: the array is allocated before any is counted */
static const char *volatile *volatile staged;
static volatile sig_atomic_t nstaged;
static const char **staged_alloc; /* the same array, to free */

static volatile sig_atomic_t holding;  /* a critical section is open */
static volatile sig_atomic_t deferred; /* the signal it held back, or 0 */

static void on_signal(int sig)
{
    if (holding) {
        deferred = sig;
        return;
    }
    for (sig_atomic_t k = 0; k < npending; k++)
        if (pending[k])
            unlink(pending[k]);
    for (sig_atomic_t k = 0; k < nstaged; k++)
        if (staged[k])
            unlink(staged[k]);
    _exit(128 + sig);
}

static const int caught[] = {SIGINT, SIGTERM, SIGHUP};

void cli_signals_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (size_t k = 0; k < sizeof caught / sizeof *caught; k++)
        sigaddset(&sa.sa_mask, caught[k]);
    for (size_t k = 0; k < sizeof caught / sizeof *caught; k++) {
        struct sigaction old;
        /* a signal the shell told us to ignore (nohup, &) stays ignored */
        if (sigaction(caught[k], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
            sigaction(caught[k], &sa, NULL);
    }
}

static void hold_signals(int hold, sigset_t *old)
{
    sigset_t set;
    sigemptyset(&set);
    for (size_t k = 0; k < sizeof caught / sizeof *caught; k++)
        sigaddset(&set, caught[k]);
    if (hold) {
        sigprocmask(SIG_BLOCK, &set, old);
        holding = 1;
    } else {
        sigprocmask(SIG_SETMASK, old, NULL); /* one blocked here runs now */
        holding = 0;
        if (deferred) /* one another thread took while the section was open */
            on_signal(deferred);
    }
}

void cli_signals_defer(int defer)
{
    holding = defer;
    if (!defer && deferred) /* one that came after the last look */
        on_signal(deferred);
}

int cli_signal_taken(void)
{
    const int sig = deferred;
    deferred = 0;
    return sig;
}

/* Do paths a and b name one file that each output would replace (a
 * regular file, or a name not there yet): the same string, or (both
 * existing) the same device and inode (./x and x, a link)?  Standard
 * output, devices and FIFOs are written in place, and several outputs
 * may share one (all of them to /dev/null). */
static int same_file(const char *a, const char *b)
{
    if (!strcmp(a, "-") || !strcmp(b, "-"))
        return 0;
    struct stat sa, sb;
    const int ea = stat(a, &sa) == 0, eb = stat(b, &sb) == 0;
    if ((ea && !S_ISREG(sa.st_mode)) || (eb && !S_ISREG(sb.st_mode)))
        return 0;
    return !strcmp(a, b) ||
           (ea && eb && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino);
}

int cli_png_name_check(const char *path, const char *option)
{
    static const char *const other[] = {".jpg", ".jpeg", ".gif", ".bmp", ".tif", ".tiff",
                                        ".webp", ".ppm", ".pgm", ".svg", ".pdf", ".eps",
                                        ".exr", ".hdr", ".tga"};
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (!dot || (slash && slash > dot))
        return 0;
    for (size_t k = 0; k < sizeof other / sizeof *other; k++)
        if (!strcasecmp(dot, other[k])) {
            cli_error("%s '%s': the picture is written as PNG only, not %s (name it .png)",
                      option, path, dot + 1);
            return 1;
        }
    return 0;
}

int cli_outputs_check(const cli_output *o, int n)
{
    rad_error err;
    for (int k = 0; k < n; k++)
        for (int l = k + 1; l < n && o[k].path; l++)
            if (o[l].path && same_file(o[k].path, o[l].path)) {
                /* one would silently replace the other */
                if (!strcmp(o[k].path, o[l].path))
                    cli_error("%s: named by two outputs of the run", o[k].path);
                else
                    cli_error("%s and %s: one file named by two outputs of the run",
                              o[k].path, o[l].path);
                return 1;
            }
    for (int k = 0; k < n; k++) {
        if (o[k].path && radi_afile_check(o[k].path, &err) != RAD_OK) {
            cli_error_rec(&err);
            return 1;
        }
    }
    return 0;
}

static void abort_all(rad_afile *f, int n)
{
    sigset_t old;
    hold_signals(1, &old);
    for (int k = 0; k < n; k++)
        radi_afile_abort(&f[k]);
    npending = 0;
    hold_signals(0, &old);
}

/* Open every output (registering its temporary) and write it. */
static int write_all(const cli_output *o, int n, rad_afile *f)
{
    rad_error err;
    for (int k = 0; k < n; k++) {
        if (!o[k].path)
            continue;
        sigset_t old;
        hold_signals(1, &old); /* created and registered as one step */
        rad_status st = radi_afile_open(&f[k], o[k].path, &err);
        if (st == RAD_OK && f[k].tmp)
            pending[npending++] = f[k].tmp;
        hold_signals(0, &old);
        if (st != RAD_OK) {
            cli_error_rec(&err);
            return 1;
        }
        errno = 0;
        if (o[k].write(f[k].fp, o[k].ctx) != 0 || fflush(f[k].fp) != 0 || ferror(f[k].fp)) {
            cli_error("%s: %s", o[k].path, errno ? strerror(errno) : "write error");
            return 1;
        }
    }
    return 0;
}

int cli_outputs_write(const cli_output *o, int n)
{
    rad_afile f[CLI_MAX_OUTPUTS];
    rad_error err;
    int status = 0;
    if (n > CLI_MAX_OUTPUTS)
        abort(); /* a programming error: raise CLI_MAX_OUTPUTS */
    memset(f, 0, sizeof f);
    if (write_all(o, n, f)) {
        abort_all(f, n);
        return 1;
    }
    sigset_t old;
    hold_signals(1, &old); /* all renamed, or a signal waits until they are */
    for (int k = 0; k < n; k++) {
        if (!o[k].path)
            continue;
        if (status) { /* one failed: keep the old versions of the rest */
            radi_afile_abort(&f[k]);
        } else if (radi_afile_commit(&f[k], &err) != RAD_OK) {
            cli_error_rec(&err);
            status = 1;
        }
    }
    npending = 0;
    hold_signals(0, &old);
    return status;
}

int cli_write_atomic(const char *path, cli_writer_fn fn, const void *ctx)
{
    cli_output o = {path, fn, ctx};
    return cli_outputs_write(&o, 1);
}

/* ---- staged outputs ------------------------------------------------------ */

int cli_staged_begin(cli_staged *s, int capacity)
{
    memset(s, 0, sizeof *s);
    if (capacity < 1)
        capacity = 1;
    s->f = calloc((size_t)capacity, sizeof *s->f);
    const char **names = calloc((size_t)capacity, sizeof *names);
    if (!s->f || !names || staged) { /* staged: one set at a time */
        free(s->f);
        free(names);
        s->f = NULL;
        cli_error("out of memory for %d outputs", capacity);
        return 1;
    }
    s->cap = capacity;
    nstaged = 0;
    staged_alloc = names;
    staged = names;
    return 0;
}

int cli_staged_write(cli_staged *s, const char *path, cli_writer_fn fn, const void *ctx)
{
    rad_error err;
    if (s->n == s->cap)
        abort(); /* a programming error: the capacity counts every output */
    rad_afile *f = &s->f[s->n];
    sigset_t old;
    hold_signals(1, &old); /* created and registered as one step */
    rad_status st = radi_afile_open(f, path, &err);
    if (st == RAD_OK) {
        staged[s->n] = f->tmp; /* NULL for a direct output */
        nstaged = ++s->n;
    }
    hold_signals(0, &old);
    if (st != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    errno = 0;
    if (fn(f->fp, ctx) != 0 || fflush(f->fp) != 0 || ferror(f->fp)) {
        cli_error("%s: %s", path, errno ? strerror(errno) : "write error");
        return 1;
    }
    hold_signals(1, &old); /* a failed close removes the temporary it names */
    st = radi_afile_close(f, &err);
    if (st != RAD_OK)
        staged[s->n - 1] = NULL;
    hold_signals(0, &old);
    if (st != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    return 0;
}

static void staged_end(cli_staged *s)
{
    sigset_t old;
    hold_signals(1, &old);
    nstaged = 0;
    staged = NULL;
    free(staged_alloc);
    staged_alloc = NULL;
    hold_signals(0, &old);
    free(s->f);
    memset(s, 0, sizeof *s);
}

int cli_staged_commit(cli_staged *s)
{
    rad_error err;
    int status = 0;
    sigset_t old;
    hold_signals(1, &old); /* all renamed, or a signal waits until they are */
    for (int k = 0; k < s->n; k++) {
        if (status) {
            radi_afile_abort(&s->f[k]);
        } else if (radi_afile_commit(&s->f[k], &err) != RAD_OK) {
            cli_error_rec(&err);
            status = 1;
        }
        staged[k] = NULL;
    }
    hold_signals(0, &old);
    staged_end(s);
    return status;
}

void cli_staged_abort(cli_staged *s)
{
    if (!s->f)
        return;
    sigset_t old;
    hold_signals(1, &old);
    for (int k = 0; k < s->n; k++) {
        staged[k] = NULL;
        radi_afile_abort(&s->f[k]);
    }
    hold_signals(0, &old);
    staged_end(s);
}
