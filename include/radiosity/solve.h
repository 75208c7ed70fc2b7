/* radiosity/solve.h -- the radiosity system, band by band.
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 */
#ifndef RADIOSITY_SOLVE_H
#define RADIOSITY_SOLVE_H

#include "radiosity/formfactor.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the radiosity system ----------------------------------------------- */

/* For each band b: (I - diag(rho_b) F) B_b = E_b (Goral et al. 1984,
 * eq. 6-7).  B and E are n x RAD_BANDS column-major: B[e + b*n]. */

typedef enum rad_solver {
    RAD_SOLVER_GAUSS = 0,       /* LU with partial pivoting (LAPACK dgesv) */
    RAD_SOLVER_JACOBI,
    RAD_SOLVER_GAUSS_SEIDEL,
    RAD_SOLVER_PROGRESSIVE,     /* shooting, Cohen et al. 1988 */
    RAD_SOLVER_CHOLESKY,        /* the symmetric form, LAPACK dpotrf;
                                   LU where it is not positive definite */
    RAD_SOLVER_CG               /* conjugate gradients on the symmetric form */
} rad_solver;

/* One step of progressive refinement, for a trace (rad_solve_options.on_shot). */
typedef struct rad_shot {
    int step;                   /* 1, 2, ... */
    int shooter;                /* element (or patch, with patches) that shot */
    double shot;                /* power shot, summed over the bands */
    double unshot;              /* unshot power left, summed over the bands */
    double rms, rms_ambient;    /* area-weighted RMS error of the band-averaged
                                   radiosity against the reference (Cohen et al.
                                   1988, eq. 14), without and with the ambient
                                   term */
    double rms_bands, rms_ambient_bands; /* the same per band, averaged over the
                                   bands (what rms was before eq. 14 was read
                                   as the paper means it) */
} rad_shot;

/* Called after each shooting step; return non-zero to stop the solve
 * (RAD_ERR_INVALID, "interrupted"). */
typedef int (*rad_shot_fn)(void *user, const rad_shot *row);

typedef struct rad_solve_options {
    rad_solver solver;
    double tolerance;           /* iterative: stop when a bound on the relative
                                   error of B, ||B - B*||inf / ||B||inf, is below
                                   it (rad_solve_report.error_bound) */
    int max_iterations;         /* iterative: sweeps before giving up */
    int bounces;                /* >= 0: exactly that many reflections,
                                   B_K = sum_{m=0..K} (rho F)^m E; -1: solve */
    int error_bounds;           /* gauss: dgesvx forward/backward error bounds */
    int threads;                /* 0: default */
    rad_progress_fn progress;   /* may be NULL */
    void *progress_user;
    /* progressive refinement (Cohen et al. 1988) */
    int patches;                /* 0: elements shoot; 1: each surface shoots as a patch */
    int patch_p, patch_q;       /* > 0: a P x Q grid of patches per surface shoots
                                   (substructuring, Cohen et al. 1988, section 3.4):
                                   one unshot radiosity per patch, elements receive */
    int sort;                   /* 1: shoot the largest unshot power first (default) */
    int ambient;                /* 1: trace/display with the ambient term */
    rad_shot_fn on_shot;        /* progressive: called with each step, or NULL */
    void *shot_user;
    const double *reference;    /* converged B for the rms of on_shot, or NULL
                                   (then a gauss solve of the same mesh) */
    double ff_row_error;        /* a bound on ||dF||_inf, the error of F
                                   (rad_ff_stats.max_row_error), or NaN if
                                   unknown: gauss then bounds the error it
                                   causes in B, and calls the system singular
                                   when F's error could make it so */
    /* adaptive subdivision (Cohen et al. 1988, section 4; pipeline only:
       progressive, the starting elements shoot as fixed patches) */
    int adaptive;               /* 1: split elements where B varies */
    double subdivide_threshold; /* split an element whose B differs from an edge
                                   neighbour's by more than this fraction of the
                                   largest reflected radiosity B - E in the
                                   scene, per band (default 0.1) */
    int max_depth;              /* levels of splitting below a starting element
                                   (default 3: down to 1/8 of its side) */
    int subdivide_by_error;     /* 0 (default): the threshold bounds the
                                   difference itself (Cohen et al. 1988,
                                   section 4); 1: the difference times the
                                   element's side over the largest splittable
                                   patch's (splits ranked by their gain in
                                   the area-weighted RMS error) */
} rad_solve_options;

