/* occspace.h -- what the occlusion files share (internal to them): the
 * tolerances, the scene's culling data (struct rad_occ), the per-thread
 * work space and the functions one file calls in another.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * occlusion.c lists the files and their jobs; each function is described
 * where it is defined.
 */
#ifndef RAD_OCCSPACE_H
#define RAD_OCCSPACE_H

#include <math.h>
#include <stddef.h>
#include <time.h>

#include "ff/formfactor.h"
#include "occ/occlusion.h"
#include "radiosity/base.h"
#include "radiosity/formfactor.h"
#include "util/util.h"

/* Tolerances.  A point is on a plane (and a blocker only touches a shaft)
 * within OCC_SNAP of the scene's bounding-box diagonal L, plus the
 * rounding of the scene's coordinates (OCC_ROUND ulps of the largest as
 * the user gave them: the frame's shift, mesh.h, keeps their rounding),
 * plus the surfaces' own departures from planarity (the scene accepts
 * 1e-6 of a quad's size; scene.c): two faces of one twisted panel lie on
 * one plane as far as the data can say.  The kernel decides what is on a
 * plane with the same first two (radi_occ_scene_snap, occshaft.c).
 * Nothing larger: near the origin a blocker 1e-9 of the scene's size
 * from an element is in front of it, and hides what lies behind (a
 * tolerance of 1e-9 L once let a floor's light through to an element
 * 1e-9 above it); far from it, what the coordinates' rounding resolves. */
#define OCC_SNAP 1e-11
#define OCC_ROUND 16
#define OCC_SLIVER 1e-10    /* pieces below this fraction of the inner element
                               are slivers: of the inner element seen from a
                               point, dropped; of the outer element's domain,
                               not cut off (occspace.c, occ_cut_piece) */
/* Per-pair error targets, relative to the occluded A_i F_ij down to
 * OCC_FLOOR of the unoccluded one (occhidden.c, integrate), half of each
 * mode's promise (the kernel's error of the unoccluded S adds to it); the
 * order of the rule on a cell (occrule.c); the largest number of cells
 * the adaptive rule may add to the domain's first ones. */
#define OCC_TOL_DEFAULT 5e-7
#define OCC_TOL_REFERENCE 5e-10
#define OCC_FLOOR RAD_OCC_FLOOR
#define OCC_KERNEL_SHARE 0.25   /* of the promise: see occlusion.c, sharper_sum */
/* The round-off each point-to-polygon sum of the integrand may carry, as
 * a share of the pair's target spread over its domain (occhidden.c,
 * integrate; an evaluation adds one sum per hidden piece): a sum that
 * could carry more is done again in long double (occpoint.c,
 * ff_point_polygon). */
#define OCC_NOISE_SHARE 0.125
/* The round-off of a sum of eq. 6's terms, in eps times the sum of their
 * magnitudes (measured: occpoint.c, ff_point_polygon). */
#define OCC_NOISE_EPS 4.0
/* Classic mode takes the 3-point rule on a fan triangle's four midpoint
 * children, or on the triangle itself when it is smaller than
 * OCC_CLASSIC_ONCE of the outer element (occhidden.c, node_eval): the
 * many small triangles that the pieces of a domain cut by many blockers
 * fan into are then sampled about as densely as the large ones' children.
 * Measured against default mode's F (within 1e-6 of itself), on the
 * entries this changes: torus 250 (bench/scenes.py) 7,540 entries, RMS
 * error 0.0677 of the entry before and 0.068 after, the largest 5.83 and
 * 5.86, the change itself 0.0015 RMS, and half the evaluations; torus 60,
 * squares 6, the closed Cornell box, the cube on a table and a torus in a
 * box likewise (RMS errors up by at most 12%, on squares 6, largest by at
 * most 0.4%).  At 1/32 the squares' largest error doubled. */
#define OCC_CLASSIC_ONCE (1.0 / 64)
/* Default mode raises a cell's order up to 8 before it must split it: a
 * cell whose rule still converges at order 6 spends 112 evaluations more
 * on orders 7 and 8 (48 and 64: the odd orders share their centre),
 * where its four children would start at 52 and most go on to be raised
 * or split again.  Against a limit
 * of 6, measured by the fill's count of evaluations: torus 60
 * (bench/scenes.py) 1,985,441 -> 1,719,305 (-13%), the cube on a table
 * -6.7%, torus 250 -3.6% (with 28 entries left above the promise by
 * their own estimates instead of 34), the Cornell box -0.5%, squares 6
 * the same; every entry within 6e-9 of itself. */
