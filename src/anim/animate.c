/* animate.c -- scenes that change, frame by frame (George et al. 1990).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Design.  The animation meshes EVERY surface once, absent objects' too,
 * so that an element keeps its index through all frames; a presence flag
 * per element says which are in the scene.  An absent element has rho = E
 * = 0, B = dB = H = 0 and a zero row and column of F: it neither gives
 * nor takes.  One dense F (n x n, that of one solve) is kept up to date in
 * place; the form factors of a frame are always those a fresh solve of
 * its scene would compute (animpairs.c).
 *
 * A frame (rad_anim_next):
 *   1. what the previous frame left to redistribute (with --steps) stays
 *      pending: the change log (animlog.c) merges it pair by pair with
 *      what this frame's changes call for;
 *   2. the frame's changes are applied to the scene copy in file order
 *      (a move, a rotation, add, remove, a material); a series of changes
 *      to one object is recorded as one removal from where it was and one
 *      addition where it ends (the change log of George et al. 1990,
 *      Fig. 5): only the object's box before and after matter;
 *   3. the mesh is rebuilt (same elements, new positions, materials);
 *   4. the pairs the dirty objects can alter are recomputed into F, and
 *      dF with T = B - dB is kept for the redistribution (animpairs.c);
 *      with opt.direct_first, in a frame that converges, in two stages:
 *      (a) the pairs with an element that emits, before or after the
 *      change; those elements restated (step 5); their shots at once:
 *      the first shot of a light added or whose emission changed, and
 *      the redistribution of what the lights had shot (their new
 *      shadows, what they newly light); then (b) the other pairs, most of
 *      the form factors' time, and the other elements restated.  So the
 *      lights' part of the change is in B before stage (b) runs.  Stage
 *      (b)'s pairs have no emitter at either end, so their dF T takes T
 *      of non-emitters only, and stage (a)'s shots leave that T as it
 *      was: a shot's receivers gain as much in B as in dB (animshoot.c),
 *      restating leaves T = B - dB of a present element alone, and only
 *      the shooter of a first shot, an emitter, changes its own T.  The
 *      frame converges to the same B, its shots in another order;
 *   5. elements whose rho or E changed (material changes, additions)
 *      restate B = E + rho H, the difference going to dB (their own
 *      correction, propagated by the shots); removed elements drop to 0
 *      and the energy they had shot is taken back by their redistribution
 *      shots (dF_ij = -F_ij);
 *   6. shots (animshoot.c) until converged, or for --steps K shots;
 *   7. a frame that converges after unconverged ones runs the log's final
 *      pass (animlog.c) and closes the log.
 * With these rules the state obeys B = E + rho (F S - dF T) per element
 * before the redistribution and B = E + rho F S after it, S = B - dB
 * (George et al. 1990, eq. 2-6), so a converged frame solves the frame's
 * radiosity system (Goral et al. 1984, eq. 6) to the tolerance.
 *
 * Units: those of radiosity.h; how a change moves, turns, adds, removes or
 * recolours is changeapply.c's.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "anim/animint.h"
#include "util/util.h"


void rad_anim_options_init(rad_anim_options *opt)
{
    memset(opt, 0, sizeof *opt);
    rad_ff_options_init(&opt->ff);
    opt->tolerance = 1e-12;
    opt->strategy = 1;
    opt->gather = 1;
    opt->direct_first = 1;
}

int rad_anim_frame(const rad_anim *a) { return a->frame; }
const rad_scene *rad_anim_scene(const rad_anim *a) { return &a->scene; }
const rad_mesh *rad_anim_mesh(const rad_anim *a) { return &a->mesh; }
const unsigned char *rad_anim_present(const rad_anim *a) { return a->present; }
const double *rad_anim_radiosity(const rad_anim *a) { return a->B; }

void rad_anim_free(rad_anim *a)
{
    if (!a)
        return;
    rad_scene_free(&a->scene);
    rad_mesh_free(&a->mesh);
    radi_redist_free(&a->rd);
    free(a->elem_object);
    free(a->obj_present);
    free(a->present);
    free(a->F);
    free(a->B);
    free(a->dB);
    free(a->H);
    free(a->rho);
    free(a->E);
    free(a->first);
    free(a->log_obj);
    free(a->imp);
    free(a);
}

/* ---- element state ------------------------------------------------------- */

