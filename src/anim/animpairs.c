/* animpairs.c -- the form factors a frame's changes alter, recomputed in place.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Which pairs (George, Sillion & Greenberg 1990, section "Form factor
 * modification"): F_ij can change only if i or j is on an object that
 * moved, turned, came or went (its "dirty" objects), or if such an object,
 * where it was or where it is now, can stand between i and j.  Whatever
 * blocks a segment from a point of i to a point of j meets the convex
 * hull of i and j; so a pair is recomputed when the box of a dirty object,
 * old or new (padded by 1e-9 of the scene's size), meets the bounding box
 * of the two elements and no separating axis or plane clears it of their
 * shaft (box_may_block).  The test is geometric and conservative: no pair
 * the object can block is missed, and pairs it only grazes may be kept.
 * What it does not promise is the last bits of a pair the occlusion code
 * treats as a candidate without a block: on the Cornell moving box, one
 * pair of 7095 whose F a fresh fill gives 1.5e-8 relative off (far from any
 * blocker, a different integration route), which the box test alone had
 * recomputed; the frames still equal fresh solves within 5e-12.
 * A change of material alters no form factor.
 *
 * Classic mode's routes.  The pairs the test keeps out still have their
 * F as a fresh fill gives it in default and reference modes: where the
 * fill counts a dirty object among a pair's possible blockers and it
 * hides nothing, the pair's value moves within its estimate (the last
 * bits above).  Classic mode has no estimate: a possible blocker that
 * hides nothing still cuts its rule's cells, and on the Cornell moving
 * box moved one entry by 0.2% of itself and a frame's B by up to 1e-6
 * of a fresh solve's.  So in classic mode a pair is recomputed too when
 * a surface of a dirty object is on the candidate list of its two
 * surfaces (radi_occ_candidate, occshaft.c) before or after the change,
 * or a surface whose convex solid (occsolid.c) the change may alter: a
 * member of a solid that holds a dirty surface or whose members differ
 * after the change (a moved surface that meets a block's edge at a fold
 * joins its faces into one group, and a group that is not convex is no
 * solid) -- unless the pair's own route is the same in both scenes: its
 * snap tolerance and the surfaces its element shaft keeps before the
 * solids' cull (radi_occ_pair_route), none of them marked.  The fill then
 * computes it from the same numbers in the same order.  (On the Cornell
 * moving box the surface test alone recomputed 17% to 33% of the pairs
 * per frame, the pairs' routes 8% to 10%.)  Outside those the fill takes
 * the same route for the pair, on the same numbers as long as the
 * scene's box stays the same (it sets the frame, radi_mesh_normalized,
 * and the tolerance, radi_occ_scene_snap): a move that grows the box
 * changes them by round-off for every pair (seen: the box moved 1000 mm
 * out of the Cornell box, frames 1.1e-9 off).
 *
 * How: the pairs go to radi_ff_pairs (ffpairs.h), which computes each as
 * the full fill would on the mesh of the present surfaces of this frame
 * (rad_scene_present_copy): so F stays, entry for entry, the F of a fresh
 * solve of the frame's scene.  Pairs with an absent element become 0.
 *
 * In place: the new values overwrite F; what the redistribution needs is
 * dF T on the changed pairs only (dF = F(t) - F(t-1), T = B - dB what
 * each shooter had shot), kept in compressed columns (animint.h) and
 * merged with what earlier partial frames left (the change log,
 * animlog.c).  No second n x n
 * matrix is ever made: memory is F, the pair lists and O(n).
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "anim/animint.h"
#include "fill/fill.h"
#include "mesh/mesh.h"
#include "occ/occlusion.h"
#include "util/util.h"

/* Elements with more vertices (polygons, disks) skip the shaft test and
 * are recomputed whenever their box meets the object's. */
#define RAD_SHAFT_VERTS 8

void radi_redist_free(rad_redist *rd)
{
    free(rd->start);
    free(rd->recv);
    free(rd->amt);
    free(rd->power);
    free(rd->epow);
    free(rd->done);
    free(rd->rstart);
    free(rd->rent);
    free(rd->rpower);
    free(rd->ncol);
    free(rd->nrow);
    memset(rd, 0, sizeof *rd);
}

void radi_anim_object_box(const rad_anim *a, int o, rad_vec3 *lo, rad_vec3 *hi)
{
    *lo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL);
    *hi = v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL);
    for (int s = 0; s < a->scene.nsurfaces; s++) {
        const rad_surface *f = &a->scene.surfaces[s];
        if (f->object != o)
            continue;
        rad_vec3 l, h;
        v3_bounds(f->verts, f->nverts, &l, &h);
        *lo = v3(fmin(lo->x, l.x), fmin(lo->y, l.y), fmin(lo->z, l.z));
        *hi = v3(fmax(hi->x, h.x), fmax(hi->y, h.y), fmax(hi->z, h.z));
    }
}

