#!/usr/bin/env python3
# python.py -- the Python binding (import radiosity) against closed forms,
# identities and the program's own outputs for the same scenes.  TAP.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: python.py PROGRAM WORKDIR   (radiosity importable, numpy present)
# Independent sources: the closed form of directly opposed rectangles
# (Howell's catalogue, C-11) and the nine-point rule of Goral et al. 1984
# (eq. 13 with 3 Gauss-Legendre points per edge, A&S 25.4.29) both written
# here in NumPy; the furnace identity B = E / (1 - rho); reciprocity; the
# program's own tables of a fresh run (the binding must only carry them).
import math
import os
import signal
import subprocess
import sys
import threading
import warnings

import numpy as np

import radiosity

program, work = sys.argv[1], sys.argv[2]
count = [0, 0]


def ok(cond, what):
    count[0] += 1
    if not cond:
        count[1] += 1
    print("%s %d - %s" % ("ok" if cond else "not ok", count[0], what))


def raises(kind, fn, *args, **kw):
    """The exception fn raises (of kind), or None."""
    try:
        fn(*args, **kw)
    except kind as e:
        return e
    return None


def parallel_rectangles(a, b, c):
    """Howell's catalogue C-11: a x b rectangles directly opposed, c apart."""
    x, y = a / c, b / c
    return 2 / (math.pi * x * y) * (
        math.log(math.sqrt((1 + x * x) * (1 + y * y) / (1 + x * x + y * y)))
        + x * math.sqrt(1 + y * y) * math.atan(x / math.sqrt(1 + y * y))
        + y * math.sqrt(1 + x * x) * math.atan(y / math.sqrt(1 + x * x))
        - x * math.atan(x) - y * math.atan(y))


def nine_point(p, q):
    """Goral et al. 1984, eq. 13, each edge integral by 3 Gauss-Legendre
    points: F = 1/(2 pi A_p) sum sum (e_i . e_j) int int ln r ds dt, the
    contours counter-clockwise about normals that face each other (no
    colinear edges here, so no closed form is needed)."""
    x = np.array([-math.sqrt(0.6), 0.0, math.sqrt(0.6)])
    s, w = (1 + x) / 2, np.array([5, 8, 5]) / 18.0
    area = 0.5 * np.linalg.norm(sum(np.cross(p[k], p[(k + 1) % len(p)])
                                    for k in range(len(p))))
    total = 0.0
    for i in range(len(p)):
        a0, ea = p[i], p[(i + 1) % len(p)] - p[i]
        for j in range(len(q)):
            b0, eb = q[j], q[(j + 1) % len(q)] - q[j]
            d = ea @ eb
            if d == 0:
                continue
            for si, wi in zip(s, w):
                for tj, wj in zip(s, w):
                    total += d * wi * wj * math.log(
                        np.linalg.norm(a0 + si * ea - b0 - tj * eb))
    return abs(total) / (2 * math.pi * area)


def tsv(path):
    with open(path) as f:
        head = f.readline().rstrip("\n").split("\t")
        rows = [line.rstrip("\n").split("\t") for line in f]
    return {h: [r[k] for r in rows] for k, h in enumerate(head)}


squares = ("material w reflect 0.5\n"
           "quad w 0 0 0  1 0 0  1 1 0  0 1 0\n"
           "quad w 0 0 1  0 1 1  1 1 1  1 0 1\n")
two = radiosity.load_scene(squares)
ok(isinstance(two, radiosity.Scene) and two.surfaces == 2 and two.materials == ["w"],
   "load_scene(text): a Scene of 2 surfaces, material ['w'] (%r)" % two)

# ---- form factors against independent values ------------------------------
want = parallel_rectangles(1, 1, 1)
F = radiosity.form_factors(two, accuracy="reference")
ok(F.dtype == np.float64 and F.shape == (2, 2),
   "form_factors: a 2 x 2 float64 array (%s, %s)" % (F.dtype, F.shape))
ok(abs(F[0, 1] - want) <= 1e-9 * want and abs(F[1, 0] - want) <= 1e-9 * want,
   "reference: F within 1e-9 of Howell C-11's %.15g (%.15g, %.15g)" % (want, F[0, 1], F[1, 0]))
ok(F[0, 0] == 0 and F[1, 1] == 0, "F_ii = 0 for planar elements")
p = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
q = np.array([[0, 0, 1], [0, 1, 1], [1, 1, 1], [1, 0, 1]], float)
rule = nine_point(p, q)
F = radiosity.form_factors(two, accuracy="classic")
ok(abs(F[0, 1] - rule) <= 1e-13,
   "classic: the nine-point rule as computed here in NumPy (%.15g, %.15g)" % (rule, F[0, 1]))
