/* shown.c -- the buffers of what the page is shown: element and vertex
 * radiosity, grown when the mesh drawn grows (the animation's, the
 * adaptive method's leaves).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include <stdlib.h>

#include "view/viewint.h"

int view_reserve(view_session *s, size_t elements, size_t vertices)
{
    if (elements > s->cap_elements) {
        double *e = realloc(s->element_b, sizeof *e * 3 * elements);
        if (!e)
            return -1;
        s->element_b = e;
        s->cap_elements = elements;
    }
    if (vertices > s->cap_vertices) {
        double *v = realloc(s->vertex_b, sizeof *v * 3 * vertices);
        if (!v)
            return -1;
        s->vertex_b = v;
        s->cap_vertices = vertices;
    }
    return 0;
}
