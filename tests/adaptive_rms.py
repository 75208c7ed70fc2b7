#!/usr/bin/env python3
# adaptive_rms.py -- compare element tables on a common grid, for the
# adaptive-subdivision tests (tests/papers/adaptive.sh) and figure.
#
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage:
#   adaptive_rms.py rms REF.tsv X.tsv     area-weighted RMS error of X against REF
#   adaptive_rms.py smooth REF.tsv X.ply  the same for X's smoothed (vertex)
#                                         radiosity, bilinear in each element
#   adaptive_rms.py shadow SCENE X.tsv    share of subdivided elements near the
#                                         shadow boundary (see below)
#   adaptive_rms.py cracks A.png B.png    background pixels of A that are not
#                                         background in B (see below)
#   adaptive_rms.py seams X.ply -         largest jump of the smoothed radiosity
#                                         across the mesh's T-junctions
#   adaptive_rms.py oracle REF.tsv S:RMS SCENE  the fewest elements any
#                                         quadtree from S x S can have at
#                                         error RMS, and its shadow share
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
#
# smooth: as rms, but X is the vertex radiosity of a solution PLY,
# interpolated bilinearly from each element's four corners (hanging
# vertices lie on the sides and carry the interpolated value already).
#
# seams: a vertex of X that lies on a side of an element but is not one of
# its corners (a hanging vertex) must carry the value the element's
# bilinear interpolation has there, or Gouraud shading jumps across that
# side.  Prints: largest |difference| and the number of such pairs.
#
# oracle: the best any adaptive subdivision can do in the rms measure.
# The candidates are the quadtrees over each surface's S x S starting
# elements whose leaves are unions of reference elements (S divides the
# reference's 32; depth down to the reference's cells: deeper leaves are
# averaged back onto them by rms, so they cannot help).  Each leaf is given
# the area average of the reference over it, the value that minimises its
# share of the squared error (no solver can do better: rms is then the
# representation error alone).  A leaf's share is sum_r A_r (B_r - mean)^2;
# the fewest leaves at which the sum over all leaves is at most
# RMS^2 sum A is found exactly by dynamic programming over the trees
# (per node: the least error with k leaves, as a leaf or as the best split
# of k among its four children; then across the starting elements).  The
# tree it finds is passed to shadow as an element table.  Prints:
# min_leaves rms_at_min shadow_share near subdivided
#
# cracks: both images are 8-bit RGB PNGs (the renderer's); background is
# exactly black (0, 0, 0), which no surface of data/blocker.scene reaches
# (its darkest radiosity, about 0.005, tone-maps to a byte near 17).  A is
# the adaptive picture, B one of the same scene and camera on a uniform
# mesh (no T-junctions): a pixel black in A but not in B is a crack.
# Prints: cracks background_pixels_of_A
import math
import struct
import sys
import zlib


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


def read_ply(path):
    """Faces of a solution PLY as elements with their corner vertex values."""
    return read_ply_all(path)[1]


def read_ply_all(path):
    with open(path) as f:
        lines = f.read().split('\n')
    k = lines.index('end_header')
    nv = int([l for l in lines[:k] if l.startswith('element vertex')][0].split()[2])
    verts = []
    for l in lines[k + 1:k + 1 + nv]:
        v = [float(t) for t in l.split()]
        verts.append(((v[0], v[1], v[2]), (v[3] + v[4] + v[5]) / 3))
    faces, vsurf = [], {}
    for l in lines[k + 1 + nv:]:
        t = l.split()
        if not t:
            continue
        n = int(t[0])
        idx = [int(x) for x in t[1:1 + n]]
        pts = [verts[i] for i in idx]
        for i in idx:
            vsurf[i] = int(t[1 + n])
        lo = [min(p[0][i] for p in pts) for i in range(3)]
        hi = [max(p[0][i] for p in pts) for i in range(3)]
        axes = [i for i in range(3) if hi[i] > lo[i]]
        corner = {}
        for p, b in pts:  # the box's corners (hanging vertices lie on its sides)
            key = tuple(p[i] == lo[i] for i in axes)
            if all(p[i] in (lo[i], hi[i]) for i in axes):
                corner[key] = b
        faces.append({'s': int(t[1 + n]), 'lo': lo, 'hi': hi, 'axes': axes, 'corner': corner})
    return [(p, b, vsurf.get(v)) for v, (p, b) in enumerate(verts)], faces


