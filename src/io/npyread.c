/* npyread.c -- a square matrix from NumPy's .npy format (ffread.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The format is npy.c's (NumPy Enhancement Proposal 1 and
 * numpy/lib/format.py): the magic "\x93NUMPY", a version (1.0 with a
 * 2-byte header length; 2.0 and 3.0 with a 4-byte one; all little-endian),
 * the header, a Python dict literal with the keys 'descr', 'fortran_order'
 * and 'shape', then the data.  Read here: descr '<f8' (float64
 * little-endian, what numpy.save writes on every common machine) or
 * '<f4' (float32, what GPU solvers usually write; each value is then
 * widened exactly, and the caller says the precision), both orders,
 * shape (N, N) with N the scene's element count.  Anything else is
 * refused with what the file holds (another dtype, a big-endian '>f8', a
 * 1-D or 3-D array, a non-square one), so the user knows which numpy call
 * to fix (`F.astype('<f8')`, ...).
 *
 * The dict is parsed by looking for each key, not by a Python parser: the
 * values this reader accepts have one spelling each.  The data must be
 * exactly N * N * 8 (or 4) bytes; the file is read in one pass with fread, its
 * length checked before the allocation is trusted (the caller allocated
 * n * n for the scene's n, so a lying shape cannot make us allocate).
 */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/ffread.h"
#include "util/util.h"

enum { NPY_HEADER_LIMIT = 1 << 16 };

/* The value text after 'key': in the dict h, or NULL. */
static const char *dict_value(const char *h, const char *key)
{
    const char *p = strstr(h, key);
    if (!p)
        return NULL;
    p += strlen(key);
    while (*p == ' ' || *p == ':')
        p++;
    return p;
}

/* The tuple "(D1, D2, ...)" at s: how many dimensions (up to 3 stored in
 * dim), or -1 when it is not a tuple of whole numbers. */
static int shape(const char *s, long long dim[3])
{
    int nd = 0;
    char *end;
    if (*s++ != '(')
        return -1;
    for (;;) {
        s += strspn(s, " ");
        if (*s == ')')
            return nd;
        errno = 0;
        const long long v = strtoll(s, &end, 10);
        if (end == s || errno || v < 0)
            return -1;
        if (nd < 3)
            dim[nd] = v;
        nd++;
        s = end + strspn(end, " ");
        if (*s == ',')
            s++;
        else if (*s != ')')
            return -1;
    }
}

/* Check the dict h: descr '<f8' or '<f4', an order, shape (n, n).
 * *fortran receives the order, *bits 64 or 32. */
static rad_status check_dict(const char *path, const char *h, int n, int *fortran, int *bits,
                             rad_error *err)
{
    const char *d = dict_value(h, "'descr'"), *o = dict_value(h, "'fortran_order'");
    const char *s = dict_value(h, "'shape'");
    if (!d || !o || !s)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy header lacks descr, fortran_order or "
                                            "shape", path);
    *bits = strncmp(d, "'<f8'", 5) == 0 ? 64 : strncmp(d, "'<f4'", 5) == 0 ? 32 : 0;
    if (!*bits) {
        int k = 0;
        while (d[k] && d[k] != ',' && k < 20)
            k++;
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy dtype %.*s; form factors must be "
                        "float64 or float32, little-endian ('<f8', '<f4')", path, k, d);
    }
    if (strncmp(o, "True", 4) != 0 && strncmp(o, "False", 5) != 0)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy fortran_order is neither True nor "
                                            "False", path);
    *fortran = o[0] == 'T';
    long long dim[3] = {0, 0, 0};
    const int nd = shape(s, dim);
    if (nd != 2)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy shape %.*s: a form-factor matrix is "
                        "2-D, (N, N)", path, (int)strcspn(s, ")") + 1, s);
    const long long r = dim[0], c = dim[1];
    if (r != c)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy shape (%lld, %lld) is not square",
                        path, r, c);
    if (r != n)
        return radi_fail(err, RAD_ERR_PARSE, "%s: a %lld x %lld matrix; the scene has %d "
                        "elements", path, r, c, n);
    return RAD_OK;
}

/* Little-endian unsigned of k bytes. */
static uint32_t le(const unsigned char *b, int k)
{
    uint32_t v = 0;
    for (int i = k - 1; i >= 0; i--)
        v = v << 8 | b[i];
    return v;
}

