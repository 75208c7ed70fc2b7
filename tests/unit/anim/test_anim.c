/* test_anim.c -- scenes that change: radiosity redistribution, frame by frame.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The anim module (src/anim/; George, Sillion & Greenberg 1990) on a
 * closed room of 24 elements whose ceiling emits, a floating box of 6
 * elements and an absent shade of 2.  Every coordinate and every move is a
 * binary fraction, so a move and its inverse give the same doubles back.
 * The change file, read with rad_changes_parse, makes these frames:
 *
 *   1  the box moves               5  the lamp's emission x (1/2, 0, 3)
 *   2  it moves back               6  the lamp as it was, the shade added
 *   3  no change                   7  the shade removed: frame 0's scene
 *   4  the lamp's emission x 2
 *
 * Independent reference: each frame's scene, made here by applying the
 * change file to a copy of the scene (rad_changes_apply), meshed afresh
 * (its present part, rad_scene_present_copy), F filled (rad_ff_matrix)
 * and solved by LU (rad_solve, gauss).  F depends on the geometry alone,
 * so a frame whose mesh is an earlier frame's to the bit (a move back, a
 * material change) takes that frame's F instead of filling it again.
 *
 * The bound.  With nothing left to redistribute, a converged frame obeys
 * B = E + rho H with H = F S, S = B - dB the radiosity shot so far and dB
 * the unshot radiosity (animshoot.c), so per band
 *     (I - rho F) B = E - rho F dB,   while   (I - rho F) B* = E
 * for the fresh B*, on the same F (the animation keeps F entry for entry
 * the F a fresh fill of the frame's scene computes, animpairs.c).  Hence
 *     B - B* = -sum_{m>=1} (rho F)^m dB.
 * In the power norm |v|_A = sum_i A_i |v_i|, reciprocity A_i F_ij =
 * A_j F_ji gives
 *     |rho F v|_A <= sum_j |v_j| sum_i A_i rho_i |F_ij| <= q |v|_A,
 *     q = rho_max x the largest row sum of |F| (about rho_max: the room is
 *         closed; |F| for classic accuracy, whose F_ij may be below 0),
 * so |B_b - B*_b|_A <= q / (1 - q) |dB_b|_A in each band b.  Summed over
 * the bands, sum_b |dB_b|_A is the unshot power U, and a converged frame
 * has U <= tolerance x max(its emitted power, frame 0's) (animate.h).  So
 *     sum_b |B_b - B*_b|_A <= beta = q / (1 - q) x tolerance x scale,
 * an area-weighted L1 distance over every element and band, which is what
 * is checked (element by element it gives |B_ib - B*_ib| <= beta / A_i,
 * weaker).  Round-off comes on top: ROUND (below) times |B*|_A.
 *
 * Energy balance per band, the sums of rad_solve_report: emitted sum A E,
 * absorbed sum A (1 - rho) H, escaped sum A B (1 - sum_j F_ij), H = F B.
 * Reciprocity makes sum_i A_i (F B)_i = sum_j A_j B_j sum_i F_ji, so
 *     emitted - absorbed - escaped = -sum_i A_i (B - E - rho F B)_i
 *                                  = -sum_i A_i (rho F dB)_i,
 * at most q |dB_b|_A <= q x tolerance x scale in magnitude.
 *
 * Linearity in E: each band's system is linear in E, so with the lamp's
 * emission times k_b the fresh solution is k_b B*_b (the same F and rho),
 * and sum_b |B_b - k_b B0_b|_A <= beta + max_b k_b x beta_0.
 * Reversibility: a frame whose scene is frame 0's to the bit has frame 0's
 * F and B*, so |B - B0|_A <= beta + beta_0.
 *
 * The other orders of shots (strategy 2, shooters only, the paper's
 * importance) are checked against fresh solves in classic accuracy, which
 * also takes classic mode's own choice of the pairs to recompute
 * (animpairs.c).  Run time: the fills of default accuracy dominate (about
 * 0.2 s each on 30 elements): 3 for the references, 1 and the recomputed
 * pairs of 4 frames for the animation; classic fills cost an eighth of
 * that.  The whole test takes under 2 s on one core.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "radiosity/changes.h"
#include "radiosity/animate.h"
#include "../tap.h"

/* A room of 1 x 1 x 1, walls inward, 2 x 2 elements each (the ceiling
 * emits); a box of side 1/4 floating in it, one element per face; a
 * double-sided shade under the ceiling, absent until frame 6. */
