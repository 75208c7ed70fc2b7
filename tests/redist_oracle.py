#!/usr/bin/env python3
# redist_oracle.py -- the least eq. 7 error any two redistribution steps can
# reach on the patches a change alters most (George, Sillion & Greenberg
# 1990, eq. 2-7).
#
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# usage: redist_oracle.py best SCENE F_OLD.npy F_NEW.npy PREV.tsv REF.tsv [SEQ...]
#        redist_oracle.py eq7 PREV.tsv REF.tsv TABLE...
#
# eq7 prints, for each TABLE (an element table of the changed scene), its
# error against REF overall (George et al. 1990, eq. 7: sum A |Y - Yref|
# over sum A Yref) and on the mask below, normalised by the change.
#
# best:
# SCENE is the changed scene (every surface present, for the reflectances:
# "material NAME reflect R [G B]" and the material name after each surface
# keyword), F_OLD.npy / F_NEW.npy the form factors before and after the
# change (`radiosity formfactor -o F.npy`; the first n_old elements of the
# new mesh are the old mesh's, in the same order: the change adds an object
# after them), PREV.tsv the converged table before the change, REF.tsv the
# converged table after it (`solve --elements`).  Pure Python: no numpy.
#
# The model is that of src/anim/animshoot.c, written here from the
# paper's equations and not from the program's code.  At the change,
# every element j has shot T_j = B_j (a converged frame; an added element
# has T = 0) along the old factors; pair (i, j) with dF_ij = Fnew_ij -
# Fold_ij != 0 owes receiver i the amount rho_i dF_ij T_j (George et al.
# 1990, eq. 4-6).  A step is one of
#   R j  redistribution shot of j: every pending entry (., j) is paid;
#   G i  gather by receiver i: every pending entry (i, .) is paid;
#   P j  propagation shot of j: every i gets rho_i Fnew_ij dB_j, where dB_j
#        is what j received since the change (Cohen et al. 1988, eq. 4).
# Paid entries are paid once.  Only the patches of the mask matter for the
# measure: the top 1% (at least one) of elements by A |Yref - Yprev|, the
# error sum_M A |Y - Yref| over sum_M A |Yref - Yprev| (rad_anim_error_
# changed in animerror.c; Y the BT.709 luminance).  The oracle tries every
# sequence of two steps and prints the least error and the sequence that
# reaches it: no ordering rule, importance estimate or strategy can do
# better in two steps.  SEQ (e.g. "R0 R277") prints the error of given
# sequences too, to check the model against the program's own trace.
import struct
import sys
from array import array

BANDS = 3
LUM = (0.2126, 0.7152, 0.0722)  # ITU-R BT.709


def load_npy(path):
    """A square float64 .npy (NumPy format 1.0 or 2.0) as (n, flat array in
    C order: F[i, j] at i * n + j)."""
    with open(path, 'rb') as f:
        if f.read(6) != b'\x93NUMPY':
            sys.exit('%s: not a .npy file' % path)
        major = f.read(2)[0]
        hlen = struct.unpack('<H' if major == 1 else '<I', f.read(2 if major == 1 else 4))[0]
        header = f.read(hlen).decode('latin1')
        if "'<f8'" not in header:
            sys.exit('%s: expected little-endian float64' % path)
        fortran = "'fortran_order': True" in header
        shape = header.split("'shape':")[1].split(')')[0].strip(' (')
        n, m = (int(x) for x in shape.split(',')[:2])
        if n != m:
            sys.exit('%s: not square' % path)
        data = array('d')
        data.frombytes(f.read(8 * n * n))
        if sys.byteorder != 'little':
            data.byteswap()
        if fortran:
            data = array('d', (data[i + j * n] for i in range(n) for j in range(n)))
        return n, data


def load_table(path):
    """(area, (r, g, b), surface) per element of an element table."""
    with open(path) as f:
        rows = [line.rstrip('\n').split('\t') for line in f]
    h = {k: i for i, k in enumerate(rows[0])}
    return [(float(r[h['area']]), tuple(float(r[h[c]]) for c in 'rgb'), int(r[h['surface']]))
            for r in rows[1:]]


def surface_rho(scene):
    """The reflectance (r, g, b) of each surface, in file order."""
    mat, rho = {}, []
    with open(scene) as f:
        for line in f:
            w = line.split('#')[0].split()
            if len(w) >= 4 and w[0] == 'material' and 'reflect' in w:
                k = w.index('reflect') + 1
                v = []
                while k < len(w) and len(v) < 3 and w[k] != 'emit':
                    v.append(float(w[k]))
                    k += 1
                mat[w[1]] = tuple(v) if len(v) == 3 else (v[0],) * 3
            elif w and w[0] in ('quad', 'polygon', 'disk'):
                rho.append(mat[w[1]])
    return rho


def lum(v):
    return sum(LUM[b] * v[b] for b in range(BANDS))