#define OCC_ORDER_DEFAULT 8
#define OCC_ORDER_REFERENCE 10
#define OCC_TAIL_QMAX 0.9 /* a stalled rule's estimate: occhidden.c, slow_tail */
#define OCC_TOUCH_MAX 8   /* blocker vertices on the outer element kept (touch_points) */
/* Default's cells were 1,024.  That stopped a pair whose domain starts
 * with thousands of cells (a triangulated model, 13 to 20 blockers) long
 * before its evaluations did: a split adds three cells for the 52
 * evaluations of its children's first rules, so 1,024 cells are about
 * 18,000 evaluations of splitting, where the budget below allows 40,000
 * and 64 more for each first cell.  On bench/scenes.py torus 250, 34
 * pairs stopped on cells on their first domain and were done again on
 * finer ones, 11 stopped so on every domain, and 15 pairs missed the
 * promise by their own estimates.  With 4,096, 27 stop on their first
 * domain and 2 on every domain, all of them on evaluations, and 6 pairs
 * miss the promise, for 5% fewer evaluations in all (33.3 to 31.6
 * million).  The 36 entries that moved did so within their two
 * estimates, by up to 1.7e-7 of themselves, except the two of a pair
 * visible to 2e-11 of its unoccluded value, whose estimates are 40 to 70
 * times their values in both runs.  16,384 changes nothing more there.
 * Torus 60, squares 6, the scenes of data/ and 20 rooms of the geometry
 * fuzzer (tests/geomfuzz.py, seed 99) never reach 1,024 cells: their
 * tables are the same bytes. */
#define OCC_LEAVES_DEFAULT 4096
#define OCC_LEAVES_REFERENCE 8192
/* ... and the most evaluations of hidden(x) it may spend on a pair
 * beyond those of the first cells: a
 * pair whose integrand keeps a kink inside a piece (in the lens a chord of
 * occeee.c leaves) converges slowly there, and stops here with its
 * estimate (which the fill then reports as an unmet promise).  Default's
 * budgets were 256 leaves and 1e4 evaluations: on the 6x6 Cornell box 14
 * entries above 1e-6 stopped there more than 1e-6 from reference mode's
 * value; with these none do.  Reference's were 2048 and 1e5: with the
 * strips of occeee.c its rows of the closed Cornell box (2x2) missed 1 by
 * 5e-8 there, and by 6e-10 with these. */
#define OCC_EVALS_DEFAULT 4e4
#define OCC_EVALS_REFERENCE 4e5
/* ... and this many more for each of the domain's first cells: a domain
 * of thousands of pieces spends the budgets above on raising a few
 * hundred cells' orders (each of orders 1 to 3 first, occhidden.c eq. 2,
 * whose differences overstate a smooth cell's error).  Seen in rooms of
 * the geometry fuzzer (tests/geomfuzz.py at af114e8, family room, seed
 * 99: pairs with 7 to 10 blockers and 2,298 to 4,225 pieces): in 5 rooms
 * of 20, 54 default entries missed the promise by their own estimates,
 * up to 3.6e-5 of their values; with 64 evaluations more a cell (raising
 * a cell from order 3 to 5 takes about 40) none did, for 11% more time
 * over the 20 rooms.  The closed Cornell box's tables do not change. */
#define OCC_EVALS_PER_CELL 64
/* ... but no more than this many times the budget above, so that a
 * domain cut into a runaway number of pieces stops with its estimate
 * (default mode: 4e5 more at most, 6,250 cells' worth). */
#define OCC_EVALS_CELLS_MAX 10
/* In default mode a pair is first integrated on a domain cut only where
 * each event happens (occevent.c), with OCC_WEDGE_BUDGET of the budgets
 * above; if it misses its target there, it is done again on the domain
 * cut along every event plane, with the whole budgets, and a pair with
 * more than OCC_WEDGE_BLOCKERS blockers first with two blockers' planes
 * still cut only where their events happen (occhidden.c,
 * orient_integral).  (Pairs with more blockers once went to that second
 * domain at once: the wedges alone then left kinks of two blockers'
 * events inside larger pieces, before occevent.c's BB wedges cut them.
 * Now the wedges first: on bench/scenes.py torus 250, 20% fewer
 * evaluations of the hidden part (41.3 to 33.3 million), and one pair
 * more of its 41,905 above the promise by its own estimate (15): one
 * hidden to 1e-13 of its unoccluded value, whose estimate is 2.7e-8 of
 * that value where the promise at that depth asks 1e-10; torus 60 49%
 * fewer, squares 6 31%, the Cornell box at 6x6 0.3%.  Against reference
 * mode's F, every entry of torus 60, of the Cornell box at 3x3 and 6x6
 * and of the closed box and the cube on a table at 3x3 is within 1e-6
 * or its estimate says so, as before.) */
