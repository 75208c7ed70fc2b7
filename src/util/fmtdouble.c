/* fmtdouble.c -- "%.*g" from one 64 x 128-bit product, exact.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * What "%.Pg" prints (C11 7.21.6.1): the value rounded to P significant
 * digits, d.ddd x 10^X; style e when X < -4 or X >= P, style f otherwise,
 * trailing zeros of the fraction and a bare point removed.  glibc rounds
 * the exact binary value correctly (to nearest, ties to even, in the
 * default rounding mode); so does this file, or it asks snprintf.
 *
 * The digits.  A finite v > 0 is m 2^e with m < 2^64 shifted so its top
 * bit is bit 63.  d = floor(log10 v) is floor((e + 63) log10 2) (with
 * log10 2 ~ 1292913986 / 2^32: for the binary exponents of doubles,
 * -1074..1023, the constant's error moves the product by less than 1.3e-7,
 * and e log10 2 never comes within 4.5e-4 of an integer but at e = 0,
 * where it is one), plus one when m reaches the binade's power of ten (a
 * threshold per binade, pow10tab.h); the scale k = P - 1 - d puts v 10^k
 * in [10^(P-1), 10^P).  The table (pow10tab.h, generated
 * exactly by scripts/gen-pow10.py) gives 10^k = (P_k + delta) 2^q_k with
 * the 128-bit P_k truncated, 0 <= delta < 1.  So
 *     v 10^k = T 2^(e + q_k),   T = m (P_k + delta),
 *     W = m P_k <= T < W + m < W + 2^64,
 * with W the exact 192-bit product (W >= 2^190).  The integer part
 * N = floor(W / 2^s'), s' = -(e + q_k), has P digits (N < 2^57, so
 * s' >= 133, and N >= 10^0 with W < 2^192, so s' <= 191), unless W < T
 * hides the step to 10^(P-1) (snprintf then).  The remainder R = W mod
 * 2^s' decides the rounding of T: R > 2^(s'-1) rounds up, R + 2^64 <=
 * 2^(s'-1) rounds down, and anything between (within 2^64 of a tie:
 * fewer than one value in 2^64 at random) goes to snprintf.  For
 * 0 <= k <= 55, 10^k has at most 128 significant bits, delta = 0 and T = W:
 * R decides every case, ties (R = 2^(s'-1)) to the even N.  Rounding up
 * to 10^P means one digit more: N = 10^(P-1) and X + 1.  Precisions up
 * to 9 (the error column's 3) first try plain double arithmetic
 * (short_decimal), exact wherever it decides.  The test
 * (tests/unit/util/test_fmtdouble.c) compares against snprintf on a few million
 * random bit patterns and the edges (subnormals, +-0, 1e+-308, integers,
 * decimal fractions, ties).
 *
 * This is the idea of Ryu printf (Adams 2019, "Ryu revisited: printf
 * floating point conversion", OOPSLA) in its simplest form: one product of
 * fixed width instead of Ryu's exact multi-word ones, with the
 * multiple-precision printf as the referee of the cases it cannot settle.
 */
#include <config.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "util/fmtdouble.h"
#include "util/pow10tab.h"

typedef unsigned __int128 u128;

static const uint64_t pow10_u64[18] = {
    1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u, 100000000u,
    1000000000u, 10000000000u, 100000000000u, 1000000000000u, 10000000000000u,
    100000000000000u, 1000000000000000u, 10000000000000000u, 100000000000000000u};

static const char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/* Exactly 8 digits of v < 10^8, in 32-bit arithmetic. */
static void put8(char *out, uint32_t v)
{
    const uint32_t hi = v / 10000, lo = v % 10000;
    memcpy(out, digit_pairs + 2 * (hi / 100), 2);
    memcpy(out + 2, digit_pairs + 2 * (hi % 100), 2);
    memcpy(out + 4, digit_pairs + 2 * (lo / 100), 2);
    memcpy(out + 6, digit_pairs + 2 * (lo % 100), 2);
}

