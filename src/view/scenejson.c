/* scenejson.c -- the scene and the state as the page reads them (JSON).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The scene is sent once, and again when a change moves it (geometry,
 * its version, as the state's): the mesh's vertices, each element's
 * vertex list (counter-clockwise from its front; 4: a quad element, drawn
 * as `radiosity render` draws it), its surface, whether it emits and is
 * present, the objects and their surfaces, the materials as they now are,
 * the camera (the scene's, or when it has
 * none one that frames the scene's box from +z, 30 degrees wide), the
 * picture size of `radiosity render` (512 x 512) and the exposure: the
 * automatic exposure of the converged solution (rad_mesh_auto_exposure,
 * from the reflectors), as `radiosity progress` gives its snapshots, so
 * that a picture brightens as it converges.  Coordinates and radiosity go
 * with 9 digits (float32's round trip: the page draws in float32); the
 * element radiosity of /api/elements with 17 (exact).
 */
#include <config.h>

#include <math.h>
#include <string.h>

#include "view/viewint.h"
#include "solve/solve.h"
#include "util/util.h"
#include "radiosity/render.h"

#define VIEW_WIDTH 512          /* `radiosity render`'s default picture */
#define VIEW_HEIGHT 512
#define VIEW_FOV 30.0           /* degrees, for a scene without a camera */

/* x, y, z as three comma-separated JSON numbers (exact: 17 digits). */
static void three(jbuf *b, double x, double y, double z, int exact)
{
    jb_num(b, x, exact);
    jb_printf(b, ",");
    jb_num(b, y, exact);
    jb_printf(b, ",");
    jb_num(b, z, exact);
}

static void vec(jbuf *b, rad_vec3 v)
{
    jb_printf(b, "[");
    three(b, v.x, v.y, v.z, 0);
    jb_printf(b, "]");
}

/* The scene's camera, or one at the box's centre + (0, 0, d) looking at
 * it, d such that the box's bounding sphere fills the vertical view. */
static rad_camera camera_of(const view_session *s)
{
    if (s->scene->camera.defined)
        return s->scene->camera;
    const rad_mesh *m = s->mesh;
    rad_vec3 lo = {0, 0, 0}, hi = {0, 0, 0};
    for (int k = 0; k < m->nvertices; k++) {
        const rad_vec3 p = m->vertices[k];
        lo = k ? v3(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z)) : p;
        hi = k ? v3(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z)) : p;
    }
    const rad_vec3 c = v3_scale(v3_add(lo, hi), 0.5);
    const double r = 0.5 * v3_norm(v3_sub(hi, lo));
    const double d = (r > 0 ? r : 1) / sin(0.5 * VIEW_FOV * RAD_PI / 180) * 1.05;
    rad_camera cam = {1, v3_add(c, v3(0, 0, d)), c, v3(0, 1, 0), VIEW_FOV};
    return cam;
}

/* Does element e emit: its surface's material in sc (a change may have
 * made a light of it, or put one out). */
static int emits(const rad_mesh *m, const rad_scene *sc, int e)
{
    const double *E = sc->materials[sc->surfaces[m->elements[e].surface].material].emit;
    return E[0] > 0 || E[1] > 0 || E[2] > 0;
}

static void elements_json(const rad_mesh *m, const rad_scene *sc, const unsigned char *present,
                          jbuf *b)
{
    jb_printf(b, "\"faces\":[");
    for (int e = 0; e < m->nelements; e++) {
        const rad_element *el = &m->elements[e];
        jb_printf(b, "%s[", e ? "," : "");
        for (int k = 0; k < el->nverts; k++)
            jb_printf(b, "%s%d", k ? "," : "", m->vindex[el->first + k]);
        jb_printf(b, "]");
    }
    jb_printf(b, "],\"surface\":[");
    for (int e = 0; e < m->nelements; e++)
        jb_printf(b, "%s%d", e ? "," : "", m->elements[e].surface);
    jb_printf(b, "],\"emits\":[");
    for (int e = 0; e < m->nelements; e++)
        jb_printf(b, "%s%d", e ? "," : "", emits(m, sc, e));
    jb_printf(b, "],\"present\":[");
    for (int e = 0; e < m->nelements; e++)
        jb_printf(b, "%s%d", e ? "," : "", present ? present[e] != 0 : 1);
    jb_printf(b, "]");
}

static void objects_json(const rad_scene *sc, jbuf *b)
{
    jb_printf(b, "\"objects\":[");
    for (int o = 0; o < sc->nobjects; o++) {
        jb_printf(b, "%s{\"name\":", o ? "," : "");
        jb_str(b, sc->objects[o].name);
        jb_printf(b, ",\"surfaces\":[");
        int first = 1;
        for (int k = 0; k < sc->nsurfaces; k++)
            if (sc->surfaces[k].object == o) {
                jb_printf(b, "%s%d", first ? "" : ",", k);
                first = 0;
            }
        jb_printf(b, "]}");
    }
    jb_printf(b, "]");
}

