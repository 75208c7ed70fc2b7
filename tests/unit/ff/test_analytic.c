/* test_analytic.c -- checks of the closed-form form factors (analytic.c).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Every expected value here is computed independently of analytic.c:
 *
 *   (a) published values: Howell's catalogue tables and closed forms that
 *       reduce to elementary constants at special arguments;
 *   (b) the textbook formulas as printed, evaluated in long double (64-bit
 *       mantissa, eps_ld = 1.08e-19), each together with a rounding-error
 *       bound from the sizes of the terms it subtracts.  Such a reference is
 *       used only where that bound is below 1e-15, i.e. where its
 *       cancellation is mild; elsewhere
 *   (c) other long-double references valid in that regime: the Catalan
 *       series of the disk-disk quadratic, a series of the area-area kernel
 *       for thin rectangles, a one-dimensional integral of the kernel for
 *       perpendicular rectangles, and asymptotic limits with their leading
 *       corrections;
 *   (d) identities: reciprocity, symmetry;
 *   (e) Gauss-Legendre quadrature of the area-area kernel
 *       cos t1 cos t2 / (pi r^2) in long double for moderate geometries.
 *
 * The required accuracy of analytic.c is 1e-13 relative for all positive
 * finite parameters (absolute 1e-13 DBL_MIN where F is subnormal): the
 * sweeps below cover 1e-4..1e4 with the references above and
 * 1e-300..1e300 with limits (test_wide_range); tests/analytic.py compares
 * a denser grid with mpmath.  Every comparison states where its tolerance comes from.  The
 * sweeps print one TAP line each (the worst point) and a diagnostic line for
 * every failing point.
 */
#include "radiosity/formfactor.h"
#include "../tap.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

typedef long double ld;

#define PI_L 3.141592653589793238462643383279502884L
#define EPS_L LDBL_EPSILON

/* The accuracy analytic.c promises. */
#define TOL 1e-13
/* A reference is used for the 1e-13 check only if its own error bound is
 * below this: then a failure cannot be the reference's fault. */
#define REF_TRUST 1e-15L

/* Parameters of the sweeps: 1e-4, 1e-3, ..., 1e4. */
#define NGRID 9
static const double grid[NGRID] = {1e-4, 1e-3, 1e-2, 1e-1, 1.0,
                                   1e1,  1e2,  1e3,  1e4};

/* A reference value and a bound on its relative error (HUGE_VALL: none). */
typedef struct ref {
    ld value;
    ld bound;
} ref;

static ref no_ref(void)
{
    ref r = {0.0L, HUGE_VALL};
    return r;
}

static ref better(ref a, ref b)
{
    return a.bound <= b.bound ? a : b;
}

static ld rel_err(double got, ld want)
{
    return fabsl((ld)got - want) / fabsl(want);
}

/* ---- sweep bookkeeping --------------------------------------------------- */

typedef struct sweep {
    const char *what;
    int points;       /* compared */
    int skipped;      /* no trustworthy reference */
    int failed;
    double worst;
    double at[3];
} sweep;

static void sweep_add(sweep *s, double got, ref want, double tol, double p,
                      double q, double r)
{
    double err;
    if (!(want.bound <= REF_TRUST)) {
        s->skipped++;
        tap_diag("%s: no trustworthy reference at (%g, %g, %g)", s->what, p, q,
                 r);
        return;
    }
    err = (double)rel_err(got, want.value);
    if (!isfinite(got))
        err = HUGE_VAL;
    s->points++;
    if (err > s->worst || s->points == 1) {
        s->worst = err;
        s->at[0] = p;
        s->at[1] = q;
        s->at[2] = r;
    }
    if (!(err <= tol)) {
        s->failed++;
        tap_diag("%s: at (%g, %g, %g) got %.17g want %.20Lg (rel err %.3g)",
                 s->what, p, q, r, got, want.value, err);
    }
}

static void sweep_done(const sweep *s, double tol, int allow_skips)
{
    tap_ok(s->points > 0 && s->failed == 0 && (allow_skips || !s->skipped),
           "%s: %d points, %d without reference, worst rel err %.3g at "
           "(%g, %g, %g), tol %.0e",
           s->what, s->points, s->skipped, s->worst, s->at[0], s->at[1],
           s->at[2], tol);
}

/* ---- Gauss-Legendre in long double --------------------------------------- */

#define GL_MAX 96

typedef struct gauss {
    int n;
    ld x[GL_MAX], w[GL_MAX];  /* nodes and weights on [-1, 1] */
} gauss;

/* Nodes by Newton's method on P_n (three-term recurrence), weights
 * 2 / ((1 - x^2) P_n'(x)^2) (Abramowitz & Stegun 25.4.29).  Newton from the
 * Tricomi estimate cos(pi (i - 1/4) / (n + 1/2)) converges to every root. */
static void gauss_init(gauss *g, int n)
{
    int i, it, k;
    g->n = n;
    for (i = 0; i < n; i++) {
        ld x = cosl(PI_L * (i + 0.75L) / (n + 0.5L)), dp = 1.0L;
        for (it = 0; it < 100; it++) {
            ld p0 = 1.0L, p1 = x, dx;
            for (k = 2; k <= n; k++) {
                const ld p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1.0L);
            dx = p1 / dp;
            x -= dx;
            if (fabsl(dx) <= 4 * EPS_L)
                break;
        }
        g->x[i] = x;
        g->w[i] = 2.0L / ((1.0L - x * x) * dp * dp);
    }
}

/* Node i and weight mapped to [a, b]. */
static ld gauss_node(const gauss *g, int i, ld a, ld b)
{
    return 0.5L * (a + b) + 0.5L * (b - a) * g->x[i];
}

static ld gauss_weight(const gauss *g, int i, ld a, ld b)
{
    return 0.5L * (b - a) * g->w[i];
}

/* ---- point to disk --------------------------------------------------------- */

/* Textbook ([SH] App. C): F = r^2 / (h^2 + r^2); no subtraction, so the
 * long-double value is good to a few eps_ld. */
static ref point_disk_textbook(double r, double h)
{
    ref f;
    const ld r2 = (ld)r * r, h2 = (ld)h * h;
    f.value = r2 / (h2 + r2);
    f.bound = 8 * EPS_L;
    return f;
}

/* Area-area (here point-area) kernel integrated by Gauss-Legendre:
 * F = int_0^r 2 rho h^2 / (h^2 + rho^2)^2 d rho (the disk in rings). */
static ld point_disk_quadrature(const gauss *g, double r, double h)
{
    ld s = 0.0L;
    int i;
    for (i = 0; i < g->n; i++) {
        const ld rho = gauss_node(g, i, 0, r);
        const ld d = (ld)h * h + rho * rho;
        s += gauss_weight(g, i, 0, r) * 2 * rho * (ld)h * h / (d * d);
    }
    return s;
}