#define OCC_WEDGE_BLOCKERS 4
#define OCC_WEDGE_BUDGET 0.25
/* A blocker within this part of the outer element's size of its plane
 * has every event plane cut whole (occdomain.c, near_outer). */
#define OCC_NEAR_OUTER 1e-4
/* A pair integrated again with narrower lenses (occhidden.c,
 * orient_integral) has OCC_LENS_BUDGET times default mode's budgets
 * above: each strip the lenses add is a piece, and each piece a leaf.
 * (With the budget of the first try, two nearly hidden pairs of the
 * closed 6x6 Cornell box in default mode spent their leaves on the
 * pieces, missed the target by 2e5 and 5e5 times, and kept the first
 * try, one with a lens estimate of 5e-6 of its value.  Reference mode's
 * budgets, eight and ten times default's, are left as they are: four
 * times more cost its fill of that box 5% and confirmed no more
 * entries.) */
#define OCC_LENS_BUDGET 4
/* The events of three edges (occeee.c) are cut for pairs with at most
 * OCC_EEE_BLOCKERS blockers: their number grows as the square of the
 * blockers' (64 edge triples per pair of quads), and a pair with more
 * (seen: 34 with shaft culling off) spent minutes there.  On the Cornell
 * box with culling no pair has more than 9. */
#define OCC_EEE_BLOCKERS 12
/* The chords along the conics of occeee.c leave lenses of the outer
 * element with a kink inside: where a lens is wider than the pair's
 * arc_tol of its chord, the piece is cut into strips first (occeee.c,
 * follow_arc, with the measurements).  Default mode uses
 * OCC_ARC_TOL_DEFAULT, reference mode OCC_ARC_TOL_REFERENCE.  Relative
 * to a partly hidden pair's smaller value the kink in a lens weighs
 * more, so a pair that kept a lens wider than it needs is integrated
 * again with narrower ones (occhidden.c, arcs_by_fraction): in default mode
 * a pair whose occluded value came out below OCC_NEAR_HIDDEN of its
 * unoccluded one, with OCC_ARC_TOL_HIDDEN; in reference mode a pair
 * below OCC_PARTLY_HIDDEN of it, with OCC_ARC_TOL_REFERENCE times the
 * cube root of its visible fraction (the lens's error falls as the cube
 * of its width), down to OCC_ARC_TOL_FINEST. */
#define OCC_ARC_TOL_DEFAULT 1e-2
#define OCC_ARC_TOL_HIDDEN 5e-4
#define OCC_ARC_TOL_REFERENCE 5e-4
#define OCC_ARC_TOL_FINEST 2e-5
#define OCC_NEAR_HIDDEN 0.1
#define OCC_PARTLY_HIDDEN 0.25
/* A pair whose lenses' error estimate (occeee.c, eq. 2) is above
 * OCC_ARC_SHARE of its target is integrated again with narrower lenses
 * too (occhidden.c, arcs_by_estimate).  The target is half the promise
 * and the rules' estimate stops below it, so a quarter more for the
 * lenses keeps the two together within the promise. */
#define OCC_ARC_SHARE 0.25

struct rad_occ {
    rad_occ_mode mode;
    rad_accuracy accuracy;
    int nsurf;
    rad_vec3 *sv;               /* surface polygons: sv[sfirst[s] .. sfirst[s+1]) */
    int *sfirst;
    rad_vec3 *snormal, *slo, *shi;
    double *stwist;             /* each surface's largest vertex distance from
                                   its plane through the vertex mean */
    int *esurf;                 /* surface of each element */
    int *twin;                  /* an earlier surface that is this one reversed
                                   (a two-sided panel's other face), or -1 */
    size_t *cand_off;           /* candidates of surface pair p: cand[cand_off[p] ..) */
    int *cand;
    double snap;                /* absolute tolerance (see OCC_SNAP) */
    int *solid;                 /* each surface's convex solid (occsolid.c), or -1 */
    int nsolid;
    int *hfirst;                /* solid g's face planes: [hfirst[g], hfirst[g+1]) */
    rad_vec3 *hnrm, *hpt;       /* outward unit normal, a point */
    unsigned char *hopen;       /* the solid's surfaces do not cover the facet */
    int *patch;                 /* each surface's coplanar patch (occflat.c), or -1 */
    int npatch;
    rad_vec3 *pv;               /* patch g's polygon: pv[pfirst[g] .. pfirst[g+1]) */
    int *pfirst;
    int *prep;                  /* one member of each patch */
    int *closed;                /* each surface's closed mesh (occclosed.c), or -1 */
    int nclosed;
    rad_vec3 *clo, *chi;        /* each closed mesh's box */
};

