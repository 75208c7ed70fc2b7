/* occshaft.c -- which element pairs some surface can block at all, and
 * each such pair's list of possible blockers (shaft culling).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Shaft culling (Haines & Wallace, "Shaft culling for efficient ray-cast
 * radiosity", Eurographics Workshop on Rendering 1991).  The shaft of a
 * pair is the convex hull H of the two elements, each first clipped to
 * the front of the other's plane (only those parts exchange light).  For
 * convex A and B, conv(A u B) is the union of the segments from A to B
 * (Rockafellar, Convex Analysis, 1970, Thm. 3.3), so a surface can block
 * the pair only if it meets the interior of H.  A surface polygon P is
 * ruled out by a separating plane: either P's own plane with H on one
 * closed side, or a face plane of H with P on its outer closed side.  The
 * face planes of the hull of two convex polygons pass through an edge of
 * one and a vertex of the other; they are those candidates with every
 * vertex on one side.  The test is conservative: a pair it cannot clear
 * goes on to the integration (occhidden.c), which then finds nothing
 * hidden and keeps S unchanged.  Touching counts as separated: what a
 * surface hides through a contact of zero thickness has zero measure.
 * Touching means within round-off and the surfaces' own twist (OCC_SNAP,
 * occspace.h), nothing more: an element a hair above a floor, facing it,
 * is in front of the floor.
 *
 * Blockers are the scene's surfaces, not elements: a planar surface
 * cannot block a segment that starts on it, so the surfaces of i and j
 * are left out, and the rest is tested whole.  The test runs twice: once
 * per pair of surfaces at setup (a walk of a tree of the surfaces' boxes
 * by the shaft, occtree.c, gives the surfaces that may meet it), and
 * per pair of elements only against that short list.  When no pair of
 * surfaces has a candidate (a convex room seen from inside), the scene
 * needs no visibility work and radi_occ_create says so.  Last, a pair's
 * list loses the faces of a convex block that the block's other faces
 * make redundant for it (occsolid.c): a segment through a box crosses
 * two of its faces.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#else
#define omp_get_max_threads() 1
#define omp_get_thread_num() 0
#endif

#include "ff/formfactor.h"
#include "occ/occlusion.h"
#include "occ/occspace.h"
#include "util/util.h"
#include "radiosity/base.h"
#include "mesh/mesh.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"


/* Planes through an edge of p and a vertex of q with all of p and q on one
 * closed side: face planes of conv(p u q), appended with their outward
 * normals to sp->hn / sp->ha starting at *nh. */
static int side_planes(occ_space *sp, const rad_vec3 *p, int np, const rad_vec3 *q, int nq,
                       const rad_vec3 *all, int nall, double tol, int *nh)
{
    for (int k = 0; k < np; k++) {
        const rad_vec3 a = p[k];
        for (int l = 0; l < nq; l++) {
            rad_vec3 nrm;
            if (!poly_edge_plane(p, np, k, q[l], &nrm))
                continue;
            double lo, hi;
            if (occ_grow_d(&sp->d, &sp->capd, nall))
                return -1;
            poly_distances(all, nall, nrm, a, tol, sp->d, &lo, &hi);
            if (hi > 0 && lo < 0)
                continue;
            if (occ_grow_v3(&sp->hn, &sp->caphn, *nh + 1) ||
                occ_grow_v3(&sp->ha, &sp->capha, *nh + 1))
                return -1;
            sp->hn[*nh] = hi > 0 ? v3_scale(nrm, -1.0) : nrm;
            sp->ha[*nh] = a;
            ++*nh;
        }
    }
    return 0;
}

/* The face planes of the shaft conv(p u q): both polygons' own planes
 * (outward = away from the other polygon) and the side planes.  The
 * points of p and q follow each other in `all`.  Returns the count or -1. */