/* The boxes to test pairs against: dirty objects where they were (if
 * they were in) and where they are (if they are in), padded. */
typedef struct box_list {
    rad_vec3 *lo, *hi;
    int n;
} box_list;

static void add_box(box_list *bl, rad_vec3 lo, rad_vec3 hi, double pad)
{
    bl->lo[bl->n] = v3(lo.x - pad, lo.y - pad, lo.z - pad);
    bl->hi[bl->n] = v3(hi.x + pad, hi.y + pad, hi.z + pad);
    bl->n++;
}

static int boxes_meet(rad_vec3 alo, rad_vec3 ahi, rad_vec3 blo, rad_vec3 bhi)
{
    return alo.x <= bhi.x && blo.x <= ahi.x && alo.y <= bhi.y && blo.y <= ahi.y &&
           alo.z <= bhi.z && blo.z <= ahi.z;
}

/* Element boxes of the mesh. */
static void element_boxes(const rad_mesh *m, rad_vec3 *lo, rad_vec3 *hi)
{
    for (int e = 0; e < m->nelements; e++) {
        lo[e] = hi[e] = rad_mesh_vertex(m, e, 0);
        for (int k = 1; k < m->elements[e].nverts; k++) {
            rad_vec3 p = rad_mesh_vertex(m, e, k);
            lo[e] = v3(fmin(lo[e].x, p.x), fmin(lo[e].y, p.y), fmin(lo[e].z, p.z));
            hi[e] = v3(fmax(hi[e].x, p.x), fmax(hi[e].y, p.y), fmax(hi[e].z, p.z));
        }
    }
}

/* Is the box [lo, hi] separated from the convex hull of the points p[0..np)
 * along axis a?  (The separating axis theorem: disjoint intervals of
 * projection along any axis prove the two convex sets disjoint.) */
static int separated_along(rad_vec3 a, const rad_vec3 *p, int np, rad_vec3 lo, rad_vec3 hi)
{
    const rad_vec3 c = v3_scale(v3_add(lo, hi), 0.5), h = v3_scale(v3_sub(hi, lo), 0.5);
    const double bc = v3_dot(a, c);
    const double br = fabs(a.x) * h.x + fabs(a.y) * h.y + fabs(a.z) * h.z;
    double pmin = HUGE_VAL, pmax = -HUGE_VAL;
    for (int k = 0; k < np; k++) {
        const double t = v3_dot(a, p[k]);
        pmin = t < pmin ? t : pmin;
        pmax = t > pmax ? t : pmax;
    }
    const double slack = 1e-12 * (fabs(bc) + br + fabs(pmin) + fabs(pmax));
    return pmax < bc - br - slack || pmin > bc + br + slack;
}

/* Can the box stand between elements i and j?  Whatever blocks a segment
 * from a point of i to a point of j meets the convex hull of the two
 * polygons; and such a segment runs in front of both planes (a point of j
 * behind i's plane sees nothing of i; Goral et al. 1984, section 2).  So
 * the box is harmless when it lies behind either plane, or when some axis
 * separates it from the hull: the box's own axes, the two normals, and the
 * cross products of the box's axes with the line between the centroids
 * and with the elements' edges (the sides of the shaft, Haines & Wallace
 * 1994, "Shaft culling").  Finding no such axis keeps the pair: the test
 * errs only toward recomputing. */
static int box_may_block(const rad_mesh *m, int i, int j, rad_vec3 lo, rad_vec3 hi)
{
    rad_vec3 p[2 * RAD_SHAFT_VERTS];
    const rad_element *ei = &m->elements[i], *ej = &m->elements[j];
    if (ei->nverts > RAD_SHAFT_VERTS || ej->nverts > RAD_SHAFT_VERTS)
        return 1;
    int np = 0;
    for (int k = 0; k < ei->nverts; k++)
        p[np++] = rad_mesh_vertex(m, i, k);
    for (int k = 0; k < ej->nverts; k++)
        p[np++] = rad_mesh_vertex(m, j, k);
    const rad_vec3 box_c = v3_scale(v3_add(lo, hi), 0.5), box_h = v3_scale(v3_sub(hi, lo), 0.5);
    const rad_element *e2[2] = {ei, ej};
    for (int s = 0; s < 2; s++) { /* behind a plane: every corner's distance < 0 */
        const rad_vec3 n = e2[s]->normal;
        double top = v3_dot(n, v3_sub(box_c, e2[s]->centroid)) + fabs(n.x) * box_h.x +
                     fabs(n.y) * box_h.y + fabs(n.z) * box_h.z;
        if (top < -1e-12 * (v3_norm(box_h) + v3_norm(v3_sub(box_c, e2[s]->centroid))))
            return 0;
    }
    const rad_vec3 axes[3] = {v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1)};
    if (separated_along(ei->normal, p, np, lo, hi) || separated_along(ej->normal, p, np, lo, hi))
        return 0;
    const rad_vec3 d = v3_sub(ej->centroid, ei->centroid);
    for (int a = 0; a < 3; a++) {
        if (separated_along(v3_cross(axes[a], d), p, np, lo, hi))
            return 0;
        for (int k = 0; k < np; k++) {
            const int first = k < ei->nverts ? 0 : ei->nverts;
            const int cnt = k < ei->nverts ? ei->nverts : ej->nverts;
            const rad_vec3 edge = v3_sub(p[first + (k - first + 1) % cnt], p[k]);
            if (separated_along(v3_cross(axes[a], edge), p, np, lo, hi))
                return 0;
        }
    }
    return 1;
}