/* Index of the unordered surface pair a < b among ns(ns-1)/2. */
static inline size_t pair_index(int a, int b, int ns)
{
    return (size_t)a * (size_t)(2 * ns - a - 1) / 2 + (size_t)(b - a - 1);
}

/* One cell of the adaptive rule, a triangle or (default and reference
 * modes) a convex quadrilateral: the 3-point values of its four midpoint
 * children, or of itself alone in qc[0] (classic), or its product rules'
 * values. */
typedef struct tri_node {
    rad_vec3 p[4];
    int nv;                     /* its vertices, 3 or 4 */
    double area;
    double q;                   /* the rule on the cell */
    double qc[4];               /* the rule on each child */
    double err;                 /* its estimated error */
    double dlast;               /* the last difference of two orders */
    int order;                  /* the product rule's order (occrule.c), or 0 */
    int stalled;                /* raising the order did not help: split */
    double center;              /* hidden(x) at the point the odd orders
                                   share, or NaN (occrule.c) */
    int lfirst, ln;             /* the blockers that may hide anything from
                                   the cell: sp->clist[lfirst .. lfirst + ln)
                                   (occdomain.c, occ_cell_blockers) */
} tri_node;

/* The leaves of the adaptive rule as a tournament tree (occleaves.c):
 * best[1] the leaf with the largest estimate (-1: none), err[1] and
 * val[1] the sums of the leaves' estimates and values. */
typedef struct occ_leaves {
    int *best;
    double *err, *val;
    int cap;                    /* leaves the tree holds (a power of 2) */
    int alloc;                  /* leaves the arrays can hold */
} occ_leaves;

/* A list of polygons sharing one vertex array. */
typedef struct polyset {
    rad_vec3 *v;
    int nv, capv;
    int *first;                 /* np + 1 entries */
    int np, capp;
} polyset;

