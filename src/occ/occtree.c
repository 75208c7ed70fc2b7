/* occtree.c -- a bounding-volume hierarchy of the surfaces' boxes, and
 * the surfaces a shaft may meet, found by walking it.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The candidate listing (occshaft.c) asks, for every pair of surfaces,
 * which other surfaces may meet the pair's shaft H (the convex hull of
 * the two, each clipped to the front of the other).  A box of the tree
 * that lies beyond one of H's face planes, or misses H's bounding box,
 * holds no surface that can meet H, and the walk skips it whole (Haines &
 * Wallace 1991 cull by the same planes, one surface at a time).  Only the
 * surfaces of the boxes left are tested one by one (occshaft.c,
 * clear_of_shaft).  The tree is built once, by splitting the surfaces at
 * the median of their boxes' centres along the longest side of the
 * node's box (Kay & Kajiya 1986 bound, Goldsmith & Salmon 1987 build),
 * down to OCC_TREE_LEAF surfaces a leaf.
 *
 * The tests are conservative: a box is skipped only when the corner of it
 * nearest to H is more than the pair's tolerance beyond a face plane, and
 * every surface of such a box has all its vertices beyond that plane
 * too, which clear_of_shaft would clear.  So the walk lists every surface
 * that the one-by-one test keeps.
 */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "occ/occlusion.h"
#include "occ/occspace.h"
#include "util/util.h"
#include "radiosity/base.h"

#define OCC_TREE_LEAF 4

typedef struct occ_tree_node {
    rad_vec3 lo, hi;
    int left, right;            /* children, or -1 in a leaf */
    int first, count;           /* a leaf's surfaces: idx[first .. first+count) */
} occ_tree_node;

struct occ_tree {
    occ_tree_node *node;
    int nnode;
    int *idx;
};

static double centre(const rad_occ *o, int s, int axis)
{
    const rad_vec3 c = v3_scale(v3_add(o->slo[s], o->shi[s]), 0.5);
    return axis == 0 ? c.x : axis == 1 ? c.y : c.z;
}

typedef struct tree_key {
    double c;
    int s;
} tree_key;

static int key_cmp(const void *pa, const void *pb)
{
    const tree_key *a = pa, *b = pb;
    if (a->c != b->c)
        return a->c < b->c ? -1 : 1;
    return (a->s > b->s) - (a->s < b->s);
}

/* Node for idx[first .. first+count); returns its index, -1. */
static int build(occ_tree *t, const rad_occ *o, int first, int count, tree_key *key)
{
    const int me = t->nnode++;
    occ_tree_node *n = t->node + me;
    n->lo = o->slo[t->idx[first]];
    n->hi = o->shi[t->idx[first]];
    for (int k = 1; k < count; k++) {
        const int s = t->idx[first + k];
        n->lo = v3(fmin(n->lo.x, o->slo[s].x), fmin(n->lo.y, o->slo[s].y), fmin(n->lo.z, o->slo[s].z));
        n->hi = v3(fmax(n->hi.x, o->shi[s].x), fmax(n->hi.y, o->shi[s].y), fmax(n->hi.z, o->shi[s].z));
    }
    n->first = first;
    n->count = count;
    n->left = n->right = -1;
    if (count <= OCC_TREE_LEAF)
        return me;
    const rad_vec3 d = v3_sub(n->hi, n->lo);
    const int axis = d.x >= d.y && d.x >= d.z ? 0 : d.y >= d.z ? 1 : 2;
    for (int k = 0; k < count; k++) {
        key[k].s = t->idx[first + k];
        key[k].c = centre(o, key[k].s, axis);
    }
    qsort(key, (size_t)count, sizeof *key, key_cmp);
    for (int k = 0; k < count; k++)
        t->idx[first + k] = key[k].s;
    const int half = count / 2;
    const int l = build(t, o, first, half, key);
    const int r = build(t, o, first + half, count - half, key);
    t->node[me].left = l; /* t->node did not move: allocated whole */
    t->node[me].right = r;
    return me;
}

occ_tree *occ_tree_create(const rad_occ *o)
{
    occ_tree *t = calloc(1, sizeof *t);
    const int ns = o->nsurf;
    tree_key *key = malloc(sizeof *key * (size_t)(ns > 0 ? ns : 1));
    if (t) {
        t->idx = malloc(sizeof *t->idx * (size_t)(ns > 0 ? ns : 1));
        t->node = malloc(sizeof *t->node * (size_t)(2 * ns + 1));
    }
    if (!t || !key || !t->idx || !t->node) {
        free(key);
        occ_tree_free(t);
        return NULL;
    }
    int n = 0;
    for (int s = 0; s < ns; s++)
        if (o->sfirst[s + 1] - o->sfirst[s] >= 3)
            t->idx[n++] = s;
    if (n > 0)
        build(t, o, 0, n, key);
    free(key);
    return t;
}

void occ_tree_free(occ_tree *t)
{
    if (!t)
        return;
    free(t->node);
    free(t->idx);
    free(t);
}

/* Is box [lo, hi] more than tol beyond the plane (outward normal n
 * through a)?  Its corner nearest the inside decides. */
static int box_beyond(rad_vec3 lo, rad_vec3 hi, rad_vec3 n, rad_vec3 a, double tol)
{
    const rad_vec3 c = v3(n.x > 0 ? lo.x : hi.x, n.y > 0 ? lo.y : hi.y, n.z > 0 ? lo.z : hi.z);
    return v3_dot(n, v3_sub(c, a)) > tol;
}

static int boxes_miss(rad_vec3 alo, rad_vec3 ahi, rad_vec3 blo, rad_vec3 bhi)
{
    return alo.x > bhi.x || blo.x > ahi.x || alo.y > bhi.y || blo.y > ahi.y || alo.z > bhi.z ||
           blo.z > ahi.z;
}

int occ_tree_shaft(const occ_tree *t, rad_vec3 lo, rad_vec3 hi, const rad_vec3 *hn,
                   const rad_vec3 *ha, int nh, double tol, int *out)
{
    if (t->nnode == 0)
        return 0;
    int stack[128], top = 0, n = 0;
    stack[top++] = 0;
    while (top > 0) {
        const occ_tree_node *v = t->node + stack[--top];
        if (boxes_miss(v->lo, v->hi, lo, hi))
            continue;
        int beyond = 0;
        for (int h = 0; h < nh && !beyond; h++)
            beyond = box_beyond(v->lo, v->hi, hn[h], ha[h], tol);
        if (beyond)
            continue;
        if (v->left < 0) {
            memcpy(out + n, t->idx + v->first, sizeof *out * (size_t)v->count);
            n += v->count;
        } else {
            stack[top++] = v->left;
            stack[top++] = v->right;
        }
    }
    return n;
}
