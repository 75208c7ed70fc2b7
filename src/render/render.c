/* render.c -- camera, software z-buffer rasteriser and tone mapping.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Each face goes through five steps (the z-buffer: Catmull 1974; the
 * pipeline as in Foley, van Dam, Feiner & Hughes, "Computer Graphics",
 * 2nd ed. 1990, chapters 6 and 15):
 *
 *   1. back-face culling: the face's Newell normal (from its vertex order,
 *      counter-clockwise = front) must point towards the eye; surfaces are
 *      one-sided, so a camera looks into a box through its front wall;
 *   2. camera space (x right, y up, z forward, the eye at the origin) and
 *      clipping to the near plane z >= znear (Sutherland & Hodgman 1974),
 *      so a camera inside the scene draws the walls that pass behind it;
 *   3. perspective projection x_s = cx + f x/z, y_s = cy - f y/z with
 *      f = (height/2) / tan(fov/2), (cx, cy) the image centre;
 *   4. scan conversion of the convex projected polygon row by row: the
 *      pixel centres between the leftmost and the rightmost edge crossing
 *      of the row, both ends included.  Every edge, and every near-plane
 *      intersection, is computed from its two endpoints taken in one
 *      canonical order, so two faces sharing an edge get bit-identical
 *      crossings and no pixel centre falls between them;
 *   5. per pixel, the ray through the pixel centre meets the face's plane
 *      at depth t.  Intersecting exactly makes depth and shading
 *      perspective-correct: it is the rational-linear interpolation of
 *      Heckbert & Moreton, "Interpolation for Polygon Texture Mapping and
 *      Shading", 1991, in closed form.  The z-buffer keeps the nearest face;
 *      only a strictly nearer face replaces a pixel, so ties keep the face
 *      drawn first (faces are drawn in model order: deterministic).
 *
 * Shading: flat is the element radiosity.  Smooth interpolates the vertex
 * radiosity at the surface point (Gouraud, "Continuous Shading of Curved
 * Surfaces", IEEE Trans. Computers C-20(6), 1971): bilinearly in a quad
 * element's own (u, v), found by inverting
 *     P(u,v) = (1-u)(1-v) P0 + u(1-v) P1 + uv P2 + (1-u)v P3
 * in the face's plane (a quadratic in v, solved in the cancellation-free
 * form of Press et al., Numerical Recipes, 2nd ed., section 5.6); for other
 * polygons barycentrically over the fan of triangles from vertex 0.  A
 * linear field is reproduced exactly by both.
 *
 * Element edges (the `edges` option) are the pixels whose centre lies within
 * EDGE_HALF_WIDTH pixels of an edge of the face drawn there.  The screen
 * line of an edge is the trace of the plane through the eye and the edge,
 * m = a x b in camera space, so it needs no clipping.
 *
 * Tone mapping: radiosity is linear; it is multiplied by the exposure
 * (given, or automatic: exposure.c), clamped to [0, 1], encoded with the sRGB transfer curve (IEC 61966-2-1:1999)
 * and rounded to 8 bits.
 */
#include <config.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>

#include "render/plot.h"
#include "util/util.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/render.h"

#define ZNEAR_REL 1e-6          /* near plane, relative to the scene's size */
#define EDGE_HALF_WIDTH 0.55    /* pixels: lines about one pixel wide */

/* ---- tone mapping ------------------------------------------------------- */