static int hull_planes(occ_space *sp, const rad_vec3 *all, int np, rad_vec3 pn, int nq,
                       rad_vec3 qn, double tol)
{
    const rad_vec3 *p = all, *q = all + np;
    int nh = 2;
    if (occ_grow_v3(&sp->hn, &sp->caphn, 2) ||
        occ_grow_v3(&sp->ha, &sp->capha, 2))
        return -1;
    sp->hn[0] = v3_scale(pn, -1.0);
    sp->ha[0] = p[0];
    sp->hn[1] = v3_scale(qn, -1.0);
    sp->ha[1] = q[0];
    if (side_planes(sp, p, np, q, nq, all, np + nq, tol, &nh) ||
        side_planes(sp, q, nq, p, np, all, np + nq, tol, &nh))
        return -1;
    return nh;
}

/* Is blocker b (nb vertices, unit normal bn) clear of the shaft with
 * points `all` and face planes sp->hn/ha (nh of them)? */
static int clear_of_shaft(const occ_space *sp, int nh, const rad_vec3 *all, int nall,
                          const rad_vec3 *b, int nb, rad_vec3 bn, double tol)
{
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < nall; k++) {
        double s = v3_dot(bn, v3_sub(all[k], b[0]));
        lo = fmin(lo, s);
        hi = fmax(hi, s);
    }
    if (lo >= -tol || hi <= tol)
        return 1; /* the shaft lies on one side of the blocker's plane */
    for (int h = 0; h < nh; h++) {
        int out = 1;
        for (int k = 0; k < nb && out; k++)
            out = v3_dot(sp->hn[h], v3_sub(b[k], sp->ha[h])) >= -tol;
        if (out)
            return 1; /* the blocker lies outside a face of the shaft */
    }
    return 0;
}

static int boxes_meet(rad_vec3 alo, rad_vec3 ahi, rad_vec3 blo, rad_vec3 bhi, double tol)
{
    return alo.x <= bhi.x + tol && blo.x <= ahi.x + tol && alo.y <= bhi.y + tol &&
           blo.y <= ahi.y + tol && alo.z <= bhi.z + tol && blo.z <= ahi.z + tol;
}

/* Clip p and q (unit normals pn, qn) each to the front of the other's plane
 * into sp->elem (polygon 0 from p, 1 from q).  Returns 1 if both keep an
 * area, 0 if not, -1 when memory ran out. */
int occ_clip_pair(occ_space *sp, const rad_vec3 *p, int np, rad_vec3 pn, const rad_vec3 *q,
                  int nq, rad_vec3 qn, double tol)
{
    occ_ps_clear(&sp->elem);
    int a = occ_clip_into(sp, &sp->elem, p, np, qn, q[0], tol);
    if (a <= 0)
        return a;
    int b = occ_clip_into(sp, &sp->elem, q, nq, pn, p[0], tol);
    return b < 0 ? -1 : b > 0;
}

int radi_occ_candidate(const rad_occ *o, int a, int b, const unsigned char *mask)
{
    if (!o || a == b)
        return 0;
    const size_t p = pair_index(a < b ? a : b, a < b ? b : a, o->nsurf);
    for (size_t k = o->cand_off[p]; k < o->cand_off[p + 1]; k++)
        if (mask[o->cand[k]])
            return 1;
    return 0;
}

int radi_occ_solid(const rad_occ *o, int s)
{
    return o && o->solid ? o->solid[s] : -1;
}

/* The tolerance for the surfaces a and b and the candidates of their pair. */
double occ_pair_snap(const rad_occ *o, int a, int b, const int *cand, int ncand)
{
    double t = o->snap + o->stwist[a] + o->stwist[b], tc = 0;
    for (int k = 0; k < ncand; k++)
        tc = fmax(tc, o->stwist[cand[k]]);
    return t + tc;
}

