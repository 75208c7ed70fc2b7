/* test_fmtdouble.c -- radi_fmt_g (src/util/fmtdouble.h) against glibc's printf.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Reference: snprintf(buf, size, "%.*g", prec, v) itself, which glibc
 * computes with exact multiple-precision arithmetic (stdio-common/
 * printf_fp.c); the output contract (radiosity-files(5)) is those bytes.
 * No tolerance: every byte must match.  Cases: the edges (+-0, subnormals,
 * DBL_MIN, DBL_MAX, 1e+-308, inf, nan), every power of two, powers of ten
 * and their neighbours (where the digit count changes), integers, decimal
 * fractions like 0.1, exact ties of short precisions, and random bit
 * patterns and random values in [0, 1) (what form factors look like).
 */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/fmtdouble.h"
#include "../tap.h"

typedef struct tally {
    long checked, wrong;
    long fast;                  /* decided by the product alone (no fallback) */
    char first[160];            /* the first mismatch, for the TAP line */
} tally;

/* Compare one value at one precision. */
static void check(tally *t, double v, int prec)
{
    char want[64], got[RAD_FMT_G_MAX + 8];
    memset(got, 'X', sizeof got);
    const int wl = snprintf(want, sizeof want, "%.*g", prec, v);
    int gl = radi_fmt_g(got, v, prec);
    t->checked++;
    /* the fast path alone: when it answers, it must be right too (the
     * fallback would otherwise hide its faults) */
    char fast[RAD_FMT_G_MAX + 8];
    const int fl = radi_fmt_g_fast(fast, v, prec);
    if (fl >= 0) {
        t->fast++;
        if (fl != wl || strcmp(fast, want) != 0)
            gl = -1;
    }
    if (gl != wl || strcmp(got, want) != 0) {
        if (!t->wrong++)
            snprintf(t->first, sizeof t->first, "%a at %%.%dg: got '%.*s' want '%s'", v,
                     prec, RAD_FMT_G_MAX, got, want);
    }
}

/* Both signs, the precisions the writers use (17 and 3) and, for some, all. */
static void check_all(tally *t, double v, int all_precisions)
{
    for (int s = 0; s < 2; s++, v = -v) {
        if (all_precisions)
            for (int p = 1; p <= 17; p++)
                check(t, v, p);
        else {
            check(t, v, 17);
            check(t, v, 3);
        }
    }
}

static void report(const tally *t, const char *what)
{
    tap_ok(t->wrong == 0, "%s: %ld of %ld formatted as snprintf does (%ld without it)%s%s",
           what, t->checked - t->wrong, t->checked, t->fast, t->wrong ? "; first: " : "",
           t->wrong ? t->first : "");
}

/* The fast path must carry the load: the fallback only for ties and near
 * ties, which random values hit with probability below 2^-64 per value
 * (fmtdouble.c); 1e-4 leaves room for the exact ties of short precisions. */
static void report_fast(const tally *t, const char *what)
{
    tap_ok(t->fast >= t->checked - t->checked / 10000,
           "%s: the product decides %ld of %ld without snprintf", what, t->fast, t->checked);
}

/* xorshift64* (Vigna 2016): a fixed seed, the same cases on every run. */
static uint64_t next(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * UINT64_C(2685821657736338717);
}

static double from_bits(uint64_t b)
{
    double v;
    memcpy(&v, &b, sizeof v);
    return v;
}

