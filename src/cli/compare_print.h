/* compare_print.h -- what `radiosity compare` prints and writes.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The comparison's figures (ffcompare.h) with the geometry of the pairs
 * and the run's context, as text for a reader (standard output), JSON for
 * a program (--report) and a histogram (--plot).  Each writer prints to a
 * stream it is given (cli_output.c makes files atomic) and returns 0, or
 * -1 on a write error.
 */
#ifndef RAD_COMPARE_PRINT_H
#define RAD_COMPARE_PRINT_H

#include <stdio.h>

#include "compare/compare.h"
#include "radiosity/mesh.h"

typedef struct compare_ctx {
    const char *scene, *matrix, *format;    /* paths, and the format found */
    const char *elements;                   /* --elements TABLE, or NULL */
    const rad_mesh *mesh;
    const rad_ffcmp *cmp;
    int accuracy;                           /* of our values */
    int has_tolerance;
    double tolerance;
    int nrows;                              /* worst rows to print */
    double seconds_read, seconds_ff;
} compare_ctx;

/* 1 when the largest error is within the tolerance (or none was given). */
int compare_within(const compare_ctx *c);

int compare_print_text(FILE *out, const void *ctx);
int compare_print_json(FILE *out, const void *ctx);
int compare_plot(FILE *out, const void *ctx);

#endif /* RAD_COMPARE_PRINT_H */
