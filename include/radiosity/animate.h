/* animate.h -- scenes that change: radiosity redistribution.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * George, Sillion & Greenberg, "Radiosity Redistribution for Dynamic
 * Environments", IEEE CG&A 10(4), July 1990.  An animation keeps one
 * solution alive while objects move, turn, come, go and change colour
 * (the change file, changes.h): instead of solving each frame again it
 * shoots the change.  Frame 0 is solved by shooting (Cohen et al. 1988);
 * each later frame recomputes the form factors that the frame's changes
 * can alter, in place, and redistributes the energy that earlier shots
 * sent along them (positive toward what became visible, negative toward
 * what became hidden), then propagates by shooting, both signs, until the
 * unshot power is below the tolerance.  radiosity(3) says how.
 *
 * Units and conventions are those of radiosity.h.  Element indices are
 * those of the mesh of every surface, absent objects' included
 * (rad_anim_mesh); rad_anim_present says which are in the scene now.
 */
#ifndef RAD_ANIMATE_H
#define RAD_ANIMATE_H

#include "radiosity/solve.h"
#include "radiosity/changes.h"

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One shot, for a trace. */
typedef struct rad_anim_shot {
    int frame;                  /* 0, 1, ... */
    long step;                  /* 1, 2, ... within the frame */
    int shooter;                /* element (rad_anim_mesh numbering) */
    int redistribute;           /* 1: a redistribution shot (George et al. 1990,
                                   eq. 5); 0: propagation of unshot radiosity */
    int sign;                   /* +1 or -1: the sign of the power shot */
    double power;               /* |power| shot, summed over the bands */
    double unshot;              /* unshot power left, sum_j A_j sum_b |dB_j| */
    double redistribution_left; /* power of the redistribution shots pending */
    int gather;                 /* redistribute: 1 when `shooter` is the receiver
                                   that gathered its pending terms at once */
    const struct rad_anim *anim; /* the animation shooting: its B, mesh and
                                   presence as they are after the shot (in
                                   frame 0 too, before rad_anim_create
                                   returns it); valid during the call only */
    int direct;                 /* 1: a shot of the frame's direct light's stage
                                   (rad_anim_options.direct_first); 2: its
                                   last, after which the frame recomputes the
                                   rest of its form factors before the next
                                   shot; 0: any other shot */
} rad_anim_shot;

/* Called after each shot; non-zero stops the frame (RAD_ERR_INVALID,
 * "interrupted"). */
typedef int (*rad_anim_shot_fn)(void *user, const rad_anim_shot *shot);

/* The order of redistribution shots (rad_anim_options.importance). */
enum { RAD_ANIM_IMPORTANCE_EXACT = 0, RAD_ANIM_IMPORTANCE_PAPER = 1 };

typedef struct rad_anim_options {
    rad_ff_options ff;          /* accuracy, quadrature, threads, progress */
    double tolerance;           /* a frame is converged when its unshot power
                                   is at most tolerance x the emitted power,
                                   the frame's or frame 0's, the larger
                                   (default 1e-12) */
    long steps;                 /* 0: converge each frame; K > 0: stop each
                                   frame after K shots (a partial solution);
                                   frame 0 is converged unless partial_start */
    int partial_start;          /* 1: frame 0 too stops after `steps` shots:
                                   progressive refinement from scratch (Cohen
                                   et al. 1988), the comparison of George et
                                   al. 1990, Fig. 6 */
    int strategy;               /* 1: redistribute first, then propagate;
                                   2: the larger shot first (Fig. 4) */
    int gather;                 /* 1 (default): a redistribution step may be a
                                   receiver gathering its pending terms;
                                   0: shooters only, as in the paper */
    int importance;             /* RAD_ANIM_IMPORTANCE_EXACT (default): shooters
                                   in order of their exact pending power;
                                   RAD_ANIM_IMPORTANCE_PAPER: of the paper's
                                   estimate from sample points on the changed
                                   objects (section 4), shooters only */
    int converge_last;          /* 1: with steps, the last frame of the change
                                   file is converged all the same (the log's
                                   final pass) */
    long max_shots;             /* per frame before RAD_ERR_NOCONV (default
                                   1000 n + 100000) */
    rad_anim_shot_fn on_shot;   /* may be NULL */
    void *shot_user;
    int time_changed;           /* 1: after a frame's recompute, compute the
                                   pairs whose F changed once more, alone, and
                                   time it (rad_anim_report.t_changed); the
                                   result is thrown away */
    int direct_first;           /* 1 (default): a frame that converges (steps
                                   0, strategy 1, exact importance) first
                                   recomputes the pairs with an emitter and
                                   shoots the lights' change (a new or changed
                                   emission's first shot, the redistribution
                                   of what they had shot), then the rest: the
                                   lights' change is in B (and on_shot) before
                                   the bulk of the form factors is computed.
                                   The converged frame is the same within the
                                   tolerance; 0: all the pairs at once */
} rad_anim_options;

RAD_API void rad_anim_options_init(rad_anim_options *opt);

