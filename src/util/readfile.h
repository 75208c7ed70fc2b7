/* readfile.h -- the one line reader of the text parsers (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The scene parser (scene.c) and the PLY reader (plyread.c) read their
 * input through this reader, one line at a time, from a file, standard
 * input or text in memory.  What it guarantees, for both:
 *   - bounded memory: a line holds at most RAD_LINE_MAX bytes and a file at
 *     most RAD_FILE_MAX; the first line over either limit is an error with
 *     its line number, reported as soon as the limit is crossed (so
 *     /dev/zero or an endless pipe is refused at once, not read whole);
 *   - lines end with LF, CR LF or a lone CR (old Mac OS files), and one
 *     UTF-8 byte order mark at the start of the input is skipped;
 *   - a NUL byte is an error naming its line, found as the byte is read;
 *   - one tokenizer: white space (space, tab, CR, FF, VT) separates tokens,
 *     and an optional comment character ends the line's text.
 * Messages read "NAME:LINE: what is wrong" (RAD_ERR_PARSE), or
 * "NAME: reason" when reading itself fails (RAD_ERR_IO).
 */
#ifndef RAD_READFILE_H
#define RAD_READFILE_H

#include <stdio.h>
#include <stddef.h>

#include "radiosity/base.h"

#define RAD_LINE_MAX ((size_t)1 << 20)   /* 1 MiB: bytes in a line, without its end */
#define RAD_FILE_MAX ((size_t)1 << 30)   /* 1 GiB: bytes in a file */

typedef struct rad_lines {
    /* The current line: its text (split in place by the tokenizer), its
     * number from 1, and its tokens.  Read-only for the parsers. */
    char *text;
    int line;
    char **tok;
    int ntok;
    const char *name;           /* in messages */
    rad_error *err;
    rad_status status;          /* of the failure that made radi_lines_next return -1 */
    /* Limits: RAD_LINE_MAX and RAD_FILE_MAX unless a test lowers them. */
    size_t line_max, file_max;
    /* private */
    FILE *f;                    /* NULL: read from mem */
    int close_f;
    const char *mem;
    size_t mem_len, mem_pos;
    size_t known_size;          /* a regular file's size or mem_len; 0: unknown */
    size_t total;               /* bytes consumed */
    size_t len, cap;            /* of text */
    int tokcap;
    char comment;               /* '\0': no comments */
    unsigned char back[3];      /* bytes read ahead (BOM test, CR LF), in order */
    int nback, started, failed;
} rad_lines;

/* Open path ("-": standard input) for reading lines.  `comment` is the
 * character that starts a comment ('\0' for none). */
rad_status radi_lines_open(rad_lines *r, const char *path, char comment, rad_error *err);
/* Read lines from text[0..len) instead; `name` is used in messages. */
void radi_lines_mem(rad_lines *r, const char *text, size_t len, const char *name,
                   char comment, rad_error *err);
/* The next line, tokenized: 1; end of input: 0; an error (r->status, and
 * err filled): -1, and -1 again on every later call. */
int radi_lines_next(rad_lines *r);
/* Fail at the current line: "NAME:LINE: what" (RAD_ERR_PARSE). */
rad_status radi_lines_fail(const rad_lines *r, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
/* Tokens from `from` on must be printable ASCII; otherwise fail naming the
 * first offending byte, its column and (for U+00A0) what it probably is. */
rad_status radi_lines_ascii(const rad_lines *r, int from);
/* How many more bytes the input can hold at most: what is left of a file
 * of known size or of the text in memory, else what the file limit leaves. */
size_t radi_lines_left(const rad_lines *r);
/* Close the file (unless standard input) and free the buffers. */
void radi_lines_close(rad_lines *r);

#endif /* RAD_READFILE_H */
