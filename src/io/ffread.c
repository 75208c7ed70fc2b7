/* ffread.c -- another solver's form factors: which format, and the text
 * ones (ffread.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The first bytes of the file choose the reader (ffread.h lists the
 * signatures); a file that matches none is refused at its first line, so
 * an image or a scene file given by mistake is named as such rather than
 * half parsed.  The text formats go through the one line reader
 * (readfile.h), which bounds lines and files and reports "FILE:LINE:".
 *
 * Matrix Market (Boisvert, Pozo & Remington, "The Matrix Market Exchange
 * Formats: Initial Design", NISTIR 5935, 1996): a banner line
 * "%%MatrixMarket matrix FORMAT FIELD SYMMETRY", comment lines starting
 * with '%', a size line, then the entries.  `array` lists all rows x cols
 * values column by column (column-major, our own layout); `coordinate`
 * gives "rows cols nnz" and nnz lines "i j value", 1-based, absent entries
 * 0.  Only `real general` (and `integer`/`double`, which read alike) is a
 * form-factor matrix: F is not symmetric (A_i F_ij = A_j F_ji).
 *
 * The program's table (`radiosity formfactor`) lists every ordered pair
 * of distinct elements: one that misses some is another mesh's, and is
 * refused with the counts (it has no size line to say so).
 *
 * Sparse entries (coordinate, TSV) may not repeat: some tools sum
 * repeated entries and some keep the last, so a repeat is an error rather
 * than a guess.  A map of one byte per entry finds them.
 */
#include <config.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "io/ffread.h"
#include "util/util.h"

enum { PEEK = 128 };

/* The next line with tokens: 1; end: 0; error: -1. */
static int next_tokens(rad_lines *r)
{
    int k;
    while ((k = radi_lines_next(r)) == 1 && r->ntok == 0)
        ;
    return k;
}

/* Entry (i, j) = v, 0-based, refusing repeats (seen: n * n bytes). */
static rad_status put(const rad_lines *r, double *F, unsigned char *seen, size_t n, long i,
                      long j, double v)
{
    const size_t k = (size_t)i + (size_t)j * n;
    if (seen[k])
        return radi_lines_fail(r, "entry (%ld, %ld) given twice", i, j);
    seen[k] = 1;
    F[k] = v;
    return RAD_OK;
}

/* "ROWS COLS" (and NNZ for coordinate) must say n x n. */
static rad_status size_line(const rad_lines *r, int n, int coordinate, long *nnz)
{
    long rows, cols;
    rad_status st;
    if (r->ntok != 2 + coordinate)
        return radi_lines_fail(r, "the size line must hold %s, not %d numbers",
                              coordinate ? "ROWS COLS ENTRIES" : "ROWS COLS", r->ntok);
    if ((st = radi_tok_long(r, r->tok[0], "rows", 0, 1L << 40, &rows)) ||
        (st = radi_tok_long(r, r->tok[1], "columns", 0, 1L << 40, &cols)))
        return st;
    if (rows != n || cols != n)
        return radi_lines_fail(r, "a %ld x %ld matrix; the scene has %d elements", rows, cols,
                              n);
    if (coordinate)
        return radi_tok_long(r, r->tok[2], "entries", 0, (long)n * n, nnz);
    return RAD_OK;
}

/* The entries of an array: n * n values, column by column. */
static rad_status mm_array(rad_lines *r, size_t n, double *F)
{
    size_t k = 0, nn = n * n;
    int more = 1;
    while (k < nn && (more = next_tokens(r)) == 1)
        for (int t = 0; t < r->ntok; t++, k++) {
            if (k == nn)
                return radi_lines_fail(r, "more than %zu values", nn);
            rad_status st = radi_tok_number(r, t, "a form factor", &F[k]);
            if (st)
                return st;
        }
    if (more < 0)
        return r->status;
    if (k < nn)
        return radi_lines_fail(r, "the file ends after %zu of %zu values", k, nn);
    if ((more = next_tokens(r)) == 1)
        return radi_lines_fail(r, "more than %zu values", nn);
    return more < 0 ? r->status : RAD_OK;
}

