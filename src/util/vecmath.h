/* vecmath.h -- natural logarithm and arctangent written so that they
 * vectorise: scalar (rad_log_core, rad_atan_core, for loops the compiler
 * vectorises) and on four lanes (rad_log4, rad_log4_short).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The Gauss rules spend most of their time in logarithms of squared
 * distances.  libm's log is scalar; this one is plain arithmetic on the
 * bits of the argument, with no branch and no table.  It is inline: a
 * caller compiled in an AVX2/FMA clone (target_clones) gets 4-lane code.
 *
 * Method (the classic reduction, e.g. Cody & Waite 1980, ch. 5; Tang 1990):
 *   x = 2^k z with z in [sqrt(1/2), sqrt(2)), read off the bits;
 *   ln x = k ln 2 + ln z,  ln z = 2 atanh(s),  s = f/(2 + f),  f = z - 1,
 *   2 atanh(s) = 2s + s T(s^2),  T(w) = sum_{j=1..10} 2 w^j / (2j + 1)
 *   (evaluated as w Q(w) by Estrin's scheme: a dependency chain of 5
 *   steps instead of Horner's 10, so short batches pipeline)
 *   (the Taylor series; |s| <= 3 - 2 sqrt 2 = 0.1716, w <= 0.0295, so the
 *   first omitted term, 2 w^11 / 23 times s, is below 3e-19 of ln z).
 * f is exact (Sterbenz), and 2s = f - s f, so
 *   ln z = f - (s f - s T) = f - s (f - T):
 * the large part f is exact and only a small correction carries round-off.
 * k ln 2 uses ln 2 split in a head with trailing zero bits (k ln2_hi is
 * exact for |k| < 2^11) and a tail.  Against long-double logl on 1e7
 * random arguments over the whole range the largest error seen was 1.1
 * ulp; tests/unit/util/test_vecmath.c checks 2 ulp against libm.
 *
 * rad_log4 passes arguments that are not positive normal numbers (0,
 * subnormal, negative, infinite, NaN) to libm's log afterwards, so those
 * results are exactly libm's.
 *
 * Arctangent atan(y/x) for x > 0 (rad_atan_core; the closed form of the
 * parallel-edge integral needs no other quadrant), by three reductions
 * (e.g. Muller, Elementary Functions, 2016, ch. 11): t = |y|/x, and
 * atan t = pi/2 - atan(1/t) for t > 1; atan z = pi/4 + atan((z-1)/(z+1))
 * for z > tan(pi/8), leaving |w| <= tan(pi/8) = 0.4142; then the Taylor
 * series atan w = sum_{j=0..19} (-1)^j w^(2j+1) / (2j+1), whose first
 * omitted term is below 2e-17 of the result.  pi/2 and pi/4 enter as head
 * and tail.  tests/unit/util/test_vecmath.c checks 4 ulp against libm's atan2.
 */
#ifndef RAD_VECMATH_H
#define RAD_VECMATH_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* The instruction-set clones of the form-factor kernels (ffgauss.c,
 * ffcontour.c): an AVX2/FMA (x86-64-v3) clone beside the baseline, picked
 * at load time by the compiler's resolver from what the CPU supports.  The
 * resolver cannot be overruled at run time, so a build that defines
 * RAD_ONE_ISA compiles the kernels for its -march alone: make bench links
 * bench/ff_rate_base and bench/ff_rate_v3 (and _v4, AVX-512) that way to
 * measure each clone's fill rate. */
#if defined(HAVE_ATTRIBUTE_TARGET_CLONES) && !defined(RAD_ONE_ISA)
#define RAD_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define RAD_KERNEL_CLONES
#endif

/* sqrt(1/2) as bits: subtracting it shifts the exponent boundary so that
 * the reduced argument lands in [sqrt(1/2), sqrt(2)). */
#define RAD_LOG_SQRT_HALF_BITS 0x3fe6a09e667f3bcdULL
#define RAD_LOG_EXP_MASK 0xfff0000000000000ULL

#if defined(__GNUC__)
#define RAD_LOG_INLINE static inline __attribute__((always_inline))
#else
#define RAD_LOG_INLINE static inline
#endif

/* The reduced argument's part of ln x, shared by the scalar and the
 * four-lane versions (T is double or rad_v4d, the same operators): from z
 * (in [sqrt(1/2), sqrt(2))) and k (as T), ln x = k ln 2 + ln z. */
