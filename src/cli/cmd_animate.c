/* cmd_animate.c -- `radiosity animate`: a scene through its changes.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Reads the scene and the change file (every change line checked before
 * any work), solves frame 0 and brings the solution to each later frame
 * by redistribution (the library's animate.h), writing per frame what the
 * options ask for: a picture (--frames PATTERN.png, the scene's camera,
 * the exposure of frame 0 so that frames compare), an element table
 * (--elements PATTERN, the format of `solve --elements`, numbered as a
 * fresh solve of the frame's scene numbers it: absent objects' elements
 * are left out).  --trace and --report are written at the end.  Every
 * path is checked before the work; each file is written to a temporary
 * as its frame is done, and all are renamed at the end (cli_staged).
 * --reference solves each frame afresh (LU, the pipeline) to measure the
 * error of eq. 7 per shot and per frame.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/atomicfile.h"
#include "cli/animrun.h"
#include "cli/cli.h"
#include "util/util.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/changes.h"
#include "radiosity/render.h"
#include "radiosity/export.h"
#include "radiosity/pipeline.h"
#include "radiosity/animate.h"
#include "radiosity/animate.h"

enum {
    OPT_FRAMES = 1300,
    OPT_AN_ELEMENTS,
    OPT_AN_TOLERANCE,
    OPT_STEPS,
    OPT_STRATEGY,
    OPT_AN_TRACE,
    OPT_AN_REPORT,
    OPT_REFERENCE,
    OPT_WIDTH,
    OPT_HEIGHT,
    OPT_FROM_SCRATCH,
    OPT_NO_GATHER,
    OPT_LOG,
    OPT_RESUME,
    OPT_CONVERGE_LAST,
    OPT_ERRORS,
    OPT_IMPORTANCE,
    OPT_EXPOSURE_FROM
};

static void help(void)
{
    printf("Usage: radiosity animate [OPTIONS] SCENE CHANGES\n"
           "Solve frame 0 of SCENE, then bring the solution to each later frame of\n"
           "the change file CHANGES by radiosity redistribution (George, Sillion &\n"
           "Greenberg 1990): the form factors a change alters are recomputed in\n"
           "place, the energy shot along them is redistributed (positive toward\n"
           "what became visible, negative toward what became hidden) and then\n"
           "propagated by shooting until the unshot power is below the tolerance.\n"
           "A converged frame equals a fresh 'radiosity solve' of its scene.  The\n"
           "change file (move, rotate, add, remove, material, frame) is described\n"
           "in radiosity-scene(5); every line is checked before any work.\n"
           "\n"
           "Options:\n"
           "      --frames PATTERN    one PNG per frame, PATTERN a printf pattern with\n"
           "                          one integer conversion (frame%%03d.png, a width\n"
           "                          below 100); the scene's camera, frame 0's\n"
           "                          automatic exposure (see --exposure-from; after\n"
           "                          --resume, the first frame run's)\n"
           "      --width W, --height H  picture size (default 384 x 384)\n"
           CLI_EXPOSURE_FROM_HELP
           "      --elements PATTERN  one element table per frame (the format of\n"
           "                          'solve --elements'; absent objects' elements\n"
           "                          left out, numbered as a fresh solve would)\n"
           "      --tolerance T       a frame is converged when its unshot power is\n"
           "                          at most T x the emitted power, the frame's or\n"
           "                          frame 0's, the larger (default 1e-12)\n"
           "      --max-iterations N  give up on a frame that has not converged after\n"
           "                          N shots (exit 1; default 1000 n + 100000, n the\n"
           "                          elements)\n"
           "      --solver progressive  accepted, as solve's option: what animate does\n"
           "                          (another solver is a usage error)\n"
           "      --form-factors-method contour  accepted: the method animate\n"
           "                          recomputes pairs with (hemicube is a usage error)\n"
           "      --steps K           stop each frame after K shots: a partial\n"
           "                          solution, as in an interactive session\n"
           "      --from-scratch      frame 0 too stops after --steps K shots:\n"
           "                          progressive refinement from scratch, to compare\n"
           "                          with redistribution (the paper's Fig. 6)\n"
           "      --no-gather         redistribute by shooters only, as the paper does\n"
           "                          (default: an element may also gather all that\n"
           "                          is redistributed to it in one step)\n"
           "      --strategy 1|2      1: redistribute, then propagate (default;\n"
           "                          without --steps, a frame first recomputes\n"
           "                          the lights' pairs and shoots the lights'\n"
           "                          change, then the other pairs); 2: the larger\n"
           "                          shot first (the paper's Fig. 4)\n"
           "      --importance exact|paper  the order of redistribution shots: exact\n"
           "                          (default) by the power each has pending, known\n"
           "                          here from the recomputed form factors; paper:\n"
           "                          by the paper's estimate of the energy toward\n"
           "                          the changed objects from sample points on\n"
           "                          them (section 4), shooters only\n"
           "      --converge-last     with --steps, converge the last frame all the\n"
           "                          same: the change log's final pass sets right\n"
           "                          what the partial frames left\n"
           "      --log FILE          the change log, written at the end of every\n"
           "                          frame: the state the next frame needs\n"
           "                          (radiosity-files(5))\n"
           "      --resume FILE       continue an interrupted animation from its\n"
           "                          --log FILE (same SCENE, CHANGES and options):\n"
           "                          the frames after the log's frame are run\n"
           "      --trace FILE        one TSV row per shot: frame step shooter kind\n"
           "                          sign power unshot redistribution_left error\n"
           "                          error_top1 gather\n"
           "      --reference         solve every frame afresh too, for the error of\n"
           "                          eq. 7 (luminance, area-weighted, normalised)\n"
           "                          per shot and per frame, overall and on the 1%%\n"
           "                          of patches the frame changes most (there\n"
           "                          relative to the change: 1 = not updated)\n"
           "      --errors FILE       one TSV row per frame: frame shots seconds\n"
           "                          pairs_recomputed pairs_share error error_top1\n"
           "                          (the eq. 7 errors; implies --reference)\n"
           "      --report FILE       per-frame figures as JSON (shots, pairs\n"
           "                          recomputed and their share, times, errors;\n"
           "                          with --reference the fresh solve's time and\n"
           "                          that of the changed pairs alone)\n"
           CLI_COMMON_HELP
           "\n"
           "Examples:\n"
           "  radiosity animate --mesh 2x2 data/cornell-moving-box.scene \\\n"
           "      data/cornell-moving-box.changes\n"
           "  radiosity animate --steps 50 --strategy 2 --reference \\\n"
           "      data/cube-on-table.scene data/cube-on-table.changes\n"
           "  radiosity animate --steps 3 --converge-last --log anim.log \\\n"
           "      --errors anim-errors.tsv data/cube-on-table.scene \\\n"
           "      data/cube-on-table.changes\n"
           "  radiosity animate --resume anim.log --steps 3 --converge-last \\\n"
           "      data/cube-on-table.scene data/cube-on-table.changes\n"
           "  radiosity animate --mesh 2x2 --elements frame%%02d.tsv \\\n"
           "      --frames frame%%02d.png data/cornell-moving-box.scene \\\n"
           "      data/cornell-moving-box.changes\n"
           "\n"
           "Every path is checked before the work.  Each regular file is written to a\n"
           "temporary beside it as its frame is done, and all are renamed together at\n"
           "the end: a failed or interrupted run replaces none (but --log, which is\n"
           "replaced after every frame, the state to resume from); a device or FIFO\n"
           "given to --trace, --report, --errors or --log is written in place, but a\n"
           "frame pattern must make files (a frame path naming a device, FIFO or\n"
           "descriptor is an error).  Exit status: 0 on success, 1 on an error, 2\n"
           "on a usage error; 128 + signal when interrupted.\n");
}

/* ---- arguments --------------------------------------------------------- */