/* Per-thread space. */
typedef struct occ_space {
    polyset loc;                /* the two elements in the pair's frame: 0 = i, 1 = j */
    polyset elem;               /* the two clipped elements: 0 = i, 1 = j */
    polyset blk;                /* the pair's blockers, whole */
    polyset blkc;               /* the same, clipped to the front of the inner plane */
    int *bid;                   /* surface of each blocker of the pair */
    int capb;
    rad_vec3 *bn, *bc;          /* clipped blockers: normal, centroid */
    int capbn, capbc;
    double *br;                 /* the radius of a ball about bc holding the
                                   clipped blocker (occunion.c, in_pyramid) */
    int capbr;
    polyset cur, next;          /* visible pieces before / after a blocker */
    rad_vec3 *rem, *tmp, *tmp2; /* the piece being cut, and the cut's output
                                   (tmp2: the other side, occdomain.c) */
    int caprem, captmp, captmp2;
    double *d;                  /* signed distances */
    int capd;
    rad_vec3 *cone, *conep;     /* cone planes: inward normal, point */
    int capcone, capconep;
    rad_vec3 *sn, *sa;          /* penumbra or umbra planes of all blockers */
    int capsn, capsa;
    int *sfirst;                /* blocker b's planes: [sfirst[b], sfirst[b+1]) */
    int capsf;
    int *empty;                 /* blocker b's umbra has no interior */
    int capem;
    rad_vec3 *pn, *pa;          /* the penumbra planes of all blockers, kept
                                   for the cells (occ_cell_blockers) */
    int cappn, cappa;
    int *pfirst;                /* blocker b's: [pfirst[b], pfirst[b+1]) */
    int cappf;
    int *clist;                 /* the cells' lists of blockers, one after
                                   another (tri_node.lfirst, ln) */
    int capclist, nclist;
    int cell_on;                /* 1 while a cell is evaluated: only the
                                   blockers clist[cell_first ..
                                   cell_first + cell_n) are taken (occunion.c) */
    int cell_first, cell_n;
    polyset da, db;             /* the support domain while it is built */
    polyset dom;                /* the support domain: disjoint convex pieces */
    rad_vec3 *pcen, *qcen;      /* bounding spheres of dom's (p) and db's (q)
                                   pieces while split_events runs */
    double *prad, *qrad;
    int cappc, capqc, cappr, capqr;
    polyset umb;                /* its pieces inside some blocker's umbra */
    polyset arc;                /* a piece cut along an arc and its strips,
                                   in the order made (occeee.c, follow_arc) */
    polyset arc2;               /* the pieces after one of two arcs is cut
                                   (occeee.c, follow_two_arcs) */
    rad_vec3 *pj0, *pj1;        /* a blocker's shadow on the inner plane, clipped */
    int cappj0, cappj1;
    rad_vec3 *hn, *ha;          /* hull planes: outward normal, point */
    int caphn, capha;
    tri_node *node;
    int capnode;
    int nhull;                  /* the pair's shaft: the face planes
                                   hn/ha[0 .. nhull) of occshaft.c (0: not
                                   built, with culling off) */
    occ_leaves leaves;          /* the tree of sp->node's leaves */
    double snap;                /* the pair's tolerance: o->snap plus the
                                   twists of its surfaces and candidates */
    int any_hidden, any_visible;/* over the pair's evaluations */
    double arc_left;            /* the widest lens a chord of occeee.c left,
                                   a part of its chord */
    double arc_err;             /* the error estimate of the lenses the
                                   chords of occeee.c left (its eq. 2), in
                                   the units of the hidden-part integral */
    double noise_tol;           /* the round-off allowed in one point-to-
                                   polygon sum (OCC_NOISE_SHARE) */
    double evals;
    polyset sh;                 /* the blockers' shadows on the inner plane
                                   (occunion.c) */
    double *box;                /* their boxes in the plane's axes */
    int capbox;
    int *nbr, *nbr_off, *fill;  /* the shadows whose boxes meet each one's */
    int capnbr, capnoff, capfill;
    struct sweep_key *sweep;    /* the boxes in order (occunion.c) */
    int capsweep;
    double *uv, *tuv;           /* their vertices and the inner element's
                                   in the plane's axes */
    int capuv, captuv;
    rad_vec3 *upl;              /* the pyramid from x over the inner element */
    int capupl;
    rad_vec3 *tw;               /* the inner element widened (its edges: the
                                   pyramid's), set once a pair (occunion.c) */
    int captw;
    double *iv;                 /* an edge's covered intervals */
    int capiv;
    int *inner;                 /* each shadow edge: 1 when it is interior
                                   to the union (occunion.c, inner_edges) */
    int capinner;
    int *ehash;                 /* the shadow edges hashed by their ends */
    int capehash;
    int *ccut;                  /* blockers a closed mesh makes redundant,
                                   per side (occclosed.c) */
    int capccut;
    int *xcull;                 /* blocker k of the pair, x on element i
                                   (2k) or j (2k + 1): 1 when a point x behind
                                   k's plane may leave k out (occclosed.c) */
    int capxcull, nxcull;       /* nxcull: the blockers it is for, 0: none */
    int *bx;                    /* the same for the clipped blockers, x on
                                   the outer element (occhidden.c) */
    int capbx;
    rad_vec3 *seg;              /* the union's boundary: pairs of ends */
    int capseg, nseg;
    int *mflag;                 /* each vertex of blkc: OCC_MESH_EDGE when the
                                   edge from it is inside the union of the
                                   shadows for the whole outer element,
                                   OCC_MESH_VERTEX when it is (occmesh.c) */
    int capmflag;
    int *mside;                 /* each clipped blocker: the side of it the
                                   outer element lies on, or 0 */
    int capmside;
    struct mesh_edge *medge;    /* blkc's edges by their ends (occmesh.c) */
    int capmedge;
    rad_vec3 *mends;            /* the ends of its boundary edges */
    int capmends;
} occ_space;

/* What an evaluation needs: the outer element's normal, the inner element
 * (clipped) and the blockers (clipped to the front of the inner plane). */