double rad_srgb_encode(double c)
{
    /* IEC 61966-2-1:1999, eq. (5.2): linear segment below 0.0031308 */
    if (!(c > 0))
        return 0;
    if (c >= 1)
        return 1;
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

double rad_srgb_decode(double c)
{
    /* IEC 61966-2-1:1999, eq. (5.1), the inverse of the above */
    if (!(c > 0))
        return 0;
    if (c >= 1)
        return 1;
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

unsigned char rad_tone_byte(double radiosity, double exposure)
{
    double s = rad_srgb_encode(radiosity * exposure);
    return (unsigned char)floor(255.0 * s + 0.5);
}

/* ---- the model ---------------------------------------------------------- */

void rad_render_model_free(rad_render_model *m)
{
    if (!m)
        return;
    free(m->pos);
    free(m->vrad);
    free(m->face_first);
    free(m->face_index);
    free(m->frad);
    free(m->face_surface);
    free(m->face_gi);
    free(m->face_gj);
    free(m->face_emits);
    memset(m, 0, sizeof *m);
}

rad_status rad_render_model_from_mesh(rad_render_model *m, const rad_mesh *mesh,
                                      const double *B, const double *Bv, rad_error *err)
{
    const size_t nv = (size_t)mesh->nvertices, nf = (size_t)mesh->nelements;
    size_t ni = 0;
    memset(m, 0, sizeof *m);
    for (size_t e = 0; e < nf; e++)
        ni += (size_t)mesh->elements[e].nverts;
    m->pos = malloc(sizeof *m->pos * (nv ? nv : 1));
    m->vrad = Bv ? malloc(sizeof *m->vrad * RAD_BANDS * (nv ? nv : 1)) : NULL;
    m->face_first = malloc(sizeof *m->face_first * (nf + 1));
    m->face_index = malloc(sizeof *m->face_index * (ni ? ni : 1));
    m->frad = malloc(sizeof *m->frad * RAD_BANDS * (nf ? nf : 1));
    m->face_surface = malloc(sizeof(int) * (nf ? nf : 1));
    m->face_gi = malloc(sizeof(int) * (nf ? nf : 1));
    m->face_gj = malloc(sizeof(int) * (nf ? nf : 1));
    m->face_emits = malloc(nf ? nf : 1);
    if (!m->pos || (Bv && !m->vrad) || !m->face_first || !m->face_index || !m->frad ||
        !m->face_surface || !m->face_gi || !m->face_gj || !m->face_emits) {
        rad_render_model_free(m);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a picture of %zu elements", nf);
    }
    m->nvertices = (int)nv;
    m->nfaces = (int)nf;
    if (nv)
        memcpy(m->pos, mesh->vertices, sizeof *m->pos * nv);
    if (Bv && nv)
        memcpy(m->vrad, Bv, sizeof *m->vrad * RAD_BANDS * nv);
    if (nf)
        memcpy(m->frad, B, sizeof *m->frad * RAD_BANDS * nf);
    int k = 0;
    for (size_t e = 0; e < nf; e++) {
        const rad_element *el = &mesh->elements[e];
        m->face_first[e] = k;
        for (int j = 0; j < el->nverts; j++)
            m->face_index[k++] = mesh->vindex[el->first + j];
        m->face_surface[e] = el->surface;
        m->face_gi[e] = el->gi;
        m->face_gj[e] = el->gj;
        m->face_emits[e] = el->emit[0] > 0 || el->emit[1] > 0 || el->emit[2] > 0;
    }
    m->face_first[nf] = k;
    return RAD_OK;
}

double rad_render_max_radiosity(const rad_render_model *m)
{
    double mx = 0;
    for (size_t k = 0; k < (size_t)m->nfaces * RAD_BANDS; k++)
        if (m->frad[k] > mx)
            mx = m->frad[k];
    return mx;
}

/* ---- the camera ----------------------------------------------------------- */

static int v3_finite(rad_vec3 a)
{
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

rad_status rad_camera_check(const rad_camera *c, rad_error *err)
{
    if (!c->defined)
        return radi_fail(err, RAD_ERR_INVALID, "no camera");
    if (!v3_finite(c->eye) || !v3_finite(c->at) || !v3_finite(c->up))
        return radi_fail(err, RAD_ERR_INVALID, "camera eye, at and up must be finite");
    if (!(c->fov > 0 && c->fov < 180))
        return radi_fail(err, RAD_ERR_INVALID,
                        "camera fov must be between 0 and 180 degrees, not %g", c->fov);
    rad_vec3 view = v3_sub(c->at, c->eye);
    if (!(v3_norm(view) > 0))
        return radi_fail(err, RAD_ERR_INVALID, "camera eye and at must differ");
    rad_vec3 side = v3_cross(view, c->up);
    if (!(v3_norm(side) > 1e-12 * v3_norm(view) * v3_norm(c->up)))
        return radi_fail(err, RAD_ERR_INVALID,
                        "camera up must not be zero or parallel to the view direction");
    return RAD_OK;
}

/* Camera frame and projection of one render. */
typedef struct view {
    rad_vec3 eye, right, up, fwd;
    double f, cx, cy;           /* focal length and image centre, pixels */
    double znear;
    int width, height;
} view;

static rad_vec3 v3_unit(rad_vec3 a)
{
    return v3_scale(a, 1.0 / v3_norm(a));
}

static view make_view(const rad_render_options *opt, const rad_render_model *m)
{
    view v;
    const rad_camera *c = &opt->camera;
    v.eye = c->eye;
    v.fwd = v3_unit(v3_sub(c->at, c->eye));
    v.right = v3_unit(v3_cross(v.fwd, c->up));
    v.up = v3_cross(v.right, v.fwd);
    v.width = opt->width;
    v.height = opt->height;
    v.cx = 0.5 * opt->width;
    v.cy = 0.5 * opt->height;
    v.f = 0.5 * opt->height / tan(0.5 * c->fov * RAD_PI / 180.0);
    /* the near plane scales with the scene: its size plus the eye's distance */
    double size = 0;
    if (m->nvertices > 0) {
        rad_vec3 lo = m->pos[0], hi = m->pos[0];
        for (int k = 1; k < m->nvertices; k++) {
            rad_vec3 p = m->pos[k];
            lo = v3(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
            hi = v3(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
        }
        size = v3_norm(v3_sub(hi, lo)) +
               v3_norm(v3_sub(v3_scale(v3_add(lo, hi), 0.5), v.eye));
    }
    v.znear = opt->znear > 0 ? opt->znear : ZNEAR_REL * (size > 0 && isfinite(size) ? size : 1.0);
    return v;
}

static rad_vec3 to_camera(const view *v, rad_vec3 p)
{
    rad_vec3 d = v3_sub(p, v->eye);
    return v3(v3_dot(d, v->right), v3_dot(d, v->up), v3_dot(d, v->fwd));
}

/* The ray through the image point (px, py), in world axes, scaled so that
 * its component along the view direction is 1 (t along it is depth). */
static rad_vec3 pixel_ray(const view *v, double px, double py)
{
    return v3_add(v->fwd, v3_add(v3_scale(v->right, (px - v->cx) / v->f),
                                 v3_scale(v->up, (v->cy - py) / v->f)));
}

/* ---- one face ----------------------------------------------------------- */

/* Scratch space for one face, sized for the largest face of the model. */
typedef struct face_work {
    rad_vec3 *rel;              /* n vertices relative to the eye, world axes */
    rad_vec3 *cam;              /* n vertices in camera space */
    rad_vec3 *clip;             /* after near clipping: n + 1 for a convex
                                   polygon, never more than 2 n */
    double *dz;                 /* n: distances from the near plane */
    double *sx, *sy;            /* the clipped polygon on the screen */
    double *q;                  /* 2 n: vertices in the face's plane frame */
    double *val;                /* 3 n: vertex radiosity, vertex-major */
    double *lines;              /* 3 n: edge lines a x + b y + c, |(a,b)| = 1 */
} face_work;

/* What shading needs about the face being drawn. */
typedef struct face_geom {
    int n;                      /* vertices */
    int nclip;                  /* vertices after clipping */
    int nlines;                 /* edge lines for the edge overlay */
    rad_vec3 normal;            /* unnormalised; world axes */
    double plane;               /* normal . X = plane on the face, X = p - eye */
    rad_vec3 origin, a1, a2;    /* plane frame: rel[0], two unit axes */
    double flat[RAD_BANDS];
    int smooth;
} face_geom;

static void face_work_free(face_work *w)
{
    free(w->rel);
    free(w->cam);
    free(w->clip);
    free(w->dz);
    free(w->sx);
    free(w->sy);
    free(w->q);
    free(w->val);
    free(w->lines);
}

static int face_work_alloc(face_work *w, int maxn)
{
    size_t n = (size_t)maxn;
    memset(w, 0, sizeof *w);
    w->rel = malloc(sizeof *w->rel * n);
    w->cam = malloc(sizeof *w->cam * n);
    w->clip = malloc(sizeof *w->clip * 2 * n);
    w->dz = malloc(sizeof *w->dz * n);
    w->sx = malloc(sizeof *w->sx * 2 * n);
    w->sy = malloc(sizeof *w->sy * 2 * n);
    w->q = malloc(sizeof *w->q * 2 * n);
    w->val = malloc(sizeof *w->val * RAD_BANDS * n);
    w->lines = malloc(sizeof *w->lines * 3 * n);
    if (!w->rel || !w->cam || !w->clip || !w->dz || !w->sx || !w->sy || !w->q || !w->val || !w->lines) {
        face_work_free(w);
        return -1;
    }
    return 0;
}

/* Lexicographic order of two points, so shared edges are computed alike. */
static int v3_before(rad_vec3 a, rad_vec3 b)
{
    if (a.x != b.x)
        return a.x < b.x;
    if (a.y != b.y)
        return a.y < b.y;
    return a.z < b.z;
}

/* Where segment ab crosses z = zn (a poly_crossing, ctx -> zn), from the
 * endpoints in canonical order, so that an edge two faces share is cut
 * at one point; the distances are not needed. */
static rad_vec3 near_crossing(rad_vec3 a, rad_vec3 b, double da, double db, const void *ctx)
{
    const double zn = *(const double *)ctx;
    (void)da;
    (void)db;
    if (v3_before(b, a)) {
        rad_vec3 t = a;
        a = b;
        b = t;
    }
    rad_vec3 p = v3_lerp(a, b, (zn - a.z) / (b.z - a.z));
    p.z = zn;
    return p;
}

/* Sutherland-Hodgman against the half-space z >= zn (polygon.h); d has
 * room for n distances, out for 2 n vertices.  Nothing is snapped: a
 * vertex exactly on the plane is kept and an edge from it to the far
 * side cut there too (POLY_TOUCH_CUTS), as this clipper always did.
 * Returns the count. */
static int clip_near(const rad_vec3 *in, int n, double zn, double *d, rad_vec3 *out)
{
    const poly_cut cut = {1.0, POLY_TOUCH_CUTS, near_crossing, &zn};
    for (int k = 0; k < n; k++)
        d[k] = in[k].z - zn; /* >= 0 exactly when z >= zn (finite values) */
    return poly_clip(in, d, n, &cut, out, 2 * n);
}

/* Camera-space vertices, culling and clipping.  0: draw, 1: skip. */
static int face_setup(const rad_render_model *m, int f, const view *v, int shading,
                      int edges, face_work *w, face_geom *g)
{
    const int first = m->face_first[f], n = m->face_first[f + 1] - first;
    g->n = n;
    if (n < 3)
        return 1;
    rad_vec3 mean = v3(0, 0, 0);
    for (int k = 0; k < n; k++) {
        const rad_vec3 p = m->pos[m->face_index[first + k]];
        w->rel[k] = v3_sub(p, v->eye);
        w->cam[k] = to_camera(v, p);
        mean = v3_add(mean, w->rel[k]);
    }
    mean = v3_scale(mean, 1.0 / n);
    /* the normal in world axes: the camera frame (right, up, forward) is
     * left-handed, where cross products would turn it round */
    g->normal = v3_newell(w->rel, n);
    double nn = v3_norm(g->normal);
    g->plane = v3_dot(g->normal, mean);
    /* front faces have the eye (the origin) on their normal's side */
    if (!(nn > 0) || !(g->plane < -1e-13 * nn * v3_norm(mean)))
        return 1;
    g->nclip = clip_near(w->cam, n, v->znear, w->dz, w->clip);
    if (g->nclip < 3)
        return 1;
    for (int k = 0; k < g->nclip; k++) {
        w->sx[k] = v->cx + v->f * w->clip[k].x / w->clip[k].z;
        w->sy[k] = v->cy - v->f * w->clip[k].y / w->clip[k].z;
    }
    g->smooth = shading == RAD_SHADING_SMOOTH && m->vrad != NULL;
    for (int b = 0; b < RAD_BANDS; b++)
        g->flat[b] = m->frad[f + (size_t)b * m->nfaces];
    if (g->smooth) {
        rad_vec3 nh = v3_scale(g->normal, 1.0 / nn);
        g->origin = w->rel[0];
        g->a1 = v3_unit(v3_sub(w->rel[1], w->rel[0]));
        g->a2 = v3_cross(nh, g->a1); /* (a1, a2, n) right-handed: the face
                                        stays counter-clockwise in the frame */
        for (int k = 0; k < n; k++) {
            rad_vec3 d = v3_sub(w->rel[k], g->origin);
            int vi = m->face_index[first + k];
            w->q[2 * k] = v3_dot(d, g->a1);
            w->q[2 * k + 1] = v3_dot(d, g->a2);
            for (int b = 0; b < RAD_BANDS; b++)
                w->val[RAD_BANDS * k + b] = m->vrad[vi + (size_t)b * m->nvertices];
        }
    }
    g->nlines = 0;
    if (edges)
        for (int k = 0; k < n; k++) {
            rad_vec3 a = w->cam[k], b = w->cam[(k + 1) % n];
            if (a.z < v->znear && b.z < v->znear)
                continue; /* wholly behind the eye: not on the visible boundary */
            rad_vec3 mm = v3_cross(a, b); /* its sign does not matter */
            double la = mm.x / v->f, lb = -mm.y / v->f;
            double lc = mm.z - mm.x * v->cx / v->f + mm.y * v->cy / v->f;
            double len = hypot(la, lb);
            if (!(len > 0) || !isfinite(len))
                continue;
            w->lines[3 * g->nlines] = la / len;
            w->lines[3 * g->nlines + 1] = lb / len;
            w->lines[3 * g->nlines + 2] = lc / len;
            g->nlines++;
        }
    return 0;
}

static double cross2(double ax, double ay, double bx, double by)
{
    return ax * by - ay * bx;
}

/* How far r lies outside [0, 1]. */
static double outside01(double r)
{
    return r < 0 ? -r : r > 1 ? r - 1 : 0;
}

static double clamp01(double r)
{
    return r < 0 ? 0 : r > 1 ? 1 : r;
}

/* (u, v) of the point (px, py) in the bilinear quad q[0..7]. */
static void inverse_bilinear(const double *q, double px, double py, double *u, double *v)
{
    const double ex = q[2] - q[0], ey = q[3] - q[1];                 /* P1 - P0 */
    const double fx = q[6] - q[0], fy = q[7] - q[1];                 /* P3 - P0 */
    const double gx = q[0] - q[2] + q[4] - q[6], gy = q[1] - q[3] + q[5] - q[7];
    const double hx = px - q[0], hy = py - q[1];
    /* h = u e + v f + uv g; crossing with (e + v g) eliminates u:
     * k2 v^2 + k1 v + k0 = 0 */
    const double k2 = cross2(gx, gy, fx, fy);
    const double k1 = cross2(ex, ey, fx, fy) + cross2(hx, hy, gx, gy);
    const double k0 = cross2(hx, hy, ex, ey);
    double vv;
    if (k2 == 0) {
        vv = k1 != 0 ? -k0 / k1 : 0;
    } else {
        double disc = k1 * k1 - 4 * k0 * k2;
        double s = sqrt(disc > 0 ? disc : 0);
        double qq = -0.5 * (k1 + copysign(s, k1));
        double r1 = qq / k2, r2 = qq != 0 ? k0 / qq : r1;
        vv = outside01(r2) <= outside01(r1) ? r2 : r1;
    }
    vv = clamp01(vv);
    const double dx = ex + vv * gx, dy = ey + vv * gy;
    const double nx = hx - vv * fx, ny = hy - vv * fy;
    const double dd = dx * dx + dy * dy;
    *u = clamp01(dd > 0 ? (nx * dx + ny * dy) / dd : 0);
    *v = vv;
}

/* Barycentric weights of (px, py) in the fan triangle (0, i, i+1) holding it. */
static int fan_weights(const double *q, int n, double px, double py, double w[3])
{
    const double x0 = q[0], y0 = q[1];
    int lo = 1, hi = n - 2;
    while (lo < hi) { /* the last fan edge 0->i with the point on its left */
        int mid = (lo + hi + 1) / 2;
        if (cross2(q[2 * mid] - x0, q[2 * mid + 1] - y0, px - x0, py - y0) >= 0)
            lo = mid;
        else
            hi = mid - 1;
    }
    const int i = lo;
    const double ax = q[2 * i] - x0, ay = q[2 * i + 1] - y0;
    const double bx = q[2 * i + 2] - x0, by = q[2 * i + 3] - y0;
    const double d = cross2(ax, ay, bx, by);
    double wi = d != 0 ? cross2(px - x0, py - y0, bx, by) / d : 0;
    double wj = d != 0 ? cross2(ax, ay, px - x0, py - y0) / d : 0;
    double w0 = 1 - wi - wj;
    wi = wi > 0 ? wi : 0;
    wj = wj > 0 ? wj : 0;
    w0 = w0 > 0 ? w0 : 0;
    double s = w0 + wi + wj;
    if (!(s > 0)) {
        w0 = 1;
        s = 1;
    }
    w[0] = w0 / s;
    w[1] = wi / s;
    w[2] = wj / s;
    return i;
}

/* The radiosity of the face at the point p (relative to the eye). */
static void shade(const face_geom *g, const face_work *w, rad_vec3 p, double out[RAD_BANDS])
{
    if (!g->smooth) {
        for (int b = 0; b < RAD_BANDS; b++)
            out[b] = g->flat[b];
        return;
    }
    rad_vec3 d = v3_sub(p, g->origin);
    const double px = v3_dot(d, g->a1), py = v3_dot(d, g->a2);
    const double *val = w->val;
    if (g->n == 4) {
        double u, v;
        inverse_bilinear(w->q, px, py, &u, &v);
        const double c0 = (1 - u) * (1 - v), c1 = u * (1 - v), c2 = u * v, c3 = (1 - u) * v;
        for (int b = 0; b < RAD_BANDS; b++)
            out[b] = c0 * val[b] + c1 * val[3 + b] + c2 * val[6 + b] + c3 * val[9 + b];
        return;
    }
    double wt[3];
    const int i = fan_weights(w->q, g->n, px, py, wt);
    for (int b = 0; b < RAD_BANDS; b++)
        out[b] = wt[0] * val[b] + wt[1] * val[RAD_BANDS * i + b] +
                 wt[2] * val[RAD_BANDS * (i + 1) + b];
}

/* Is the pixel centre within the edge half-width of an edge of the face? */
static int near_edge(const face_geom *g, const face_work *w, double px, double py)
{
    for (int k = 0; k < g->nlines; k++) {
        const double *l = w->lines + 3 * k;
        if (fabs(l[0] * px + l[1] * py + l[2]) < EDGE_HALF_WIDTH)
            return 1;
    }
    return 0;
}

/* Clamp a screen coordinate range to pixel indices [0, n-1]; empty if lo > hi. */
static void pixel_range(double lo, double hi, int n, int *a, int *b)
{
    /* pixel i is covered when lo <= i + 0.5 <= hi */
    double l = ceil(lo - 0.5), h = floor(hi - 0.5);
    *a = l < 0 ? 0 : l > n ? n : (int)l;
    *b = h > n - 1 ? n - 1 : h < -1 ? -1 : (int)h;
}

/* The x extent of the convex screen polygon on the line y = yc.  Each edge
 * is evaluated with its endpoints ordered by (y, x), so neighbours that
 * share it find the same crossing.  0 if the line misses the polygon. */
static int row_span(const double *sx, const double *sy, int n, double yc, double *xl,
                    double *xr)
{
    int hit = 0;
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < n; k++) {
        int a = k, b = (k + 1) % n;
        if (sy[b] < sy[a] || (sy[b] == sy[a] && sx[b] < sx[a])) {
            a = b;
            b = k;
        }
        if (yc < sy[a] || yc > sy[b])
            continue;
        double x0, x1;
        if (sy[a] == sy[b]) {
            x0 = sx[a];
            x1 = sx[b];
        } else {
            x0 = x1 = sx[a] + (yc - sy[a]) * (sx[b] - sx[a]) / (sy[b] - sy[a]);
        }
        lo = fmin(lo, x0);
        hi = fmax(hi, x1);
        hit = 1;
    }
    *xl = lo;
    *xr = hi;
    return hit;
}

/* Scan-convert face f into the image. */
static void draw_face(const view *v, int f, const face_geom *g, const face_work *w,
                      rad_image *img)
{
    double ylo = HUGE_VAL, yhi = -HUGE_VAL, xlo = HUGE_VAL, xhi = -HUGE_VAL;
    int y0, y1, xa, xb;
    for (int k = 0; k < g->nclip; k++) {
        ylo = fmin(ylo, w->sy[k]);
        yhi = fmax(yhi, w->sy[k]);
        xlo = fmin(xlo, w->sx[k]);
        xhi = fmax(xhi, w->sx[k]);
    }
    pixel_range(xlo, xhi, v->width, &xa, &xb);
    if (xa > xb) /* wholly left or right of the picture: no row would draw */
        return;
    pixel_range(ylo, yhi, v->height, &y0, &y1);
    for (int y = y0; y <= y1; y++) {
        const double yc = y + 0.5;
        double xl, xr;
        int x0, x1;
        if (!row_span(w->sx, w->sy, g->nclip, yc, &xl, &xr))
            continue;
        pixel_range(xl, xr, v->width, &x0, &x1);
        for (int x = x0; x <= x1; x++) {
            const double xc = x + 0.5;
            const size_t p = (size_t)y * (size_t)v->width + (size_t)x;
            rad_vec3 dir = pixel_ray(v, xc, yc);
            double t = g->plane / v3_dot(g->normal, dir);
            if (!(t > 0) || !isfinite(t) || !(t < img->depth[p]))
                continue;
            img->depth[p] = t;
            img->face[p] = f;
            shade(g, w, v3_scale(dir, t), img->rgb + 3 * p);
            if (img->edges)
                img->edge[p] = (unsigned char)near_edge(g, w, xc, yc);
        }
    }
}

/* ---- the picture -------------------------------------------------------- */

void rad_render_options_init(rad_render_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->width = 512;
    opt->height = 512;
    opt->shading = RAD_SHADING_SMOOTH;
    opt->edges = 0;
    opt->exposure = 0;
}

void rad_image_free(rad_image *img)
{
    if (!img)
        return;
    free(img->rgb);
    free(img->depth);
    free(img->face);
    free(img->edge);
    memset(img, 0, sizeof *img);
}

static rad_status image_alloc(rad_image *img, int width, int height, rad_error *err)
{
    const size_t np = (size_t)width * (size_t)height;
    memset(img, 0, sizeof *img);
    img->rgb = calloc(np * RAD_BANDS, sizeof *img->rgb);
    img->depth = malloc(sizeof *img->depth * np);
    img->face = malloc(sizeof *img->face * np);
    img->edge = calloc(np, 1);
    if (!img->rgb || !img->depth || !img->face || !img->edge) {
        rad_image_free(img);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a %d x %d picture", width,
                        height);
    }
    img->width = width;
    img->height = height;
    for (size_t p = 0; p < np; p++) {
        img->depth[p] = INFINITY;
        img->face[p] = -1;
    }
    return RAD_OK;
}

static rad_status check_options(const rad_render_model *m, const rad_render_options *opt,
                                rad_error *err)
{
    rad_status st = rad_camera_check(&opt->camera, err);
    if (st)
        return st;
    if (opt->width < 1 || opt->height < 1 || opt->width > RAD_RENDER_MAX_SIDE ||
        opt->height > RAD_RENDER_MAX_SIDE ||
        (double)opt->width * opt->height > RAD_RENDER_MAX_PIXELS)
        return radi_fail(err, RAD_ERR_INVALID,
                        "picture size %d x %d is outside 1 to %d per side and %d pixels",
                        opt->width, opt->height, RAD_RENDER_MAX_SIDE, RAD_RENDER_MAX_PIXELS);
    if (!(opt->exposure >= 0) || !isfinite(opt->exposure))
        return radi_fail(err, RAD_ERR_INVALID, "exposure must be positive, not %g",
                        opt->exposure);
    if (!(opt->znear >= 0) || !isfinite(opt->znear))
        return radi_fail(err, RAD_ERR_INVALID, "the near plane must be at 0 (automatic) or "
                        "beyond, not %g", opt->znear);
    if (opt->shading == RAD_SHADING_SMOOTH && !m->vrad)
        return radi_fail(err, RAD_ERR_INVALID,
                        "smooth shading needs vertex radiosity; the model has none");
    return RAD_OK;
}

/* The picture does not depend on the unit of length, so it is drawn in a
 * frame centred on the eye and scaled by a power of two (exact) until the
 * scene and the point looked at span about 1: a cube of side 1e150 then
 * draws as the unit cube does, where the plane offsets and the bilinear
 * inversion's discriminant (products of two or four coordinates) would
 * otherwise overflow.  *k receives the exponent: lengths in the frame are
 * the user's times 2^-k. */
static rad_status eye_frame(const rad_render_model *m, const rad_camera *c,
                            rad_render_model *fm, rad_camera *fc, int *k, rad_error *err)
{
    double big = 0;
    rad_vec3 at = v3_sub(c->at, c->eye);
    big = fmax(big, fmax(fabs(at.x), fmax(fabs(at.y), fabs(at.z))));
    for (int i = 0; i < m->nvertices; i++) {
        rad_vec3 d = v3_sub(m->pos[i], c->eye);
        big = fmax(big, fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z))));
    }
    if (!isfinite(big))
        return radi_fail(err, RAD_ERR_INVALID, "the scene and the camera lie farther apart "
                        "than a double can measure");
    frexp(big > 0 ? big : 1, k);
    *fm = *m;
    fm->pos = malloc(sizeof *fm->pos * (size_t)(m->nvertices ? m->nvertices : 1));
    if (!fm->pos)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    for (int i = 0; i < m->nvertices; i++) {
        rad_vec3 d = v3_sub(m->pos[i], c->eye);
        fm->pos[i] = v3(ldexp(d.x, -*k), ldexp(d.y, -*k), ldexp(d.z, -*k));
    }
    *fc = *c;
    fc->eye = v3(0, 0, 0);
    fc->at = v3(ldexp(at.x, -*k), ldexp(at.y, -*k), ldexp(at.z, -*k));
    return RAD_OK;
}

