/* exposure.c -- the automatic exposure of a picture.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A picture maps radiosity to pixels by one multiplier, the exposure,
 * before the sRGB curve (render.c).  Given none, the picture chooses the
 * one that maps its brightest element to full scale: 1 / max B over the
 * elements and the three bands.  Which elements count is the question.
 * Counting the light sources (RAD_EXPOSURE_ALL, this program's first
 * rule) lets a small bright lamp set the scale: in the Cornell box the
 * lamp's B is about 40 times the brightest wall's, and the room comes out
 * nearly black.  Photographers and the papers' pictures expose for the
 * lit surfaces and let the lamp clip to white, so the default
 * (RAD_EXPOSURE_REFLECTORS) counts only the elements that emit nothing
 * (E = 0 in every band): the brightest reflector maps to full scale and
 * emitters brighter than it are drawn white.  It falls back to all
 * elements when emission is unknown (a PLY file without the `emitting`
 * face property) or when no reflector is lit (B = 0 on every one: a scene
 * of lamps alone, or B = E before anything was shot).
 */
#include <config.h>

#include <math.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/render.h"

/* The largest B over the bands of the faces counted (emits[f] == 0, or
 * all when emits is NULL); B is nfaces x RAD_BANDS, column-major. */
static double brightest(int nfaces, const double *B, const unsigned char *emits)
{
    double mx = 0;
    for (int f = 0; f < nfaces; f++)
        if (!emits || !emits[f])
            for (int b = 0; b < RAD_BANDS; b++)
                mx = fmax(mx, B[(size_t)f + (size_t)b * (size_t)nfaces]);
    return mx;
}

/* 1 / the brightest counted value, else 1 / the brightest of all (no
 * reflector lit), else 1 (nothing lit, or 1 / max not finite). */
static double inverse_of(double counted, double all)
{
    const double mx = counted > 0 ? counted : all;
    return mx > 0 && isfinite(1 / mx) ? 1 / mx : 1;
}

static double exposure_of(int nfaces, const double *B, const unsigned char *emits,
                          rad_exposure_from from)
{
    const double mx = from == RAD_EXPOSURE_REFLECTORS && emits ? brightest(nfaces, B, emits) : 0;
    return inverse_of(mx, mx > 0 ? mx : brightest(nfaces, B, NULL));
}

double rad_render_auto_exposure(const rad_render_model *m, rad_exposure_from from)
{
    return exposure_of(m->nfaces, m->frad, m->face_emits, from);
}

double rad_mesh_auto_exposure(const rad_mesh *mesh, const double *B, rad_exposure_from from)
{
    const int n = mesh->nelements;
    double mx = 0, all = 0;
    for (int e = 0; e < n; e++) {
        int emits = 0;
        for (int b = 0; b < RAD_BANDS; b++)
            emits |= mesh->elements[e].emit[b] > 0;
        for (int b = 0; b < RAD_BANDS; b++) {
            const double v = B[(size_t)e + (size_t)b * (size_t)n];
            all = fmax(all, v);
            if (!emits || from == RAD_EXPOSURE_ALL)
                mx = fmax(mx, v);
        }
    }
    return inverse_of(mx, all);
}

int rad_exposure_from_parse(const char *name, rad_exposure_from *from)
{
    if (strcmp(name, "reflectors") == 0)
        *from = RAD_EXPOSURE_REFLECTORS;
    else if (strcmp(name, "all") == 0)
        *from = RAD_EXPOSURE_ALL;
    else
        return -1;
    return 0;
}