/* Classic mode's routes (the header) in one scene of present surfaces:
 * its candidate lists and solids (occ); flag[sa * ns + sb] when a marked
 * surface is a candidate blocker of surfaces sa and sb; smap takes a
 * surface of a->scene to its index there, or -1, sinv back, and gid to
 * its solid there, or -1; emap an element of a->mesh to its index in the
 * scene's mesh, whose polygons (polys, as the fill makes them) and work
 * space (w) give a pair's route (radi_occ_pair_route). */
typedef struct route_map {
    rad_occ *occ;
    rad_occ_work w;
    unsigned char *flag;
    int *smap, *sinv, *gid, *emap;
    unsigned char *mark;        /* rm[0] only: mark_surfaces, a->scene's numbering */
    rad_ff_poly *polys;
    rad_vec3 *pts;
    rad_ff_edge *edges;
    int ns;
} route_map;

static void route_map_free(route_map *rm)
{
    radi_occ_work_free(&rm->w);
    radi_occ_free(rm->occ);
    free(rm->flag);
    free(rm->smap);
    free(rm->sinv);
    free(rm->gid);
    free(rm->emap);
    free(rm->mark);
    free(rm->polys);
    free(rm->pts);
    free(rm->edges);
    memset(rm, 0, sizeof *rm);
}

/* The candidate lists and solids as radi_ff_pairs (ffblock.c) builds them
 * for the mesh of ps, the present surfaces of a->scene under presence
 * `in`. */
static rad_status route_map_build(const rad_anim *a, const rad_scene *ps, const unsigned char *in,
                                  route_map *rm, rad_error *err)
{
    rad_mesh m, unit;
    rad_frame fr;
    const int ns = ps->nsurfaces, nf = a->scene.nsurfaces;
    memset(&m, 0, sizeof m);
    memset(&unit, 0, sizeof unit);
    rm->ns = ns;
    rm->flag = calloc((size_t)ns * (size_t)ns + 1, 1);
    rm->smap = malloc(sizeof *rm->smap * (size_t)(nf + 1));
    rm->sinv = malloc(sizeof *rm->sinv * (size_t)(ns + 1));
    rm->gid = malloc(sizeof *rm->gid * (size_t)(nf + 1));
    rm->emap = malloc(sizeof *rm->emap * (size_t)(a->n + 1));
    rad_status st = rm->flag && rm->smap && rm->sinv && rm->gid && rm->emap
                        ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    for (int s = 0, k = 0; st == RAD_OK && s < nf; s++) {
        const int o = a->scene.surfaces[s].object;
        rm->smap[s] = o < 0 || in[o] ? k++ : -1;
        if (rm->smap[s] >= 0)
            rm->sinv[rm->smap[s]] = s;
    }
    for (int e = 0, k = 0; st == RAD_OK && e < a->n; e++)
        rm->emap[e] = rm->smap[a->mesh.elements[e].surface] >= 0 ? k++ : -1;
    if (st == RAD_OK)
        st = rad_mesh_build(&m, ps, err);
    if (st == RAD_OK)
        st = radi_mesh_normalized(&m, &unit, &fr, err);
    const double snap = st == RAD_OK ? radi_occ_scene_snap(unit.vertices, unit.nvertices,
                                                          radi_frame_offset(&fr)) : 0;
    if (st == RAD_OK &&
        radi_ff_mesh_polys(&unit, snap, &rm->polys, &rm->pts, &rm->edges) != RAD_OK)
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (st == RAD_OK)
        st = radi_occ_create(&rm->occ, &unit, snap, RAD_OCC_AUTO, &a->opt.ff, NULL, err);
    if (st == RAD_OK)
        radi_occ_work_init(&rm->w, rm->occ);
    for (int s = 0; st == RAD_OK && s < nf; s++)
        rm->gid[s] = rm->smap[s] >= 0 ? radi_occ_solid(rm->occ, rm->smap[s]) : -1;
    rad_mesh_free(&unit);
    rad_mesh_free(&m);
    return st;
}

/* Does surface s (of a->scene) belong to solids of the same members in
 * both maps (or to none in both)? */