typedef struct pair_ctx {
    rad_vec3 nx;                /* outer normal */
    rad_vec3 tn;                /* inner normal */
    const rad_vec3 *t;          /* inner element */
    int nt;
    int flat;                   /* the inner element is planar to round-off
                                   (occhidden.c, orient_integral): shadows may
                                   be taken on its plane (occpoint.c,
                                   hidden_last; occunion.c) */
    int nb;                     /* blockers in sp->blkc, sp->bn, sp->bc, sp->br */
    double snap, sliver;        /* distance and area tolerances */
    int events;                 /* split the domain along the event planes:
                                   0 not at all (classic, which leaves the
                                   umbras uncut too), OCC_SPLIT_ALL along
                                   each plane, OCC_SPLIT_WEDGES only where its
                                   event happens (occevent.c) */
    int pair_wedges;            /* cut the planes of two blockers' events
                                   only where they happen (occevent.c) */
    int direct;                 /* evaluate visible(x), not hidden(x) (occpoint.c) */
    double outer_area;          /* the outer element's area */
    int order;                  /* the rule on a cell (occrule.c): 0 the
                                   3-point rule, k >= 2 the k x k Gauss
                                   product (collapsed on a triangle) */
    double arc_tol;             /* the widest lens a chord of occeee.c may
                                   leave, a part of the chord (OCC_ARC_TOL_*) */
    rad_vec3 touch[OCC_TOUCH_MAX]; /* blocker vertices on the outer element
                                      (occhidden.c, touch_points) */
    int ntouch;
    /* the inner plane as occunion.c sees it, set once a pair by
     * occ_union_frame (its vertices in these axes: sp->tuv; widened
     * about their mean: sp->tw) */
    int uframe;                 /* 1 when set (0: not flat, or its first
                                   edge has no length) */
    rad_vec3 ue[2];             /* the plane's axes */
    double usense;              /* +1 or -1: the inner element's turn about tn */
    double tbox[4];             /* its box in those axes: ulo, uhi, vlo, vhi */
    rad_vec3 tmean;             /* the mean of its vertices */
    double tarea;               /* its area */
    int whole_near;             /* leave a blocker that the pyramid crosses
                                   whole when it is not near x's level
                                   (classic mode; occunion.c, OCC_UNION_NEAR) */
} pair_ctx;



enum { OCC_SPLIT_ALL = 1, OCC_SPLIT_WEDGES = 2 };

/* Where on an event plane the event happens (occevent.c): the event
 * plane's part inside n half-spaces, each with inward unit normal m[h]
 * through a[h]. */
typedef struct occ_wedge {
    rad_vec3 m[4], a[4];
    int n;
    int split;                  /* two wedges: half-spaces [0, split) and
                                   [split, n) (OCC_EVENT_BB); else n */
    int always;                 /* in force with c->events OCC_SPLIT_ALL too */
} occ_wedge;

enum { OCC_EVENT_EV, OCC_EVENT_VE, OCC_EVENT_BB };  /* blocker edge and inner vertex,
                                          inner edge and blocker vertex, or
                                          an edge of one blocker and a
                                          vertex of another */

/* ---- across the files (each described where it is defined) ------------ */

/* occspace.c: growable arrays, polysets, the cuts */
void *occ_realloc(void *p, int *cap, int need, size_t size);
int occ_ps_push(polyset *s, const rad_vec3 *p, int n);
int occ_ps_push_shifted(polyset *s, const rad_vec3 *p, int n, rad_vec3 origin);
void occ_ps_pop(polyset *s);
void occ_space_free(occ_space *sp);
int occ_clip_into(occ_space *sp, polyset *s, const rad_vec3 *p, int n, rad_vec3 nrm,
                  rad_vec3 a, double tol);
enum { OCC_SLIVERS_DROP, OCC_SLIVERS_KEEP, OCC_SLIVERS_MERGE }; /* occ_cut_piece */
int occ_cut_piece(occ_space *sp, const rad_vec3 *nrm, const rad_vec3 *pt, int np, double snap,
                  double sliver, int slivers, polyset *out, int *n);
int occ_load_rem(occ_space *sp, const polyset *s, int k);

/* occshaft.c: the pair's blockers */
int occ_clip_pair(occ_space *sp, const rad_vec3 *p, int np, rad_vec3 pn, const rad_vec3 *q,
                  int nq, rad_vec3 qn, double tol);
double occ_pair_snap(const rad_occ *o, int a, int b, const int *cand, int ncand);
int occ_pair_shaft(const rad_occ *o, occ_space *sp, int sa, int sb, const rad_ff_poly *pi,
                   const rad_ff_poly *pj, rad_vec3 origin);
