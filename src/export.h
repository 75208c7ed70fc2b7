/* export.h -- writers for the output files of DESIGN.md section 6.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Every writer prints to an open stream (the caller makes it atomic with
 * atomicfile.h) and returns 0, or -1 on a write error.  Numbers that a
 * validator may read back are printed with %.17g (round-trip exact).
 */
#ifndef RAD_EXPORT_H
#define RAD_EXPORT_H

#include <stdio.h>

#include "radiosity.h"

/* Everything the JSON report says about one run. */
typedef struct rad_run_info {
    const char *scene;
    const char *accuracy;
    int quadrature;
    int nelements;
    double memory_bytes;        /* peak estimate of the matrices */
    double memory_available;
    double t_parse, t_mesh, t_formfactor, t_solve, t_smooth, t_output;
    double ff_pairs_per_second;
    const rad_ff_stats *ff;
    const rad_solve_report *solve;
    const char *status;         /* "ok", "singular", "not converged" */
} rad_run_info;

/* Per-element table: element surface gi gj cx cy cz nx ny nz area r g b. */
int rad_export_elements(FILE *out, const rad_mesh *mesh, const double *B);
/* Matrix Market "array real general", column-major, %.17g. */
int rad_export_matrix_market(FILE *out, const double *F, int n, const char *comment);
/* The form-factor table (`radiosity formfactor`): header "i j F error",
 * one line per ordered pair i != j, row by row; F with %.17g, the error
 * estimate E[i + j*n] with %.3g (E may be NULL: "nan").  Both big writers
 * format in parallel (OpenMP) and write the bytes the serial printf loop
 * wrote. */
int rad_export_ff_table(FILE *out, const double *F, const double *E, int n);
/* Solution PLY: vertices with smoothed radiosity (linear doubles and sRGB
 * bytes), faces with element radiosity and surface index; the camera, when
 * the scene has one, in a comment. */
int rad_export_ply(FILE *out, const rad_scene *scene, const rad_mesh *mesh, const double *B,
                   const double *Bv);
/* The JSON report. */
int rad_export_report(FILE *out, const rad_run_info *info);

/* Linear radiosity to an 8-bit sRGB value, after scaling by `exposure`
 * (IEC 61966-2-1 transfer curve; values above 1 clip to 255). */
unsigned char rad_srgb8(double linear, double exposure);

#endif /* RAD_EXPORT_H */
