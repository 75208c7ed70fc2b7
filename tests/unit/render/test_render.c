/* test_render.c -- the rasteriser, the shading, the tone curve, the PLY reader.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * References are independent of the renderer's code paths:
 *   - coverage: the projected area of a square (pinhole geometry by hand);
 *     a row of a convex polygon holds round(span) +- 1 pixel centres, and
 *     the midpoint rule over rows errs by at most one row's width at the top
 *     and at the bottom, so |count - area| <= rows + 2 * width (+2);
 *   - the sRGB curve at its published points (IEC 61966-2-1: 0.5 -> 0.7354
 *     -> 188 of 255; the two branches meet at 0.0031308);
 *   - shading: a field linear in space is interpolated exactly, at every
 *     pixel, by bilinear quads and barycentric fans when interpolation is
 *     perspective-correct; the reference value is the field at the point
 *     where the pixel's ray meets the face, computed here from the
 *     documented camera conventions.  Tolerance 1e-9 absolute on values of
 *     O(1): the ray-plane intersection and the inverse bilinear map lose a
 *     few digits to cancellation, far from the 1e-3 an affine (screen-space)
 *     interpolation would be off by;
 *   - element centres: for a bilinear field the element value (the mean of
 *     its corners) is the field at its centre, where smooth must equal flat
 *     (the centres are placed on pixel centres by the choice of camera).
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "render/errcolour.h"
#include "render/plot.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/render.h"
#include "radiosity/plyread.h"
#include "radiosity/pipeline.h"
#include "radiosity/pipeline.h"
#include "../tap.h"
#include "util/vec.h"

#define PI 3.14159265358979323846

typedef double (*field_fn)(rad_vec3 p, int band);

typedef struct fixture {
    rad_scene scene;
    rad_mesh mesh;
    double *B, *Bv;
    rad_render_model model;
} fixture;

/* Parse and mesh the scene, give every vertex fn(p) and every element the
 * mean of its corners, and build the render model. */
static int fixture_make(fixture *fx, const char *text, field_fn fn)
{
    rad_error err;
    memset(fx, 0, sizeof *fx);
    if (rad_scene_parse(&fx->scene, text, strlen(text), "t.scene", &err) ||
        rad_mesh_build(&fx->mesh, &fx->scene, &err)) {
        tap_diag("%s", err.message);
        return -1;
    }
    const int n = fx->mesh.nelements, nv = fx->mesh.nvertices;
    fx->B = malloc(sizeof *fx->B * 3 * (size_t)n);
    fx->Bv = malloc(sizeof *fx->Bv * 3 * (size_t)nv);
    for (int v = 0; v < nv; v++)
        for (int b = 0; b < 3; b++)
            fx->Bv[v + b * nv] = fn(fx->mesh.vertices[v], b);
    for (int e = 0; e < n; e++)
        for (int b = 0; b < 3; b++) {
            double s = 0;
            const rad_element *el = &fx->mesh.elements[e];
            for (int k = 0; k < el->nverts; k++)
                s += fx->Bv[fx->mesh.vindex[el->first + k] + b * nv];
            fx->B[e + b * n] = s / el->nverts;
        }
    if (rad_render_model_from_mesh(&fx->model, &fx->mesh, fx->B, fx->Bv, &err)) {
        tap_diag("%s", err.message);
        return -1;
    }
    return 0;
}

static void fixture_free(fixture *fx)
{
    rad_render_model_free(&fx->model);
    free(fx->B);
    free(fx->Bv);
    rad_mesh_free(&fx->mesh);
    rad_scene_free(&fx->scene);
}

static rad_render_options options(rad_vec3 eye, rad_vec3 at, double fov, int w, int h,
                                  rad_shading shading)
{
    rad_render_options o;
    rad_render_options_init(&o);
    o.camera.defined = 1;
    o.camera.eye = eye;
    o.camera.at = at;
    o.camera.up = v3(0, 1, 0);
    o.camera.fov = fov;
    o.width = w;
    o.height = h;
    o.shading = shading;
    return o;
}

/* The ray through pixel centre (x, y), rebuilt from the documented camera:
 * right = (at - eye) x up, row 0 at the top, f = (h/2) / tan(fov/2). */
static rad_vec3 ray_of(const rad_render_options *o, int x, int y)
{
    const rad_camera *c = &o->camera;
    rad_vec3 fwd = v3_sub(c->at, c->eye);
    fwd = v3_scale(fwd, 1 / v3_norm(fwd));
    rad_vec3 right = v3_cross(fwd, c->up);
    right = v3_scale(right, 1 / v3_norm(right));
    rad_vec3 up = v3_cross(right, fwd);
    double f = 0.5 * o->height / tan(0.5 * c->fov * PI / 180);
    return v3_add(fwd, v3_add(v3_scale(right, (x + 0.5 - 0.5 * o->width) / f),
                              v3_scale(up, (0.5 * o->height - y - 0.5) / f)));
}

static long covered(const rad_image *img)
{
    long n = 0;
    for (long p = 0; p < (long)img->width * img->height; p++)
        n += img->face[p] >= 0;
    return n;
}

static double zero_field(rad_vec3 p, int b)
{
    (void)p;
    return 0.25 * (b + 1);
}

/* ---- tone mapping ----------------------------------------------------------- */