static void test_point_disk(void)
{
    sweep s = {"point-disk vs long double textbook", 0, 0, 0, 0, {0, 0, 0}};
    gauss g32, g64;
    int i, j;
    /* r = h: half of the hemisphere's projected area, exactly 1/2. */
    tap_close(rad_analytic_point_disk(1.0, 1.0), 0.5, 2 * DBL_EPSILON,
              "point-disk r = h is 1/2 (2 ulp: one division)");
    for (i = 0; i < NGRID; i++)
        for (j = 0; j < NGRID; j++)
            sweep_add(&s, rad_analytic_point_disk(grid[i], grid[j]),
                      point_disk_textbook(grid[i], grid[j]), TOL, grid[i],
                      grid[j], 0);
    sweep_done(&s, TOL, 0);

    /* Quadrature: the integrand is analytic with poles at rho = +-i h, a
     * distance >= h/r (relative to the interval) from [0, r]; 64 nodes
     * leave an error far below 1e-18 for r/h <= 2, and the 32- vs 64-node
     * difference (checked) bounds the error of the 32-node rule. */
    gauss_init(&g32, 32);
    gauss_init(&g64, 64);
    {
        static const double cases[][2] = {{1, 1}, {0.5, 1}, {2, 1}, {1.3, 0.7}};
        for (i = 0; i < 4; i++) {
            const double r = cases[i][0], h = cases[i][1];
            const ld q = point_disk_quadrature(&g64, r, h);
            const ld q32 = point_disk_quadrature(&g32, r, h);
            const double err = (double)rel_err(rad_analytic_point_disk(r, h), q);
            tap_ok(fabsl(q - q32) <= 1e-16L * q && err <= TOL,
                   "point-disk r=%g h=%g vs Gauss-Legendre: rel err %.3g "
                   "(quadrature converged to %.1Le), tol %.0e",
                   r, h, err, fabsl(q - q32) / q, TOL);
        }
    }
}

/* ---- disk to disk ----------------------------------------------------------- */

/* Textbook ([SH] App. C): R1 = r1/h, R2 = r2/h, X = 1 + (1 + R2^2)/R1^2,
 * F = (X - sqrt(X^2 - 4 (R2/R1)^2)) / 2.  Rounding: the discriminant has an
 * absolute error <= 8 eps X^2, which moves the square root by
 * 4 eps X^2 / sqrt(disc); the final subtraction adds eps X.  The bound
 * below is that sum (doubled) over F. */
static ref disk_disk_textbook(double r1, double r2, double h)
{
    ref f = no_ref();
    const ld R1 = (ld)r1 / h, R2 = (ld)r2 / h;
    const ld X = 1.0L + (1.0L + R2 * R2) / (R1 * R1);
    const ld q = R2 / R1;
    const ld disc = X * X - 4.0L * q * q;
    ld root;
    if (!(disc > 0))
        return f;
    root = sqrtl(disc);
    f.value = 0.5L * (X - root);
    f.bound = EPS_L * (4 * X + 16 * X * X / root + 2 * root) / f.value;
    return f;
}

/* The textbook F is the smaller root of r1^2 F^2 - S F + r2^2 = 0
 * (S = h^2 + r1^2 + r2^2), i.e. F = (r2^2/S) C(z) with z = r1^2 r2^2 / S^2
 * <= 1/4 and C(z) = (1 - sqrt(1 - 4z)) / (2z) = sum_k Cat_k z^k, the
 * generating function of the Catalan numbers (Cat_{k+1} = Cat_k
 * 2(2k+1)/(k+2)).  Positive terms only: no cancellation.  Used for
 * z <= 0.2, where the terms fall at least like 0.8^k; the sum stops when a
 * term is below 1e-21 of it (the tail is then below 4e-21), and the
 * rounding error grows at most like 3 eps_ld per term. */
static ref disk_disk_catalan(double r1, double r2, double h)
{
    ref f = no_ref();
    const ld a = (ld)r1 * r1, b = (ld)r2 * r2;
    const ld S = (ld)h * h + a + b;
    const ld z = (a / S) * (b / S);
    ld term = 1.0L, sum = 1.0L;
    int k;
    if (z > 0.2L)
        return f;
    for (k = 0; k < 1000 && term > 1e-21L * sum; k++) {
        term *= z * 2 * (2 * k + 1) / (k + 2);
        sum += term;
    }
    f.value = b / S * sum;
    f.bound = 3 * (k + 4) * EPS_L + 5e-21L;
    return f;
}

/* Equal disks nearly touching, t = h/r -> 0: the textbook formula gives
 * F = 1 - t + t^2/2 - t^3/8 + O(t^5) (Taylor series; the t^4 coefficient
 * is 0, the t^5 one is 1/128).  The first-order term is also the
 * enclosure argument: everything disk 1 loses leaves through the gap band
 * (area 2 pi r h), which sees disk 1 with factor 1/2, so by reciprocity
 * 1 - F = 2 pi r h (1/2) / (pi r^2) = t.  Used for t <= 1.5e-3 (bound
 * t^5/100 < 1e-16). */
static ref disk_disk_touching(double r1, double r2, double h)
{
    ref f = no_ref();
    const ld t = (ld)h / r1;
    if (r1 != r2 || t > 1.5e-3L)
        return f;
    f.value = 1.0L - t + t * t / 2 - t * t * t / 8;
    f.bound = t * t * t * t * t / 100 + 4 * EPS_L;
    return f;
}

/* Kernel h^2 / (pi (h^2 + d^2)^2) for parallel coaxial disks, d^2 =
 * rho1^2 + rho2^2 - 2 rho1 rho2 cos(theta); by symmetry
 * F = (2 / r1^2) int rho1 int rho2 int_0^pi 2 h^2/(pi (h^2+d^2)^2). */
static ld disk_disk_quadrature(const gauss *g, double r1, double r2, double h)
{
    const ld h2 = (ld)h * h;
    ld s = 0.0L;
    int i, j, k;
    for (i = 0; i < g->n; i++) {
        const ld p1 = gauss_node(g, i, 0, r1), w1 = gauss_weight(g, i, 0, r1);
        for (j = 0; j < g->n; j++) {
            const ld p2 = gauss_node(g, j, 0, r2);
            const ld w2 = gauss_weight(g, j, 0, r2);
            ld t = 0.0L;
            for (k = 0; k < g->n; k++) {
                const ld th = gauss_node(g, k, 0, PI_L);
                const ld d = h2 + p1 * p1 + p2 * p2 - 2 * p1 * p2 * cosl(th);
                t += gauss_weight(g, k, 0, PI_L) / (d * d);
            }
            s += w1 * w2 * p1 * p2 * t;
        }
    }
    return s * 4 * h2 / (PI_L * (ld)r1 * r1);
}

