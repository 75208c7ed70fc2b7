/* occleaves.c -- the leaves of the adaptive rule (occhidden.c) in a
 * tournament tree: the leaf with the largest estimate, and the sums of
 * the leaves' values and estimates, kept up to date in O(log n) per
 * changed leaf.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The adaptive rule raises or splits its worst leaf until the sum of the
 * estimates is small enough; with n leaves a scan for the worst and two
 * sums cost O(n) per step, O(n^2) for the pair.  Pairs of many blockers
 * in reference mode use thousands of leaves (a box and two panels
 * between two plates, 4,000 to 13,000 pieces), and there the
 * scans took a seventh of the time.  The tree (a binary heap layout:
 * node 1 the root, node i's children 2i and 2i + 1, the leaves from
 * `cap` on) keeps in every node the index of its subtree's worst leaf
 * and its subtree's two sums.  Ties go to the lower index, as the scan
 * they replace did, so the order of the steps is the scan's; the sums
 * are added pairwise, so they differ from the running sums of a scan in
 * the last bits only.
 */
#include <config.h>

#include <stdlib.h>

#include "occ/occspace.h"

static double leaf_value(const tri_node *t)
{
    return t->qc[0] + t->qc[1] + t->qc[2] + t->qc[3];
}

/* Node i from its children. */
static void pull(occ_leaves *lt, const tri_node *node, int i)
{
    const int l = lt->best[2 * i], r = lt->best[2 * i + 1];
    lt->best[i] = r >= 0 && (l < 0 || node[r].err > node[l].err) ? r : l;
    lt->err[i] = lt->err[2 * i] + lt->err[2 * i + 1];
    lt->val[i] = lt->val[2 * i] + lt->val[2 * i + 1];
}

/* Leaf k of the tree from node[k] (k < n, the leaves in use) or empty. */
static void put(occ_leaves *lt, const tri_node *node, int k, int n)
{
    const int i = lt->cap + k;
    lt->best[i] = k < n ? k : -1;
    lt->err[i] = k < n ? node[k].err : 0;
    lt->val[i] = k < n ? leaf_value(&node[k]) : 0;
}

int occ_leaves_build(occ_leaves *lt, const tri_node *node, int n)
{
    /* the smallest tree that holds n: a pair of few leaves after one of
     * thousands pays for its own size only */
    int cap = 16;
    while (cap < n)
        cap *= 2;
    if (cap > lt->alloc) {
        int *b = realloc(lt->best, sizeof *b * 2 * (size_t)cap);
        if (!b)
            return -1;
        lt->best = b;
        double *e = realloc(lt->err, sizeof *e * 2 * (size_t)cap);
        if (!e)
            return -1;
        lt->err = e;
        double *v = realloc(lt->val, sizeof *v * 2 * (size_t)cap);
        if (!v)
            return -1;
        lt->val = v;
        lt->alloc = cap;
    }
    lt->cap = cap;
    for (int k = 0; k < cap; k++)
        put(lt, node, k, n);
    for (int i = cap - 1; i >= 1; i--)
        pull(lt, node, i);
    return 0;
}

int occ_leaves_set(occ_leaves *lt, const tri_node *node, int k, int n)
{
    if (n > lt->cap)
        return occ_leaves_build(lt, node, n);
    put(lt, node, k, n);
    for (int i = (lt->cap + k) / 2; i >= 1; i /= 2)
        pull(lt, node, i);
    return 0;
}

void occ_leaves_free(occ_leaves *lt)
{
    free(lt->best);
    free(lt->err);
    free(lt->val);
    lt->best = NULL;
    lt->err = lt->val = NULL;
    lt->alloc = lt->cap = 0;
}
