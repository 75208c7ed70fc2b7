/* methods.c -- the names of the methods the viewer steps.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The race's methods (progressive.h: shooting, sorted, sorted_ambient,
 * gathering) under the names `radiosity progress` prints, and jacobi.
 */
#include <config.h>

#include <string.h>

#include "view/view.h"
#include "solve/solve.h"

static const char *const extra_name = "jacobi";

int radi_view_method(const char *name)
{
    for (int m = 0; m < RAD_STEP_METHODS; m++)
        if (strcmp(name, radi_view_method_name(m)) == 0)
            return m;
    return -1;
}

const char *radi_view_method_name(int method)
{
    return method == RAD_STEP_JACOBI ? extra_name : radi_race_name(method);
}