static const char *SCENE =
    "material white reflect 0.7 0.6 0.5\n"
    "material red reflect 0.6 0.1 0.1\n"
    "material lamp reflect 0.4 emit 2 1.5 1\n"
    "material grey reflect 0.5\n"
    "quad red 0 0 0  0 1 0  0 1 1  0 0 1 mesh 2x2\n"
    "quad white 1 0 0  1 0 1  1 1 1  1 1 0 mesh 2x2\n"
    "quad white 0 0 0  0 0 1  1 0 1  1 0 0 mesh 2x2\n"
    "quad lamp 0 1 0  1 1 0  1 1 1  0 1 1 mesh 2x2\n"
    "quad white 0 0 0  1 0 0  1 1 0  0 1 0 mesh 2x2\n"
    "quad white 0 0 1  0 1 1  1 1 1  1 0 1 mesh 2x2\n"
    "object box\n"
    "  quad grey 0.25 0.125 0.25  0.25 0.125 0.5  0.25 0.375 0.5  0.25 0.375 0.25\n"
    "  quad grey 0.5 0.125 0.25  0.5 0.375 0.25  0.5 0.375 0.5  0.5 0.125 0.5\n"
    "  quad grey 0.25 0.125 0.25  0.5 0.125 0.25  0.5 0.125 0.5  0.25 0.125 0.5\n"
    "  quad grey 0.25 0.375 0.25  0.25 0.375 0.5  0.5 0.375 0.5  0.5 0.375 0.25\n"
    "  quad grey 0.25 0.125 0.25  0.25 0.375 0.25  0.5 0.375 0.25  0.5 0.125 0.25\n"
    "  quad grey 0.25 0.125 0.5  0.5 0.125 0.5  0.5 0.375 0.5  0.25 0.375 0.5\n"
    "end\n"
    "object shade absent\n"
    "  quad grey 0.375 0.75 0.375  0.625 0.75 0.375  0.625 0.75 0.625  0.375 0.75 0.625\n"
    "  quad grey 0.375 0.75 0.375  0.375 0.75 0.625  0.625 0.75 0.625  0.625 0.75 0.375\n"
    "end\n";

static const char *CHANGES = "# frame 1: the box moves\n"
                             "frame\n"
                             "move box 0.25 0.25 0.125\n"
                             "# 2: back where it was\n"
                             "frame\n"
                             "move box -0.25 -0.25 -0.125\n"
                             "# 3: nothing\n"
                             "frame\n"
                             "# 4: the lamp's emission x 2\n"
                             "frame\n"
                             "material lamp reflect 0.4 emit 4 3 2\n"
                             "# 5: x (1/2, 0, 3), band by band\n"
                             "frame\n"
                             "material lamp reflect 0.4 emit 1 0 3\n"
                             "# 6: the lamp as it was, the shade comes\n"
                             "frame\n"
                             "material lamp reflect 0.4 emit 2 1.5 1\n"
                             "add shade\n"
                             "# 7: the shade goes\n"
                             "frame\n"
                             "remove shade\n";

enum { NFRAMES = 8 };           /* frames 0..7 */
enum { NROOM = 24, NBOX = 6, NSHADE = 2 };

static const char *const WHAT[NFRAMES] = {
    "frame 0 (as given)",          "frame 1 (box moved)",
    "frame 2 (box moved back)",    "frame 3 (no change)",
    "frame 4 (lamp x 2)",          "frame 5 (lamp x 1/2, 0, 3)",
    "frame 6 (lamp back, shade added)", "frame 7 (shade removed)"};

/* The animation's tolerance: 100 times ROUND, so that the bound it gives
 * is the one the checks test. */
#define TOLERANCE 1e-10

/* Round-off on top of beta, relative to |B*|_A.  B and H are sums that
 * every shot adds one rounded term to (up to about 800 shots a frame
 * here, some 4700 over the animation, never reset between converged
 * frames): one rounding of 2^-53 per shot gives about 5e-13 of |B|.  LU's
 * backward error is a small multiple of n 2^-53 (n = 32), far less.
 * 1e-12 covers both and is 1/100 of the tolerance. */
#define ROUND 1e-12

/* ---- the fresh solves -------------------------------------------------- */