static int same_solid(const route_map rm[2], int nf, int s)
{
    const int g0 = rm[0].gid[s], g1 = rm[1].gid[s];
    if (g0 < 0 || g1 < 0)
        return g0 < 0 && g1 < 0;
    for (int t = 0; t < nf; t++)
        if ((rm[0].gid[t] == g0) != (rm[1].gid[t] == g1))
            return 0;
    return 1;
}

/* mark[s]: surfaces of a->scene whose change may reach a pair's blocker
 * list: those of dirty objects; those whose solid has other members
 * after the change (a moved surface may join a solid's fold or break its
 * convexity, occsolid.c); and, closing over both maps, every member of a
 * solid with a marked member (which faces a pair leaves out depends on
 * all of them). */
static void mark_surfaces(const rad_anim *a, const unsigned char *dirty, const route_map rm[2],
                          unsigned char *mark)
{
    const int nf = a->scene.nsurfaces;
    for (int s = 0; s < nf; s++) {
        const int o = a->scene.surfaces[s].object;
        mark[s] = (o >= 0 && dirty[o]) || !same_solid(rm, nf, s);
    }
    for (int grew = 1; grew;) {
        grew = 0;
        for (int b = 0; b < 2; b++)
            for (int s = 0; s < nf; s++) {
                const int g = rm[b].gid[s];
                for (int t = 0; mark[s] && g >= 0 && t < nf; t++)
                    if (rm[b].gid[t] == g && !mark[t])
                        mark[t] = grew = 1;
            }
    }
}

/* rm's flags: pairs of present surfaces with a marked candidate. */
static rad_status route_flags(const rad_anim *a, const unsigned char *mark, route_map *rm,
                              rad_error *err)
{
    const int ns = rm->ns;
    unsigned char *mask = malloc((size_t)ns + 1);
    if (!mask)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    for (int s = 0; s < a->scene.nsurfaces; s++)
        if (rm->smap[s] >= 0)
            mask[rm->smap[s]] = mark[s];
    for (int sa = 0; rm->occ && sa < ns; sa++)
        for (int sb = sa + 1; sb < ns; sb++)
            if (radi_occ_candidate(rm->occ, sa, sb, mask))
                rm->flag[(size_t)sa * ns + sb] = rm->flag[(size_t)sb * ns + sa] = 1;
    free(mask);
    return RAD_OK;
}

/* Is a marked surface (mark_surfaces) a candidate blocker of pair (i, j)
 * in rm's scene? */
static int route_may_change(const rad_anim *a, const route_map *rm, int i, int j)
{
    if (!rm->flag)
        return 0;
    const int si = rm->smap[a->mesh.elements[i].surface];
    const int sj = rm->smap[a->mesh.elements[j].surface];
    return si >= 0 && sj >= 0 && rm->flag[(size_t)si * rm->ns + sj];
}

/* Pair (i, j)'s route in rm's scene: the count of its blockers before
 * the solids' cull (their surfaces, in a->scene's numbering, in ids),
 * and *snap; -1 when it cannot be had (memory, more than cap). */
#define ROUTE_CAP 64
static int pair_route(route_map *rm, int i, int j, int *ids, double *snap)
{
    const int ei = rm->emap[i], ej = rm->emap[j];
    if (ei < 0 || ej < 0)
        return -1;
    const int nb = radi_occ_pair_route(&rm->w, rm->polys, ei, ej, ids, ROUTE_CAP, snap);
    for (int k = 0; k < nb; k++)
        ids[k] = rm->sinv[ids[k]];
    return nb < 0 ? -1 : nb;
}

/* Classic mode: does pair (i, j), none of whose elements moved, take the
 * same route before and after the change, by no marked surface?  Then the
 * fill computes it from the same numbers in the same order, and its F
 * stays to the bit (the header's caveat on the scene's box aside). */
static int same_route(route_map rm[2], int i, int j)
{
    int id0[ROUTE_CAP], id1[ROUTE_CAP];
    double s0, s1;
    const int n0 = pair_route(&rm[0], i, j, id0, &s0);
    const int n1 = pair_route(&rm[1], i, j, id1, &s1);
    if (n0 < 0 || n0 != n1 || s0 != s1)
        return 0;
    for (int k = 0; k < n0; k++)
        if (id0[k] != id1[k] || rm[0].mark[id0[k]])
            return 0;
    return 1;
}

