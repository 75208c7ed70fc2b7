#!/usr/bin/env python3
# analytic.py -- the closed forms of analytic.c over the whole positive
# double range, against the textbook formulas evaluated in mpmath.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: analytic.py LIBRADIOSITY.so [--report].  Prints TAP lines (no plan).
#
# The library's four rad_analytic_* functions are called through ctypes
# (one process for thousands of points).  The reference is each formula as
# printed in the catalogue (Howell C-11, C-14, Siegel & Howell App. C):
# nothing is rearranged, so at extreme ratios the printed forms cancel
# catastrophically (up to ~1800 digits at ratios of 1e600).  mpmath has an
# unbounded exponent, so nothing overflows, and each reference is evaluated
# at a precision doubled from 40 digits until two successive precisions
# agree to 1e-30 relative: the higher one is then good to far better than
# the 1e-13 the program promises.
#
# Tolerance: 1e-13 relative when the reference is a normal double
# (>= DBL_MIN = 2.2e-308); a result below DBL_MIN can only be held to an
# absolute 1e-13 * DBL_MIN (subnormals carry fewer digits), and one whose
# reference is below half the smallest subnormal may be 0.  The grid puts
# each argument (or ratio) on 1e-300, 1e-250, ..., 1e300 plus points near 1,
# and repeats a few triples scaled by 1e+-300 (scale invariance).
# Reciprocity A1 F12 = A2 F21 is checked at every grid point too.
import ctypes
import sys

import mpmath as mp

TOL = 1e-13
DBL_MIN = 2.2250738585072014e-308
DBL_TRUE_MIN = 5e-324


# ---- references: the printed formulas ------------------------------------

def point_disk(r, h):
    # [SH] App. C: F = R^2 / (H^2 + R^2)
    return r * r / (h * h + r * r)


def disk_disk(r1, r2, h):
    # [SH] App. C: R_i = r_i/h, X = 1 + (1 + R2^2)/R1^2,
    # F = (X - sqrt(X^2 - 4 (R2/R1)^2)) / 2
    R1, R2 = r1 / h, r2 / h
    X = 1 + (1 + R2 * R2) / (R1 * R1)
    return (X - mp.sqrt(X * X - 4 * (R2 / R1) ** 2)) / 2


def parallel(a, b, c):
    # [H] C-11, X = a/c, Y = b/c
    X, Y = a / c, b / c
    X2, Y2 = X * X, Y * Y
    br = (mp.log(mp.sqrt((1 + X2) * (1 + Y2) / (1 + X2 + Y2)))
          + X * mp.sqrt(1 + Y2) * mp.atan(X / mp.sqrt(1 + Y2))
          + Y * mp.sqrt(1 + X2) * mp.atan(Y / mp.sqrt(1 + X2))
          - X * mp.atan(X) - Y * mp.atan(Y))
    return 2 * br / (mp.pi * X * Y)


def perpendicular(l, w, h):
    # [H] C-14, W = w/l, H = h/l; the logarithm of the product is taken
    # as the sum of the logarithms of its factors (exponents pulled out)
    W, H = w / l, h / l
    W2, H2 = W * W, H * H
    R2 = W2 + H2
    R = mp.sqrt(R2)
    lg = (mp.log((1 + W2) * (1 + H2) / (1 + R2))
          + W2 * mp.log(W2 * (1 + R2) / ((1 + W2) * R2))
          + H2 * mp.log(H2 * (1 + R2) / ((1 + H2) * R2)))
    br = (W * mp.atan(1 / W) + H * mp.atan(1 / H) - R * mp.atan(1 / R)
          + lg / 4)
    return br / (mp.pi * W)


def reference(f, args):
    """f(args) at a precision where it agrees with twice that precision
    to 1e-30.  The printed formulas lose up to about 4 digits per decade
    of the most extreme ratio of arguments (terms of size X^2 cancel down
    to 1/X^2), so the first precision already covers that loss: two low
    precisions can otherwise agree on the same rounding residue."""
    decades = max(abs(mp.log10(mp.mpf(x) / mp.mpf(y)))
                  for x in args for y in args)
    dps = 40 + 4 * int(decades)
    while dps <= 40000:
        with mp.workdps(dps):
            v = f(*[mp.mpf(x) for x in args])
        with mp.workdps(2 * dps):
            w = f(*[mp.mpf(x) for x in args])
        if w != 0 and abs(v - w) <= abs(w) * mp.mpf(10) ** -30:
            return w
        dps *= 2
    raise RuntimeError("no convergence for %s%r" % (f.__name__, args))


# ---- the grid ---------------------------------------------------------------

DECADES = [10.0 ** e for e in range(-300, 301, 50)]
NEAR_ONE = [1e-20, 1e-8, 1e-3, 0.3, 1.0, 3.0, 1e3, 1e8, 1e20]
# where squares overflow or underflow (1e+-154), and both sides of the
# switch-over ratio 2^40 of analytic.c
EDGES = [1e-160, 1e160, 2.0 ** -40 * 0.999, 2.0 ** -40 * 1.001,
         2.0 ** 40 * 0.999, 2.0 ** 40 * 1.001]
VALUES = sorted(set(DECADES + NEAR_ONE + EDGES))


