/* readfile.c -- read a whole input file (or standard input) into memory.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The parsers (scene.c, plyread.c) work on text in memory, so that every
 * error can name its line and the fuzz harnesses can feed them directly.
 */
#include <config.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "readfile.h"
#include "status.h"

rad_status rad_read_file(const char *path, char **text, size_t *len, rad_error *err)
{
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    size_t cap = 0;
    *text = NULL;
    *len = 0;
    if (!f)
        return rad_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno));
    for (;;) {
        if (*len == cap) {
            cap = cap ? 2 * cap : 65536;
            char *g = realloc(*text, cap);
            if (!g) {
                free(*text);
                *text = NULL;
                if (f != stdin)
                    fclose(f);
                return rad_fail(err, RAD_ERR_NOMEM, "%s: out of memory", path);
            }
            *text = g;
        }
        size_t got = fread(*text + *len, 1, cap - *len, f);
        *len += got;
        if (got == 0)
            break;
    }
    int bad = ferror(f);
    int saved = errno;
    if (f != stdin)
        fclose(f);
    if (bad) {
        free(*text);
        *text = NULL;
        return rad_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(saved));
    }
    return RAD_OK;
}