/* The entries of a coordinate matrix: nnz lines "I J VALUE", 1-based. */
static rad_status mm_coordinate(rad_lines *r, int n, long nnz, double *F)
{
    unsigned char *seen = calloc((size_t)n * (size_t)n + 1, 1);
    rad_status st = RAD_OK;
    long k = 0, i, j;
    double v;
    int more = 0;
    if (!seen)
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s: out of memory", r->name);
    while (st == RAD_OK && (more = next_tokens(r)) == 1) {
        if (++k > nnz)
            st = radi_lines_fail(r, "more entries than the %ld the size line gives", nnz);
        else if (r->ntok != 3)
            st = radi_lines_fail(r, "an entry is 'I J VALUE', not %d fields", r->ntok);
        else if (!(st = radi_tok_long(r, r->tok[0], "row", 1, n, &i)) &&
                 !(st = radi_tok_long(r, r->tok[1], "column", 1, n, &j)) &&
                 !(st = radi_tok_number(r, 2, "a form factor", &v)))
            st = put(r, F, seen, (size_t)n, i - 1, j - 1, v);
    }
    free(seen);
    if (st == RAD_OK && more < 0)
        st = r->status;
    if (st == RAD_OK && k < nnz)
        st = radi_lines_fail(r, "the file ends after %ld of %ld entries", k, nnz);
    return st;
}

/* Matrix Market: the banner (line 1), then the size line and entries. */
static rad_status read_mm(rad_lines *r, const char *banner, int n, double *F,
                           const char **format)
{
    long nnz = 0;
    rad_status st;
    if (radi_lines_next(r) != 1)
        return r->status != RAD_OK ? r->status : radi_lines_fail(r, "empty file");
    /* the banner, "%%MatrixMarket matrix FORMAT FIELD SYMMETRY", from the
     * first bytes (for the line reader it is a comment) */
    char a[32] = "", b[32] = "", c[32] = "", d[32] = "";
    if (sscanf(banner, "%%%%MatrixMarket %31s %31s %31s %31s", a, b, c, d) != 4 ||
        strcasecmp(a, "matrix") != 0)
        return radi_lines_fail(r, "a Matrix Market banner is '%%%%MatrixMarket matrix "
                                 "FORMAT FIELD SYMMETRY'");
    const int coordinate = strcasecmp(b, "coordinate") == 0;
    if (!coordinate && strcasecmp(b, "array") != 0)
        return radi_lines_fail(r, "Matrix Market format '%s': only array and coordinate", b);
    if (strcasecmp(c, "real") != 0 && strcasecmp(c, "double") != 0 &&
        strcasecmp(c, "integer") != 0)
        return radi_lines_fail(r, "Matrix Market field '%s': form factors are real", c);
    if (strcasecmp(d, "general") != 0)
        return radi_lines_fail(r, "Matrix Market symmetry '%s': form factors need general "
                                 "(F_ij differs from F_ji unless the areas are equal)", d);
    const int more = next_tokens(r);
    if (more != 1)
        return more < 0 ? r->status : radi_lines_fail(r, "no size line");
    if ((st = size_line(r, n, coordinate, &nnz)))
        return st;
    *format = coordinate ? "Matrix Market coordinate" : "Matrix Market array";
    if (coordinate) {
        memset(F, 0, sizeof *F * (size_t)n * (size_t)n);
        return mm_coordinate(r, n, nnz, F);
    }
    return mm_array(r, (size_t)n, F);
}

/* The table lists every ordered pair of distinct elements (the diagonal
 * may be left out: it is 0): a table of another size misses some. */
static rad_status complete(const rad_lines *r, const unsigned char *seen, size_t n)
{
    size_t given = 0, top = 0;
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < n; i++)
            if (seen[i + j * n]) {
                given += i != j;
                top = i > top ? i : top;
                top = j > top ? j : top;
            }
    if (given == n * (n - 1))
        return RAD_OK;
    return radi_fail(r->err, RAD_ERR_PARSE, "%s: the table gives %zu of the %zu pairs of "
                    "distinct elements; the scene has %zu elements (the table's largest index "
                    "is %zu)", r->name, given, n * (n - 1), n, top);
}