/* presence, rho and E per element from the scene and mesh; flags in
 * `changed` the elements whose presence, rho or E differ from before. */
static void element_state(rad_anim *a, unsigned char *changed)
{
    const size_t n = (size_t)a->n;
    for (int e = 0; e < a->n; e++) {
        const rad_element *el = &a->mesh.elements[e];
        const int o = a->elem_object[e];
        const unsigned char in = o < 0 || a->obj_present[o];
        int diff = in != a->present[e];
        a->present[e] = in;
        for (int b = 0; b < RAD_BANDS; b++) {
            double r = in ? el->reflect[b] : 0, x = in ? el->emit[b] : 0;
            diff |= r != a->rho[e + b * n] || x != a->E[e + b * n];
            a->rho[e + b * n] = r;
            a->E[e + b * n] = x;
        }
        if (changed)
            changed[e] = (unsigned char)diff;
    }
}

/* Step 5 of the header: B = E + rho H for changed elements (those of
 * `only` too when it is not NULL), 0 if absent; changed emitters shoot
 * first.  Their changed flag is cleared. */
static void restate(rad_anim *a, unsigned char *changed, const unsigned char *only)
{
    const size_t n = (size_t)a->n;
    for (int e = 0; e < a->n; e++) {
        if (!changed[e] || (only && !only[e]))
            continue;
        changed[e] = 0;
        for (int b = 0; b < RAD_BANDS; b++) {
            const size_t k = (size_t)e + b * n;
            if (!a->present[e]) {
                a->B[k] = a->dB[k] = a->H[k] = 0;
                continue;
            }
            const double nb = a->E[k] + a->rho[k] * a->H[k]; /* Goral et al. 1984, eq. 6 */
            a->dB[k] += nb - a->B[k];
            a->B[k] = nb;
            a->first[e] |= a->E[k] > 0;
        }
    }
}

/* ---- frame 0 ------------------------------------------------------------- */

static rad_status allocate(rad_anim *a, rad_error *err)
{
    const size_t n = (size_t)a->n, nb = n * RAD_BANDS + 1;
    if (rad_memory_check(8.0 * n * n + 64.0 * n, "the animation's form factors", NULL, err))
        return RAD_ERR_TOOBIG;
    a->F = calloc(n * n + 1, sizeof *a->F);
    a->B = calloc(nb, sizeof *a->B);
    a->dB = calloc(nb, sizeof *a->dB);
    a->H = calloc(nb, sizeof *a->H);
    a->rho = calloc(nb, sizeof *a->rho);
    a->E = calloc(nb, sizeof *a->E);
    a->first = calloc(n + 1, 1);
    a->present = calloc(n + 1, 1);
    a->elem_object = calloc(n + 1, sizeof *a->elem_object);
    a->obj_present = calloc((size_t)a->scene.nobjects + 1, 1);
    a->log_obj = calloc((size_t)a->scene.nobjects + 1, 1);
    a->imp = calloc(n + 1, sizeof *a->imp);
    if (!a->F || !a->B || !a->dB || !a->H || !a->rho || !a->E || !a->first || !a->present ||
        !a->elem_object || !a->obj_present || !a->log_obj || !a->imp)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for %zu elements", n);
    return RAD_OK;
}

