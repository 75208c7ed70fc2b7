/* test_solve.c -- the radiosity system: solvers, bounces, diagnostics.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Independent references:
 *   - the exact element-to-element form factors of the cube, assembled in
 *     this test from the closed forms for directly opposed and perpendicular
 *     rectangles (Howell C-11, C-14) by view-factor algebra: for a kernel
 *     that depends on x - xi, integral_x1^x2 integral_xi1^xi2 K = -1/2 sum
 *     (-1)^(i+k) h(|x_i - xi_k|) with h(L) the aligned value (second
 *     differences of an even antiderivative); in two directions 1/4 sum;
 *   - a plain Gaussian elimination with partial pivoting in long double,
 *     written here, for the exact discrete solution;
 *   - closed forms: the furnace B = E/(1 - rho); two facing squares with
 *     rho = 1, B1 = E/(1 - F^2);
 *   - identities: energy balance, mirror symmetry;
 *   - every solver against the long-double solution of the same F, within
 *     round-off (direct) or the error bound it reports (iterative);
 *   - the symmetric form's fallbacks on matrices built to need them, with
 *     closed-form answers; its bound from F's error against the exact
 *     inverse.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/lapack.h"
#include "solve/lu.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "../tap.h"

static const char *walls[6] = {
    "0 0 0  1 0 0  1 1 0  0 1 0", /* z = 0, +z */
    "0 0 1  0 1 1  1 1 1  1 0 1", /* z = 1, -z */
    "0 0 0  0 1 0  0 1 1  0 0 1", /* x = 0, +x */
    "1 0 0  1 0 1  1 1 1  1 1 0", /* x = 1, -x */
    "0 0 0  0 0 1  1 0 1  1 0 0", /* y = 0, +y */
    "0 1 0  1 1 0  1 1 1  0 1 1", /* y = 1, -y */
};

/* The cube with the given material per wall (front, back, x0, x1, floor, ceiling). */
static int cube(int n, const char *materials, const char *const mat[6], rad_scene *s, rad_mesh *m)
{
    char text[4096];
    int len = snprintf(text, sizeof text, "%s", materials);
    for (int w = 0; w < 6; w++)
        len += snprintf(text + len, sizeof text - (size_t)len, "quad %s %s mesh %dx%d\n", mat[w],
                        walls[w], n, n);
    rad_error err;
    if (rad_scene_parse(s, text, strlen(text), "cube", &err))
        return -1;
    return rad_mesh_build(m, s, &err) ? -1 : 0;
}

static const char *goral_materials =
    "material light reflect 0 emit 1 1 1\n"
    "material red reflect 0.8 0.1 0.1\n"
    "material blue reflect 0.1 0.1 0.8\n"
    "material grey reflect 0.6 0.6 0.6\n";
static const char *const goral[6] = {"light", "grey", "red", "blue", "grey", "grey"};

static double *form_factors(const rad_mesh *m, rad_accuracy acc)
{
    rad_ff_options o;
    rad_error err;
    rad_ff_options_init(&o);
    o.accuracy = acc;
    size_t n = (size_t)m->nelements;
    double *F = malloc(sizeof *F * n * n);
    if (F && rad_ff_matrix(m, &o, F, NULL, NULL, &err)) {
        free(F);
        return NULL;
    }
    return F;
}

/* ---- exact form factors of axis-aligned cube elements ------------------- */

static double h_par(double u, double v, double c)
{
    u = fabs(u);
    v = fabs(v);
    return u == 0 || v == 0 ? 0 : u * v * rad_analytic_parallel_rectangles(u, v, c);
}

static double h_perp(double l, double w, double h)
{
    l = fabs(l);
    return l == 0 || w == 0 || h == 0 ? 0 : l * w * rad_analytic_perpendicular_rectangles(l, w, h);
}

typedef struct box {
    int axis;               /* normal axis */
    double plane;
    double lo[3], hi[3];
} box;

static box element_box(const rad_mesh *m, int e)
{
    box b;
    rad_vec3 nrm = m->elements[e].normal;
    b.axis = fabs(nrm.x) > 0.5 ? 0 : fabs(nrm.y) > 0.5 ? 1 : 2;
    for (int k = 0; k < 3; k++) {
        b.lo[k] = HUGE_VAL;
        b.hi[k] = -HUGE_VAL;
    }
    for (int v = 0; v < 4; v++) {
        rad_vec3 p = rad_mesh_vertex(m, e, v);
        double c[3] = {p.x, p.y, p.z};
        for (int k = 0; k < 3; k++) {
            b.lo[k] = fmin(b.lo[k], c[k]);
            b.hi[k] = fmax(b.hi[k], c[k]);
        }
    }
    b.plane = b.lo[b.axis];
    return b;
}