RAD_API void rad_solve_options_init(rad_solve_options *opt);
/* A solver's name as the command line spells it ("gauss", "cholesky",
 * ...), or NULL for a value out of range. */
RAD_API const char *rad_solver_name(int solver);

typedef struct rad_solve_report {
    rad_solver solver;
    int bounces;
    int systems;                /* distinct reflectance sets factorised */
    int sweeps;                 /* iterative solvers, per the slowest band */
    double residual;            /* max over bands of ||(I - rho F)B - E||inf / ||E||inf */
    double rcond;               /* reciprocal condition estimate, min over systems:
                                   gauss of I - diag(rho) F (1-norm, dgecon);
                                   cholesky of its symmetric form scaled to a
                                   unit diagonal (dpocon) */
    double ff_error_bound;      /* gauss, cholesky, given ff_row_error: relative error of B
                                   (infinity norm) that F's error may cause,
                                   max over systems; NaN otherwise */
    double ferr, berr;          /* forward, backward error bounds (error_bounds) */
    double spectral_radius;     /* estimate of rho(diag(rho) F), max over bands */
    double row_sum_min, row_sum_max;  /* of F */
    double emitted[RAD_BANDS];  /* sum A_i E_i */
    double absorbed[RAD_BANDS]; /* sum A_i (1 - rho_i) H_i, H = F B */
    double escaped[RAD_BANDS];  /* sum A_i B_i (1 - sum_j F_ij) */
    double balance[RAD_BANDS];  /* (emitted - absorbed - escaped) / emitted */
    /* the symmetric and iterative solvers */
    double error_bound;         /* jacobi, gauss-seidel, cg: a bound on
                                   ||B - B*||inf / ||B||inf at the stop, from the
                                   contraction factor; NaN where none holds */
    double contraction;         /* q = max_i rho_i sum_j |F_ij|, max over bands:
                                   ||diag(rho) F||inf, the factor by which a
                                   Jacobi sweep at least shrinks the error */
    int fallbacks;              /* cholesky, cg: systems that went to LU */
    char fallback[256];         /* why, or "" */
} rad_solve_report;

/* Solve for B given the mesh (reflectance, emission, area) and F.  F is
 * not modified.  RAD_ERR_SINGULAR for a (numerically) singular system,
 * RAD_ERR_NOCONV for an iteration that did not converge (B then holds the
 * last iterate, which the caller must not present as the answer),
 * RAD_ERR_INVALID for a B beyond the largest double: a B returned with
 * RAD_OK is finite.  The report's powers may be inf when they exceed the
 * double range (large areas times large E); its balance is a ratio. */
RAD_API rad_status rad_solve(const rad_mesh *mesh, const double *F, const rad_solve_options *opt,
                     double *B, rad_solve_report *report, rad_error *err);

/* Progressive refinement (Cohen, Chen, Wallace & Greenberg 1988): called by
 * rad_solve for RAD_SOLVER_PROGRESSIVE; rho and E are n x 3 column-major. */
RAD_API rad_status rad_solve_progressive(const rad_mesh *mesh, const double *F, const double *rho,
                                 const double *E, const rad_solve_options *opt, double *B,
                                 rad_solve_report *report, rad_error *err);

/* Bytes the solve of n elements needs at its peak (F plus one working
 * matrix, plus O(n)), for the memory check before allocating: LU's
 * figure, the largest.  rad_solve_bytes_for gives the chosen solver's:
 * F alone for the iterative and progressive solvers, F and one working
 * matrix for gauss and cholesky (two with error_bounds), plus O(n). */
RAD_API double rad_solve_bytes(int n, int with_errest);
RAD_API double rad_solve_bytes_for(int n, const rad_solve_options *opt);

#ifdef __cplusplus
}
#endif

#endif /* RADIOSITY_SOLVE_H */
