/* status.h -- filling the error record (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_STATUS_H
#define RAD_STATUS_H

#include <stdarg.h>

#include "radiosity/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Fill err (if not NULL) with status and a printf-style message; return
 * status, so callers can write `return radi_fail(err, RAD_ERR_IO, ...)`. */
rad_status radi_fail(rad_error *err, rad_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* RAD_ERR_PARSE with the message "FILE:LINE: what" (input errors); _at
 * takes the arguments themselves, _vat a va_list for a reader's own
 * wrapper. */
rad_status radi_fail_at(rad_error *err, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
rad_status radi_fail_vat(rad_error *err, const char *file, int line, const char *fmt,
                        va_list ap) __attribute__((format(printf, 4, 0)));

/* Wall-clock seconds from an arbitrary origin (CLOCK_MONOTONIC): the one
 * clock behind every time the program reports. */
double radi_seconds(void);

#ifdef __cplusplus
}
#endif

#endif /* RAD_STATUS_H */