static void test_disk_disk(void)
{
    sweep s = {"disk-disk vs long double references", 0, 0, 0, 0, {0, 0, 0}};
    sweep recip = {"disk-disk reciprocity r1^2 F12 = r2^2 F21", 0, 0, 0, 0,
                   {0, 0, 0}};
    gauss g24, g40;
    int i, j, k;

    /* Equal disks, r = h: X = 3, F = (3 - sqrt 5)/2 ([SH] App. C; Howell's
     * table gives 0.382).  Long double is exact to 1e-19 here. */
    tap_close(rad_analytic_disk_disk(1, 1, 1), (double)((3 - sqrtl(5)) / 2),
              TOL, "disk-disk r1 = r2 = h: (3 - sqrt 5)/2");
    tap_ok(fabs(rad_analytic_disk_disk(1, 1, 1) - 0.382) < 5e-4,
           "disk-disk r1 = r2 = h matches the tabulated 0.382");

    for (i = 0; i < NGRID; i++)
        for (j = 0; j < NGRID; j++)
            for (k = 0; k < NGRID; k++) {
                const double r1 = grid[i], r2 = grid[j], h = grid[k];
                const ref want = better(
                    better(disk_disk_textbook(r1, r2, h),
                           disk_disk_catalan(r1, r2, h)),
                    disk_disk_touching(r1, r2, h));
                const double f12 = rad_analytic_disk_disk(r1, r2, h);
                const double f21 = rad_analytic_disk_disk(r2, r1, h);
                /* Reciprocity pi r1^2 F12 = pi r2^2 F21: both sides are a
                 * few roundings away from the same number; allow 8 ulps. */
                const ref via21 = {(ld)r2 * r2 * f21 / ((ld)r1 * r1), 0};
                sweep_add(&s, f12, want, TOL, r1, r2, h);
                sweep_add(&recip, f12, via21, 8 * DBL_EPSILON, r1, r2, h);
            }
    sweep_done(&s, TOL, 0);
    sweep_done(&recip, 8 * DBL_EPSILON, 0);

    /* Limit r1 -> 0: disk 1 shrinks to its centre, F -> point-disk(r2, h);
     * from the Catalan form, F = P (1 - r1^2 h^2 / (h^2 + r2^2)^2) +
     * O(r1^4/(h^2+r2^2)^2) with P = r2^2/(h^2 + r2^2).  With r1 = 1e-4 and
     * h, r2 >= 1e-1 the neglected term is below 1e-12 * 1e-4 = 1e-16. */
    {
        sweep lim = {"disk-disk r1 -> 0 tends to point-disk (with correction)",
                     0, 0, 0, 0, {0, 0, 0}};
        const double r1 = 1e-4;
        for (j = 3; j < NGRID; j++)
            for (k = 3; k < NGRID; k++) {
                const ld r2 = grid[j], h = grid[k];
                const ld A = h * h + r2 * r2;
                const ref want = {r2 * r2 / A * (1 - (ld)r1 * r1 * h * h / (A * A)),
                                  1e-16L};
                sweep_add(&lim, rad_analytic_disk_disk(r1, grid[j], grid[k]),
                          want, TOL, r1, grid[j], grid[k]);
                /* and the point-disk function itself agrees with P: */
                sweep_add(&lim,
                          rad_analytic_point_disk(grid[j], grid[k]),
                          (ref){r2 * r2 / A, 8 * EPS_L}, TOL, 0, grid[j],
                          grid[k]);
            }
        sweep_done(&lim, TOL, 0);
    }

    /* Far field h >> r1, r2: F -> A2 / (pi h^2) = r2^2/h^2, and with the
     * leading correction F = (r2^2/h^2)(1 - (r1^2 + r2^2)/h^2) + O(r^4/h^4)
     * (again from the Catalan form, C(z) = 1 + O(r^4/h^4)).  With
     * h = 1e4 and r1, r2 <= 1 the neglected part is below 1e-15. */
    {
        sweep far = {"disk-disk far field r2^2/h^2 (1 - (r1^2+r2^2)/h^2)", 0,
                     0, 0, 0, {0, 0, 0}};
        const ld h = 1e4L;
        for (i = 0; i <= 4; i++)
            for (j = 0; j <= 4; j++) {
                const ld r1 = grid[i], r2 = grid[j];
                const ref want = {r2 * r2 / (h * h) *
                                      (1 - (r1 * r1 + r2 * r2) / (h * h)),
                                  1e-15L};
                sweep_add(&far, rad_analytic_disk_disk(grid[i], grid[j], 1e4),
                          want, TOL, grid[i], grid[j], 1e4);
            }
        sweep_done(&far, TOL, 0);
    }

    /* Quadrature of the kernel for moderate geometries.  Poles of the
     * integrand lie at complex distance ~ h from the real box; 40 nodes
     * per dimension converge to ~1e-18 for h >= r/2 (checked against 24). */
    gauss_init(&g24, 24);
    gauss_init(&g40, 40);
    {
        static const double cases[][3] = {
            {1, 1, 1}, {0.5, 1, 1}, {1, 2, 1.5}, {1, 0.7, 0.8}};
        for (i = 0; i < 4; i++) {
            const double r1 = cases[i][0], r2 = cases[i][1], h = cases[i][2];
            const ld q = disk_disk_quadrature(&g40, r1, r2, h);
            const ld q24 = disk_disk_quadrature(&g24, r1, r2, h);
            const double err =
                (double)rel_err(rad_analytic_disk_disk(r1, r2, h), q);
            tap_ok(fabsl(q - q24) <= 1e-15L * q && err <= TOL,
                   "disk-disk r1=%g r2=%g h=%g vs Gauss-Legendre: rel err "
                   "%.3g (24 vs 40 nodes differ by %.1Le), tol %.0e",
                   r1, r2, h, err, fabsl(q - q24) / q, TOL);
        }
    }
}

/* ---- parallel rectangles ------------------------------------------------------ */

/* Textbook ([H] C-11) with X = a/c, Y = b/c, evaluated as printed.  Each
 * of the five terms carries a relative rounding error of a few eps_ld; the
 * logarithm of a quotient near 1 also an absolute one of a few eps_ld; the
 * bound is 16 eps_ld (1 + sum |terms|) / bracket. */
static ref parallel_textbook(double a, double b, double c)
{
    ref f = no_ref();
    const ld X = (ld)a / c, Y = (ld)b / c, X2 = X * X, Y2 = Y * Y;
    const ld sx = sqrtl(1 + X2), sy = sqrtl(1 + Y2);
    const ld t0 = 0.5L * logl((1 + X2) * (1 + Y2) / (1 + X2 + Y2));
    const ld t1 = X * sy * atanl(X / sy), t2 = Y * sx * atanl(Y / sx);
    const ld t3 = X * atanl(X), t4 = Y * atanl(Y);
    const ld br = t0 + t1 + t2 - t3 - t4;
    if (!(br > 0))
        return f;
    f.value = 2 * br / (PI_L * X * Y);
    f.bound = 16 * EPS_L * (1 + fabsl(t0) + t1 + t2 + t3 + t4) / br;
    return f;
}

/* integral_0^T cos^m(t) dt for m = 0..mmax by the reduction formula
 * I_m = cos^(m-1) T sin T / m + (m-1)/m I_(m-2) (positive terms). */
static void cos_power_integrals(ld T, int mmax, ld *I)
{
    const ld s = sinl(T), c = cosl(T);
    ld cpow = 1.0L;  /* cos^(m-1) T */
    int m;
    I[0] = T;
    if (mmax >= 1)
        I[1] = s;
    for (m = 2; m <= mmax; m++) {
        cpow = m == 2 ? c : cpow * c;
        I[m] = cpow * s / m + (ld)(m - 1) / m * I[m - 2];
    }
}

/* Thin rectangles, from the kernel itself.  With c = 1 and the x and y
 * differences u, v (convolution of the two rectangles):
 *   F = 4/(pi X Y) int_0^X int_0^Y (X-u)(Y-v) / (1+u^2+v^2)^2 dv du.
 * Expanding 1/(1+u^2+v^2)^2 = sum_k (-1)^k (k+1) v^2k / (1+u^2)^(k+2)
 * (valid for v < 1), integrating v exactly and substituting u = tan t:
 *   F = 2/(pi X) sum_k (-1)^k Y^(2k+1) K_k / (2k+1),
 *   K_k = X I_(2k+2)(T) - (1 - cos^(2k+2) T) / (2k+2),  T = atan X,
 * I_m as in cos_power_integrals.  K_k > 0 and loses at most a factor 2 to
 * cancellation; the alternating series falls at least like Y^2.  Used for
 * Y <= 1/2: terms stop below 1e-22 of the sum; rounding ~ 8 eps_ld per
 * term in K_k, 16 eps_ld bound per term overall. */
