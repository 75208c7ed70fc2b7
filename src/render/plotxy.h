/* plotxy.h -- line plots of several series (sweep, convergence curves).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_PLOTXY_H
#define RAD_PLOTXY_H

#include <stdio.h>

#include "radiosity/base.h"

typedef struct rad_series {
    const char *label;
    const double *x, *y;
    int n;
} rad_series;

typedef struct rad_plot_spec {
    const char *title, *xlabel, *ylabel;
    int logx, logy;
    int width, height;          /* 0: 900 x 520 */
} rad_plot_spec;

/* Draw the series and write the plot to out as a PNG. */
rad_status radi_plot_xy(const rad_series *s, int ns, const rad_plot_spec *spec, FILE *out,
                       rad_error *err);

#endif /* RAD_PLOTXY_H */
