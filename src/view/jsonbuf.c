/* jsonbuf.c -- a growable text buffer that writes JSON values.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * JSON as RFC 8259: numbers have no NaN or infinity (they are written
 * null), strings escape the quote, the backslash and the control
 * characters (section 7), and a byte that does not begin a well-formed
 * UTF-8 sequence (RFC 3629, section 4: no overlong form, no surrogate,
 * nothing past U+10FFFF) is written U+FFFD: a client's bytes echoed, or
 * a name in an OBJ file, may not be UTF-8 (section 8.1).
 */
#include <config.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "view/viewint.h"

void jb_init(jbuf *b)
{
    memset(b, 0, sizeof *b);
}

void jb_free(jbuf *b)
{
    free(b->s);
    jb_init(b);
}

static int grow(jbuf *b, size_t more)
{
    if (b->failed)
        return -1;
    if (b->len + more + 1 <= b->cap)
        return 0;
    size_t cap = b->cap ? b->cap : 4096;
    while (cap < b->len + more + 1)
        cap *= 2;
    char *s = realloc(b->s, cap);
    if (!s) {
        b->failed = 1;
        return -1;
    }
    b->s = s;
    b->cap = cap;
    return 0;
}

void jb_put(jbuf *b, const char *s, size_t n)
{
    if (grow(b, n) != 0)
        return; /* (failed set) */
    memcpy(b->s + b->len, s, n);
    b->len += n;
    b->s[b->len] = '\0';
}

void jb_printf(jbuf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (k < 0 || grow(b, (size_t)k) != 0) {
        b->failed = 1;
        return;
    }
    va_start(ap, fmt);
    vsnprintf(b->s + b->len, (size_t)k + 1, fmt, ap);
    va_end(ap);
    b->len += (size_t)k;
}

void jb_num(jbuf *b, double x, int exact)
{
    if (!isfinite(x))
        jb_printf(b, "null");
    else
        jb_printf(b, exact ? "%.17g" : "%.9g", x);
}

/* The length of the well-formed UTF-8 sequence at p (2 to 4), or 0. */
static int utf8_length(const unsigned char *p)
{
    const unsigned c = p[0];
    const int n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3
                  : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
    /* the second byte's range (RFC 3629, section 4) */
    const unsigned lo = c == 0xe0 ? 0xa0 : c == 0xf0 ? 0x90 : 0x80;
    const unsigned hi = c == 0xed ? 0x9f : c == 0xf4 ? 0x8f : 0xbf;
    if (n == 0 || p[1] < lo || p[1] > hi)
        return 0;
    for (int k = 2; k < n; k++)
        if (p[k] < 0x80 || p[k] > 0xbf)
            return 0;
    return n;
}

void jb_str(jbuf *b, const char *s)
{
    jb_printf(b, "\"");
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\')
            jb_printf(b, "\\%c", *p);
        else if (*p < 0x20)
            jb_printf(b, "\\u%04x", *p);
        else if (*p >= 0x80) {
            const int n = utf8_length(p);
            if (n)
                jb_printf(b, "%.*s", n, (const char *)p);
            else
                jb_printf(b, "\\ufffd");
            p += n ? n - 1 : 0;
        }
        else
            jb_printf(b, "%c", *p);
    }
    jb_printf(b, "\"");
}
