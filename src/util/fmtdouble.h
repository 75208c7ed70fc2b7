/* fmtdouble.h -- printf's "%.*g" for doubles, exact and fast.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The form-factor table of a 20 x 20 cube is 5.76 million lines; glibc's
 * printf, which formats every double with multiple-precision arithmetic,
 * spent seven times as long printing it as the fill spent computing it.
 * radi_fmt_g writes the bytes snprintf(buf, size, "%.*g", prec, v) writes
 * (round to nearest, ties to even, in the default rounding mode), from one
 * 64 x 128-bit product, and falls back to snprintf itself in the rare
 * cases that product cannot decide (fmtdouble.c).
 */
#ifndef RAD_FMTDOUBLE_H
#define RAD_FMTDOUBLE_H

#include <stddef.h>

/* The room radi_fmt_g needs where it writes.  Its longest output,
 * "-1.2345678901234567e-308" or "-0.00012345678901234567", is 24 bytes and
 * a NUL, but it copies digits in fixed lengths, to at most 35 bytes. */
#define RAD_FMT_G_MAX 40

/* Write v as "%.*g" with precision prec (1..17; outside, snprintf does the
 * work) into buf, which holds at least RAD_FMT_G_MAX bytes; NUL-terminate
 * it and return its length. */
int radi_fmt_g(char *buf, double v, int prec);

/* radi_fmt_g without the fallback: the length, or -1 (buf undefined) when
 * the one product cannot decide or prec is outside 1..17.  For tests. */
int radi_fmt_g_fast(char *buf, double v, int prec);

/* Write the decimal digits of a non-negative int (no NUL); return the
 * length (at most 10). */
int radi_fmt_uint(char *buf, unsigned v);

#endif /* RAD_FMTDOUBLE_H */