#define THIN_TERMS 60
static ref parallel_thin(double a, double b, double c)
{
    ref f = no_ref();
    const ld X = (ld)a / c, Y = (ld)b / c;
    const ld T = atanl(X);
    ld I[2 * THIN_TERMS + 3];
    ld sum = 0.0L, abs_sum = 0.0L, ypow = Y;
    int k;
    if (Y > 0.5L)
        return f;
    cos_power_integrals(T, 2 * THIN_TERMS + 2, I);
    for (k = 0; k < THIN_TERMS; k++) {
        const ld one_minus = -expm1l(-(k + 1) * log1pl(X * X));
        const ld K = X * I[2 * k + 2] - one_minus / (2 * k + 2);
        const ld term = ypow * K / (2 * k + 1);
        sum += (k % 2 ? -term : term);
        abs_sum += term;
        if (term < 1e-22L * fabsl(sum))
            break;
        ypow *= Y * Y;
    }
    if (k == THIN_TERMS || !(sum > 0))
        return f;
    f.value = 2 * sum / (PI_L * X);
    f.bound = 16 * EPS_L * abs_sum / sum * 2 + 1e-21L;
    return f;
}

/* F is symmetric in a and b; the thin reference wants the thin side second. */
static ref parallel_reference(double a, double b, double c)
{
    return better(parallel_textbook(a, b, c),
                  better(parallel_thin(a, b, c), parallel_thin(b, a, c)));
}

/* F = 4/(pi a b) int_0^a int_0^b (a-u)(b-v) c^2 / (c^2+u^2+v^2)^2: the
 * kernel cos t1 cos t2/(pi r^2) = c^2/(pi r^4) convolved over both
 * rectangles (exact reduction of the 4-D integral to 2-D). */
static ld parallel_quadrature(const gauss *g, double a, double b, double c)
{
    const ld c2 = (ld)c * c;
    ld s = 0.0L;
    int i, j;
    for (i = 0; i < g->n; i++) {
        const ld u = gauss_node(g, i, 0, a), wu = gauss_weight(g, i, 0, a);
        for (j = 0; j < g->n; j++) {
            const ld v = gauss_node(g, j, 0, b), wv = gauss_weight(g, j, 0, b);
            const ld d = c2 + u * u + v * v;
            s += wu * wv * (a - u) * (b - v) / (d * d);
        }
    }
    return 4 * c2 * s / (PI_L * (ld)a * b);
}

static void test_parallel(void)
{
    sweep s = {"parallel rectangles vs long double references", 0, 0, 0, 0,
               {0, 0, 0}};
    sweep agree = {"parallel: textbook and thin-series references agree", 0, 0,
                   0, 0, {0, 0, 0}};
    sweep close = {"parallel c -> 0: 1 - 1/X - 1/Y + (2/(pi X Y))(...)", 0, 0,
                   0, 0, {0, 0, 0}};
    sweep far = {"parallel c -> inf: (XY/pi)(1 - (X^2+Y^2)/3 + ...)", 0, 0, 0,
                 0, {0, 0, 0}};
    gauss g32, g48;
    int i, j, k;

    /* Unit squares one apart.  [H] C-11 tabulates 0.1998; at X = Y = 1 the
     * formula reduces to (2/pi)(ln(4/3)/2 + 2 sqrt2 atan(1/sqrt2) - pi/2),
     * evaluated here in long double (terms 0.14, 1.74, 1.57: cond ~ 10). */
    {
        const ld exact = 2 / PI_L *
                         (0.5L * logl(4.0L / 3) +
                          2 * sqrtl(2) * atanl(1 / sqrtl(2)) - PI_L / 2);
        const double f = rad_analytic_parallel_rectangles(1, 1, 1);
        tap_close(f, (double)exact, TOL, "parallel unit squares, 1 apart");
        tap_ok(fabs(f - 0.1998) < 5e-5,
               "parallel unit squares match the tabulated 0.1998");
        /* The often quoted 0.19982489569838746 is the textbook formula in
         * double; the true value is 0.199824895698387383..., 4e-16 away. */
        tap_close(f, 0.19982489569838746, TOL,
                  "parallel unit squares vs 0.19982489569838746");
    }

    for (i = 0; i < NGRID; i++)
        for (j = 0; j < NGRID; j++)
            for (k = 0; k < NGRID; k++) {
                const double a = grid[i], b = grid[j], c = grid[k];
                const ref tb = parallel_textbook(a, b, c);
                const ref th = better(parallel_thin(a, b, c),
                                      parallel_thin(b, a, c));
                sweep_add(&s, rad_analytic_parallel_rectangles(a, b, c),
                          parallel_reference(a, b, c), TOL, a, b, c);
                /* the two references check each other where both hold */
                if (tb.bound <= REF_TRUST && th.bound <= REF_TRUST)
                    sweep_add(&agree, (double)th.value, tb, 1e-15, a, b, c);
            }
    sweep_done(&s, TOL, 0);
    sweep_done(&agree, 1e-15, 1);

    /* Nearly touching (X, Y = a/c, b/c >= 1e6): the textbook bracket is
     * pi XY/2 - pi (X+Y)/2 + ln(XY/R) + 3/2 + (rho atan rho + atan(1/rho)
     * /rho)/2 + O(1/X^2 + 1/Y^2 + X/Y^3 + Y/X^3), R^2 = X^2 + Y^2,
     * rho = X/Y (expanding sqrt(1+Y^2) = Y + 1/(2Y) and atan X = pi/2 -
     * 1/X in C-11).  The leading correction 1/X + 1/Y is also the enclosure
     * argument: the side gaps (area 2(a+b)c) see rectangle 1 with 1/2.
     * With X, Y in 1e6..1e8 the neglected part is below 1e-20. */
    for (i = 6; i < NGRID; i++)
        for (j = 6; j < NGRID; j++) {
            const double a = grid[i], b = grid[j], c = 1e-4;
            const ld X = (ld)a / c, Y = (ld)b / c, rho = X / Y;
            const ld R = sqrtl(X * X + Y * Y);
            const ld br = logl(X * Y / R) + 1.5L +
                          (rho * atanl(rho) + atanl(1 / rho) / rho) / 2;
            const ref want = {1 - 1 / X - 1 / Y + 2 * br / (PI_L * X * Y),
                              1e-18L};
            sweep_add(&close, rad_analytic_parallel_rectangles(a, b, c), want,
                      TOL, a, b, c);
        }
    sweep_done(&close, TOL, 0);
    tap_ok(rad_analytic_parallel_rectangles(1e4, 1e4, 1e-4) > 1 - 3e-8 &&
               rad_analytic_parallel_rectangles(1e4, 1e4, 1e-4) < 1,
           "parallel c -> 0 tends to 1 from below");

    /* Far apart (X, Y <= 1e-4): the kernel series above with the moments
     * E[(u_1-u_2)^2m] = 2 a^2m / ((2m+1)(2m+2)) gives
     * F = (XY/pi)(1 - (X^2+Y^2)/3 + (X^4+Y^4)/5 + X^2 Y^2/6 + O(X^6)):
     * the leading term is A2/(pi c^2).  Neglected: < 1e-23. */
    for (i = 0; i <= 4; i++)
        for (j = 0; j <= 4; j++) {
            const double a = grid[i], b = grid[j], c = 1e4;
            const ld X = (ld)a / c, Y = (ld)b / c, X2 = X * X, Y2 = Y * Y;
            const ref want = {X * Y / PI_L *
                                  (1 - (X2 + Y2) / 3 + (X2 * X2 + Y2 * Y2) / 5 +
                                   X2 * Y2 / 6),
                              1e-18L};
            sweep_add(&far, rad_analytic_parallel_rectangles(a, b, c), want,
                      TOL, a, b, c);
        }
    sweep_done(&far, TOL, 0);

    /* Quadrature (2-D after the exact convolution), c comparable to a, b:
     * poles at complex distance ~ c; 48 nodes converge to ~1e-18 (checked
     * against 32). */
    gauss_init(&g32, 32);
    gauss_init(&g48, 48);
    {
        static const double cases[][3] = {
            {1, 1, 1}, {2, 1, 1}, {1, 3, 2}, {0.7, 1.3, 1}};
        for (i = 0; i < 4; i++) {
            const double a = cases[i][0], b = cases[i][1], c = cases[i][2];
            const ld q = parallel_quadrature(&g48, a, b, c);
            const ld q32 = parallel_quadrature(&g32, a, b, c);
            const double err =
                (double)rel_err(rad_analytic_parallel_rectangles(a, b, c), q);
            tap_ok(fabsl(q - q32) <= 1e-15L * q && err <= TOL,
                   "parallel a=%g b=%g c=%g vs Gauss-Legendre: rel err %.3g "
                   "(32 vs 48 nodes differ by %.1Le), tol %.0e",
                   a, b, c, err, fabsl(q - q32) / q, TOL);
        }
    }
}