typedef struct fresh {
    rad_mesh mesh;              /* of the frame's present surfaces */
    int n;
    double *F, *B;
    double q;                   /* rho_max x the largest row sum of |F| */
    double norm;                /* |B*|_A summed over the bands */
    int filled;                 /* 1: F filled for this frame, 0: an earlier
                                   frame's, the mesh being the same */
} fresh;

static void fresh_free(fresh *fr)
{
    rad_mesh_free(&fr->mesh);
    free(fr->F);
    free(fr->B);
    memset(fr, 0, sizeof *fr);
}

/* The same geometry to the bit: every element's vertices. */
static int same_geometry(const rad_mesh *a, const rad_mesh *b)
{
    if (a->nelements != b->nelements)
        return 0;
    for (int e = 0; e < a->nelements; e++) {
        if (a->elements[e].nverts != b->elements[e].nverts)
            return 0;
        for (int v = 0; v < a->elements[e].nverts; v++) {
            const rad_vec3 p = rad_mesh_vertex(a, e, v), r = rad_mesh_vertex(b, e, v);
            if (p.x != r.x || p.y != r.y || p.z != r.z)
                return 0;
        }
    }
    return 1;
}

/* Mesh, F and LU solve of the present part of `scene`; F taken from one
 * of the `nprev` earlier solves whose geometry is the same. */
static rad_status fresh_solve(fresh *fr, const rad_scene *scene, rad_accuracy accuracy,
                              const fresh *prev, int nprev, rad_error *err)
{
    rad_scene ps;
    rad_ff_options fo;
    rad_solve_options so;
    memset(fr, 0, sizeof *fr);
    rad_status st = rad_scene_present_copy(scene, NULL, &ps, err);
    if (st != RAD_OK)
        return st;
    st = rad_mesh_build(&fr->mesh, &ps, err);
    rad_scene_free(&ps);
    if (st != RAD_OK)
        return st;
    const int n = fr->n = fr->mesh.nelements;
    fr->F = malloc(sizeof *fr->F * (size_t)n * n);
    fr->B = malloc(sizeof *fr->B * (size_t)n * RAD_BANDS);
    if (!fr->F || !fr->B) {
        snprintf(err->message, sizeof err->message, "out of memory");
        return err->status = RAD_ERR_NOMEM;
    }
    int k = 0;
    while (k < nprev && !same_geometry(&prev[k].mesh, &fr->mesh))
        k++;
    if (k < nprev) {
        memcpy(fr->F, prev[k].F, sizeof *fr->F * (size_t)n * n);
    } else {
        rad_ff_options_init(&fo);
        fo.accuracy = accuracy;
        if ((st = rad_ff_matrix(&fr->mesh, &fo, fr->F, NULL, NULL, err)) != RAD_OK)
            return st;
        fr->filled = 1;
    }
    rad_solve_options_init(&so);
    so.solver = RAD_SOLVER_GAUSS;
    if ((st = rad_solve(&fr->mesh, fr->F, &so, fr->B, NULL, err)) != RAD_OK)
        return st;
    double rho_max = 0, row_max = 0;
    for (int i = 0; i < n; i++) {
        const rad_element *el = &fr->mesh.elements[i];
        double row = 0;
        for (int j = 0; j < n; j++)
            row += fabs(fr->F[i + (size_t)j * n]); /* classic may have F_ij < 0 */
        row_max = fmax(row_max, row);
        for (int b = 0; b < RAD_BANDS; b++) {
            rho_max = fmax(rho_max, el->reflect[b]);
            fr->norm += el->area * fabs(fr->B[i + (size_t)b * n]);
        }
    }
    fr->q = rho_max * row_max;
    return RAD_OK;
}

/* The fresh solves of frames 0..NFRAMES-1: the scene parsed again and the
 * change file applied to it, frame after frame. */
static int fresh_frames(fresh *fr, const rad_changes *ch, rad_accuracy accuracy,
                        const char *what)
{
    rad_scene s;
    rad_error err;
    int f = 0, fills = 0;
    memset(&err, 0, sizeof err);
    rad_status st = rad_scene_parse(&s, SCENE, strlen(SCENE), "room.scene", &err);
    for (; st == RAD_OK && f < NFRAMES; f++) {
        if (f > 0)
            rad_changes_apply(&s, ch, f, NULL);
        st = fresh_solve(&fr[f], &s, accuracy, fr, f, &err);
        fills += fr[f].filled;
    }
    rad_scene_free(&s);
    tap_ok(st == RAD_OK, "%s: fresh solves of the %d frames' scenes, %d fills of F (%s)", what,
           NFRAMES, fills, st ? err.message : "ok");
    return st == RAD_OK;
}

