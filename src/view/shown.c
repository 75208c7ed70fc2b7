/* shown.c -- the buffers of what the page is shown: element and vertex
 * radiosity, grown when the mesh drawn grows (the animation's, the
 * adaptive method's leaves).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include <stdlib.h>

#include "view/viewint.h"

/* *buf (3 doubles an item) holds at least `want` items; 0, or -1. */
static int grow(double **buf, size_t *cap, size_t want)
{
    if (want <= *cap)
        return 0;
    double *b = realloc(*buf, sizeof *b * 3 * want);
    if (!b)
        return -1;
    *buf = b;
    *cap = want;
    return 0;
}

int view_reserve(view_session *s, size_t elements, size_t vertices)
{
    if (grow(&s->element_b, &s->cap_elements, elements))
        return -1;
    return grow(&s->vertex_b, &s->cap_vertices, vertices);
}
