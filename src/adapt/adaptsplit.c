/* adaptsplit.c -- adaptive subdivision: which elements split, and what the
 * new ones receive.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen, Chen, Wallace & Greenberg 1988, section 4 ("Adaptive
 * subdivision"): after a patch shoots, elements where the radiosity
 * varies too much across neighbours are subdivided, the form factors from
 * the patch to the new elements are computed and the patch's radiosity is
 * shot to them again.  Here:
 *
 *   test   leaf j (of a quad surface, level < D) is split when, in some
 *          band b, |B_j - B_k| > T Bmax_b for an edge neighbour k on the
 *          same surface (a leaf whose square shares a segment of j's
 *          boundary), T = opt->subdivide_threshold and Bmax_b the largest
 *          reflected radiosity B - E of any leaf (the brightest lit
 *          surface: lamps would make the test blind to everything they
 *          light).  A difference relative to the pair's own values was
 *          tried first and refines dark regions where the error is
 *          small: on data/blocker.scene it needed 736 elements for the
 *          area-weighted RMS error the scene-relative test reaches with
 *          667 (tests/papers/adaptive.sh).
 *          With opt->subdivide_by_error the bound is T Bmax_b sqrt(A0 /
 *          A_j), A0 the area of the largest starting element that can
 *          split: the difference is weighted by the leaf's side h
 *          relative to that element's, |B_j - B_k| h/H.  Why:
 *          B varying linearly with gradient g across a square of side h
 *          has variance g^2 h^2 / 12 about its mean, so the element's
 *          share of the squared area-weighted RMS (Cohen et al. 1988,
 *          eq. 14) is g^2 h^4 / 12, and splitting it into four removes
 *          3/4 of that, g^2 h^4 / 16 = (g h)^2 h^2 / 16 with g h about
 *          the neighbour difference.  A bound on the difference alone
 *          evens out g h (every element as far from its neighbours), the
 *          weighted one evens out the gain of a split, which is what
 *          spends a given number of elements best on this error (h is
 *          the side itself, not the level, as surfaces start with
 *          elements of different sizes).  On data/blocker.scene it
 *          reaches the uniform 16 x 16 mesh's RMS with 508 elements,
 *          the plain test with 556, the best quadtree with 439; under a
 *          small lamp's sharp shadow 400, 460 and 319 (tests/papers/adaptive.sh,
 *          which computes the best any quadtree can do).
 *          The test is run again on the new
 *          leaves until none exceeds T or all are at depth D, so one shot
 *          can refine a shadow edge to the finest level.
 *   split  j's four children become leaves.  Each child c receives from
 *          every patch P that has shot so far, with its own factor:
 *              B_c = E_c + rho_c sum_P S_P F_cP                        (1)
 *          (S_P the radiosity P has shot in all its shots, adaptstate.h).
 *          That is the paper's re-shooting of the last patch's radiosity
 *          to the new elements, done for every earlier shot as well, so
 *          that a new element is what it would be had it existed from
 *          the start: "new elements receive from all patches that shot
 *          before".  F_cP = F_{c, root P} is computed by the form-factor
 *          rows (ffrow.h), reciprocity and visibility as for any pair.
 *   patch  the split changes its patch's mean radiosity; dB_P is set from
 *          the invariant (*) of adaptstate.h, so the difference is shot
 *          later (it may be negative: the parent's one factor over- or
 *          under-estimated what its children receive), and energy is
 *          conserved: the limit solves the patch-element system
 *              B_j = E_j + rho_j sum_P F_jP Bbar_P                     (2)
 *          on the final leaves (Cohen et al. 1988, section 3.4).
 *
 * Neighbours are found on the finest lattice: the cells just outside each
 * side of j's square, each mapped to the leaf covering it by descending
 * the quadtree (at most D + 1 steps).
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adapt/adaptstate.h"
#include "util/util.h"

#define NB RAD_BANDS

/* The leaf covering lattice cell (x, y) of surface s. */
static int leaf_at(const rad_adapt_state *s, int surf, int x, int y)
{
    for (int l = 0; l <= s->a->depth; l++) {
        const int k = radi_adapt_at(s->a, surf, l, x, y);
        if (s->leaf[k])
            return k;
    }
    return -1;
}

/* Does B differ between leaves j and k by more than T times the scale? */
static int differs(rad_adapt_state *s, int j, int k, double T, const double scale[NB])
{
    for (int b = 0; b < NB; b++) {
        const double x = *radi_adapt_b(s, j, b), y = *radi_adapt_b(s, k, b);
        if (fabs(x - y) > T * scale[b])
            return 1;
    }
    return 0;
}

/* The scale of the test: the largest reflected radiosity B - E of a leaf,
 * per band (the brightest lit surface, lamps not counted). */
static void test_scale(rad_adapt_state *s, double scale[NB])
{
    for (int b = 0; b < NB; b++) {
        scale[b] = 0;
        for (int j = 0; j < s->nn; j++)
            if (s->leaf[j])
                scale[b] = fmax(scale[b], *radi_adapt_b(s, j, b) -
                                              s->a->mesh.elements[j].emit[b]);
    }
}

/* The area of the error test: the largest starting element that can split. */
static double test_area(const rad_adapt_state *s)
{
    double A0 = 0;
    for (int p = 0; p < s->np; p++) {
        const rad_element *e = &s->a->mesh.elements[s->a->root[p]];
        if (s->a->splits[e->surface])
            A0 = fmax(A0, e->area);
    }
    return A0;
}

/* Is leaf j to be split: some edge neighbour differs by more than T
 * (A0: the area the error test weights against, test_area). */