static void test_tone(void)
{
    tap_ok(rad_tone_byte(0, 1) == 0, "sRGB: 0 -> 0");
    tap_ok(rad_tone_byte(1, 1) == 255, "sRGB: 1 -> 255");
    tap_ok(rad_tone_byte(0.5, 1) == 188, "sRGB: 0.5 -> 188 (got %d)", rad_tone_byte(0.5, 1));
    tap_ok(rad_tone_byte(0.25, 2) == 188 && rad_tone_byte(2, 0.5) == 255,
           "exposure multiplies before the curve (0.25 x 2 -> 188, 2 x 0.5 -> 255)");
    tap_ok(rad_tone_byte(7, 1) == 255 && rad_tone_byte(-1, 1) == 0 && rad_tone_byte(NAN, 1) == 0,
           "out of range clamps: 7 -> 255, -1 -> 0, NaN -> 0");
    const double c = 0.0031308;
    double lin = 12.92 * c, pw = 1.055 * pow(c, 1 / 2.4) - 0.055;
    tap_ok(fabs(lin - pw) < 1e-7, "the two branches meet at 0.0031308 (%.9f vs %.9f)", lin, pw);
    tap_close(rad_srgb_encode(c), 0.040449936, 1e-7, "encode(0.0031308) = 0.040449936");
    tap_close(rad_srgb_encode(0.001), 0.01292, 1e-12, "linear branch: encode(0.001) = 0.01292");
    tap_close(rad_srgb_encode(0.5), 0.735356983052, 1e-11, "encode(0.5) = 0.735356983052");
    double worst = 0;
    for (int k = 0; k <= 1000; k++)
        worst = fmax(worst, fabs(rad_srgb_decode(rad_srgb_encode(k / 1000.0)) - k / 1000.0));
    tap_ok(worst < 1e-12, "decode(encode(x)) = x on [0, 1] (worst %.3g)", worst);
    int mono = 1;
    for (int k = 1; k <= 10000; k++)
        mono &= rad_tone_byte(k / 10000.0, 1) >= rad_tone_byte((k - 1) / 10000.0, 1);
    tap_ok(mono, "8-bit tone curve is monotone");
}

/* ---- coverage, culling, depth ---------------------------------------------- */

/* The screen position of p (documented conventions, computed here). */
static void project(const rad_render_options *o, rad_vec3 p, double *sx, double *sy)
{
    const rad_camera *c = &o->camera;
    rad_vec3 fwd = v3_sub(c->at, c->eye);
    fwd = v3_scale(fwd, 1 / v3_norm(fwd));
    rad_vec3 right = v3_cross(fwd, c->up);
    right = v3_scale(right, 1 / v3_norm(right));
    rad_vec3 up = v3_cross(right, fwd);
    double f = 0.5 * o->height / tan(0.5 * c->fov * PI / 180);
    rad_vec3 d = v3_sub(p, c->eye);
    *sx = 0.5 * o->width + f * v3_dot(d, right) / v3_dot(d, fwd);
    *sy = 0.5 * o->height - f * v3_dot(d, up) / v3_dot(d, fwd);
}

/* Pixels whose coverage differs from an independent point-in-polygon test
 * of the pixel centre against the projected corners (pixels within 1e-9
 * pixel of an edge may go either way and are not counted). */
static long coverage_mismatch(const rad_image *img, const rad_render_options *o,
                              const rad_vec3 *corner)
{
    double sx[4], sy[4];
    long bad = 0;
    for (int k = 0; k < 4; k++)
        project(o, corner[k], &sx[k], &sy[k]);
    for (int y = 0; y < o->height; y++)
        for (int x = 0; x < o->width; x++) {
            int pos = 0, neg = 0, edge = 0;
            for (int k = 0; k < 4; k++) {
                double ex = sx[(k + 1) % 4] - sx[k], ey = sy[(k + 1) % 4] - sy[k];
                double e = (ex * (y + 0.5 - sy[k]) - ey * (x + 0.5 - sx[k])) / hypot(ex, ey);
                pos += e > 1e-9;
                neg += e < -1e-9;
                edge += fabs(e) <= 1e-9;
            }
            int inside = pos == 0 || neg == 0;
            if (!edge && inside != (img->face[(size_t)y * o->width + x] >= 0))
                bad++;
        }
    return bad;
}

static void test_square_coverage(void)
{
    fixture fx;
    rad_image img;
    rad_error err;
    /* 2 x 2 square in z = 0, front normal -z, seen from z = -4 */
    if (fixture_make(&fx, "material w reflect 0.5\nquad w -1 -1 0  -1 1 0  1 1 0  1 -1 0\n",
                     zero_field)) {
        tap_ok(0, "square scene");
        return;
    }
    for (int rot = 0; rot < 2; rot++) {
        /* rot 1: the camera rolled by 30 degrees, further away and a little
         * off-axis (the square stays inside the picture) */
        rad_render_options o = options(v3(0, 0, -4), v3(0, 0, 0), 30, 200, 160,
                                       RAD_SHADING_FLAT);
        if (rot) {
            o.camera.up = v3(sin(PI / 6), cos(PI / 6), 0);
            o.camera.eye = v3(0.1, -0.05, -6);
        }
        tap_ok(rad_render(&fx.model, &o, &img, &err) == RAD_OK, "render the square (roll %d)",
               30 * rot);
        const double f = 0.5 * o.height / tan(15 * PI / 180);
        long n = covered(&img);
        if (!rot) {
            /* exact: pixel centres i + 0.5 within [c - s/2, c + s/2] per axis */
            double h = f / 4; /* half-size 1 at depth 4 */
            long nx = (long)(floor(100 + h - 0.5) - ceil(100 - h - 0.5) + 1);
            long ny = (long)(floor(80 + h - 0.5) - ceil(80 - h - 0.5) + 1);
            tap_ok(n == nx * ny, "square: %ld pixels = %ld x %ld centres inside (area %.1f)",
                   n, nx, ny, 4 * h * h);
        } else {
            /* |count - area| <= rows + 2 * width + 2 (see the top of the file) */
            const rad_vec3 c4[4] = {v3(-1, -1, 0), v3(-1, 1, 0), v3(1, 1, 0), v3(1, -1, 0)};
            double sx[4], sy[4], area = 0, ylo = HUGE_VAL, yhi = -HUGE_VAL;
            for (int k = 0; k < 4; k++) {
                project(&o, c4[k], &sx[k], &sy[k]);
                ylo = fmin(ylo, sy[k]);
                yhi = fmax(yhi, sy[k]);
            }
            for (int k = 0; k < 4; k++) /* shoelace */
                area += 0.5 * (sx[k] * sy[(k + 1) % 4] - sx[(k + 1) % 4] * sy[k]);
            area = fabs(area);
            double rows = yhi - ylo, tol = 3 * rows + 2;
            (void)f;
            tap_ok(fabs(n - area) <= tol,
                   "rolled square: %ld pixels, projected area %.1f (tolerance %.0f)", n, area, tol);
        }
        const rad_vec3 corner[4] = {v3(-1, -1, 0), v3(-1, 1, 0), v3(1, 1, 0), v3(1, -1, 0)};
        long bad = coverage_mismatch(&img, &o, corner);
        tap_ok(bad == 0, "square roll %d: every pixel centre inside the projected square is "
                         "drawn, no other (%ld differ)", 30 * rot, bad);
        rad_image_free(&img);
    }
    fixture_free(&fx);

    /* the same square with its vertices reversed faces away: nothing drawn */
    if (fixture_make(&fx, "material w reflect 0.5\nquad w -1 -1 0  1 -1 0  1 1 0  -1 1 0\n",
                     zero_field) == 0) {
        rad_render_options o = options(v3(0, 0, -4), v3(0, 0, 0), 30, 200, 160,
                                       RAD_SHADING_SMOOTH);
        rad_render(&fx.model, &o, &img, &err);
        tap_ok(covered(&img) == 0, "a back face is not drawn (%ld pixels)", covered(&img));
        rad_image_free(&img);
        /* ... but seen from the other side it is */
        o.camera.eye = v3(0, 0, 4);
        rad_render(&fx.model, &o, &img, &err);
        tap_ok(covered(&img) == 22500, "seen from its front it is (%ld pixels)", covered(&img));
        rad_image_free(&img);
        fixture_free(&fx);
    }
}

