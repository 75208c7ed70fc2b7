/* status.c -- names of status codes and the error record.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include <stdarg.h>
#include <stdio.h>
#include <time.h>

#include "radiosity/base.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "util/status.h"

const char *rad_strstatus(rad_status status)
{
    switch (status) {
    case RAD_OK: return "success";
    case RAD_ERR_NOMEM: return "out of memory";
    case RAD_ERR_IO: return "input/output error";
    case RAD_ERR_PARSE: return "malformed input";
    case RAD_ERR_INVALID: return "invalid argument";
    case RAD_ERR_TOOBIG: return "problem too large for memory";
    case RAD_ERR_SINGULAR: return "singular system";
    case RAD_ERR_NOCONV: return "no convergence";
    }
    return "unknown status";
}

rad_status radi_fail(rad_error *err, rad_status status, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        err->status = status;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
    }
    return status;
}

rad_status radi_fail_at(rad_error *err, const char *file, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rad_status st = radi_fail_vat(err, file, line, fmt, ap);
    va_end(ap);
    return st;
}

rad_status radi_fail_vat(rad_error *err, const char *file, int line, const char *fmt,
                        va_list ap)
{
    char what[RAD_ERRMSG_MAX];
    vsnprintf(what, sizeof what, fmt, ap);
    return radi_fail(err, RAD_ERR_PARSE, "%s:%d: %s", file, line, what);
}

/* The one table of each: the command line parses and prints these names,
 * the report writes them. */
const char *rad_solver_name(int solver)
{
    static const char *const names[] = {"gauss",       "jacobi",   "gauss-seidel",
                                        "progressive", "cholesky", "cg"};
    return solver >= 0 && solver < (int)(sizeof names / sizeof *names) ? names[solver] : NULL;
}

const char *rad_accuracy_name(int accuracy)
{
    static const char *const names[] = {"classic", "default", "reference"};
    return accuracy >= 0 && accuracy < 3 ? names[accuracy] : NULL;
}

double radi_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