static rad_status render_frame(const rad_render_model *m, const rad_render_options *opt,
                               rad_image *img, rad_error *err);

rad_status rad_render(const rad_render_model *m, const rad_render_options *opt,
                      rad_image *img, rad_error *err)
{
    rad_render_model fm;
    rad_render_options fo = *opt;
    int k;
    memset(img, 0, sizeof *img);
    rad_status st = check_options(m, opt, err);
    if (st == RAD_OK)
        st = eye_frame(m, &opt->camera, &fm, &fo.camera, &k, err);
    if (st != RAD_OK)
        return st;
    st = render_frame(&fm, &fo, img, err);
    free(fm.pos);
    if (st == RAD_OK) /* depths back in the user's unit */
        for (size_t p = 0; p < (size_t)img->width * (size_t)img->height; p++)
            img->depth[p] = ldexp(img->depth[p], k);
    return st;
}

static rad_status render_frame(const rad_render_model *m, const rad_render_options *opt,
                               rad_image *img, rad_error *err)
{
    face_work w;
    rad_status st;
    int maxn = 3;
    for (int f = 0; f < m->nfaces; f++)
        if (m->face_first[f + 1] - m->face_first[f] > maxn)
            maxn = m->face_first[f + 1] - m->face_first[f];
    if (face_work_alloc(&w, maxn))
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if ((st = image_alloc(img, opt->width, opt->height, err))) {
        face_work_free(&w);
        return st;
    }
    img->exposure =
        opt->exposure > 0 ? opt->exposure : rad_render_auto_exposure(m, opt->exposure_from);
    img->edges = opt->edges != 0;
    const view v = make_view(opt, m);
    for (int f = 0; f < m->nfaces; f++) {
        face_geom g;
        memset(&g, 0, sizeof g);
        if (face_setup(m, f, &v, opt->shading, img->edges, &w, &g) == 0)
            draw_face(&v, f, &g, &w, img);
    }
    face_work_free(&w);
    return RAD_OK;
}