static double depth_field(rad_vec3 p, int b)
{
    (void)b;
    return p.z < 0.5 ? 0.7 : 0.2; /* near square 0.7, far square 0.2 */
}

static void test_zbuffer(void)
{
    static const char *const scenes[2] = {
        "material w reflect 0.5\n"
        "quad w -1 -1 0  -1 1 0  1 1 0  1 -1 0\n"        /* near, z = 0 */
        "quad w -3 -3 1  -3 3 1  3 3 1  3 -3 1\n",       /* far, z = 1, larger */
        "material w reflect 0.5\n"
        "quad w -3 -3 1  -3 3 1  3 3 1  3 -3 1\n"
        "quad w -1 -1 0  -1 1 0  1 1 0  1 -1 0\n"};
    for (int k = 0; k < 2; k++) {
        fixture fx;
        rad_image img;
        rad_error err;
        if (fixture_make(&fx, scenes[k], depth_field))
            continue;
        rad_render_options o = options(v3(0, 0, -4), v3(0, 0, 0), 60, 100, 100,
                                       RAD_SHADING_FLAT);
        rad_render(&fx.model, &o, &img, &err);
        const double *mid = rad_image_row(&img, 50), *top = rad_image_row(&img, 2);
        tap_ok(mid[3 * 50] == 0.7 && top[3 * 50] == 0.2 && img.depth[50 * 100 + 50] < 4.01,
               "z-buffer keeps the nearer face, %s first (centre %g, top %g)",
               k ? "far" : "near", mid[3 * 50], top[3 * 50]);
        rad_image_free(&img);
        fixture_free(&fx);
    }
}

static const char cube_text[] =
    "material w reflect 0.5\n"
    "quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 3x3\n"
    "quad w 0 0 1  0 1 1  1 1 1  1 0 1 mesh 3x3\n"
    "quad w 0 0 0  0 1 0  0 1 1  0 0 1 mesh 3x3\n"
    "quad w 1 0 0  1 0 1  1 1 1  1 1 0 mesh 3x3\n"
    "quad w 0 0 0  0 0 1  1 0 1  1 0 0 mesh 3x3\n"
    "quad w 0 1 0  1 1 0  1 1 1  0 1 1 mesh 3x3\n";

static void test_inside(void)
{
    fixture fx;
    rad_error err;
    if (fixture_make(&fx, cube_text, zero_field))
        return;
    /* from the centre of a closed box every pixel sees a wall: the walls
     * behind the eye must be clipped, not dropped or wrapped around */
    static const double at[4][3] = {{0.5, 0.5, 1}, {1, 1, 1}, {0, 0.2, 0.9}, {0.5, 0.5, -3}};
    int all = 1;
    for (int k = 0; k < 4; k++) {
        rad_render_options o = options(v3(0.5, 0.5, 0.5), v3(at[k][0], at[k][1], at[k][2]),
                                       k == 1 ? 150 : 110, 64, 48, RAD_SHADING_SMOOTH);
        rad_image img;
        if (rad_render(&fx.model, &o, &img, &err) != RAD_OK || covered(&img) != 64 * 48)
            all = 0;
        rad_image_free(&img);
    }
    tap_ok(all, "camera inside a closed box: every pixel drawn, in 4 directions (fov to 150)");
    /* a camera at a wall's plane, looking along it */
    rad_render_options o = options(v3(0.5, 0.5, 0), v3(0.5, 0.5, 1), 90, 40, 40,
                                   RAD_SHADING_FLAT);
    rad_image img;
    tap_ok(rad_render(&fx.model, &o, &img, &err) == RAD_OK && covered(&img) == 1600,
           "camera on a wall's plane: every pixel drawn");
    rad_image_free(&img);
    fixture_free(&fx);
}

/* ---- shading ------------------------------------------------------------ */

static double bilinear_field(rad_vec3 p, int b)
{
    return 1 + 0.3 * p.x + 0.2 * p.y * (b + 1) + 0.25 * p.x * p.y;
}

