/* test_occcell.c -- the blockers a cell of the outer element keeps
 * (src/occ/occdomain.c, occ_cell_blockers): leaving the others out must
 * not change hidden(x) at any point of the cell.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * A unit square (the inner element) at z = 0 faces down to a square of
 * side 4 at z = -3 (the outer element); between them stand 12 small
 * triangles at random heights and places, tilted at random, half of
 * them facing up and half down; four (two each way) may be left out by
 * points behind them (the exit rule of a closed mesh's faces, sp->bx).
 * For 200 random cells (triangles about random points of the outer
 * square, of side 0.05 to 2, some reaching past it)
 * the cell's list is taken, and each of its four midpoint children's
 * from it, as node_split does; at random points of the cell and of each
 * child hidden(x) is computed twice by occunion.c: with every blocker,
 * and with the cell's or the child's list alone.  The union of the
 * shadows with or without a shadow that misses the inner element has the
 * same boundary inside it, so the two
 * must agree to round-off (3e-15 of F(x -> inner element), a few ulps of
 * each term of the contour sum).  The check could fail: a list that left
 * out a blocker whose shadow reaches the inner element from some point of
 * the cell changes hidden(x) there by that shadow's share.  And it is not
 * empty: the lists must leave out blockers (most cells lie outside most
 * penumbras here), and must keep some that hide something.
 */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "occ/occspace.h"
#include "util/util.h"
#include "../tap.h"

enum { NB = 12, CELLS = 200, POINTS = 6 };

static double uniform(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffffff) / (double)0x1000000;
}

/* The blockers into sp (blkc, bn, bc, br, bx), as clip_blockers fills
 * them (occhidden.c). */
static int blockers(occ_space *sp, unsigned *seed)
{
    occ_ps_clear(&sp->blkc);
    if (occ_grow_v3(&sp->bn, &sp->capbn, NB) || occ_grow_v3(&sp->bc, &sp->capbc, NB) ||
        occ_grow_d(&sp->br, &sp->capbr, NB) || occ_grow_i(&sp->bx, &sp->capbx, NB))
        return -1;
    for (int b = 0; b < NB; b++) {
        const rad_vec3 o = {-1.5 + 3 * uniform(seed), -1.5 + 3 * uniform(seed),
                            -2.5 + 2 * uniform(seed)};
        rad_vec3 t[3];
        for (int k = 0; k < 3; k++)
            t[k] = v3_add(o, v3(0.3 * cos(2.1 * k + uniform(seed)),
                                0.3 * sin(2.1 * k + uniform(seed)), 0.2 * (uniform(seed) - 0.5)));
        if (b % 2) { /* every other one turned to face the outer element */
            const rad_vec3 w = t[1];
            t[1] = t[2];
            t[2] = w;
        }
        if (occ_ps_push(&sp->blkc, t, 3))
            return -1;
        const rad_vec3 n = v3_newell(t, 3);
        sp->bn[b] = v3_scale(n, 1 / v3_norm(n));
        sp->bc[b] = poly_mean(t, 3);
        double r = 0;
        for (int k = 0; k < 3; k++)
            r = fmax(r, v3_norm(v3_sub(t[k], sp->bc[b])));
        sp->br[b] = r;
        sp->bx[b] = b % 3 == 0; /* 0, 3, 6, 9: the exit rule applies */
    }
    return 0;
}

/* F(x -> q), the point-to-polygon factor (Lambert 1760; Baum, Rushmeier
 * & Winget 1989, eq. 6), up to its sign. */
static double point_polygon(rad_vec3 x, rad_vec3 nrm, const rad_vec3 *q, int m)
{
    double sum = 0;
    for (int k = 0; k < m; k++) {
        const rad_vec3 r0 = v3_sub(q[k], x), r1 = v3_sub(q[(k + 1) % m], x);
        const rad_vec3 c = v3_cross(r0, r1);
        sum += atan2(v3_norm(c), v3_dot(r0, r1)) * v3_dot(nrm, c) / v3_norm(c);
    }
    return fabs(sum) / (2 * RAD_PI);
}

