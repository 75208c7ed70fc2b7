/* fuzz_obj.c -- libFuzzer harness for the Wavefront OBJ + MTL reader.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * An input is OBJ text, then optionally the line "%%mtl" and MTL text: the
 * OBJ part is read as "fuzz.obj" by radi_obj_read, whose first `mtllib`
 * reads the MTL part from memory (nothing is opened on disk).  On success
 * the scene is checked (materials and objects exist, quads have 4
 * vertices) and meshed with rad_mesh_build up to FUZZ_MAX_ELEMENTS
 * elements; on failure the contracts of radiosity.h: the status is in the
 * error record, the message reads "NAME:LINE: reason" and the scene is
 * left empty.  A broken contract calls abort(), a crash to libFuzzer.
 *
 * Build and run: tests/fuzz/run-fuzz.sh [SECONDS] (FUZZ_HARNESSES=obj), or
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
#include "scene/objread.h"
#include "util/readfile.h"

#define FUZZ_MAX_ELEMENTS 20000
#define SEPARATOR "\n%%mtl\n"

/* "NAME:LINE: reason" with LINE >= 1 and a non-empty reason (NAME, an
 * mtllib file name, may itself hold colons and digits). */
static int message_ok(const char *msg)
{
    for (const char *p = strchr(msg, ':'); p; p = strchr(p + 1, ':')) {
        const char *q = p + 1;
        if (p == msg || !(*q >= '1' && *q <= '9'))
            continue;
        while (*q >= '0' && *q <= '9')
            q++;
        if (q[0] == ':' && q[1] == ' ' && q[2] != '\0')
            return 1;
    }
    return 0;
}

/* Where the MTL part starts, or size when there is none. */
static size_t split(const uint8_t *data, size_t size, size_t *obj_len)
{
    const size_t n = strlen(SEPARATOR);
    for (size_t k = 0; k + n <= size; k++)
        if (memcmp(data + k, SEPARATOR, n) == 0) {
            *obj_len = k + 1;
            return k + n;
        }
    *obj_len = size;
    return size;
}

static void check_scene(const rad_scene *s)
{
    size_t nelem = 0;
    if (s->nsurfaces < 1)
        abort();
    for (int k = 0; k < s->nsurfaces; k++) {
        const rad_surface *f = &s->surfaces[k];
        if (f->material < 0 || f->material >= s->nmaterials || f->object < -1 ||
            f->object >= s->nobjects || f->nverts < 3 ||
            (f->kind == RAD_SURFACE_QUAD) != (f->nverts == 4) || f->mesh_n != 1 ||
            f->mesh_m != 1)
            abort();
        nelem++;
    }
    if (nelem <= FUZZ_MAX_ELEMENTS) {
        rad_mesh mesh;
        rad_error err;
        memset(&err, 0, sizeof err);
        if (rad_mesh_build(&mesh, s, &err) != RAD_OK)
            abort(); /* a small mesh of a valid scene must build */
        if ((size_t)mesh.nelements != nelem)
            abort();
        rad_mesh_free(&mesh);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rad_scene scene;
    rad_error err;
    rad_lines r;
    size_t obj_len, mtl_at = split(data, size, &obj_len);
    memset(&err, 0, sizeof err);
    radi_lines_mem(&r, (const char *)data, obj_len, "fuzz.obj", '#', &err);
    rad_status st = radi_obj_read(&scene, &r, (const char *)data + mtl_at, size - mtl_at, 0);
    radi_lines_close(&r);
    if (st != RAD_OK) {
        if (err.status != st || !message_ok(err.message) || !fuzz_scene_empty(&scene))
            abort();
        return 0;
    }
    check_scene(&scene);
    rad_scene_free(&scene);
    return 0;
}