static int wants_split(rad_adapt_state *s, int j, const double scale[NB], double A0)
{
    const rad_adapt_nodes *a = s->a;
    const int surf = a->mesh.elements[j].surface;
    const int NF = a->mesh.surface_n[surf], MF = a->mesh.surface_m[surf];
    int x0, y0, w;
    if (!a->splits[surf] || a->level[j] >= a->depth)
        return 0;
    /* the bound on |B_j - B_k|: T, or T sqrt(A0 / A_j) with subdivide_by_error */
    const double T = s->opt->subdivide_threshold *
                     (s->opt->subdivide_by_error ? sqrt(A0 / a->mesh.elements[j].area) : 1);
    radi_adapt_box(a, j, &x0, &y0, &w);
    for (int side = 0; side < 4; side++) {
        /* the cells outside the side: a row (sides 0, 2) or a column (1, 3) */
        const int x = side == 1 ? x0 + w : side == 3 ? x0 - 1 : x0;
        const int y = side == 0 ? y0 - 1 : side == 2 ? y0 + w : y0;
        if (x < 0 || y < 0 || x >= NF || y >= MF)
            continue;
        for (int t = 0; t < w;) {
            const int cx = side % 2 ? x : x + t, cy = side % 2 ? y + t : y;
            const int k = leaf_at(s, surf, cx, cy);
            int kx, ky, kw;
            if (k < 0)
                break;
            if (differs(s, j, k, T, scale))
                return 1;
            radi_adapt_box(a, k, &kx, &ky, &kw);
            t = side % 2 ? ky + kw - y0 : kx + kw - x0; /* past that neighbour */
        }
    }
    return 0;
}

/* Add A_k B_k of the leaves under node r (its subtree, level by level). */
static void subtree_power(rad_adapt_state *s, int r, double sum[NB])
{
    const rad_adapt_nodes *a = s->a;
    const int surf = a->mesh.elements[r].surface;
    int x0, y0, w;
    if (!a->splits[surf]) { /* a polygon: one node */
        for (int b = 0; b < NB; b++)
            sum[b] += a->mesh.elements[r].area * *radi_adapt_b(s, r, b);
        return;
    }
    radi_adapt_box(a, r, &x0, &y0, &w);
    for (int l = a->level[r]; l <= a->depth; l++) {
        const int step = 1 << (a->depth - l);
        for (int y = y0; y < y0 + w; y += step)
            for (int x = x0; x < x0 + w; x += step) {
                const int k = radi_adapt_at(a, surf, l, x, y);
                for (int b = 0; b < NB && s->leaf[k]; b++)
                    sum[b] += a->mesh.elements[k].area * *radi_adapt_b(s, k, b);
            }
    }
}

void radi_adapt_patch_reset(rad_adapt_state *s, int p)
{
    const int r = s->a->root[p];
    const double Ap = s->a->mesh.elements[r].area;
    double power[NB] = {0, 0, 0};
    subtree_power(s, r, power);
    for (int b = 0; b < NB; b++)
        s->dB[(size_t)p + (size_t)b * s->np] = power[b] / Ap - s->S[(size_t)p + (size_t)b * s->np];
}

/* The new leaves list[0..k): B = E + rho sum_P S_P F_cP (eq. 1 above). */
static rad_status gather(rad_adapt_state *s, int k)
{
    const rad_adapt_nodes *a = s->a;
    for (int q = 0; q < k; q++)
        for (int b = 0; b < NB; b++)
            *radi_adapt_b(s, s->list[q], b) = a->mesh.elements[s->list[q]].emit[b];
    for (int p = 0; p < s->np; p++) {
        const double *Sp = s->S + p;
        const size_t np = (size_t)s->np;
        if (Sp[0] == 0 && Sp[np] == 0 && Sp[2 * np] == 0)
            continue;
        rad_status st = radi_ffrow_pairs(s->row, a->root[p], s->list, k, s->list_f, s->err);
        if (st != RAD_OK)
            return st;
        for (int q = 0; q < k; q++) {
            const rad_element *el = &a->mesh.elements[s->list[q]];
            for (int b = 0; b < NB; b++)
                *radi_adapt_b(s, s->list[q], b) += el->reflect[b] * Sp[b * np] * s->list_f[q];
        }
    }
    return RAD_OK;
}

/* One round: split every leaf that wants it; *any = how many split. */
static rad_status split_round(rad_adapt_state *s, unsigned char *mark, int *any)
{
    const rad_adapt_nodes *a = s->a;
    int k = 0;
    double scale[NB];
    *any = 0;
    const double A0 = test_area(s);
    test_scale(s, scale);
    for (int j = 0; j < s->nn; j++)
        mark[j] = s->leaf[j] && wants_split(s, j, scale, A0);
    for (int j = 0; j < s->nn; j++) {
        if (!mark[j])
            continue;
        s->leaf[j] = 0;
        for (int c = 0; c < 4; c++) {
            s->list[k] = radi_adapt_child(a, j, c);
            s->leaf[s->list[k++]] = 1;
        }
        ++*any;
    }
    if (k == 0)
        return RAD_OK;
    s->splits += *any;
    rad_status st = gather(s, k);
    for (int q = 0; q < k && st == RAD_OK; q += 4) /* once per split parent */
        radi_adapt_patch_reset(s, a->patch[s->list[q]]);
    return st;
}

rad_status radi_adapt_subdivide(rad_adapt_state *s)
{
    if (s->a->depth == 0)
        return RAD_OK;
    unsigned char *mark = malloc((size_t)s->nn);
    if (!mark)
        return radi_fail(s->err, RAD_ERR_NOMEM, "out of memory for adaptive subdivision");
    rad_status st = RAD_OK;
    for (int round = 0; round < s->a->depth && st == RAD_OK; round++) {
        int any;
        st = split_round(s, mark, &any);
        if (!any)
            break;
    }
    free(mark);
    return st;
}