#define RAD_LOG_TAIL(T, z, kd)                                                            \
    ({                                                                                   \
        /* ln 2 = LN2_HI + LN2_LO; LN2_HI has 21 trailing zero bits */                   \
        const double LN2_HI_ = 6.93147180369123816490e-01;                               \
        const double LN2_LO_ = 1.90821492927058770002e-10;                               \
        const T f_ = (z)-1.0;                                                            \
        const T s_ = f_ / (2.0 + f_);                                                    \
        const T w_ = s_ * s_;                                                            \
        /* T(w) = w Q(w), Q(w) = sum_{j=0..9} 2 w^j/(2j+3), by Estrin's scheme         \
         * (pairs, then powers w^2, w^4, w^8): a dependency chain of 5 steps           \
         * instead of Horner's 10, so short batches pipeline */                        \
        const T w2_ = w_ * w_, w4_ = w2_ * w2_, w8_ = w4_ * w4_;                         \
        const T q01_ = 2.0 / 3 + 2.0 / 5 * w_, q23_ = 2.0 / 7 + 2.0 / 9 * w_;            \
        const T q45_ = 2.0 / 11 + 2.0 / 13 * w_, q67_ = 2.0 / 15 + 2.0 / 17 * w_;        \
        const T q89_ = 2.0 / 19 + 2.0 / 21 * w_;                                         \
        const T q03_ = q01_ + q23_ * w2_, q47_ = q45_ + q67_ * w2_;                      \
        const T p_ = (q03_ + q47_ * w4_) + q89_ * w8_;                                   \
        const T tw_ = p_ * w_;                                                           \
        (kd) * LN2_HI_ + ((f_ - s_ * (f_ - tw_)) + (kd) * LN2_LO_);                      \
    })

/* ln x for a positive normal x, branch-free. */
RAD_LOG_INLINE double rad_log_core(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    const uint64_t t = b - RAD_LOG_SQRT_HALF_BITS;
    /* k = (signed) t >> 52, from the 12 top bits: sign-extend by hand (no
     * 64-bit arithmetic shift before AVX-512) and convert through 2^52 */
    const uint64_t top = (t >> 52) ^ 0x800;
    uint64_t kb = 0x4330000000000000ULL | top;
    double kd;
    memcpy(&kd, &kb, sizeof kd);
    kd -= 4503599627370496.0 + 2048.0; /* 2^52 + 2^11 */
    const uint64_t zb = b - (t & RAD_LOG_EXP_MASK);
    double z;
    memcpy(&z, &zb, sizeof z);
    return RAD_LOG_TAIL(double, z, kd);
}

/* atan(y / x) for x > 0 and finite y, branch-free. */
RAD_LOG_INLINE double rad_atan_core(double y, double x)
{
    /* pi/2 and pi/4 as double heads and tails */
    static const double PI_2 = 1.57079632679489655800e+00, PI_2_LO = 6.12323399573676603587e-17;
    static const double PI_4 = 7.85398163397448278999e-01, PI_4_LO = 3.06161699786838301793e-17;
    static const double TAN_PI_8 = 0.41421356237309504880;
    /* both sides of each reduction are computed (for t = 0, 1/t = inf is
     * discarded): conditional divisions would keep the loop scalar */
    const double t = fabs(y) / x, inv = 1 / t;
    const int big = t > 1;
    const double z = big ? inv : t, zr = (z - 1) / (z + 1);
    const int mid = z > TAN_PI_8;
    const double w = mid ? zr : z;
    /* sum_{j=0..19} (-1)^j w^2j / (2j+1), Horner, written out (a loop here
     * would keep callers' loops from vectorising) */
    const double w2 = w * w;
    double p = -1.0 / 39;
    p = p * w2 + 1.0 / 37;
    p = p * w2 + -1.0 / 35;
    p = p * w2 + 1.0 / 33;
    p = p * w2 + -1.0 / 31;
    p = p * w2 + 1.0 / 29;
    p = p * w2 + -1.0 / 27;
    p = p * w2 + 1.0 / 25;
    p = p * w2 + -1.0 / 23;
    p = p * w2 + 1.0 / 21;
    p = p * w2 + -1.0 / 19;
    p = p * w2 + 1.0 / 17;
    p = p * w2 + -1.0 / 15;
    p = p * w2 + 1.0 / 13;
    p = p * w2 + -1.0 / 11;
    p = p * w2 + 1.0 / 9;
    p = p * w2 + -1.0 / 7;
    p = p * w2 + 1.0 / 5;
    p = p * w2 + -1.0 / 3;
    p = p * w2 + 1.0 / 1;
    const double a = mid ? PI_4 + (w * p + PI_4_LO) : w * p;
    const double r = big ? (PI_2 - a) + PI_2_LO : a;
    return copysign(r, y);
}

