/* fuzz_changes.c -- libFuzzer harness for the change file of `animate`.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Reads a fixed scene with a present object `box` and an absent object
 * `shade`, then feeds arbitrary bytes to rad_changes_parse() as the text
 * of "fuzz.changes".  On failure it checks the contracts of changes.h: the
 * message reads "fuzz.changes:LINE: reason" and the result is empty.  On
 * success every change must be consistent: a known object or material,
 * frames from 1 to nframes in order, a unit rotation axis, finite numbers,
 * reflectances in [0, 1], emission >= 0, and add/remove alternating with
 * the presence that the file implies.  A broken contract calls abort().
 *
 * Build and run: `make fuzz FUZZ_SECONDS=600` or
 * FUZZ_HARNESSES=changes tests/fuzz/run-fuzz.sh [SECONDS].
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/changes.h"

#define FUZZ_NAME "fuzz.changes"

static const char SCENE[] = "material w reflect 0.5\n"
                            "material lamp reflect 0 emit 1\n"
                            "quad w 0 0 0  1 0 0  1 1 0  0 1 0\n"
                            "object box\n quad w 0 0 1  1 0 1  1 1 1  0 1 1\nend\n"
                            "object shade absent\n polygon lamp 3 0 0 2 1 0 2 0 1 2\nend\n";

static int bands_ok(const double *v, double hi)
{
    for (int b = 0; b < RAD_BANDS; b++)
        if (!(v[b] >= 0 && v[b] <= hi))
            return 0;
    return 1;
}

static int change_ok(const rad_change *c, const rad_changes *all, unsigned char *present)
{
    if (c->frame < 1 || c->frame > all->nframes || c->line < 1)
        return 0;
    switch (c->kind) {
    case RAD_CHANGE_MOVE:
        return c->object >= 0 && c->object < 2 && isfinite(c->v.x + c->v.y + c->v.z);
    case RAD_CHANGE_ROTATE: {
        double len = sqrt(c->v.x * c->v.x + c->v.y * c->v.y + c->v.z * c->v.z);
        return c->object >= 0 && c->object < 2 && fabs(len - 1) < 1e-12 &&
               isfinite(c->degrees);
    }
    case RAD_CHANGE_ADD:
    case RAD_CHANGE_REMOVE: {
        int add = c->kind == RAD_CHANGE_ADD;
        if (c->object < 0 || c->object > 1 || present[c->object] == add)
            return 0;
        present[c->object] = (unsigned char)add;
        return 1;
    }
    case RAD_CHANGE_MATERIAL:
        return c->material >= 0 && c->material < 2 && bands_ok(c->reflect, 1) &&
               (!c->has_emit || bands_ok(c->emit, HUGE_VAL));
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rad_scene scene;
    rad_changes ch;
    rad_error err;
    if (rad_scene_parse(&scene, SCENE, sizeof SCENE - 1, "fuzz.scene", &err) != RAD_OK)
        abort();
    memset(&err, 0, sizeof err);
    rad_status st = rad_changes_parse(&ch, &scene, (const char *)data, size, FUZZ_NAME, &err);
    if (st != RAD_OK) {
        if (err.status != st || !fuzz_message_at(err.message, FUZZ_NAME) ||
            ch.changes || ch.nchanges)
            abort();
    } else {
        unsigned char present[2] = {1, 0};
        for (int k = 0; k < ch.nchanges; k++)
            if (!change_ok(&ch.changes[k], &ch, present) ||
                (k > 0 && ch.changes[k].frame < ch.changes[k - 1].frame))
                abort();
    }
    rad_changes_free(&ch);
    rad_scene_free(&scene);
    return 0;
}
