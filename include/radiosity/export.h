/* export.h -- writers for the output files of radiosity-files(5).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Every writer prints to an open stream (the caller makes the file whole
 * or absent, by writing a temporary file and renaming it) and returns
 * RAD_OK, RAD_ERR_IO on a write error (errno says which) or RAD_ERR_NOMEM.
 * Numbers that a validator may read back are printed with %.17g
 * (round-trip exact).
 */
#ifndef RAD_EXPORT_H
#define RAD_EXPORT_H

#include <stdio.h>

#include "radiosity/solve.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Everything the JSON report says about one run. */
typedef struct rad_run_info {
    const char *scene;
    const char *accuracy;       /* the contour's mode, or NULL (null: the
                                   hemicube has none) */
    int quadrature;             /* Gauss points per edge, or 0 (null) */
    int nelements;
    double memory_bytes;        /* peak estimate of the matrices */
    double memory_available;
    double t_parse, t_mesh, t_formfactor, t_solve, t_smooth, t_output;
    double ff_pairs_per_second;
    const rad_ff_stats *ff;
    const rad_solve_report *solve;
    const char *status;         /* "ok", "singular", "not converged",
                                   "promise unmet" (--strict), "error" */
    long b_negative;            /* element-band values of B below 0: impossible
                                   (classic mode's nonsense), -1 unknown */
    const char *matrix;         /* "dense", "none" (form factors per shot), or NULL */
    const char *method;         /* "contour", "hemicube", or NULL (not said) */
    int resolution;             /* the hemicube's R (method "hemicube") */
    const rad_scene *repaired;  /* the scene read: what an OBJ reader
                                   repaired (key "repairs"), or NULL */
} rad_run_info;

/* Per-element table: element surface gi gj cx cy cz nx ny nz area r g b. */
RAD_API rad_status rad_export_elements(FILE *out, const rad_mesh *mesh, const double *B);
/* The same with a last column `level' (the element's level of adaptive
 * subdivision, 0 for a starting element) when level is not NULL. */
RAD_API rad_status rad_export_elements_level(FILE *out, const rad_mesh *mesh, const double *B,
                                             const int *level);
/* Matrix Market "array real general", column-major, %.17g. */
RAD_API rad_status rad_export_matrix_market(FILE *out, const double *F, int n, const char *comment);
/* The form-factor table (`radiosity formfactor`): header "i j F error",
 * one line per ordered pair i != j, row by row; F with %.17g, the error
 * estimate E[i + j*n] with %.3g (E may be NULL: "nan").  Both big writers
 * format in parallel (OpenMP) and write the bytes the serial printf loop
 * wrote. */
RAD_API rad_status rad_export_ff_table(FILE *out, const double *F, const double *E, int n);
/* The same table with the pairs i = i as well, n^2 lines: for factors
 * whose rows may see themselves (a union of surfaces, rad_mesh_reduce). */
RAD_API rad_status rad_export_ff_table_diagonal(FILE *out, const double *F, const double *E,
                                                int n);
/* Surface-to-surface form factors, every ordered pair S, K
 * including S = K: header "S K F error S_line K_line S_area"; S and K are
 * 0-based surface indices in file order, S_line and K_line the scene-file
 * lines that define them, error the area-weighted sum of the elements'
 * error estimates (ES may be NULL: "nan"), S_area = A_S. */
RAD_API rad_status rad_export_surface_table(FILE *out, const rad_scene *scene, const rad_mesh *mesh,
                                            const double *FS, const double *ES, const double *AS);
/* NumPy .npy, version 1.0: a rows x cols column-major matrix as
 * float64 '<f8' with 'fortran_order': True and the shape in the header,
 * the data 64-byte aligned; numpy.load(path)[i, j] = A[i + j*rows]. */
RAD_API rad_status rad_export_npy(FILE *out, const double *A, size_t rows, size_t cols);
/* The n x n form-factor matrix: shape (n, n), [i, j] = F_ij (row i = from
 * element i, zero diagonal). */
RAD_API rad_status rad_export_matrix_npy(FILE *out, const double *F, int n);
/* The radiosity table B (nelements x RAD_BANDS, column-major): shape
 * (n, 3), [e, b] = B of element e in band b (r, g, b); the geometry columns
 * of the text table are not in it (element e is row e of that table). */
RAD_API rad_status rad_export_elements_npy(FILE *out, const rad_mesh *mesh, const double *B);
/* Whether an output path asks for .npy (its name ends in ".npy"). */
RAD_API int rad_export_is_npy(const char *path);
/* Solution PLY: vertices with smoothed radiosity (linear doubles and sRGB
 * bytes), faces with element radiosity and surface index; the camera, when
 * the scene has one, in a comment. */
RAD_API rad_status rad_export_ply(FILE *out, const rad_scene *scene, const rad_mesh *mesh,
                                  const double *B, const double *Bv);
/* The JSON report. */
RAD_API rad_status rad_export_report(FILE *out, const rad_run_info *info);

#ifdef __cplusplus
}
#endif

#endif /* RAD_EXPORT_H */