/* F of the present elements by the full fill, scattered into a->F. */
static rad_status fill_frame0(rad_anim *a, rad_anim_report *rep, rad_error *err)
{
    rad_scene ps;
    rad_mesh pm;
    rad_status st = rad_scene_present_copy(&a->scene, a->obj_present, &ps, err);
    if (st != RAD_OK)
        return st;
    st = rad_mesh_build(&pm, &ps, err);
    const size_t np = st == RAD_OK ? (size_t)pm.nelements : 0, n = (size_t)a->n;
    double *Fp = np == n ? a->F : malloc(sizeof *Fp * (np * np + 1));
    if (st == RAD_OK && !Fp)
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for %zu elements", np);
    if (st == RAD_OK)
        st = rad_ff_matrix(&pm, &a->opt.ff, Fp, NULL, NULL, err);
    if (st == RAD_OK && Fp != a->F) {
        int *idx = malloc(sizeof *idx * (np + 1));
        if (!idx)
            st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
        for (size_t e = 0, k = 0; idx && e < n; e++)
            if (a->present[e])
                idx[k++] = (int)e;
        for (size_t j = 0; idx && j < np; j++)
            for (size_t i = 0; i < np; i++)
                a->F[idx[i] + idx[j] * n] = Fp[i + j * np];
        free(idx);
    }
    if (Fp != a->F)
        free(Fp);
    rep->pairs_recomputed = rep->pairs_total = 0.5 * (double)np * ((double)np - 1);
    rad_mesh_free(&pm);
    rad_scene_free(&ps);
    return st;
}

/* The animation at `frame` of `changes` (0: the scene as given), its F
 * filled as a fresh solve fills it; no radiosity yet. */
static rad_status setup(rad_anim **out, const rad_scene *scene, const rad_changes *changes,
                        int frame, const rad_anim_options *opt, rad_anim_report *rep,
                        rad_error *err)
{
    *out = NULL;
    rad_anim *a = calloc(1, sizeof *a);
    if (!a)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    a->opt = *opt;
    if (a->opt.max_shots <= 0)
        a->opt.max_shots = 1000L * (long)rad_scene_element_count(scene) + 100000L;
    rad_status st = radi_anim_copy_scene(&a->scene, scene, err);
    for (int f = 1; st == RAD_OK && f <= frame; f++)
        rad_changes_apply(&a->scene, changes, f, NULL);
    a->frame = a->converged_frame = frame;
    if (st == RAD_OK)
        st = rad_mesh_build(&a->mesh, &a->scene, err);
    a->n = a->mesh.nelements;
    if (st == RAD_OK)
        st = allocate(a, err);
    for (int o = 0; st == RAD_OK && o < a->scene.nobjects; o++)
        a->obj_present[o] = !a->scene.objects[o].absent;
    for (int e = 0; st == RAD_OK && e < a->n; e++)
        a->elem_object[e] = a->scene.surfaces[a->mesh.elements[e].surface].object;
    if (st == RAD_OK) {
        element_state(a, NULL);
        st = fill_frame0(a, rep, err);
    }
    if (st != RAD_OK) {
        rad_anim_free(a);
        return st;
    }
    *out = a;
    return RAD_OK;
}

rad_status rad_anim_create(rad_anim **out, const rad_scene *scene, const rad_anim_options *opt,
                           rad_anim_report *rep_out, rad_error *err)
{
    rad_anim_report rep;
    double t0 = radi_seconds();
    memset(&rep, 0, sizeof rep);
    rep.t_changed = NAN; /* frame 0 recomputes nothing */
    rad_anim *a;
    rad_status st = setup(&a, scene, NULL, 0, opt, &rep, err);
    rep.t_formfactor = radi_seconds() - t0;
    if (st == RAD_OK) { /* shooting from B = dB = E (Cohen et al. 1988) */
        memcpy(a->B, a->E, sizeof *a->B * (size_t)a->n * RAD_BANDS);
        memcpy(a->dB, a->E, sizeof *a->B * (size_t)a->n * RAD_BANDS);
        a->emitted0 = radi_anim_emitted(a);
        double t1 = radi_seconds();
        st = radi_anim_shoot(a, a->opt.partial_start ? RADI_SHOOT_PARTIAL : RADI_SHOOT_CONVERGE,
                             a->opt.max_shots, &rep, err);
        rep.t_shoot = radi_seconds() - t1;
        a->log_open = !rep.converged;
    }
    rep.t_total = radi_seconds() - t0;
    if (rep_out)
        *rep_out = rep;
    if (st != RAD_OK) {
        rad_anim_free(a);
        return st;
    }
    *out = a;
    return RAD_OK;
}

