/* plot.h -- scanline plots and PNG output through cairo.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The one place that encodes PNG: render.c hands its picture here.  Every
 * writer prints to a stream the caller opened (the program makes it
 * atomic); nothing here opens a file.
 */
#ifndef RAD_PLOT_H
#define RAD_PLOT_H

#include <stdio.h>

#include "radiosity/base.h"

/* cairo's surface, declared here so that users of this header (the
 * program, built without cairo's include path) need not include cairo.h;
 * it is the struct behind cairo_surface_t. */
struct _cairo_surface;
struct _cairo;

#define RAD_PLOT_WIDTH 720      /* default plot size, pixels */
#define RAD_PLOT_HEIGHT 405

/* Plot a scanline profile: n samples, sample x band b at rgb[3*x + b]
 * (the layout of rad_image_row), as three curves R, G, B in red, green and
 * blue over x = 0 .. n-1 ("pixel column") against "radiosity", with ticks,
 * a legend and the title (may be NULL).  Written as a PNG of width x height
 * pixels to out.  Deterministic: same input, same bytes. */
rad_status radi_plot_scanline(const double *rgb, int n, const char *title, int width,
                             int height, FILE *out, rad_error *err);

/* Write a cairo image surface as a PNG to out. */
rad_status radi_png_write_surface(struct _cairo_surface *surface, FILE *out, rad_error *err);

/* Finish a drawing: check cairo's status, write the surface as a PNG
 * (radi_png_write_surface), and destroy the context and the surface. */
rad_status radi_plot_finish(struct _cairo *cr, struct _cairo_surface *surface, FILE *out,
                           rad_error *err);

#endif /* RAD_PLOT_H */
