/* jsonread.c -- the change lines of a JSON request body.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * POST /api/change takes the lines of a change file as its body, as text,
 * or as JSON (Content-Type: application/json) in one of these forms:
 *     "move box 10 0 0"
 *     ["move box 10 0 0", "rotate box 0 1 0 15"]
 *     {"changes": "move box 10 0 0\nframe\nremove box"}
 *     {"changes": ["move box 10 0 0", ...]}      ("change" too)
 * each string one or more lines.  JSON as RFC 8259: strings with every
 * escape of section 7 (\uXXXX as UTF-8, surrogate pairs joined),
 * whitespace between tokens, nothing after the value.  Anything else
 * (another key, a number where a string belongs, a NUL, a lone surrogate,
 * a truncated text) is refused with the offset where it went wrong.
 */
#include <config.h>

#include <stdio.h>
#include <string.h>

#include "view/viewint.h"

typedef struct jr {
    const char *s;
    size_t n, at;
    char *why;
    size_t cap;
} jr;

static int bad(jr *r, const char *what)
{
    snprintf(r->why, r->cap, "JSON body, byte %zu: %s", r->at + 1, what);
    return -1;
}

static void space(jr *r)
{
    while (r->at < r->n && (r->s[r->at] == ' ' || r->s[r->at] == '\t' || r->s[r->at] == '\n' ||
                            r->s[r->at] == '\r'))
        r->at++;
}

static int hex4(jr *r, unsigned *u)
{
    *u = 0;
    for (int k = 0; k < 4; k++, r->at++) {
        const char c = r->at < r->n ? r->s[r->at] : '\0';
        const int d = c >= '0' && c <= '9'   ? c - '0'
                      : c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                             : -1;
        if (d < 0)
            return bad(r, "\\u needs four hexadecimal digits");
        *u = *u * 16 + (unsigned)d;
    }
    return 0;
}

static void utf8(jbuf *out, unsigned u)
{
    if (u < 0x80)
        jb_printf(out, "%c", (char)u);
    else if (u < 0x800)
        jb_printf(out, "%c%c", (char)(0xc0 | u >> 6), (char)(0x80 | (u & 0x3f)));
    else if (u < 0x10000)
        jb_printf(out, "%c%c%c", (char)(0xe0 | u >> 12), (char)(0x80 | (u >> 6 & 0x3f)),
                  (char)(0x80 | (u & 0x3f)));
    else
        jb_printf(out, "%c%c%c%c", (char)(0xf0 | u >> 18), (char)(0x80 | (u >> 12 & 0x3f)),
                  (char)(0x80 | (u >> 6 & 0x3f)), (char)(0x80 | (u & 0x3f)));
}

/* \uXXXX (the backslash and u read), a surrogate pair joined. */
static int escape_u(jr *r, jbuf *out)
{
    unsigned u, lo;
    if (hex4(r, &u))
        return -1;
    if (u >= 0xdc00 && u <= 0xdfff)
        return bad(r, "a low surrogate alone");
    if (u >= 0xd800 && u <= 0xdbff) {
        if (r->at + 2 > r->n || r->s[r->at] != '\\' || r->s[r->at + 1] != 'u')
            return bad(r, "a high surrogate alone");
        r->at += 2;
        if (hex4(r, &lo) || lo < 0xdc00 || lo > 0xdfff)
            return bad(r, "a high surrogate without its low one");
        u = 0x10000 + ((u - 0xd800) << 10) + (lo - 0xdc00);
    }
    if (u == 0)
        return bad(r, "a NUL character");
    utf8(out, u);
    return 0;
}

/* A string (at its opening quote) appended to out. */
static int string(jr *r, jbuf *out)
{
    static const char from[] = "\"\\/bfnrt", to[] = "\"\\/\b\f\n\r\t";
    if (r->at >= r->n || r->s[r->at] != '"')
        return bad(r, "a string expected");
    for (r->at++; r->at < r->n; r->at++) {
        const char c = r->s[r->at];
        if (c == '"') {
            r->at++;
            return 0;
        }
        if ((unsigned char)c < 0x20)
            return bad(r, "a control character in a string");
        if (c != '\\') {
            jb_printf(out, "%c", c);
            continue;
        }
        if (++r->at >= r->n)
            break;
        const char *e = strchr(from, r->s[r->at]);
        if (r->s[r->at] == 'u') {
            r->at++;
            if (escape_u(r, out))
                return -1;
            r->at--;
        } else if (e && r->s[r->at])
            jb_printf(out, "%c", to[e - from]);
        else
            return bad(r, "an unknown escape");
    }
    return bad(r, "a string not closed");
}

/* A string, or an array of strings (each a line), appended to out. */
static int lines(jr *r, jbuf *out)
{
    space(r);
    if (r->at < r->n && r->s[r->at] == '"') {
        if (string(r, out))
            return -1;
        jb_printf(out, "\n");
        return 0;
    }
    if (r->at >= r->n || r->s[r->at] != '[')
        return bad(r, "a string or an array of strings expected");
    r->at++;
    space(r);
    if (r->at < r->n && r->s[r->at] == ']') {
        r->at++;
        return 0;
    }
    for (;;) {
        space(r);
        if (string(r, out))
            return -1;
        jb_printf(out, "\n");
        space(r);
        if (r->at < r->n && r->s[r->at] == ',') {
            r->at++;
            continue;
        }
        if (r->at < r->n && r->s[r->at] == ']') {
            r->at++;
            return 0;
        }
        return bad(r, "',' or ']' expected");
    }
}

/* {"changes": LINES} or {"change": LINES}. */
static int object(jr *r, jbuf *out)
{
    jbuf key;
    r->at++;
    space(r);
    jb_init(&key);
    if (string(r, &key)) {
        jb_free(&key);
        return -1;
    }
    const int known = key.s && (!strcmp(key.s, "changes") || !strcmp(key.s, "change"));
    jb_free(&key);
    if (!known)
        return bad(r, "the only key is \"changes\" (or \"change\")");
    space(r);
    if (r->at >= r->n || r->s[r->at] != ':')
        return bad(r, "':' expected");
    r->at++;
    if (lines(r, out))
        return -1;
    space(r);
    if (r->at >= r->n || r->s[r->at] != '}')
        return bad(r, "'}' expected (one key only)");
    r->at++;
    return 0;
}

int view_json_changes(const char *s, size_t n, jbuf *out, char *why, size_t cap)
{
    jr r = {s, n, 0, why, cap};
    space(&r);
    if (r.at < n && s[r.at] == '{' ? object(&r, out) : lines(&r, out))
        return -1;
    space(&r);
    if (r.at != n)
        return bad(&r, "text after the value");
    if (out->failed)
        return snprintf(why, cap, "out of memory"), -1;
    return 0;
}