/* ---- distances and checks ---------------------------------------------- */

/* sum_b sum_i A_i |X_ib - k_b Y_ib| (k NULL: 1). */
static double dist_A(const rad_mesh *m, const double *X, const double *Y, const double *k)
{
    const size_t n = (size_t)m->nelements;
    double s = 0;
    for (size_t i = 0; i < n; i++)
        for (int b = 0; b < RAD_BANDS; b++)
            s += m->elements[i].area * fabs(X[i + b * n] - (k ? k[b] : 1) * Y[i + b * n]);
    return s;
}

/* beta of the header: q / (1 - q) x tolerance x scale. */
static double beta(const fresh *fr, double scale)
{
    return fr->q / (1 - fr->q) * TOLERANCE * scale;
}

/* The animation's present result numbers its elements as the fresh mesh:
 * the same centroids, areas and materials in the same order. */
static int same_elements(const rad_mesh *x, const rad_mesh *y)
{
    if (x->nelements != y->nelements)
        return 0;
    for (int e = 0; e < x->nelements; e++) {
        const rad_element *p = &x->elements[e], *r = &y->elements[e];
        if (fabs(p->area - r->area) > 1e-12 * r->area ||
            fabs(p->centroid.x - r->centroid.x) > 1e-12 ||
            fabs(p->centroid.y - r->centroid.y) > 1e-12 ||
            fabs(p->centroid.z - r->centroid.z) > 1e-12)
            return 0;
        for (int b = 0; b < RAD_BANDS; b++)
            if (p->reflect[b] != r->reflect[b] || p->emit[b] != r->emit[b])
                return 0;
    }
    return 1;
}

/* One frame of the default animation. */
typedef struct frame_out {
    rad_anim_report rep;
    double *B;                  /* the animation's B, present numbering */
    double scale;               /* max(emitted, frame 0's emitted) */
    double beta;
} frame_out;

/* The frame the animation is at against its fresh solve: the numbering,
 * the report, B within beta (+ round-off), the energy balance per band.
 * out->rep is the frame's report; fills the rest of out. */
static void check_frame(const rad_anim *an, int f, const fresh *fr, double emitted0,
                        frame_out *out)
{
    rad_error err;
    rad_mesh pm;
    const int n = fr->n;
    const rad_anim_report *rep = &out->rep;
    out->B = NULL;
    out->scale = fmax(rep->emitted, emitted0);
    out->beta = beta(fr, out->scale);
    if (rad_anim_present_result(an, &pm, &out->B, &err) != RAD_OK) {
        tap_ok(0, "%s: the present result (%s)", WHAT[f], err.message);
        return;
    }
    const int aligned = same_elements(&pm, &fr->mesh);
    rad_mesh_free(&pm);
    tap_ok(aligned && rad_anim_frame(an) == f && rep->frame == f,
           "%s: the present result numbers its %d elements as a fresh solve does", WHAT[f], n);
    if (!aligned) {
        free(out->B);
        out->B = NULL;
        return;
    }
    double emitted = 0;
    for (int i = 0; i < n; i++)
        for (int b = 0; b < RAD_BANDS; b++)
            emitted += fr->mesh.elements[i].area * fr->mesh.elements[i].emit[b];
    tap_ok(rep->converged && rep->unshot <= TOLERANCE * out->scale &&
               fabs(rep->emitted - emitted) <= 1e-12 * emitted,
           "%s: converged, unshot %.3g <= tolerance x %g; emitted %g, the scene's", WHAT[f],
           rep->unshot, out->scale, rep->emitted);
    const double d = dist_A(&fr->mesh, out->B, fr->B, NULL);
    tap_ok(d <= out->beta + ROUND * fr->norm,
           "%s: |B - B_fresh|_A = %.3g <= beta %.3g (q %.3f) + round-off %.2g", WHAT[f], d,
           out->beta, fr->q, ROUND * fr->norm);
    /* emitted = absorbed + escaped, band by band, H = F B on the fresh F */
    double worst = 0;
    int ok = 1;
    for (int b = 0; b < RAD_BANDS; b++) {
        const double *Bb = out->B + (size_t)b * n;
        double em = 0, ab = 0, es = 0, mag = 0;
        for (int i = 0; i < n; i++) {
            const rad_element *el = &fr->mesh.elements[i];
            double H = 0, row = 0;
            for (int j = 0; j < n; j++) {
                H += fr->F[i + (size_t)j * n] * Bb[j];
                row += fr->F[i + (size_t)j * n];
            }
            em += el->area * el->emit[b];
            ab += el->area * (1 - el->reflect[b]) * H;
            es += el->area * Bb[i] * (1 - row);
            mag += el->area * fabs(Bb[i]);
        }
        const double lim = fr->q * TOLERANCE * out->scale + ROUND * mag;
        const double gap = fabs(em - ab - es);
        worst = fmax(worst, gap / lim);
        ok &= gap <= lim;
    }
    tap_ok(ok, "%s: emitted = absorbed + escaped in each band, the worst gap %.2f of its "
           "bound q x tolerance x %g", WHAT[f], worst, out->scale);
}