/* The `len` (at most 8) low decimal digits of v, zero-padded, into out. */
static void put_short(char *out, uint32_t v, int len)
{
    int i = len;
    while (i >= 2) {
        const uint32_t r = v % 100;
        v /= 100;
        i -= 2;
        memcpy(out + i, digit_pairs + 2 * r, 2);
    }
    if (i)
        out[0] = (char)('0' + v % 10);
}

/* The `len` (at most 20) low decimal digits of n, zero-padded, into out:
 * 8 at a time in 32-bit arithmetic, which is cheaper than 64-bit. */
static void put_digits(char *out, uint64_t n, int len)
{
    while (len > 8) {
        put8(out + len - 8, (uint32_t)(n % 100000000u));
        n /= 100000000u;
        len -= 8;
    }
    put_short(out, (uint32_t)n, len);
}

int radi_fmt_uint(char *buf, unsigned v)
{
    int len = 1;
    for (unsigned t = v; t >= 10; t /= 10)
        len++;
    put_digits(buf, v, len);
    return len;
}

/* v (finite, > 0) rounded to prec digits: N 10^(X - prec + 1) with
 * 10^(prec-1) <= N < 10^prec.  0, or -1 when the product cannot decide. */
/* Few digits (the error column's 3) in double arithmetic: for |k| <= 22,
 * 10^|k| is a double and y = v 10^k (or v / 10^-k) is the true product
 * rounded once, within 2^-53 y < 10^P 2^-53 of it.  Where the fraction of
 * y is farther than twice that from 1/2 the rounding of the true value is
 * the rounding of y; else 0, and the exact path decides. */
enum { SHORT_MAX = 9 };

static const double pow10_dbl[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                     1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

static inline __attribute__((always_inline)) int short_decimal(double v, int prec, int k,
                                                               uint64_t *n_out)
{
    const double y = k >= 0 ? v * pow10_dbl[k] : v / pow10_dbl[-k];
    const double margin = 2 * pow10_dbl[prec] * 0x1p-53;
    if (!(y >= (double)pow10_u64[prec - 1] && y < (double)pow10_u64[prec]))
        return 0;
    const uint64_t n = (uint64_t)y;
    const double frac = y - (double)n;      /* exact: y < 2^53 */
    if (fabs(frac - 0.5) <= margin)
        return 0;
    *n_out = n + (frac > 0.5);
    return 1;
}

static inline __attribute__((always_inline)) int decimal(double v, int prec, uint64_t *n_out,
                                                         int *x_out)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    uint64_t m = bits & ((UINT64_C(1) << 52) - 1);
    const int biased = (int)(bits >> 52) & 0x7ff;
    int e = -1074;
    if (biased) {
        m |= UINT64_C(1) << 52;
        e = biased - 1075;
    }
    const int lz = __builtin_clzll(m);
    m <<= lz;
    e -= lz;
    /* d = floor(log10 v): floor((e + 63) log10 2), plus one above the
     * binade's power of ten (>> of a negative is arithmetic in GCC, Clang) */
    const int d = (int)(((int64_t)(e + 63) * INT64_C(1292913986)) >> 32) +
                  (m >= radi_log10_thr[e + 63 - RAD_LOG10_EMIN]);
    const int k = prec - 1 - d;
    if (prec <= SHORT_MAX && k >= -22 && k <= 22 && short_decimal(v, prec, k, n_out))
        goto done;
    if (k < RAD_POW10_KMIN || k > RAD_POW10_KMAX)
        return -1;
    const struct rad_pow10 *p = &radi_pow10_tab[k - RAD_POW10_KMIN];
    const u128 lo = (u128)m * p->lo, hi = (u128)m * p->hi;
    const u128 top = hi + (lo >> 64);       /* W >> 64, exactly */
    const uint64_t w2 = (uint64_t)(top >> 64), w1 = (uint64_t)top, w0 = (uint64_t)lo;
    const int s = -(e + p->q) - 128;        /* N = W >> (s + 128) = w2 >> s */
    if (s < 2 || s > 63)
        return -1;                          /* impossible by the bounds above */
    uint64_t n = w2 >> s;
    if (n >= pow10_u64[prec] || n < pow10_u64[prec - 1])
        return -1;                          /* W < T hid a digit: not seen */
    /* R = (rh, w1, w0) in 64-bit digits, and T's remainder lies in
     * [R, R + 2^64): at most one unit of w1 above it */
    const uint64_t rh = w2 & ((UINT64_C(1) << s) - 1), half = UINT64_C(1) << (s - 1);
    const int exact = k >= 0 && k <= RAD_POW10_EXACT_MAX;  /* T = W */
    const int above = rh > half || (rh == half && (w1 | w0) != 0);
    const int tie = rh == half && (w1 | w0) == 0;
    if (!exact && !above && (tie || (rh + 1 == half && w1 == UINT64_MAX)))
        return -1;                          /* too close to a tie to tell */
    n += above || (tie && (n & 1));         /* ties (exact ones) to even */
    *n_out = n;
done:
    *x_out = prec - 1 - k;
    if (*n_out == pow10_u64[prec]) {
        *n_out = pow10_u64[prec - 1];
        ++*x_out;
    }
    return 0;
}