F4, E4 = radiosity.form_factors(two, mesh=(2, 2), accuracy="reference", errors=True)
fold = F4[:4, 4:].sum() / 4
ok(F4.shape == (8, 8) and E4.shape == (8, 8) and abs(fold - want) <= 1e-9 * want,
   "mesh=(2, 2): 8 elements, and the 16 pieces sum back to C-11 (additivity: %.15g)" % fold)
ok(np.all(E4[:4, 4:] <= 1e-9 * F4[:4, 4:] + 1e-15) and np.all(E4[:4, 4:] > 0),
   "errors=True: each estimate within the reference promise (max %.3g)" % E4.max())

# ---- rows and columns: a closed cube of unequal elements -----------------
cube_text = """material w reflect 0.5
quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 1x1
quad w 0 0 1  0 1 1  1 1 1  1 0 1  mesh 2x1
quad w 0 0 0  0 1 0  0 1 1  0 0 1  mesh 2x2
quad w 1 0 0  1 0 1  1 1 1  1 1 0  mesh 3x1
quad w 0 0 0  0 0 1  1 0 1  1 0 0  mesh 1x2
quad w 0 1 0  1 1 0  1 1 1  0 1 1  mesh 2x3
"""
cube_path = os.path.join(work, "cube.scene")
with open(cube_path, "w") as f:
    f.write(cube_text)
cube = radiosity.load_scene(cube_path)
F = radiosity.form_factors(cube, accuracy="reference")
el = radiosity.elements(cube)
a = el["area"]
rows = F.sum(axis=1)
ok(F.shape == (18, 18) and np.max(np.abs(rows - 1)) <= 18e-9,
   "closed cube: every row (from element i) sums to 1 within 18 x 1e-9 (worst %.3g)"
   % np.max(np.abs(rows - 1)))
ok(np.max(np.abs(F.sum(axis=0) - 1)) > 0.1,
   "columns do not (unequal areas): the array is not transposed")
rec = np.abs(a[:, None] * F - (a[:, None] * F).T).max()
ok(rec <= 1e-15, "reciprocity A_i F_ij = A_j F_ji with elements()['area'] (worst %.3g)" % rec)
ok(abs(a.sum() - 6) <= 1e-14 and el["centroid"].shape == (18, 3) and
   list(el["surface"][:3]) == [0, 1, 1] and not el["obstruction"].any(),
   "elements(): areas sum to the cube's 6, centroids 18 x 3, surfaces in file order")
npy = os.path.join(work, "f.npy")
subprocess.run([program, "formfactor", "-q", "--accuracy", "reference", "-o", npy, cube_path],
               check=True)
ok(np.array_equal(np.load(npy), F),
   "bit for bit the matrix `radiosity formfactor -o f.npy` writes for the same scene")

# ---- the solve -------------------------------------------------------------
furnace = radiosity.load_scene(cube_text.replace("reflect 0.5", "reflect 0.2 0.5 0.8 emit 1"))
B = radiosity.solve(furnace, accuracy="reference")
rho = np.array([0.2, 0.5, 0.8])
delta = np.max(np.abs(radiosity.form_factors(furnace, accuracy="reference").sum(axis=1) - 1))
# B = E + rho F B with rows short of 1 by at most delta: |B - B*| / B* <=
# rho delta / (1 - rho (1 - delta)), plus LU's rounding
tol = rho * delta / (1 - rho) + 1e-12
err = np.abs(B / (1 / (1 - rho)) - 1).max(axis=0)
ok(B.shape == (18, 3) and np.all(err <= tol),
   "furnace: B = E / (1 - rho) per band, within rho delta / (1 - rho) (errors %s, bounds %s)"
   % (np.array2string(err, precision=3), np.array2string(tol, precision=3)))
B0 = radiosity.solve(furnace, bounces=0)
ok(np.all(B0 == 1), "bounces=0: B = E exactly")
goral = os.path.join(radiosity.scene_dir, "goral1984-cube.scene")
if not os.path.exists(goral):
    goral = os.path.join(os.environ.get("top_srcdir", "."), "data", "goral1984-cube.scene")
g = radiosity.load_scene(goral)
B = radiosity.solve(g, mesh=(4, 4))
table = os.path.join(work, "g.tsv")
subprocess.run([program, "solve", "-q", "--mesh", "4x4", "--elements", table, goral], check=True)
t = tsv(table)
ref = np.array([[float(v) for v in t[b]] for b in "rgb"]).T
ok(np.array_equal(B, ref), "solve(): bit for bit `radiosity solve --elements` (r, g, b columns)")
Bc = radiosity.solve(g, mesh=(4, 4), solver="cholesky")
ok(np.abs(Bc - B).max() <= 1e-12 * np.abs(B).max(),
   "solver='cholesky' agrees with gauss within 1e-12 (%.3g)" % np.abs(Bc - B).max())