#if defined(__GNUC__)
/* These functions are always inlined, so no call passes a vector through
 * the ABI whose AVX and SSE variants GCC warns about. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
/* Four doubles in one SIMD register (GCC vector extensions: AVX in an
 * AVX2 clone, two SSE2 halves otherwise), and their bit patterns. */
typedef double rad_v4d __attribute__((vector_size(32)));
typedef unsigned long long rad_v4u __attribute__((vector_size(32)));
typedef long long rad_v4i __attribute__((vector_size(32)));

/* rad_log_core on four lanes at once: the same arithmetic, step for step
 * (so the same results), for positive normal lanes; see rad_log4 for the
 * others. */
RAD_LOG_INLINE rad_v4d rad_log4_core(rad_v4d x)
{
    const rad_v4u b = (rad_v4u)x;
    const rad_v4u t = b - RAD_LOG_SQRT_HALF_BITS;
    const rad_v4u kb = 0x4330000000000000ULL | ((t >> 52) ^ 0x800);
    const rad_v4d kd = (rad_v4d)kb - (4503599627370496.0 + 2048.0);
    const rad_v4d z = (rad_v4d)(b - (t & RAD_LOG_EXP_MASK));
    return RAD_LOG_TAIL(rad_v4d, z, kd);
}

/* A shorter ln of four lanes for callers that budget its error: the
 * series T(w) to j = 7 (Q to w^6, Estrin's scheme in 4 steps), whose
 * first omitted term, 2 w^8 / 17 times s, is below 3.4e-14 of ln z, so the
 * result errs by at most 1.2e-14 absolute (|ln z| <= 0.35) plus round-off.
 * Positive normal lanes only. */
RAD_LOG_INLINE rad_v4d rad_log4_short(rad_v4d x)
{
    const double LN2_HI = 6.93147180369123816490e-01;
    const double LN2_LO = 1.90821492927058770002e-10;
    const rad_v4u b = (rad_v4u)x;
    const rad_v4u t = b - RAD_LOG_SQRT_HALF_BITS;
    const rad_v4u kb = 0x4330000000000000ULL | ((t >> 52) ^ 0x800);
    const rad_v4d kd = (rad_v4d)kb - (4503599627370496.0 + 2048.0);
    const rad_v4d z = (rad_v4d)(b - (t & RAD_LOG_EXP_MASK));
    const rad_v4d f = z - 1.0;
    const rad_v4d s = f / (2.0 + f);
    const rad_v4d w = s * s, w2 = w * w, w4 = w2 * w2;
    const rad_v4d q01 = 2.0 / 3 + 2.0 / 5 * w, q23 = 2.0 / 7 + 2.0 / 9 * w;
    const rad_v4d q45 = 2.0 / 11 + 2.0 / 13 * w;
    const rad_v4d p = (q01 + q23 * w2) + (q45 + (2.0 / 15) * w2) * w4;
    return kd * LN2_HI + ((f - s * (f - p * w)) + kd * LN2_LO);
}

/* ln of four lanes; lanes that are not positive normal numbers get
 * libm's log. */
RAD_LOG_INLINE rad_v4d rad_log4(rad_v4d x)
{
    rad_v4d y = rad_log4_core(x);
    const rad_v4i bad = (x >= DBL_MIN) & (x <= DBL_MAX); /* -1 where fine */
    if (__builtin_expect((bad[0] & bad[1] & bad[2] & bad[3]) != -1, 0))
        for (int i = 0; i < 4; i++)
            if (!bad[i])
                y[i] = log(x[i]);
    return y;
}
#pragma GCC diagnostic pop
#endif

#endif /* RAD_VECMATH_H */
