/* test_scale.c -- the unit of length and the size of E do not matter,
 * through the library.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * References, none taken from the program's output:
 *   - Howell's catalogue C-11: directly opposed unit squares one apart,
 *     F = 0.19982489569838746 (evaluated in long double below); at every
 *     scale from 1e-300 to 1e300, near the origin or 1e12 sides away, the
 *     default rule must land within its own error estimate of it;
 *   - exact invariance: the 1984 cube scaled by 2^-500 or 2^500, or moved
 *     by 2^40, has the very same image in the form factors' frame (a shift
 *     by an exact amount, a scaling by a power of two), so its F must equal
 *     the unit cube's bit for bit, and so must B;
 *   - linearity in E with exact scaling: emission 2^k E gives 2^k B, bit
 *     for bit, for k = 1000 and -1000; a furnace whose B = E / (1 - rho)
 *     would exceed the largest double is refused, not returned as inf;
 *   - areas in the user's units: 2^-1000 apart in scale, the element areas
 *     of the scaled cube are 2^-1000 times the unit cube's (exactly: they
 *     are computed on the polygon scaled by a power of two).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "../tap.h"

/* Howell C-11 for X = Y = 1 (a = b = c), in long double */
static double parallel_unit_squares(void)
{
    const long double X = 1, Y = 1, pi = 3.14159265358979323846264338327950288L;
    long double f = logl(sqrtl((1 + X * X) * (1 + Y * Y) / (1 + X * X + Y * Y))) +
                    X * sqrtl(1 + Y * Y) * atanl(X / sqrtl(1 + Y * Y)) +
                    Y * sqrtl(1 + X * X) * atanl(Y / sqrtl(1 + X * X)) - X * atanl(X) -
                    Y * atanl(Y);
    return (double)(2 / (pi * X * Y) * f);
}

static void plates_at(double s, double t, double want)
{
    /* bottom faces +z, top (z = s) faces -z; everything moved by t */
    rad_vec3 a[4] = {{t, t, t}, {s + t, t, t}, {s + t, s + t, t}, {t, s + t, t}};
    rad_vec3 b[4] = {{t, t, s + t}, {t, s + t, s + t}, {s + t, s + t, s + t}, {s + t, t, s + t}};
    rad_ff_options opt;
    double est = NAN;
    rad_ff_options_init(&opt);
    opt.accuracy = RAD_ACCURACY_DEFAULT;
    double f = rad_ff_polygons(a, 4, b, 4, &opt, &est);
    /* moved by t, the side rounds to an ulp of t: the closed form of the
     * rounded plates, X = Y = side/gap = 1 still (all axes alike) */
    tap_ok(isfinite(f) && fabs(f - want) <= est && est < 1e-7,
           "plates of side %g moved by %g: F = %.17g, error %.3g within its estimate %.3g", s,
           t, f, fabs(f - want), est);
}

static const char *cube_text =
    "material light reflect 0 emit 1 1 1\n"
    "material red reflect 0.8 0.1 0.1\n"
    "material blue reflect 0.1 0.1 0.8\n"
    "material grey reflect 0.6 0.6 0.6\n"
    "quad light 0 0 0  1 0 0  1 1 0  0 1 0\n"
    "quad grey 0 0 1  0 1 1  1 1 1  1 0 1\n"
    "quad red 0 0 0  0 1 0  0 1 1  0 0 1\n"
    "quad blue 1 0 0  1 0 1  1 1 1  1 1 0\n"
    "quad grey 0 0 0  0 0 1  1 0 1  1 0 0\n"
    "quad grey 0 1 0  1 1 0  1 1 1  0 1 1\n";

/* The cube meshed 3x3, every coordinate x -> x s + t, its F and B. */
typedef struct run {
    rad_scene scene;
    rad_mesh mesh;
    double *F, *B;
    rad_status st;
} run;

static void run_cube(run *r, double s, double t, double emit_scale)
{
    rad_error err;
    rad_ff_options ff;
    rad_solve_options so;
    memset(r, 0, sizeof *r);
    r->st = rad_scene_parse(&r->scene, cube_text, strlen(cube_text), "cube", &err);
    if (r->st)
        return;
    for (int k = 0; k < r->scene.nsurfaces; k++) {
        rad_surface *f = &r->scene.surfaces[k];
        for (int v = 0; v < f->nverts; v++)
            f->verts[v] = (rad_vec3){f->verts[v].x * s + t, f->verts[v].y * s + t,
                                     f->verts[v].z * s + t};
    }
    for (int k = 0; k < r->scene.nmaterials; k++)
        for (int b = 0; b < RAD_BANDS; b++)
            r->scene.materials[k].emit[b] *= emit_scale;
    rad_scene_set_mesh(&r->scene, 3, 3);
    if ((r->st = rad_mesh_build(&r->mesh, &r->scene, &err)))
        return;
    const int n = r->mesh.nelements;
    r->F = malloc(sizeof *r->F * (size_t)n * n);
    r->B = malloc(sizeof *r->B * (size_t)n * RAD_BANDS);
    rad_ff_options_init(&ff);
    ff.accuracy = RAD_ACCURACY_DEFAULT;
    rad_solve_options_init(&so);
    if ((r->st = rad_ff_matrix(&r->mesh, &ff, r->F, NULL, NULL, &err)))
        return;
    r->st = rad_solve(&r->mesh, r->F, &so, r->B, NULL, &err);
}

