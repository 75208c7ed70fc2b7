/* animshoot.c -- the shots of an animation: propagation and redistribution.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * State (animint.h), per element i and band b: B (radiosity), dB (unshot
 * radiosity), H (what it has gathered, sum_j F_ij S_j with S = B - dB the
 * radiosity shot so far) and rho, E, so that B_i = E_i + rho_i H_i always
 * (Goral et al. 1984, eq. 6, with the shot part of B on the right).
 *
 * Propagation shot of j (Cohen et al. 1988, eq. 4 and fig. 3): every i
 * receives F_ij dB_j (reciprocity, A_i F_ij = A_j F_ji, turns "j gives
 * rho_i dB_j F_ji A_j / A_i" into this): H_i += F_ij dB_j, and B_i, dB_i
 * grow by rho_i F_ij dB_j; then dB_j = 0.  dB may be negative (energy
 * taken back): the same shot, the other sign.
 *
 * Redistribution shot of j (George, Sillion & Greenberg 1990, eq. 2-6):
 * when F changes to F + dF, what j had shot, T_j = B_j - dB_j at the
 * change, went along the old F; the correction is the shot of T_j along
 * dF: H_i += dF_ij T_j, B_i and dB_i grow by rho_i dF_ij T_j, positive
 * toward elements j now sees better, negative toward those now hidden.
 * Partly converged solutions thus redistribute B_j - dB_j only (eq. 6).
 *
 * Power, the yardstick of ordering and stopping, is A times radiosity
 * summed over the bands (a power per unit of the radiometric unit): the
 * unshot power U = sum_j A_j sum_b |dB_j,b|; the power of j's pending
 * redistribution sum_i A_i |dF_ij| sum_b rho_i,b |T_j,b|.  A frame is
 * converged when nothing is left to redistribute and U is at most
 * tolerance x the emitted power (that of frame 0 when larger: a frame
 * whose lights were all removed converges to B = 0 on that scale).
 *
 * A redistribution step is either a shooter's (all its pending entries,
 * the paper's shot) or, with opt.gather, a receiver's: all pending entries
 * into one element at once, the same terms summed by rows.  A patch that a
 * new object covers has received light from every patch of the room; the
 * paper takes it back one shooter at a time, a gather in one step.
 *
 * Order (George et al. 1990, section "Ordering", Fig. 4): emitters whose
 * emission changed shoot first; then strategy 1 takes every
 * redistribution step (largest pending power first, shooter or receiver:
 * the exact energy toward and away from the change, which the paper's
 * importance estimates from sample points; with opt.importance PAPER,
 * shooters only, in order of that estimate, animimportance.c) and then
 * propagates; strategy 2 takes at each step the larger of the largest
 * pending redistribution (power or estimate) and the largest unshot
 * power.  The direct light's stage of a frame (animate.c) takes the
 * first shots and the redistribution steps of what is pending, in the
 * same order, and no other shot.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "anim/animint.h"
#include "util/util.h"

double radi_anim_unshot(const rad_anim *a)
{
    double u = 0;
    for (int j = 0; j < a->n; j++) {
        double s = 0;
        for (int b = 0; b < RAD_BANDS; b++)
            s += fabs(a->dB[j + (size_t)b * a->n]);
        u += a->mesh.elements[j].area * s;
    }
    return u;
}

double radi_anim_emitted(const rad_anim *a)
{
    double e = 0;
    for (int j = 0; j < a->n; j++)
        for (int b = 0; b < RAD_BANDS; b++)
            e += a->mesh.elements[j].area * a->E[j + (size_t)b * a->n];
    return e;
}

/* Receiver i gets x (per band) of gathered radiosity. */
void radi_anim_receive(rad_anim *a, int i, const double x[RAD_BANDS])
{
    const size_t n = (size_t)a->n;
    for (int b = 0; b < RAD_BANDS; b++) {
        const size_t k = (size_t)i + b * n;
        const double r = a->rho[k] * x[b];
        a->H[k] += x[b];
        a->B[k] += r;
        a->dB[k] += r;
    }
}

