/* test_export.c -- the big writers against the printf loops they replace,
 * and the B table in .npy (include/radiosity/export.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Reference: the serial fprintf loops that wrote the form-factor table
 * ("%d\t%d\t%.17g\t%.3g\n", row by row) and the Matrix Market body
 * ("%.17g\n", column-major) before the writers went parallel;
 * radiosity-files(5) makes those bytes the contract.  No tolerance: every
 * byte.
 * The matrices are big enough for several blocks per thread (the writers
 * format blocks of rows in parallel and must write them in order), and
 * hold values of every kind: zeros, tiny, huge, negative, random.
 * For .npy: NEP 1 / numpy/lib/format.py, read back by hand.
 */
#include <config.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/export.h"
#include "radiosity/export.h"
#include "../tap.h"

/* xorshift64* (Vigna 2016), fixed seed */
static uint64_t next(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * UINT64_C(2685821657736338717);
}

static double value(uint64_t *s, size_t k)
{
    const double u = (double)(next(s) >> 11) * 0x1p-53;
    switch (k % 7) {
    case 0: return 0;
    case 1: return u * 1e-300;
    case 2: return -u;
    case 3: return u * 1e300;
    case 4: return floor(u * 1000);
    default: return u * 0.2;
    }
}

/* What one writer put in a memory stream. */
typedef struct mem {
    char *buf;
    size_t len;
} mem;

static void ff_table_printf(FILE *out, const double *F, const double *E, int n)
{
    fprintf(out, "i\tj\tF\terror\n");
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            if (i != j) {
                size_t k = (size_t)i + (size_t)j * n;
                fprintf(out, "%d\t%d\t%.17g\t%.3g\n", i, j, F[k], E ? E[k] : (double)NAN);
            }
}

static void mm_printf(FILE *out, const double *F, int n)
{
    fprintf(out, "%%%%MatrixMarket matrix array real general\n%% c\n%d %d\n", n, n);
    for (size_t k = 0; k < (size_t)n * n; k++)
        fprintf(out, "%.17g\n", F[k]);
}

static int same(const mem *a, const mem *b)
{
    return a->len == b->len && memcmp(a->buf, b->buf, a->len) == 0;
}

static void check_writers(int n, int all)
{
    uint64_t seed = 20261201;
    double *F = malloc(sizeof *F * (size_t)n * n), *E = malloc(sizeof *E * (size_t)n * n);
    for (size_t k = 0; k < (size_t)n * n; k++) {
        F[k] = value(&seed, k);
        E[k] = fabs(value(&seed, k + 3)) * 1e-9;
    }
    mem want, got;
    FILE *w = open_memstream(&want.buf, &want.len), *g = open_memstream(&got.buf, &got.len);
    ff_table_printf(w, F, E, n);
    const int rc = rad_export_ff_table(g, F, E, n);
    fclose(w);
    fclose(g);
    tap_ok(rc == 0 && same(&want, &got), "n = %d: form-factor table equals the printf loop's "
           "(%zu bytes)", n, want.len);
    free(want.buf);
    free(got.buf);
    if (!all) {
        free(F);
        free(E);
        return;
    }

    w = open_memstream(&want.buf, &want.len);
    g = open_memstream(&got.buf, &got.len);
    ff_table_printf(w, F, NULL, n);
    const int rc2 = rad_export_ff_table(g, F, NULL, n);
    fclose(w);
    fclose(g);
    tap_ok(rc2 == 0 && same(&want, &got), "n = %d: without estimates (nan column) too", n);
    free(want.buf);
    free(got.buf);

    w = open_memstream(&want.buf, &want.len);
    g = open_memstream(&got.buf, &got.len);
    mm_printf(w, F, n);
    const int rc3 = rad_export_matrix_market(g, F, n, "c");
    fclose(w);
    fclose(g);
    tap_ok(rc3 == 0 && same(&want, &got), "n = %d: Matrix Market equals the printf loop's "
           "(%zu bytes)", n, want.len);
    free(want.buf);
    free(got.buf);
    free(F);
    free(E);
}

