/* radiosity.h -- the public C API of the radiosity library.
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 * This is the one header a library user includes.  Everything public starts
 * with `rad_`.  The library keeps no global mutable state: every function
 * works on the objects it is given, so separate objects may be used from
 * separate threads.
 *
 * Conventions, stated once:
 *   - lengths are in the user's unit; radiosity B and emission E share one
 *     radiometric unit (power per area); form factors are dimensionless;
 *   - polygons run counter-clockwise seen from their front side, the side
 *     that reflects and emits; the front normal follows the right-hand rule;
 *   - colour bands are RAD_BANDS = 3 (red, green, blue), index 0, 1, 2;
 *   - matrices are double, column-major (LAPACK): entry (i, j) of an n x n
 *     matrix M is M[i + j*n]; F[i + j*n] is the form factor FROM element i
 *     TO element j (row i = from element i);
 *   - a function that can fail returns a rad_status and, when given a
 *     rad_error, fills it with a message of the form "FILE:LINE: reason"
 *     for input errors, or a plain reason otherwise.  Library code never
 *     prints.
 */
#ifndef RADIOSITY_H
#define RADIOSITY_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* RAD_API marks what the shared library exports; it is built with hidden
 * visibility, so nothing else leaves it (Drepper, "How to Write Shared
 * Libraries", 2011, section 2.2). */
#if defined(__GNUC__) && __GNUC__ >= 4
#define RAD_API __attribute__((visibility("default")))
#else
#define RAD_API
#endif

#define RAD_BANDS 3

/* ---- status and errors ------------------------------------------------ */

typedef enum rad_status {
    RAD_OK = 0,
    RAD_ERR_NOMEM,      /* allocation failed */
    RAD_ERR_IO,         /* a file could not be read or written */
    RAD_ERR_PARSE,      /* malformed input (message names file and line) */
    RAD_ERR_INVALID,    /* an argument out of its domain */
    RAD_ERR_TOOBIG,     /* the problem does not fit in memory */
    RAD_ERR_SINGULAR,   /* the radiosity system is (numerically) singular */
    RAD_ERR_NOCONV      /* an iteration stopped without converging */
} rad_status;

#define RAD_ERRMSG_MAX 512

typedef struct rad_error {
    rad_status status;
    char message[RAD_ERRMSG_MAX];
} rad_error;

/* A short English name of a status ("singular system", ...). */
RAD_API const char *rad_strstatus(rad_status status);

/* ---- geometry ----------------------------------------------------------- */

typedef struct rad_vec3 {
    double x, y, z;
} rad_vec3;

/* ---- scene (scene.c) ---------------------------------------------------- */

#define RAD_NAME_MAX 64

typedef struct rad_material {
    char name[RAD_NAME_MAX];
    double reflect[RAD_BANDS];  /* rho in [0, 1] */
    double emit[RAD_BANDS];     /* E >= 0 */
    int line;                   /* where it was defined */
} rad_material;

typedef enum rad_surface_kind {
    RAD_SURFACE_QUAD = 0,       /* meshed into mesh_n x mesh_m elements */
    RAD_SURFACE_POLYGON         /* convex planar polygon, one element */
} rad_surface_kind;

typedef struct rad_surface {
    rad_surface_kind kind;
    int material;               /* index into rad_scene.materials */
    int nverts;                 /* 4 for a quad, K >= 3 for a polygon */
    rad_vec3 *verts;            /* counter-clockwise about the front */
    int mesh_n, mesh_m;         /* v1->v2 in N parts, v2->v3 in M parts */
    int line;                   /* input line, for messages */
    int object;                 /* index into rad_scene.objects; -1: the static
                                   environment (outside every object) */
} rad_surface;

/* A named group of surfaces that a change may move, add or remove (the
 * dynamic-scene contract of radiosity-scene(5)): `object NAME [absent]`
 * ... `end` in a scene file, `o` and `g` statements in OBJ. */
typedef struct rad_object {
    char name[RAD_NAME_MAX];
    int absent;                 /* 1: joins the scene only when a change adds it */
    int line;                   /* where it was first named */
} rad_object;

typedef struct rad_camera {
    int defined;                /* 0: the scene has no camera line */
    rad_vec3 eye, at, up;
    double fov;                 /* vertical, degrees */
} rad_camera;

typedef struct rad_scene {
    char *filename;
    rad_material *materials;
    int nmaterials;
    rad_surface *surfaces;
    int nsurfaces;
    rad_object *objects;
    int nobjects;
    rad_camera camera;
} rad_scene;

/* Parse a scene file (format: radiosity-scene(5)).  "-" reads standard
 * input.  A name ending in ".obj" is read as Wavefront OBJ (its mtllib
 * files relative to it), one ending in ".vs3" as View3D 3.x input (both
 * case-insensitive; radiosity-scene(5) says what they map to).  On
 * failure *scene is left empty and err says FILE:LINE: why. */
RAD_API rad_status rad_scene_load(rad_scene *scene, const char *path, rad_error *err);
/* Parse scene text held in memory; `name` is used in messages and picks
 * the format by its ending as rad_scene_load does. */
RAD_API rad_status rad_scene_parse(rad_scene *scene, const char *text, size_t len,
                           const char *name, rad_error *err);
RAD_API void rad_scene_free(rad_scene *scene);
/* Override the mesh of every quad (the --mesh option). */
RAD_API void rad_scene_set_mesh(rad_scene *scene, int n, int m);
/* 1 if some surface belongs to an absent object (scenepresent.c). */
RAD_API int rad_scene_has_absent(const rad_scene *scene);
/* A copy of the scene with only the present surfaces, in file order:
 * present[o] (nobjects entries) says which objects are in, or, when
 * present is NULL, the objects not declared absent.  Free it with
 * rad_scene_free. */
RAD_API rad_status rad_scene_present_copy(const rad_scene *in, const unsigned char *present,
                                          rad_scene *out, rad_error *err);

/* ---- mesh (mesh.c) ------------------------------------------------------ */

typedef struct rad_element {
    int surface;                /* index of the scene surface it came from */
    int gi, gj;                 /* position in the surface's grid (0,0 for polygons) */
    int nverts;                 /* 4 for quad elements, K for polygons */
    int first;                  /* its vertex indices: mesh.vindex[first..first+nverts) */
    rad_vec3 centroid;
    rad_vec3 normal;            /* unit front normal */
    double area;
    double reflect[RAD_BANDS];
    double emit[RAD_BANDS];
} rad_element;

typedef struct rad_mesh {
    int nelements;
    rad_element *elements;
    int nvertices;
    rad_vec3 *vertices;         /* shared inside a surface, never across */
    int *vindex;                /* element vertex lists, counter-clockwise */
    int nsurfaces;
    int *surface_first;         /* elements of surface s: [first[s], first[s+1]) */
    int *surface_vfirst;        /* vertices of surface s: [vfirst[s], vfirst[s+1]);
                                   a quad's are row-major: (gj) * (n+1) + gi */
    int *surface_n, *surface_m; /* grid size per surface (1 x 1 for polygons) */
} rad_mesh;

/* Refuses (RAD_ERR_INVALID, naming the scene's line) an element whose area
 * is not a normal double: the areas are in the user's units. */
RAD_API rad_status rad_mesh_build(rad_mesh *mesh, const rad_scene *scene, rad_error *err);
RAD_API void rad_mesh_free(rad_mesh *mesh);
/* The vertex v (0..nverts-1) of element e. */
RAD_API rad_vec3 rad_mesh_vertex(const rad_mesh *mesh, int e, int v);
/* Elements the scene's mesh specification makes (a double: it may exceed
 * any int), without meshing. */
RAD_API double rad_scene_element_count(const rad_scene *scene);

/* ---- form factors (formfactor.c) ---------------------------------------- */

typedef enum rad_accuracy {
    RAD_ACCURACY_CLASSIC = 0,   /* Goral et al. 1984: K Gauss points per edge,
                                   closed form for colinear edges, nothing else */
    RAD_ACCURACY_DEFAULT,       /* the classic rule, made safe where it fails */
    RAD_ACCURACY_REFERENCE      /* error-controlled, relative error <= 1e-9 */
} rad_accuracy;

/* Called now and then during long computations; `done` of `total` units.
 * Return non-zero to ask the computation to stop (it then returns
 * RAD_ERR_INVALID with the message "interrupted"). */
typedef int (*rad_progress_fn)(void *user, const char *stage, double done, double total);

/* How the form factors are computed. */
typedef enum rad_ff_method {
    RAD_FF_CONTOUR = 0,         /* the contour integral, element to element
                                   (Goral et al. 1984, eq. 13; the default) */
    RAD_FF_HEMICUBE             /* the hemicube at each element's centre
                                   (Cohen & Greenberg 1985): row i of F from
                                   i's centre, visibility by a z-buffer */
} rad_ff_method;

typedef struct rad_ff_options {
    int quadrature;             /* Gauss points per edge, 1..RAD_GAUSS_MAX (3) */
    rad_accuracy accuracy;
    int threads;                /* 0: OpenMP default */
    rad_progress_fn progress;   /* may be NULL */
    void *progress_user;
    rad_ff_method method;       /* contour (default) or hemicube */
    int resolution;             /* hemicube: pixels along the top face, even,
                                   2..RAD_HEMICUBE_MAX (RAD_HEMICUBE_DEFAULT) */
} rad_ff_options;

#define RAD_HEMICUBE_DEFAULT 64
#define RAD_HEMICUBE_MAX 4096
/* "contour", "hemicube", or NULL for a value out of range. */
RAD_API const char *rad_ff_method_name(int method);

#define RAD_GAUSS_MAX 20
/* A row of F may exceed 1 by this much before the fill calls it wrong:
 * the default mode's promise, summed over a row (sum_j 1e-6 F_ij <= 1e-6). */
#define RAD_ROW_SUM_SLACK 1e-6

RAD_API void rad_ff_options_init(rad_ff_options *opt);
/* An accuracy mode's name ("classic", "default", "reference"), or NULL. */
RAD_API const char *rad_accuracy_name(int accuracy);

/* Form factor from polygon a (na vertices, area computed) to polygon b, both
 * planar and convex, counter-clockwise about their fronts.  If errest is not
 * NULL it receives an estimate of the absolute error of the result.  Always
 * the contour integral (opt->method is not read: the hemicube gives rows). */
RAD_API double rad_ff_polygons(const rad_vec3 *a, int na, const rad_vec3 *b, int nb,
                       const rad_ff_options *opt, double *errest);

/* What a fill of the form-factor matrix found. */
typedef struct rad_ff_stats {
    double pairs;               /* unordered pairs of distinct elements */
    double integrated;          /* pairs that needed a contour integral */
    long negative;              /* entries below 0 (only possible in classic) */
    long above_one;             /* entries above 1 (only possible in classic) */
    double min_value, max_value;
    double max_errest;          /* largest estimated absolute error */
    double max_relerr;          /* largest estimated relative error (of a
                                   partly hidden entry: relative to the
                                   entry, or to 1e-4 of its unoccluded value
                                   when larger; radiosity-files(5)) */
    double max_row_error;       /* largest row sum of the estimated absolute
                                   errors, max_i sum_j |dF_ij| (a bound on
                                   ||dF||_inf; NaN in classic) */
    double promise;             /* the mode's promise on each entry's relative
                                   error: 1e-6 default, 1e-9 reference, NaN classic */
    long promise_unmet;         /* entries whose own error estimate exceeds
                                   promise x |F_ij| (ordered pairs; |F_ij|
                                   as in max_relerr) */
    long rows_above_one;        /* rows with sum_j F_ij > 1 + RAD_ROW_SUM_SLACK:
                                   impossible (energy from nowhere) */
    int vis_needed;             /* 0: nothing can be blocked, no visibility work */
    double vis_pairs_tested, vis_pairs_blockable, vis_pairs_blocked, vis_pairs_partial;
    double vis_seconds;         /* visibility setup + thread time (occlusion.h) */
    double clamped_to_one;      /* pairs whose value exceeded 1 one way by no more
                                   than its error bound, set to 1 (formfactor.c) */
} rad_ff_stats;

/* All form factors of a mesh: F is n x n column-major, F[i + j*n] = F_ij,
 * F_ii = 0.  Each unordered pair is computed once; the other entry follows
 * by reciprocity A_i F_ij = A_j F_ji.  errest (n x n, may be NULL) receives
 * the estimated absolute error of each entry; stats (may be NULL) what the
 * fill found.  With opt->method RAD_FF_HEMICUBE each row i is a hemicube
 * on element i's centre instead (no reciprocity; errest NaN). */
RAD_API rad_status rad_ff_matrix(const rad_mesh *mesh, const rad_ff_options *opt, double *F,
                         double *errest, rad_ff_stats *stats, rad_error *err);

/* Gauss-Legendre nodes on [-1, 1] and weights for k = 1..RAD_GAUSS_MAX
 * points (Abramowitz & Stegun 1964, 25.4.29 and table 25.4). */
RAD_API const double *rad_gauss_nodes(int k);
RAD_API const double *rad_gauss_weights(int k);

/* I = integral over s in [a1, a2], t in [b1, b2] of ln sqrt((s-t)^2 + d^2):
 * two parallel segments on lines a distance d >= 0 apart, parameterised by
 * the same unit direction (d = 0: colinear). */
RAD_API double rad_ln_parallel(double a1, double a2, double b1, double b2, double d);

/* ---- the radiosity system (solve.c) ------------------------------------- */

/* For each band b: (I - diag(rho_b) F) B_b = E_b (Goral et al. 1984,
 * eq. 6-7).  B and E are n x RAD_BANDS column-major: B[e + b*n]. */

typedef enum rad_solver {
    RAD_SOLVER_GAUSS = 0,       /* LU with partial pivoting (LAPACK dgesv) */
    RAD_SOLVER_JACOBI,
    RAD_SOLVER_GAUSS_SEIDEL,
    RAD_SOLVER_PROGRESSIVE,     /* shooting, Cohen et al. 1988 (progressive.c) */
    RAD_SOLVER_CHOLESKY,        /* the symmetric form, LAPACK dpotrf (cholesky.c);
                                   LU where it is not positive definite */
    RAD_SOLVER_CG               /* conjugate gradients on the symmetric form (cg.c) */
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

/* Bytes of memory available now (Linux MemAvailable), 0 if unknown. */
RAD_API double rad_memory_available(void);
/* Refuse (RAD_ERR_TOOBIG) when `need` bytes exceed what the machine allows
 * now (rad_memory_limit); `what` names the need in the message.  *have
 * (may be NULL) receives the limit, 0 if unknown. */
RAD_API rad_status rad_memory_check(double need, const char *what, double *have, rad_error *err);

/* The smallest of the memory available now (MemAvailable), the address
 * space and data limits (RLIMIT_AS, RLIMIT_DATA) and the cgroup's
 * memory.max less its memory.current; 0 if none is known. */
RAD_API double rad_memory_limit(void);

/* ---- vertex radiosity (smooth.c) ---------------------------------------- */

/* Vertex radiosity from element radiosity (Goral et al. 1984, section 3;
 * Gouraud 1971), never across surfaces.  B is nelements x RAD_BANDS and Bv
 * nvertices x RAD_BANDS, both column-major. */
RAD_API void rad_smooth_vertices(const rad_mesh *mesh, const double *B, double *Bv);

/* How a vertex on a surface's boundary gets its value (smooth.c):
 * EXTRAPOLATE is the 1984 paper's linear extrapolation (the default, what
 * rad_smooth_vertices does); CORNER is the course notes' rule, where the
 * mean of a boundary vertex and its nearest interior vertex equals the
 * mean of the elements that meet at the boundary vertex.  The two agree
 * on edges and on fields linear over the surface; they differ at
 * corners. */
typedef enum rad_vertex_rule {
    RAD_VERTEX_EXTRAPOLATE = 0,
    RAD_VERTEX_CORNER
} rad_vertex_rule;
RAD_API void rad_smooth_vertices_rule(const rad_mesh *mesh, const double *B, double *Bv,
                                      rad_vertex_rule rule);
/* "extrapolate", "corner", or NULL. */
RAD_API const char *rad_vertex_rule_name(int rule);

/* ---- closed forms (analytic.c) ------------------------------------------ */

/* Differential area to a coaxial parallel disk of radius r at distance h. */
RAD_API double rad_analytic_point_disk(double r, double h);
/* Disk of radius r1 to a coaxial parallel disk of radius r2, h apart. */
RAD_API double rad_analytic_disk_disk(double r1, double r2, double h);
/* Directly opposed parallel a x b rectangles, c apart. */
RAD_API double rad_analytic_parallel_rectangles(double a, double b, double c);
/* From the l x w rectangle to the l x h rectangle sharing its edge of
 * length l at a right angle. */
RAD_API double rad_analytic_perpendicular_rectangles(double l, double w, double h);

#ifdef __cplusplus
}
#endif

#endif /* RADIOSITY_H */