/* A_i F_ij for two elements of the unit cube, exactly. */
static double exact_af(const box *a, const box *b)
{
    if (a->axis == b->axis) {
        if (a->plane == b->plane)
            return 0;
        int u = (a->axis + 1) % 3, v = (a->axis + 2) % 3;
        double s = 0;
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                for (int k = 0; k < 2; k++)
                    for (int l = 0; l < 2; l++) {
                        double x = i ? a->hi[u] : a->lo[u], y = j ? a->hi[v] : a->lo[v];
                        double xi = k ? b->hi[u] : b->lo[u], eta = l ? b->hi[v] : b->lo[v];
                        s += ((i + j + k + l) % 2 ? -1 : 1) * h_par(x - xi, y - eta, fabs(a->plane - b->plane));
                    }
        return s / 4;
    }
    int sh = 3 - a->axis - b->axis; /* the shared axis */
    /* distances from the common line: a along b's axis, b along a's axis */
    double y[2] = {fabs(a->lo[b->axis] - b->plane), fabs(a->hi[b->axis] - b->plane)};
    double z[2] = {fabs(b->lo[a->axis] - a->plane), fabs(b->hi[a->axis] - a->plane)};
    double s = 0;
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 2; k++) {
            double x = i ? a->hi[sh] : a->lo[sh], xi = k ? b->hi[sh] : b->lo[sh];
            double sx = (i + k) % 2 ? -1 : 1;
            for (int j = 0; j < 2; j++)
                for (int l = 0; l < 2; l++) {
                    double w0 = fmin(y[0], y[1]), w1 = fmax(y[0], y[1]);
                    double z0 = fmin(z[0], z[1]), z1 = fmax(z[0], z[1]);
                    double wj = j ? w1 : w0, zl = l ? z1 : z0;
                    double sy = (j + l) % 2 ? -1 : 1;
                    s += -0.5 * sx * sy * h_perp(x - xi, wj, zl);
                }
        }
    return s;
}

/* Gaussian elimination with partial pivoting in long double: A x = b. */
static void ge_solve(int n, long double *A, long double *x)
{
    for (int k = 0; k < n; k++) {
        int p = k;
        for (int i = k + 1; i < n; i++)
            if (fabsl(A[(size_t)i * n + k]) > fabsl(A[(size_t)p * n + k]))
                p = i;
        if (p != k) {
            for (int j = 0; j < n; j++) {
                long double t = A[(size_t)k * n + j];
                A[(size_t)k * n + j] = A[(size_t)p * n + j];
                A[(size_t)p * n + j] = t;
            }
            long double t = x[k];
            x[k] = x[p];
            x[p] = t;
        }
        for (int i = k + 1; i < n; i++) {
            long double f = A[(size_t)i * n + k] / A[(size_t)k * n + k];
            for (int j = k; j < n; j++)
                A[(size_t)i * n + j] -= f * A[(size_t)k * n + j];
            x[i] -= f * x[k];
        }
    }
    for (int k = n - 1; k >= 0; k--) {
        for (int j = k + 1; j < n; j++)
            x[k] -= A[(size_t)k * n + j] * x[j];
        x[k] /= A[(size_t)k * n + k];
    }
}

static void test_cube_exact(int nm)
{
    rad_scene s;
    rad_mesh m;
    rad_solve_options o;
    rad_error err;
    if (cube(nm, goral_materials, goral, &s, &m)) {
        tap_ok(0, "cube %dx%d", nm, nm);
        return;
    }
    const int n = m.nelements;
    double *F = form_factors(&m, RAD_ACCURACY_DEFAULT);
    double *B = malloc(sizeof *B * (size_t)n * 3);
    box *bx = malloc(sizeof *bx * (size_t)n);
    long double *A = malloc(sizeof *A * (size_t)n * n), *x = malloc(sizeof *x * (size_t)n);
    rad_solve_options_init(&o);
    int ok = F && B && rad_solve(&m, F, &o, B, NULL, &err) == RAD_OK;
    double worst = 0, worst_f = 0;
    for (int e = 0; e < n; e++)
        bx[e] = element_box(&m, e);
    for (int b = 0; ok && b < 3; b++) {
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double fij = i == j ? 0 : exact_af(&bx[i], &bx[j]) / m.elements[i].area;
                if (b == 0)
                    worst_f = fmax(worst_f, fabs(fij - F[i + (size_t)j * n]));
                A[(size_t)i * n + j] = (i == j) - (long double)m.elements[i].reflect[b] * fij;
            }
            x[i] = m.elements[i].emit[b];
        }
        ge_solve(n, A, x);
        for (int i = 0; i < n; i++)
            worst = fmax(worst, fabs(B[i + (size_t)b * n] - (double)x[i]));
    }
    /* within 1e-5 of the exact discrete solution */
    tap_ok(ok && worst <= 1e-5, "cube %dx%d: B within 1e-5 of the exact solution (worst %.3g; "
           "F vs exact closed forms: %.3g)", nm, nm, worst, worst_f);
    free(F);
    free(B);
    free(bx);
    free(A);
    free(x);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