def mask_of(area, yprev, yref):
    """The top 1% (at least one) of elements by A |Yref - Yprev|, and the
    sum of that weight over them.  (Where weights tie at the 1% boundary
    the program's sort may take another of the tied elements.)"""
    n = len(area)
    M = sorted(range(n), key=lambda i: -area[i] * abs(yref[i] - yprev[i]))[:max(1, n // 100)]
    return M, sum(area[i] * abs(yref[i] - yprev[i]) for i in M)


def ratio(num, den):
    """num / den as src/anim/animerror.c takes it: 0 / 0 is 0, x / 0 is inf."""
    return num / den if den > 0 else float('inf') if num > 0 else 0.0


def eq7(argv):
    prev, ref = load_table(argv[0]), load_table(argv[1])
    n = len(ref)
    area = [a for (a, _, _) in ref]
    yref = [lum(v) for (_, v, _) in ref]
    yprev = [lum(prev[i][1]) if i < len(prev) else 0.0 for i in range(n)]
    M, den = mask_of(area, yprev, yref)
    for path in argv[2:]:
        t = load_table(path)
        if len(t) != n:
            sys.exit('redist_oracle: %s: %d elements, expected %d' % (path, len(t), n))
        y = [lum(v) for (_, v, _) in t]
        num = sum(area[i] * abs(y[i] - yref[i]) for i in range(n))
        top = sum(area[i] * abs(y[i] - yref[i]) for i in M)
        print('%.17g %.17g' % (ratio(num, sum(area[i] * yref[i] for i in range(n))),
                               ratio(top, den)))


def main(argv):
    if len(argv) >= 5 and argv[1] == 'eq7':
        return eq7(argv[2:])
    if len(argv) < 7 or argv[1] != 'best':
        sys.exit('usage: redist_oracle.py best SCENE F_OLD F_NEW PREV REF [SEQ...]\n'
                 '       redist_oracle.py eq7 PREV REF TABLE...')
    argv = argv[1:]
    rho_s = surface_rho(argv[1])
    no, fo = load_npy(argv[2])
    n, fn = load_npy(argv[3])
    prev, ref = load_table(argv[4]), load_table(argv[5])
    if len(prev) != no or len(ref) != n or no > n:
        sys.exit('redist_oracle: tables and matrices disagree on the element counts')
    rho = [rho_s[s] for (_, _, s) in ref]
    area = [a for (a, _, _) in ref]
    T = [prev[j][1] if j < no else (0.0,) * BANDS for j in range(n)]
    yprev = [lum(T[i]) for i in range(n)]
    yref = [lum(ref[i][1]) for i in range(n)]

    def dF(i, j):
        old = fo[i * no + j] if i < no and j < no else 0.0
        return fn[i * n + j] - old

    M, den = mask_of(area, yprev, yref)

    # owed[i][j]: the entry (i, j) on receiver i of the mask, per band.
    owed = {i: [tuple(rho[i][b] * dF(i, j) * T[j][b] for b in range(BANDS)) for j in range(n)]
            for i in M}
    gather_all = {i: tuple(sum(owed[i][j][b] for j in range(n)) for b in range(BANDS)) for i in M}

    def error(B):
        return ratio(sum(area[i] * abs(lum(B[i]) - yref[i]) for i in M), den)

    def step(B, paid_shooters, gathered, dB, s, follow=True):
        """Apply step s = (kind, e) to the mask's B; return what every
        element received in this step (its new unshot radiosity), or with
        follow false only what the mask received (for a last step)."""
        kind, e = s
        new = {}
        if kind == 'R':
            if e in paid_shooters:
                return {}
            for r in (range(n) if follow else M):
                d = dF(r, e)
                if d != 0 and r not in gathered:
                    new[r] = tuple(rho[r][b] * d * T[e][b] for b in range(BANDS))
        elif kind == 'G':
            if e in gathered or (e not in M and not follow):
                return {}
            if e in M:
                new[e] = tuple(gather_all[e][b] - sum(owed[e][j][b] for j in paid_shooters)
                               for b in range(BANDS))
            else:
                new[e] = tuple(sum(rho[e][b] * dF(e, j) * T[j][b] for j in range(n)
                                   if j not in paid_shooters) for b in range(BANDS))
        else:  # 'P'
            d = dB.get(e)
            for r in (range(n) if follow else M) if d else ():
                f = fn[r * n + e]
                if f:
                    new[r] = tuple(rho[r][b] * f * d[b] for b in range(BANDS))
        for i in M:
            if i in new:
                B[i] = tuple(B[i][b] + new[i][b] for b in range(BANDS))
        return new

    def run(seq):
        B = {i: T[i] for i in M}
        paid, gathered, dB = set(), set(), {}
        for s in seq:
            new = step(B, paid, gathered, dB, s)
            if s[0] == 'R':
                paid.add(s[1])
            elif s[0] == 'G':
                gathered.add(s[1])
            else:
                dB.pop(s[1], None)  # shot: what it receives now is new
            for r, v in new.items():
                old = dB.get(r, (0.0,) * BANDS)
                dB[r] = tuple(old[b] + v[b] for b in range(BANDS))
        return error(B)

    for text in argv[6:]:
        seq = [(w[0], int(w[1:])) for w in text.split()]
        print('%.17g' % run(seq))

    # Exhaustive search over two steps: the second step's effect on the mask
    # depends on the first only through which entries are paid and what dB
    # the first step left.
    best = (run([]), 'none')
    firsts = [('R', j) for j in range(n)] + [('G', i) for i in range(n)]
    for s1 in firsts:
        B1 = {i: T[i] for i in M}
        paid = {s1[1]} if s1[0] == 'R' else set()
        gathered = {s1[1]} if s1[0] == 'G' else set()
        dB = step(B1, set(), set(), {}, s1)
        e1 = error(B1)
        if e1 < best[0]:
            best = (e1, '%s%d' % s1)
        # second step: R j2, G i2 (i2 in the mask; elsewhere a no-op on it),
        # P k for every k that received something.
        cand = [('R', j) for j in range(n) if j not in paid]
        cand += [('G', i) for i in M if i not in gathered]
        cand += [('P', r) for r in dB]
        for s2 in cand:
            B2 = dict(B1)
            step(B2, paid, gathered, dB, s2, follow=False)
            e2 = error(B2)
            if e2 < best[0]:
                best = (e2, '%s%d %s%d' % (s1 + s2))
    print('mask %s' % ' '.join(str(i) for i in M))
    print('best %.17g %s' % best)


if __name__ == '__main__':
    main(sys.argv)
