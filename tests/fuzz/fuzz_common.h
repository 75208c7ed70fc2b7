/* fuzz_common.h -- the contracts every libFuzzer harness checks.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Header-only (static functions): run-fuzz.sh compiles each harness as one
 * program with the sources it needs, nothing else.
 */
#ifndef RAD_FUZZ_COMMON_H
#define RAD_FUZZ_COMMON_H

#include <string.h>

#include "radiosity/scene.h"

/* "NAME:" then a line number >= 1, then ": " and a non-empty reason. */
static int fuzz_message_at(const char *msg, const char *name)
{
    const size_t n = strlen(name);
    if (strncmp(msg, name, n) != 0 || msg[n] != ':')
        return 0;
    const char *p = msg + n + 1;
    if (!(*p >= '1' && *p <= '9'))
        return 0;
    while (*p >= '0' && *p <= '9')
        p++;
    return p[0] == ':' && p[1] == ' ' && p[2] != '\0';
}

/* A scene left empty by a failed parse (radiosity.h's contract). */
static int fuzz_scene_empty(const rad_scene *s)
{
    return s->filename == NULL && s->materials == NULL && s->nmaterials == 0 &&
           s->surfaces == NULL && s->nsurfaces == 0 && s->objects == NULL &&
           s->nobjects == 0 && !s->camera.defined;
}

#endif /* RAD_FUZZ_COMMON_H */