static void test_centres(void)
{
    fixture fx;
    rad_error err;
    rad_image flat, smooth;
    if (fixture_make(&fx, "material w reflect 0.5\nquad w -1 -1 0  -1 1 0  1 1 0  1 -1 0 mesh 4x4\n",
                     bilinear_field))
        return;
    /* f = 32 / tan(fov/2) = 36 pixels at depth 2 puts the element centres
     * x, y = +-0.25, +-0.75 at 32 +- 4.5 and 32 +- 13.5: pixel centres */
    const double fov = 2 * atan(8.0 / 9.0) * 180 / PI;
    rad_render_options o = options(v3(0, 0, -2), v3(0, 0, 0), fov, 64, 64, RAD_SHADING_FLAT);
    rad_render(&fx.model, &o, &flat, &err);
    o.shading = RAD_SHADING_SMOOTH;
    rad_render(&fx.model, &o, &smooth, &err);
    double worst = 0, differ = 0;
    int checked = 0;
    for (int e = 0; e < fx.mesh.nelements; e++) {
        rad_vec3 c = fx.mesh.elements[e].centroid;
        int x = (int)floor(32 - 18 * c.x), y = (int)floor(32 - 18 * c.y);
        size_t p = (size_t)y * 64 + (size_t)x;
        if (flat.face[p] != e || smooth.face[p] != e)
            continue;
        checked++;
        for (int b = 0; b < 3; b++) {
            worst = fmax(worst, fabs(smooth.rgb[3 * p + b] - fx.B[e + b * fx.mesh.nelements]));
            worst = fmax(worst, fabs(flat.rgb[3 * p + b] - fx.B[e + b * fx.mesh.nelements]));
        }
    }
    for (size_t p = 0; p < 64 * 64; p++)
        differ = fmax(differ, fabs(flat.rgb[3 * p] - smooth.rgb[3 * p]));
    tap_ok(checked == 16 && worst < 1e-12,
           "at the 16 element centres smooth = flat = element value (%d checked, worst %.3g)",
           checked, worst);
    tap_ok(differ > 0.05, "away from the centres smooth differs from flat (max %.3g)", differ);
    rad_image_free(&flat);
    rad_image_free(&smooth);
    fixture_free(&fx);
}

static double linear_field(rad_vec3 p, int b)
{
    static const double g[3][4] = {{1, 0.3, -0.2, 0.1}, {2, -0.1, 0.4, 0.25}, {0.5, 0.2, 0.2, -0.3}};
    return g[b][0] + g[b][1] * p.x + g[b][2] * p.y + g[b][3] * p.z;
}

/* Render with smooth shading from an oblique camera and compare every drawn
 * pixel with the linear field where its ray meets the face. */
static double linear_worst(const fixture *fx, rad_vec3 eye, rad_vec3 at, long *n)
{
    rad_render_options o = options(eye, at, 50, 160, 120, RAD_SHADING_SMOOTH);
    rad_image img;
    rad_error err;
    double worst = 0;
    *n = 0;
    if (rad_render(&fx->model, &o, &img, &err) != RAD_OK)
        return INFINITY;
    const rad_render_model *m = &fx->model;
    for (int y = 0; y < o.height; y++)
        for (int x = 0; x < o.width; x++) {
            size_t p = (size_t)y * o.width + x;
            int f = img.face[p];
            if (f < 0)
                continue;
            const int *idx = m->face_index + m->face_first[f];
            rad_vec3 a = m->pos[idx[0]];
            rad_vec3 nrm = v3_cross(v3_sub(m->pos[idx[1]], a), v3_sub(m->pos[idx[2]], a));
            rad_vec3 d = ray_of(&o, x, y);
            double t = v3_dot(nrm, v3_sub(a, eye)) / v3_dot(nrm, d);
            rad_vec3 X = v3_add(eye, v3_scale(d, t));
            for (int b = 0; b < 3; b++)
                worst = fmax(worst, fabs(img.rgb[3 * p + b] - linear_field(X, b)));
            (*n)++;
        }
    rad_image_free(&img);
    return worst;
}

static void test_linear(void)
{
    fixture fx;
    /* a tilted parallelogram, a tilted trapezoid (non-affine (u,v)) and a
     * hexagon (fan), all facing roughly -z */
    const char *text = "material w reflect 0.5\n"
                       "quad w -2 -1 0  -2 1 0.5  -0.5 1.2 0.8  -0.5 -0.8 0.3 mesh 3x2\n"
                       "quad w 0 -1 1  0 1 1  1.5 0.5 2  1.5 -0.5 2 mesh 2x3\n"
                       "disk w 1 1.5 0  0.2 -0.3 -1  0.6 6\n";
    if (fixture_make(&fx, text, linear_field))
        return;
    long n1, n2;
    double w1 = linear_worst(&fx, v3(-0.5, 0.3, -3), v3(0, 0.2, 1), &n1);
    double w2 = linear_worst(&fx, v3(1.5, -1, -2), v3(-0.5, 0.5, 1), &n2);
    tap_ok(n1 > 3000 && n2 > 3000 && w1 < 1e-9 && w2 < 1e-9,
           "smooth shading reproduces a linear field exactly, perspective-correct "
           "(%ld and %ld pixels, worst %.3g and %.3g)",
           n1, n2, w1, w2);
    fixture_free(&fx);
}

/* ---- edges, exposure, determinism --------------------------------------- */

static void test_edges_exposure(void)
{
    fixture fx;
    rad_error err;
    rad_image img;
    if (fixture_make(&fx, "material w reflect 0.5\nquad w -1 -1 0  -1 1 0  1 1 0  1 -1 0 mesh 4x4\n",
                     bilinear_field))
        return;
    const double fov = 2 * atan(8.0 / 9.0) * 180 / PI;
    rad_render_options o = options(v3(0, 0, -2), v3(0, 0, 0), fov, 64, 64, RAD_SHADING_FLAT);
    o.edges = 1;
    rad_render(&fx.model, &o, &img, &err);
    /* grid lines x = 0 and y = 0 fall on the pixel boundary 32: columns 31, 32 */
    tap_ok(img.edge[20 * 64 + 31] && img.edge[20 * 64 + 32] && !img.edge[27 * 64 + 27],
           "edges: the grid line x = 0 is drawn, an element centre is not");
    long ne = 0;
    for (int p = 0; p < 64 * 64; p++)
        ne += img.edge[p];
    /* 5 + 5 lines of 36 px, each 1-2 px wide */
    tap_ok(ne >= 10 * 36 - 20 && ne <= 2 * 10 * 36, "edges: %ld edge pixels for 10 lines of 36", ne);
    unsigned char *rgb = malloc(3 * 64 * 64);
    rad_image_to_rgb8(&img, rgb);
    tap_ok(rgb[3 * (20 * 64 + 31)] == 0 && rgb[3 * (27 * 64 + 27)] > 0, "edges are black");
    /* default exposure: the brightest element is white in its brightest band */
    double mx = rad_render_max_radiosity(&fx.model);
    int found = 0;
    for (int p = 0; p < 64 * 64; p++)
        for (int b = 0; b < 3; b++)
            if (img.face[p] >= 0 && img.rgb[3 * p + b] == mx && !img.edge[p])
                found |= rgb[3 * p + b] == 255;
    tap_ok(found && img.exposure == 1 / mx, "default exposure: the brightest element is 255");
    free(rgb);
    rad_image_free(&img);
    fixture_free(&fx);
}