static double max_diff(const double *a, const double *b, size_t n)
{
    double d = 0;
    for (size_t k = 0; k < n; k++)
        d = fmax(d, fabs(a[k] - b[k]));
    return d;
}

static void test_solvers_and_bounces(void)
{
    rad_scene s;
    rad_mesh m;
    rad_error err;
    rad_solve_options o;
    rad_solve_report rep;
    cube(5, goral_materials, goral, &s, &m);
    const int n = m.nelements;
    const size_t n3 = (size_t)n * 3;
    double *F = form_factors(&m, RAD_ACCURACY_DEFAULT);
    double *Bg = malloc(sizeof *Bg * n3), *B = malloc(sizeof *B * n3);
    double *S = malloc(sizeof *S * n3), *T = malloc(sizeof *T * n3);
    rad_solve_options_init(&o);
    tap_ok(rad_solve(&m, F, &o, Bg, &rep, &err) == RAD_OK && rep.systems == 3,
           "gauss solves the cube with 3 factorisations (bands differ)");
    /* energy balance: emitted = absorbed + escaped, to 1e-12 of the emitted power */
    double bal = fmax(fabs(rep.balance[0]), fmax(fabs(rep.balance[1]), fabs(rep.balance[2])));
    tap_ok(bal <= 1e-12, "energy balance to 1e-12 of the emitted power (worst %.3g)", bal);
    tap_ok(rep.residual <= 1e-13, "residual %.3g <= 1e-13", rep.residual);
    o.solver = RAD_SOLVER_JACOBI;
    o.tolerance = 1e-14;
    rad_status st = rad_solve(&m, F, &o, B, &rep, &err);
    double d = max_diff(B, Bg, n3);
    tap_ok(st == RAD_OK && d <= 1e-10, "jacobi agrees with gauss to 1e-10 (%.3g, %d sweeps)", d,
           rep.sweeps);
    o.solver = RAD_SOLVER_GAUSS_SEIDEL;
    st = rad_solve(&m, F, &o, B, &rep, &err);
    d = max_diff(B, Bg, n3);
    tap_ok(st == RAD_OK && d <= 1e-10, "gauss-seidel agrees with gauss to 1e-10 (%.3g, %d sweeps)",
           d, rep.sweeps);
    /* bounces: B_K = sum_{m<=K} (rho F)^m E, computed here by plain loops */
    o.solver = RAD_SOLVER_JACOBI;
    for (size_t k = 0; k < n3; k++)
        S[k] = T[k] = m.elements[k % n].emit[k / n]; /* T = (rho F)^m E, S = partial sum */
    int K[] = {0, 1, 2, 4, 8}, next = 0;
    for (int step = 0; step <= 8; step++) {
        if (step == K[next]) {
            o.bounces = step;
            st = rad_solve(&m, F, &o, B, NULL, &err);
            d = max_diff(B, S, n3);
            tap_ok(st == RAD_OK && d <= 1e-12, "--bounces %d equals sum_{m<=%d} (rho F)^m E (%.3g)",
                   step, step, d);
            next++;
        }
        double *U = malloc(sizeof *U * n3);
        for (int b = 0; b < 3; b++)
            for (int i = 0; i < n; i++) {
                double h = 0;
                for (int j = 0; j < n; j++)
                    h += F[i + (size_t)j * n] * T[j + (size_t)b * n];
                U[i + (size_t)b * n] = m.elements[i].reflect[b] * h;
            }
        for (size_t k = 0; k < n3; k++) {
            T[k] = U[k];
            S[k] += U[k];
        }
        free(U);
    }
    o.bounces = 200;
    rad_solve(&m, F, &o, B, NULL, &err);
    d = max_diff(B, Bg, n3);
    tap_ok(d <= 1e-12, "200 bounces converge to the full solution (%.3g)", d);
    o.bounces = -1;
    o.max_iterations = 3;
    st = rad_solve(&m, F, &o, B, NULL, &err);
    tap_ok(st == RAD_ERR_NOCONV && strstr(err.message, "did not converge in 3 sweeps"),
           "3 sweeps are not enough: %s", err.message);
    /* symmetry: floor (surface 4) and ceiling (5) see the same light */
    double sym = 0;
    int per = 25;
    for (int b = 0; b < 3; b++)
        for (int gi = 0; gi < 5; gi++)
            for (int gj = 0; gj < 5; gj++) {
                /* floor v1->v2 runs along +z, ceiling v1->v2 along +x: element
                 * (gi, gj) of the floor sits at z = gi, x = gj; of the ceiling
                 * at x = gi, z = gj. */
                int f = 4 * per + gj * 5 + gi, c = 5 * per + gi * 5 + gj;
                sym = fmax(sym, fabs(Bg[f + (size_t)b * n] - Bg[c + (size_t)b * n]));
            }
    tap_ok(sym <= 1e-13, "floor and ceiling agree element by element (%.3g)", sym);
    free(F);
    free(Bg);
    free(B);
    free(S);
    free(T);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

/* Swapping the red and blue walls mirrors the solution in x. */
static void test_mirror(void)
{
    static const char *const swapped[6] = {"light", "grey", "blue", "red", "grey", "grey"};
    rad_scene s1, s2;
    rad_mesh m1, m2;
    rad_error err;
    rad_solve_options o;
    rad_solve_options_init(&o);
    cube(4, goral_materials, goral, &s1, &m1);
    cube(4, goral_materials, swapped, &s2, &m2);
    const int n = m1.nelements;
    double *F = form_factors(&m1, RAD_ACCURACY_DEFAULT);
    double *B1 = malloc(sizeof *B1 * (size_t)n * 3), *B2 = malloc(sizeof *B2 * (size_t)n * 3);
    rad_solve(&m1, F, &o, B1, NULL, &err);
    rad_solve(&m2, F, &o, B2, NULL, &err); /* same geometry, same F */
    /* the mirror x -> 1 - x maps each element to one with its centroid
     * mirrored; find it by centroid */
    double worst = 0;
    int found = 0;
    for (int i = 0; i < n; i++) {
        rad_vec3 c = m1.elements[i].centroid;
        for (int j = 0; j < n; j++) {
            rad_vec3 d = m2.elements[j].centroid;
            if (fabs(d.x - (1 - c.x)) < 1e-12 && fabs(d.y - c.y) < 1e-12 && fabs(d.z - c.z) < 1e-12) {
                found++;
                for (int b = 0; b < 3; b++) /* scene 2 is scene 1 mirrored */
                    worst = fmax(worst, fabs(B1[i + (size_t)b * n] - B2[j + (size_t)b * n]));
                break;
            }
        }
    }
    tap_ok(found == n && worst <= 1e-12,
           "swapping the red and blue walls mirrors B in x (%.3g)", worst);
    free(F);
    free(B1);
    free(B2);
    rad_mesh_free(&m1);
    rad_mesh_free(&m2);
    rad_scene_free(&s1);
    rad_scene_free(&s2);
}

static void test_furnace_and_singular(void)
{
    static const char *const w6[6] = {"w", "w", "w", "w", "w", "w"};
    rad_scene s;
    rad_mesh m;
    rad_error err;
    rad_solve_options o;
    rad_solve_report rep;
    rad_solve_options_init(&o);
    cube(3, "material w reflect 0.5 emit 1\n", w6, &s, &m);
    int n = m.nelements;
    double *F = form_factors(&m, RAD_ACCURACY_DEFAULT);
    double *B = malloc(sizeof *B * (size_t)n * 3);
    rad_solve(&m, F, &o, B, &rep, &err);
    /* B = E/(1 - rho) = 2, up to rho * |1 - row sum| / (1 - rho)^2 */
    double dev = fmax(fabs(rep.row_sum_max - 1), fabs(rep.row_sum_min - 1));
    double worst = 0;
    for (int k = 0; k < 3 * n; k++)
        worst = fmax(worst, fabs(B[k] - 2));
    tap_ok(worst <= 2 * dev + 1e-14, "furnace: B = 2 everywhere (worst %.3g, row sums within %.3g)",
           worst, dev);
    tap_ok(rep.systems == 1, "a grey scene is one factorisation (%d)", rep.systems);
    rad_mesh_free(&m);
    rad_scene_free(&s);
    /* closed box with rho = 1: singular */
    cube(3, "material w reflect 1 emit 1\n", w6, &s, &m);
    rad_status st = rad_solve(&m, F, &o, B, NULL, &err);
    tap_ok(st == RAD_ERR_SINGULAR && strstr(err.message, "singular"),
           "closed box, rho = 1: singular (%s)", err.message);
    o.solver = RAD_SOLVER_JACOBI;
    o.max_iterations = 500;
    st = rad_solve(&m, F, &o, B, NULL, &err);
    tap_ok(st == RAD_ERR_NOCONV && strstr(err.message, "singular"),
           "closed box, rho = 1, jacobi: no convergence, looks singular (%s)", err.message);
    free(F);
    free(B);
    rad_mesh_free(&m);
    rad_scene_free(&s);
    /* open scene with rho = 1: two facing squares, one emitting.
     * B1 = E + F B2, B2 = F B1  =>  B1 = E / (1 - F^2), F from Howell C-11 */
    const char *two = "material l reflect 1 emit 1\nmaterial w reflect 1\n"
                      "quad l 0 0 0  1 0 0  1 1 0  0 1 0\nquad w 0 0 1  0 1 1  1 1 1  1 0 1\n";
    rad_scene_parse(&s, two, strlen(two), "two", &err);
    rad_mesh_build(&m, &s, &err);
    F = form_factors(&m, RAD_ACCURACY_REFERENCE);
    B = malloc(sizeof *B * 6);
    rad_solve_options_init(&o);
    st = rad_solve(&m, F, &o, B, NULL, &err);
    /* the solver to round-off against the F it was given; that F against
     * Howell C-11 within the reference mode's promise (1e-9) */
    const double f = F[1];
    tap_close(f, 0.19982489569838746, 1e-9, "open rho = 1: F within 1e-9 of Howell C-11");
    tap_ok(st == RAD_OK, "open scene with rho = 1 solves");
    tap_close(B[0], 1 / (1 - f * f), 1e-14, "open rho = 1: B1 = 1/(1 - F^2)");
    tap_close(B[1], f / (1 - f * f), 1e-14, "open rho = 1: B2 = F/(1 - F^2)");
    free(F);
    free(B);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

/* The blocked LU (lu.c) against LAPACK's dgetrf on a matrix large enough
 * to take the blocked path: the same algorithm, so the same pivots, and
 * factors equal to round-off (1e-12 relative to the largest entry: the
 * blocked update sums in another order, n * eps * growth). */
static void test_blocked_lu(void)
{
    const int n = 2100;
    double *A = malloc(sizeof *A * (size_t)n * n), *C = malloc(sizeof *C * (size_t)n * n);
    int *p1 = malloc(sizeof *p1 * n), *p2 = malloc(sizeof *p2 * n), info, stopped;
    unsigned seed = 7;
    for (size_t k = 0; k < (size_t)n * n; k++) {
        seed = seed * 1103515245u + 12345u;
        A[k] = ((seed >> 8) & 0xffff) / 65536.0 - 0.5;
    }
    memcpy(C, A, sizeof *A * (size_t)n * n);
    dgetrf_(&n, &n, A, &n, p1, &info);
    int info2 = radi_lu_factor(n, C, p2, NULL, NULL, "lu", &stopped);
    double worst = 0, big = 0;
    int same = info == info2 && !stopped;
    for (int i = 0; i < n; i++)
        same &= p1[i] == p2[i];
    for (size_t k = 0; k < (size_t)n * n; k++) {
        worst = fmax(worst, fabs(A[k] - C[k]));
        big = fmax(big, fabs(A[k]));
    }
    tap_ok(same && worst <= 1e-12 * big, "blocked LU equals dgetrf: same pivots, factors to %.3g", worst / big);
    free(A);
    free(C);
    free(p1);
    free(p2);
}


/* ---- the symmetric form (cholesky.c) --------------------------------------- */

/* The exact discrete solution for this F, in long double: X (n x 3). */
static void reference_solution(const rad_mesh *m, const double *F, double *X)
{
    const int n = m->nelements;
    long double *A = malloc(sizeof *A * (size_t)n * n), *x = malloc(sizeof *x * (size_t)n);
    for (int b = 0; b < 3; b++) {
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++)
                A[(size_t)i * n + j] = (i == j) - (long double)m->elements[i].reflect[b] *
                                                      F[i + (size_t)j * n];
            x[i] = m->elements[i].emit[b];
        }
        ge_solve(n, A, x);
        for (int i = 0; i < n; i++)
            X[i + (size_t)b * n] = (double)x[i];
    }
    free(A);
    free(x);
}