def seams(path):
    verts, faces = read_ply_all(path)
    worst, pairs = 0.0, 0
    for p, b, surf in verts:
        for f in faces:
            i, j = f['axes']
            if f['s'] != surf:
                continue
            if not all(f['lo'][k] <= p[k] <= f['hi'][k] for k in (i, j)):
                continue
            on_side = p[i] in (f['lo'][i], f['hi'][i]) or p[j] in (f['lo'][j], f['hi'][j])
            corner = p[i] in (f['lo'][i], f['hi'][i]) and p[j] in (f['lo'][j], f['hi'][j])
            if not on_side or corner:
                continue
            worst = max(worst, abs(smooth_value(f, p) - b))
            pairs += 1
    return worst, pairs


def smooth_value(f, c):
    """The bilinear interpolation of the face's corner values at c, or None."""
    i, j = f['axes']
    if not all(f['lo'][k] - 1e-12 <= c[k] <= f['hi'][k] + 1e-12 for k in (i, j)):
        return None
    u = (c[i] - f['lo'][i]) / (f['hi'][i] - f['lo'][i])
    v = (c[j] - f['lo'][j]) / (f['hi'][j] - f['lo'][j])
    q = f['corner']
    return ((1 - u) * (1 - v) * q[(True, True)] + u * (1 - v) * q[(False, True)] +
            u * v * q[(False, False)] + (1 - u) * v * q[(True, False)])


def rms_smooth(ref, faces):
    by_surface = {}
    for f in faces:
        by_surface.setdefault(f['s'], []).append(f)
    num = den = 0.0
    for r in ref:
        vals = [smooth_value(f, r['c']) for f in by_surface.get(r['s'], [])]
        vals = [x for x in vals if x is not None]
        if not vals:
            sys.exit('adaptive_rms.py: no face of surface %d contains %r' % (r['s'], r['c']))
        num += r['a'] * (vals[0] - r['b']) ** 2
        den += r['a']
    return math.sqrt(num / den)


def png_rgb(path):
    """Width, height and rows of bytes of an 8-bit RGB non-interlaced PNG."""
    with open(path, 'rb') as f:
        data = f.read()
    pos, idat, w = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, ctype, _, _, lace = struct.unpack('>IIBBBBB', body)
            if depth != 8 or ctype != 2 or lace != 0:
                sys.exit('adaptive_rms.py: %s is not 8-bit RGB' % path)
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), 3 * w, [], bytearray(3 * w)
    for y in range(h):
        ftype, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):  # PNG filters (PNG specification, section 9)
            a = line[x - 3] if x >= 3 else 0
            b, c = prev[x], prev[x - 3] if x >= 3 else 0
            if ftype == 1:
                line[x] = (line[x] + a) & 255
            elif ftype == 2:
                line[x] = (line[x] + b) & 255
            elif ftype == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else b if pb <= pc else c
                line[x] = (line[x] + pred) & 255
        rows.append(line)
        prev = line
    return w, h, rows


def cracks(a_path, b_path):
    wa, ha, a = png_rgb(a_path)
    wb, hb, b = png_rgb(b_path)
    if (wa, ha) != (wb, hb):
        sys.exit('adaptive_rms.py: the pictures differ in size')
    bad = bg = 0
    for y in range(ha):
        for x in range(wa):
            black_a = a[y][3 * x:3 * x + 3] == b'\0\0\0'
            black_b = b[y][3 * x:3 * x + 3] == b'\0\0\0'
            bg += black_a
            bad += black_a and not black_b
    return bad, bg


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


def ref_grid(path):
    """Reference elements by surface and grid index (gi, gj)."""
    grids = {}
    with open(path) as f:
        head = f.readline().rstrip('\n').split('\t')
        col = {name: k for k, name in enumerate(head)}
        for line in f:
            v = line.rstrip('\n').split('\t')
            s = int(v[col['surface']])
            grids.setdefault(s, {})[(int(v[col['gi']]), int(v[col['gj']]))] = {
                'c': tuple(float(v[col[k]]) for k in ('cx', 'cy', 'cz')),
                'a': float(v[col['area']]),
                'b': sum(float(v[col[k]]) for k in ('r', 'g', 'b')) / 3}
    return grids