/* ---- perpendicular rectangles ---------------------------------------------------- */

/* Textbook ([H] C-14), W = w/l, H = h/l, as printed (powers and one
 * logarithm of their product).  Rounding: the product has a relative error
 * of about eps_ld (8 + 8 W^2 + 8 H^2 + |W^2 ln bw| + |H^2 ln bh|) (powl
 * multiplies the base's error by the exponent), which becomes an absolute
 * error of the logarithm; the atan terms carry a few eps_ld each. */
static ref perpendicular_textbook(double l, double w, double h)
{
    ref f = no_ref();
    const ld W = (ld)w / l, H = (ld)h / l, W2 = W * W, H2 = H * H;
    const ld R2 = W2 + H2, R = sqrtl(R2);
    const ld p1 = W * atanl(1 / W), p2 = H * atanl(1 / H), p3 = R * atanl(1 / R);
    const ld a0 = (1 + W2) * (1 + H2) / (1 + R2);
    const ld bw = W2 * (1 + R2) / ((1 + W2) * R2);
    const ld bh = H2 * (1 + R2) / ((1 + H2) * R2);
    const ld lg = 0.25L * logl(a0 * powl(bw, W2) * powl(bh, H2));
    const ld B = p1 + p2 - p3 + lg;
    const ld err_prod = 8 + 8 * W2 + 8 * H2 + fabsl(W2 * logl(bw)) +
                        fabsl(H2 * logl(bh));
    if (!(B > 0) || !isfinite(lg))
        return f;
    f.value = B / (PI_L * W);
    f.bound = 8 * EPS_L * (p1 + p2 + p3 + fabsl(lg) + err_prod) / B;
    return f;
}

/* The kernel cos t1 cos t2 / (pi r^2) = y z / (pi r^4) between
 * (x1, y, 0) on the l x w rectangle and (x2, 0, z) on the l x h one.  With
 * l = 1, the x-convolution (u = |x1 - x2|, weight 2(1 - u)) and the exact
 * z-integral int_0^H z/(q+z^2)^2 dz = H^2/(2q(q+H^2)), q = u^2 + y^2:
 *   F = H^2/(pi W) int_0^1 int_0^W (1-u) y / (q (q + H^2)) dy du.
 * In polar coordinates u = rho cos p, y = rho sin p the singularity at the
 * common edge disappears:
 *   F = H^2/(pi W) int_0^(pi/2) sin p int_0^P(p) (1 - rho cos p) /
 *       (rho^2 + H^2) d rho dp,    P = min(1/cos p, W/sin p),
 * and the rho-integral is elementary:
 *   G(p) = H atan(P/H) - (H^2 cos p / 2) log1p(P^2/H^2)
 *        = H^2 int_0^P (1 - rho cos p)/(rho^2 + H^2) d rho >= 0,
 * which loses at most a factor ~2 to cancellation (the weight 1 - rho
 * cos p >= 0 falls linearly).  F = (1/(pi W)) int_0^(pi/2) sin p G(p) dp,
 * split at the corner p0 = atan W.  P spans many decades when W or 1/W is
 * large, so both pieces are integrated in s = ln tan p (dp = ds tan p /
 * (1 + tan^2 p)), where the integrand is smooth and analytic, on panels one
 * decade of tan p wide with n Gauss-Legendre nodes each.  sin p and cos p
 * are formed from tan p. */
static ld perp_G(ld cos_p, ld P, ld H)
{
    return H * atanl(P / H) - H * H * cos_p / 2 * log1pl(P * P / (H * H));
}

/* int over p in [p_a, p_b] of sin p G(p) with P = 1/cos p (side u = 1)
 * or P = W/sin p (side y = W), on panels uniform in log tan p. */
static ld perp_piece(const gauss *g, ld W, ld H, ld ta, ld tb, int side_u)
{
    const ld la = logl(ta), lb = logl(tb);
    const int panels = 1 + (int)((lb - la) / 2.3L);
    ld s = 0.0L;
    int k, i;
    for (k = 0; k < panels; k++) {
        const ld a = la + (lb - la) * k / panels;
        const ld b = la + (lb - la) * (k + 1) / panels;
        for (i = 0; i < g->n; i++) {
            const ld lt = gauss_node(g, i, a, b);
            const ld t = expl(lt);
            /* sin p and cos p from t = tan p (not from p: cos p near pi/2
             * would lose digits) */
            const ld sec = sqrtl(1 + t * t);
            const ld cos_p = 1 / sec, sin_p = t / sec;
            /* dp = t/(1+t^2) d(log t) */
            const ld jac = t / (1 + t * t);
            const ld P = side_u ? sec : W * sec / t;
            s += gauss_weight(g, i, a, b) * jac * sin_p * perp_G(cos_p, P, H);
        }
    }
    return s;
}

/* The 1-D integral above.  The ends tan p = 0 and tan p = inf are
 * replaced by tan p = 1e-12 min(W, 1) and 1e22 max(W, 1): the integrand
 * (in log tan p) falls like tan^2 p at the one end and like 1/tan p at the
 * other, so the parts cut off are below 1e-22 of the whole. */
static ld perpendicular_integral(const gauss *g, double l, double w, double h)
{
    const ld W = (ld)w / l, H = (ld)h / l;
    const ld lo = perp_piece(g, W, H, 1e-12L * (W < 1 ? W : 1), W, 1);
    const ld hi = perp_piece(g, W, H, W, 1e22L * (W > 1 ? W : 1), 0);
    return (lo + hi) / (PI_L * W);
}

