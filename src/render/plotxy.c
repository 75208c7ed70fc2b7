/* plotxy.c -- line plots of several series, linear or logarithmic axes.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Used by `radiosity sweep` (error against time, log-log) and fit for any
 * convergence curve.  Points that cannot be drawn on a log axis (<= 0, or
 * not finite) are skipped; a series is drawn as a polyline with a marker at
 * each point.  Deterministic output (cairo image surface, fixed fonts).
 */
#include <config.h>

#include <cairo.h>
#include <math.h>
#include <stdio.h>

#include "render/plot.h"
#include "render/plotxy.h"
#include "util/util.h"

#define ML 86.0
#define MR 210.0
#define MT 40.0
#define MB 56.0

static const double palette[8][3] = {{0.85, 0.1, 0.1}, {0.1, 0.45, 0.85}, {0.1, 0.6, 0.2},
                                     {0.6, 0.3, 0.7},  {0.9, 0.55, 0.0}, {0.3, 0.3, 0.3},
                                     {0.0, 0.6, 0.6},  {0.6, 0.4, 0.2}};

typedef struct axis {
    int log;
    double lo, hi;
} axis;

static int usable(const axis *a, double v)
{
    return isfinite(v) && (!a->log || v > 0);
}

static double tr(const axis *a, double v)
{
    return a->log ? log10(v) : v;
}

static void range(const rad_series *s, int ns, int which, axis *a)
{
    a->lo = HUGE_VAL;
    a->hi = -HUGE_VAL;
    for (int k = 0; k < ns; k++)
        for (int i = 0; i < s[k].n; i++) {
            double v = which ? s[k].y[i] : s[k].x[i];
            if (!usable(a, v))
                continue;
            a->lo = fmin(a->lo, tr(a, v));
            a->hi = fmax(a->hi, tr(a, v));
        }
    if (!(a->lo <= a->hi)) {
        a->lo = 0;
        a->hi = 1;
    }
    if (a->log) { /* whole decades */
        a->lo = floor(a->lo);
        a->hi = ceil(a->hi);
    }
    if (a->hi - a->lo < 1e-12) {
        a->lo -= 0.5;
        a->hi += 0.5;
    }
}

static void ticks(cairo_t *cr, const axis *a, int vertical, double x0, double y0, double len,
                  double other)
{
    double step = a->log ? 1 : pow(10, floor(log10((a->hi - a->lo) / 2)));
    if (a->log && a->hi - a->lo > 8)
        step = 2;
    for (double t = ceil(a->lo / step) * step; t <= a->hi + 1e-9; t += step) {
        double f = (t - a->lo) / (a->hi - a->lo);
        char label[32];
        if (a->log)
            snprintf(label, sizeof label, "1e%+d", (int)lround(t));
        else
            snprintf(label, sizeof label, "%g", t);
        cairo_text_extents_t ext;
        cairo_text_extents(cr, label, &ext);
        if (vertical) {
            double y = y0 - f * len;
            cairo_move_to(cr, x0 - 5, y);
            cairo_line_to(cr, x0, y);
            cairo_stroke(cr);
            cairo_move_to(cr, x0 - 8 - ext.width, y + ext.height / 2);
        } else {
            double x = x0 + f * len;
            cairo_move_to(cr, x, y0);
            cairo_line_to(cr, x, y0 + 5);
            cairo_stroke(cr);
            cairo_move_to(cr, x - ext.width / 2, y0 + 8 + ext.height);
        }
        cairo_show_text(cr, label);
        (void)other;
    }
}

rad_status radi_plot_xy(const rad_series *s, int ns, const rad_plot_spec *spec,
                       FILE *out, rad_error *err)
{
    const int w = spec->width > 0 ? spec->width : 900, h = spec->height > 0 ? spec->height : 520;
    axis ax = {spec->logx, 0, 0}, ay = {spec->logy, 0, 0};
    range(s, ns, 0, &ax);
    range(s, ns, 1, &ay);
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    cairo_t *cr = cairo_create(surf);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        cairo_destroy(cr);
        cairo_surface_destroy(surf);
        return radi_fail(err, RAD_ERR_NOMEM, "cannot draw the plot");
    }
    const double pw = w - ML - MR, ph = h - MT - MB;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 12);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, ML, MT, pw, ph);
    cairo_stroke(cr);
    ticks(cr, &ax, 0, ML, MT + ph, pw, 0);
    ticks(cr, &ay, 1, ML, MT + ph, ph, 0);
    cairo_text_extents_t ext;
    if (spec->xlabel) {
        cairo_text_extents(cr, spec->xlabel, &ext);
        cairo_move_to(cr, ML + pw / 2 - ext.width / 2, h - 12);
        cairo_show_text(cr, spec->xlabel);
    }
    if (spec->ylabel) {
        cairo_save(cr);
        cairo_text_extents(cr, spec->ylabel, &ext);
        cairo_move_to(cr, 18, MT + ph / 2 + ext.width / 2);
        cairo_rotate(cr, -RAD_PI / 2);
        cairo_show_text(cr, spec->ylabel);
        cairo_restore(cr);
    }
    if (spec->title) {
        cairo_set_font_size(cr, 14);
        cairo_text_extents(cr, spec->title, &ext);
        cairo_move_to(cr, ML + pw / 2 - ext.width / 2, 24);
        cairo_show_text(cr, spec->title);
        cairo_set_font_size(cr, 12);
    }
    for (int k = 0; k < ns; k++) {
        const double *c = palette[k % 8];
        int started = 0;
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_set_line_width(cr, 1.8);
        for (int i = 0; i < s[k].n; i++) {
            if (!usable(&ax, s[k].x[i]) || !usable(&ay, s[k].y[i]))
                continue;
            double x = ML + (tr(&ax, s[k].x[i]) - ax.lo) / (ax.hi - ax.lo) * pw;
            double y = MT + ph - (tr(&ay, s[k].y[i]) - ay.lo) / (ay.hi - ay.lo) * ph;
            if (started)
                cairo_line_to(cr, x, y);
            else
                cairo_move_to(cr, x, y);
            started = 1;
        }
        cairo_stroke(cr);
        for (int i = 0; i < s[k].n; i++) {
            if (!usable(&ax, s[k].x[i]) || !usable(&ay, s[k].y[i]))
                continue;
            double x = ML + (tr(&ax, s[k].x[i]) - ax.lo) / (ax.hi - ax.lo) * pw;
            double y = MT + ph - (tr(&ay, s[k].y[i]) - ay.lo) / (ay.hi - ay.lo) * ph;
            cairo_arc(cr, x, y, 3, 0, 2 * RAD_PI);
            cairo_fill(cr);
        }
        /* legend */
        double ly = MT + 14 + 18 * k;
        cairo_rectangle(cr, ML + pw + 12, ly - 8, 16, 4);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, ML + pw + 34, ly - 2);
        cairo_show_text(cr, s[k].label ? s[k].label : "");
    }
    return radi_plot_finish(cr, surf, out, err);
}
