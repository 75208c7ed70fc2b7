/* atomicfile.h -- output files that appear whole or not at all.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * radi_afile_open prepares an output: a regular file (or an absent path) is
 * written to a temporary file beside it, which radi_afile_commit flushes,
 * syncs and renames over the target and radi_afile_abort removes; a device,
 * FIFO or held descriptor ("-", /dev/stdout, /dev/fd/N) is written directly;
 * a symbolic link is followed and its target replaced, the link kept.
 * atomicfile.c spells out every case.  A run that fails or is killed never
 * leaves a truncated output, and never replaces what is not a regular file.
 */
#ifndef RAD_ATOMICFILE_H
#define RAD_ATOMICFILE_H

#include <stdio.h>

#include "radiosity/base.h"

typedef struct rad_afile {
    FILE *fp;
    char *user_path; /* as given, for messages */
    char *path;      /* the target, links followed; NULL when written directly */
    char *tmp;       /* temporary name, NULL when written directly */
    int direct;      /* written in place (device, FIFO, held descriptor) */
} rad_afile;

rad_status radi_afile_open(rad_afile *f, const char *path, rad_error *err);
rad_status radi_afile_commit(rad_afile *f, rad_error *err);
/* Flush, sync and close the temporary without renaming it: a later
 * radi_afile_commit renames it, radi_afile_abort removes it.  A direct
 * output is finished here.  (For many outputs committed together, without
 * holding a descriptor each.) */
rad_status radi_afile_close(rad_afile *f, rad_error *err);
void radi_afile_abort(rad_afile *f);

/* Could path be written?  Checks, without creating anything, what can be
 * known before a long computation: the directory of a file to be replaced
 * exists and takes new files; a device or FIFO is writable; the path is not
 * a directory or a broken link chain. */
rad_status radi_afile_check(const char *path, rad_error *err);

/* Would path be written in place: a held descriptor ("-", /dev/fd/N, ...),
 * or (links followed) a device, FIFO or socket?  A pattern that makes one
 * file per frame must name files, not these. */
int radi_afile_is_direct(const char *path);

#endif /* RAD_ATOMICFILE_H */