static ref perpendicular_reference_integral(const gauss *g, const gauss *g2,
                                            double l, double w, double h)
{
    ref f;
    const ld a = perpendicular_integral(g, l, w, h);
    const ld b = perpendicular_integral(g2, l, w, h);
    f.value = b;
    /* the difference of two rules, plus rounding (G loses <= 2x) */
    f.bound = fabsl(a - b) / b + 64 * EPS_L;
    return f;
}

static void test_perpendicular(void)
{
    sweep s = {"perpendicular rectangles vs long double references", 0, 0, 0,
               0, {0, 0, 0}};
    sweep recip = {"perpendicular reciprocity l w F(l,w,h) = l h F(l,h,w)", 0,
                   0, 0, 0, {0, 0, 0}};
    sweep strips = {"perpendicular l >> w, h: crossed strings + end correction",
                    0, 0, 0, 0, {0, 0, 0}};
    sweep tall = {"perpendicular h -> inf: (B_inf(W) - W^2/4H^2)/(pi W)", 0, 0,
                  0, 0, {0, 0, 0}};
    sweep agree = {"perpendicular: textbook and 1-D integral references agree",
                   0, 0, 0, 0, {0, 0, 0}};
    gauss g20, g28;
    int i, j, k;

    gauss_init(&g20, 20);
    gauss_init(&g28, 28);

    /* Unit squares at 90 degrees.  [H] C-14 tabulates 0.2000; at W = H = 1
     * the formula reduces to (1/pi)(pi/2 - sqrt2 atan(1/sqrt2)
     * + ln(3/4)/4) (cond ~ 3 in long double). */
    {
        const ld exact = (PI_L / 2 - sqrtl(2) * atanl(1 / sqrtl(2)) +
                          0.25L * logl(0.75L)) / PI_L;
        const double f = rad_analytic_perpendicular_rectangles(1, 1, 1);
        tap_close(f, (double)exact, TOL, "perpendicular unit squares");
        tap_close(f, 0.20004377607540316, TOL,
                  "perpendicular unit squares vs 0.20004377607540316");
        tap_ok(fabs(f - 0.2000) < 5e-5,
               "perpendicular unit squares match the tabulated 0.2000");
    }

    for (i = 0; i < NGRID; i++)
        for (j = 0; j < NGRID; j++)
            for (k = 0; k < NGRID; k++) {
                const double l = grid[i], w = grid[j], h = grid[k];
                const ref tb = perpendicular_textbook(l, w, h);
                const ref in =
                    perpendicular_reference_integral(&g20, &g28, l, w, h);
                const double f = rad_analytic_perpendicular_rectangles(l, w, h);
                const double fr = rad_analytic_perpendicular_rectangles(l, h, w);
                sweep_add(&s, f, better(tb, in), TOL, l, w, h);
                if (tb.bound <= REF_TRUST && in.bound <= REF_TRUST)
                    sweep_add(&agree, (double)in.value, tb, 1e-14, l, w, h);
                /* reciprocity: w F(l,w,h) = h F(l,h,w), 8 ulps */
                sweep_add(&recip, (double)((ld)w * f / h),
                          (ref){(ld)fr, 0}, 8 * DBL_EPSILON, l, w, h);
            }
    sweep_done(&s, TOL, 0);
    sweep_done(&agree, 1e-14, 1);
    sweep_done(&recip, 8 * DBL_EPSILON, 0);

    /* Long strips, l >> w, h (W, H <= 1e-4): Hottel's crossed strings give
     * the 2-D factor (W + H - R)/(2W), R = sqrt(W^2 + H^2); expanding C-14
     * for small W, H adds the end correction:
     *   pi W F = pi/2 (W + H - R) + (W^2 ln(W^2/R^2) + H^2 ln(H^2/R^2))/4
     *            + W^2 H^2 / 12 + O(W^2 H^2 R^2)
     * (psi(x) = pi x/2 - x^2 + x^4/3 - ..., log1p to second order).  As
     * pi W F >= pi W H / (W + H + R), the relative remainder is O(R^5),
     * below 1e-18 here.  W + H - R is evaluated as 2WH/(W + H + R). */
    for (j = 0; j <= 4; j++)
        for (k = 0; k <= 4; k++) {
            const double l = 1e4, w = grid[j], h = grid[k];
            const ld W = (ld)w / l, H = (ld)h / l, R = sqrtl(W * W + H * H);
            const ld B = PI_L * W * H / (W + H + R) +
                         (W * W * logl(W * W / (R * R)) +
                          H * H * logl(H * H / (R * R))) / 4 +
                         W * W * H * H / 12;
            sweep_add(&strips, rad_analytic_perpendicular_rectangles(l, w, h),
                      (ref){B / (PI_L * W), 1e-18L}, TOL, l, w, h);
        }
    sweep_done(&strips, TOL, 0);
    /* The 2-D factor H/(W + H + R) = 1/2 - W/(4H) + O(W^2/H^2): from a
     * narrow strip along the edge of a wide, long wall half of the
     * hemisphere is wall.  W = 1e-8, H = 1e-4: end effects ~3e-8. */
    tap_ok(fabs(rad_analytic_perpendicular_rectangles(1e4, 1e-4, 1) -
                (0.5 - 1e-8 / 4e-4)) < 1e-7,
           "perpendicular l >> h >> w tends to 1/2 (minus W/4H)");

    /* Tall receiver, h -> inf.  In C-14, psi(H) - psi(R) = O(W^2/H^4) and
     * the three logarithms tend to ln(1 + W^2) - W^2/H^2,
     * -W^2 ln(1 + 1/W^2) + W^2/H^2 and -W^2/H^2, so
     *   pi W F = B_inf - W^2/(4 H^2) + O((W^2 + W^4)/H^4),
     *   B_inf = W atan(1/W) + (ln(1 + W^2) - W^2 ln(1 + 1/W^2))/4,
     * (for W -> 0 this is 1/2: h >> l >> w).  The remainder, relative,
     * stays below est = (W^2 + W^4)/(H^4 B_inf) (it is about est/10 in
     * 80-digit arithmetic); points with est <= 1e-15 are checked. */
    for (i = 0; i < NGRID; i++)
        for (j = 0; j < NGRID; j++) {
            const double l = grid[i], w = grid[j], h = 1e4;
            const ld W = (ld)w / l, H = (ld)h / l, W2 = W * W;
            const ld B = W * atanl(1 / W) +
                         (log1pl(W2) - W2 * log1pl(1 / W2)) / 4;
            const ld est = (W2 + W2 * W2) / (H * H * H * H * B);
            if (est > 1e-15L)
                continue;
            sweep_add(&tall, rad_analytic_perpendicular_rectangles(l, w, h),
                      (ref){(B - W2 / (4 * H * H)) / (PI_L * W), est}, TOL,
                      l, w, h);
        }
    sweep_done(&tall, TOL, 0);

    /* Quadrature of the kernel (the 1-D reduction above, which integrates
     * the area-area kernel with two of four dimensions done exactly) for
     * moderate cases, against the closed form; the rule difference 20 vs
     * 28 nodes bounds the quadrature error. */
    {
        static const double cases[][3] = {
            {1, 1, 1}, {1, 2, 1}, {2, 1, 3}, {1, 0.5, 0.25}};
        for (i = 0; i < 4; i++) {
            const double l = cases[i][0], w = cases[i][1], h = cases[i][2];
            const ref q = perpendicular_reference_integral(&g20, &g28, l, w, h);
            const double err = (double)rel_err(
                rad_analytic_perpendicular_rectangles(l, w, h), q.value);
            tap_ok(q.bound <= 1e-15L && err <= TOL,
                   "perpendicular l=%g w=%g h=%g vs Gauss-Legendre: rel err "
                   "%.3g (20 vs 28 nodes differ by %.1Le), tol %.0e",
                   l, w, h, err, q.bound, TOL);
        }
    }
}