/* ---- the animation, default options -------------------------------------- */

/* What the direct light's stage of frame 1 left (rad_anim_options.
 * direct_first): B after its last shot, present numbering. */
typedef struct direct_seen {
    double *B;
    int shots, last, other;     /* its shots, its last ones, its shots of
                                   another kind than redistribution */
    int lamp4, first4;          /* frame 4 (the lamp x 2): the direct stage's
                                   shots, and the first of them a propagation
                                   (the lamp's first shot) */
} direct_seen;

static int see_direct(void *user, const rad_anim_shot *shot)
{
    direct_seen *d = user;
    if (shot->frame == 4 && shot->direct && d->lamp4++ == 0)
        d->first4 = !shot->redistribute && shot->power > 0;
    if (shot->frame != 1 || !shot->direct)
        return 0;
    d->shots++;
    d->other += !shot->redistribute;
    if (shot->direct == 2 && d->last++ == 0) {
        rad_mesh pm;
        rad_error err;
        if (rad_anim_present_result(shot->anim, &pm, &d->B, &err) == RAD_OK)
            rad_mesh_free(&pm);
    }
    return 0;
}

/* Frame 1's direct stage against its own equations: after it, element i
 * holds B0_i + rho_i sum_j (F1_ij - F0_ij) T_j over the pairs with a lamp
 * element (i's or j's), T = B0 - dB0 (George et al. 1990, eq. 5), F0 and
 * F1 the fresh fills of frames 0 and 1.  T = B0 within frame 0's unshot
 * power (a beta0 at most, q x tolerance x scale), and a pair the move
 * cannot alter keeps F0 where a fresh fill of frame 1 may differ in its
 * last bits (within 2e-8 of the entry, animpairs.c): these bound the gap,
 * with round-off.  The light's change is most of the move's: the gap
 * must be small against |B1 - B0|_A, what the stage did not do yet. */
static void check_direct(const direct_seen *d, const fresh *fr, const frame_out *out)
{
    const fresh *f0 = &fr[0], *f1 = &fr[1];
    const int n = f0->n;
    tap_ok(d->B && d->last == 1 && d->other == 0 && d->shots >= 1 &&
               d->shots <= out[1].rep.redistribution_shots,
           "frame 1: the direct light's stage shot %d redistribution steps (of %ld), the last "
           "one marked once", d->shots, out[1].rep.redistribution_shots);
    if (!d->B || f1->n != n)
        return;
    double *want = malloc(sizeof *want * (size_t)n * RAD_BANDS), moved = 0;
    for (int i = 0; want && i < n; i++) {
        const rad_element *ei = &f1->mesh.elements[i];
        for (int b = 0; b < RAD_BANDS; b++) {
            double x = 0;
            for (int j = 0; j < n; j++) {
                const size_t k = (size_t)i + (size_t)j * n;
                const rad_element *ej = &f1->mesh.elements[j];
                if (ei->emit[0] > 0 || ej->emit[0] > 0) /* George et al. 1990, eq. 5 */
                    x += (f1->F[k] - f0->F[k]) * out[0].B[j + (size_t)b * n];
            }
            want[i + (size_t)b * n] = out[0].B[i + (size_t)b * n] + ei->reflect[b] * x;
        }
    }
    if (!want) {
        tap_ok(0, "frame 1's direct stage: memory");
        return;
    }
    const double gap = dist_A(&f1->mesh, d->B, want, NULL);
    const double lim = out[0].beta + (2e-8 + ROUND) * f0->norm;
    moved = dist_A(&f1->mesh, out[1].B, out[0].B, NULL);
    const double direct = dist_A(&f1->mesh, want, out[0].B, NULL);
    tap_ok(gap <= lim && direct > 0.5 * moved && gap < 1e-3 * direct,
           "frame 1: after the direct stage |B - (B0 + rho dF_lit T)|_A = %.3g <= %.3g; the "
           "stage's change %.3g of the frame's %.3g", gap, lim, direct, moved);
    free(want);
}