# ---- View3D's obstructions -------------------------------------------------
vs3 = os.path.join(work, "obs.vs3")
with open(vs3, "w") as f:
    f.write("T two unit squares, an obstruction midway covering every line between\n"
            "F 3\nV 1 0 0 0\nV 2 1 0 0\nV 3 1 1 0\nV 4 0 1 0\nV 5 0 0 1\nV 6 1 0 1\n"
            "V 7 1 1 1\nV 8 0 1 1\nV 9 0 0 .5\nV 10 1 0 .5\nV 11 1 1 .5\nV 12 0 1 .5\n"
            "S 1  1 2 3 4  0 0 0.9 bottom\nS 2  5 8 7 6  0 0 0.9 top\n"
            "O 3  9 12 11 10\nE\n")
obs = radiosity.load_scene(vs3)
F = radiosity.form_factors(obs)
ok(F.shape == (2, 2) and abs(F[0, 1]) <= 1e-12,
   "an O surface blocks (every line meets it at its midpoint: F = 0, got %.3g) but has no row"
   % F[0, 1])
ok(list(radiosity.elements(obs)["obstruction"]) == [False, False, True],
   "elements(): the obstruction is flagged, last")

# ---- OBJ repairs said, or refused -----------------------------------------
obj = os.path.join(work, "m.obj")
with open(obj, "w") as f:
    f.write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nusemtl nowhere\n"
            "f 1 2 3 4\nf 1 2 5\n")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    m = radiosity.load_scene(obj)
said = [str(w.message) for w in caught if w.category is RuntimeWarning]
ok(m.surfaces == 1 and len(said) == 2 and said[0].startswith(obj + ":7: repaired: 1 face use")
   and said[1].startswith(obj + ":8: repaired: 1 face without area") and m.repairs == said,
   "OBJ: each repair said as a RuntimeWarning with its line, and kept in .repairs (%s)" % said)
e = raises(radiosity.Error, radiosity.load_scene, obj, strict=True)
ok(e is not None and str(e).startswith(obj + ":6: undefined material"),
   "strict=True refuses the repair: %s" % e)
e = raises(radiosity.Error, radiosity.load_scene, cube_path, format="obj")
ok(e is not None and str(e).startswith(cube_path + ":"),
   "format='obj' reads a native file as OBJ, and says where it fails: %s" % e)

# ---- errors ----------------------------------------------------------------
e = raises(radiosity.Error, radiosity.load_scene, "material w reflect 2\nquad w 0 0 0\n")
ok(e is not None and str(e).startswith("<string>:1: ") and e.status == "malformed input",
   "bad text raises radiosity.Error 'FILE:LINE: reason' with its status: %s (%s)"
   % (e, getattr(e, "status", None)))
missing = os.path.join(work, "none.scene")
e = raises(radiosity.Error, radiosity.load_scene, missing)
ok(e is not None and str(e).startswith(missing + ": "), "a missing file: %s" % e)
e = raises(radiosity.Error, radiosity.form_factors, cube, mesh=(2000, 2000))
ok(e is not None and e.status == "problem too large for memory" and "24000000 elements" in str(e),
   "a mesh too large for memory is refused before anything is allocated: %s" % e)
e = raises(ValueError, radiosity.form_factors, cube, accuracy="best")
ok(e is not None and "'reference'" in str(e), "an unknown accuracy: ValueError: %s" % e)
e = raises(ValueError, radiosity.form_factors, cube, mesh=(0, 2))
ok(e is not None, "mesh=(0, 2): ValueError: %s" % e)
e = raises(TypeError, radiosity.form_factors, "cube.scene")
ok(e is not None, "a str where a Scene belongs: TypeError: %s" % e)
e = raises(ValueError, radiosity.solve, cube, solver="lu")
ok(e is not None and "'gauss'" in str(e), "an unknown solver: ValueError: %s" % e)
ok(raises(TypeError, radiosity.Scene) is not None, "a Scene is made by load_scene alone")

# ---- threads and Ctrl-C ----------------------------------------------------
out = [None, None]


def fill(k):
    out[k] = radiosity.form_factors(g, mesh=(3, 3))


threads = [threading.Thread(target=fill, args=(k,)) for k in range(2)]
for th in threads:
    th.start()
for th in threads:
    th.join()
ok(out[0] is not None and np.array_equal(out[0], out[1]),
   "two threads filling at once (the GIL released) get the same matrix")


def alarm(signum, frame):
    raise KeyboardInterrupt


signal.signal(signal.SIGALRM, alarm)
signal.setitimer(signal.ITIMER_REAL, 0.05)
e = raises(KeyboardInterrupt, radiosity.form_factors, g, mesh=(20, 20), accuracy="reference")
signal.setitimer(signal.ITIMER_REAL, 0)
ok(e is not None, "a signal during a long fill stops it with the handler's exception")
print("1..%d" % count[0])
sys.exit(1 if count[1] else 0)