/* Does the change alter pair (i, j)? (the file's header says why) */
static int pair_affected(const rad_anim *a, const unsigned char *dirty, const box_list *bl,
                         route_map *rm, const rad_vec3 *lo, const rad_vec3 *hi, int i,
                         int j)
{
    const int oi = a->elem_object[i], oj = a->elem_object[j];
    if ((oi >= 0 && dirty[oi]) || (oj >= 0 && dirty[oj]))
        return 1;
    if (!a->present[i] || !a->present[j])
        return 0; /* F stays 0 */
    rad_vec3 l = v3(fmin(lo[i].x, lo[j].x), fmin(lo[i].y, lo[j].y), fmin(lo[i].z, lo[j].z));
    rad_vec3 h = v3(fmax(hi[i].x, hi[j].x), fmax(hi[i].y, hi[j].y), fmax(hi[i].z, hi[j].z));
    for (int k = 0; k < bl->n; k++)
        if (boxes_meet(l, h, bl->lo[k], bl->hi[k]) &&
            box_may_block(&a->mesh, i, j, bl->lo[k], bl->hi[k]))
            return 1;
    return (route_may_change(a, &rm[0], i, j) || route_may_change(a, &rm[1], i, j)) &&
           !same_route(rm, i, j);
}

/* The pairs to recompute, as growable lists pi < pj (full numbering). */
typedef struct pair_list {
    int *pi, *pj;
    size_t n, cap;
} pair_list;

static int push_pair(pair_list *pl, int i, int j)
{
    if (pl->n == pl->cap) {
        size_t cap = pl->cap ? 2 * pl->cap : 1024;
        int *a = realloc(pl->pi, sizeof *a * cap), *b = a ? realloc(pl->pj, sizeof *b * cap) : NULL;
        if (a)
            pl->pi = a;
        if (!a || !b)
            return -1;
        pl->pj = b;
        pl->cap = cap;
    }
    pl->pi[pl->n] = i;
    pl->pj[pl->n++] = j;
    return 0;
}

/* Is pair (i, j) one of `which` (RADI_PAIRS_*)? */
static int pair_in(const unsigned char *lit, int which, int i, int j)
{
    return which == RADI_PAIRS_ALL || (which == RADI_PAIRS_LIT) == (lit[i] || lit[j]);
}

static rad_status list_pairs(const rad_anim *a, const unsigned char *dirty, const box_list *bl,
                             route_map *rm, const unsigned char *lit, int which, pair_list *pl,
                             rad_error *err)
{
    const rad_mesh *m = &a->mesh;
    rad_vec3 *lo = malloc(sizeof *lo * (size_t)(a->n + 1));
    rad_vec3 *hi = malloc(sizeof *hi * (size_t)(a->n + 1));
    rad_status st = lo && hi ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (st == RAD_OK)
        element_boxes(m, lo, hi);
    for (int i = 0; st == RAD_OK && i < a->n; i++)
        for (int j = i + 1; j < a->n; j++)
            if (pair_in(lit, which, i, j) && pair_affected(a, dirty, bl, rm, lo, hi, i, j) &&
                push_pair(pl, i, j) != 0) {
                st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for the changed pairs");
                break;
            }
    free(lo);
    free(hi);
    return st;
}

/* time_changed: the nq pairs (qi, qj) of the present mesh pm, whose new
 * values are vij, vji, computed again, only those whose F changed (the
 * old values are a->F's, at[] their list positions), into scratch: the
 * seconds that takes, the form factors' share of a frame that recomputed
 * the changed pairs and no other (rad_anim_report.t_changed).  A failure
 * here leaves the frame alone: the time is then NaN. */
static double time_changed(const rad_anim *a, const pair_list *pl, const rad_mesh *pm,
                           const int *qi, const int *qj, const size_t *at, size_t nq,
                           const double *vij, const double *vji)
{
    const size_t n = (size_t)a->n;
    int *ci = malloc(sizeof *ci * (nq + 1)), *cj = malloc(sizeof *cj * (nq + 1));
    double *s = malloc(sizeof *s * (2 * nq + 2));
    size_t nc = 0;
    rad_error err;
    rad_status st = ci && cj && s ? RAD_OK : RAD_ERR_NOMEM;
    for (size_t q = 0; st == RAD_OK && q < nq; q++) {
        const int i = pl->pi[at[q]], j = pl->pj[at[q]];
        if (vij[q] != a->F[i + j * n] || vji[q] != a->F[j + i * n]) {
            ci[nc] = qi[q];
            cj[nc++] = qj[q];
        }
    }
    const double t0 = radi_seconds();
    if (st == RAD_OK && nc > 0)
        st = radi_ff_pairs(pm, &a->opt.ff, ci, cj, nc, s, s + nc + 1, &err);
    const double t = st == RAD_OK ? radi_seconds() - t0 : NAN;
    free(ci);
    free(cj);
    free(s);
    return t;
}

/* New values of the listed pairs: computed on the mesh of the present
 * surfaces where both ends are present (rep->pairs_recomputed counts
 * them), 0 otherwise; with time_changed, rep->t_changed. */
