/* animint.h -- the state of an animation, shared by its files (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * animate.c owns the state and the frames, animframe.c the scene a frame
 * meshes, animpairs.c the form factors a change alters, animshoot.c the
 * shots.  Arrays of n x RAD_BANDS are column-major (x[e + b*n]); F is
 * n x n, F[i + j*n] = F_ij.
 */
#ifndef RAD_ANIMINT_H
#define RAD_ANIMINT_H

#include <stddef.h>
#include <stdio.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/animate.h"

/* The redistribution a change calls for (George et al. 1990, eq. 5): for
 * each shooter j with T_j != 0, the receivers i and the amount i still
 * has to gather from j, amt = dF_ij T_j per band (dF_ij = F_ij(t) -
 * F_ij(t-1)), in compressed columns: receivers of j are
 * recv[start[j] .. start[j+1]).  Amounts left over from earlier frames
 * (--steps) are merged into the new ones pair by pair (the change log,
 * animlog.c), so a pair carries one pending amount however often it
 * changed since the last converged frame.  The same entries are indexed by receiver
 * (rent[rstart[i] .. rstart[i+1]) are the entries into i), so that either
 * a shooter shoots all its pending entries or a receiver gathers all of
 * its own; done[] marks the entries applied. */
typedef struct rad_redist {
    size_t *start;              /* n + 1 */
    int *recv;
    double *amt;                /* per entry x RAD_BANDS: amt[3k + b] */
    double *epow;               /* per entry: A_i sum_b rho_i |dF_ij T_j| */
    unsigned char *done;        /* per entry */
    size_t *rstart, *rent;      /* the entries by receiver */
    double *power, *rpower;     /* n: pending power per shooter, per receiver */
    int *ncol, *nrow;           /* n: pending entries per shooter, per receiver */
    size_t npending;            /* pending entries */
    double left;                /* their power */
} rad_redist;

/* A sample point on a changed object (animimportance.c). */
typedef struct rad_anim_sample {
    rad_vec3 centroid, normal;
    double area;
} rad_anim_sample;

struct rad_anim {
    rad_scene scene;            /* every surface, as moved; current materials */
    rad_anim_options opt;
    rad_mesh mesh;              /* of every surface */
    int n;
    int frame;
    int *elem_object;           /* n: object of the element, or -1 */
    unsigned char *obj_present; /* nobjects */
    unsigned char *present;     /* n */
    double *F;                  /* n x n; rows and columns of absent elements 0 */
    double *B, *dB, *H;         /* n x 3: radiosity, unshot, gathered F S */
    double *rho, *E;            /* n x 3: 0 for absent elements */
    double emitted0;            /* frame 0's emitted power, the scale of the
                                   tolerance when lights go */
    rad_redist rd;
    unsigned char *first;       /* n: emitters that shoot first this frame */
    double *imp;                /* n: the paper's importance estimate (with
                                   opt.importance, animimportance.c) */
    /* The change log (animlog.c, George et al. 1990, Fig. 5). */
    int converged_frame;        /* the last frame that converged */
    int log_open;               /* a frame since then stopped unconverged */
    unsigned char *log_obj;     /* nobjects: changed since converged_frame */
    double log_residual;        /* largest |F S - H| / |H| the last pass removed */
};

/* Which of the pairs a change alters one call recomputes: all, those
 * with an element flagged in `lit` (the direct light's), or the others. */
enum { RADI_PAIRS_ALL = 0, RADI_PAIRS_LIT = 1, RADI_PAIRS_UNLIT = 2 };

/* animpairs.c: recompute, in F, the pairs of `which` that moving the
 * objects flagged in `dirty` (their boxes before, old_lo/old_hi with
 * old_in[o], and now) can alter, set up a->rd from T = B - dB merged with
 * what is pending, and count them into rep (pairs_recomputed,
 * pairs_changed and, with opt.time_changed, t_changed).  old_scene: the present surfaces before the
 * change (rad_scene_present_copy), needed in classic mode only (NULL
 * elsewhere).  lit: n flags, read unless which is RADI_PAIRS_ALL. */
rad_status radi_anim_update_pairs(rad_anim *a, const unsigned char *dirty,
                                 const unsigned char *old_in, const rad_vec3 *old_lo,
                                 const rad_vec3 *old_hi, const rad_scene *old_scene,
                                 const unsigned char *lit, int which, rad_anim_report *rep,
                                 rad_error *err);
/* A deep copy of the scene, every surface, each object's presence kept
 * (animframe.c). */
rad_status radi_anim_copy_scene(rad_scene *out, const rad_scene *in, rad_error *err);
/* err, the mesh's refusal of frame `frame`, put on the line of ch to
 * blame: the frame's last move or rotate, else its first change. */
void radi_anim_blame_changes(const rad_changes *ch, int frame, rad_error *err);
/* The box of object o's surfaces in a->scene. */
void radi_anim_object_box(const rad_anim *a, int o, rad_vec3 *lo, rad_vec3 *hi);
void radi_redist_free(rad_redist *rd);
/* Index rd's columns (start, recv, amt filled) by receiver, with their
 * powers and pending counts. */
rad_status radi_anim_redist_index(rad_anim *a, rad_error *err);

/* How far radi_anim_shoot goes: until converged; until converged or
 * opt.steps shots (a partial frame); the direct light's stage
 * (animate.c): the first shots of emitters whose emission changed, then
 * redistribution steps until nothing is left to redistribute, and no
 * other shot. */
enum { RADI_SHOOT_CONVERGE = 0, RADI_SHOOT_PARTIAL = 1, RADI_SHOOT_DIRECT = 2 };

/* animshoot.c: shoot as `how` says (RADI_SHOOT_*), at most `budget` shots
 * (RAD_ERR_NOCONV past them); rep's shots, counts and unshot power
 * follow, and rep->converged is set when the frame is. */
rad_status radi_anim_shoot(rad_anim *a, int how, long budget, rad_anim_report *rep,
                          rad_error *err);
/* Receiver i gathers x (per band): H, B and dB grow (animshoot.c). */
void radi_anim_receive(rad_anim *a, int i, const double x[RAD_BANDS]);

/* animimportance.c: a->imp for every shooter from the samples on the
 * frame's changed objects (`dirty`). */
void radi_anim_importance(rad_anim *a, const unsigned char *dirty, const rad_anim_sample *s,
                         int ns);

/* animlog.c: the log's final pass: every present row's H set to F S
 * exactly (S = B - dB), the difference propagated like any received
 * radiosity; and the log closed on a converged frame. */
void radi_anim_log_pass(rad_anim *a);
/* Read the log's state (after its header, radi_anim_log_header) into a,
 * whose scene, mesh and F are those of the log's frame. */
rad_status radi_anim_log_body(rad_anim *a, FILE *in, const char *name, int *line,
                             rad_error *err);
/* The log's header: its frame and element count. */
rad_status radi_anim_log_header(FILE *in, const char *name, int *line, int *frame, int *n,
                               rad_error *err);
/* sum_j A_j sum_b |dB_j| and sum_j A_j sum_b E_j. */
double radi_anim_unshot(const rad_anim *a);
double radi_anim_emitted(const rad_anim *a);

#endif /* RAD_ANIMINT_H */