static rad_status load_surfaces(rad_occ *o, const rad_mesh *m)
{
    const int ns = m->nsurfaces;
    int total = 0;
    for (int s = 0; s < ns; s++) {
        total += radi_mesh_outline(m, s, NULL);
    }
    o->nsurf = ns;
    o->sv = malloc(sizeof *o->sv * (size_t)(total > 0 ? total : 1));
    o->sfirst = malloc(sizeof *o->sfirst * (size_t)(ns + 1));
    o->snormal = malloc(sizeof *o->snormal * (size_t)(ns > 0 ? ns : 1));
    o->slo = malloc(sizeof *o->slo * (size_t)(ns > 0 ? ns : 1));
    o->shi = malloc(sizeof *o->shi * (size_t)(ns > 0 ? ns : 1));
    o->stwist = malloc(sizeof *o->stwist * (size_t)(ns > 0 ? ns : 1));
    o->esurf = malloc(sizeof *o->esurf * (size_t)m->nelements);
    if (!o->sv || !o->sfirst || !o->snormal || !o->slo || !o->shi || !o->stwist || !o->esurf)
        return RAD_ERR_NOMEM;
    int at = 0;
    for (int s = 0; s < ns; s++) {
        int e0 = m->surface_first[s], ne = m->surface_first[s + 1] - e0;
        o->sfirst[s] = at;
        if (ne > 0) {
            int n = radi_mesh_outline(m, s, o->sv + at);
            o->snormal[s] = m->elements[e0].normal;
            v3_bounds(o->sv + at, n, &o->slo[s], &o->shi[s]);
            o->stwist[s] = poly_twist(o->sv + at, n, o->snormal[s]);
            at += n;
        } else {
            o->snormal[s] = o->slo[s] = o->shi[s] = v3(0, 0, 0);
            o->stwist[s] = 0;
        }
    }
    o->sfirst[ns] = at;
    for (int e = 0; e < m->nelements; e++)
        o->esurf[e] = m->elements[e].surface;
    return RAD_OK;
}

/* Is surface c surface t reversed: opposite normals, the same vertices
 * within tol, in the opposite order (the back face of a two-sided panel
 * or disk)?  Then c hides from any pair exactly what t hides, and one of
 * them suffices as a blocker: a doubled K-gon blocker otherwise costs a
 * K^2 cone cut per point where the last blocker costs K (occpoint.c). */
static int reversed_twin(const rad_occ *o, int t, int c, double tol)
{
    const int n = o->sfirst[t + 1] - o->sfirst[t];
    if (n < 3 || n != o->sfirst[c + 1] - o->sfirst[c] ||
        v3_dot(o->snormal[t], o->snormal[c]) > -1 + 1e-12 ||
        v3_norm(v3_sub(o->slo[t], o->slo[c])) > tol || v3_norm(v3_sub(o->shi[t], o->shi[c])) > tol)
        return 0;
    const rad_vec3 *p = o->sv + o->sfirst[t], *q = o->sv + o->sfirst[c];
    for (int r = 0; r < n; r++) { /* q[k] against p[r - k] */
        int same = 1;
        for (int k = 0; k < n && same; k++)
            same = v3_norm(v3_sub(q[k], p[((r - k) % n + n) % n])) <= tol;
        if (same)
            return 1;
    }
    return 0;
}

/* o->twin: for each surface the first earlier surface it reverses, or -1. */
static rad_status find_twins(rad_occ *o)
{
    o->twin = malloc(sizeof *o->twin * (size_t)(o->nsurf > 0 ? o->nsurf : 1));
    if (!o->twin)
        return RAD_ERR_NOMEM;
    for (int c = 0; c < o->nsurf; c++) {
        o->twin[c] = -1;
        for (int t = 0; t < c && o->twin[c] < 0; t++)
            if (o->twin[t] < 0 && reversed_twin(o, t, c, o->snap))
                o->twin[c] = t;
    }
    return RAD_OK;
}

static int int_cmp(const void *pa, const void *pb)
{
    const int a = *(const int *)pa, b = *(const int *)pb;
    return (a > b) - (a < b);
}

/* Append to the candidate list the surfaces that may block surfaces a and
 * b.  Returns the number appended, or -1. */
