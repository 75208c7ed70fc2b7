/* plot.c -- scanline plots and PNG output through cairo.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A scanline plot is the modern form of the 1984 paper's RGB intensity
 * traces (Goral et al. 1984, figure 6): the linear radiosity of the three
 * bands along one image row.  The axes start at 0; the ticks are "nice"
 * numbers 1, 2 or 5 times a power of ten (Heckbert, "Nice Numbers for Graph
 * Labels", Graphics Gems, 1990).  Drawing is cairo's, single-threaded, so
 * the same input gives the same bytes on the same system (text goes through
 * the installed fonts, so another system may differ in the labels' pixels).
 *
 * PNG files are written through rad_afile: a temporary file beside the
 * target, renamed over it once complete.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <cairo.h>

#include "render/plot.h"
#include "radiosity/base.h"
#include "util/util.h"

/* ---- PNG output ------------------------------------------------------------ */

static cairo_status_t write_to_file(void *closure, const unsigned char *data,
                                    unsigned int length)
{
    FILE *fp = closure;
    return fwrite(data, 1, length, fp) == length ? CAIRO_STATUS_SUCCESS
                                                 : CAIRO_STATUS_WRITE_ERROR;
}

rad_status radi_png_write_surface(cairo_surface_t *surface, FILE *out, rad_error *err)
{
    cairo_surface_flush(surface);
    cairo_status_t cs = cairo_surface_write_to_png_stream(surface, write_to_file, out);
    if (cs != CAIRO_STATUS_SUCCESS)
        return radi_fail(err, cs == CAIRO_STATUS_NO_MEMORY ? RAD_ERR_NOMEM : RAD_ERR_IO,
                        "PNG: %s", cairo_status_to_string(cs));
    return RAD_OK;
}

rad_status radi_plot_finish(cairo_t *cr, cairo_surface_t *s, FILE *out, rad_error *err)
{
    rad_status st;
    cairo_status_t cs = cairo_status(cr);
    if (cs != CAIRO_STATUS_SUCCESS)
        st = radi_fail(err, cs == CAIRO_STATUS_NO_MEMORY ? RAD_ERR_NOMEM : RAD_ERR_INVALID,
                      "plot: %s", cairo_status_to_string(cs));
    else
        st = radi_png_write_surface(s, out, err);
    cairo_destroy(cr);
    cairo_surface_destroy(s);
    return st;
}

/* ---- the plot ------------------------------------------------------------ */

#define MARGIN_LEFT 78.0
#define MARGIN_RIGHT 24.0
#define MARGIN_TOP 40.0
#define MARGIN_BOTTOM 56.0
#define FONT "DejaVu Sans"

/* 1, 2 or 5 times a power of ten, near range / target. */
static double nice_step(double range, int target)
{
    double raw = range / target;
    double mag = pow(10.0, floor(log10(raw)));
    double r = raw / mag;
    return (r < 1.5 ? 1 : r < 3 ? 2 : r < 7 ? 5 : 10) * mag;
}

/* The plot's frame: data ranges and where they land on the page. */
typedef struct frame {
    double x0, x1, xstep;       /* data */
    double y0, y1, ystep;
    double left, right, top, bottom; /* page */
} frame;

static double page_x(const frame *fr, double x)
{
    return fr->left + (x - fr->x0) / (fr->x1 - fr->x0) * (fr->right - fr->left);
}

static double page_y(const frame *fr, double y)
{
    return fr->bottom - (y - fr->y0) / (fr->y1 - fr->y0) * (fr->bottom - fr->top);
}

static frame make_frame(const double *rgb, int n, int width, int height)
{
    frame fr;
    double lo = 0, hi = 0;
    for (int k = 0; k < 3 * n; k++)
        if (isfinite(rgb[k])) {
            lo = fmin(lo, rgb[k]);
            hi = fmax(hi, rgb[k]);
        }
    if (!(hi > lo))
        hi = lo + 1;
    fr.ystep = nice_step(hi - lo, 5);
    fr.y0 = floor(lo / fr.ystep) * fr.ystep;
    fr.y1 = ceil(hi / fr.ystep - 1e-9) * fr.ystep;
    if (fr.y1 < hi)
        fr.y1 += fr.ystep;
    fr.x0 = 0;
    fr.x1 = n > 1 ? n - 1 : 1;
    fr.xstep = fmax(1.0, nice_step(fr.x1 - fr.x0, 8));
    fr.left = MARGIN_LEFT;
    fr.right = width - MARGIN_RIGHT;
    fr.top = MARGIN_TOP;
    fr.bottom = height - MARGIN_BOTTOM;
    return fr;
}

/* Text centred on (x, y) horizontally, with its baseline at y. */
static void text_centred(cairo_t *cr, double x, double y, const char *s)
{
    cairo_text_extents_t te;
    cairo_text_extents(cr, s, &te);
    cairo_move_to(cr, x - te.x_advance / 2, y);
    cairo_show_text(cr, s);
}