/* The error colours of errcolour.c by hand from its documented scale:
 * grey 128 at e = 0, linear to red (255, 0, 0) at e = +0.5 and beyond, to
 * blue (0, 0, 255) at -0.5 and beyond; e = 0.25 is half way: 191.5 -> 192
 * (round half away from zero) and 64.  And the picture drawn from the
 * field at exposure 1, flat, shows those bytes exactly. */
static void test_errcolour(void)
{
    static const struct { double e; unsigned char c[3]; } cases[] = {
        {0, {128, 128, 128}},  {0.25, {192, 64, 64}}, {0.5, {255, 0, 0}},
        {7, {255, 0, 0}},      {-0.25, {64, 64, 192}}, {-1, {0, 0, 255}},
        {INFINITY, {255, 0, 0}}};
    int bad = 0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        unsigned char c[3];
        radi_errcolour_of(cases[k].e, c);
        bad += memcmp(c, cases[k].c, 3) != 0;
    }
    tap_ok(bad == 0, "error colours: grey at 0, red over, blue under, full at 50%% (%d off)", bad);
    /* B = 1.25 Bref on element 0 (red-ish), 0.5 Bref on element 1 (blue) */
    const double B[6] = {1.25, 0.5, 2.5, 1, 1.25, 0.5}, Bref[6] = {1, 1, 2, 2, 1, 1};
    tap_close(radi_errcolour_relative(2, 0, B, Bref), 0.25, 1e-15, "relative error of the band mean");
    double field[6];
    radi_errcolour_field(2, B, Bref, field);
    int same = 1;
    for (int i = 0; i < 2; i++) {
        unsigned char c[3];
        radi_errcolour_of(i == 0 ? 0.25 : -0.5, c);
        for (int b = 0; b < 3; b++)
            same &= rad_tone_byte(field[i + 2 * b], 1) == c[b];
    }
    tap_ok(same, "the field at exposure 1 tone-maps back to the colour bytes");
}

/* 8-bit sRGB of a linear value clamped to [0, 1] (IEC 61966-2-1:1999). */
static double srgb_byte(double x)
{
    x = fmin(fmax(x, 0), 1);
    return 255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055);
}

/* The automatic exposure on the Cornell box (data/cornell-box.scene at
 * 2x2 per surface): by default the brightest element that emits nothing,
 * found here from the mesh's E and the solution's B, maps to full scale
 * and the lamp, about 18 times brighter, clips to white; with
 * RAD_EXPOSURE_ALL the lamp sets the scale and the walls fall to 1/18 of
 * it: the nearly black picture of before. */
static void test_exposure_cornell(void)
{
    const char *top = getenv("top_srcdir");
    char path[4096];
    rad_scene sc;
    rad_result res;
    rad_pipeline_options po;
    rad_render_model model;
    rad_error err;
    snprintf(path, sizeof path, "%s/data/cornell-box.scene", top ? top : ".");
    memset(&res, 0, sizeof res);
    if (rad_scene_load(&sc, path, &err)) {
        tap_ok(0, "cornell box: %s", err.message);
        return;
    }
    rad_scene_set_mesh(&sc, 2, 2);
    rad_pipeline_options_init(&po);
    if (rad_pipeline_run(&sc, &po, &res, &err) ||
        rad_render_model_from_mesh(&model, &res.mesh, res.B, res.Bv, &err)) {
        tap_ok(0, "cornell box: %s", err.message);
        rad_result_free(&res);
        rad_scene_free(&sc);
        return;
    }
    const int n = res.mesh.nelements;
    double wall = 0, lamp = 0;
    for (int e = 0; e < n; e++) {
        const double *E = res.mesh.elements[e].emit;
        const int emits = E[0] > 0 || E[1] > 0 || E[2] > 0;
        for (int b = 0; b < 3; b++) {
            const double v = res.B[e + (size_t)b * n];
            if (emits)
                lamp = fmax(lamp, v);
            else
                wall = fmax(wall, v);
        }
    }
    rad_render_options o;
    rad_render_options_init(&o);
    o.camera = sc.camera;
    o.width = o.height = 96;
    o.shading = RAD_SHADING_FLAT;
    rad_image img, all;
    rad_render(&model, &o, &img, &err);
    o.exposure_from = RAD_EXPOSURE_ALL;
    rad_render(&model, &o, &all, &err);
    tap_ok(lamp > 10 * wall, "cornell box: the lamp (%g) outshines the brightest wall (%g)",
           lamp, wall);
    tap_ok(img.exposure == 1 / wall && all.exposure == 1 / lamp,
           "default exposure 1 / brightest reflector (%g), 'all' 1 / lamp (%g)", img.exposure,
           all.exposure);
    tap_ok(rad_mesh_auto_exposure(&res.mesh, res.B, RAD_EXPOSURE_REFLECTORS) == 1 / wall &&
               rad_mesh_auto_exposure(&res.mesh, res.B, RAD_EXPOSURE_ALL) == 1 / lamp,
           "the mesh's automatic exposure is the same");
    unsigned char *rgb = malloc(3 * 96 * 96), *rgb_all = malloc(3 * 96 * 96);
    rad_image_to_rgb8(&img, rgb);
    rad_image_to_rgb8(&all, rgb_all);
    /* every pixel (flat shading: its face's B) is the sRGB curve (IEC
     * 61966-2-1, 1.055 x^(1/2.4) - 0.055 above 0.0031308, 12.92 x below)
     * of B times the exposure, clamped to [0, 1], in 8 bits, +-1 */
    long lamp_px = 0, lamp_white = 0, bad = 0, bad_all = 0;
    int hi = 0, hi_all = 0;
    for (int p = 0; p < 96 * 96; p++) {
        const int f = img.face[p];
        if (f < 0)
            continue;
        const double *E = res.mesh.elements[f].emit;
        if (E[0] > 0 || E[1] > 0 || E[2] > 0) {
            lamp_px++;
            lamp_white += rgb[3 * p] == 255 && rgb[3 * p + 1] == 255 && rgb[3 * p + 2] == 255;
            continue;
        }
        for (int b = 0; b < 3; b++) {
            const double v = res.B[f + (size_t)b * n];
            bad += fabs(rgb[3 * p + b] - srgb_byte(v / wall)) > 1;
            bad_all += fabs(rgb_all[3 * p + b] - srgb_byte(v / lamp)) > 1;
            hi = rgb[3 * p + b] > hi ? rgb[3 * p + b] : hi;
            hi_all = rgb_all[3 * p + b] > hi_all ? rgb_all[3 * p + b] : hi_all;
        }
    }
    tap_ok(bad == 0 && bad_all == 0, "every reflector pixel is srgb(B / brightest reflector), "
           "or with RAD_EXPOSURE_ALL srgb(B / lamp) (%ld, %ld off)", bad, bad_all);
    tap_ok(lamp_px > 0 && lamp_white == lamp_px, "the lamp clips to white (%ld of %ld pixels)",
           lamp_white, lamp_px);
    /* the exposures differ by lamp / wall (17.8); through the power branch
     * of the curve a byte shrinks by at least that ^ (1 / 2.4) = 3.3 (the
     * brightest reflector on top of the tall block is out of sight) */
    tap_ok(hi > 3 * hi_all, "the brightest reflector pixel: %d of 255, %d with "
           "RAD_EXPOSURE_ALL (no longer nearly black)", hi, hi_all);
    free(rgb);
    free(rgb_all);
    rad_image_free(&img);
    rad_image_free(&all);
    rad_render_model_free(&model);
    rad_result_free(&res);
    rad_scene_free(&sc);
}

