/* animrun.h -- the state of one `radiosity animate` run, shared by the
 * command (cmd_animate.c) and its end-of-run files (animout.c).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_CLI_ANIMRUN_H
#define RAD_CLI_ANIMRUN_H

#include <stdio.h>

#include "cli/cli.h"
#include "radiosity/scene.h"
#include "radiosity/changes.h"
#include "radiosity/render.h"
#include "radiosity/animate.h"
#include "radiosity/animate.h"

typedef struct anim_args {
    cli_common common;
    rad_anim_options opt;
    const char *frames, *elements, *trace, *report, *log, *resume, *errors;
    int reference, width, height;
    rad_exposure_from exposure_from; /* of frame 0, which every frame keeps */
} anim_args;

/* One frame's figures for the summary and the report. */
typedef struct frame_row {
    rad_anim_report rep;
    int ran;                    /* run here (not before a --resume) */
    double error, error_top;    /* eq. 7 at the end of the frame, NaN without --reference */
    double t_reference;         /* seconds of the frame's fresh solve (--reference) */
} frame_row;

typedef struct anim_run {
    anim_args *args;
    rad_scene scene;            /* as loaded */
    rad_scene fscene;           /* --reference: the frame's scene, changes applied */
    rad_changes changes;
    rad_anim *anim;
    double *Bref, *Bprev;       /* --reference: n x 3, full numbering */
    unsigned char *top;         /* --reference: the 1% most changed */
    rad_anim_shot *shots;
    double *shot_err;           /* 2 per shot */
    size_t nshots, cap;
    frame_row *frames;
    double exposure;
    double t_reference;         /* of the last reference solve */
    int failed_shot;
    cli_staged stage;           /* every file of the run, renamed together at its end */
} anim_run;

/* The files written at the end of the run, as cli_writer_fn: --trace (a
 * row per shot), --errors (a row per frame run) and --report (JSON);
 * radiosity-files(5) gives their columns and keys. */
int cli_anim_trace(FILE *out, const void *ctx);
int cli_anim_errors(FILE *out, const void *ctx);
int cli_anim_report(FILE *out, const void *ctx);

#endif /* RAD_CLI_ANIMRUN_H */