int main(void)
{
    tally t = {0};
    const double edges[] = {0.0, DBL_TRUE_MIN, 2 * DBL_TRUE_MIN, 3 * DBL_TRUE_MIN,
                            DBL_MIN, DBL_MIN - DBL_TRUE_MIN, DBL_MIN / 3, DBL_MAX, 1e308,
                            1e-308, 1e-307, 1.7976931348623157e308, 2.2250738585072009e-308,
                            4.9406564584124654e-324, 1.0, 0.1, 0.2, 0.3, 1.0 / 3, 2.0 / 3,
                            0.19982489569838746, 0.20004377607540316, 1e-5, 1e-4, 0.0001,
                            9.9999999999999995e-5, 123456789012345678.0, 1e16, 1e17, 1e22,
                            9007199254740992.0, 9007199254740993.0, 0.5, 0.125, 2.5, 0.25,
                            1.5, 0.05, 0.15, 0.35, 1e23, 5e-324, 9.5, 99.5, 0.095};
    for (size_t i = 0; i < sizeof edges / sizeof edges[0]; i++)
        check_all(&t, edges[i], 1);
    report(&t, "edges (+-0, subnormals, DBL_MIN, DBL_MAX, 1e+-308, 0.1, ties), precisions 1..17");

    tally s = {0};
    check_all(&s, INFINITY, 1);
    check_all(&s, NAN, 1);
    report(&s, "inf and nan with both signs");

    tally p2 = {0};
    for (int e = -1074; e <= 1023; e++)
        check_all(&p2, ldexp(1, e), e % 7 == 0);
    report(&p2, "every power of two, 2^-1074 .. 2^1023");
    report_fast(&p2, "powers of two");

    tally p10 = {0};
    for (int k = -323; k <= 308; k++) {
        const double v = strtod("1", NULL) * pow(10, k);
        check_all(&p10, v, 1);
        check_all(&p10, nextafter(v, 0), 1);
        check_all(&p10, nextafter(v, INFINITY), 1);
    }
    report(&p10, "powers of ten and their neighbours, 1e-323 .. 1e308, precisions 1..17");

    tally in = {0};
    for (int i = 0; i <= 100000; i++)
        check_all(&in, i, i < 2000);
    for (int e = 53; e < 70; e++)
        for (int i = -50; i <= 50; i++)
            check_all(&in, ldexp(1, e) + ldexp(i, e - 52), 1);
    report(&in, "integers 0 .. 100000 and near 2^53 .. 2^69");

    tally dec = {0};
    for (int i = 1; i <= 100000; i++) {
        check_all(&dec, i / 1000.0, i < 3000);
        check_all(&dec, i * 1e-6, 0);
        check_all(&dec, i * 1e-20, 0);
    }
    report(&dec, "decimal fractions i/1000, i*1e-6, i*1e-20");

    uint64_t seed = UINT64_C(0x9e3779b97f4a7c15);
    tally rb = {0};
    for (int i = 0; i < 300000; i++) {
        const double v = from_bits(next(&seed));
        check_all(&rb, v, i < 20000);
    }
    report(&rb, "random bit patterns (3e5; 2e4 at every precision)");
    report_fast(&rb, "random bit patterns");

    tally ru = {0};
    for (int i = 0; i < 300000; i++) {
        const double v = (double)(next(&seed) >> 11) * 0x1p-53;
        check_all(&ru, v, 0);
        check_all(&ru, v * v * v * v, 0);
    }
    report(&ru, "random values in [0, 1) and their fourth powers (6e5)");
    report_fast(&ru, "random values in [0, 1)");

    tally iu = {0};
    const unsigned uints[] = {0, 1, 9, 10, 11, 99, 100, 101, 999, 1000, 12345, 99999, 100000,
                              2147483647u, 4294967295u};
    for (size_t i = 0; i < sizeof uints / sizeof uints[0] + 100000; i++) {
        const unsigned u = i < sizeof uints / sizeof uints[0] ? uints[i] : (unsigned)next(&seed);
        char want[16], got[16];
        snprintf(want, sizeof want, "%u", u);
        const int len = radi_fmt_uint(got, u);
        got[len] = '\0';
        iu.checked++;
        if (strcmp(got, want) && !iu.wrong++)
            snprintf(iu.first, sizeof iu.first, "%u: got '%s'", u, got);
    }
    report(&iu, "radi_fmt_uint against %u");
    return tap_done();
}