static void run_default(const rad_scene *scene, const rad_changes *ch, const fresh *fr)
{
    rad_anim_options ao;
    rad_anim_report rep;
    rad_error err;
    rad_anim *an = NULL;
    frame_out out[NFRAMES];
    memset(out, 0, sizeof out);
    direct_seen seen;
    memset(&seen, 0, sizeof seen);
    rad_anim_options_init(&ao);
    ao.tolerance = TOLERANCE;
    ao.on_shot = see_direct;
    ao.shot_user = &seen;
    rad_status st = rad_anim_create(&an, scene, &ao, &out[0].rep, &err);
    tap_ok(st == RAD_OK, "rad_anim_create solves frame 0 (%ld shots) (%s)", out[0].rep.shots,
           st ? err.message : "ok");
    if (st)
        return;
    const int nall = rad_anim_mesh(an)->nelements;
    const unsigned char *pr = rad_anim_present(an);
    const double *Ball = rad_anim_radiosity(an);
    int absent = 0, zero = 1;
    for (int e = 0; e < nall; e++)
        if (!pr[e]) {
            absent++;
            for (int b = 0; b < RAD_BANDS; b++)
                zero &= Ball[e + (size_t)b * nall] == 0;
        }
    tap_ok(nall == NROOM + NBOX + NSHADE && absent == NSHADE && zero,
           "the animation meshes all %d elements, the absent shade's %d too, whose B is 0", nall,
           absent);
    check_frame(an, 0, &fr[0], out[0].rep.emitted, &out[0]);
    const double emitted0 = out[0].rep.emitted;
    for (int f = 1; f < NFRAMES; f++) {
        st = rad_anim_next(an, ch, &out[f].rep, &err);
        tap_ok(st == RAD_OK, "rad_anim_next: %s, %ld shots (%ld redistribution), %.0f pairs "
               "recomputed (%s)", WHAT[f], out[f].rep.shots, out[f].rep.redistribution_shots,
               out[f].rep.pairs_recomputed, st ? err.message : "ok");
        if (st)
            goto done;
        check_frame(an, f, &fr[f], emitted0, &out[f]);
    }
    memset(&err, 0, sizeof err);
    st = rad_anim_next(an, ch, &rep, &err);
    tap_ok(st == RAD_ERR_INVALID && rad_anim_frame(an) == NFRAMES - 1,
           "after the last frame, rad_anim_next refuses (%s)", err.message);

    for (int f = 0; f < NFRAMES; f++)
        if (!out[f].B) {
            tap_ok(0, "every frame's B for the comparisons between frames");
            goto done;
        }
    /* frames 0, 2, 3, 4, 5 and 7 share frame 0's mesh: fr[f].n == fr[0].n */
    const rad_mesh *m0 = &fr[0].mesh;
    const size_t bytes = sizeof *out[0].B * (size_t)fr[0].n * RAD_BANDS;
    const double round0 = ROUND * fr[0].norm;
    double d = dist_A(&fr[1].mesh, out[1].B, out[0].B, NULL);
    tap_ok(d > 1e3 * (out[1].beta + out[0].beta) && out[1].rep.redistribution_shots > 0,
           "the move changes B (|B1 - B0|_A = %.3g), with redistribution shots", d);
    check_direct(&seen, fr, out);
    /* reversibility */
    double lim = out[2].beta + out[0].beta;
    d = dist_A(m0, out[2].B, out[0].B, NULL);
    tap_ok(d <= lim + 2 * round0,
           "moved and moved back: |B2 - B0|_A = %.3g <= beta2 + beta0 = %.3g (+ round-off)", d,
           lim);
    lim = out[7].beta + out[0].beta;
    d = dist_A(m0, out[7].B, out[0].B, NULL);
    tap_ok(d <= lim + 2 * round0,
           "lamp back, shade added, shade removed: |B7 - B0|_A = %.3g <= %.3g (+ round-off)", d,
           lim);
    /* a frame without change */
    tap_ok(memcmp(out[3].B, out[2].B, bytes) == 0,
           "a frame without change leaves B as it was, bit for bit");
    tap_ok(out[3].rep.shots == 0 && out[3].rep.pairs_recomputed == 0,
           "... with no shot (%ld) and no pair recomputed (%.0f)", out[3].rep.shots,
           out[3].rep.pairs_recomputed);
    /* linearity in E */
    const double k2[RAD_BANDS] = {2, 2, 2}, kb[RAD_BANDS] = {0.5, 0, 3};
    lim = out[4].beta + 2 * out[0].beta;
    d = dist_A(m0, out[4].B, out[0].B, k2);
    tap_ok(d <= lim + 3 * round0,
           "the lamp's emission x 2: |B4 - 2 B0|_A = %.3g <= beta4 + 2 beta0 = %.3g", d, lim);
    lim = out[5].beta + 3 * out[0].beta;
    d = dist_A(m0, out[5].B, out[0].B, kb);
    tap_ok(d <= lim + 4 * round0,
           "the lamp's emission x (1/2, 0, 3): |B5 - k B0|_A = %.3g <= beta5 + 3 beta0 = %.3g",
           d, lim);
    tap_ok(out[4].rep.redistribution_shots == 0 && out[4].rep.pairs_recomputed == 0,
           "a change of emission recomputes no form factor and redistributes nothing");
    tap_ok(seen.first4 && seen.lamp4 >= 1,
           "... its direct stage is the lamp's changed emission shot first (%d shots)",
           seen.lamp4);
done:
    for (int f = 0; f < NFRAMES; f++)
        free(out[f].B);
    free(seen.B);
    rad_anim_free(an);
}

