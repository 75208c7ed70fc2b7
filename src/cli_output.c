/* cli_output.c -- a run's outputs: checked before the work, written
 * together after it, and never left half-done by a signal.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A command lists its outputs (path, writer, context) and calls
 *   cli_outputs_check  before any work: every path is one the program could
 *                      write (atomicfile.h, rad_afile_check), so a missing
 *                      directory is reported before an hour of solving;
 *   cli_outputs_write  after it: every temporary is opened and written
 *                      first, then all are renamed over their targets with
 *                      SIGINT, SIGTERM and SIGHUP held back, so the outputs
 *                      of one run are all old or all new.
 * Until then, a signal removes every temporary registered here and ends
 * the program with status 128 + signal.  The registry is the program's only
 * global state: a signal handler can reach nothing else.  It lives in the
 * program, not the library, which keeps none.  The handler calls only
 * unlink(2) and _exit(2), both async-signal-safe (POSIX.1-2017 2.4.3).
 */
#include <config.h>

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "atomicfile.h"
#include "cli.h"

static const char *volatile pending[CLI_MAX_OUTPUTS];
static volatile sig_atomic_t npending;

static void on_signal(int sig)
{
    for (sig_atomic_t k = 0; k < npending; k++)
        if (pending[k])
            unlink(pending[k]);
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
    if (hold)
        sigprocmask(SIG_BLOCK, &set, old);
    else
        sigprocmask(SIG_SETMASK, old, NULL);
}

int cli_outputs_check(const cli_output *o, int n)
{
    rad_error err;
    for (int k = 0; k < n; k++) {
        if (o[k].path && rad_afile_check(o[k].path, &err) != RAD_OK) {
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
        rad_afile_abort(&f[k]);
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
        rad_status st = rad_afile_open(&f[k], o[k].path, &err);
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
            rad_afile_abort(&f[k]);
        } else if (rad_afile_commit(&f[k], &err) != RAD_OK) {
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
