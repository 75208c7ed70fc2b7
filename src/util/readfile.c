/* readfile.c -- the one line reader of the text parsers.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The parsers (scene.c, plyread.c) pull one line at a time, so an error is
 * reported as soon as its line has been read and memory stays bounded by
 * the limits of readfile.h whatever the input is: /dev/zero fails at its
 * first byte (NUL), an endless line at RAD_LINE_MAX bytes, an endless
 * stream of lines at RAD_FILE_MAX.  A file is read byte by byte through
 * stdio's buffer (getc_unlocked), which returns what a pipe has as soon as
 * it has it; text in memory (rad_scene_parse, rad_ply_parse, the fuzz
 * harnesses) goes through the same code, so both see the same rules.
 *
 * End of line: LF, CR LF or a lone CR.  A CR is looked ahead past by one
 * byte, which goes back into a three-byte queue (`back`); the same queue
 * holds the first bytes while the reader looks for a UTF-8 byte order mark.
 */
#include <config.h>

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "util/readfile.h"
#include "util/status.h"

#define END_OF_INPUT (-1)
#define OVER_LIMIT (-2)

static void lines_init(rad_lines *r, const char *name, char comment, rad_error *err)
{
    memset(r, 0, sizeof *r);
    r->name = name;
    r->err = err;
    r->comment = comment;
    r->line_max = RAD_LINE_MAX;
    r->file_max = RAD_FILE_MAX;
}