const double *rad_image_row(const rad_image *img, int y)
{
    if (!img || !img->rgb || y < 0 || y >= img->height)
        return NULL;
    return img->rgb + (size_t)3 * (size_t)img->width * (size_t)y;
}

void rad_image_to_rgb8(const rad_image *img, unsigned char *rgb)
{
    const size_t np = (size_t)img->width * (size_t)img->height;
    for (size_t p = 0; p < np; p++)
        for (int b = 0; b < RAD_BANDS; b++)
            rgb[3 * p + b] = img->edges && img->edge[p]
                                 ? 0
                                 : rad_tone_byte(img->rgb[3 * p + b], img->exposure);
}

rad_status rad_image_write_png(const rad_image *img, FILE *out, rad_error *err)
{
    const int w = img->width, h = img->height;
    const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_RGB24, w);
    if (stride <= 0)
        return radi_fail(err, RAD_ERR_INVALID, "a PNG cannot be %d pixels wide", w);
    unsigned char *data = calloc((size_t)stride * (size_t)h, 1);
    unsigned char *rgb = malloc((size_t)3 * (size_t)w * (size_t)h);
    if (!data || !rgb) {
        free(data);
        free(rgb);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a %d x %d PNG", w, h);
    }
    rad_image_to_rgb8(img, rgb);
    for (int y = 0; y < h; y++) {
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
        for (int x = 0; x < w; x++) {
            const unsigned char *c = rgb + 3 * ((size_t)y * (size_t)w + (size_t)x);
            /* CAIRO_FORMAT_RGB24: native-endian 0x00RRGGBB words */
            row[x] = (uint32_t)c[0] << 16 | (uint32_t)c[1] << 8 | (uint32_t)c[2];
        }
    }
    free(rgb);
    cairo_surface_t *s =
        cairo_image_surface_create_for_data(data, CAIRO_FORMAT_RGB24, w, h, stride);
    rad_status st;
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
        st = radi_fail(err, RAD_ERR_NOMEM, "PNG: %s",
                      cairo_status_to_string(cairo_surface_status(s)));
    else
        st = radi_png_write_surface(s, out, err);
    cairo_surface_destroy(s);
    free(data);
    return st;
}