rad_status rad_anim_resume(rad_anim **out, const rad_scene *scene, const rad_changes *changes,
                           FILE *log, const char *logname, const rad_anim_options *opt,
                           rad_error *err)
{
    rad_anim_report rep;
    int line = 0, frame, n;
    memset(&rep, 0, sizeof rep);
    *out = NULL;
    rad_status st = radi_anim_log_header(log, logname, &line, &frame, &n, err);
    if (st == RAD_OK && frame > changes->nframes)
        st = radi_fail(err, RAD_ERR_PARSE, "%s:2: frame %d is beyond the change file's %d",
                      logname, frame, changes->nframes);
    if (st == RAD_OK && (double)n != rad_scene_element_count(scene))
        st = radi_fail(err, RAD_ERR_PARSE, "%s:3: %d elements, the scene has %.0f", logname, n,
                      (double)rad_scene_element_count(scene));
    rad_anim *a = NULL;
    if (st == RAD_OK)
        st = setup(&a, scene, changes, frame, opt, &rep, err);
    if (st == RAD_OK)
        st = radi_anim_log_body(a, log, logname, &line, err);
    if (st != RAD_OK) {
        rad_anim_free(a);
        return st;
    }
    *out = a;
    return RAD_OK;
}

/* ---- later frames -------------------------------------------------------- */

/* With the paper's importance: the samples of the objects the frame
 * changed, where they were (old mesh) and where they are (new mesh);
 * their count.  `out` holds 2 n. */
static int collect_samples(const rad_anim *a, const rad_mesh *now, const unsigned char *dirty,
                           const unsigned char *old_in, rad_anim_sample *out)
{
    int ns = 0;
    for (int e = 0; e < a->n; e++) {
        const int o = a->elem_object[e];
        if (o < 0 || !dirty[o])
            continue;
        const rad_element *was = &a->mesh.elements[e], *is = &now->elements[e];
        if (old_in[o])
            out[ns++] = (rad_anim_sample){was->centroid, was->normal, was->area};
        if (a->obj_present[o])
            out[ns++] = (rad_anim_sample){is->centroid, is->normal, is->area};
    }
    return ns;
}

/* Step 7: a frame that converged after unconverged ones runs the log's
 * final pass, shoots what it found, and the log starts anew here. */
static rad_status close_log(rad_anim *a, rad_anim_report *rep, rad_error *err)
{
    if (!rep->converged) {
        a->log_open = 1;
        return RAD_OK;
    }
    if (a->log_open) {
        rad_anim_report more;
        memset(&more, 0, sizeof more);
        more.shots = rep->shots; /* the trace's steps go on */
        radi_anim_log_pass(a);
        rep->log_pass = 1;
        rep->log_residual = a->log_residual;
        rad_status st = radi_anim_shoot(a, RADI_SHOOT_CONVERGE, a->opt.max_shots, &more, err);
        if (st != RAD_OK)
            return st;
        rep->shots = more.shots;
        rep->propagation_shots += more.propagation_shots;
        rep->unshot = more.unshot;
    }
    a->log_open = 0;
    a->converged_frame = a->frame;
    memset(a->log_obj, 0, (size_t)a->scene.nobjects);
    return RAD_OK;
}

/* Does element e emit (any band)? */
static int emits(const rad_anim *a, int e)
{
    const size_t n = (size_t)a->n;
    return a->E[e] > 0 || a->E[e + n] > 0 || a->E[e + 2 * n] > 0;
}

/* Does this frame take the direct light first (step 4)?  A frame that
 * converges, of strategy 1 (redistribution before propagation, which the
 * stages keep) in the exact order. */
