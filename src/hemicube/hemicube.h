/* hemicube.h -- form factors by the hemicube (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen & Greenberg, "The Hemi-Cube: A Radiosity Solution for Complex
 * Environments", SIGGRAPH 1985; Cohen, Chen, Wallace & Greenberg 1988,
 * section 3.1.  A half cube of side 2 stands on element i's centre, its
 * top face one unit up the normal, its four side faces half above the
 * element's plane.  Every receiving element is projected onto the five
 * faces through the centre and drawn into an item buffer (the renderer's
 * z-buffer, render.h: the id of the nearest element per pixel); each pixel
 * carries the delta form factor of its small square seen from the centre,
 * and F_ij is the sum of the deltas of the pixels that show j.  Visibility
 * comes with the z-buffer.
 *
 * What it computes is row i of F from the single point at i's centre:
 * the form factor of a differential area there, not the area average of
 * the contour integral.  Reciprocity A_i F_ij = A_j F_ji then holds only
 * as far as both approximations are good; progressive refinement uses the
 * row as the 1988 paper does, F_ji = F_ij A_i / A_j.  Two errors remain
 * as the resolution grows: the centre for the whole element (it falls as
 * the mesh is refined) and the pixels themselves (aliasing, it falls as
 * 1/R: hemicube.c).
 */
#ifndef RAD_HEMICUBE_H
#define RAD_HEMICUBE_H

#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"

/* The delta form factors of one resolution R (even).  Pixel (x, y) of the
 * top face (x, y = 0..R-1) has its centre at (u, v, 1) with u = -1 +
 * (2x+1)/R, v = -1 + (2y+1)/R; pixel (x, y) of a side face (y = 0..R/2-1,
 * counted down from the top edge, as the renderer counts image rows) at
 * (u, 1, w) with w = 1 - (2y+1)/R above the element's plane. */
typedef struct rad_hc_table {
    int res;                    /* R */
    double *top;                /* R x R, top[y*R + x] */
    double *side;               /* R/2 x R, side[y*R + x] (the four alike) */
    long double raw_sum;        /* the sum of the deltas before normalising */
} rad_hc_table;

/* Cohen & Greenberg 1985's deltas, divided by their sum (so that they sum
 * to 1 to round-off; hcdelta.c says why that is honest).  RAD_ERR_INVALID
 * for an odd R or one outside 2..RAD_HEMICUBE_MAX. */
rad_status radi_hc_table_make(rad_hc_table *t, int res, rad_error *err);
void radi_hc_table_free(rad_hc_table *t);
/* The raw delta of one pixel centre (u, v) of the top face, and of
 * (u, w) of a side face; dA = (2/R)^2 the pixel's area. */
double radi_hc_delta_top(double u, double v, double dA);
double radi_hc_delta_side(double u, double w, double dA);

/* The item buffers of one mesh (normalized: radi_mesh_normalized) at one
 * resolution: read-only once made, shared by any number of threads. */
typedef struct rad_hemicube rad_hemicube;

rad_status radi_hemicube_create(rad_hemicube **hc, const rad_mesh *unit, int res,
                               rad_error *err);
void radi_hemicube_free(rad_hemicube *hc);
/* row[j] = F_ij for every element j of the mesh (row[i] = 0): the deltas
 * of the pixels that show j from i's centre. */
rad_status radi_hemicube_row(const rad_hemicube *hc, int i, double *row, rad_error *err);
int radi_hemicube_elements(const rad_hemicube *hc);
/* The same row, and what each pixel shows (items, 3 R^2 ints, or NULL):
 * the element seen (-1: nothing, or the back of a blocker), the top face
 * first (R x R, row y at y R, counted as rad_hc_table counts), then the
 * four sides (R/2 x R each) in the order of the side directions t1, -t1,
 * n x t1, -(n x t1), t1 the element's first edge's direction and n its
 * normal, each with the normal up. */
rad_status radi_hemicube_row_items(const rad_hemicube *hc, int i, double *row, int *items,
                                   rad_error *err);
/* The bytes one radi_hemicube_row call holds at its peak: one picture of
 * R x R pixels (render.h, about 37 bytes each, counted as
 * RAD_HEMICUBE_PIXEL_BYTES) and the row's buffers. */
#define RAD_HEMICUBE_PIXEL_BYTES 40.0
double radi_hemicube_row_bytes(const rad_hemicube *hc);

/* The dense matrix by hemicubes: F[i + j*n] = F_ij, row i from i's
 * centre, rows shared among opt->threads; stats as rad_ff_matrix fills
 * them, with no error estimates (NaN) and no promise (hcmatrix.c). */
rad_status radi_hemicube_matrix(const rad_mesh *m, const rad_ff_options *opt, double *F,
                               double *errest, rad_ff_stats *stats, rad_error *err);

#endif /* RAD_HEMICUBE_H */