def oracle(ref_path, start, target, scene):
    grids = ref_grid(ref_path)
    inf = float('inf')

    def cells(g, i, j, n):
        return [g[(x, y)] for x in range(i, i + n) for y in range(j, j + n)]

    def leaf_error(g, i, j, n):
        c = cells(g, i, j, n)
        area = sum(r['a'] for r in c)
        mean = sum(r['a'] * r['b'] for r in c) / area
        return sum(r['a'] * (r['b'] - mean) ** 2 for r in c)

    def merge(tables):
        """Least error with k leaves over several independent subtrees."""
        acc = {0: (0.0, ())}
        for t in tables:
            new = {}
            for k1, (e1, w1) in acc.items():
                for k2, (e2, _) in t.items():
                    if e1 + e2 < new.get(k1 + k2, (inf,))[0]:
                        new[k1 + k2] = (e1 + e2, w1 + (k2,))
            acc = new
        return acc

    def node(g, i, j, n, memo):
        # memo[(i, j, n)]: k -> (error, children's k or None for a leaf)
        best = {1: (leaf_error(g, i, j, n), None)}
        if n > 1:
            m = n // 2
            kids = [(i + a * m, j + b * m, m) for a in (0, 1) for b in (0, 1)]
            split = merge([node(g, *k, memo) for k in kids])
            for k, (e, w) in split.items():
                if e < best.get(k, (inf,))[0]:
                    best[k] = (e, w)
        memo[(i, j, n)] = best
        return best

    def leaves(g, i, j, n, k, memo, level, out):
        e, w = memo[(i, j, n)][k]
        if w is None:
            c = cells(g, i, j, n)
            area = sum(r['a'] for r in c)
            out.append({'c': tuple(sum(r['c'][d] * r['a'] for r in c) / area for d in range(3)),
                        'a': area, 'level': level})
            return
        m = n // 2
        for (a, b), kk in zip([(0, 0), (0, 1), (1, 0), (1, 1)], w):
            leaves(g, i + a * m, j + b * m, m, kk, memo, level + 1, out)

    roots, total_area = [], 0.0
    for s, g in sorted(grids.items()):
        size = max(i for i, _ in g) + 1
        if size % start or max(j for _, j in g) + 1 != size:
            sys.exit('adaptive_rms.py: the reference is not a square grid %d divides' % start)
        n = size // start
        total_area += sum(r['a'] for r in g.values())
        for I in range(start):
            for J in range(start):
                memo = {}
                roots.append((g, I * n, J * n, n, memo, node(g, I * n, J * n, n, memo)))
    whole = merge([r[5] for r in roots])
    bound = target ** 2 * total_area
    k = min(k for k, (e, _) in whole.items() if e <= bound * (1 + 1e-12))
    tree = []
    for (g, i, j, n, memo, _), kk in zip(roots, whole[k][1]):
        leaves(g, i, j, n, kk, memo, 0, tree)
    near, sub = shadow_share(scene, tree)
    return k, math.sqrt(whole[k][0] / total_area), near, sub


def main():
    if len(sys.argv) == 5 and sys.argv[1] == 'oracle':
        start, target = sys.argv[3].split(':')
        k, r, near, sub = oracle(sys.argv[2], int(start), float(target), sys.argv[4])
        print('%d %.10g %.4f %d %d' % (k, r, near / sub if sub else 0.0, near, sub))
        return
    if len(sys.argv) != 4 or sys.argv[1] not in ('rms', 'smooth', 'shadow', 'cracks', 'seams'):
        sys.exit('usage: adaptive_rms.py rms|smooth REF.tsv X.tsv|X.ply | shadow SCENE X.tsv'
                 ' | cracks A.png B.png')
    if sys.argv[1] == 'seams':
        print('%.3g %d' % seams(sys.argv[2]))
        return
    if sys.argv[1] == 'cracks':
        print('%d %d' % cracks(sys.argv[2], sys.argv[3]))
        return
    if sys.argv[1] == 'smooth':
        f = read_ply(sys.argv[3])
        print('%.10g %d' % (rms_smooth(read_table(sys.argv[2]), f), len(f)))
    elif sys.argv[1] == 'rms':
        x = read_table(sys.argv[3])
        print('%.10g %d' % (rms(read_table(sys.argv[2]), x), len(x)))
    else:
        near, sub = shadow_share(sys.argv[2], read_table(sys.argv[3]))
        print('%.4f %d %d' % (near / sub if sub else 0.0, near, sub))


if __name__ == '__main__':  # importable: tests/progress_adaptive.py reads PNGs with it
    main()