/* What one frame did. */
typedef struct rad_anim_report {
    int frame;
    long shots, redistribution_shots, propagation_shots;
    int converged;              /* unshot power within the tolerance, nothing
                                   left to redistribute */
    double unshot;              /* at the end of the frame */
    double emitted;             /* sum_j A_j sum_b E_j, present elements */
    double pairs_recomputed;    /* unordered pairs of present elements whose
                                   F was recomputed */
    double pairs_total;         /* n (n - 1) / 2 over present elements */
    double pairs_changed;       /* ... whose F changed */
    double t_formfactor, t_shoot, t_total;  /* wall-clock seconds */
    int log_pass;               /* 1: the frame converged after unconverged
                                   ones and ran the change log's final pass */
    double log_residual;        /* the largest |F S - H| / |F S| it removed */
    double t_changed;           /* with time_changed (frames after 0): seconds
                                   to compute only the pairs whose F changed,
                                   on the frame's mesh: the least that form
                                   factors a frame could cost if it knew them
                                   in advance; not in t_formfactor or t_total.
                                   NaN when not measured */
} rad_anim_report;

typedef struct rad_anim rad_anim;

/* Mesh every surface of `scene` (absent objects too, so that indices stay
 * put), fill F for the present ones and solve frame 0 to the tolerance.
 * The scene is copied; rep (may be NULL) receives frame 0's figures. */
RAD_API rad_status rad_anim_create(rad_anim **anim, const rad_scene *scene,
                                   const rad_anim_options *opt, rad_anim_report *rep,
                                   rad_error *err);
/* Apply the next frame of `changes` (those with frame == the next frame
 * number) and redistribute.  RAD_ERR_INVALID when there is no next frame. */
RAD_API rad_status rad_anim_next(rad_anim *anim, const rad_changes *changes,
                                 rad_anim_report *rep, rad_error *err);
RAD_API void rad_anim_free(rad_anim *anim);

/* The change log (George et al. 1990, Fig. 5): the state the
 * next frame needs, written as text to `out` (RAD_ERR_IO on a write
 * error).  rad_anim_resume reads it back from `log` (`logname` for
 * messages, RAD_ERR_PARSE naming its line) for the same scene and change
 * file, rebuilds the log's frame from them, F afresh, and continues: the
 * next rad_anim_next brings it to the following frame as the
 * uninterrupted animation would. */
RAD_API rad_status rad_anim_log_write(FILE *out, const rad_anim *anim);
RAD_API rad_status rad_anim_resume(rad_anim **anim, const rad_scene *scene,
                                   const rad_changes *changes, FILE *log, const char *logname,
                                   const rad_anim_options *opt, rad_error *err);
/* The largest relative difference |F S - H| / |F S| the last final pass
 * of the log removed (0 before any). */
RAD_API double rad_anim_log_residual(const rad_anim *anim);

/* The current frame number, scene (moved, materials changed), mesh of
 * every surface, presence per element (1 in the scene), and B
 * (nelements x RAD_BANDS, column-major; 0 for absent elements). */
RAD_API int rad_anim_frame(const rad_anim *anim);
RAD_API const rad_scene *rad_anim_scene(const rad_anim *anim);
RAD_API const rad_mesh *rad_anim_mesh(const rad_anim *anim);
RAD_API const unsigned char *rad_anim_present(const rad_anim *anim);
RAD_API const double *rad_anim_radiosity(const rad_anim *anim);

/* The current frame as a fresh solve of its scene would number it: the
 * mesh of the present surfaces only (rad_scene_present_copy) and B in
 * that order.  Free with rad_mesh_free and free(). */
RAD_API rad_status rad_anim_present_result(const rad_anim *anim, rad_mesh *mesh, double **B,
                                           rad_error *err);

/* The error of George et al. 1990, eq. 7: sum_i A_i |Y_i -
 * Yref_i| / sum_i A_i Yref_i over the elements i with mask[i] (NULL: all
 * n), Y = 0.2126 R + 0.7152 G + 0.0722 B (ITU-R BT.709 luminance of linear
 * RGB).  B and Bref are n x RAD_BANDS. */
RAD_API double rad_anim_error(const rad_mesh *mesh, const unsigned char *mask, const double *B,
                              const double *Bref);
/* The same error over the elements with mask[i], normalised by the
 * change from Bprev to Bref there, sum A_i |Yref_i - Yprev_i|: 1 is the
 * error of not updating at all.  (The patches a change alters most are
 * often those it shadows, whose Yref is near 0: normalising by Yref would
 * blow up.) */
RAD_API double rad_anim_error_changed(const rad_mesh *mesh, const unsigned char *mask,
                                      const double *B, const double *Bref,
                                      const double *Bprev);
/* mask[i] = 1 for the `fraction` (at least one) of the elements with
 * present[i] (NULL: all) whose A_i |Y_i - Yprev_i| is largest: the
 * patches a change alters most, for eq. 7 over them. */
RAD_API void rad_anim_most_changed(const rad_mesh *mesh, const unsigned char *present,
                                   const double *B, const double *Bprev, double fraction,
                                   unsigned char *mask);

#ifdef __cplusplus
}
#endif

#endif /* RAD_ANIMATE_H */