static void text_right(cairo_t *cr, double x, double y, const char *s)
{
    cairo_text_extents_t te;
    cairo_text_extents(cr, s, &te);
    cairo_move_to(cr, x - te.x_advance, y);
    cairo_show_text(cr, s);
}

static void draw_axes(cairo_t *cr, const frame *fr)
{
    char buf[64];
    cairo_set_font_size(cr, 12);
    cairo_set_line_width(cr, 1);
    /* grid and ticks; ticks at whole multiples of the step */
    for (long k = (long)ceil(fr->y0 / fr->ystep - 1e-9); k * fr->ystep <= fr->y1 + 1e-9 * fr->ystep;
         k++) {
        double py = floor(page_y(fr, k * fr->ystep)) + 0.5;
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_move_to(cr, fr->left, py);
        cairo_line_to(cr, fr->right, py);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, fr->left - 5, py);
        cairo_line_to(cr, fr->left, py);
        cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%.6g", k * fr->ystep);
        text_right(cr, fr->left - 8, py + 4, buf);
    }
    for (long k = (long)ceil(fr->x0 / fr->xstep - 1e-9); k * fr->xstep <= fr->x1 + 1e-9 * fr->xstep;
         k++) {
        double px = floor(page_x(fr, k * fr->xstep)) + 0.5;
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_move_to(cr, px, fr->top);
        cairo_line_to(cr, px, fr->bottom);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, px, fr->bottom);
        cairo_line_to(cr, px, fr->bottom + 5);
        cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%.6g", k * fr->xstep);
        text_centred(cr, px, fr->bottom + 18, buf);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_rectangle(cr, floor(fr->left) + 0.5, floor(fr->top) + 0.5,
                    floor(fr->right) - floor(fr->left), floor(fr->bottom) - floor(fr->top));
    cairo_stroke(cr);
}

static void draw_labels(cairo_t *cr, const frame *fr, int width, const char *title)
{
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 14);
    text_centred(cr, 0.5 * (fr->left + fr->right), fr->bottom + 42, "pixel column");
    cairo_save(cr);
    cairo_translate(cr, 22, 0.5 * (fr->top + fr->bottom));
    cairo_rotate(cr, -0.5 * RAD_PI);
    text_centred(cr, 0, 0, "radiosity");
    cairo_restore(cr);
    if (title && *title) {
        cairo_set_font_size(cr, 15);
        text_centred(cr, 0.5 * width, 26, title);
    }
}

static const double band_colour[3][3] = {{0.85, 0, 0}, {0, 0.6, 0}, {0, 0, 0.9}};

static void draw_curves(cairo_t *cr, const frame *fr, const double *rgb, int n)
{
    cairo_save(cr);
    cairo_rectangle(cr, fr->left, fr->top, fr->right - fr->left, fr->bottom - fr->top);
    cairo_clip(cr);
    cairo_set_line_width(cr, 1.5);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (int b = 0; b < 3; b++) {
        int pen = 0;
        cairo_set_source_rgb(cr, band_colour[b][0], band_colour[b][1], band_colour[b][2]);
        for (int x = 0; x < n; x++) {
            double v = rgb[3 * x + b];
            if (!isfinite(v)) {
                pen = 0;
                continue;
            }
            if (pen)
                cairo_line_to(cr, page_x(fr, x), page_y(fr, v));
            else
                cairo_move_to(cr, page_x(fr, x), page_y(fr, v));
            pen = 1;
        }
        cairo_stroke(cr);
    }
    cairo_restore(cr);
}

static void draw_legend(cairo_t *cr, const frame *fr)
{
    static const char *const name[3] = {"R", "G", "B"};
    cairo_set_font_size(cr, 12);
    cairo_set_line_width(cr, 2);
    for (int b = 0; b < 3; b++) {
        double x = fr->right - 110 + 36 * b, y = fr->top - 12;
        cairo_set_source_rgb(cr, band_colour[b][0], band_colour[b][1], band_colour[b][2]);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + 16, y);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, x + 19, y + 4);
        cairo_show_text(cr, name[b]);
    }
}

rad_status radi_plot_scanline(const double *rgb, int n, const char *title, int width,
                             int height, FILE *out, rad_error *err)
{
    if (n < 1)
        return radi_fail(err, RAD_ERR_INVALID, "a scanline plot needs at least one pixel");
    if (width < 200 || height < 150 || width > 16384 || height > 16384)
        return radi_fail(err, RAD_ERR_INVALID,
                        "plot size %d x %d is outside 200 x 150 to 16384 x 16384", width,
                        height);
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
    cairo_t *cr = cairo_create(s);
    frame fr = make_frame(rgb, n, width, height);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    draw_axes(cr, &fr);
    draw_curves(cr, &fr, rgb, n);
    draw_legend(cr, &fr);
    draw_labels(cr, &fr, width, title);
    return radi_plot_finish(cr, s, out, err);
}