static int read_file(const char *path, unsigned char **buf, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    fseek(f, 0, SEEK_END);
    *len = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    *buf = malloc(*len ? *len : 1);
    size_t got = fread(*buf, 1, *len, f);
    fclose(f);
    return got == *len ? 0 : -1;
}

/* The PNG writers print to a stream; these open and close it. */
static rad_status png_to(const char *path, const rad_image *img, rad_error *err)
{
    FILE *f = fopen(path, "wb");
    rad_status st = f ? rad_image_write_png(img, f, err) : RAD_ERR_IO;
    if (f && fclose(f) != 0 && st == RAD_OK)
        st = RAD_ERR_IO;
    return st;
}

static rad_status plot_to(const char *path, const double *row, rad_error *err)
{
    FILE *f = fopen(path, "wb");
    rad_status st = f ? radi_plot_scanline(row, 96, "test", 400, 300, f, err) : RAD_ERR_IO;
    if (f && fclose(f) != 0 && st == RAD_OK)
        st = RAD_ERR_IO;
    return st;
}

static void test_determinism(void)
{
    fixture fx;
    rad_error err;
    char dir[] = "/tmp/test_render.XXXXXX";
    if (!mkdtemp(dir) || fixture_make(&fx, cube_text, bilinear_field)) {
        tap_ok(0, "determinism setup");
        return;
    }
    char p1[64], p2[64], p3[64];
    snprintf(p1, sizeof p1, "%s/a.png", dir);
    snprintf(p2, sizeof p2, "%s/b.png", dir);
    snprintf(p3, sizeof p3, "%s/plot.png", dir);
    rad_render_options o = options(v3(0.5, 0.5, -1.2), v3(0.5, 0.5, 1), 45, 96, 80,
                                   RAD_SHADING_SMOOTH);
    o.edges = 1;
    rad_image a, b;
    rad_render(&fx.model, &o, &a, &err);
    rad_render(&fx.model, &o, &b, &err);
    tap_ok(memcmp(a.rgb, b.rgb, sizeof *a.rgb * 3 * 96 * 80) == 0 &&
               memcmp(a.face, b.face, sizeof *a.face * 96 * 80) == 0,
           "two renders give identical linear pictures");
    tap_ok(png_to(p1, &a, &err) == RAD_OK && png_to(p2, &b, &err) == RAD_OK, "PNG written");
    unsigned char *ba = NULL, *bb = NULL;
    size_t la = 0, lb = 0;
    int same = read_file(p1, &ba, &la) == 0 && read_file(p2, &bb, &lb) == 0 && la == lb &&
               memcmp(ba, bb, la) == 0;
    tap_ok(same, "identical PNG bytes (%zu)", la);
    /* the PNG header: signature, IHDR width and height big-endian */
    tap_ok(la > 24 && memcmp(ba, "\x89PNG\r\n\x1a\n", 8) == 0 && ba[16] == 0 && ba[19] == 96 &&
               ba[20] == 0 && ba[23] == 80,
           "PNG signature and IHDR size 96 x 80");
    free(ba);
    free(bb);
    /* the scanline plot is deterministic too */
    const double *row = rad_image_row(&a, 40);
    tap_ok(plot_to(p3, row, &err) == RAD_OK, "scanline plot written");
    read_file(p3, &ba, &la);
    plot_to(p3, row, &err);
    read_file(p3, &bb, &lb);
    tap_ok(la == lb && memcmp(ba, bb, la) == 0, "scanline plot bytes identical (%zu)", la);
    free(ba);
    free(bb);
    tap_ok(rad_image_row(&a, -1) == NULL && rad_image_row(&a, 80) == NULL &&
               rad_image_row(&a, 79) == a.rgb + 3 * 96 * 79,
           "rad_image_row: row 79 is the last, -1 and 80 are outside");
    FILE *ro = fopen(p1, "r"); /* a stream that refuses writes */
    tap_ok(ro && rad_image_write_png(&a, ro, &err) == RAD_ERR_IO,
           "a stream that cannot be written: %s", err.message);
    if (ro)
        fclose(ro);
    rad_image_free(&a);
    rad_image_free(&b);
    unlink(p1);
    unlink(p2);
    unlink(p3);
    rmdir(dir);
    fixture_free(&fx);
}