/* Propagation shot of j (Cohen et al. 1988, eq. 4); its signed power. */
static double propagate(rad_anim *a, int j)
{
    const size_t n = (size_t)a->n;
    double d[RAD_BANDS], p = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        d[b] = a->dB[j + b * n];
        a->dB[j + b * n] = 0;
        p += d[b];
    }
    const double *col = a->F + (size_t)j * n; /* F_ij, i = 0..n-1 */
    for (int i = 0; i < a->n; i++) {
        const double f = col[i];
        if (f != 0) {
            double x[RAD_BANDS] = {f * d[0], f * d[1], f * d[2]};
            radi_anim_receive(a, i, x);
        }
    }
    return p * a->mesh.elements[j].area;
}

/* Apply the pending entry k of column j (receiver i gets dF_ij T_j, eq. 5);
 * its signed power. */
static double apply_entry(rad_anim *a, int j, size_t k)
{
    rad_redist *rd = &a->rd;
    const size_t n = (size_t)a->n;
    const int i = rd->recv[k];
    double x[RAD_BANDS], p = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        x[b] = rd->amt[3 * k + b]; /* dF_ij T_j, George et al. 1990, eq. 5 */
        p += a->mesh.elements[i].area * a->rho[i + b * n] * x[b];
    }
    radi_anim_receive(a, i, x);
    rd->done[k] = 1;
    rd->npending--;
    rd->left -= rd->epow[k];
    rd->power[j] = --rd->ncol[j] ? rd->power[j] - rd->epow[k] : 0;
    rd->rpower[i] = --rd->nrow[i] ? rd->rpower[i] - rd->epow[k] : 0;
    if (rd->npending == 0 || rd->left < 0)
        rd->left = 0; /* no round-off residue when nothing is pending */
    return p;
}

/* Redistribution shot of j (George et al. 1990, eq. 5): its pending
 * entries; their signed power. */
static double redistribute(rad_anim *a, int j)
{
    double p = 0;
    for (size_t k = a->rd.start[j]; k < a->rd.start[j + 1]; k++)
        if (!a->rd.done[k])
            p += apply_entry(a, j, k);
    return p;
}

