/* test_vecmath.c -- the vectorisable logarithm (src/util/vecmath.h) against libm.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Reference: glibc's log, documented correctly rounded in practice for
 * double (glibc manual, "Known Maximum Errors in Math Functions": 0 or 1
 * ulp), and exact identities (ln 1 = 0, ln 2^k = k ln 2).  Tolerance: 2 ulp
 * of the result (our claim), which a wrong reduction, a wrong coefficient
 * or a lost exponent misses by orders of magnitude.
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "../tap.h"
#include "util/vecmath.h"

/* rad_log4 is inlined: no vector crosses a call (see vecmath.h) */
#pragma GCC diagnostic ignored "-Wpsabi"

/* rad_log4 over x[0..n), four at a time (the last group padded with 1) */
static void log_all(double *y, const double *x, int n)
{
    for (int i = 0; i < n; i += 4) {
        rad_v4d v = {1, 1, 1, 1};
        for (int j = 0; j < 4 && i + j < n; j++)
            v[j] = x[i + j];
        const rad_v4d l = rad_log4(v);
        for (int j = 0; j < 4 && i + j < n; j++)
            y[i + j] = l[j];
    }
}

static double ulps(double got, double want)
{
    if (got == want)
        return 0;
    double u = nextafter(fabs(want), INFINITY) - fabs(want);
    return fabs(got - want) / u;
}

int main(void)
{
    enum { N = 200000 };
    static double x[N], y[N];
    unsigned long seed = 12345;
    /* arguments spread over the whole exponent range, and dense near 1
     * where ln x is small and relative accuracy is hardest */
    for (int i = 0; i < N; i++) {
        seed = seed * 6364136223846793005UL + 1442695040888963407UL;
        double u = (double)(seed >> 11) / 9007199254740992.0;
        if (i % 3 == 0)
            x[i] = exp((u - 0.5) * 1410);
        else if (i % 3 == 1)
            x[i] = 1 + (u - 0.5) * 1e-3;
        else
            x[i] = 0.25 + 3.75 * u;
    }
    log_all(y, x, N);
    double worst = 0, worst_x = 0;
    for (int i = 0; i < N; i++) {
        double e = ulps(y[i], log(x[i]));
        if (e > worst) {
            worst = e;
            worst_x = x[i];
        }
    }
    tap_ok(worst <= 2, "within 2 ulp of libm on %d arguments (worst %.2f ulp at %.17g)", N,
           worst, worst_x);

    /* exact values: ln 1 = 0; ln 2^k = k ln 2 to 1 ulp */
    double p[5] = {1.0, 2.0, 0.5, 0x1p-1000, 0x1p1000}, q[5];
    log_all(q, p, 5);
    tap_ok(q[0] == 0, "ln 1 = 0 exactly (got %g)", q[0]);
    int good = 1;
    const int k[5] = {0, 1, -1, -1000, 1000};
    for (int i = 1; i < 5; i++)
        good &= ulps(q[i], k[i] * 0.69314718055994530942) <= 1;
    tap_ok(good, "ln 2^k = k ln 2 for k = 1, -1, -1000, 1000");

    /* arguments outside the fast path get libm's own results */
    double s[7] = {0.0, -1.0, INFINITY, NAN, 4.9e-324, DBL_MIN, DBL_MAX}, t[7];
    log_all(t, s, 7);
    tap_ok(t[0] == -INFINITY, "ln 0 = -inf");
    tap_ok(isnan(t[1]) && isnan(t[3]), "ln of a negative number or NaN is NaN");
    tap_ok(t[2] == INFINITY, "ln inf = inf");
    tap_ok(t[4] == log(4.9e-324), "a subnormal argument gets libm's value (%.17g)", t[4]);
    tap_ok(ulps(t[5], log(DBL_MIN)) <= 1 && ulps(t[6], log(DBL_MAX)) <= 1,
           "the ends of the normal range");
    /* atan(y/x), x > 0: against atan2 over ratios 1e-8 .. 1e8 of both signs,
     * and the reduction boundaries exactly */
    double worst_a = 0, worst_t = 0;
    for (int i = 0; i < N; i++) {
        seed = seed * 6364136223846793005UL + 1442695040888963407UL;
        double u = (double)(seed >> 11) / 9007199254740992.0;
        double yy = (i % 2 ? -1 : 1) * exp((u - 0.5) * 37), xx = 0.5 + u;
        double e = ulps(rad_atan_core(yy, xx), atan2(yy, xx));
        if (e > worst_a) {
            worst_a = e;
            worst_t = yy / xx;
        }
    }
    tap_ok(worst_a <= 4, "atan within 4 ulp of libm on %d arguments (worst %.2f ulp at %.17g)", N,
           worst_a, worst_t);
    const double edges[] = {0, 1, 0.41421356237309504880, 1e-300, 1e300, 3, 0.3};
    int good_a = 1;
    for (size_t i = 0; i < sizeof edges / sizeof *edges; i++)
        good_a &= ulps(rad_atan_core(edges[i], 1), atan(edges[i])) <= 4 &&
                  ulps(rad_atan_core(-edges[i], 1), -atan(edges[i])) <= 4;
    tap_ok(good_a, "atan at 0, 1, tan(pi/8), 1e-300, 1e300, 3, 0.3 and their negatives");

    /* the scalar log of the closed forms (ffcontour.c): the same arithmetic
     * as the four lanes, so the same values */
    int same = 1;
    for (int i = 0; i < N; i++)
        same &= rad_log_core(x[i]) == y[i];
    tap_ok(same, "rad_log_core equals rad_log4 on all %d arguments", N);
    /* the short series (default mode's rules): its claim, 1.2e-14 absolute,
     * plus a few ulp of the result */
    double worst_s = 0;
    for (int i = 0; i + 4 <= N; i += 4) {
        rad_v4d v = {x[i], x[i + 1], x[i + 2], x[i + 3]}, l = rad_log4_short(v);
        for (int j = 0; j < 4; j++) {
            const double e = fabs(l[j] - log(x[i + j])) - 4 * DBL_EPSILON * fabs(log(x[i + j]));
            worst_s = e > worst_s ? e : worst_s;
        }
    }
    tap_ok(worst_s <= 1.2e-14, "rad_log4_short within 1.2e-14 (and 4 ulp) of libm (worst excess %.2g)",
           worst_s);
    return tap_done();
}
