/* atomicfile.h -- output files that appear whole or not at all.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * rad_afile_open writes to a temporary file beside the target;
 * rad_afile_commit flushes, syncs and renames it over the target;
 * rad_afile_abort removes it.  A run that fails or is killed never leaves a
 * truncated output or clobbers an existing one.  The path "-" is standard
 * output (written directly).
 */
#ifndef RAD_ATOMICFILE_H
#define RAD_ATOMICFILE_H

#include <stdio.h>

#include "radiosity.h"

typedef struct rad_afile {
    FILE *fp;
    char *path;     /* target */
    char *tmp;      /* temporary name, NULL for standard output */
} rad_afile;

rad_status rad_afile_open(rad_afile *f, const char *path, rad_error *err);
rad_status rad_afile_commit(rad_afile *f, rad_error *err);
void rad_afile_abort(rad_afile *f);

#endif /* RAD_ATOMICFILE_H */