/* ---- the other orders of shots, in classic accuracy ------------------------ */

/* Every frame converged and within its bound of the fresh solve. */
static void run_variant(const rad_scene *scene, const rad_changes *ch, const fresh *fr,
                        const char *what, int strategy, int gather, int importance,
                        int direct_first)
{
    rad_anim_options ao;
    rad_anim_report rep;
    rad_error err;
    rad_anim *an = NULL;
    rad_anim_options_init(&ao);
    ao.ff.accuracy = RAD_ACCURACY_CLASSIC;
    ao.tolerance = TOLERANCE;
    ao.strategy = strategy;
    ao.gather = gather;
    ao.importance = importance;
    ao.direct_first = direct_first;
    double worst = 0, emitted0 = 0;
    int ok = 1, f = 0;
    rad_status st = rad_anim_create(&an, scene, &ao, &rep, &err);
    while (st == RAD_OK) {
        rad_mesh pm;
        double *B = NULL;
        if (f == 0)
            emitted0 = rep.emitted;
        if ((st = rad_anim_present_result(an, &pm, &B, &err)) != RAD_OK)
            break;
        const double lim = beta(&fr[f], fmax(rep.emitted, emitted0)) + ROUND * fr[f].norm;
        const double d = same_elements(&pm, &fr[f].mesh) ? dist_A(&pm, B, fr[f].B, NULL)
                                                         : INFINITY;
        worst = fmax(worst, d / lim);
        ok &= rep.converged && d <= lim;
        free(B);
        rad_mesh_free(&pm);
        if (++f == NFRAMES)
            break;
        st = rad_anim_next(an, ch, &rep, &err);
    }
    tap_ok(st == RAD_OK && ok && f == NFRAMES,
           "classic, %s: all %d frames converged within their bound of a fresh classic solve "
           "(the worst at %.2f of it)%s%s", what, f, worst, st ? ": " : "",
           st ? err.message : "");
    rad_anim_free(an);
}

/* ---- a frame stopped in its direct light's stage ------------------------- */

static int stop_in_direct(void *user, const rad_anim_shot *shot)
{
    int *stops = user;
    if (shot->frame == 1 && shot->direct) {
        ++*stops;
        return 1;
    }
    return 0;
}

/* Frame 1 interrupted at its first direct shot: the frame's other form
 * factors are still recomputed (the state stays whole), so frame 2, run
 * after it, is within its bound of a fresh classic solve. */
