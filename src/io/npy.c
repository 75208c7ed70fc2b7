/* npy.c -- matrices in NumPy's .npy format, version 1.0.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The format (NumPy Enhancement Proposal 1, "A simple file format for
 * NumPy arrays", and numpy/lib/format.py, which reads and writes it):
 *
 *   "\x93NUMPY"          6 bytes, the magic string
 *   1, 0                 2 bytes, format version 1.0
 *   HEADER_LEN           2 bytes, unsigned little-endian
 *   header               HEADER_LEN bytes of ASCII: a Python dict literal
 *                        {'descr': '<f8', 'fortran_order': True,
 *                        'shape': (R, C), } padded with spaces and ended by
 *                        '\n' so that the data starts at a multiple of 64
 *                        bytes (format.py's ARRAY_ALIGN)
 *   data                 R * C float64, little-endian ('<f8')
 *
 * The library's matrices are column-major (LAPACK), which is NumPy's
 * fortran_order: the data is the array's memory as it is, written at disk
 * speed, and numpy.load(path)[i, j] is entry (i, j): for the form-factor
 * matrix F[i, j] = F_ij, from element i to element j.  On a big-endian
 * host the doubles are byte-swapped on the way out.
 */
#include <config.h>

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/export.h"
#include "radiosity/export.h"

enum { NPY_ALIGN = 64, NPY_PREAMBLE = 10, NPY_HEADER_MAX = 256 };

/* The header dict for a rows x cols column-major float64 matrix, padded:
 * fills h (NPY_HEADER_MAX bytes) and returns HEADER_LEN. */
static size_t npy_header(char *h, size_t rows, size_t cols)
{
    int len = snprintf(h, NPY_HEADER_MAX,
                       "{'descr': '<f8', 'fortran_order': True, 'shape': (%zu, %zu), }", rows,
                       cols);
    size_t total = NPY_PREAMBLE + (size_t)len + 1;      /* + the final '\n' */
    total = (total + NPY_ALIGN - 1) / NPY_ALIGN * NPY_ALIGN;
    const size_t hlen = total - NPY_PREAMBLE;
    memset(h + len, ' ', hlen - 1 - (size_t)len);
    h[hlen - 1] = '\n';
    return hlen;
}

/* n doubles as little-endian float64. */
static int put_le_doubles(FILE *out, const double *x, size_t n)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    unsigned char buf[8 * 512];
    while (n > 0) {
        const size_t k = n < 512 ? n : 512;
        for (size_t i = 0; i < k; i++) {
            uint64_t u;
            memcpy(&u, x + i, 8);
            for (int b = 0; b < 8; b++)
                buf[8 * i + b] = (unsigned char)(u >> (8 * b));
        }
        if (fwrite(buf, 8, k, out) != k)
            return -1;
        x += k;
        n -= k;
    }
    return 0;
#else
    return n == 0 || fwrite(x, sizeof *x, n, out) == n ? 0 : -1;
#endif
}

rad_status rad_export_npy(FILE *out, const double *A, size_t rows, size_t cols)
{
    char h[NPY_HEADER_MAX];
    const size_t hlen = npy_header(h, rows, cols);
    const unsigned char pre[NPY_PREAMBLE] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0,
                                             (unsigned char)(hlen & 0xff),
                                             (unsigned char)(hlen >> 8)};
    if (fwrite(pre, 1, sizeof pre, out) != sizeof pre || fwrite(h, 1, hlen, out) != hlen)
        return RAD_ERR_IO;
    if (put_le_doubles(out, A, rows * cols))
        return RAD_ERR_IO;
    return ferror(out) ? RAD_ERR_IO : RAD_OK;
}

rad_status rad_export_matrix_npy(FILE *out, const double *F, int n)
{
    const size_t m = n > 0 ? (size_t)n : 0;
    return rad_export_npy(out, F, m, m);
}

rad_status rad_export_elements_npy(FILE *out, const rad_mesh *mesh, const double *B)
{
    const size_t n = mesh->nelements > 0 ? (size_t)mesh->nelements : 0;
    return rad_export_npy(out, B, n, RAD_BANDS);
}

int rad_export_is_npy(const char *path)
{
    const size_t len = path ? strlen(path) : 0;
    return len > 4 && strcmp(path + len - 4, ".npy") == 0;
}