static int surface_pair_candidates(rad_occ *o, const occ_tree *tree, occ_space *sp, int a,
                                   int b, int *owners, int **cand, int *ncand, int *capcand)
{
    const rad_vec3 *pa = o->sv + o->sfirst[a], *pb = o->sv + o->sfirst[b];
    int na = o->sfirst[a + 1] - o->sfirst[a], nb = o->sfirst[b + 1] - o->sfirst[b];
    if (na < 3 || nb < 3)
        return 0;
    const double snap = o->snap + o->stwist[a] + o->stwist[b];
    int r = occ_clip_pair(sp, pa, na, o->snormal[a], pb, nb, o->snormal[b], snap);
    if (r <= 0)
        return r; /* they see nothing of each other */
    const rad_vec3 *all = sp->elem.v;
    int nca = sp->elem.first[1], nall = sp->elem.nv;
    int nh = o->mode == RAD_OCC_ALL
                 ? 0
                 : hull_planes(sp, all, nca, o->snormal[a], nall - nca, o->snormal[b], snap);
    if (nh < 0)
        return -1;
    int nc;
    if (o->mode == RAD_OCC_ALL) {
        nc = 0;
        for (int c = 0; c < o->nsurf; c++)
            owners[nc++] = c;
    } else {
        rad_vec3 lo, hi, pad = v3(snap, snap, snap);
        v3_bounds(all, nall, &lo, &hi);
        nc = occ_tree_shaft(tree, v3_sub(lo, pad), v3_add(hi, pad), sp->hn, sp->ha, nh, snap,
                            owners);
        qsort(owners, (size_t)nc, sizeof *owners, int_cmp); /* in order, as listed before */
    }
    int added = 0;
    for (int k = 0; k < nc; k++) {
        int c = owners[k], n = o->sfirst[c + 1] - o->sfirst[c];
        if (c == a || c == b || n < 3)
            continue;
        /* a twin hides what its original hides, unless the original is one
         * of the pair (then the twin lies in that surface's plane) */
        if (o->twin[c] >= 0 && o->twin[c] != a && o->twin[c] != b)
            continue;
        if (o->mode != RAD_OCC_ALL &&
            clear_of_shaft(sp, nh, all, nall, o->sv + o->sfirst[c], n, o->snormal[c],
                           snap + o->stwist[c]))
            continue;
        if (occ_grow_i(cand, capcand, *ncand + 1))
            return -1;
        (*cand)[(*ncand)++] = c;
        added++;
    }
    return added;
}

/* Every surface pair's candidate blockers, into o->cand_off and o->cand
 * (the pairs in pair_index order), on opt->threads threads (0: OpenMP's
 * default), telling opt->progress (stage "visibility") as rows finish;
 * *blockable_pairs counts the pairs with any.  Returns RAD_ERR_INVALID
 * when the progress callback asked to stop.  The listing is
 * a query of the AABB tree and a shaft test per pair, O(S^2) for S
 * surfaces: on a 3,732-triangle model it took 80 s on one thread. */
