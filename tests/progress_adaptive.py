#!/usr/bin/env python3
# progress_adaptive.py -- independent checks of `progress --adaptive`
# (tests/papers/progress_adaptive.sh).
#
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage:
#   progress_adaptive.py project STEP.tsv FINAL.tsv   eq. 14 of STEP against
#                                                     FINAL projected onto it
#   progress_adaptive.py grey ERROR.png                pixels of an error image
#                                                     that are neither black
#                                                     (background) nor grey
#
# project: both are element tables with the column level (solve --elements
# --adaptive, progress --snapshot-elements).  An element is the square
# (surface, level, gi, gj) of its surface's grid at its level; a final
# element (s, l', i', j') lies inside a step element (s, l, i, j) when
# l' >= l and (i' >> (l' - l), j' >> (l' - l)) = (i, j), and contains it
# when l' < l and (i >> (l - l'), j >> (l - l')) = (i', j').  The step
# element's reference is the area mean of the final elements inside it, or
# the value of the one containing it.  Then, with Y the band-averaged
# radiosity (r + g + b) / 3 (Cohen et al. 1988, eq. 14),
#     RMS = sqrt( sum_j A_j (Y_j - Yref_j)^2 / sum_j A_j )
# over the step's elements.  This reads only the tables' columns, not the
# program's node numbering.  Prints: rms elements
#
# grey: the error picture colours an element (128, 128, 128) where its
# error is 0 (errcolour.c); the background is black.  Prints: count total
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from adaptive_rms import png_rgb  # noqa: E402


def read_levels(path):
    with open(path) as f:
        head = f.readline().rstrip('\n').split('\t')
        col = {name: k for k, name in enumerate(head)}
        if 'level' not in col:
            sys.exit('progress_adaptive.py: %s has no column level' % path)
        rows = []
        for line in f:
            v = line.rstrip('\n').split('\t')
            rows.append((int(v[col['surface']]), int(v[col['level']]), int(v[col['gi']]),
                         int(v[col['gj']]), float(v[col['area']]),
                         (float(v[col['r']]) + float(v[col['g']]) + float(v[col['b']])) / 3))
    return rows


def reference(e, final):
    s, l, i, j = e[:4]
    inside = [f for f in final if f[0] == s and f[1] >= l and
              (f[2] >> (f[1] - l), f[3] >> (f[1] - l)) == (i, j)]
    if inside:
        return sum(f[4] * f[5] for f in inside) / sum(f[4] for f in inside)
    around = [f for f in final if f[0] == s and f[1] < l and
              (i >> (l - f[1]), j >> (l - f[1])) == (f[2], f[3])]
    if len(around) != 1:
        sys.exit('progress_adaptive.py: element %r is covered by no final element' % (e[:4],))
    return around[0][5]


def project(step_path, final_path):
    step, final = read_levels(step_path), read_levels(final_path)
    num = sum(e[4] * (e[5] - reference(e, final)) ** 2 for e in step)
    return (num / sum(e[4] for e in step)) ** 0.5, len(step)


def grey(path):
    w, h, rows = png_rgb(path)
    odd = 0
    for line in rows:
        for x in range(w):
            px = tuple(line[3 * x:3 * x + 3])
            odd += px not in ((0, 0, 0), (128, 128, 128))
    return odd, w * h


def main():
    if len(sys.argv) == 4 and sys.argv[1] == 'project':
        print('%.17g %d' % project(sys.argv[2], sys.argv[3]))
    elif len(sys.argv) == 3 and sys.argv[1] == 'grey':
        print('%d %d' % grey(sys.argv[2]))
    else:
        sys.exit('usage: progress_adaptive.py project STEP.tsv FINAL.tsv | grey ERROR.png')


main()
