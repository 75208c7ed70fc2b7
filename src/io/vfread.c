/* vfread.c -- NIST View3D's view-factor files (ffread.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * View3D 3.x (G. N. Walton, NISTIR 6925, 2002) writes its results with
 * SaveVF (savevf.c of its sources, public domain) in the format its
 * input's control line asks for.  Both square formats start with a header
 * line of 30 characters padded with spaces:
 *
 *   "View3D VERSION FORMAT ENCL DIDEMIT NSRF"
 *
 * FORMAT 0, text: the header ended by '\n'; one line of the NSRF areas
 *   (%g); NSRF lines, row n holding F_nm for m = 1..NSRF (%.6f); one line
 *   of the NSRF emissivities (%.3f).
 * FORMAT 1, binary: the header ended by "\r\n" (32 bytes); NSRF float32
 *   areas; NSRF x NSRF float32 factors, row by row; NSRF float32
 *   emissivities.  The floats are the writer's own byte order: View3D
 *   ran on x86 (little-endian), and that is what is read here.
 *
 * Row n is from surface n, as ours (doc/design.md, "Conventions"), and
 * surfaces are numbered in input order, which is our element order for a
 * .vs3 scene whose surfaces are not meshed further.  Text rows carry six
 * decimals: an entry's absolute error is up to 5e-7, which the report's
 * relative errors show as they are.  Other formats (View3D's sparse
 * format 2 of some forks, the AF listing) are refused by the header.
 */
#include <config.h>

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/ffread.h"
#include "util/util.h"

enum { VF_HEADER = 32 };

/* The surface count of the header must be the scene's element count. */
static rad_status check_nsrf(const char *path, long nsrf, int n, rad_error *err)
{
    if (nsrf != n)
        return radi_fail(err, RAD_ERR_PARSE, "%s:1: %ld surfaces; the scene has %d elements",
                        path, nsrf, n);
    return RAD_OK;
}

/* The header "View3D VERSION FORMAT ENCL DIDEMIT NSRF" of a binary file. */
static rad_status check_count(const char *path, const char *header, int n, rad_error *err)
{
    char prog[16], ver[16];
    int format, encl, emit, nsrf;
    if (sscanf(header, "%15s %15s %d %d %d %d", prog, ver, &format, &encl, &emit, &nsrf) != 6)
        return radi_fail(err, RAD_ERR_PARSE, "%s:1: not a View3D header", path);
    return check_nsrf(path, nsrf, n, err);
}

/* A stream of numbers over the lines of a text file. */
typedef struct tokens {
    rad_lines r;
    int t;                      /* next token of the current line */
} tokens;

/* The next number (what: for messages). */
static rad_status next_number(tokens *s, const char *what, double *v)
{
    while (s->t >= s->r.ntok) {
        const int k = radi_lines_next(&s->r);
        if (k < 0)
            return s->r.status;
        if (k == 0)
            return radi_lines_fail(&s->r, "the file ends before %s", what);
        s->t = 0;
    }
    return radi_tok_number(&s->r, s->t++, what, v);
}

static rad_status extra(const rad_lines *r, int n)
{
    return radi_lines_fail(r, "more numbers than %d areas, %d x %d view factors and %d "
                             "emissivities", n, n, n, n);
}

rad_status radi_vf_read_text(const char *path, int n, double *F, rad_error *err)
{
    tokens s = {.t = 0};
    rad_status st = radi_lines_open(&s.r, path, '\0', err);
    const size_t nn = (size_t)n;
    double v;
    if (st == RAD_OK && radi_lines_next(&s.r) != 1)
        st = s.r.status ? s.r.status : radi_lines_fail(&s.r, "empty file");
    long nsrf;
    if (st == RAD_OK && s.r.ntok != 6)
        st = radi_lines_fail(&s.r, "a View3D header has 6 fields, not %d", s.r.ntok);
    if (st == RAD_OK &&
        (st = radi_tok_long(&s.r, s.r.tok[5], "the surface count", 0, 1L << 30, &nsrf)) == RAD_OK)
        st = check_nsrf(path, nsrf, n, err);
    s.t = s.r.ntok;             /* the header's fields are used up */
    for (size_t k = 0; st == RAD_OK && k < nn; k++)
        st = next_number(&s, "the areas", &v);
    /* row i is from surface i: F_ij goes to F[i + j n] */
    for (size_t i = 0; st == RAD_OK && i < nn; i++)
        for (size_t j = 0; st == RAD_OK && j < nn; j++)
            st = next_number(&s, "the view factors", &F[i + j * nn]);
    for (size_t k = 0; st == RAD_OK && k < nn; k++)
        st = next_number(&s, "the emissivities", &v);
    if (st == RAD_OK && s.t < s.r.ntok)
        st = extra(&s.r, n);
    int k;
    while (st == RAD_OK && (k = radi_lines_next(&s.r)) != 0)
        st = k < 0 ? s.r.status : s.r.ntok > 0 ? extra(&s.r, n) : RAD_OK;
    radi_lines_close(&s.r);
    return st;
}

/* A little-endian IEEE binary32 to double. */
static double f32le(const unsigned char *b)
{
    const uint32_t u = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 |
                       (uint32_t)b[3] << 24;
    float x;
    memcpy(&x, &u, sizeof x);
    return (double)x;
}

/* The rows of the binary file, after the header and the areas. */
static rad_status binary_rows(FILE *f, const char *path, size_t n, double *F, rad_error *err)
{
    unsigned char *row = malloc(4 * n + 1);
    rad_status st = RAD_OK;
    if (!row)
        return radi_fail(err, RAD_ERR_NOMEM, "%s: out of memory", path);
    if (fread(row, 4, n, f) != n) /* the areas */
        st = radi_fail(err, RAD_ERR_PARSE, "%s: the file ends in the areas", path);
    for (size_t i = 0; st == RAD_OK && i < n; i++) {
        if (fread(row, 4, n, f) != n) {
            st = radi_fail(err, RAD_ERR_PARSE, "%s: the file ends in row %zu of %zu", path,
                          i + 1, n);
            break;
        }
        for (size_t j = 0; j < n; j++)
            F[i + j * n] = f32le(row + 4 * j);
    }
    if (st == RAD_OK && fread(row, 4, n, f) != n)
        st = radi_fail(err, RAD_ERR_PARSE, "%s: the file ends in the emissivities", path);
    if (st == RAD_OK && fgetc(f) != EOF)
        st = radi_fail(err, RAD_ERR_PARSE, "%s: more bytes than %zu areas, %zu x %zu view "
                      "factors and %zu emissivities (float32)", path, n, n, n, n);
    free(row);
    return st;
}

rad_status radi_vf_read_binary(const char *path, int n, double *F, rad_error *err)
{
    FILE *f = fopen(path, "rb");
    char header[VF_HEADER + 1];
    if (!f)
        return radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno));
    rad_status st = RAD_OK;
    if (fread(header, 1, VF_HEADER, f) != VF_HEADER || header[30] != '\r' ||
        header[31] != '\n')
        st = radi_fail(err, RAD_ERR_PARSE, "%s: a View3D binary file starts with a 32-byte "
                      "header ended by CR LF", path);
    header[30] = '\0';
    if (st == RAD_OK)
        st = check_count(path, header, n, err);
    if (st == RAD_OK)
        st = binary_rows(f, path, (size_t)n, F, err);
    fclose(f);
    return st;
}
