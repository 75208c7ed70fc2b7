/* test_occleaves.c -- the tree of the adaptive rule's leaves
 * (src/occ/occleaves.c) against a plain scan, the way the rule used it
 * before: the worst leaf is the first of the largest estimate, and the
 * sums are those of all leaves in use.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The leaves' values and estimates are drawn by a fixed linear
 * congruential generator; ties are made on purpose (estimates from a
 * set of eight values), since the tie rule decides the rule's steps.
 * The sums are compared within 1e-13 relative: the tree adds pairwise,
 * the scan in order, and n <= 5000 terms of one sign (estimates) differ
 * by at most about n ulps of the sum, 1e-12 in the worst case and far
 * less in practice.
 */
#include <config.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "occ/occspace.h"
#include "../tap.h"

static uint64_t state = 12345;

static double draw(void) /* in [0, 1) (Knuth's MMIX constants) */
{
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(state >> 11) / 9007199254740992.0;
}

static void fill(tri_node *t)
{
    t->err = floor(draw() * 8) / 8; /* ties */
    t->qc[0] = draw();
    t->qc[1] = draw() * 1e-3;
    t->qc[2] = t->qc[3] = 0;
}

/* The scan that the tree replaces. */
static void scan(const tri_node *node, int n, int *worst, double *err, double *val)
{
    *worst = n > 0 ? 0 : -1;
    *err = *val = 0;
    for (int k = 0; k < n; k++) {
        if (node[k].err > node[*worst].err)
            *worst = k;
        *err += node[k].err;
        *val += node[k].qc[0] + node[k].qc[1] + node[k].qc[2] + node[k].qc[3];
    }
}

static int agree(const occ_leaves *lt, const tri_node *node, int n)
{
    int worst;
    double err, val;
    scan(node, n, &worst, &err, &val);
    return lt->best[1] == worst && fabs(lt->err[1] - err) <= 1e-13 * err &&
           fabs(lt->val[1] - val) <= 1e-13 * val;
}

int main(void)
{
    enum { MAX = 5000 };
    tri_node *node = calloc(MAX, sizeof *node);
    occ_leaves lt = {0};
    if (!node)
        return 1;

    tap_ok(occ_leaves_build(&lt, node, 0) == 0 && lt.best[1] == -1 && lt.err[1] == 0,
           "no leaves: no worst, sums 0");

    int n = 5;
    for (int k = 0; k < n; k++)
        fill(&node[k]);
    tap_ok(occ_leaves_build(&lt, node, n) == 0 && agree(&lt, node, n),
           "5 leaves built: the scan's worst and sums");

    /* the rule's two steps, at random: raise (the worst changes) or split
     * (the worst changes and three leaves are appended); the tree grows
     * past its first capacities on the way */
    int bad = 0, steps = 0;
    while (n + 3 <= MAX) {
        const int w = lt.best[1];
        fill(&node[w]);
        if (draw() < 0.5) {
            if (occ_leaves_set(&lt, node, w, n))
                return 1;
        } else {
            for (int k = n; k < n + 3; k++)
                fill(&node[k]);
            n += 3;
            for (int k = n - 3; k < n; k++)
                if (occ_leaves_set(&lt, node, k, n))
                    return 1;
            if (occ_leaves_set(&lt, node, w, n))
                return 1;
        }
        bad += !agree(&lt, node, n);
        steps++;
    }
    tap_ok(bad == 0, "%d steps to %d leaves: worst and sums as the scan's at each (%d differ)",
           steps, n, bad);
    tap_ok(lt.cap >= n && (lt.cap & (lt.cap - 1)) == 0, "capacity %d: a power of 2, >= %d",
           lt.cap, n);

    /* a leaf changed that is not the worst */
    node[7].err = 100;
    tap_ok(occ_leaves_set(&lt, node, 7, n) == 0 && lt.best[1] == 7 && agree(&lt, node, n),
           "leaf 7 raised above all: it is the worst");

    /* rebuilding a smaller set in the same tree (the next pair) */
    const int grown = lt.alloc;
    tap_ok(occ_leaves_build(&lt, node, 3) == 0 && agree(&lt, node, 3),
           "3 leaves again in the grown tree: the scan's worst and sums");
    tap_ok(lt.cap == 16 && lt.alloc == grown,
           "the next pair's tree is 16 leaves (%d), its arrays kept (%d of %d)", lt.cap,
           lt.alloc, grown);

    occ_leaves_free(&lt);
    free(node);
    return tap_done();
}