static void test_bad_options(void)
{
    fixture fx;
    rad_error err;
    rad_image img;
    if (fixture_make(&fx, cube_text, zero_field))
        return;
    rad_render_options o = options(v3(0.5, 0.5, -1), v3(0.5, 0.5, -1), 45, 10, 10,
                                   RAD_SHADING_FLAT);
    tap_ok(rad_render(&fx.model, &o, &img, &err) == RAD_ERR_INVALID, "eye = at refused: %s",
           err.message);
    o = options(v3(0.5, 0.5, -1), v3(0.5, 0.5, 1), 180, 10, 10, RAD_SHADING_FLAT);
    tap_ok(rad_render(&fx.model, &o, &img, &err) == RAD_ERR_INVALID, "fov 180 refused: %s",
           err.message);
    o = options(v3(0.5, 0.5, -1), v3(0.5, 2.5, -1), 45, 10, 10, RAD_SHADING_FLAT);
    tap_ok(rad_render(&fx.model, &o, &img, &err) == RAD_ERR_INVALID,
           "up parallel to the view refused: %s", err.message);
    o = options(v3(0.5, 0.5, -1), v3(0.5, 0.5, 1), 45, 0, 10, RAD_SHADING_FLAT);
    tap_ok(rad_render(&fx.model, &o, &img, &err) == RAD_ERR_INVALID, "width 0 refused: %s",
           err.message);
    o = options(v3(0.5, 0.5, -1), v3(0.5, 0.5, 1), 45, 10, 10, RAD_SHADING_FLAT);
    o.znear = -1;
    tap_ok(rad_render(&fx.model, &o, &img, &err) == RAD_ERR_INVALID,
           "a near plane behind the eye refused: %s", err.message);
    o.znear = NAN;
    tap_ok(rad_render(&fx.model, &o, &img, &err) == RAD_ERR_INVALID,
           "a NaN near plane refused: %s", err.message);
    fixture_free(&fx);
}

/* ---- PLY ------------------------------------------------------------------ */

static const char good_ply[] =
    "ply\n"
    "format ascii 1.0\n"
    "comment radiosity 0.1 solution\n"
    "comment scene t.scene\n"
    "comment camera eye 0.5 0.5 -2 at 0.5 0.5 0 up 0 1 0 fov 40\n"
    "element vertex 5\n"
    "property double x\nproperty double y\nproperty double z\n"
    "property double radiosity_r\nproperty double radiosity_g\nproperty double radiosity_b\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "property int surface\n"
    "property double radiosity_r\nproperty double radiosity_g\nproperty double radiosity_b\n"
    "end_header\n"
    "0 0 0 0.1 0.2 0.3 1 2 3\n"
    "0 1 0 0.1 0.2 0.3 1 2 3\n"
    "1 1 0 0.4 0.5 0.6 1 2 3\n"
    "1 0 0 0.4 0.5 0.6 1 2 3\n"
    "2 0.5 0 0.7 0.8 0.9 1 2 3\n"
    "4 0 1 2 3 0 0.25 0.35 0.45\n"
    "3 3 2 4 1 0.5 0.6 0.7\n";

static void test_ply_good(void)
{
    rad_render_model m;
    rad_camera cam;
    rad_error err;
    rad_status st = rad_ply_parse(&m, &cam, good_ply, strlen(good_ply), "t.ply", &err);
    tap_ok(st == RAD_OK, "PLY: the solution format parses%s%s", st ? ": " : "",
           st ? err.message : "");
    if (st)
        return;
    tap_ok(m.nvertices == 5 && m.nfaces == 2 && m.face_first[1] == 4 && m.face_first[2] == 7 &&
               m.face_index[6] == 4,
           "PLY: 5 vertices, faces of 4 and 3");
    tap_ok(m.pos[4].x == 2 && m.pos[4].y == 0.5 && m.vrad[4] == 0.7 && m.vrad[4 + 10] == 0.9,
           "PLY: vertex position and radiosity (not the 8-bit colour)");
    tap_ok(m.frad[1] == 0.5 && m.frad[1 + 4] == 0.7 && m.face_surface[0] == 0 &&
               m.face_surface[1] == 1,
           "PLY: face radiosity and surface");
    tap_ok(cam.defined && cam.eye.z == -2 && cam.at.x == 0.5 && cam.fov == 40,
           "PLY: the camera comment");
    rad_render_model_free(&m);

    /* properties in another order, an unknown property, colours only on
     * vertices, an extra element, CRLF line ends */
    const char *other =
        "ply\r\nformat ascii 1.0\r\n"
        "element vertex 3\r\n"
        "property uchar blue\r\nproperty float z\r\nproperty float nx\r\nproperty uchar green\r\n"
        "property float y\r\nproperty uchar red\r\nproperty float x\r\n"
        "element face 1\r\n"
        "property int flags\r\nproperty list int int vertex_index\r\n"
        "element edge 1\r\nproperty int a\r\nproperty int b\r\n"
        "end_header\r\n"
        "255 0 0 0 0 255 0\r\n"
        "0 0 0 255 0 0 1\r\n"
        "0 0 0 0 1 0 0\r\n"
        "7 3 0 1 2\r\n"
        "0 1\r\n";
    st = rad_ply_parse(&m, &cam, other, strlen(other), "o.ply", &err);
    tap_ok(st == RAD_OK, "PLY: any property order, unknown properties and elements, CRLF%s%s",
           st ? ": " : "", st ? err.message : "");
    if (st == RAD_OK) {
        tap_ok(m.pos[1].x == 1 && m.vrad[0 + 2 * 3] == 1 && m.vrad[1 + 1 * 3] == 1 &&
                   fabs(m.frad[0] - 1.0 / 3) < 1e-15 && !cam.defined,
               "PLY: colours decoded, face radiosity the mean of its vertices, no camera");
        rad_render_model_free(&m);
    }
}

typedef struct bad_case {
    const char *what, *text;
    int line;
    const char *reason;
} bad_case;

#define HDR "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n" \
            "property double z\nproperty double radiosity_r\nproperty double radiosity_g\n"  \
            "property double radiosity_b\nelement face 1\nproperty list uchar int vertex_indices\n" \
            "end_header\n"