static void run_free(run *r)
{
    free(r->F);
    free(r->B);
    rad_mesh_free(&r->mesh);
    rad_scene_free(&r->scene);
}

/* a and b bit for bit, n doubles */
static int same(const double *a, const double *b, size_t n)
{
    return memcmp(a, b, sizeof *a * n) == 0;
}

static void exact_invariance(const run *u, double s, double t, const char *what)
{
    run r;
    run_cube(&r, s, t, 1);
    const size_t n = (size_t)u->mesh.nelements;
    tap_ok(r.st == RAD_OK && same(u->F, r.F, n * n) && same(u->B, r.B, n * RAD_BANDS),
           "the cube %s: F and B bit for bit those of the unit cube", what);
    run_free(&r);
}

static void areas_scale(const run *u)
{
    run r;
    run_cube(&r, 0x1p-500, 0, 1);
    int ok = r.st == RAD_OK;
    for (int e = 0; ok && e < u->mesh.nelements; e++)
        ok = r.mesh.elements[e].area == ldexp(u->mesh.elements[e].area, -1000);
    tap_ok(ok, "scaled by 2^-500: every element's area is 2^-1000 times the unit cube's");
    run_free(&r);
}

static void emission_scale(const run *u, int k)
{
    run r;
    run_cube(&r, 1, 0, ldexp(1, k));
    const size_t n3 = (size_t)u->mesh.nelements * RAD_BANDS;
    int ok = r.st == RAD_OK;
    for (size_t i = 0; ok && i < n3; i++)
        ok = r.B[i] == ldexp(u->B[i], k);
    tap_ok(ok, "emission 2^%d: B is 2^%d times B at emission 1, bit for bit", k, k);
    run_free(&r);
}

static void furnace_overflow(void)
{
    const char *text = "material w reflect 0.5 emit 1e308\n"
                       "quad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 2x2\n"
                       "quad w 0 0 1  0 1 1  1 1 1  1 0 1 mesh 2x2\n"
                       "quad w 0 0 0  0 1 0  0 1 1  0 0 1 mesh 2x2\n"
                       "quad w 1 0 0  1 0 1  1 1 1  1 1 0 mesh 2x2\n"
                       "quad w 0 0 0  0 0 1  1 0 1  1 0 0 mesh 2x2\n"
                       "quad w 0 1 0  1 1 0  1 1 1  0 1 1 mesh 2x2\n";
    static const rad_solver solvers[] = {RAD_SOLVER_GAUSS, RAD_SOLVER_JACOBI,
                                         RAD_SOLVER_GAUSS_SEIDEL, RAD_SOLVER_PROGRESSIVE};
    rad_scene sc;
    rad_mesh m;
    rad_error err;
    rad_ff_options ff;
    rad_scene_parse(&sc, text, strlen(text), "furnace", &err);
    rad_mesh_build(&m, &sc, &err);
    const int n = m.nelements;
    double *F = malloc(sizeof *F * (size_t)n * n), *B = malloc(sizeof *B * (size_t)n * RAD_BANDS);
    rad_ff_options_init(&ff);
    rad_ff_matrix(&m, &ff, F, NULL, NULL, &err);
    for (int k = 0; k < 4; k++) {
        rad_solve_options so;
        rad_solve_options_init(&so);
        so.solver = solvers[k];
        rad_status st = rad_solve(&m, F, &so, B, NULL, &err);
        tap_ok(st == RAD_ERR_INVALID && strstr(err.message, "largest double"),
               "furnace of emission 1e308 (B = 2e308), solver %d: refused (%s)", k,
               st ? err.message : "returned");
    }
    free(F);
    free(B);
    rad_mesh_free(&m);
    rad_scene_free(&sc);
}

int main(void)
{
    const double want = parallel_unit_squares();
    tap_close(want, 0.19982489569838746, 1e-15, "Howell C-11, unit squares one apart");
    const double scales[] = {1e-300, 1e-150, 1e-80, 1, 1e80, 1e150, 1e300};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        plates_at(scales[k], 0, want);
        if (isfinite(1e12 * scales[k] + scales[k]))
            plates_at(scales[k], 1e12 * scales[k], want);
    }

    run u;
    run_cube(&u, 1, 0, 1);
    tap_ok(u.st == RAD_OK, "the unit cube, 3x3 per wall, solves");
    exact_invariance(&u, 0x1p-500, 0, "scaled by 2^-500");
    exact_invariance(&u, 0x1p500, 0, "scaled by 2^500");
    exact_invariance(&u, 1, 0x1p40, "moved by 2^40 (its 3x3 grid rounds there)");
    exact_invariance(&u, 0x1p-400, 0x1p-360, "scaled by 2^-400 and moved by 2^40 sides");
    areas_scale(&u);
    emission_scale(&u, 1000);
    emission_scale(&u, -1000);
    furnace_overflow();
    run_free(&u);
    return tap_done();
}
