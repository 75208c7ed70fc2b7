/* tap.h -- a minimal Test Anything Protocol writer for the unit tests.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Each check prints "ok N - what" or "not ok N - what"; tap_done() prints
 * the plan "1..N" and returns the exit status.  Automake's tap-driver.sh
 * counts every check, so `make check` reports checks, not programs.
 *
 * Tolerances: tap_close() compares |got - want| <= tol * max(|want|, tiny);
 * every caller states where its tolerance comes from.
 */
#ifndef RAD_TESTS_TAP_H
#define RAD_TESTS_TAP_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

typedef struct tap_state {
    int count;
    int failed;
} tap_state;

static tap_state tap_ = {0, 0};

static void tap_ok(int cond, const char *fmt, ...)
    __attribute__((format(printf, 2, 3), unused));
static void tap_ok(int cond, const char *fmt, ...)
{
    va_list ap;
    tap_.count++;
    if (!cond)
        tap_.failed++;
    printf("%s %d - ", cond ? "ok" : "not ok", tap_.count);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    fflush(stdout);
}

/* Relative comparison: |got - want| <= rel * |want| (absolute when want = 0). */
static int tap_close(double got, double want, double rel, const char *what)
    __attribute__((unused));
static int tap_close(double got, double want, double rel, const char *what)
{
    double scale = fabs(want) > 0 ? fabs(want) : 1.0;
    double err = fabs(got - want) / scale;
    int ok = isfinite(got) && err <= rel;
    tap_ok(ok, "%s: got %.17g want %.17g (rel err %.3g, tol %.3g)", what, got,
           want, err, rel);
    return ok;
}

static void tap_diag(const char *fmt, ...) __attribute__((format(printf, 1, 2), unused));
static void tap_diag(const char *fmt, ...)
{
    va_list ap;
    printf("# ");
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
}

static int tap_done(void) __attribute__((unused));
static int tap_done(void)
{
    printf("1..%d\n", tap_.count);
    return tap_.failed ? 1 : 0;
}

#endif /* RAD_TESTS_TAP_H */