int view_scene_json(const view_session *s, const rad_mesh *m, const rad_scene *sc,
                    const unsigned char *present, jbuf *b)
{
    const rad_camera cam = camera_of(s);
    jb_printf(b, "{\"elements\":%d,\"vertices\":[", m->nelements);
    for (int k = 0; k < m->nvertices; k++) {
        const rad_vec3 p = m->vertices[k];
        jb_printf(b, "%s", k ? "," : "");
        three(b, p.x, p.y, p.z, 0);
    }
    jb_printf(b, "],");
    elements_json(m, sc, present, b);
    jb_printf(b, ",");
    objects_json(sc, b);
    jb_printf(b, ",\"camera\":{\"eye\":");
    vec(b, cam.eye);
    jb_printf(b, ",\"at\":");
    vec(b, cam.at);
    jb_printf(b, ",\"up\":");
    vec(b, cam.up);
    jb_printf(b, ",\"fov\":");
    jb_num(b, cam.fov, 0);
    jb_printf(b, "},\"width\":%d,\"height\":%d,\"exposure\":", VIEW_WIDTH, VIEW_HEIGHT);
    jb_num(b, s->exposure, 1);
    jb_printf(b, ",\"materials\":[");
    for (int k = 0; k < sc->nmaterials; k++) {
        const rad_material *mt = &sc->materials[k];
        jb_printf(b, "%s{\"name\":", k ? "," : "");
        jb_str(b, mt->name);
        jb_printf(b, ",\"reflect\":[");
        three(b, mt->reflect[0], mt->reflect[1], mt->reflect[2], 1);
        jb_printf(b, "],\"emit\":[");
        three(b, mt->emit[0], mt->emit[1], mt->emit[2], 1);
        jb_printf(b, "]}");
    }
    jb_printf(b, "],\"geometry\":%ld,\"methods\":[", s->geometry);
    for (int k = 0; k <= RADI_VIEW_ADAPTIVE; k++) {
        jb_printf(b, "%s", k ? "," : "");
        jb_str(b, radi_view_method_name(k));
    }
    jb_printf(b, "]}");
    return b->failed ? -1 : 0;
}

static void interleaved(jbuf *b, const char *key, const double *x, size_t count, int exact)
{
    jb_printf(b, ",\"%s\":[", key);
    for (size_t k = 0; k < count; k++) {
        jb_printf(b, "%s", k ? "," : "");
        jb_num(b, x[k], exact);
    }
    jb_printf(b, "]");
}

/* The race's lanes: each method's shooter, unshot power, error and vertex
 * radiosity (the first lane's is vertex_b too). */
static void race_json(const view_session *s, jbuf *b)
{
    const size_t nv = (size_t)s->shown_vertices;
    jb_printf(b, ",\"race\":[");
    for (int l = 0; l < s->lanes; l++) {
        jb_printf(b, "%s{\"method\":", l ? "," : "");
        jb_str(b, radi_view_method_name(l));
        jb_printf(b, ",\"shooter\":%d,\"unshot\":", s->lane_shooter[l]);
        jb_num(b, s->lane_unshot[l], 0);
        jb_printf(b, ",\"rms\":");
        jb_num(b, s->lane_rms[l], 1);
        interleaved(b, "vertex_b", s->vertex_b + (size_t)l * nv * 3, nv * 3, 0);
        jb_printf(b, "}");
    }
    jb_printf(b, "]");
}

void view_state_json(const view_session *s, jbuf *b, int vertices, int elements)
{
    jb_printf(b, "{\"version\":%ld,\"method\":", s->version);
    jb_str(b, radi_view_method_name(s->method));
    jb_printf(b, ",\"running\":%s,\"busy\":%s,\"step\":%ld,\"shooter\":%d,\"unshot\":",
              s->running ? "true" : "false",
              s->pending > 0 || s->reset_method >= 0 ? "true" : "false", s->step, s->shooter);
    jb_num(b, s->unshot, 0);
    jb_printf(b, ",\"rms\":");
    jb_num(b, s->rms, 1);
    jb_printf(b, ",\"rate\":");
    jb_num(b, s->rate, 0);
    jb_printf(b, ",\"shots_per_second\":");
    jb_num(b, s->sps, 0);
    jb_printf(b, ",\"failure\":");
    if (s->failure[0])
        jb_str(b, s->failure);
    else
        jb_printf(b, "null");
    static const char *const stage[] = {"done", "direct", "form_factors", "shooting"};
    jb_printf(b, ",\"mode\":\"%s\",\"frame\":%d,\"frames\":%d,\"frame_shots\":%d,"
                 "\"frame_stage\":\"%s\","
                 "\"converged\":%s,\"undo\":%d,\"geometry\":%ld,\"changes\":\"%s\","
                 "\"changes_failure\":",
              s->animate ? "animate" : "race", s->applied, s->frames, s->frame_shots,
              stage[s->frame_stage],
              s->frame_converged ? "true" : "false", s->ninverse, s->geometry,
              s->anim_state > 0 ? "ready" : s->anim_state < 0 ? "failed" : "building");
    if (s->anim_failure[0])
        jb_str(b, s->anim_failure);
    else
        jb_printf(b, "null");
    jb_printf(b, ",\"rms_history\":[");
    for (int k = 0; k < s->nhistory; k++) {
        jb_printf(b, "%s[%.0f", k ? "," : "", s->history[k][0]);
        for (int l = 0; l < s->lanes; l++) {
            jb_printf(b, ",");
            jb_num(b, s->history[k][1 + l], 0);
        }
        jb_printf(b, "]");
    }
    jb_printf(b, "]");
    if (s->lanes > 1 && vertices && !s->animate)
        race_json(s, b);
    if (vertices)
        interleaved(b, "vertex_b", s->vertex_b, (size_t)s->shown_vertices * 3, 0);
    if (elements && !s->animate)
        interleaved(b, "element_b", s->element_b, (size_t)s->shown_elements * 3, 1);
    if (elements && s->animate) /* the last frame run, numbered as a fresh solve */
        interleaved(b, "element_b", s->element_now, (size_t)s->n_now * 3, 1);
    jb_printf(b, "}");
}