int occ_pair_blockers(const rad_occ *o, occ_space *sp, int sa, int sb, const rad_ff_poly *pi,
                      const rad_ff_poly *pj, rad_vec3 origin);

/* occsolid.c: convex solids, and the faces a pair may leave out */
rad_status occ_find_solids(rad_occ *o);
/* occtree.c: the surfaces' boxes in a tree, walked by a shaft */
typedef struct occ_tree occ_tree;
occ_tree *occ_tree_create(const rad_occ *o);
void occ_tree_free(occ_tree *t);
int occ_tree_shaft(const occ_tree *t, rad_vec3 lo, rad_vec3 hi, const rad_vec3 *hn,
                   const rad_vec3 *ha, int nh, double tol, int *out);
/* occclosed.c: closed meshes, and their faces a pair need not take */
rad_status occ_find_closed(rad_occ *o);
int occ_closed_cull(const rad_occ *o, occ_space *sp, int nb, int sa, int sb,
                    const rad_ff_poly *pi, const rad_ff_poly *pj, rad_vec3 origin);
/* occflat.c: coplanar neighbours as one blocker */
rad_status occ_find_patches(rad_occ *o);
int occ_flat_blockers(const rad_occ *o, occ_space *sp, int nb, int sa, int sb, rad_vec3 origin);
int occ_solid_cull(const rad_occ *o, occ_space *sp, int nb, rad_vec3 origin);

/* occdomain.c: the domain of integration */
int occ_support_domain(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no);
int occ_cell_blockers(occ_space *sp, const pair_ctx *c, const rad_vec3 *p, int nv, int lfirst,
                      int ln);

/* occunion.c: hidden(x) from the boundary of the union of the shadows
 * (1; 0 where it does not apply, -1) */
int occ_union_frame(occ_space *sp, pair_ctx *c);
int occ_hidden_union(occ_space *sp, const pair_ctx *c, rad_vec3 x, double *out);

/* occsplit.c: sp->dom's pieces split by a plane (their bounding spheres
 * first, then every piece the plane crosses; with a wedge w only where
 * its chord meets w), or by a whole plane after occeee.c's cuts */
int occ_dom_spheres(occ_space *sp);
int occ_split_dom(occ_space *sp, const pair_ctx *c, rad_vec3 nrm, rad_vec3 a,
                  const occ_wedge *w, double sliver);
int occ_split_plane(occ_space *sp, const pair_ctx *c, rad_vec3 nrm, rad_vec3 a);

/* occevent.c: the wedges of the event planes */
void occ_event_wedge(occ_wedge *w, int kind, rad_vec3 nrm, rad_vec3 e0, rad_vec3 e1,
                     rad_vec3 f);
int occ_event_misses(const occ_wedge *w, const rad_vec3 *p, const double *d, int n, double tol);

/* occeee.c: the events of three edges, cut by chords (but for the
 * blocker edges sp->mflag marks inside the union: occmesh.c first) */
int occ_split_three_edges(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no);

/* occmesh.c: sp->mflag for the pair's clipped blockers (sp->blkc) seen
 * from the outer element o (no vertices): the edges and vertices that
 * take part in no event.  0 or -1 (out of memory). */
enum { OCC_MESH_EDGE = 1, OCC_MESH_VERTEX = 2 };
int occ_mesh_interior(occ_space *sp, const pair_ctx *c, const rad_vec3 *o, int no);

/* occpoint.c: hidden(x) */
int occ_hidden_at(occ_space *sp, const pair_ctx *c, rad_vec3 x, double *out);

/* occrule.c: the integral of hidden(x) over one cell.  occ_rule: c's
 * rule on a triangle (the 3-point rule, or the collapsed product of
 * order c->order); occ_rule_order: the product rule of order k on a cell
 * of nv vertices; occ_cell_children: the four children a cell is split
 * into (a triangle's midpoint triangles, or the quarters of a
 * quadrilateral's bilinear map). */
int occ_rule(occ_space *sp, const pair_ctx *c, const rad_vec3 *p, double area, double *q);
/* The n = k^2 points x and weights w of occ_rule_order's rule of order k
 * on cell p (nv 3 or 4 vertices, area `area`); returns n. */
