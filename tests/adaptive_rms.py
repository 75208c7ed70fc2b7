#!/usr/bin/env python3
# adaptive_rms.py -- compare element tables on a common grid, for the
# adaptive-subdivision tests (tests/adaptive.sh) and figure.
#
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage:
#   adaptive_rms.py rms REF.tsv X.tsv     area-weighted RMS error of X against REF
#   adaptive_rms.py shadow SCENE X.tsv    share of subdivided elements near the
#                                         shadow boundary (see below)
#
# rms: the reference is a uniform fine mesh (e.g. 32 x 32 per surface); every
# element of X, uniform or adaptive, is a union of reference elements (its
# grid lines are among the reference's).  X is brought onto the reference
# grid by area averaging: a piecewise-constant field averaged over a
# reference element that lies inside one X element is that element's value,
# which is X's value at the reference element's centroid.  So each
# reference element r takes the value of the X element of the same surface
# containing its centroid, and
#     RMS = sqrt( sum_r A_r (Bx_r - Bref_r)^2 / sum_r A_r )
# over all surfaces, with B the band-averaged radiosity (r + g + b) / 3
# (Cohen et al. 1988, eq. 14).  Containment assumes axis-aligned square
# elements (data/blocker.scene): |c - centroid| <= side/2 along the two axes
# of the surface's plane; a reference centroid that no X element contains is
# an error.  Prints: rms elements
#
# shadow: the boundary of the shadow the blocker casts from the light on a
# receiver, computed from the scene's geometry alone.  For planes normal to
# z (data/blocker.scene: light at z = 0, blocker at z = 0.5, receiver at
# z = 1), the visibility of the light from a receiver point changes
# character where a light edge and a parallel blocker edge line up
# (edge-edge critical lines of discontinuity meshing: Heckbert, "Discontinuity
# meshing for radiosity", 1992; Lischinski, Tampieri & Greenberg 1992): the
# line through the light edge at coordinate a (z = zl) and the blocker edge
# at coordinate b (z = zb) meets the receiver z = zr at
#     a + (b - a) (zr - zl) / (zb - zl),
# in x and in y.  The boundary is those lines inside the receiver.  A
# subdivided element (level >= 1) lies "within one parent-element width"
# of it when it is on the receiver and its centroid's distance to the
# nearest line is at most its parent's side (twice its own).
# Prints: share near subdivided
import math
import sys


def read_table(path):
    with open(path) as f:
        head = f.readline().rstrip('\n').split('\t')
        col = {name: k for k, name in enumerate(head)}
        rows = []
        for line in f:
            v = line.rstrip('\n').split('\t')
            rows.append({
                's': int(v[col['surface']]),
                'c': (float(v[col['cx']]), float(v[col['cy']]), float(v[col['cz']])),
                'n': (float(v[col['nx']]), float(v[col['ny']]), float(v[col['nz']])),
                'a': float(v[col['area']]),
                'b': (float(v[col['r']]) + float(v[col['g']]) + float(v[col['b']])) / 3,
                'level': int(v[col['level']]) if 'level' in col else 0,
            })
    return rows


def plane_axes(n):
    k = max(range(3), key=lambda i: abs(n[i]))
    return [i for i in range(3) if i != k]


def contains(e, c):
    half = math.sqrt(e['a']) / 2
    return all(abs(c[i] - e['c'][i]) <= half * (1 + 1e-9) for i in plane_axes(e['n']))


def rms(ref, x):
    by_surface = {}
    for e in x:
        by_surface.setdefault(e['s'], []).append(e)
    num = den = 0.0
    for r in ref:
        hit = [e for e in by_surface.get(r['s'], []) if contains(e, r['c'])]
        if not hit:
            sys.exit('adaptive_rms.py: no element of surface %d contains %r' % (r['s'], r['c']))
        num += r['a'] * (hit[0]['b'] - r['b']) ** 2
        den += r['a']
    return math.sqrt(num / den)


def read_quads(path):
    mats, quads = {}, []
    with open(path) as f:
        for line in f:
            t = line.split('#')[0].split()
            if not t:
                continue
            if t[0] == 'material':
                mats[t[1]] = 'emit' in t and float(t[t.index('emit') + 1]) > 0
            elif t[0] == 'quad':
                p = [tuple(float(t[2 + 3 * k + i]) for i in range(3)) for k in range(4)]
                quads.append((mats[t[1]], p))
    return quads


def shadow_lines(scene):
    """Critical lines (axis, value) on the receivers, and the receivers' z."""
    quads = read_quads(scene)
    light = [p for emit, p in quads if emit][0]
    zl = light[0][2]
    planes = sorted({p[0][2] for emit, p in quads if not emit}, key=lambda z: abs(z - zl))
    zb, zr = planes[0], planes[-1]  # the blocker nearest the light, the receiver farthest
    blocker = [p for emit, p in quads if not emit and p[0][2] == zb][0]
    receiver = [p for emit, p in quads if not emit and p[0][2] == zr][0]
    lines = []
    for axis in (0, 1):
        lo = min(v[axis] for v in receiver)
        hi = max(v[axis] for v in receiver)
        for a in {v[axis] for v in light}:
            for b in {v[axis] for v in blocker}:
                u = a + (b - a) * (zr - zl) / (zb - zl)
                if lo <= u <= hi:
                    lines.append((axis, u))
    return lines, zr


def shadow_share(scene, x):
    lines, zr = shadow_lines(scene)
    sub = [e for e in x if e['level'] >= 1]
    near = 0
    for e in sub:
        if abs(e['c'][2] - zr) > 1e-9:
            continue
        d = min(abs(e['c'][axis] - u) for axis, u in lines)
        near += d <= 2 * math.sqrt(e['a']) * (1 + 1e-9)
    return near, len(sub)


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in ('rms', 'shadow'):
        sys.exit('usage: adaptive_rms.py rms REF.tsv X.tsv | shadow SCENE X.tsv')
    if sys.argv[1] == 'rms':
        x = read_table(sys.argv[3])
        print('%.10g %d' % (rms(read_table(sys.argv[2]), x), len(x)))
    else:
        near, sub = shadow_share(sys.argv[2], read_table(sys.argv[3]))
        print('%.4f %d %d' % (near / sub if sub else 0.0, near, sub))


main()