/* The styles copy digits in fixed lengths (moves the compiler inlines)
 * and then advance by the true ones: dg holds DG_MAX bytes, and the
 * output has RAD_FMT_G_MAX bytes of room. */
enum { DG_MAX = 40 };

/* Style e: d.ddd (nd digits) e+XX. */
static char *style_e(char *p, const char *dg, int nd, int x)
{
    *p++ = dg[0];
    if (nd > 1) {
        *p++ = '.';
        memcpy(p, dg + 1, 16);
        p += nd - 1;
    }
    *p++ = 'e';
    *p++ = x < 0 ? '-' : '+';
    const unsigned ax = (unsigned)(x < 0 ? -x : x);
    if (ax >= 100)
        *p++ = (char)('0' + ax / 100);
    memcpy(p, digit_pairs + 2 * (ax % 100), 2);
    return p + 2;
}

/* Style f with the digits dg[0..nd) and exponent x in [-4, prec). */
static char *style_f(char *p, const char *dg, int nd, int x)
{
    if (x < 0) {
        memcpy(p, "0.000", 5);
        p += 1 - x;
        memcpy(p, dg, 17);
        return p + nd;
    }
    memcpy(p, dg, 17);                  /* stripped zeros of the integer part stay */
    p += x + 1;
    if (nd > x + 1) {
        *p++ = '.';
        memcpy(p, dg + x + 1, 16);
        p += nd - x - 1;
    }
    return p;
}

/* radi_fmt_g_fast's work; inlined where prec is a constant (the writers' 17
 * and 3), so the digit loops and powers of ten fold. */
static inline __attribute__((always_inline)) int fmt_g(char *buf, double v, int prec)
{
    if (prec < 1 || prec > 17)
        return -1;
    char *p = buf;
    if (signbit(v))
        *p++ = '-';
    if (!isfinite(v) || v == 0) {
        const char *word = isnan(v) ? "nan" : isinf(v) ? "inf" : "0";
        const size_t len = strlen(word);
        memcpy(p, word, len + 1);
        return (int)(p - buf + (ptrdiff_t)len);
    }
    uint64_t n;
    int x;
    if (decimal(fabs(v), prec, &n, &x))
        return -1;
    char dg[DG_MAX];
    put_digits(dg, n, prec);
    int nd = prec;
    while (nd > 1 && dg[nd - 1] == '0')
        nd--;
    p = (x < -4 || x >= prec) ? style_e(p, dg, nd, x) : style_f(p, dg, nd, x);
    *p = '\0';
    return (int)(p - buf);
}

int radi_fmt_g(char *buf, double v, int prec)
{
    const int len = prec == 17 ? fmt_g(buf, v, 17)
                    : prec == 3 ? fmt_g(buf, v, 3)
                                : fmt_g(buf, v, prec);
    return len >= 0 ? len : snprintf(buf, RAD_FMT_G_MAX, "%.*g", prec, v);
}

int radi_fmt_g_fast(char *buf, double v, int prec)
{
    return fmt_g(buf, v, prec);
}