/* A random point of triangle p. */
static rad_vec3 inside(const rad_vec3 *p, unsigned *seed)
{
    double u = uniform(seed), v = uniform(seed);
    if (u + v > 1) {
        u = 1 - u;
        v = 1 - v;
    }
    return v3_add(p[0], v3_add(v3_scale(v3_sub(p[1], p[0]), u), v3_scale(v3_sub(p[2], p[0]), v)));
}

int main(void)
{
    const rad_vec3 inner[4] = {{-0.5, -0.5, 0}, {-0.5, 0.5, 0}, {0.5, 0.5, 0}, {0.5, -0.5, 0}};
    const rad_vec3 outer[4] = {{-2, -2, -3}, {2, -2, -3}, {2, 2, -3}, {-2, 2, -3}};
    occ_space sp;
    memset(&sp, 0, sizeof sp);
    unsigned seed = 2026;
    if (blockers(&sp, &seed))
        return 1;
    pair_ctx c;
    memset(&c, 0, sizeof c);
    c.nx = v3(0, 0, 1);
    c.tn = v3(0, 0, -1);
    c.t = inner;
    c.nt = 4;
    c.flat = 1;
    c.nb = NB;
    c.snap = 1e-12;
    c.sliver = OCC_SLIVER;
    c.outer_area = 16;
    sp.noise_tol = 1e-300; /* every sum in long double where it could matter */
    if (occ_union_frame(&sp, &c) || occ_support_domain(&sp, &c, outer, 4))
        return 1;

    int kept = 0, left = 0, points = 0, hiding = 0, narrower = 0;
    double worst = 0;
    for (int cell = 0; cell < CELLS; cell++) {
        /* a cell about a random point, of side 0.05 to 2 */
        const rad_vec3 m = inside((const rad_vec3[]){outer[0], outer[1], outer[2]}, &seed);
        const double side = 0.05 + 1.95 * uniform(&seed) * uniform(&seed);
        rad_vec3 p[3];
        for (int k = 0; k < 3; k++)
            p[k] = v3_add(m, v3(side * cos(2.1 * k), side * sin(2.1 * k), 0));
        sp.nclist = 0;
        const int n = occ_cell_blockers(&sp, &c, p, 3, -1, 0);
        if (n < 0)
            return 1;
        kept += n;
        left += NB - n;
        rad_vec3 ch[4][4];
        occ_cell_children(p, 3, ch);
        for (int part = -1; part < 4; part++) {
            const rad_vec3 *q = part < 0 ? p : ch[part];
            int first = 0, count = n;
            if (part >= 0) { /* the child's list, from the cell's */
                count = occ_cell_blockers(&sp, &c, q, 3, 0, n);
                if (count < 0)
                    return 1;
                first = sp.nclist - count;
                narrower += count < n;
            }
            for (int l = 0; l < POINTS; l++) {
                const rad_vec3 x = inside(q, &seed);
                double all, listed;
                sp.cell_on = 0;
                if (occ_hidden_union(&sp, &c, x, &all) != 1)
                    return 1;
                sp.cell_on = 1;
                sp.cell_first = first;
                sp.cell_n = count;
                if (occ_hidden_union(&sp, &c, x, &listed) != 1)
                    return 1;
                sp.cell_on = 0;
                const double whole = point_polygon(x, c.nx, inner, 4);
                worst = fmax(worst, fabs(listed - all) / whole);
                hiding += all > 1e-6 * whole;
                points++;
            }
        }
    }
    tap_ok(worst <= 3e-15,
           "%d points of %d cells and their children: hidden(x) with the cell's blockers "
           "within %.1e of F(x -> inner) of hidden(x) with all (tol 3e-15)",
           points, CELLS, worst);
    tap_ok(left > kept && kept > 0,
           "the cells' lists leave blockers out (%d) and keep some (%d)", left, kept);
    tap_ok(narrower > 0, "children's lists narrower than their cell's: %d of %d", narrower,
           4 * CELLS);
    tap_ok(hiding > points / 10, "something is hidden at %d of the %d points", hiding, points);
    occ_space_free(&sp);
    return tap_done();
}
