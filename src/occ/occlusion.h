/* occlusion.h -- hidden surfaces in the form factors (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The matrix fill (ffmatrix.c) computes the unoccluded contour sum S of
 * each unordered pair {i, j} (S = 2 pi A_i F_ij = 2 pi A_j F_ji) and hands
 * it to radi_occ_pair, which returns it unchanged when nothing can stand
 * between the two elements, 0 when they are fully hidden from each other,
 * and S minus 2 pi times the hidden part otherwise.  The value stays one
 * symmetric number per pair, so reciprocity A_i F_ij = A_j F_ji survives
 * occlusion exactly.  occlusion.c lists the files that do the work and
 * what each does.
 */
#ifndef RAD_OCCLUSION_H
#define RAD_OCCLUSION_H

#include "ff/formfactor.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"

typedef enum rad_occ_mode {
    RAD_OCC_AUTO = 0,   /* shaft culling decides which pairs need visibility */
    RAD_OCC_OFF,        /* no hidden surfaces (Goral et al. 1984) */
    RAD_OCC_ALL         /* no culling: every other surface is a possible blocker
                           of every pair (slow; for tests of the culling) */
} rad_occ_mode;

/* What the visibility work found and cost.  Counts are doubles like those
 * of rad_ff_stats (n^2/2 overflows an int for large meshes). */
typedef struct rad_occ_stats {
    int needed;                 /* 0: no pair of surfaces can be blocked, and
                                   no visibility work was done at all */
    double surfaces;            /* surfaces (blocker polygons) in the scene */
    double closed_meshes;       /* closed meshes found among them (occclosed.c) */
    double pairs_tested;        /* element pairs with S != 0 looked at */
    double pairs_blockable;     /* ... whose shaft meets another surface */
    double pairs_blocked;       /* ... found fully hidden: F = 0 */
    double pairs_partial;       /* ... found partly hidden */
    double candidates;          /* blockers summed over the blockable pairs:
                                   what the shaft test and the culls of
                                   occ_pair_blockers left each */
    double evaluations;         /* point evaluations of the hidden part */
    double max_errest;          /* largest estimated absolute error of an
                                   occluded F_ij (either direction) */
    double seconds;             /* setup (wall) plus time inside the pair hook,
                                   summed over threads */
} rad_occ_stats;

/* Per-scene data, read-only once built (shared by the fill's threads). */
typedef struct rad_occ rad_occ;

/* What lies within this of a plane is on it, beyond the surfaces' own
 * twists, for visibility and the kernel's decision alike (formfactor.c,
 * pair_setup): OCC_SNAP of the diagonal of the box of the n points v
 * (a scene's vertices, in a frame whose offset is off: radi_frame_offset,
 * mesh.h) plus OCC_ROUND ulps of their largest coordinate as the user
 * gave them (v[k] + off), which the frame keeps (occspace.h). */
double radi_occ_scene_snap(const rad_vec3 *v, int n, rad_vec3 off);

/* Build the culling data of a mesh (normalized: mesh.h) whose on-plane
 * tolerance is snap (radi_occ_scene_snap, above: the kernel's polygons
 * carry the same number).  *occ is NULL on return when the mode is
 * RAD_OCC_OFF or when no pair of surfaces can be blocked: then no
 * visibility work is needed.  From opt: the accuracy, the threads that
 * list the candidate blockers, and the progress callback (stage
 * "visibility"; a non-zero return stops the setup: RAD_ERR_INVALID,
 * "interrupted").  stats (may be NULL) is cleared and receives the
 * setup's share. */
rad_status radi_occ_create(rad_occ **occ, const rad_mesh *mesh, double snap, rad_occ_mode mode,
                          const rad_ff_options *opt, rad_occ_stats *stats, rad_error *err);
void radi_occ_free(rad_occ *occ);

/* Is a surface c with mask[c] set on the candidate list of the pair of
 * surfaces a, b (occshaft.c): may the fill count it as a blocker of some
 * pair of their elements?  With occ NULL (nothing can be blocked), no. */
int radi_occ_candidate(const rad_occ *occ, int a, int b, const unsigned char *mask);

/* The convex solid surface s belongs to (occsolid.c: the faces a pair's
 * blocker list may leave out depend on all of its members), or -1. */
int radi_occ_solid(const rad_occ *occ, int s);

/* Per-thread work space and counters. */
typedef struct rad_occ_work {
    const rad_occ *occ;
    rad_occ_stats stats;        /* this thread's counts */
    void *space;                /* growable buffers (occspace.h) */
    rad_ff_scratch kernel;      /* for the unoccluded sum again (occlusion.c,
                                   sharper_sum) */
} rad_occ_work;

void radi_occ_work_init(rad_occ_work *w, const rad_occ *occ);
void radi_occ_work_free(rad_occ_work *w);

/* Apply occlusion to the pair (i, j) of the element polygons `polys` (as
 * made by the fill: the mesh's normals, centroids and areas): *s is the
 * unoccluded contour sum on entry and the occluded one on return; *errest
 * (may be NULL) is increased by the estimated absolute error of the
 * change, in the units of s; *scale (may be NULL) receives what the
 * accuracy promise of the pair is relative to, in the same units: |S|,
 * or RAD_OCC_FLOOR of the unoccluded |S| where that is larger (the
 * promise holds relative to the occluded value down to pairs hidden
 * to that part of their unoccluded one; a pair hidden further is
 * integrated to that floor, and its error relative to its own tiny value
 * would say nothing).  Returns 0, or -1 when memory ran out. */
#define RAD_OCC_FLOOR 1e-4
int radi_occ_pair(rad_occ_work *w, const rad_ff_poly *polys, int i, int j, double *s,
                 double *errest, double *scale);

/* What radi_occ_pair's work on the pair (i, j) rests on, its route: the
 * snap tolerance (*snap, 0 when no surface is a candidate) and the
 * surfaces the element shaft keeps, before the solids cull them (ids,
 * room for cap).  Two scenes that give a pair the same route give it the
 * same bits when they also agree on the pair's elements, on those
 * surfaces, on the solids they belong to (every member: the cull reads
 * the solid's planes) and on the scene's frame and snap (animpairs.c
 * checks all of it).  Returns their count, -1 when memory ran out, -2
 * beyond cap. */
int radi_occ_pair_route(rad_occ_work *w, const rad_ff_poly *polys, int i, int j, int *ids,
                       int cap, double *snap);

/* The visibility fields of a form-factor record (vis_*) from v. */
void radi_occ_stats_to_ff(const rad_occ_stats *v, rad_ff_stats *st);

/* into += from (counts and times add, maxima combine). */
void radi_occ_stats_add(rad_occ_stats *into, const rad_occ_stats *from);

/* rad_ff_matrix with a choice of visibility mode and its statistics
 * (vstats may be NULL); rad_ff_matrix is this with RAD_OCC_AUTO.
 * Defined in ffmatrix.c. */
rad_status radi_ff_matrix_occ(const rad_mesh *mesh, const rad_ff_options *opt,
                             rad_occ_mode mode, double *F, double *errest,
                             rad_ff_stats *stats, rad_occ_stats *vstats, rad_error *err);

#endif /* RAD_OCCLUSION_H */