rad_status radi_lines_open(rad_lines *r, const char *path, char comment, rad_error *err)
{
    lines_init(r, path, comment, err);
    const int is_stdin = strcmp(path, "-") == 0;
    r->f = is_stdin ? stdin : fopen(path, "rb");
    if (!r->f)
        return r->status = radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno));
    r->close_f = !is_stdin;
    struct stat st;
    if (fstat(fileno(r->f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0)
        r->known_size = (size_t)st.st_size;
    return RAD_OK;
}

void radi_lines_mem(rad_lines *r, const char *text, size_t len, const char *name,
                   char comment, rad_error *err)
{
    lines_init(r, name, comment, err);
    r->mem = text;
    r->mem_len = len;
    r->known_size = len;
}

void radi_lines_close(rad_lines *r)
{
    if (r->close_f)
        fclose(r->f);
    free(r->text);
    free(r->tok);
    r->f = NULL;
    r->close_f = 0;
    r->text = NULL;
    r->tok = NULL;
    r->ntok = 0;
}

rad_status radi_lines_fail(const rad_lines *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rad_status st = radi_fail_vat(r->err, r->name, r->line > 0 ? r->line : 1, fmt, ap);
    va_end(ap);
    return st;
}

size_t radi_lines_left(const rad_lines *r)
{
    size_t bound = r->known_size && r->known_size < r->file_max ? r->known_size : r->file_max;
    return bound > r->total ? bound - r->total : 0;
}

/* ---- bytes ---------------------------------------------------------------- */

static int raw_byte(rad_lines *r)
{
    if (!r->f)
        return r->mem_pos < r->mem_len ? (unsigned char)r->mem[r->mem_pos++] : END_OF_INPUT;
    int c = getc_unlocked(r->f);
    return c == EOF ? END_OF_INPUT : c;
}

static void put_back(rad_lines *r, int c)
{
    memmove(r->back + 1, r->back, (size_t)r->nback);
    r->back[0] = (unsigned char)c;
    r->nback++;
}

/* The next byte, counted against the file limit: a byte, END_OF_INPUT or
 * OVER_LIMIT. */
static int next_byte(rad_lines *r)
{
    int c;
    if (r->nback > 0) {
        c = r->back[0];
        memmove(r->back, r->back + 1, (size_t)--r->nback);
        return c;
    }
    if (r->total > r->file_max)
        return OVER_LIMIT; /* and so on, once crossed */
    c = raw_byte(r);
    if (c == END_OF_INPUT)
        return c;
    if (++r->total > r->file_max)
        return OVER_LIMIT;
    return c;
}

/* Skip a UTF-8 byte order mark (EF BB BF) at the very start. */
static void skip_bom(rad_lines *r)
{
    static const unsigned char bom[3] = {0xEF, 0xBB, 0xBF};
    int got[3], n = 0;
    r->started = 1;
    while (n < 3 && (got[n] = next_byte(r)) >= 0 && got[n] == bom[n])
        n++;
    if (n == 3)
        return;
    if (n < 3 && got[n] != END_OF_INPUT)
        n++; /* the byte that differed goes back too (or OVER_LIMIT, below) */
    for (int k = n - 1; k >= 0; k--)
        if (got[k] >= 0)
            put_back(r, got[k]);
}

/* ---- lines ---------------------------------------------------------------- */

static int fail_line(rad_lines *r, rad_status st)
{
    r->status = st;
    r->failed = 1;
    return -1;
}

static int append(rad_lines *r, char c)
{
    if (r->len + 1 >= r->cap) {
        size_t ncap = r->cap ? 2 * r->cap : 256;
        if (ncap > r->line_max + 1)
            ncap = r->line_max + 1;
        char *g = realloc(r->text, ncap);
        if (!g)
            return -1;
        r->text = g;
        r->cap = ncap;
    }
    r->text[r->len++] = c;
    return 0;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/* Split r->text in place into white-space separated tokens, up to the
 * comment character. */
static int tokenize(rad_lines *r)
{
    char *p = r->text;
    if (r->comment) {
        char *hash = strchr(p, r->comment);
        if (hash)
            *hash = '\0';
    }
    r->ntok = 0;
    for (;;) {
        while (is_blank(*p))
            p++;
        if (!*p)
            return 0;
        if (r->ntok == r->tokcap) {
            int ncap = r->tokcap ? 2 * r->tokcap : 32;
            char **g = realloc(r->tok, sizeof *g * (size_t)ncap);
            if (!g)
                return -1;
            r->tok = g;
            r->tokcap = ncap;
        }
        r->tok[r->ntok++] = p;
        while (*p && !is_blank(*p))
            p++;
        if (*p)
            *p++ = '\0';
    }
}

/* Does the input start with a UTF-16 byte order mark (FF FE or FE FF)? */
static int utf16_start(const rad_lines *r)
{
    const unsigned char *t = (const unsigned char *)r->text;
    return r->line == 1 && r->len >= 2 &&
           ((t[0] == 0xFF && t[1] == 0xFE) || (t[0] == 0xFE && t[1] == 0xFF));
}

static int read_error(rad_lines *r)
{
    return fail_line(r, radi_fail(r->err, RAD_ERR_IO, "%s: %s", r->name,
                                 strerror(errno ? errno : EIO)));
}

static int over_limit(rad_lines *r)
{
    return fail_line(r, radi_lines_fail(r, "the input is longer than %zu bytes (the limit)",
                                       r->file_max));
}

int radi_lines_next(rad_lines *r)
{
    if (r->failed)
        return -1;
    if (!r->started)
        skip_bom(r);
    r->len = 0;
    r->ntok = 0;
    errno = 0;
    int c = next_byte(r);
    if (c == OVER_LIMIT)
        return over_limit(r);
    if (c == END_OF_INPUT)
        return r->f && ferror(r->f) ? read_error(r) : 0;
    r->line++;
    while (c != '\n' && c != '\r') {
        if (c == END_OF_INPUT) {
            if (r->f && ferror(r->f))
                return read_error(r);
            break;
        }
        if (c == OVER_LIMIT)
            return over_limit(r);
        if (c == '\0')
            return fail_line(r, radi_lines_fail(r, "line contains a NUL character (byte 0x00 "
                                                  "at column %zu%s)", r->len + 1,
                                               utf16_start(r) ? "; a UTF-16 file? save it "
                                                                "as ASCII or UTF-8" : ""));
        if (r->len >= r->line_max)
            return fail_line(r, radi_lines_fail(r, "line longer than %zu bytes (the limit)",
                                               r->line_max));
        if (append(r, (char)c))
            return fail_line(r, radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory",
                                         r->name, r->line));
        c = next_byte(r);
    }
    if (c == '\r') { /* CR LF is one line end; a lone CR is one too */
        int d = next_byte(r);
        if (d == OVER_LIMIT)
            return over_limit(r);
        if (d >= 0 && d != '\n')
            put_back(r, d);
    }
    if (append(r, '\0') || tokenize(r))
        return fail_line(r, radi_fail(r->err, RAD_ERR_NOMEM, "%s:%d: out of memory", r->name,
                                     r->line));
    r->len--;
    return 1;
}

/* ---- token checks ----------------------------------------------------------- */

rad_status radi_lines_ascii(const rad_lines *r, int from)
{
    for (int k = from; k < r->ntok; k++)
        for (const unsigned char *p = (const unsigned char *)r->tok[k]; *p; p++) {
            if (*p > 0x20 && *p < 0x7f)
                continue;
            const size_t col = (size_t)((const char *)p - r->text) + 1;
            if (*p < 0x80)
                return radi_lines_fail(r, "control character (byte 0x%02X at column %zu); "
                                         "only printable ASCII may appear outside comments",
                                      *p, col);
            return radi_lines_fail(r, "non-ASCII character (byte 0x%02X at column %zu%s); "
                                     "only printable ASCII may appear outside comments",
                                  *p, col,
                                  p[0] == 0xC2 && p[1] == 0xA0
                                      ? ", a UTF-8 no-break space U+00A0?" : "");
        }
    return RAD_OK;
}