static rad_status new_values(const rad_anim *a, const pair_list *pl, double *fij, double *fji,
                             rad_anim_report *rep, rad_error *err)
{
    rad_scene ps;
    rad_mesh pm;
    rad_status st = rad_scene_present_copy(&a->scene, a->obj_present, &ps, err);
    if (st != RAD_OK)
        return st;
    memset(&pm, 0, sizeof pm);
    st = rad_mesh_build(&pm, &ps, err);
    int *map = malloc(sizeof *map * (size_t)(a->n + 1));
    int *qi = malloc(sizeof *qi * (pl->n + 1)), *qj = malloc(sizeof *qj * (pl->n + 1));
    size_t *at = malloc(sizeof *at * (pl->n + 1)), nq = 0;
    if (st == RAD_OK && (!map || !qi || !qj || !at))
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for the changed pairs");
    for (int e = 0, k = 0; st == RAD_OK && e < a->n; e++)
        map[e] = a->present[e] ? k++ : -1;
    for (size_t k = 0; st == RAD_OK && k < pl->n; k++) {
        fij[k] = fji[k] = 0;
        if (map[pl->pi[k]] >= 0 && map[pl->pj[k]] >= 0) {
            qi[nq] = map[pl->pi[k]];
            qj[nq] = map[pl->pj[k]];
            at[nq++] = k;
        }
    }
    double *vij = st == RAD_OK ? malloc(sizeof *vij * (nq + 1)) : NULL;
    double *vji = st == RAD_OK ? malloc(sizeof *vji * (nq + 1)) : NULL;
    if (st == RAD_OK && (!vij || !vji))
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for the changed pairs");
    if (st == RAD_OK && nq > 0)
        st = radi_ff_pairs(&pm, &a->opt.ff, qi, qj, nq, vij, vji, err);
    rep->pairs_recomputed = (double)nq;
    if (st == RAD_OK && a->opt.time_changed)
        rep->t_changed = time_changed(a, pl, &pm, qi, qj, at, nq, vij, vji);
    for (size_t q = 0; st == RAD_OK && q < nq; q++) {
        fij[at[q]] = vij[q];
        fji[at[q]] = vji[q];
    }
    free(vij);
    free(vji);
    free(map);
    free(qi);
    free(qj);
    free(at);
    rad_mesh_free(&pm);
    rad_scene_free(&ps);
    return st;
}

/* The power entry k (receiver i, shooter j) moves: animshoot.c's yardstick. */
static double entry_power(const rad_anim *a, int j, size_t k)
{
    const rad_redist *rd = &a->rd;
    const size_t n = (size_t)a->n;
    const int i = rd->recv[k];
    double p = 0;
    (void)j;
    for (int b = 0; b < RAD_BANDS; b++)
        p += fabs(a->rho[i + b * n] * rd->amt[3 * k + b]);
    return a->mesh.elements[i].area * p;
}

/* Does shooter j carry anything to redistribute (T_j != 0)? */
static int has_shot(const double *T, size_t n, int j)
{
    return T[j] != 0 || T[j + n] != 0 || T[j + 2 * n] != 0;
}

/* The entries' count per column: what the old log still holds (pending
 * entries of `old`) and the new pairs (i present, j had shot, dF != 0). */
static void count_entries(const rad_anim *a, const rad_redist *old, const double *T,
                          const pair_list *pl, const double *fij, const double *fji,
                          size_t *count, rad_anim_report *rep)
{
    const size_t n = (size_t)a->n;
    for (size_t j = 0; old->start && j < n; j++)
        for (size_t k = old->start[j]; k < old->start[j + 1]; k++)
            count[j] += !old->done[k] && a->present[old->recv[k]];
    for (size_t k = 0; k < pl->n; k++) {
        const int i = pl->pi[k], j = pl->pj[k];
        const double dij = fij[k] - a->F[i + j * n], dji = fji[k] - a->F[j + i * n];
        /* of the pairs recomputed (both ends present), as the report says;
         * a pair that lost an end changes to 0 without being computed */
        rep->pairs_changed += (dij != 0 || dji != 0) && a->present[i] && a->present[j];
        count[j] += dij != 0 && a->present[i] && has_shot(T, n, j);
        count[i] += dji != 0 && a->present[j] && has_shot(T, n, i);
    }
}

static void put(rad_redist *rd, size_t *at, int i, const double x[RAD_BANDS])
{
    rd->recv[*at] = i;
    for (int b = 0; b < RAD_BANDS; b++)
        rd->amt[3 * *at + b] = x[b];
    (*at)++;
}

/* One entry per pair: the amounts a column holds twice for one receiver
 * are summed (the log's "one remove and one add" per pair, Fig. 5). */