static double rel_err(const double *B, const double *X, size_t n)
{
    double big = 0;
    for (size_t k = 0; k < n; k++)
        big = fmax(big, fabs(X[k]));
    return max_diff(B, X, n) / big;
}

/* Every solver against the exact discrete solution of the same F, on the
 * 7x7 cube (294 elements).
 * Direct solvers: backward stable with growth factor <= 2 for a
 * diagonally dominant matrix (Higham 2002, thm. 9.9; Cholesky thm. 10.5),
 * so the error is <= 2 gamma_3n kappa, kappa_inf(I - rho F) <= (1 + q) /
 * (1 - q) = 9 for q = 0.8: we allow 6 n eps kappa.  Iterative solvers:
 * their reported bound must hold, up to that same round-off. */
static void test_all_solvers_exact(void)
{
    static const rad_solver which[] = {RAD_SOLVER_GAUSS, RAD_SOLVER_CHOLESKY,
                                       RAD_SOLVER_JACOBI, RAD_SOLVER_GAUSS_SEIDEL,
                                       RAD_SOLVER_CG};
    static const char *const names[] = {"gauss", "cholesky", "jacobi", "gauss-seidel", "cg"};
    rad_scene s;
    rad_mesh m;
    rad_error err;
    rad_solve_options o;
    rad_solve_report rep;
    cube(7, goral_materials, goral, &s, &m);
    const int n = m.nelements;
    const size_t n3 = (size_t)n * 3;
    double *F = form_factors(&m, RAD_ACCURACY_DEFAULT);
    double *X = malloc(sizeof *X * n3), *B = malloc(sizeof *B * n3);
    reference_solution(&m, F, X);
    const double q = 0.8, kappa = (1 + q) / (1 - q), floor = 6 * n * DBL_EPSILON * kappa;
    for (size_t k = 0; k < sizeof which / sizeof *which; k++) {
        rad_solve_options_init(&o);
        o.solver = which[k];
        rad_status st = rad_solve(&m, F, &o, B, &rep, &err);
        const double e = rel_err(B, X, n3);
        if (k < 2)
            tap_ok(st == RAD_OK && e <= floor && rep.fallbacks == 0,
                   "%s: B within 6 n eps kappa = %.3g of the exact solution (%.3g)", names[k],
                   floor, e);
        else
            tap_ok(st == RAD_OK && e <= rep.error_bound + floor && rep.error_bound <= 1e-12 &&
                       fabs(rep.contraction - q) <= 1e-9 && rep.fallbacks == 0,
                   "%s: error %.3g within its bound %.3g <= 1e-12 (+ %.3g), %d sweeps, q = %.12g",
                   names[k], e, rep.error_bound, floor, rep.sweeps, rep.contraction);
    }
    free(F);
    free(X);
    free(B);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

/* Three Gauss-Seidel sweeps written out here, element by element along
 * the rows of F, against the solver's blocked sweeps down the columns
 * (rad_solve stops after max_iterations with B the last iterate).  Three
 * sweeps of sums of n terms each: round-off 3 gamma_n max|B| (Higham 2002,
 * eq. 3.5), plus 2 eps for the reciprocal entries the solver reads. */
static void test_gauss_seidel_blocks(void)
{
    rad_scene s;
    rad_mesh m;
    rad_error err;
    rad_solve_options o;
    cube(14, goral_materials, goral, &s, &m); /* 1176 elements: two blocks of 1024 */
    const int n = m.nelements;
    const size_t n3 = (size_t)n * 3;
    double *F = form_factors(&m, RAD_ACCURACY_DEFAULT);
    double *X = malloc(sizeof *X * n3), *B = malloc(sizeof *B * n3);
    for (size_t k = 0; k < n3; k++)
        X[k] = m.elements[k % n].emit[k / n];
    for (int sweep = 0; sweep < 3; sweep++)
        for (int i = 0; i < n; i++)
            for (int b = 0; b < 3; b++) {
                double h = 0;
                for (int j = 0; j < n; j++)
                    h += F[i + (size_t)j * n] * X[j + (size_t)b * n];
                X[i + (size_t)b * n] = m.elements[i].emit[b] + m.elements[i].reflect[b] * h;
            }
    rad_solve_options_init(&o);
    o.solver = RAD_SOLVER_GAUSS_SEIDEL;
    o.max_iterations = 3;
    rad_status st = rad_solve(&m, F, &o, B, NULL, &err);
    const double e = rel_err(B, X, n3), tol = 3 * (n + 2) * DBL_EPSILON;
    tap_ok(st == RAD_ERR_NOCONV && e <= tol,
           "gauss-seidel in blocks of columns = element by element along rows, 3 sweeps "
           "(%.3g <= %.3g)", e, tol);
    free(F);
    free(X);
    free(B);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

/* Two facing unit squares 1 apart (F from Howell C-11 within 1e-9). */
static double *two_squares(const char *materials, rad_scene *s, rad_mesh *m)
{
    char text[512];
    rad_error err;
    snprintf(text, sizeof text, "%squad l 0 0 0  1 0 0  1 1 0  0 1 0\n"
                                "quad w 0 0 1  0 1 1  1 1 1  1 0 1\n", materials);
    rad_scene_parse(s, text, strlen(text), "two", &err);
    rad_mesh_build(m, s, &err);
    return form_factors(m, RAD_ACCURACY_REFERENCE);
}

static void test_cholesky_fallbacks(void)
{
    static const char *const w6[6] = {"w", "w", "w", "w", "w", "w"};
    rad_scene s;
    rad_mesh m;
    rad_error err;
    rad_solve_options o;
    rad_solve_report rep;
    double B[6], G[6];
    rad_solve_options_init(&o);
    o.solver = RAD_SOLVER_CHOLESKY;
    /* open pair with rho = 1: K = [1 -F; -F 1] is positive definite */
    double *F = two_squares("material l reflect 1 emit 1\nmaterial w reflect 1\n", &s, &m);
    const double f = F[1];
    rad_status st = rad_solve(&m, F, &o, B, &rep, &err);
    tap_ok(st == RAD_OK && rep.fallbacks == 0, "cholesky: open pair, rho = 1, positive definite");
    tap_close(B[0], 1 / (1 - f * f), 1e-14, "cholesky, open rho = 1: B1 = 1/(1 - F^2)");
    tap_close(B[1], f / (1 - f * f), 1e-14, "cholesky, open rho = 1: B2 = F/(1 - F^2)");
    /* F_12 = F_21 = 1.5 (not a form factor; reciprocal, equal areas), rho
     * = 0.9: K = [1 -1.35; -1.35 1] has eigenvalue -0.35; M = K is not
     * singular: B1 = 1 / (1 - 1.35^2), B2 = 1.35 B1 */
    rad_mesh_free(&m);
    rad_scene_free(&s);
    free(F);
    F = two_squares("material l reflect 0.9 emit 1\nmaterial w reflect 0.9\n", &s, &m);
    F[2] = F[1] = 1.5;
    st = rad_solve(&m, F, &o, B, &rep, &err);
    tap_ok(st == RAD_OK && rep.fallbacks == 1 && strstr(rep.fallback, "not positive definite"),
           "F_12 = 1.5: not positive definite, LU instead (%s)", rep.fallback);
    tap_close(B[0], 1 / (1 - 1.35 * 1.35), 1e-14, "F_12 = 1.5: B1 = 1/(1 - 1.35^2) by LU");
    tap_close(B[1], 1.35 / (1 - 1.35 * 1.35), 1e-14, "F_12 = 1.5: B2 = 1.35 B1 by LU");
    /* not reciprocal: LU, the same B as gauss bit for bit (the same code) */
    F[2] = 1.5 * (1 + 1e-9);
    st = rad_solve(&m, F, &o, B, &rep, &err);
    rad_solve_options_init(&o);
    rad_solve(&m, F, &o, G, NULL, &err);
    tap_ok(st == RAD_OK && rep.fallbacks == 1 && strstr(rep.fallback, "not reciprocal") &&
               memcmp(B, G, sizeof B) == 0,
           "F not reciprocal to 1e-9: LU, equal to gauss (%s)", rep.fallback);
    rad_mesh_free(&m);
    rad_scene_free(&s);
    free(F);
    /* closed box, rho = 1: singular, whichever way it is found */
    cube(3, "material w reflect 1 emit 1\n", w6, &s, &m);
    F = form_factors(&m, RAD_ACCURACY_DEFAULT);
    double *Bc = malloc(sizeof *Bc * 3 * (size_t)m.nelements);
    o.solver = RAD_SOLVER_CHOLESKY;
    st = rad_solve(&m, F, &o, Bc, &rep, &err);
    tap_ok(st == RAD_ERR_SINGULAR && strstr(err.message, "singular"),
           "cholesky, closed box, rho = 1: singular (%s%s%s)", err.message,
           rep.fallbacks ? "; " : "", rep.fallback);
    rad_mesh_free(&m);
    rad_scene_free(&s);
    /* furnace, rho = 0.5: B = E / (1 - rho) = 2, as gauss's test */
    cube(3, "material w reflect 0.5 emit 1\n", w6, &s, &m);
    st = rad_solve(&m, F, &o, Bc, &rep, &err);
    double dev = fmax(fabs(rep.row_sum_max - 1), fabs(rep.row_sum_min - 1)), worst = 0;
    for (int k = 0; k < 3 * m.nelements; k++)
        worst = fmax(worst, fabs(Bc[k] - 2));
    tap_ok(st == RAD_OK && rep.systems == 1 && worst <= 2 * dev + 1e-14,
           "cholesky furnace: B = 2 (worst %.3g), one factorisation", worst);
    free(Bc);
    free(F);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

/* The bound from F's error: cholesky estimates ||(I - rho F)^-1||_inf with
 * dlacn2 through its factor; here it is computed exactly (the inverse, in
 * long double, column by column).  Hager-Higham's estimate never exceeds
 * the norm and is exact for a matrix with entries >= 0 (Higham 2002,
 * section 15.3), which M^-1 is (M is an M-matrix: I minus a non-negative
 * matrix of norm < 1). */
static void test_cholesky_ff_bound(void)
{
    rad_scene s;
    rad_mesh m;
    rad_error err;
    rad_solve_options o;
    rad_solve_report rep;
    cube(3, goral_materials, goral, &s, &m);
    const int n = m.nelements;
    double *F = form_factors(&m, RAD_ACCURACY_DEFAULT);
    double *B = malloc(sizeof *B * (size_t)n * 3), *rowsum = calloc((size_t)n, sizeof *rowsum);
    long double *A = malloc(sizeof *A * (size_t)n * n), *x = malloc(sizeof *x * (size_t)n);
    double worst = 0; /* max over bands of rho_max ||M^-1||_inf */
    for (int b = 0; b < 3; b++) {
        double rmax = 0;
        memset(rowsum, 0, sizeof *rowsum * (size_t)n);
        for (int c = 0; c < n; c++) { /* column c of M^-1 */
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++)
                    A[(size_t)i * n + j] = (i == j) - (long double)m.elements[i].reflect[b] *
                                                          F[i + (size_t)j * n];
                x[i] = i == c;
            }
            ge_solve(n, A, x);
            for (int i = 0; i < n; i++)
                rowsum[i] += fabs((double)x[i]);
        }
        for (int i = 0; i < n; i++)
            rmax = fmax(rmax, m.elements[i].reflect[b]);
        double ninv = 0;
        for (int i = 0; i < n; i++)
            ninv = fmax(ninv, rowsum[i]);
        worst = fmax(worst, rmax * ninv);
    }
    rad_solve_options_init(&o);
    o.solver = RAD_SOLVER_CHOLESKY;
    o.ff_row_error = 1e-6;
    rad_status st = rad_solve(&m, F, &o, B, &rep, &err);
    const double k = worst * 1e-6, want = k / (1 - k);
    tap_ok(st == RAD_OK, "cholesky with the bound from F's error");
    tap_close(rep.ff_error_bound, want, 1e-9,
              "cholesky: F's error bound = k/(1-k), k = rho_max ||dF|| ||M^-1||, exact inverse");
    free(F);
    free(B);
    free(rowsum);
    free(A);
    free(x);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

/* Conjugate gradients where the symmetric form does not apply: the whole
 * solve goes to cholesky (and on to LU), and the report says why. */
static void test_cg_fallbacks(void)
{
    static const char *const w6[6] = {"w", "w", "w", "w", "w", "w"};
    rad_scene s;
    rad_mesh m;
    rad_error err;
    rad_solve_options o;
    rad_solve_report rep;
    double B[6];
    rad_solve_options_init(&o);
    o.solver = RAD_SOLVER_CG;
    /* open pair, rho = 1: q = F < 1, CG converges; closed forms as above */
    double *F = two_squares("material l reflect 1 emit 1\nmaterial w reflect 1\n", &s, &m);
    const double f = F[1];
    rad_status st = rad_solve(&m, F, &o, B, &rep, &err);
    tap_ok(st == RAD_OK && rep.fallbacks == 0 && rep.error_bound <= 1e-12,
           "cg: open pair, rho = 1, %d iterations, bound %.3g", rep.sweeps, rep.error_bound);
    tap_close(B[0], 1 / (1 - f * f), 1e-12 + 1e-14, "cg, open rho = 1: B1 = 1/(1 - F^2)");
    tap_close(B[1], f / (1 - f * f), 1e-12 / f + 1e-14, "cg, open rho = 1: B2 = F/(1 - F^2)");
    F[2] *= 1 + 1e-9; /* not reciprocal */
    st = rad_solve(&m, F, &o, B, &rep, &err);
    tap_ok(st == RAD_OK && rep.fallbacks == 2 && strstr(rep.fallback, "cg: F is not reciprocal") &&
               strstr(rep.fallback, "solved by LU"),
           "cg, F not reciprocal: cholesky, then LU (%s)", rep.fallback);
    rad_mesh_free(&m);
    rad_scene_free(&s);
    free(F);
    cube(3, "material w reflect 1 emit 1\n", w6, &s, &m);
    F = form_factors(&m, RAD_ACCURACY_DEFAULT);
    double *Bc = malloc(sizeof *Bc * 3 * (size_t)m.nelements);
    st = rad_solve(&m, F, &o, Bc, &rep, &err);
    tap_ok(st == RAD_ERR_SINGULAR && strstr(rep.fallback, ">= 1 bounds no error"),
           "cg, closed box, rho = 1: no bound, cholesky says singular (%s)", rep.fallback);
    free(Bc);
    free(F);
    rad_mesh_free(&m);
    rad_scene_free(&s);
}

int main(void)
{
    test_blocked_lu();
    for (int nm = 1; nm <= 7; nm++)
        test_cube_exact(nm);
    test_solvers_and_bounces();
    test_mirror();
    test_furnace_and_singular();
    test_all_solvers_exact();
    test_gauss_seidel_blocks();
    test_cholesky_fallbacks();
    test_cholesky_ff_bound();
    test_cg_fallbacks();
    return tap_done();
}
