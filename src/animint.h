/* animint.h -- the state of an animation, shared by its files (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * animate.c owns the state and the frames, animpairs.c the form factors a
 * change alters, animshoot.c the shots.  Arrays of n x RAD_BANDS are
 * column-major (x[e + b*n]); F is n x n, F[i + j*n] = F_ij.
 */
#ifndef RAD_ANIMINT_H
#define RAD_ANIMINT_H

#include <stddef.h>

#include "radiosity/animate.h"

/* The redistribution a change calls for (George et al. 1990, eq. 5): for
 * each shooter j with T_j != 0, the receivers i and dF_ij = F_ij(t) -
 * F_ij(t-1), in compressed columns: receivers of j are
 * recv[start[j] .. start[j+1]).  The same entries are indexed by receiver
 * (rent[rstart[i] .. rstart[i+1]) are the entries into i), so that either
 * a shooter shoots all its pending entries or a receiver gathers all of
 * its own; done[] marks the entries applied. */
typedef struct rad_redist {
    size_t *start;              /* n + 1 */
    int *recv;
    double *dF;
    double *T;                  /* n x 3: what j had shot when F changed */
    double *epow;               /* per entry: A_i sum_b rho_i |dF_ij T_j| */
    unsigned char *done;        /* per entry */
    size_t *rstart, *rent;      /* the entries by receiver */
    double *power, *rpower;     /* n: pending power per shooter, per receiver */
    int *ncol, *nrow;           /* n: pending entries per shooter, per receiver */
    size_t npending;            /* pending entries */
    double left;                /* their power */
} rad_redist;

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
};

/* animpairs.c: recompute, in F, every pair that moving the objects flagged
 * in `dirty` (their boxes before, old_lo/old_hi with old_in[o], and now)
 * can alter, set up a->rd from T = B - dB, and count pairs into rep. */
rad_status rad_anim_update_pairs(rad_anim *a, const unsigned char *dirty,
                                 const unsigned char *old_in, const rad_vec3 *old_lo,
                                 const rad_vec3 *old_hi, rad_anim_report *rep, rad_error *err);
/* The box of object o's surfaces in a->scene. */
void rad_anim_object_box(const rad_anim *a, int o, rad_vec3 *lo, rad_vec3 *hi);
void rad_redist_free(rad_redist *rd);

/* animshoot.c: shoot until converged (or opt.steps shots when `partial`). */
rad_status rad_anim_shoot(rad_anim *a, int partial, rad_anim_report *rep, rad_error *err);
/* Apply every pending redistribution shot at once. */
void rad_anim_flush(rad_anim *a);
/* sum_j A_j sum_b |dB_j| and sum_j A_j sum_b E_j. */
double rad_anim_unshot(const rad_anim *a);
double rad_anim_emitted(const rad_anim *a);

#endif /* RAD_ANIMINT_H */
