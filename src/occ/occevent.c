/* occevent.c -- where on an event plane the kink of hidden(x) runs: the
 * part of the plane that occdomain.c's split_events need cut a piece for.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * hidden(x) has a kink where, seen from x, a blocker's vertex crosses an
 * edge of the inner element (VE) or a blocker's edge crosses a vertex of
 * it (EV) (Heckbert, "Discontinuity meshing for radiosity", Eurographics
 * Workshop on Rendering 1992; Lischinski, Tampieri & Greenberg, "Discontinuity
 * meshing for accurate radiosity", IEEE CG&A 12(6), 1992).  Both happen on
 * the plane through the edge and the vertex, but only on a wedge of it,
 * the points x on a line that meets both:
 *   EV (blocker edge e0 e1, inner vertex f): x = f + s (y - f), y on the
 *      edge, s >= 1: beyond the edge as seen from f, the region between
 *      the rays from f through e0 and e1 on the far side of the edge's line;
 *   VE (inner edge e0 e1, blocker vertex f): x = y + s (f - y), y on the
 *      edge, s >= 1: the vertical angle at f of the triangle f e0 e1, the
 *      region opposite e1 across the line f e0 and opposite e0 across f e1;
 *   BB (an edge e0 e1 of one blocker, a vertex f of another: where, seen
 *      from x, f's shadow crosses the edge's and the union of the shadows
 *      gains or loses a corner): x on a line through f that meets the
 *      edge, f nearer x or the edge nearer x, so the union of two wedges,
 *      the angle at f of the triangle f e0 e1 (with what lies beyond the
 *      edge) and its vertical angle.  Across the rest of the plane f's
 *      shadow crosses only the line of the edge's shadow, not the edge's.
 * Elsewhere on the plane x sees no event (the segment from x to the vertex
 * misses the edge), and hidden(x) is as smooth across the plane as on
 * either side.  A piece that the plane crosses only there need not be cut:
 * with a box as the blocker, most of the 32 planes of each face cross the
 * outer element far from their wedge, and each needless cut adds a piece
 * whose rule costs 14 or more evaluations of hidden(x).
 *
 * A wedge is kept as the half-spaces (boundary planes at right angles to
 * the event plane) whose intersection with the event plane it is.  A piece
 * is left whole only when its chord on the event plane lies wholly outside
 * one of them by more than the pair's tolerance: when in doubt, cut.
 *
 * The cuts left out are no events.  Before occeee.c cut the events of
 * three edges (an edge of each of two blockers lined up with one of the
 * inner element, seen from x), the extra cuts did refine the domain
 * where those left kinks inside a piece, kinks that the adaptive rule's
 * estimate can miss.  So occhidden.c cuts only the wedges of one blocker
 * for pairs with few blockers (OCC_SPLIT_WEDGES), and in default mode
 * only the wedges of two blockers (BB, w->always) for every pair; a pair
 * that misses its target so is done again with every plane cut whole,
 * as reference mode always does.  (The BB planes are most of a
 * triangulated model's cuts: on a torus of 90 triangles under a lamp
 * (bench/scenes.py), the pieces of a pair with 20 blockers went from
 * 1,880 after the planes of one blocker to 8,143 after those of two, and
 * default mode's fill took half the time with the BB wedges, every entry
 * within 2.2e-8 of reference mode's, within the estimates of both.)
 */
#include <config.h>

#include <math.h>

#include "occ/occspace.h"
#include "util/util.h"

/* Add to w the half-space (of the event plane, unit normal nrm) bounded
 * by the line through a and b: the side of ref when `in`, else the other
 * one.  A degenerate line adds nothing (the wedge only grows). */
static void add_side(occ_wedge *w, rad_vec3 nrm, rad_vec3 a, rad_vec3 b, rad_vec3 ref, int in)
{
    rad_vec3 m = v3_cross(nrm, v3_sub(b, a));
    double len = v3_norm(m);
    if (!(len > 0))
        return;
    m = v3_scale(m, 1.0 / len);
    double s = v3_dot(m, v3_sub(ref, a));
    if (s == 0)
        return;
    if ((s > 0) != (in != 0))
        m = v3_scale(m, -1.0);
    w->m[w->n] = m;
    w->a[w->n] = a;
    w->n++;
}

void occ_event_wedge(occ_wedge *w, int kind, rad_vec3 nrm, rad_vec3 e0, rad_vec3 e1,
                     rad_vec3 f)
{
    w->n = 0;
    w->always = 0;
    if (kind == OCC_EVENT_EV) {
        add_side(w, nrm, f, e0, e1, 1);
        add_side(w, nrm, f, e1, e0, 1);
        add_side(w, nrm, e0, e1, f, 0);
    } else if (kind == OCC_EVENT_VE) {
        add_side(w, nrm, f, e0, e1, 0);
        add_side(w, nrm, f, e1, e0, 0);
    } else {
        /* BB: the lines through f that meet the edge, on either side of f */
        add_side(w, nrm, f, e0, e1, 1);
        add_side(w, nrm, f, e1, e0, 1);
        w->split = w->n;
        add_side(w, nrm, f, e0, e1, 0);
        add_side(w, nrm, f, e1, e0, 0);
        return;
    }
    w->split = w->n;
}

/* Does the chord x[0 .. nx) lie wholly outside one of the half-spaces
 * [h0, h1) of w by more than tol? */
static int chord_misses(const occ_wedge *w, int h0, int h1, const rad_vec3 *x, int nx, double tol)
{
    for (int h = h0; h < h1; h++) {
        int out = 1;
        for (int k = 0; k < nx && out; k++)
            out = v3_dot(w->m[h], v3_sub(x[k], w->a[h])) < -tol;
        if (out)
            return 1;
    }
    return 0;
}

/* Does the chord of convex piece p (n vertices, signed distances d from
 * the event plane, snapped to 0 within tol, of both signs) miss wedge w
 * by more than tol?  The chord's ends are the crossings of the edges whose
 * ends lie on opposite sides, and the vertices on the plane. */
int occ_event_misses(const occ_wedge *w, const rad_vec3 *p, const double *d, int n, double tol)
{
    rad_vec3 x[4];
    int nx = 0;
    for (int k = 0; k < n && nx < 4; k++) {
        int k1 = k + 1 < n ? k + 1 : 0;
        if (d[k] == 0)
            x[nx++] = p[k];
        else if ((d[k] > 0 && d[k1] < 0) || (d[k] < 0 && d[k1] > 0))
            x[nx++] = v3_lerp(p[k], p[k1], d[k] / (d[k] - d[k1]));
    }
    if (nx == 0 || nx > 3)
        return 0; /* no chord, or round-off's: cut */
    return chord_misses(w, 0, w->split, x, nx, tol) &&
           (w->split == w->n || chord_misses(w, w->split, w->n, x, nx, tol));
}
