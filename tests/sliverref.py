#!/usr/bin/env python3
"""sliverref.py -- an independent form factor from a sliver triangle to a
triangle that shares its long edge, for tests/accuracy/sliver.sh.

Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.

Nothing here is the program's method.  The sliver S has vertices (0,0,0),
(1,0,0), (0.5,H,0) and faces +z; the triangle T has (0,0,0),
(0.3,-0.5,0.866), (1,0,0) and faces up and towards S.  From a point x of
S the factor to T is Lambert's (1760), as Baum, Rushmeier & Winget 1989
write it:
    F(x -> T) = |sum_k gamma_k n_x . (R_k x R_k+1) / |R_k x R_k+1|| / (2 pi),
and F(S -> T) = (1/A_S) int_S F(x -> T) dx.  With x = (0.5 v + (1 - v) u,
H v, 0), u and v in [0, 1], dx = H (1 - v) du dv and A_S = H / 2, so
    F(S -> T) = 2 int_0^1 (1 - v) int_0^1 F(x(u, v) -> T) du dv.
On the shared edge F(x -> T) is the same at every point (the planes
through x and T's other edges are T's plane), so the integrand is smooth
but near the edge's ends, where it turns within a distance H v.  The
integral is taken of F - c, c = F at 1e-12 above the edge's middle (any
constant would do, since the measure has mass 1; this one leaves small
differences to round), by Gauss-Legendre rules of N
points on panels graded geometrically towards u = 0, u = 1 and v = 0
(ends 10^-1 .. 10^-16).  Prints the value for N = 12 and N = 20: their
difference is this computation's error estimate.

Usage: sliverref.py H
"""
import math
import sys

T = [(0.0, 0.0, 0.0), (0.3, -0.5, 0.866), (1.0, 0.0, 0.0)]


def ff(x):
    s = 0.0
    for k in range(3):
        a, b = T[k], T[(k + 1) % 3]
        r0 = (a[0] - x[0], a[1] - x[1], a[2] - x[2])
        r1 = (b[0] - x[0], b[1] - x[1], b[2] - x[2])
        c = (r0[1] * r1[2] - r0[2] * r1[1], r0[2] * r1[0] - r0[0] * r1[2],
             r0[0] * r1[1] - r0[1] * r1[0])
        cn = math.sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2])
        if cn > 0:
            s += math.atan2(cn, r0[0] * r1[0] + r0[1] * r1[1] + r0[2] * r1[2]) * c[2] / cn
    return abs(s) / (2 * math.pi)


def legendre(n):
    """Nodes and weights on [-1, 1] (Newton's method on P_n)."""
    xs, ws = [], []
    for i in range(1, n + 1):
        z = math.cos(math.pi * (i - 0.25) / (n + 0.5))
        for _ in range(100):
            p1, p2 = 1.0, 0.0
            for j in range(1, n + 1):
                p1, p2 = ((2 * j - 1) * z * p1 - (j - 1) * p2) / j, p1
            dp = n * (z * p1 - p2) / (z * z - 1)
            z, old = z - p1 / dp, z
            if abs(z - old) < 1e-16:
                break
        xs.append(z)
        ws.append(2 / ((1 - z * z) * dp * dp))
    return xs, ws


def rule(ends, n):
    xs, ws = legendre(n)
    pts = []
    for a, b in zip(ends[:-1], ends[1:]):
        pts += [(a + (b - a) * (x + 1) / 2, (b - a) / 2 * w) for x, w in zip(xs, ws)]
    return pts


def sliver(h, n):
    fine = [10.0 ** -k for k in range(16, 0, -1)]
    us = rule([0.0] + fine + [0.5] + [1 - f for f in reversed(fine)] + [1.0], n)
    vs = rule([0.0] + fine + [1.0], n)
    c = ff((0.5, 1e-12, 0.0))
    total = 0.0
    for v, wv in vs:
        inner = sum(wu * (ff((0.5 * v + (1 - v) * u, h * v, 0.0)) - c) for u, wu in us)
        total += wv * (1 - v) * inner
    return c + 2 * total


if __name__ == "__main__":
    h = float(sys.argv[1])
    print("%.17g %.17g" % (sliver(h, 12), sliver(h, 20)))
