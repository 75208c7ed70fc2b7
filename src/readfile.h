/* readfile.h -- read a whole file into memory (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_READFILE_H
#define RAD_READFILE_H

#include <stddef.h>

#include "radiosity.h"

/* Read all of path ("-": standard input) into *text (malloc'ed, caller
 * frees), its size in *len.  On failure *text is NULL and err says why. */
rad_status rad_read_file(const char *path, char **text, size_t *len, rad_error *err);

#endif /* RAD_READFILE_H */