/* float64 little-endian to host, in place. */
static void from_le(double *x, size_t m)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    for (size_t i = 0; i < m; i++) {
        unsigned char b[8], t;
        memcpy(b, x + i, 8);
        for (int k = 0; k < 4; k++)
            t = b[k], b[k] = b[7 - k], b[7 - k] = t;
        memcpy(x + i, b, 8);
    }
#else
    (void)x;
    (void)m;
#endif
}

/* float32 little-endian, read into the upper half of F's bytes, widened
 * in place to the m doubles of F (exactly: every float is a double).
 * Value k is read before F[k] is written, and F[k]'s bytes cover only
 * floats already read (those before 2k - m + 2 <= k + 1). */
static void widen(double *F, size_t m)
{
    const unsigned char *src = (const unsigned char *)F + 4 * m;
    for (size_t k = 0; k < m; k++) {
        unsigned char b[4];
        memcpy(b, src + 4 * k, 4);
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
        unsigned char t = b[0];
        b[0] = b[3], b[3] = t, t = b[1], b[1] = b[2], b[2] = t;
#endif
        float v;
        memcpy(&v, b, 4);
        F[k] = v;
    }
}

/* Row-major (C order) to column-major, in place: the transpose. */
static void transpose(double *F, size_t n)
{
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            const double t = F[i + j * n];
            F[i + j * n] = F[j + i * n];
            F[j + i * n] = t;
        }
}

/* Preamble and header dict of the open file: the dict in *h (malloc'd). */
static rad_status read_header(FILE *f, const char *path, char **h, rad_error *err)
{
    unsigned char pre[12];
    if (fread(pre, 1, 8, f) != 8)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy file ends in its preamble", path);
    if (pre[6] < 1 || pre[6] > 3)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy version %d.%d; this reader knows "
                        "1.0, 2.0 and 3.0", path, pre[6], pre[7]);
    const int lenbytes = pre[6] == 1 ? 2 : 4;
    if (fread(pre + 8, 1, (size_t)lenbytes, f) != (size_t)lenbytes)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy file ends in its preamble", path);
    const uint32_t hlen = le(pre + 8, lenbytes);
    if (hlen == 0 || hlen > NPY_HEADER_LIMIT)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy header of %u bytes", path,
                        (unsigned)hlen);
    *h = malloc(hlen + 1);
    if (!*h)
        return radi_fail(err, RAD_ERR_NOMEM, "%s: out of memory", path);
    if (fread(*h, 1, hlen, f) != hlen)
        return radi_fail(err, RAD_ERR_PARSE, "%s: .npy file ends in its header", path);
    (*h)[hlen] = '\0';
    return RAD_OK;
}

rad_status radi_npy_read_square(const char *path, int n, double *F, int *bits, rad_error *err)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno));
    char *h = NULL;
    int fortran = 1;
    *bits = 64;
    rad_status st = read_header(f, path, &h, err);
    if (st == RAD_OK)
        st = check_dict(path, h, n, &fortran, bits, err);
    const size_t nn = (size_t)n * (size_t)n;
    const size_t size = *bits == 32 ? 4 : 8;
    void *to = *bits == 32 ? (void *)((unsigned char *)F + 4 * nn) : (void *)F;
    const char *type = *bits == 32 ? "float32" : "float64";
    if (st == RAD_OK && fread(to, size, nn, f) != nn)
        st = radi_fail(err, RAD_ERR_PARSE, "%s: .npy data shorter than %d x %d %s", path, n, n,
                       type);
    if (st == RAD_OK && fgetc(f) != EOF)
        st = radi_fail(err, RAD_ERR_PARSE, "%s: .npy data longer than %d x %d %s", path, n, n,
                       type);
    if (st == RAD_OK) {
        if (*bits == 32)
            widen(F, nn);
        else
            from_le(F, nn);
        /* as the text readers: a NaN or infinity is no form factor */
        for (size_t k = 0; k < nn && st == RAD_OK; k++)
            if (!isfinite(F[k]))
                st = radi_fail(err, RAD_ERR_PARSE, "%s: .npy entry %zu (of row %zu, column "
                              "%zu) is %g; a form factor must be finite", path, k,
                              fortran ? k % (size_t)n : k / (size_t)n,
                              fortran ? k / (size_t)n : k % (size_t)n, F[k]);
    }
    if (st == RAD_OK && !fortran)
        transpose(F, (size_t)n);
    free(h);
    fclose(f);
    return st;
}