/* The program's form-factor table: header "i j F ...", rows "I J F ...". */
static rad_status read_tsv(rad_lines *r, int n, double *F)
{
    unsigned char *seen = calloc((size_t)n * (size_t)n + 1, 1);
    rad_status st = RAD_OK;
    long i, j;
    double v;
    int more = next_tokens(r); /* the header, seen by the caller */
    if (!seen)
        return radi_fail(r->err, RAD_ERR_NOMEM, "%s: out of memory", r->name);
    memset(F, 0, sizeof *F * (size_t)n * (size_t)n);
    while (st == RAD_OK && more == 1 && (more = next_tokens(r)) == 1) {
        if (r->ntok < 3)
            st = radi_lines_fail(r, "a row is 'i j F ...', not %d fields", r->ntok);
        else if (!(st = radi_tok_long(r, r->tok[0], "i", 0, n - 1L, &i)) &&
                 !(st = radi_tok_long(r, r->tok[1], "j", 0, n - 1L, &j)) &&
                 !(st = radi_tok_number(r, 2, "F", &v)))
            st = put(r, F, seen, (size_t)n, i, j, v);
    }
    if (st == RAD_OK && more < 0)
        st = r->status;
    if (st == RAD_OK)
        st = complete(r, seen, (size_t)n);
    free(seen);
    return st;
}

/* The first bytes of path (up to PEEK, NUL-terminated): their count, or
 * -1 (err filled). */
static long peek(const char *path, char *buf, rad_error *err)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno)), -1;
    errno = 0;
    const size_t k = fread(buf, 1, PEEK, f);
    const int bad = ferror(f), e = errno;
    fclose(f);
    if (bad)
        return radi_fail(err, RAD_ERR_IO, "%s: %s", path, e ? strerror(e) : "read error"), -1;
    buf[k] = '\0';
    return (long)k;
}

/* View3D's header "View3D VERSION FORMAT ENCL DIDEMIT NSRF" (a 30-byte
 * line): FORMAT, or -1 when the bytes are not one. */
static int vf_format(const char *buf, long len)
{
    char prog[16], ver[16];
    int format, encl, emit, nsrf;
    if (len < 32 || strncmp(buf, "View", 4) != 0)
        return -1;
    if (sscanf(buf, "%15s %15s %d %d %d %d", prog, ver, &format, &encl, &emit, &nsrf) != 6)
        return -1;
    return format;
}

/* A first line whose first three fields are i, j, F. */
static int tsv_header(const char *buf)
{
    char a[8], b[8], c[8];
    return sscanf(buf, "%7s %7s %7s", a, b, c) == 3 && strcmp(a, "i") == 0 &&
           strcmp(b, "j") == 0 && strcmp(c, "F") == 0;
}

rad_status radi_ff_read(const char *path, int n, double *F, const char **format,
                       rad_error *err)
{
    char buf[PEEK + 1];
    const long len = peek(path, buf, err);
    if (len < 0)
        return RAD_ERR_IO;
    if (len >= 6 && memcmp(buf, "\x93NUMPY", 6) == 0) {
        int bits;
        const rad_status st = radi_npy_read_square(path, n, F, &bits, err);
        /* float32 keeps 24 bits: each entry is within 2^-24 of its own
         * value, which a comparison must not take for the solver's error */
        *format = bits == 32 ? "NumPy .npy float32 (each entry rounded to 6e-8 of itself)"
                             : "NumPy .npy";
        return st;
    }
    const int vf = vf_format(buf, len);
    if (vf == 1) {
        *format = "View3D binary";
        return radi_vf_read_binary(path, n, F, err);
    }
    if (vf == 0) {
        *format = "View3D text";
        return radi_vf_read_text(path, n, F, err);
    }
    if (vf > 1)
        return radi_fail(err, RAD_ERR_PARSE, "%s:1: View3D format %d; only its square "
                        "formats 0 (text) and 1 (binary) are read", path, vf);
    const int mm = strncasecmp(buf, "%%MatrixMarket", 14) == 0;
    if (!mm && !tsv_header(buf))
        return radi_fail(err, RAD_ERR_PARSE,
                        "%s:1: not a form-factor matrix (expected Matrix Market, NumPy .npy, "
                        "a table with the header 'i j F', or View3D's view-factor file)",
                        path);
    rad_lines r;
    rad_status st = radi_lines_open(&r, path, mm ? '%' : '#', err);
    if (st == RAD_OK) {
        if (mm)
            st = read_mm(&r, buf, n, F, format);
        else {
            *format = "form-factor table";
            st = read_tsv(&r, n, F);
        }
    }
    radi_lines_close(&r);
    return st;
}