static void run_interrupted(const rad_scene *scene, const rad_changes *ch, const fresh *fr)
{
    rad_anim_options ao;
    rad_anim_report rep;
    rad_error err;
    rad_anim *an = NULL;
    int stops = 0;
    rad_anim_options_init(&ao);
    ao.ff.accuracy = RAD_ACCURACY_CLASSIC;
    ao.tolerance = TOLERANCE;
    ao.on_shot = stop_in_direct;
    ao.shot_user = &stops;
    rad_status st = rad_anim_create(&an, scene, &ao, &rep, &err);
    const double emitted0 = rep.emitted;
    rad_status st1 = st == RAD_OK ? rad_anim_next(an, ch, &rep, &err) : st;
    tap_ok(st1 == RAD_ERR_INVALID && stops == 1,
           "classic: frame 1 stopped at its first direct shot (%s)", err.message);
    st = st == RAD_OK ? rad_anim_next(an, ch, &rep, &err) : st;
    rad_mesh pm;
    double *B = NULL;
    if (st == RAD_OK)
        st = rad_anim_present_result(an, &pm, &B, &err);
    const double lim = beta(&fr[2], fmax(rep.emitted, emitted0)) + ROUND * fr[2].norm;
    double d = INFINITY;
    if (st == RAD_OK) {
        d = same_elements(&pm, &fr[2].mesh) ? dist_A(&pm, B, fr[2].B, NULL) : INFINITY;
        rad_mesh_free(&pm);
    }
    tap_ok(st == RAD_OK && rep.converged && d <= lim,
           "classic: frame 2 after it converges within its bound of a fresh solve (%.3g <= "
           "%.3g)%s%s", d, lim, st ? ": " : "", st ? err.message : "");
    free(B);
    rad_anim_free(an);
}

int main(void)
{
    rad_scene scene;
    rad_changes ch;
    rad_error err;
    fresh fr[NFRAMES], fc[NFRAMES];
    memset(fr, 0, sizeof fr);
    memset(fc, 0, sizeof fc);
    memset(&ch, 0, sizeof ch);
    rad_status st = rad_scene_parse(&scene, SCENE, strlen(SCENE), "room.scene", &err);
    tap_ok(st == RAD_OK && scene.nobjects == 2 && scene.objects[1].absent,
           "the room parses, with a box and an absent shade (%s)", st ? err.message : "ok");
    if (st)
        return tap_done();
    st = rad_changes_parse(&ch, &scene, CHANGES, strlen(CHANGES), "room.changes", &err);
    tap_ok(st == RAD_OK && ch.nframes == NFRAMES - 1, "the change file parses: %d frames (%s)",
           ch.nframes, st ? err.message : "ok");
    if (st == RAD_OK && ch.nframes == NFRAMES - 1 &&
        fresh_frames(fr, &ch, RAD_ACCURACY_DEFAULT, "default accuracy")) {
        tap_ok(fr[0].n == NROOM + NBOX && fr[6].n == NROOM + NBOX + NSHADE && fr[0].q < 1 &&
                   same_geometry(&fr[2].mesh, &fr[0].mesh) &&
                   !same_geometry(&fr[1].mesh, &fr[0].mesh),
               "the references: %d elements, %d with the shade; the move back is frame 0's "
               "mesh to the bit; q = %.4f < 1", fr[0].n, fr[6].n, fr[0].q);
        run_default(&scene, &ch, fr);
    }
    if (st == RAD_OK && ch.nframes == NFRAMES - 1 &&
        fresh_frames(fc, &ch, RAD_ACCURACY_CLASSIC, "classic accuracy")) {
        run_variant(&scene, &ch, fc, "the default order", 1, 1, RAD_ANIM_IMPORTANCE_EXACT, 1);
        run_variant(&scene, &ch, fc, "all pairs at once (no direct light first)", 1, 1,
                    RAD_ANIM_IMPORTANCE_EXACT, 0);
        run_variant(&scene, &ch, fc, "strategy 2 (the larger shot first)", 2, 1,
                    RAD_ANIM_IMPORTANCE_EXACT, 1);
        run_variant(&scene, &ch, fc, "shooters only (no gather)", 1, 0,
                    RAD_ANIM_IMPORTANCE_EXACT, 1);
        run_variant(&scene, &ch, fc, "the paper's importance estimate", 1, 1,
                    RAD_ANIM_IMPORTANCE_PAPER, 1);
        run_interrupted(&scene, &ch, fc);
    }
    for (int f = 0; f < NFRAMES; f++) {
        fresh_free(&fr[f]);
        fresh_free(&fc[f]);
    }
    rad_changes_free(&ch);
    rad_scene_free(&scene);
    return tap_done();
}