/* ---- the whole double range ------------------------------------------------ */

/* Arguments 1e-300, 1e-250, ..., 1e300: two different ones differ by a
 * factor of at least 1e50, so every triple of them that is not a scaled
 * copy of a moderate one lies deep in an asymptotic regime with a limit
 * derived below, independently of analytic.c, whose neglected terms are
 * far below 1e-20 relative.  The references are evaluated in long double,
 * whose exponent (to 1e4932 on x86) holds products of such ratios; where
 * the reference is below DBL_MIN the result can only be held to an
 * absolute TOL * DBL_MIN (a subnormal has fewer digits). */
#define NWIDE 13
static double wide(int i)
{
    return pow(10.0, -300 + 50 * i);
}

/* Like sweep_add, for references that may be subnormal or out of range. */
static void wide_add(sweep *s, double got, ld want, double p, double q,
                     double r)
{
    ld err;
    if (want >= DBL_MIN)
        err = rel_err(got, want);
    else
        err = fabsl((ld)got - want) / DBL_MIN;
    if (!isfinite(got) || got < 0)
        err = HUGE_VALL;
    s->points++;
    if ((double)err > s->worst || s->points == 1) {
        s->worst = (double)err;
        s->at[0] = p;
        s->at[1] = q;
        s->at[2] = r;
    }
    if (!(err <= TOL)) {
        s->failed++;
        tap_diag("%s: at (%g, %g, %g) got %.17g want %.20Lg", s->what, p, q,
                 r, got, want);
    }
}

/* Hottel's crossed strings for two infinite parallel strips of width b,
 * c apart: sqrt(1 + t^2) - t, t = c/b, rationalised. */
static ld strips_2d(ld t)
{
    return 1 / (sqrtl(1 + t * t) + t);
}

/* Parallel rectangles, X = a/c, Y = b/c, ratios 1 or >= 1e50 apart:
 *   X, Y <= 1e-20: far apart, F = (XY/pi)(1 - (X^2 + Y^2)/3) + O(X^4)
 *     (the kernel series of test_parallel's far sweep);
 *   min(X, Y) = e <= 1e-20: a thin strip, the first term of the thin
 *     series above (K_0 = X atan(X)/2 after I_2(T) = T/2 + sin(2T)/4):
 *     F = e atan(other)/pi (1 + O(e^2)); at X = 1 it is e/4, the kernel
 *     int_0^1 (1 - u)/(1 + u^2)^2 du = pi/8 convolved along the strips;
 *   X, Y >= 1e20: nearly touching, F = 1 - 1/X - 1/Y + O(ln X / X^2):
 *     all but what leaves through the gap band of area 2(a + b)c, which
 *     sees each plate with factor 1/2, so by reciprocity the loss is
 *     (a + b)c/(ab);
 *   otherwise one ratio >= 1e50 times the other and >= 1: an infinite
 *     strip, crossed strings with relative end correction O(1/max). */
static ld parallel_limit(ld X, ld Y)
{
    const ld lo = X < Y ? X : Y, hi = X < Y ? Y : X;
    if (hi <= 1e-20L)
        return X * Y / PI_L * (1 - (X * X + Y * Y) / 3);
    if (lo <= 1e-20L)
        return lo * atanl(hi) / PI_L;
    if (lo >= 1e20L)
        return 1 - 1 / X - 1 / Y;
    return strips_2d(1 / lo);
}

/* Perpendicular rectangles, W = w/l, H = h/l, m = min, M = max:
 *   M <= 1e-20: long strips, pi W F = pi/2 (W + H - R) + (W^2 ln(W^2/R^2)
 *     + H^2 ln(H^2/R^2))/4 + W^2 H^2/12 (test_perpendicular's strips);
 *   m >= 1e20: l << w, h.  psi(t) = 1 - 1/(3t^2) + ..., the first
 *     logarithm of C-14 tends to ln(W^2 H^2/R^2), the two others to
 *     -H^2/R^2 and -W^2/R^2 (ln(1 + x) = x + O(x^2)):
 *     B = 3/4 + ln(W H/R)/2 + O(1/m^2);
 *   M >= 1e20 max(1, m): a tall receiver or a deep emitter,
 *     B = B_inf(m) (test_perpendicular's tall limit, remainder
 *     (m^2 + m^4)/(M^4 B));
 *   otherwise m <= 1e-20 min(1, M) <= M <= 1e20: a strip along the
 *     common edge, B/m = atan(1/m) + O(m ln m): F = 1/2 from the narrow
 *     one (a point on the edge sees half its hemisphere filled), and
 *     F = (m/M)/2 the other way (reciprocity). */
static ld perpendicular_limit(ld W, ld H)
{
    const ld m = W < H ? W : H, M = W < H ? H : W;
    const ld R = sqrtl(W * W + H * H);
    ld B;
    if (M <= 1e-20L)
        B = PI_L * W * H / (W + H + R) +
            (W * W * logl(W * W / (R * R)) + H * H * logl(H * H / (R * R))) /
                4 +
            W * W * H * H / 12;
    else if (m >= 1e20L)
        B = 0.75L + (logl(W) + logl(H) - logl(R)) / 2;
    else if (M >= 1e20L * (m > 1 ? m : 1))
        B = m * atanl(1 / m) +
            (log1pl(m * m) - m * m * log1pl(1 / (m * m))) / 4;
    else
        B = m * PI_L / 2;
    return B / (PI_L * W);
}

/* Coaxial disks, ratios 1 or >= 1e50 apart:
 *   h >= 1e20 max(r1, r2): far, (r2/h)^2 (1 - (r1^2 + r2^2)/h^2);
 *   r1 <= 1e-20 min(r2, h): disk 1 a point, r2^2/(h^2 + r2^2) (1 -
 *     r1^2 h^2/(h^2 + r2^2)^2) (test_disk_disk's r1 -> 0 limit);
 *   r2 <= 1e-20 min(r1, h): disk 2 a point seen from disk 1, the same by
 *     reciprocity: (r2^2/r1^2) F21;
 *   h <= 1e-20 min(r1, r2): touching.  Equal radii: 1 - t + t^2/2
 *     (t = h/r); else the smaller disk sees all of the larger, the larger
 *     the smaller's area: min(1, r2^2/r1^2), corrections O(h^2/r^2). */
static ld disk_limit(ld r1, ld r2, ld h, int *known)
{
    *known = 1;
    if (h >= 1e20L * (r1 > r2 ? r1 : r2))
        return r2 * r2 / (h * h) * (1 - (r1 * r1 + r2 * r2) / (h * h));
    if (r1 <= 1e-20L * (r2 < h ? r2 : h)) {
        const ld A = h * h + r2 * r2;
        return r2 * r2 / A * (1 - r1 * r1 * h * h / (A * A));
    }
    if (r2 <= 1e-20L * (r1 < h ? r1 : h)) {
        const ld A = h * h + r1 * r1;
        return r2 * r2 / (r1 * r1) * (r1 * r1 / A) *
               (1 - r2 * r2 * h * h / (A * A));
    }
    if (h <= 1e-20L * (r1 < r2 ? r1 : r2)) {
        const ld t = h / r1;
        if (r1 == r2)
            return 1 - t + t * t / 2;
        return r2 < r1 ? r2 * r2 / (r1 * r1) : 1;
    }
    *known = 0;
    return 0;
}