static rad_status candidates(rad_occ *o, const occ_tree *tree, const rad_ff_options *opt,
                             double *blockable_pairs)
{
    const int threads = opt->threads;
    const int ns = o->nsurf;
    const size_t npairs = ns > 1 ? (size_t)ns * (size_t)(ns - 1) / 2 : 0;
    int **rows = calloc((size_t)(ns > 0 ? ns : 1), sizeof *rows);
    int *rowlen = calloc((size_t)(ns > 0 ? ns : 1), sizeof *rowlen);
    int failed = !rows || !rowlen, stop = 0;
    double blockable = 0, done = 0;
    o->cand_off = malloc(sizeof *o->cand_off * (npairs + 1));
    o->cand = NULL;
    failed = failed || !o->cand_off;
    /* each thread lists whole rows a (the pairs (a, b > a), contiguous in
     * pair_index order) into a buffer of its own, the row's counts into
     * cand_off; the rows are joined in order afterwards, so the lists are
     * those of one thread, in the same order */
#pragma omp parallel num_threads(threads > 0 ? threads : omp_get_max_threads()) \
    reduction(|| : failed) reduction(+ : blockable) if (!failed)
    {
        occ_space sp;
        memset(&sp, 0, sizeof sp);
        int *owners = malloc(sizeof *owners * (size_t)(ns > 0 ? ns : 1));
        failed = !owners;
#pragma omp for schedule(dynamic, 1)
        for (int a = 0; a < ns; a++) {
            int n = 0, cap = 0, halt;
#pragma omp atomic read
            halt = stop;
            for (int b = a + 1; b < ns && !failed && !halt; b++) {
                const int before = n;
                const int r =
                    surface_pair_candidates(o, tree, &sp, a, b, owners, &rows[a], &n, &cap);
                if (r < 0)
                    failed = 1;
                o->cand_off[pair_index(a, b, ns)] = (size_t)(n - before);
                blockable += r > 0;
            }
            rowlen[a] = n;
            double now;
#pragma omp atomic capture
            now = done += ns - a - 1;
            /* the caller's callback, from the calling thread only */
            if (opt->progress && omp_get_thread_num() == 0 && !halt && now < (double)npairs &&
                opt->progress(opt->progress_user, "visibility", now, (double)npairs)) {
#pragma omp atomic write
                stop = 1;
            }
        }
        free(owners);
        occ_space_free(&sp);
    }
    /* the end, whichever thread finished the last row */
    if (opt->progress && !failed && !stop &&
        opt->progress(opt->progress_user, "visibility", (double)npairs, (double)npairs))
        stop = 1;
    size_t total = 0;
    for (int a = 0; a < ns && !failed; a++)
        total += (size_t)rowlen[a];
    if (!failed && !stop && !(o->cand = malloc(sizeof *o->cand * (total > 0 ? total : 1))))
        failed = 1;
    if (!failed && !stop) {
        size_t off = 0;
        for (size_t p = 0; p < npairs; p++) {
            const size_t c = o->cand_off[p];
            o->cand_off[p] = off;
            off += c;
        }
        o->cand_off[npairs] = off;
        size_t at = 0;
        for (int a = 0; a < ns; a++) {
            if (rowlen[a] > 0)
                memcpy(o->cand + at, rows[a], sizeof *o->cand * (size_t)rowlen[a]);
            at += (size_t)rowlen[a];
        }
    }
    for (int a = 0; rows && a < ns; a++)
        free(rows[a]);
    free(rows);
    free(rowlen);
    *blockable_pairs = failed || stop ? 0 : blockable;
    return failed ? RAD_ERR_NOMEM : stop ? RAD_ERR_INVALID : RAD_OK;
}

void radi_occ_free(rad_occ *o)
{
    if (!o)
        return;
    free(o->sv);
    free(o->sfirst);
    free(o->snormal);
    free(o->slo);
    free(o->shi);
    free(o->stwist);
    free(o->esurf);
    free(o->twin);
    free(o->solid);
    free(o->hfirst);
    free(o->hnrm);
    free(o->hpt);
    free(o->hopen);
    free(o->patch);
    free(o->pv);
    free(o->pfirst);
    free(o->prep);
    free(o->closed);
    free(o->clo);
    free(o->chi);
    free(o->cand_off);
    free(o->cand);
    free(o);
}

double radi_occ_scene_snap(const rad_vec3 *v, int n, rad_vec3 off)
{
    if (n < 1)
        return OCC_SNAP;
    rad_vec3 lo, hi;
    v3_bounds(v, n, &lo, &hi);
    const double L = v3_norm(v3_sub(hi, lo));
    /* the largest |coordinate| as the user gave them, from the box */
    const double mag = fmax(v3_maxabs(v3_add(lo, off)), v3_maxabs(v3_add(hi, off)));
    return OCC_SNAP * (L > 0 ? L : 1.0) + OCC_ROUND * DBL_EPSILON * mag;
}