def ratio_grid(n):
    """n-tuples of positive doubles: the last argument 1, the others over
    VALUES (for 3 arguments), and the lists repeated at scales 1e+-300."""
    pts = []
    if n == 2:
        for x in VALUES:
            pts.append((x, 1.0))
            pts.append((1.0, x))
    else:
        for x in VALUES:
            for y in VALUES:
                pts.append((x, y, 1.0))
    # permutations of a few triples with extreme ratios, the absolute
    # scale moved by 1e+-300 where it stays representable
    extra = []
    for t in [(1e300, 1e-300, 1.0), (1e300, 1e300, 1e-300),
              (1e-300, 1e-300, 1e300), (1e300, 1e-10, 1e-300),
              (1e-300, 1e-150, 1e-290), (1e300, 1e-300, 1e-300)]:
        t = t[:n]
        for p in set(_perms(t)):
            extra.append(p)
    for s in (1e-300, 1e300):
        for p in [(1.0, 1.0, 1.0), (2.0, 3.0, 0.5), (1.0, 1e-8, 1e8)]:
            q = tuple(x * s for x in p[:n])
            extra.append(q)
    return pts + extra


def _perms(t):
    if len(t) <= 1:
        return [t]
    out = []
    for i in range(len(t)):
        for rest in _perms(t[:i] + t[i + 1:]):
            out.append((t[i],) + rest)
    return out


# ---- checks -----------------------------------------------------------------

def within(got, want):
    """|got - want| <= 1e-13 want, relaxed for a subnormal reference."""
    if not (got == got) or got < 0 or got == float("inf"):
        return False, float("inf")
    want = mp.mpf(want)
    if want >= DBL_MIN:
        err = abs(mp.mpf(got) - want) / want
        return err <= TOL, float(err)
    err = abs(mp.mpf(got) - want) / DBL_MIN
    return err <= TOL, float(err)


def reciprocity(name, fn, n):
    """A1 F12 = A2 F21: r1^2 F(r1, r2, h) = r2^2 F(r2, r1, h) for disks,
    w F(l, w, h) = h F(l, h, w) for perpendicular rectangles (products
    taken exactly in mpmath); F(a, b, c) = F(b, a, c) for the opposed
    rectangles (equal areas).  Both sides must agree to 1e-13 wherever
    both values are normal doubles."""
    worst, worst_at, bad, count = 0.0, None, [], 0
    for args in ratio_grid(n):
        x, y, z = args
        if name == "disk-disk":
            p, q = fn(x, y, z), fn(y, x, z)
            lhs, rhs = mp.mpf(x) ** 2 * mp.mpf(p), mp.mpf(y) ** 2 * mp.mpf(q)
        elif name == "perpendicular-rectangles":
            p, q = fn(x, y, z), fn(x, z, y)
            lhs, rhs = mp.mpf(y) * mp.mpf(p), mp.mpf(z) * mp.mpf(q)
        else:
            p, q = fn(x, y, z), fn(y, x, z)
            lhs, rhs = mp.mpf(p), mp.mpf(q)
        if not (p >= DBL_MIN and q >= DBL_MIN):
            continue
        err = float(abs(lhs - rhs) / abs(rhs))
        count += 1
        if err > worst or worst_at is None:
            worst, worst_at = err, args
        if not err <= TOL:
            bad.append((args, p, q, err))
    for args, p, q, err in bad[:20]:
        print("# %s%r reciprocity: %.17g vs %.17g (err %.3g)"
              % (name, args, p, q, err))
    print("%s - %s reciprocity A1 F12 = A2 F21: %d points, worst error %.3g"
          " at %r (tol %g)" % ("not ok" if bad else "ok", name, count, worst,
                               worst_at, TOL))


def main():
    lib = ctypes.CDLL(sys.argv[1])
    report = "--report" in sys.argv
    cases = [
        ("point-disk", lib.rad_analytic_point_disk, point_disk, 2),
        ("disk-disk", lib.rad_analytic_disk_disk, disk_disk, 3),
        ("parallel-rectangles", lib.rad_analytic_parallel_rectangles,
         parallel, 3),
        ("perpendicular-rectangles",
         lib.rad_analytic_perpendicular_rectangles, perpendicular, 3),
    ]
    for name, fn, ref, n in cases:
        fn.restype = ctypes.c_double
        fn.argtypes = [ctypes.c_double] * n
        worst, worst_at, bad, count = 0.0, None, [], 0
        for args in ratio_grid(n):
            want = reference(ref, args)
            got = fn(*args)
            good, err = within(got, want)
            count += 1
            if err > worst or worst_at is None:
                worst, worst_at = err, args
            if not good:
                bad.append((args, got, want, err))
            if report:
                print("# %s %r got %.17g want %s err %.3g"
                      % (name, args, got, mp.nstr(want, 20), err))
        for args, got, want, err in bad[:20]:
            print("# %s%r: got %.17g, want %s (err %.3g)"
                  % (name, args, got, mp.nstr(want, 20), err))
        print("%s - %s: %d points over 1e-300..1e300, worst error %.3g"
              " (relative; in units of DBL_MIN below it) at %r"
              " (tol %g)" % ("not ok" if bad else "ok", name, count, worst,
                            worst_at, TOL))
        if n == 3:
            reciprocity(name, fn, n)


if __name__ == "__main__":
    main()