/* The shooter of entry k: the column that holds it. */
static int column_of(const rad_redist *rd, int n, size_t k)
{
    int lo = 0, hi = n; /* start[lo] <= k < start[hi] */
    while (hi - lo > 1) {
        const int mid = lo + (hi - lo) / 2;
        if (rd->start[mid] <= k)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* Redistribution gathered by receiver i: every pending entry into i at
 * once (the same sum, taken by rows: a patch the change shadows or
 * uncovers is set right in one step instead of one shot per shooter). */
static double gather(rad_anim *a, int i)
{
    rad_redist *rd = &a->rd;
    double p = 0;
    for (size_t r = rd->rstart[i]; r < rd->rstart[i + 1]; r++) {
        const size_t k = rd->rent[r];
        if (!rd->done[k])
            p += apply_entry(a, column_of(rd, a->n, k), k);
    }
    return p;
}

/* The element with the largest unshot power, or -1 when all are 0. */
static int largest_unshot(const rad_anim *a, double *power)
{
    const size_t n = (size_t)a->n;
    int best = -1;
    *power = 0;
    for (int j = 0; j < a->n; j++) {
        double s = fabs(a->dB[j]) + fabs(a->dB[j + n]) + fabs(a->dB[j + 2 * n]);
        s *= a->mesh.elements[j].area;
        if (s > *power) {
            *power = s;
            best = j;
        }
    }
    return best;
}

/* The largest pending power among counts[] > 0: its index, or -1. */
static int largest_pending(const int *counts, const double *power, int n, double *best_power)
{
    int best = -1;
    *best_power = -1;
    for (int j = 0; j < n; j++)
        if (counts[j] > 0 && power[j] > *best_power) {
            *best_power = power[j];
            best = j;
        }
    return best;
}

/* Is an emitter waiting for its first shot? */
static int first_waiting(const rad_anim *a)
{
    for (int j = 0; j < a->n; j++)
        if (a->first[j])
            return 1;
    return 0;
}

/* The next shot: its kind (0 propagation, 1 redistribution by a shooter,
 * 2 gathered by a receiver) and element, or -1 when nothing is left;
 * with `direct`, the first shots and redistribution steps only. */
static int choose(rad_anim *a, int direct, int *kind)
{
    double pu = -1, pr = -1, pg = -1;
    for (int j = 0; j < a->n; j++)
        if (a->first[j]) {
            a->first[j] = 0;
            *kind = 0;
            return j;
        }
    const int u = direct ? -1 : largest_unshot(a, &pu);
    int r = -1, g = -1;
    const int paper = a->opt.importance == RAD_ANIM_IMPORTANCE_PAPER;
    if (a->rd.npending > 0) {
        r = largest_pending(a->rd.ncol, paper ? a->imp : a->rd.power, a->n, &pr);
        if (a->opt.gather && !paper)
            g = largest_pending(a->rd.nrow, a->rd.rpower, a->n, &pg);
    }
    const int red = g >= 0 && pg > pr ? g : r;
    const double pred = g >= 0 && pg > pr ? pg : pr;
    if (red >= 0 && (a->opt.strategy != 2 || pred >= pu || u < 0)) {
        *kind = red == g && pg > pr ? 2 : 1;
        return red;
    }
    *kind = 0;
    return u;
}

rad_status radi_anim_shoot(rad_anim *a, int how, long budget, rad_anim_report *rep,
                          rad_error *err)
{
    const int partial = how == RADI_SHOOT_PARTIAL, direct = how == RADI_SHOOT_DIRECT;
    const double emitted = radi_anim_emitted(a);
    const double scale = emitted > a->emitted0 ? emitted : a->emitted0;
    double unshot = radi_anim_unshot(a);
    /* the log's final pass numbers its shots on from the frame's (animate.c,
     * close_log), and has max_shots of its own */
    const long first = rep->shots;
    long step = first;
    rep->emitted = emitted;
    for (;;) {
        if (direct && a->rd.npending == 0 && !first_waiting(a))
            break;
        if (a->rd.npending == 0 && unshot <= a->opt.tolerance * scale) {
            rep->converged = 1;
            break;
        }
        if (partial && a->opt.steps > 0 && step >= a->opt.steps)
            break;
        if (step - first >= budget)
            return radi_fail(err, RAD_ERR_NOCONV, "frame %d: not converged after %ld shots "
                            "(unshot power %.3g of %.3g emitted)", a->frame, step, unshot,
                            scale);
        int kind, j = choose(a, direct, &kind);
        if (j < 0 && direct)
            break;
        if (j < 0 && a->rd.npending == 0) {
            rep->converged = 1; /* nothing left to shoot at all */
            break;
        }
        const int redist = kind != 0;
        double p = kind == 2 ? gather(a, j) : kind == 1 ? redistribute(a, j) : propagate(a, j);
        step++;
        rep->redistribution_shots += redist;
        rep->propagation_shots += !redist;
        unshot = radi_anim_unshot(a);
        if (a->opt.on_shot) {
            rad_anim_shot s = {a->frame, step, j, redist, p < 0 ? -1 : 1, fabs(p), unshot,
                               a->rd.left, kind == 2, a,
                               direct ? 1 + (a->rd.npending == 0 && !first_waiting(a)) : 0};
            if (a->opt.on_shot(a->opt.shot_user, &s))
                return radi_fail(err, RAD_ERR_INVALID, "interrupted");
        }
    }
    rep->shots = step;
    rep->unshot = unshot;
    return RAD_OK;
}
