/* fuzz_vs3.c -- libFuzzer harness for the View3D 3.x reader.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Feeds arbitrary bytes to rad_scene_parse() as the text of "fuzz.vs3",
 * which the name sends to the View3D reader.  On success the scene is
 * checked (materials exist, no objects, 3 or 4 vertices a surface, quads
 * exactly the 4-vertex ones) and meshed with rad_mesh_build up to
 * FUZZ_MAX_ELEMENTS elements; on failure the contracts of radiosity.h: the
 * status is in the error record, the message reads "fuzz.vs3:LINE:
 * reason" and the scene is left empty.  A broken contract calls abort(),
 * a crash to libFuzzer.
 *
 * Build and run: tests/fuzz/run-fuzz.sh [SECONDS] (FUZZ_HARNESSES=vs3), or
 * `make fuzz`; see fuzz_scene.c for the compiler flags.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"

#define FUZZ_MAX_ELEMENTS 20000
#define FUZZ_NAME "fuzz.vs3"

static void check_scene(const rad_scene *s)
{
    if (s->nsurfaces < 1 || s->nobjects != 0)
        abort();
    for (int k = 0; k < s->nsurfaces; k++) {
        const rad_surface *f = &s->surfaces[k];
        if (f->material < 0 || f->material >= s->nmaterials || f->object != -1 ||
            (f->nverts != 3 && f->nverts != 4) ||
            (f->kind == RAD_SURFACE_QUAD) != (f->nverts == 4))
            abort();
        /* a combination names an earlier S surface that combines with none */
        if (f->combine != -1 && (f->combine < 0 || f->combine >= k || f->obstruction ||
                                 s->surfaces[f->combine].combine != -1 ||
                                 s->surfaces[f->combine].obstruction))
            abort();
        for (int b = 0; b < RAD_BANDS; b++) {
            const rad_material *m = &s->materials[f->material];
            if (!(m->reflect[b] >= 0 && m->reflect[b] <= 1) || m->emit[b] != 0)
                abort();
        }
    }
    if (s->nsurfaces <= FUZZ_MAX_ELEMENTS) {
        rad_mesh mesh;
        rad_error err;
        memset(&err, 0, sizeof err);
        if (rad_mesh_build(&mesh, s, &err) != RAD_OK)
            abort(); /* a small mesh of a valid scene must build */
        if (mesh.nelements != s->nsurfaces)
            abort();
        rad_mesh_free(&mesh);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rad_scene scene;
    rad_error err;
    memset(&err, 0, sizeof err);
    rad_status st = rad_scene_parse(&scene, (const char *)data, size, FUZZ_NAME, &err);
    if (st != RAD_OK) {
        if (err.status != st || !fuzz_message_at(err.message, FUZZ_NAME) ||
            !fuzz_scene_empty(&scene))
            abort();
        return 0;
    }
    check_scene(&scene);
    rad_scene_free(&scene);
    return 0;
}
