/* fuzz_ply.c -- libFuzzer harness for the PLY reader (plyread.c).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Feeds arbitrary bytes to rad_ply_parse() as the text of "fuzz.ply", the
 * way `radiosity render SOLUTION.ply` reads a solution back.  It checks the
 * contracts of plyread.h and abort()s (a crash to libFuzzer) when one
 * breaks:
 *   - a failure leaves the model empty and its message reads
 *     "fuzz.ply:LINE: reason" (or "fuzz.ply: ..." when memory runs out);
 *   - a success has at least one face, offsets that rise, vertex indices
 *     that exist, at least three vertices a face, finite positions and
 *     finite radiosity in every band.
 * Build and run with tests/fuzz/run-fuzz.sh (see README.md there), which
 * compiles it with src/{plyread,readfile,scene,status,render,plot,
 * atomicfile,mesh}.c, libFuzzer, ASan and UBSan; replay one input with
 * $WORK/fuzz_ply FILE.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/render.h"
#include "radiosity/plyread.h"
#include "radiosity/plyread.h"
#include "fuzz_common.h"

#define FUZZ_NAME "fuzz.ply"

/* "fuzz.ply:" then a line number >= 1, then ": " and some reason. */
static int message_ok(const char *msg, rad_status st)
{
    if (st == RAD_ERR_NOMEM)
        return strncmp(msg, FUZZ_NAME, strlen(FUZZ_NAME)) == 0;
    return fuzz_message_at(msg, FUZZ_NAME);
}

static int model_empty(const rad_render_model *m)
{
    return m->nvertices == 0 && m->nfaces == 0 && m->pos == NULL && m->vrad == NULL &&
           m->face_first == NULL && m->face_index == NULL && m->frad == NULL;
}

static int finite3(rad_vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

static int model_sound(const rad_render_model *m)
{
    const size_t nv = (size_t)m->nvertices, nf = (size_t)m->nfaces;
    if (nf < 1 || m->face_first[0] != 0)
        return 0;
    for (size_t v = 0; v < nv; v++) {
        if (!finite3(m->pos[v]))
            return 0;
        for (int b = 0; m->vrad && b < RAD_BANDS; b++)
            if (!isfinite(m->vrad[v + b * nv]))
                return 0;
    }
    for (size_t f = 0; f < nf; f++) {
        if (m->face_first[f + 1] - m->face_first[f] < 3)
            return 0;
        for (int k = m->face_first[f]; k < m->face_first[f + 1]; k++)
            if (m->face_index[k] < 0 || (size_t)m->face_index[k] >= nv)
                return 0;
        for (int b = 0; b < RAD_BANDS; b++)
            if (!isfinite(m->frad[f + b * nf]))
                return 0;
    }
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rad_render_model model;
    rad_camera cam;
    rad_error err;
    memset(&err, 0, sizeof err);
    rad_status st = rad_ply_parse(&model, &cam, (const char *)data, size, FUZZ_NAME, &err);
    if (st != RAD_OK) {
        if (err.status != st || !message_ok(err.message, st) || !model_empty(&model) ||
            cam.defined)
            abort();
        return 0;
    }
    if (!model_sound(&model))
        abort();
    rad_render_model_free(&model);
    return 0;
}