rad_status radi_occ_create(rad_occ **out, const rad_mesh *m, double snap, rad_occ_mode mode,
                          const rad_ff_options *opt, rad_occ_stats *stats, rad_error *err)
{
    double t0 = radi_seconds(), blockable = 0;
    rad_occ_stats st;
    occ_tree *tree = NULL;
    memset(&st, 0, sizeof st);
    *out = NULL;
    if (mode == RAD_OCC_OFF || m->nelements < 2 || m->nsurfaces < 3) {
        if (stats)
            *stats = st;
        return RAD_OK;
    }
    rad_occ *o = calloc(1, sizeof *o);
    if (!o)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the visibility data");
    o->mode = mode;
    o->accuracy = opt->accuracy;
    o->snap = snap;
    rad_status s = load_surfaces(o, m);
    if (s == RAD_OK)
        s = find_twins(o);
    if (s == RAD_OK && mode != RAD_OCC_ALL)
        s = occ_find_patches(o);
    if (s == RAD_OK && mode != RAD_OCC_ALL)
        s = occ_find_solids(o);
    if (s == RAD_OK && mode != RAD_OCC_ALL)
        s = occ_find_closed(o);
    if (s == RAD_OK && !(tree = occ_tree_create(o)))
        s = RAD_ERR_NOMEM;
    if (s != RAD_OK)
        radi_fail(err, s, "out of memory for the visibility data");
    if (s == RAD_OK) {
        st.surfaces = o->nsurf;
        st.closed_meshes = o->nclosed;
        s = candidates(o, tree, opt, &blockable);
        if (s == RAD_ERR_INVALID)
            radi_fail(err, s, "interrupted");
        else if (s != RAD_OK)
            radi_fail(err, s, "out of memory for the visibility data");
    }
    occ_tree_free(tree);
    if (s != RAD_OK || blockable == 0) {
        radi_occ_free(o);
        o = NULL;
    }
    st.needed = o != NULL;
    st.seconds = radi_seconds() - t0;
    if (stats)
        *stats = st;
    *out = o;
    return s;
}

/* Collect the blockers of the pair: the surface pair's candidates that the
 * element shaft does not clear, before the solids cull them.  Returns
 * their count (ids in sp->bid), or -1. */
int occ_pair_shaft(const rad_occ *o, occ_space *sp, int sa, int sb, const rad_ff_poly *pi,
                   const rad_ff_poly *pj, rad_vec3 origin)
{
    int a = sa < sb ? sa : sb, b = sa < sb ? sb : sa;
    size_t p = pair_index(a, b, o->nsurf);
    const int *cand = o->cand + o->cand_off[p];
    int ncand = (int)(o->cand_off[p + 1] - o->cand_off[p]);
    const rad_vec3 *all = sp->elem.v;
    int ni = sp->elem.first[1], nall = sp->elem.nv;
    int nh = 0;
    if (o->mode != RAD_OCC_ALL) {
        nh = hull_planes(sp, all, ni, pi->normal, nall - ni, pj->normal, sp->snap);
        if (nh < 0)
            return -1;
    }
    sp->nhull = nh;
    rad_vec3 lo, hi;
    v3_bounds(all, nall, &lo, &hi);
    lo = v3_add(lo, origin); /* the boxes are in scene coordinates */
    hi = v3_add(hi, origin);
    occ_ps_clear(&sp->blk);
    int nb = 0;
    for (int k = 0; k < ncand; k++) {
        int c = cand[k], n = o->sfirst[c + 1] - o->sfirst[c];
        if (o->mode != RAD_OCC_ALL && !boxes_meet(lo, hi, o->slo[c], o->shi[c], sp->snap))
            continue;
        if (occ_grow_i(&sp->bid, &sp->capb, nb + 1) ||
            occ_ps_push_shifted(&sp->blk, o->sv + o->sfirst[c], n, origin))
            return -1;
        if (o->mode != RAD_OCC_ALL &&
            clear_of_shaft(sp, nh, all, nall, sp->blk.v + sp->blk.first[nb], n, o->snormal[c],
                           sp->snap)) {
            occ_ps_pop(&sp->blk);
            continue;
        }
        sp->bid[nb++] = c;
    }
    return nb;
}

/* The same, coplanar neighbours taken as their patch (occflat.c), culled
 * by the convex solids (occsolid.c) and the closed meshes (occclosed.c):
 * the pair's blockers. */
int occ_pair_blockers(const rad_occ *o, occ_space *sp, int sa, int sb, const rad_ff_poly *pi,
                      const rad_ff_poly *pj, rad_vec3 origin)
{
    sp->nxcull = 0; /* no exit faces known until occ_closed_cull says */
    int nb = occ_pair_shaft(o, sp, sa, sb, pi, pj, origin);
    if (nb <= 0 || o->mode == RAD_OCC_ALL)
        return nb;
    nb = occ_flat_blockers(o, sp, nb, sa, sb, origin);
    if (nb > 0)
        nb = occ_solid_cull(o, sp, nb, origin);
    return nb <= 0 ? nb : occ_closed_cull(o, sp, nb, sa, sb, pi, pj, origin);
}
