/* fuzz_scene.c -- libFuzzer harness for the scene parser and the mesher.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Feeds arbitrary bytes to rad_scene_parse() as the text of "fuzz.scene".
 * On success the scene is meshed with rad_mesh_build() (unless the mesh
 * would exceed FUZZ_MAX_ELEMENTS elements, to keep each run fast) and
 * everything is freed.  On failure it checks the contracts of radiosity.h:
 * the message reads "fuzz.scene:LINE: reason" and the scene is left empty.
 * A broken contract calls abort(), which libFuzzer reports as a crash.
 *
 * Build and run (clang with libFuzzer, ASan and UBSan), from the top of the
 * source tree:
 *     make fuzz FUZZ_SECONDS=600   or   tests/fuzz/run-fuzz.sh [SECONDS]
 * which does, in a temporary directory holding a config.h that defines
 * PACKAGE_VERSION:
 *     clang -g -O1 -fsanitize=fuzzer,address,undefined \
 *         -fno-sanitize-recover=undefined -I$TMP -Isrc \
 *         tests/fuzz/fuzz_scene.c src/scene/scene.c src/scene/polycheck.c src/scene/scenebuild.c \
 *         src/scene/objread.c src/scene/vs3read.c src/util/readnum.c src/mesh/mesh.c \
 *         src/util/status.c src/util/readfile.c -lm -o $TMP/fuzz_scene
 *     $TMP/fuzz_scene -max_total_time=600 -max_len=4096 \
 *         -dict=tests/fuzz/scene.dict $TMP/scene/corpus
 * To replay one input: $TMP/fuzz_scene FILE.
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
#define FUZZ_NAME "fuzz.scene"

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
    if (scene.nsurfaces < 1)
        abort();

    size_t nelem = 0;
    for (int k = 0; k < scene.nsurfaces && nelem <= FUZZ_MAX_ELEMENTS; k++) {
        const rad_surface *f = &scene.surfaces[k];
        if (f->material < 0 || f->material >= scene.nmaterials)
            abort();
        if (f->kind == RAD_SURFACE_QUAD)
            nelem += (size_t)f->mesh_n * (size_t)f->mesh_m;
        else
            nelem += 1;
    }
    if (nelem <= FUZZ_MAX_ELEMENTS) {
        rad_mesh mesh;
        memset(&err, 0, sizeof err);
        if (rad_mesh_build(&mesh, &scene, &err) != RAD_OK)
            abort(); /* a small mesh of a valid scene must build */
        if ((size_t)mesh.nelements != nelem || mesh.nsurfaces != scene.nsurfaces)
            abort();
        rad_mesh_free(&mesh);
    }
    rad_scene_free(&scene);
    return 0;
}
