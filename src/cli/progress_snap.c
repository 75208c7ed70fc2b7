/* progress_snap.c -- the snapshots of `radiosity progress`: picture, error
 * picture and element table of one method at one step.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The pictures are the paper's figures 2-5 and 8 (Cohen, Chen, Wallace &
 * Greenberg 1988): the scene's camera at the converged solution's
 * exposure.  The error picture colours each element by the relative error
 * of its band-averaged radiosity against the converged solution on the
 * same element (errcolour.c), drawn flat at exposure 1 so that the colours
 * come out as their bytes.  The table is `solve --elements` of the
 * radiosity shown (with the column level for an adaptive mesh), so that
 * what a picture claims can be checked.  Only files and messages here; the
 * numbers come from the race.
 */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "render/render.h"
#include "cli/progress_snap.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/render.h"
#include "radiosity/export.h"
#include "radiosity/export.h"

#define MAX_PATH_STEP 10000000 /* progress's largest step */

static int write_png(FILE *out, const void *img)
{
    rad_error err;
    if (rad_image_write_png(img, out, &err) != RAD_OK) {
        cli_error_rec(&err);
        return -1;
    }
    return 0;
}

static int write_elements(FILE *out, const void *ctx)
{
    const progress_frame *f = ctx;
    return rad_export_elements_level(out, f->mesh, f->B, f->level);
}

/* PREFIX-METHOD-STEP[SUFFIX] into path[4096] (SUFFIX ".png", "-error.png"
 * or ".tsv"): 0, or 1 when it does not fit. */
static int snapshot_path(char *path, const char *prefix, int method, int step,
                         const char *suffix)
{
    const int len = snprintf(path, 4096, "%s-%s-%06d%s", prefix, radi_race_name(method), step,
                             suffix);
    return len < 0 || len >= 4096;
}

int progress_snap_check(const char *prefix, const rad_race_options *race, int error_images,
                        int elements, int first)
{
    char path[4096];
    if (race->snapshot_every <= 0 && race->nsnapshot_at <= 0)
        return 0;
    for (int m = first; m < RAD_RACE_METHODS; m++) {
        if (snapshot_path(path, prefix, m, MAX_PATH_STEP, "-error.png")) {
            cli_error("--snapshot-prefix '%.60s...' makes paths of more than 4095 bytes",
                      prefix);
            return 1;
        }
        /* the picture, and its error picture and table when asked for */
        const char *const suffix[3] = {".png", error_images ? "-error.png" : NULL,
                                       elements ? ".tsv" : NULL};
        for (int k = 0; k < 3; k++) {
            if (!suffix[k])
                continue;
            snapshot_path(path, prefix, m, race->nsnapshot_at ? race->snapshot_at[0] : 0,
                          suffix[k]);
            const cli_output o = {path, write_png, NULL};
            if (cli_outputs_check(&o, 1))
                return 1;
        }
    }
    return 0;
}

/* Draw B (element radiosity, and Bv at the vertices or NULL) with ro to path. */
static int draw(progress_snap *c, const rad_mesh *mesh, const double *B, const double *Bv,
                const rad_render_options *ro, const char *path)
{
    rad_render_model model;
    rad_image img;
    if (rad_render_model_from_mesh(&model, mesh, B, Bv, &c->err) != RAD_OK)
        return 1;
    int failed = rad_render(&model, ro, &img, &c->err) != RAD_OK;
    if (!failed) {
        failed = cli_write_atomic(path, write_png, &img) != 0;
        rad_image_free(&img);
    }
    rad_render_model_free(&model);
    return failed;
}

/* The error picture of f against its converged solution (errcolour.c):
 * flat, at exposure 1, so that the colours come out as their bytes. */
static int draw_error(progress_snap *c, const progress_frame *f, const char *path)
{
    const int n = f->mesh->nelements;
    rad_render_options ro = c->ropt;
    double *field = malloc(sizeof *field * (size_t)(n ? n : 1) * RAD_BANDS);
    if (!field) {
        snprintf(c->err.message, sizeof c->err.message, "out of memory for an error picture");
        return 1;
    }
    ro.shading = RAD_SHADING_FLAT;
    ro.exposure = 1;
    radi_errcolour_field(n, f->B, f->Bref, field);
    const int failed = draw(c, f->mesh, field, NULL, &ro, path);
    free(field);
    return failed;
}

int progress_snap_write(progress_snap *c, int method, int step, const progress_frame *f)
{
    char path[4096];
    if (snapshot_path(path, c->prefix, method, step, "-error.png")) { /* checked before */
        c->failed = 1;
        snprintf(c->err.message, sizeof c->err.message, "a snapshot path is too long");
        return 1;
    }
    snapshot_path(path, c->prefix, method, step, ".png");
    c->failed = draw(c, f->mesh, f->B, f->Bv, &c->ropt, path);
    if (!c->failed && c->error_images) {
        snapshot_path(path, c->prefix, method, step, "-error.png");
        c->failed = draw_error(c, f, path);
    }
    if (!c->failed && c->elements) {
        snapshot_path(path, c->prefix, method, step, ".tsv");
        c->failed = cli_write_atomic(path, write_elements, f) != 0;
    }
    if (c->failed && !c->err.message[0])
        snprintf(c->err.message, sizeof c->err.message, "the snapshots stop at step %d", step);
    return c->failed;
}
