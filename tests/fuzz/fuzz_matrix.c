/* fuzz_matrix.c -- libFuzzer harness for compare's matrix readers.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The first byte chooses the element count n (1 to 8); the rest is
 * written to a file that radi_ff_read() reads as another solver's n x n
 * form-factor matrix: NumPy .npy, Matrix Market, View3D's text or binary
 * view-factor file, or the program's own form-factor table (ffread.h).
 * Contracts checked: the status is RAD_OK, RAD_ERR_IO or RAD_ERR_PARSE;
 * a failure's message starts with the file's name and a colon; a success
 * names its format and leaves F fully written (every entry set: the
 * harness fills F with a signalling pattern first and looks for it).  A
 * broken contract calls abort(), a crash to libFuzzer.  The file lives in
 * a directory made once per process.
 *
 * Build and run: tests/fuzz/run-fuzz.sh [SECONDS] (FUZZ_HARNESSES=matrix),
 * or `make fuzz`; see fuzz_scene.c for the compiler flags.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/ffread.h"
#include "radiosity/base.h"

static char path[4096];

static void make_path(void)
{
    char dir[] = "/tmp/radiosity-fuzz-matrix.XXXXXX";
    if (!mkdtemp(dir))
        abort();
    snprintf(path, sizeof path, "%s/theirs", dir);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    if (!path[0])
        make_path();
    const int n = 1 + data[0] % 8;
    FILE *f = fopen(path, "wb");
    if (!f)
        abort();
    if (size > 1 && fwrite(data + 1, 1, size - 1, f) != size - 1)
        abort();
    if (fclose(f) != 0)
        abort();
    double F[64];
    const uint64_t mark = 0x7ff4deadbeef0001ULL; /* a signalling NaN */
    for (int k = 0; k < n * n; k++)
        memcpy(&F[k], &mark, sizeof mark);
    const char *format = NULL;
    rad_error err;
    memset(&err, 0, sizeof err);
    rad_status st = radi_ff_read(path, n, F, &format, &err);
    if (st == RAD_OK) {
        if (!format)
            abort();
        for (int k = 0; k < n * n; k++)
            if (memcmp(&F[k], &mark, sizeof mark) == 0)
                abort(); /* an entry left unwritten */
    } else {
        if (st != RAD_ERR_IO && st != RAD_ERR_PARSE)
            abort();
        if (strncmp(err.message, path, strlen(path)) != 0 || err.message[strlen(path)] != ':')
            abort();
    }
    return 0;
}