#define V3 "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n"

static void test_ply_bad(void)
{
    static const bad_case cases[] = {
        {"empty file", "", 1, "not a PLY"},
        {"not PLY", "solid x\n", 1, "not a PLY"},
        {"binary", "ply\nformat binary_little_endian 1.0\n", 2, "not supported"},
        {"no end_header", "ply\nformat ascii 1.0\nelement vertex 3\n", 3, "end_header"},
        {"bad keyword", "ply\nformat ascii 1.0\nelemnt vertex 3\n", 3, "unknown header keyword"},
        {"bad type", "ply\nformat ascii 1.0\nelement vertex 3\nproperty real x\n", 4,
         "unknown property type"},
        {"property first", "ply\nformat ascii 1.0\nproperty double x\n", 3, "before any element"},
        {"negative count", "ply\nformat ascii 1.0\nelement vertex -3\n", 3, "element count"},
        {"no x", "ply\nformat ascii 1.0\nelement vertex 1\nproperty double y\nelement face 1\n"
                 "property list uchar int vertex_indices\nend_header\n", 3, "x, y and z"},
        {"no faces", "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
                     "property double z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                     "end_header\n0 0 0 1 1 1\n", 10, "no face element"},
        {"huge count", "ply\nformat ascii 1.0\nelement vertex 400000000\nproperty double x\n"
                       "property double y\nproperty double z\nproperty double radiosity_r\n"
                       "property double radiosity_g\nproperty double radiosity_b\nelement face 1\n"
                       "property list uchar int vertex_indices\nend_header\n0 0 0 1 1 1\n",
         3, "more than the rest of the file"},
        {"truncated", HDR "0 0 0 1 1 1\n1 0 0 1 1 1\n", 14, "unexpected end of file"},
        {"not a number", HDR "0 0 0 1 1 1\n1 zero 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n", 14,
         "not a number"},
        {"nan", HDR "0 0 0 1 1 1\n1 nan 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n", 14, "finite"},
        {"missing value", HDR "0 0 0 1 1 1\n1 0 0 1 1\n0 1 0 1 1 1\n3 0 1 2\n", 14,
         "missing value"},
        {"extra value", HDR "0 0 0 1 1 1 9\n1 0 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n", 13,
         "unexpected '9'"},
        {"index range", HDR V3 "3 0 1 3\n", 16, "refers to vertex 3"},
        {"fractional index", HDR V3 "3 0 1 1.5\n", 16, "whole number"},
        {"uchar range", HDR V3 "300 0 1 2\n", 16, "whole number from 0 to 255"},
        {"two vertices", HDR V3 "2 0 1\n", 16, "a face needs 3"},
        {"short list", HDR V3 "4 0 1 2\n", 16, "lists 4 vertices"},
        {"degenerate face", HDR "0 0 0 1 1 1\n1 0 0 1 1 1\n2 0 0 1 1 1\n" "3 0 1 2\n", 16,
         "zero area"},
        {"trailing data", HDR V3 "3 0 1 2\n3 0 1 2\n", 17, "after the last element"},
        {"bad camera", "ply\nformat ascii 1.0\ncomment camera eye 0 0 0 at 0 0 0 up 0 1 0 fov 40\n",
         3, "eye and at must differ"},
        {"short camera", "ply\nformat ascii 1.0\ncomment camera eye 0 0 0\n", 3, "camera comment"},
        {"NUL byte", "ply\nformat ascii 1.0\ncomment a\0b\n", 3, "NUL"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const bad_case *c = &cases[k];
        size_t len = strlen(c->text);
        if (strcmp(c->what, "NUL byte") == 0)
            len = sizeof "ply\nformat ascii 1.0\ncomment a\0b\n" - 1;
        rad_render_model m;
        rad_camera cam;
        rad_error err;
        char want[64];
        memset(&err, 0, sizeof err);
        rad_status st = rad_ply_parse(&m, &cam, c->text, len, "t.ply", &err);
        snprintf(want, sizeof want, "t.ply:%d: ", c->line);
        tap_ok(st == RAD_ERR_PARSE && strncmp(err.message, want, strlen(want)) == 0 &&
                   strstr(err.message, c->reason) && m.nfaces == 0 && m.pos == NULL,
               "PLY %s: '%s'", c->what, err.message);
    }
}

/* Every prefix and a few thousand byte mutations of a good file: the parser
 * returns, and a failure names the file and a line. */
static void test_ply_mangled(void)
{
    const size_t len = strlen(good_ply);
    char *buf = malloc(len + 1);
    unsigned long seed = 12345;
    int bad = 0, ok = 0;
    static const char alphabet[] = " \n0123456789.-+eEx#plyfacevrtn\t";
    for (size_t cut = 0; cut <= len + 3000; cut++) {
        size_t n = cut <= len ? cut : len;
        memcpy(buf, good_ply, len);
        if (cut > len) { /* mutate 1-3 bytes */
            for (int j = 0; j < 1 + (int)(cut % 3); j++) {
                seed = seed * 6364136223846793005UL + 1442695040888963407UL;
                size_t at = (seed >> 33) % len;
                buf[at] = alphabet[(seed >> 20) % (sizeof alphabet - 1)];
            }
        }
        rad_render_model m;
        rad_camera cam;
        rad_error err;
        rad_status st = rad_ply_parse(&m, &cam, buf, n, "m.ply", &err);
        if (st == RAD_OK) {
            ok++;
            rad_render_model_free(&m);
        } else if (strncmp(err.message, "m.ply:", 6) != 0 || m.pos != NULL) {
            bad++;
            tap_diag("bad failure: %s", err.message);
        }
    }
    tap_ok(bad == 0, "PLY: %zu prefixes and 3000 mutations never crash; every failure says "
                     "FILE:LINE (%d parsed)", len + 1, ok);
    free(buf);
}

int main(void)
{
    test_tone();
    test_square_coverage();
    test_zbuffer();
    test_inside();
    test_centres();
    test_linear();
    test_edges_exposure();
    test_exposure_cornell();
    test_errcolour();
    test_determinism();
    test_bad_options();
    test_ply_good();
    test_ply_bad();
    test_ply_mangled();
    return tap_done();
}
