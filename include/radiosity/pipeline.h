/* pipeline.h -- the whole run, scene to smoothed radiosity, as one call.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * scene -> mesh -> form factors -> solve per band -> smooth (radiosity(3),
 * DESCRIPTION).  Every command that solves a scene goes through
 * rad_pipeline_run; it prints nothing and opens no file: progress and
 * cancellation go through the callback in the options, and the result
 * record carries what the summary and the JSON report say.
 */
#ifndef RAD_PIPELINE_H
#define RAD_PIPELINE_H

#include "radiosity/solve.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Whether the form factors are stored (progressive refinement only can do
 * without: Cohen et al. 1988 compute each shooter's on the fly). */
typedef enum rad_matrix_mode {
    RAD_MATRIX_AUTO = 0,        /* progressive: dense when 8 n^2 bytes (the
                                   dense path's peak, rad_solve_bytes) fit in
                                   half the memory allowed, else none; the
                                   other solvers: dense */
    RAD_MATRIX_DENSE,           /* fill F (n x n) first, then solve */
    RAD_MATRIX_NONE             /* progressive: each shot computes its column */
} rad_matrix_mode;

/* "auto", "dense", "none", or NULL for a value out of range. */
RAD_API const char *rad_matrix_name(int mode);

typedef struct rad_pipeline_options {
    rad_ff_options ff;          /* accuracy, quadrature, threads, progress */
    rad_solve_options solve;    /* solver and its options (progress is
                                   taken from ff when not set) */
    int keep_form_factors;      /* 1: leave F in the result (--form-factors;
                                   needs the dense matrix) */
    rad_matrix_mode matrix;     /* stored F or not (default auto) */
    rad_vertex_rule vertex_rule;  /* how boundary vertices are smoothed
                                     (default: extrapolate) */
    double crease;              /* degrees: smooth vertex radiosity across
                                   surfaces of one object and material
                                   meeting at less (rad_smooth_across); 0:
                                   never; RAD_CREASE_AUTO (the default):
                                   the scene's rad_crease_default.  Not
                                   with adaptive subdivision, whose hanging
                                   vertices follow their edges (AUTO is 0
                                   there) */
} rad_pipeline_options;

RAD_API void rad_pipeline_options_init(rad_pipeline_options *opt);

/* What one run produced.  Filled as far as the run got: after a failed
 * solve the statistics are there for the report, B is not. */
typedef struct rad_result {
    rad_mesh mesh;
    double *F;                  /* n x n when keep_form_factors, else NULL */
    double *B;                  /* nelements x RAD_BANDS, column-major */
    double *Bv;                 /* nvertices x RAD_BANDS, column-major */
    rad_ff_stats ff;
    rad_solve_report solve;
    int ff_done, solve_done;    /* which of ff, solve hold figures */
    long b_negative;            /* element-band values of B below 0 (solved) */
    double memory_bytes;        /* the estimate checked before allocating */
    double memory_available;    /* what the machine allowed (rad_memory_limit) */
    double t_mesh, t_formfactor, t_solve, t_smooth;  /* seconds */
    rad_matrix_mode matrix;     /* what the run used: DENSE or NONE (with
                                   NONE the form factors are computed inside
                                   the solve: t_formfactor is 0, ff counts
                                   the pairs integrated over all shots) */
    int *level;                 /* --adaptive: each element's level of
                                   subdivision (0: a starting element), else
                                   NULL; the mesh is then the conforming mesh
                                   of the leaves */
    int splits;                 /* --adaptive: elements split */
} rad_result;

/* Mesh, form factors, solve and smooth `scene` (which must outlive the
 * result: the mesh refers to its materials by index only, but callers
 * print its name).  The memory the run needs is computed from the scene's
 * mesh specification and checked before anything is meshed or allocated
 * (RAD_ERR_TOOBIG, with both numbers).  On failure the result holds what
 * was done so far; free it with rad_result_free in every case. */
RAD_API rad_status rad_pipeline_run(const rad_scene *scene, const rad_pipeline_options *opt,
                            rad_result *result, rad_error *err);
RAD_API void rad_result_free(rad_result *result);

/* The signature of rad_pipeline_run, for callers that take another run
 * with the same contract (the distributed solve of radiosity-mpi). */
typedef rad_status (*rad_pipeline_fn)(const rad_scene *scene, const rad_pipeline_options *opt,
                                      rad_result *result, rad_error *err);

/* Call run on the scene's present part: the scene itself, or, when some
 * object is declared absent, a copy without it (an error when nothing is
 * left).  rad_pipeline_run is this around the serial run. */
RAD_API rad_status rad_pipeline_present(const rad_scene *scene, const rad_pipeline_options *opt,
                                        rad_result *result, rad_error *err, rad_pipeline_fn run);

#ifdef __cplusplus
}
#endif

#endif /* RAD_PIPELINE_H */
