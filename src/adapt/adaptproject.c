/* adaptproject.c -- the converged adaptive solution on every node.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The error of Cohen et al. 1988 (eq. 14) compares the radiosity of each
 * element with the converged solution's on the same element.  With
 * adaptive subdivision the elements after k shots are leaves of the
 * quadtrees (adaptnodes.h) that need not be the converged run's:
 *
 *   - a leaf of step k is most often a union of final leaves (it has not
 *     split yet): its reference is their area mean,
 *         Rbar_j = sum_{c final in j} A_c B_c / sum A_c,
 *     the value a patch-element solution gives the union (its Bbar,
 *     adaptstate.h), and the value whose difference eq. 14 weighs by A_j;
 *   - a leaf of step k may lie inside a final leaf (when the run being
 *     measured has split where the converged one did not, as another
 *     shooting order may): it takes that final leaf's value, constant
 *     over it.
 *
 * So every node gets a value, three passes over the nodes: the final
 * leaves' own; then in node order (a parent before its children, since
 * levels are stored in order) each final or below-final node hands its
 * value to its children; then backwards (children first) each node above
 * the final leaves takes the area mean of its four children.  A node
 * above that has no children left uncovered: the leaves were not a
 * partition of this tree's patches.
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "adapt/adaptproject.h"
#include "util/util.h"

#define NB RAD_BANDS

enum { ABOVE = 0, FINAL, BELOW };

static int has_children(const rad_adapt_nodes *a, int node)
{
    return a->splits[a->mesh.elements[node].surface] && a->level[node] < a->depth;
}

/* The node of the converged run's leaf e, or -1 when there is none. */
static int node_of(const rad_adapt_nodes *a, const rad_mesh *mesh, const int *level, int e)
{
    const rad_element *el = &mesh->elements[e];
    const int s = el->surface, l = level[e];
    if (s < 0 || s >= a->mesh.nsurfaces || l < 0 || l > a->depth || el->gi < 0 || el->gj < 0)
        return -1;
    if (!a->splits[s]) /* a polygon's elements, in the same order */
        return l == 0 && e - mesh->surface_first[s] <
                             a->mesh.surface_first[s + 1] - a->mesh.surface_first[s]
                   ? a->mesh.surface_first[s] + (e - mesh->surface_first[s])
                   : -1;
    if (el->gi >= a->cn[s] << l || el->gj >= a->cm[s] << l)
        return -1;
    const int sh = a->depth - l;
    const int node = radi_adapt_at(a, s, l, el->gi << sh, el->gj << sh);
    return a->level[node] == l && a->mesh.elements[node].surface == s ? node : -1;
}

static void copy_value(double *Rn, size_t nn, int to, const double *from, size_t stride,
                       int at)
{
    for (int b = 0; b < NB; b++)
        Rn[(size_t)to + b * nn] = from[(size_t)at + b * stride];
}

/* Children of nodes at or below a final leaf take its value. */
static void hand_down(const rad_adapt_nodes *a, unsigned char *state, double *Rn)
{
    const size_t nn = (size_t)a->mesh.nelements;
    for (int j = 0; j < a->mesh.nelements; j++) {
        if (state[j] == ABOVE || !has_children(a, j))
            continue;
        for (int k = 0; k < 4; k++) {
            const int c = radi_adapt_child(a, j, k);
            state[c] = BELOW;
            copy_value(Rn, nn, c, Rn, nn, j);
        }
    }
}

/* Nodes above the final leaves: the area mean of their children. */
static int average_up(const rad_adapt_nodes *a, const unsigned char *state, double *Rn)
{
    const size_t nn = (size_t)a->mesh.nelements;
    for (int j = a->mesh.nelements - 1; j >= 0; j--) {
        if (state[j] != ABOVE)
            continue;
        if (!has_children(a, j))
            return -1; /* no final leaf covers it */
        double sum[NB] = {0, 0, 0}, area = 0;
        for (int k = 0; k < 4; k++) {
            const int c = radi_adapt_child(a, j, k);
            const double ac = a->mesh.elements[c].area;
            area += ac;
            for (int b = 0; b < NB; b++)
                sum[b] += ac * Rn[(size_t)c + b * nn];
        }
        for (int b = 0; b < NB; b++)
            Rn[(size_t)j + b * nn] = area > 0 ? sum[b] / area : 0;
    }
    return 0;
}

rad_status radi_adapt_project(const rad_adapt_nodes *a, const rad_mesh *mesh, const double *B,
                             const int *level, double *Rn, rad_error *err)
{
    const size_t nn = (size_t)a->mesh.nelements, ne = (size_t)mesh->nelements;
    unsigned char *state = calloc(nn ? nn : 1, 1);
    if (!state)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the projected solution");
    int bad = 0;
    for (int e = 0; e < mesh->nelements && !bad; e++) {
        const int node = node_of(a, mesh, level, e);
        bad = node < 0 || state[node] != ABOVE;
        if (!bad) {
            state[node] = FINAL;
            copy_value(Rn, nn, node, B, ne, e);
        }
    }
    if (!bad) {
        hand_down(a, state, Rn);
        bad = average_up(a, state, Rn) != 0;
    }
    free(state);
    if (bad)
        return radi_fail(err, RAD_ERR_INVALID, "the converged adaptive solution's elements do "
                        "not tile the starting mesh's %d patches", a->npatches);
    return RAD_OK;
}