static void test_wide_range(void)
{
    sweep pd = {"point-disk over 1e-300..1e300 vs r^2/(r^2 + h^2)", 0, 0, 0,
                0, {0, 0, 0}};
    sweep dd = {"disk-disk over 1e-300..1e300 vs limits", 0, 0, 0, 0,
                {0, 0, 0}};
    sweep pr = {"parallel over 1e-300..1e300 vs limits", 0, 0, 0, 0,
                {0, 0, 0}};
    sweep pp = {"perpendicular over 1e-300..1e300 vs limits", 0, 0, 0, 0,
                {0, 0, 0}};
    sweep rd = {"disk-disk reciprocity r1^2 F12 = r2^2 F21 over 1e-300..1e300",
                0, 0, 0, 0, {0, 0, 0}};
    sweep rp = {"perpendicular reciprocity w F(l,w,h) = h F(l,h,w) over "
                "1e-300..1e300", 0, 0, 0, 0, {0, 0, 0}};
    sweep sc = {"scale invariance F(k a, k b, k c) = F(a, b, c), k = 2^e to "
                "the ends of the double range", 0, 0, 0, 0, {0, 0, 0}};
    int i, j, k, known;

    for (i = 0; i < NWIDE; i++)
        for (j = 0; j < NWIDE; j++) {
            const ld r = wide(i), h = wide(j);
            wide_add(&pd, rad_analytic_point_disk(wide(i), wide(j)),
                     r * r / (r * r + h * h), wide(i), wide(j), 0);
        }
    for (i = 0; i < NWIDE; i++)
        for (j = 0; j < NWIDE; j++)
            for (k = 0; k < NWIDE; k++) {
                const double a = wide(i), b = wide(j), c = wide(k);
                const ld want = disk_limit(a, b, c, &known);
                const double f12 = rad_analytic_disk_disk(a, b, c);
                const double f21 = rad_analytic_disk_disk(b, a, c);
                const double g = rad_analytic_perpendicular_rectangles(a, b, c);
                const double gr = rad_analytic_perpendicular_rectangles(a, c, b);
                if (known)
                    wide_add(&dd, f12, want, a, b, c);
                if (!(i == j && j == k)) {
                    wide_add(&pr, rad_analytic_parallel_rectangles(a, b, c),
                             parallel_limit((ld)a / c, (ld)b / c), a, b, c);
                    wide_add(&pp, g, perpendicular_limit((ld)b / a, (ld)c / a),
                             a, b, c);
                }
                /* reciprocity, both sides from the library; the products
                 * in long double are exact to 1e-19 */
                if (f12 >= DBL_MIN && f21 >= DBL_MIN)
                    wide_add(&rd, f12, (ld)b * b * f21 / ((ld)a * a), a, b, c);
                if (g >= DBL_MIN && gr >= DBL_MIN)
                    wide_add(&rp, g, (ld)c * gr / b, a, b, c);
            }
    sweep_done(&pd, TOL, 0);
    sweep_done(&dd, TOL, 0);
    sweep_done(&pr, TOL, 0);
    sweep_done(&pp, TOL, 0);
    sweep_done(&rd, TOL, 0);
    sweep_done(&rp, TOL, 0);

    /* Only ratios matter: scaling every length by 2^e (exact), with e
     * taking the largest length to 2^1015 or the smallest to 2^-1015,
     * must leave F unchanged up to the rounding of the logarithms of
     * ratios (a few ulps; 8 allowed), for moderate and extreme shapes. */
    {
        static const double shapes[][3] = {
            {1, 1, 1}, {2, 3, 0.5}, {1, 1e-8, 1e8}, {1e-60, 1, 1e-70},
            {1e60, 1e50, 1}, {1, 1e-100, 1e-90}};
        const int n = (int)(sizeof shapes / sizeof shapes[0]);
        for (i = 0; i < n; i++)
            for (k = -1; k <= 1; k += 2) {
                const double a = shapes[i][0], b = shapes[i][1],
                             c = shapes[i][2];
                const int e = k > 0 ? 1015 - ilogb(fmax(fmax(a, b), c))
                                    : -1015 - ilogb(fmin(fmin(a, b), c));
                const double sa = ldexp(a, e), sb = ldexp(b, e),
                             scc = ldexp(c, e);
                sweep_add(&sc, rad_analytic_disk_disk(sa, sb, scc),
                          (ref){rad_analytic_disk_disk(a, b, c), 0},
                          8 * DBL_EPSILON, sa, sb, scc);
                sweep_add(&sc, rad_analytic_parallel_rectangles(sa, sb, scc),
                          (ref){rad_analytic_parallel_rectangles(a, b, c), 0},
                          8 * DBL_EPSILON, sa, sb, scc);
                sweep_add(&sc,
                          rad_analytic_perpendicular_rectangles(sa, sb, scc),
                          (ref){rad_analytic_perpendicular_rectangles(a, b, c),
                                0},
                          8 * DBL_EPSILON, sa, sb, scc);
                sweep_add(&sc, rad_analytic_point_disk(sa, sb),
                          (ref){rad_analytic_point_disk(a, b), 0},
                          8 * DBL_EPSILON, sa, sb, 0);
            }
        sweep_done(&sc, 8 * DBL_EPSILON, 0);
    }
}

/* ---- invalid input ------------------------------------------------------------ */

static void test_invalid(void)
{
    static const double bad[] = {0.0, -0.0, -1.0, INFINITY, -INFINITY, NAN};
    const int nbad = (int)(sizeof bad / sizeof bad[0]);
    int i, ok1 = 1, ok2 = 1, ok3 = 1, ok4 = 1;
    for (i = 0; i < nbad; i++) {
        const double x = bad[i];
        ok1 &= isnan(rad_analytic_point_disk(x, 1)) &&
               isnan(rad_analytic_point_disk(1, x));
        ok2 &= isnan(rad_analytic_disk_disk(x, 1, 1)) &&
               isnan(rad_analytic_disk_disk(1, x, 1)) &&
               isnan(rad_analytic_disk_disk(1, 1, x));
        ok3 &= isnan(rad_analytic_parallel_rectangles(x, 1, 1)) &&
               isnan(rad_analytic_parallel_rectangles(1, x, 1)) &&
               isnan(rad_analytic_parallel_rectangles(1, 1, x));
        ok4 &= isnan(rad_analytic_perpendicular_rectangles(x, 1, 1)) &&
               isnan(rad_analytic_perpendicular_rectangles(1, x, 1)) &&
               isnan(rad_analytic_perpendicular_rectangles(1, 1, x));
    }
    tap_ok(ok1, "point-disk: NaN for zero, negative, infinite, NaN input");
    tap_ok(ok2, "disk-disk: NaN for zero, negative, infinite, NaN input");
    tap_ok(ok3, "parallel: NaN for zero, negative, infinite, NaN input");
    tap_ok(ok4, "perpendicular: NaN for zero, negative, infinite, NaN input");
}

int main(void)
{
    test_invalid();
    test_point_disk();
    test_disk_disk();
    test_parallel();
    test_perpendicular();
    test_wide_range();
    return tap_done();
}