int occ_rule_points(int k, const rad_vec3 *p, int nv, double area, rad_vec3 *x, double *w);
int occ_rule_order(occ_space *sp, const pair_ctx *c, int k, const rad_vec3 *p, int nv,
                   double area, double *q, double *center);
void occ_cell_children(const rad_vec3 *p, int nv, rad_vec3 ch[4][4]);

/* occleaves.c: the worst leaf and the sums, O(log n) per change.  Build
 * from node[0 .. n); set: node[k] changed and n leaves are in use (the
 * tree grows when n passes its capacity).  0, or -1 on memory. */
int occ_leaves_build(occ_leaves *lt, const tri_node *node, int n);
int occ_leaves_set(occ_leaves *lt, const tri_node *node, int k, int n);
void occ_leaves_free(occ_leaves *lt);

/* occhidden.c: how much of a pair is hidden */
int occ_occluded_sum(const rad_occ *o, occ_space *sp, rad_occ_stats *st, int nb,
                     const rad_ff_poly *pi, const rad_ff_poly *pj, double s, double *snew,
                     double *errest, int *direct);

/* Make room for `need` elements in *p (capacity *cap); 0, or -1 when
 * memory ran out (then *p is untouched).  One per element type, so that
 * no pointer is accessed through a pointer of another type; the check is
 * inline (the cuts call it once per plane), the growth is occ_realloc. */
#define OCC_GROW(name, T)                                                                   \
    static inline int name(T **p, int *cap, int need)                                       \
    {                                                                                       \
        if (need <= *cap)                                                                   \
            return 0;                                                                       \
        T *q = occ_realloc(*p, cap, need, sizeof *q);                                       \
        if (!q)                                                                             \
            return -1;                                                                      \
        *p = q;                                                                             \
        return 0;                                                                           \
    }
OCC_GROW(occ_grow_v3, rad_vec3)
OCC_GROW(occ_grow_d, double)
OCC_GROW(occ_grow_node, tri_node)
OCC_GROW(occ_grow_i, int)

/* Points in lexicographic order (x, then y, then z): -1, 0 (the same
 * numbers), 1.  The setup files match shared vertices with it, bit for
 * bit (occsolid.c, occflat.c, occclosed.c). */
static inline int occ_vec_cmp(rad_vec3 a, rad_vec3 b)
{
    if (a.x != b.x)
        return a.x < b.x ? -1 : 1;
    if (a.y != b.y)
        return a.y < b.y ? -1 : 1;
    if (a.z != b.z)
        return a.z < b.z ? -1 : 1;
    return 0;
}

/* The root of a in a union-find forest (parent), halving the path. */
static inline int occ_uf_find(int *parent, int a)
{
    while (parent[a] != a)
        a = parent[a] = parent[parent[a]];
    return a;
}

/* Exchange two growable arrays (a cut's input and output). */
static inline void occ_swap_v3(rad_vec3 **a, int *capa, rad_vec3 **b, int *capb)
{
    rad_vec3 *t = *a;
    int tc = *capa;
    *a = *b;
    *capa = *capb;
    *b = t;
    *capb = tc;
}

static inline void occ_ps_clear(polyset *s)
{
    s->nv = s->np = 0;
}

/* The difference q - x in long double: exact where the two exponents
 * are within 11 of each other, else rounded once in long double. */
static inline void occ_diff_long(rad_vec3 q, rad_vec3 x, long double r[3])
{
    r[0] = (long double)q.x - x.x;
    r[1] = (long double)q.y - x.y;
    r[2] = (long double)q.z - x.z;
}

/* One edge's term of eq. 6 (occpoint.c) in long double, edge a -> b seen
 * from x (occpoint.c and occunion.c sum them): from differences that are
 * exact there. */
static inline long double occ_edge_term_long(rad_vec3 a, rad_vec3 b, rad_vec3 x, rad_vec3 nrm)
{
    long double r0[3], r1[3];
    occ_diff_long(a, x, r0);
    occ_diff_long(b, x, r1);
    const long double c[3] = {r0[1] * r1[2] - r0[2] * r1[1], r0[2] * r1[0] - r0[0] * r1[2],
                              r0[0] * r1[1] - r0[1] * r1[0]};
    const long double cn = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (!(cn > 0))
        return 0;
    return atan2l(cn, r0[0] * r1[0] + r0[1] * r1[1] + r0[2] * r1[2]) *
           (nrm.x * c[0] + nrm.y * c[1] + nrm.z * c[2]) / cn;
}

#endif /* RAD_OCCSPACE_H */