static void merge_columns(rad_redist *rd, size_t n, long *pos)
{
    size_t out = 0;
    for (size_t j = 0; j < n; j++) {
        const size_t lo = rd->start[j], hi = rd->start[j + 1], first = out;
        rd->start[j] = out;
        for (size_t k = lo; k < hi; k++) {
            const int i = rd->recv[k];
            if (pos[i] >= 0) {
                for (int b = 0; b < RAD_BANDS; b++)
                    rd->amt[3 * (size_t)pos[i] + b] += rd->amt[3 * k + b];
                continue;
            }
            pos[i] = (long)out;
            put(rd, &out, i, &rd->amt[3 * k]);
        }
        for (size_t k = first; k < out; k++)
            pos[rd->recv[k]] = -1;
    }
    rd->start[n] = out;
}

/* Write the new values into F and keep, in compressed columns, the old
 * pending amounts and the new ones dF_ij T_j (receiver i present now, j
 * had shot), merged per pair. */
static rad_status store(rad_anim *a, const rad_redist *old, const double *T,
                        const pair_list *pl, const double *fij, const double *fji,
                        rad_anim_report *rep, rad_error *err)
{
    rad_redist *rd = &a->rd;
    const size_t n = (size_t)a->n;
    size_t *count = calloc(n + 1, sizeof *count), total = 0;
    long *pos = malloc(sizeof *pos * (n + 1));
    if (!count || !pos) {
        free(count);
        free(pos);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    count_entries(a, old, T, pl, fij, fji, count, rep);
    for (size_t j = 0; j < n; j++) {
        rd->start[j] = total;
        total += count[j];
        count[j] = rd->start[j];
        pos[j] = -1;
    }
    rd->start[n] = total;
    rd->recv = malloc(sizeof *rd->recv * (total + 1));
    rd->amt = malloc(sizeof *rd->amt * RAD_BANDS * (total + 1));
    if (!rd->recv || !rd->amt) {
        free(count);
        free(pos);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the redistribution");
    }
    for (size_t j = 0; old->start && j < n; j++)
        for (size_t k = old->start[j]; k < old->start[j + 1]; k++)
            if (!old->done[k] && a->present[old->recv[k]])
                put(rd, &count[j], old->recv[k], &old->amt[3 * k]);
    for (size_t k = 0; k < pl->n; k++) {
        const int i = pl->pi[k], j = pl->pj[k];
        const double dij = fij[k] - a->F[i + j * n], dji = fji[k] - a->F[j + i * n];
        if (dij != 0 && a->present[i] && has_shot(T, n, j)) { /* George et al. 1990, eq. 5 */
            const double x[RAD_BANDS] = {dij * T[j], dij * T[j + n], dij * T[j + 2 * n]};
            put(rd, &count[j], i, x);
        }
        if (dji != 0 && a->present[j] && has_shot(T, n, i)) {
            const double x[RAD_BANDS] = {dji * T[i], dji * T[i + n], dji * T[i + 2 * n]};
            put(rd, &count[i], j, x);
        }
        a->F[i + j * n] = fij[k];
        a->F[j + i * n] = fji[k];
    }
    merge_columns(rd, n, pos);
    free(count);
    free(pos);
    return RAD_OK;
}

/* The entries by receiver, the powers and the pending counts. */
rad_status radi_anim_redist_index(rad_anim *a, rad_error *err)
{
    rad_redist *rd = &a->rd;
    const size_t n = (size_t)a->n, total = rd->start[n];
    if (!rd->power && !(rd->power = calloc(n + 1, sizeof *rd->power)))
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the redistribution");
    rd->epow = malloc(sizeof *rd->epow * (total + 1));
    rd->done = calloc(total + 1, 1);
    rd->rstart = calloc(n + 1, sizeof *rd->rstart);
    rd->rent = malloc(sizeof *rd->rent * (total + 1));
    rd->rpower = calloc(n + 1, sizeof *rd->rpower);
    rd->ncol = calloc(n + 1, sizeof *rd->ncol);
    rd->nrow = calloc(n + 1, sizeof *rd->nrow);
    size_t *fill = calloc(n + 1, sizeof *fill);
    if (!rd->epow || !rd->done || !rd->rstart || !rd->rent || !rd->rpower || !rd->ncol ||
        !rd->nrow || !fill) {
        free(fill);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the redistribution");
    }
    for (size_t j = 0; j < n; j++)
        for (size_t k = rd->start[j]; k < rd->start[j + 1]; k++) {
            rd->epow[k] = entry_power(a, (int)j, k);
            rd->power[j] += rd->epow[k];
            rd->rpower[rd->recv[k]] += rd->epow[k];
            rd->left += rd->epow[k];
            rd->ncol[j]++;
            rd->nrow[rd->recv[k]]++;
        }
    for (size_t i = 0; i < n; i++)
        rd->rstart[i + 1] = rd->rstart[i] + (size_t)rd->nrow[i];
    for (size_t j = 0; j < n; j++)
        for (size_t k = rd->start[j]; k < rd->start[j + 1]; k++) {
            const size_t i = (size_t)rd->recv[k];
            rd->rent[rd->rstart[i] + fill[i]++] = k;
        }
    rd->npending = total;
    free(fill);
    return RAD_OK;
}

/* rd: T = B - dB now, the old log's pending amounts and the new columns
 * of dF T, their powers.  Removed elements' old entries are dropped:
 * they hold nothing to receive (B = H = 0). */
static rad_status start_redist(rad_anim *a, const pair_list *pl, const double *fij,
                               const double *fji, rad_anim_report *rep, rad_error *err)
{
    rad_redist old = a->rd, *rd = &a->rd;
    const size_t n = (size_t)a->n;
    memset(rd, 0, sizeof *rd);
    double *T = malloc(sizeof *T * n * RAD_BANDS);
    rd->start = malloc(sizeof *rd->start * (n + 1));
    rd->power = calloc(n, sizeof *rd->power);
    rad_status st = T && rd->start && rd->power
                        ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory for the "
                                            "redistribution");
    for (size_t k = 0; st == RAD_OK && k < n * RAD_BANDS; k++)
        T[k] = a->B[k] - a->dB[k];
    if (st == RAD_OK)
        st = store(a, &old, T, pl, fij, fji, rep, err);
    free(T);
    radi_redist_free(&old);
    return st == RAD_OK ? radi_anim_redist_index(a, err) : st;
}