static int staged(const rad_anim *a)
{
    return a->opt.direct_first && a->opt.steps == 0 && a->opt.strategy == 1 &&
           a->opt.importance == RAD_ANIM_IMPORTANCE_EXACT;
}

/* Steps 4 and 5: the pairs recomputed and the changed elements restated,
 * in one stage or two (the header); the counts of rep, *t_direct the
 * seconds of stage (a)'s shots and *shot how they ended.  A stage (a)
 * that stops (interrupted, out of shots) does not stop stage (b): F and
 * the state stay whole, as after a frame stopped in its last shots. */
static rad_status update(rad_anim *a, const unsigned char *dirty, const unsigned char *old_in,
                         const rad_vec3 *lo, const rad_vec3 *hi, const rad_scene *old_scene,
                         const unsigned char *lit, unsigned char *changed,
                         rad_anim_report *rep, double *t_direct, rad_status *shot,
                         rad_error *err)
{
    const int two = staged(a);
    const int which[2] = {two ? RADI_PAIRS_LIT : RADI_PAIRS_ALL, RADI_PAIRS_UNLIT};
    rad_status st = RAD_OK;
    *t_direct = 0;
    *shot = RAD_OK;
    for (int k = 0; st == RAD_OK && k < 1 + two; k++) {
        rad_anim_report part;
        memset(&part, 0, sizeof part);
        part.t_changed = NAN;
        st = radi_anim_update_pairs(a, dirty, old_in, lo, hi, old_scene, lit, which[k], &part,
                                   err);
        rep->pairs_recomputed += part.pairs_recomputed;
        rep->pairs_changed += part.pairs_changed;
        rep->t_changed = k == 0 ? part.t_changed : rep->t_changed + part.t_changed;
        if (st == RAD_OK && k == 0 && two) {
            restate(a, changed, lit);
            const double t = radi_seconds();
            *shot = radi_anim_shoot(a, RADI_SHOOT_DIRECT, a->opt.max_shots, rep, err);
            *t_direct = radi_seconds() - t;
        }
    }
    if (st == RAD_OK)
        restate(a, changed, NULL);
    return st;
}

