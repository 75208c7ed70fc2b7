/* methods.c -- the names of the methods the viewer steps.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The race's methods (progressive.h: shooting, sorted, sorted_ambient,
 * gathering) under the names `radiosity progress` prints, jacobi, race:
 * the four of figure 7 side by side, and adaptive (adaptview.c).
 */
#include <config.h>

#include <string.h>

#include "view/view.h"
#include "solve/solve.h"

int radi_view_method(const char *name)
{
    for (int m = 0; m <= RADI_VIEW_ADAPTIVE; m++)
        if (strcmp(name, radi_view_method_name(m)) == 0)
            return m;
    return -1;
}

const char *radi_view_method_name(int method)
{
    return method == RAD_STEP_JACOBI ? "jacobi"
           : method == RADI_VIEW_RACE     ? "race"
           : method == RADI_VIEW_ADAPTIVE ? "adaptive"
                                          : radi_race_name(method);
}
