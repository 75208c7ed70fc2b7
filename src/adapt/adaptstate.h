/* adaptstate.h -- the state of an adaptive solve, shared by its two files.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * adaptive.c shoots; adaptsplit.c splits.  Both keep one invariant per
 * patch P (a starting element, the only shooters):
 *     Bbar_P = S_P + dB_P                                          (*)
 * with Bbar_P the area mean of B over P's leaves (area A_P, the starting
 * element's), S_P the radiosity P has shot so far and dB_P its unshot
 * radiosity.  Shooting moves d from dB_P to S_P and adds what each leaf
 * receives to its patch's mean and unshot radiosity alike; a split
 * re-reads the mean from the new leaves and sets dB_P = Bbar_P - S_P.
 */
#ifndef RAD_ADAPTSTATE_H
#define RAD_ADAPTSTATE_H

#include "adapt/adaptnodes.h"
#include "fill/fill.h"
#include "radiosity/base.h"
#include "radiosity/solve.h"

typedef struct rad_adapt_state {
    const rad_adapt_nodes *a;
    const rad_solve_options *opt;
    rad_ffrow *row;             /* form factors between nodes, on the fly */
    int nn, np;                 /* nodes, patches */
    unsigned char *leaf;        /* 1: the node is an element now */
    double *B;                  /* nn x NB, column-major: B of leaves (and of
                                   split nodes, their last value) */
    double *dB, *S;             /* np x NB: unshot and shot radiosity */
    double *list_f;             /* scratch: factors for a receiver list */
    int *list;                  /* scratch: receiver nodes */
    int splits;                 /* nodes split so far */
    rad_error *err;
} rad_adapt_state;

/* B of node k, band b. */
static inline double *radi_adapt_b(rad_adapt_state *s, int k, int b)
{
    return &s->B[(size_t)k + (size_t)b * (size_t)s->nn];
}

/* After patch `shooter` shot: split every leaf whose B differs from an edge
 * neighbour's by more than the threshold, level by level down to the
 * depth; the new leaves gather from every patch that has shot (adaptsplit.c). */
rad_status radi_adapt_subdivide(rad_adapt_state *s);

/* Set dB_P = Bbar_P - S_P from P's leaves (the invariant (*)). */
void radi_adapt_patch_reset(rad_adapt_state *s, int p);

#endif /* RAD_ADAPTSTATE_H */