rad_status rad_anim_next(rad_anim *a, const rad_changes *ch, rad_anim_report *rep,
                         rad_error *err)
{
    const int no = a->scene.nobjects, next = a->frame + 1;
    double t0 = radi_seconds();
    memset(rep, 0, sizeof *rep);
    rep->t_changed = NAN; /* measured by radi_anim_update_pairs with time_changed */
    if (next > ch->nframes)
        return radi_fail(err, RAD_ERR_INVALID, "there is no frame %d", next);
    unsigned char *dirty = calloc((size_t)no + 1, 1), *old_in = malloc((size_t)no + 1);
    unsigned char *changed = malloc((size_t)a->n + 1), *lit = malloc((size_t)a->n + 1);
    rad_vec3 *lo = malloc(sizeof *lo * (size_t)(no + 1)), *hi = malloc(sizeof *hi * (size_t)(no + 1));
    rad_mesh mesh;
    const int paper = a->opt.importance == RAD_ANIM_IMPORTANCE_PAPER;
    rad_anim_sample *smp = paper ? malloc(sizeof *smp * (2 * (size_t)a->n + 1)) : NULL;
    int ns = 0;
    rad_status st = dirty && old_in && changed && lit && lo && hi && (smp || !paper)
                        ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    for (int e = 0; st == RAD_OK && e < a->n; e++)
        lit[e] = (unsigned char)emits(a, e);
    for (int o = 0; st == RAD_OK && o < no; o++) {
        old_in[o] = a->obj_present[o];
        radi_anim_object_box(a, o, &lo[o], &hi[o]);
    }
    rad_scene old_scene; /* classic mode's routes (animpairs.c) */
    const int keep_old = a->opt.ff.accuracy == RAD_ACCURACY_CLASSIC;
    memset(&old_scene, 0, sizeof old_scene);
    if (st == RAD_OK && keep_old)
        st = rad_scene_present_copy(&a->scene, a->obj_present, &old_scene, err);
    if (st == RAD_OK) { /* step 2 */
        rad_changes_apply(&a->scene, ch, next, dirty);
        for (int o = 0; o < no; o++) {
            a->obj_present[o] = !a->scene.objects[o].absent;
            a->log_obj[o] |= dirty[o];
        }
    }
    if (st == RAD_OK && (st = rad_mesh_build(&mesh, &a->scene, err)) != RAD_OK)
        if (st != RAD_ERR_NOMEM)
            radi_anim_blame_changes(ch, next, err);
    if (st == RAD_OK) { /* 3 */
        if (mesh.nelements != a->n) {
            rad_mesh_free(&mesh);
            st = radi_fail(err, RAD_ERR_INVALID, "the mesh changed its element count");
        } else {
            ns = paper ? collect_samples(a, &mesh, dirty, old_in, smp) : 0;
            rad_mesh_free(&a->mesh);
            a->mesh = mesh;
        }
    }
    a->frame = next;
    rep->frame = next;
    double t_direct = 0;
    rad_status shot = RAD_OK;
    if (st == RAD_OK) {
        element_state(a, changed);
        for (int e = 0; e < a->n; e++)
            lit[e] |= emits(a, e);
        st = update(a, dirty, old_in, lo, hi, keep_old ? &old_scene : NULL, lit, changed, rep,
                    &t_direct, &shot, err); /* 4, 5 */
        if (st == RAD_OK)
            st = shot;
    }
    if (keep_old)
        rad_scene_free(&old_scene);
    double np = 0;
    for (int e = 0; e < a->n; e++)
        np += a->present[e];
    rep->pairs_total = 0.5 * np * (np - 1);
    const double rerun = isfinite(rep->t_changed) ? rep->t_changed : 0; /* not the frame's */
    rep->t_formfactor = radi_seconds() - t0 - rerun - t_direct;
    if (st == RAD_OK) {
        if (paper)
            radi_anim_importance(a, dirty, smp, ns);
        double t1 = radi_seconds();
        const int partial = !(a->opt.converge_last && next == ch->nframes);
        st = radi_anim_shoot(a, partial ? RADI_SHOOT_PARTIAL : RADI_SHOOT_CONVERGE,
                             a->opt.max_shots - rep->shots, rep, err); /* 6: max_shots is
                                                                            the frame's */
        if (st == RAD_OK)
            st = close_log(a, rep, err); /* 7 */
        rep->t_shoot = radi_seconds() - t1 + t_direct;
    }
    rep->t_total = radi_seconds() - t0 - rerun;
    free(dirty);
    free(old_in);
    free(changed);
    free(lit);
    free(lo);
    free(hi);
    free(smp);
    return st;
}

/* ---- the frame as a fresh solve numbers it, and eq. 7 -------------------- */

rad_status rad_anim_present_result(const rad_anim *a, rad_mesh *mesh, double **Bout,
                                   rad_error *err)
{
    rad_scene ps;
    *Bout = NULL;
    memset(mesh, 0, sizeof *mesh);
    rad_status st = rad_scene_present_copy(&a->scene, a->obj_present, &ps, err);
    if (st == RAD_OK)
        st = rad_mesh_build(mesh, &ps, err);
    rad_scene_free(&ps);
    if (st != RAD_OK)
        return st;
    const size_t np = (size_t)mesh->nelements, n = (size_t)a->n;
    double *B = malloc(sizeof *B * (np * RAD_BANDS + 1));
    if (!B) {
        rad_mesh_free(mesh);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    for (size_t e = 0, k = 0; e < n; e++)
        if (a->present[e]) {
            for (int b = 0; b < RAD_BANDS; b++)
                B[k + b * np] = a->B[e + b * n];
            k++;
        }
    *Bout = B;
    return RAD_OK;
}
