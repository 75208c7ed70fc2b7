/* adaptnodes.h -- the quadtree of every element adaptive subdivision may make.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Adaptive subdivision (Cohen, Chen, Wallace & Greenberg 1988, section 4)
 * splits an element into four, down to D levels.  Every element it could
 * ever make is known in advance: the nodes of a complete quadtree of depth
 * D over each element of the starting mesh (of a quad surface; a polygon
 * surface is one element and is never split).  rad_adapt_nodes holds them
 * all as the elements of one rad_mesh, so that the form-factor rows
 * (ffrow.h) and the visibility structure are built once, and a split only
 * switches which nodes are leaves.
 *
 * Layout.  A quad surface s meshed N x M is, at level l, a grid of
 * (N 2^l) x (M 2^l) nodes; node (l, i, j) is
 *     mesh.elements[surface_first[s] + N M (4^l - 1) / 3 + j (N 2^l) + i],
 * its gi, gj are i, j, and its children are (l + 1, 2i + a, 2j + b),
 * a, b in {0, 1}.  The vertices of surface s are the finest lattice,
 * (N 2^D + 1) x (M 2^D + 1) points row-major, made by radi_mesh_bilinear as
 * rad_mesh_build would make them for a mesh of N 2^D x M 2^D: the starting
 * mesh's vertices are among them bit for bit, and mesh.surface_n, surface_m
 * give the lattice's size (the surface outline the visibility code reads).
 * A node's polygon is its four lattice corners, counter-clockwise as the
 * starting element's.  Level 0 of a surface is the starting mesh in its
 * order: patch p (the starting element p) is node root[p].
 */
#ifndef RAD_ADAPTNODES_H
#define RAD_ADAPTNODES_H

#include "radiosity/base.h"
#include "radiosity/mesh.h"

/* The most nodes a run may hold (about 0.5 kB each with the form-factor
 * rows' polygons): a larger request is refused as too big. */
#define RAD_ADAPT_MAX_NODES 4000000

typedef struct rad_adapt_nodes {
    rad_mesh mesh;              /* every node as an element (see above) */
    int depth;                  /* D */
    int npatches;               /* elements of the starting mesh */
    int *root;                  /* node of starting element p, level 0 */
    int *patch;                 /* starting element of each node */
    unsigned char *level;       /* level of each node */
    int *cn, *cm;               /* starting grid of each surface */
    unsigned char *splits;      /* 1: surface s is a quad (its nodes split) */
} rad_adapt_nodes;

/* All nodes over the starting mesh m, depth D >= 0.  RAD_ERR_TOOBIG past
 * RAD_ADAPT_MAX_NODES. */
rad_status radi_adapt_nodes_build(rad_adapt_nodes *a, const rad_mesh *m, int depth,
                                 rad_error *err);
void radi_adapt_nodes_free(rad_adapt_nodes *a);

/* Child k (0..3: a = k & 1 along v1->v2, b = k >> 1 along v2->v3) of a
 * node of level < D on a quad surface. */
int radi_adapt_child(const rad_adapt_nodes *a, int node, int k);

/* The node's square in lattice units: x0 <= x < x0 + w, y0 <= y < y0 + w. */
void radi_adapt_box(const rad_adapt_nodes *a, int node, int *x0, int *y0, int *w);

/* The node covering lattice cell (x, y) of surface s at level l. */
int radi_adapt_at(const rad_adapt_nodes *a, int s, int l, int x, int y);

#endif /* RAD_ADAPTNODES_H */