/* A printf pattern with exactly one integer conversion (%d, %05d, ...). */
static int pattern_ok(const char *p)
{
    int conv = 0;
    for (; *p; p++) {
        if (*p != '%')
            continue;
        if (p[1] == '%') {
            p++;
            continue;
        }
        p++;
        while (*p == '0' || *p == '-' || *p == '+' || *p == ' ')
            p++;
        /* a width of at most 2 digits: %2147483648d overflows printf's int
         * and names some other file, %4000d outgrows any path */
        for (int digits = 0; *p >= '0' && *p <= '9'; p++)
            if (++digits > 2)
                return 0;
        if (*p != 'd' && *p != 'i')
            return 0;
        conv++;
    }
    return conv == 1;
}

static int parse_option(anim_args *a, int opt, const char *arg)
{
    int k;
    switch (opt) {
    case OPT_FRAMES:
    case OPT_AN_ELEMENTS:
        if (!pattern_ok(arg)) {
            cli_error("--%s needs a pattern with one integer conversion such as %%03d, "
                      "not '%s'", opt == OPT_FRAMES ? "frames" : "elements", arg);
            return 2;
        }
        if (opt == OPT_FRAMES && cli_png_name_check(arg, "--frames"))
            return 2;
        *(opt == OPT_FRAMES ? &a->frames : &a->elements) = arg;
        return 0;
    case OPT_AN_TOLERANCE:
        if (cli_parse_double(arg, &a->opt.tolerance) || !(a->opt.tolerance > 0)) {
            cli_error("--tolerance needs a positive number, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_STEPS:
    case OPT_MAX_ITERATIONS: /* solve's option: the shots a frame may take */
        if (cli_parse_int(arg, 1, 2000000000, &k)) {
            cli_error("--%s needs a whole number from 1, not '%s'",
                      opt == OPT_STEPS ? "steps" : "max-iterations", arg);
            return 2;
        }
        *(opt == OPT_STEPS ? &a->opt.steps : &a->opt.max_shots) = k;
        return 0;
    case OPT_STRATEGY:
        if (cli_parse_int(arg, 1, 2, &a->opt.strategy)) {
            cli_error("--strategy is 1 or 2, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_WIDTH:
    case OPT_HEIGHT:
        if (cli_parse_int(arg, 1, RAD_RENDER_MAX_SIDE, opt == OPT_WIDTH ? &a->width : &a->height)) {
            cli_error("--%s needs a whole number from 1 to %d, not '%s'",
                      opt == OPT_WIDTH ? "width" : "height", RAD_RENDER_MAX_SIDE, arg);
            return 2;
        }
        return 0;
    case OPT_AN_TRACE:
        a->trace = arg;
        return 0;
    case OPT_AN_REPORT:
        a->report = arg;
        return 0;
    case OPT_REFERENCE:
        a->reference = 1;
        return 0;
    case OPT_FROM_SCRATCH:
        a->opt.partial_start = 1;
        return 0;
    case OPT_NO_GATHER:
        a->opt.gather = 0;
        return 0;
    case OPT_IMPORTANCE:
        if (strcmp(arg, "exact") != 0 && strcmp(arg, "paper") != 0) {
            cli_error("--importance is exact or paper, not '%s'", arg);
            return 2;
        }
        a->opt.importance = arg[0] == 'p' ? RAD_ANIM_IMPORTANCE_PAPER : RAD_ANIM_IMPORTANCE_EXACT;
        return 0;
    case OPT_CONVERGE_LAST:
        a->opt.converge_last = 1;
        return 0;
    case OPT_LOG:
        a->log = arg;
        return 0;
    case OPT_RESUME:
        a->resume = arg;
        return 0;
    case OPT_EXPOSURE_FROM:
        return cli_parse_exposure_from(arg, &a->exposure_from);
    case OPT_ERRORS:
        a->errors = arg;
        a->reference = 1;
        return 0;
    /* solve's options that mean something here: animate is progressive
     * refinement on the contour's form factors */
    case OPT_SOLVER:
        if (strcmp(arg, "progressive") != 0) {
            cli_error("--solver: animate shoots (progressive refinement); it takes only "
                      "progressive, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_FF_METHOD:
        if (strcmp(arg, "contour") != 0) {
            cli_error("--form-factors-method: animate recomputes form factors pair by pair "
                      "with the contour integral; it takes only contour, not '%s'", arg);
            return 2;
        }
        return 0;
    }
    return cli_common_option(&a->common, opt, arg) == 0 ? 0 : 2;
}

/* ---- the run ----------------------------------------------------------- */


static int record_shot(void *user, const rad_anim_shot *s)
{
    anim_run *r = user;
    if (!r->args->trace)
        return 0;
    if (r->nshots == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 4096;
        rad_anim_shot *g = realloc(r->shots, sizeof *g * cap);
        double *e = g ? realloc(r->shot_err, sizeof *e * 2 * cap) : NULL;
        if (g)
            r->shots = g;
        if (!g || !e)
            return r->failed_shot = 1;
        r->shot_err = e;
        r->cap = cap;
    }
    double e = NAN, et = NAN;
    if (r->Bref) { /* s->anim: frame 0's shots come before rad_anim_create returns */
        const rad_mesh *m = rad_anim_mesh(s->anim);
        e = rad_anim_error(m, rad_anim_present(s->anim), rad_anim_radiosity(s->anim), r->Bref);
        et = rad_anim_error_changed(m, r->top, rad_anim_radiosity(s->anim), r->Bref, r->Bprev);
    }
    r->shot_err[2 * r->nshots] = e;
    r->shot_err[2 * r->nshots + 1] = et;
    r->shots[r->nshots++] = *s;
    return 0;
}

/* --reference: B of a fresh solve of the frame's scene, scattered into the
 * animation's numbering (every surface; absent ones 0). */
static int reference(anim_run *r, int frame, const rad_mesh *full)
{
    rad_pipeline_options po;
    rad_result res;
    rad_error err;
    rad_pipeline_options_init(&po);
    po.crease = 0; /* no vertex values are used here */
    po.ff = r->args->common.ff;
    double t0 = cli_seconds();
    rad_status st = rad_pipeline_run(&r->fscene, &po, &res, &err);
    r->t_reference = cli_seconds() - t0;
    if (st != RAD_OK) {
        cli_error("the reference solve of frame %d: %s", frame, err.message);
        rad_result_free(&res);
        return 1;
    }
    const size_t n = (size_t)full->nelements, np = (size_t)res.mesh.nelements;
    memcpy(r->Bprev, r->Bref, sizeof *r->Bref * n * RAD_BANDS);
    memset(r->Bref, 0, sizeof *r->Bref * n * RAD_BANDS);
    size_t k = 0;
    for (int s = 0; s < r->fscene.nsurfaces; s++) {
        int o = r->fscene.surfaces[s].object;
        if (o >= 0 && r->fscene.objects[o].absent)
            continue;
        for (int e = full->surface_first[s]; e < full->surface_first[s + 1] && k < np; e++, k++)
            for (int b = 0; b < RAD_BANDS; b++)
                r->Bref[e + b * n] = res.B[k + b * np];
    }
    rad_result_free(&res);
    rad_anim_most_changed(full, NULL, r->Bref, r->Bprev, 0.01, r->top);
    return 0;
}

static int w_elements(FILE *out, const void *ctx)
{
    const anim_run *r = ctx;
    rad_mesh m;
    double *B;
    rad_error err;
    if (rad_anim_present_result(r->anim, &m, &B, &err) != RAD_OK) {
        cli_error_rec(&err);
        return -1;
    }
    int rc = rad_export_elements(out, &m, B);
    rad_mesh_free(&m);
    free(B);
    return rc;
}

static int w_png(FILE *out, const void *ctx)
{
    rad_error err;
    if (rad_image_write_png(ctx, out, &err) != RAD_OK) {
        cli_error_rec(&err);
        return -1;
    }
    return 0;
}

/* The frame's picture: the present elements, smoothed, frame 0's exposure. */
static int picture(anim_run *r, const char *path)
{
    rad_mesh m;
    double *B, *Bv = NULL;
    rad_error err;
    rad_render_model model;
    rad_image img;
    rad_render_options ro;
    int rc = 1;
    if (rad_anim_present_result(r->anim, &m, &B, &err) != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    Bv = malloc(sizeof *Bv * ((size_t)m.nvertices + 1) * RAD_BANDS);
    if (r->exposure == 0) {
        r->exposure = rad_mesh_auto_exposure(&m, B, r->args->exposure_from);
    }
    rad_render_options_init(&ro);
    ro.camera = r->scene.camera;
    ro.width = r->args->width;
    ro.height = r->args->height;
    ro.exposure = r->exposure;
    if (Bv) {
        rad_smooth_vertices(&m, B, Bv);
        if (rad_render_model_from_mesh(&model, &m, B, Bv, &err) == RAD_OK) {
            if (rad_render(&model, &ro, &img, &err) == RAD_OK) {
                rc = cli_staged_write(&r->stage, path, w_png, &img);
                rad_image_free(&img);
            } else {
                cli_error_rec(&err);
            }
            rad_render_model_free(&model);
        } else {
            cli_error_rec(&err);
        }
    }
    free(Bv);
    free(B);
    rad_mesh_free(&m);
    return rc;
}

static int w_log(FILE *out, const void *ctx)
{
    return rad_anim_log_write(out, ctx) == RAD_OK ? 0 : -1;
}

/* The path of one frame: 0, or 1 (printed) when it does not fit, rather
 * than a truncated name that is not what the user asked for. */
static int pattern_path(char *buf, size_t size, const char *pattern, int frame)
{
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
    const int len = snprintf(buf, size, pattern, frame);
#pragma GCC diagnostic pop
    if (len < 0 || (size_t)len >= size) {
        cli_error("the pattern '%.60s...' makes a path of more than %zu bytes for frame %d",
                  pattern, size - 1, frame);
        return 1;
    }
    return 0;
}

/* The frame's files, its errors and its summary line. */
static int frame_done(anim_run *r, const rad_anim_report *rep)
{
    const int f = rep->frame;
    char path[4096];
    frame_row *row = &r->frames[f];
    row->rep = *rep;
    row->ran = 1;
    row->error = row->error_top = row->t_reference = NAN;
    if (r->Bref) {
        row->t_reference = r->t_reference;
        const rad_mesh *m = rad_anim_mesh(r->anim);
        row->error = rad_anim_error(m, rad_anim_present(r->anim), rad_anim_radiosity(r->anim),
                                    r->Bref);
        row->error_top = rad_anim_error_changed(m, r->top, rad_anim_radiosity(r->anim), r->Bref,
                                                r->Bprev);
    }
    if (r->args->elements) {
        if (pattern_path(path, sizeof path, r->args->elements, f) ||
            cli_staged_write(&r->stage, path, w_elements, r))
            return 1;
    }
    if (r->args->frames) {
        if (pattern_path(path, sizeof path, r->args->frames, f) || picture(r, path))
            return 1;
    }
    if (r->args->log && cli_write_atomic(r->args->log, w_log, r->anim))
        return 1;
    if (!r->args->common.quiet) {
        fprintf(stderr, "frame %d: %ld shots (%ld redistribution), %s, %.0f of %.0f pairs "
                "recomputed (%.1f%%), %.3f s", f, rep->shots, rep->redistribution_shots,
                rep->converged ? "converged" : "partial", rep->pairs_recomputed,
                rep->pairs_total, rep->pairs_total > 0 ? 100 * rep->pairs_recomputed /
                rep->pairs_total : 0.0, rep->t_total);
        if (r->Bref)
            fprintf(stderr, ", eq. 7 error %.3g (%.3g on the 1%% most changed)", row->error,
                    row->error_top);
        fputc('\n', stderr);
    }
    return 0;
}

/* ---- the steps of a run -------------------------------------------------- */

static int path_cmp(const void *x, const void *y)
{
    return strcmp(*(char *const *)x, *(char *const *)y);
}

/* No two outputs of the run may name one file (--elements f%d.x with
 * --frames f%d.x, or --trace f1.x): the later would silently replace the
 * earlier.  Paths are compared as written; "-" may repeat.  0, or 1. */
static int check_distinct(char **paths, size_t n)
{
    qsort(paths, n, sizeof *paths, path_cmp);
    for (size_t k = 1; k < n; k++)
        if (strcmp(paths[k], paths[k - 1]) == 0 && strcmp(paths[k], "-") != 0) {
            cli_error("%s: named by two outputs of the run (--frames, --elements, --trace, "
                      "--report, --errors, --log)", paths[k]);
            return 1;
        }
    return 0;
}

/* Every path the run will write, checked before any work: 0 or 1. */
static int check_paths(const anim_run *r)
{
    const anim_args *a = r->args;
    char path[4096];
    cli_output o[4] = {{a->trace, cli_anim_trace, r}, {a->report, cli_anim_report, r},
                       {a->errors, cli_anim_errors, r}, {a->log, w_log, NULL}};
    if (cli_outputs_check(o, 4))
        return 1;
    const size_t cap = 2 * ((size_t)r->changes.nframes + 1) + 4;
    char **paths = calloc(cap, sizeof *paths);
    size_t n = 0;
    int rc = 0;
    if (!paths) {
        cli_error("out of memory");
        return 1;
    }
    for (int k = 0; k < 4 && !rc; k++)
        if (o[k].path && !(paths[n++] = strdup(o[k].path))) {
            cli_error("out of memory");
            rc = 1;
        }
    for (int f = 0; f <= r->changes.nframes && !rc; f++) {
        const char *pat[2] = {a->elements, a->frames};
        for (int k = 0; k < 2 && !rc; k++) {
            if (!pat[k])
                continue;
            if (pattern_path(path, sizeof path, pat[k], f))
                rc = 1;
            else if (radi_afile_is_direct(path)) {
                /* /dev/fd/%d would write frame 0 to standard input, frame
                 * 1 over the summary... */
                cli_error("--%s: frame %d's path '%s' names a descriptor, device or FIFO; "
                          "a per-frame pattern must name files",
                          k ? "frames" : "elements", f, path);
                rc = 1;
            }
            cli_output one = {path, cli_anim_trace, r};
            if (!rc && cli_outputs_check(&one, 1))
                rc = 1;
            if (!rc && !(paths[n++] = strdup(path))) {
                cli_error("out of memory");
                rc = 1;
            }
        }
    }
    if (!rc)
        rc = check_distinct(paths, n);
    for (size_t k = 0; k < n; k++)
        free(paths[k]);
    free(paths);
    return rc;
}

static int load(anim_run *r, const char *scene, const char *changes)
{
    rad_error err;
    rad_status st;
    if (cli_load_scene(scene, &r->args->common, &r->scene))
        return 1;
    if ((st = rad_changes_load(&r->changes, &r->scene, changes, &err)) != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    if (r->args->frames && (!r->scene.camera.defined ||
                            rad_camera_check(&r->scene.camera, &err) != RAD_OK)) {
        cli_error("%s: --frames needs a camera line in the scene", scene);
        return 1;
    }
    r->frames = calloc((size_t)r->changes.nframes + 1, sizeof *r->frames);
    if (!r->frames) {
        cli_error("out of memory");
        return 1;
    }
    return 0;
}

/* --reference: the frame's scene and the arrays of the errors. */
static int reference_setup(anim_run *r)
{
    rad_error err;
    unsigned char *all = malloc((size_t)r->scene.nobjects + 1);
    size_t n = (size_t)rad_scene_element_count(&r->scene);
    if (!all || rad_scene_present_copy(&r->scene, (memset(all, 1, (size_t)r->scene.nobjects + 1),
                                                   all), &r->fscene, &err) != RAD_OK) {
        free(all);
        cli_error("out of memory");
        return 1;
    }
    free(all);
    for (int o = 0; o < r->scene.nobjects; o++)
        r->fscene.objects[o].absent = r->scene.objects[o].absent;
    r->Bref = calloc(n * RAD_BANDS + 1, sizeof *r->Bref);
    r->Bprev = calloc(n * RAD_BANDS + 1, sizeof *r->Bprev);
    r->top = calloc(n + 1, 1);
    if (!r->Bref || !r->Bprev || !r->top) {
        cli_error("out of memory");
        return 1;
    }
    return 0;
}

/* The reference of frame f needs the full mesh's numbering, which is that
 * of the loaded scene's surfaces: build it once. */
static int reference_frame(anim_run *r, int f)
{
    rad_mesh full;
    rad_error err;
    if (rad_mesh_build(&full, &r->fscene, &err) != RAD_OK) { /* before the changes */
        cli_error_rec(&err);
        return 1;
    }
    if (f > 0)
        rad_changes_apply(&r->fscene, &r->changes, f, NULL);
    int rc = reference(r, f, &full);
    rad_mesh_free(&full);
    return rc;
}

/* --resume: the animation from its log; *first is the next frame. */
static int resume(anim_run *r, int *first)
{
    rad_error err;
    anim_args *a = r->args;
    FILE *in = fopen(a->resume, "r");
    if (!in) {
        cli_error("%s: cannot read the log", a->resume);
        return 1;
    }
    rad_status st = rad_anim_resume(&r->anim, &r->scene, &r->changes, in, a->resume, &a->opt,
                                    &err);
    fclose(in);
    if (st != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    const int f = rad_anim_frame(r->anim);
    *first = f + 1;
    if (!a->common.quiet)
        fprintf(stderr, "resumed from %s after frame %d of %d%s\n", a->resume, f,
                r->changes.nframes, f == r->changes.nframes ? ": nothing left to do" : "");
    if (!a->reference)
        return 0;
    for (int k = 1; k < f; k++) /* the frames before the log's, unsolved */
        rad_changes_apply(&r->fscene, &r->changes, k, NULL);
    return reference_frame(r, f);
}

static int animate(anim_run *r)
{
    rad_error err;
    rad_anim_report rep;
    anim_args *a = r->args;
    int first = 1;
    a->opt.ff = a->common.ff;
    a->opt.on_shot = record_shot;
    a->opt.shot_user = r;
    if (a->reference && reference_setup(r))
        return 1;
    if (a->resume) {
        if (resume(r, &first))
            return 1;
    } else {
        if (a->reference && reference_frame(r, 0))
            return 1;
        if (rad_anim_create(&r->anim, &r->scene, &a->opt, &rep, &err) != RAD_OK) {
            cli_error_rec(&err);
            return 1;
        }
        if (frame_done(r, &rep))
            return 1;
    }
    for (int f = first; f <= r->changes.nframes; f++) {
        if (a->reference && reference_frame(r, f))
            return 1;
        if (rad_anim_next(r->anim, &r->changes, &rep, &err) != RAD_OK) {
            cli_error_rec(&err);
            return 1;
        }
        if (r->failed_shot) {
            cli_error("out of memory for the trace");
            return 1;
        }
        if (frame_done(r, &rep))
            return 1;
    }
    return 0;
}

static void run_free(anim_run *r)
{
    rad_anim_free(r->anim);
    rad_changes_free(&r->changes);
    rad_scene_free(&r->scene);
    rad_scene_free(&r->fscene);
    free(r->Bref);
    free(r->Bprev);
    free(r->top);
    free(r->shots);
    free(r->shot_err);
    free(r->frames);
}

static int run(anim_args *a, const char *scene, const char *changes)
{
    anim_run r;
    memset(&r, 0, sizeof r);
    r.args = a;
    int status = 1;
    /* Frames are written as they are computed, each to a temporary, and
     * all renamed with the trace and report at the end: a run that fails at
     * frame 7 replaces none of the files of frames 0-6. */
    if (!load(&r, scene, changes) && !check_paths(&r) &&
        !cli_staged_begin(&r.stage, 2 * (r.changes.nframes + 1) + 3) && !animate(&r) &&
        !(a->trace && cli_staged_write(&r.stage, a->trace, cli_anim_trace, &r)) &&
        !(a->report && cli_staged_write(&r.stage, a->report, cli_anim_report, &r)) &&
        !(a->errors && cli_staged_write(&r.stage, a->errors, cli_anim_errors, &r)))
        status = cli_staged_commit(&r.stage) ? 1 : 0;
    cli_staged_abort(&r.stage); /* after a failure: every temporary removed */
    run_free(&r);
    return status;
}

int cmd_animate(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"frames", required_argument, NULL, OPT_FRAMES},
        {"elements", required_argument, NULL, OPT_AN_ELEMENTS},
        {"tolerance", required_argument, NULL, OPT_AN_TOLERANCE},
        {"steps", required_argument, NULL, OPT_STEPS},
        {"strategy", required_argument, NULL, OPT_STRATEGY},
        {"trace", required_argument, NULL, OPT_AN_TRACE},
        {"report", required_argument, NULL, OPT_AN_REPORT},
        {"reference", no_argument, NULL, OPT_REFERENCE},
        {"from-scratch", no_argument, NULL, OPT_FROM_SCRATCH},
        {"exposure-from", required_argument, NULL, OPT_EXPOSURE_FROM},
        {"no-gather", no_argument, NULL, OPT_NO_GATHER},
        {"converge-last", no_argument, NULL, OPT_CONVERGE_LAST},
        {"importance", required_argument, NULL, OPT_IMPORTANCE},
        {"log", required_argument, NULL, OPT_LOG},
        {"resume", required_argument, NULL, OPT_RESUME},
        {"errors", required_argument, NULL, OPT_ERRORS},
        {"width", required_argument, NULL, OPT_WIDTH},
        {"height", required_argument, NULL, OPT_HEIGHT},
        {"solver", required_argument, NULL, OPT_SOLVER},
        {"max-iterations", required_argument, NULL, OPT_MAX_ITERATIONS},
        {"form-factors-method", required_argument, NULL, OPT_FF_METHOD},
        CLI_COMMON_LONGOPTS,
        {NULL, 0, NULL, 0}};
    anim_args a;
    int opt;
    memset(&a, 0, sizeof a);
    cli_common_init(&a.common);
    rad_anim_options_init(&a.opt);
    a.width = a.height = 384;
    while ((opt = getopt_long(argc, argv, "hq", longopts, NULL)) != -1) {
        if (opt == OPT_HELP || opt == 'h') {
            help();
            return 0;
        }
        if (opt == '?' || parse_option(&a, opt == 'q' ? OPT_QUIET : opt, optarg) != 0)
            return cli_usage_hint("animate");
    }
    /* the report's t_changed: a frame's floor, beside the fresh solve's time */
    a.opt.time_changed = a.reference && a.report;
    if (a.opt.steps > 0 && a.opt.max_shots > 0 && a.opt.max_shots < a.opt.steps) {
        cli_error("--max-iterations %ld is below --steps %ld: every frame would give up "
                  "before its steps", a.opt.max_shots, a.opt.steps);
        return cli_usage_hint("animate");
    }
    if (a.opt.partial_start && a.opt.steps == 0) {
        cli_error("--from-scratch needs --steps K");
        return cli_usage_hint("animate");
    }
    if (argc - optind != 2) {
        cli_error(argc - optind < 2 ? "animate needs a SCENE and a CHANGES file"
                                    : "animate takes one SCENE and one CHANGES file");
        return cli_usage_hint("animate");
    }
    cli_signals_install();
    cli_progress_attach(&a.common);
    return run(&a, argv[optind], argv[optind + 1]);
}