/* Classic mode's route maps (the header): rm[0] before the change, from
 * old_scene and old_in, rm[1] after it. */
static rad_status route_maps(const rad_anim *a, const unsigned char *dirty,
                             const rad_scene *old_scene, const unsigned char *old_in,
                             route_map rm[2], rad_error *err)
{
    if (a->opt.ff.accuracy != RAD_ACCURACY_CLASSIC || !old_scene)
        return RAD_OK;
    rad_scene ps;
    unsigned char *mark = rm[0].mark = malloc((size_t)a->scene.nsurfaces + 1);
    rad_status st = mark ? route_map_build(a, old_scene, old_in, &rm[0], err)
                         : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    if (st == RAD_OK && (st = rad_scene_present_copy(&a->scene, a->obj_present, &ps, err)) ==
                            RAD_OK) {
        st = route_map_build(a, &ps, a->obj_present, &rm[1], err);
        rad_scene_free(&ps);
    }
    if (st == RAD_OK) {
        mark_surfaces(a, dirty, rm, mark);
        st = route_flags(a, mark, &rm[0], err);
    }
    if (st == RAD_OK)
        st = route_flags(a, mark, &rm[1], err);
    return st;
}

rad_status radi_anim_update_pairs(rad_anim *a, const unsigned char *dirty,
                                 const unsigned char *old_in, const rad_vec3 *old_lo,
                                 const rad_vec3 *old_hi, const rad_scene *old_scene,
                                 const unsigned char *lit, int which, rad_anim_report *rep,
                                 rad_error *err)
{
    route_map rm[2];
    memset(rm, 0, sizeof rm);
    const int no = a->scene.nobjects;
    box_list bl = {malloc(sizeof(rad_vec3) * (size_t)(2 * no + 1)),
                   malloc(sizeof(rad_vec3) * (size_t)(2 * no + 1)), 0};
    pair_list pl = {NULL, NULL, 0, 0};
    double *fij = NULL, *fji = NULL;
    rad_vec3 slo, shi;
    radi_anim_object_box(a, -1, &slo, &shi); /* the environment sets the pad's scale */
    double pad = 1e-9 * (isfinite(shi.x - slo.x) ? v3_norm(v3_sub(shi, slo)) : 1.0);
    rad_status st = bl.lo && bl.hi ? RAD_OK : radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    for (int o = 0; st == RAD_OK && o < no; o++) {
        if (!dirty[o])
            continue;
        rad_vec3 lo, hi;
        radi_anim_object_box(a, o, &lo, &hi);
        if (old_in[o])
            add_box(&bl, old_lo[o], old_hi[o], pad);
        if (a->obj_present[o])
            add_box(&bl, lo, hi, pad);
    }
    if (st == RAD_OK)
        st = route_maps(a, dirty, old_scene, old_in, rm, err);
    if (st == RAD_OK)
        st = list_pairs(a, dirty, &bl, rm, lit, which, &pl, err);
    route_map_free(&rm[0]);
    route_map_free(&rm[1]);
    if (st == RAD_OK) {
        fij = malloc(sizeof *fij * (pl.n + 1));
        fji = malloc(sizeof *fji * (pl.n + 1));
        if (!fij || !fji)
            st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for the changed pairs");
    }
    if (st == RAD_OK)
        st = new_values(a, &pl, fij, fji, rep, err);
    if (st == RAD_OK)
        st = start_redist(a, &pl, fij, fji, rep, err);
    free(fij);
    free(fji);
    free(pl.pi);
    free(pl.pj);
    free(bl.lo);
    free(bl.hi);
    return st;
}