/* rad_export_elements_npy: shape (n, 3), [e, b] = B[e + b n]. */
static void check_elements_npy(void)
{
    static const char scene_text[] =
        "material w reflect 0.5\n"
        "quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 3x2\n"
        "quad w 0 0 1  0 1 1  1 1 1  1 0 1\n";
    rad_scene scene;
    rad_mesh mesh;
    rad_error err;
    if (rad_scene_parse(&scene, scene_text, sizeof scene_text - 1, "t", &err) != RAD_OK ||
        rad_mesh_build(&mesh, &scene, &err) != RAD_OK) {
        tap_ok(0, "scene for the .npy test: %s", err.message);
        return;
    }
    const int n = mesh.nelements;
    double B[7 * RAD_BANDS];
    for (int k = 0; k < n * RAD_BANDS; k++)
        B[k] = 1.0 / (k + 3);
    mem got;
    FILE *g = open_memstream(&got.buf, &got.len);
    const int rc = rad_export_elements_npy(g, &mesh, B);
    fclose(g);
    const unsigned char *u = (const unsigned char *)got.buf;
    const size_t hlen = got.len >= 10 ? (size_t)u[8] | (size_t)u[9] << 8 : 0;
    tap_ok(rc == 0 && n == 7 && got.len >= 10 && memcmp(got.buf, "\x93NUMPY\x01\x00", 8) == 0,
           "elements .npy: magic and version 1.0");
    tap_ok((10 + hlen) % 64 == 0 && got.len == 10 + hlen + sizeof B,
           "elements .npy: data 64-byte aligned, 7 x 3 doubles");
    char want_hdr[] = "{'descr': '<f8', 'fortran_order': True, 'shape': (7, 3), }";
    tap_ok(hlen > sizeof want_hdr && memcmp(got.buf + 10, want_hdr, sizeof want_hdr - 1) == 0 &&
               got.buf[10 + hlen - 1] == '\n',
           "elements .npy: header says '<f8', fortran_order True, shape (7, 3)");
    int equal = got.len == 10 + hlen + sizeof B;
    for (int e = 0; equal && e < n; e++)
        for (int b = 0; b < RAD_BANDS; b++) {
            /* fortran order: [e, b] at offset e + b n, little-endian */
            uint64_t bits = 0, want;
            for (int k = 0; k < 8; k++)
                bits |= (uint64_t)u[10 + hlen + 8 * ((size_t)e + (size_t)b * n) + k] << (8 * k);
            memcpy(&want, &B[e + b * n], 8);
            equal &= bits == want;
        }
    tap_ok(equal, "elements .npy: [e, b] is B of element e in band b, bit for bit");
    free(got.buf);
    rad_mesh_free(&mesh);
    rad_scene_free(&scene);
}

/* A stream that cannot be written (a file opened for reading): every
 * writer says RAD_ERR_IO, the status the whole library uses. */
static void check_write_error(void)
{
    char path[] = "/tmp/test_export_XXXXXX";
    const int fd = mkstemp(path);
    FILE *r = fd >= 0 ? fdopen(fd, "r") : NULL;
    if (!r) {
        tap_ok(0, "a read-only stream for the write-error checks");
        return;
    }
    double F[4] = {0, 0.5, 0.5, 0};
    int bad = 0;
    bad += rad_export_ff_table(r, F, NULL, 2) != RAD_ERR_IO;
    clearerr(r);
    bad += rad_export_matrix_market(r, F, 2, NULL) != RAD_ERR_IO;
    clearerr(r);
    bad += rad_export_matrix_npy(r, F, 2) != RAD_ERR_IO;
    fclose(r);
    remove(path);
    tap_ok(bad == 0, "a stream that cannot be written: the table, Matrix Market and .npy "
                     "writers return RAD_ERR_IO (%d did not)", bad);
}

int main(void)
{
    /* one block; 34 blocks of up to 18 rows (table) and 14 of up to 43 columns
     * (Matrix Market); 1370 rows of 131 kB, over the 1 MB / 8 of a block:
     * blocks of the least 8 rows */
    check_writers(3, 1);
    check_writers(600, 1);
    check_writers(1370, 0);
    check_elements_npy();
    check_write_error();
    return tap_done();
}
