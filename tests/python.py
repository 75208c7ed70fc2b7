#!/usr/bin/env python3
# python.py -- the Python binding (import radiosity) against closed forms,
# identities and the program's own outputs for the same scenes: unittest
# cases, reported as TAP when run as a script (tests/commands/python.sh),
# or by `python3 -m unittest` with $RADIOSITY naming the program.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Independent sources: the closed form of directly opposed rectangles
# (Howell's catalogue, C-11) and the nine-point rule of Goral et al. 1984
# (eq. 13 with 3 Gauss-Legendre points per edge, A&S 25.4.29) both written
# here in NumPy; the furnace identity B = E / (1 - rho); reciprocity; the
# program's own tables of a fresh run (the binding must only carry them).
import math
import os
import signal
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import unittest
import warnings

import numpy as np

import radiosity

PROGRAM = os.environ.get("RADIOSITY", "radiosity")
TOP = os.environ.get("top_srcdir", os.path.join(os.path.dirname(__file__), ".."))


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




def perpendicular_rectangles(l, w, h):
    """Howell's catalogue C-14: from the l x w rectangle to the l x h one
    sharing its edge of length l at a right angle."""
    H, W = h / l, w / l
    r = math.sqrt(H * H + W * W)
    a = (1 + W * W) * (1 + H * H) / (1 + W * W + H * H)
    b = (W * W * (1 + W * W + H * H) / ((1 + W * W) * (W * W + H * H))) ** (W * W)
    c = (H * H * (1 + H * H + W * W) / ((1 + H * H) * (H * H + W * W))) ** (H * H)
    return (W * math.atan(1 / W) + H * math.atan(1 / H) - r * math.atan(1 / r)
            + 0.25 * math.log(a * b * c)) / (math.pi * W)


def disk_disk(r1, r2, h):
    """Howell's catalogue C-41: coaxial parallel disks."""
    R1, R2 = r1 / h, r2 / h
    X = 1 + (1 + R2 * R2) / (R1 * R1)
    return 0.5 * (X - math.sqrt(X * X - 4 * (R2 / R1) ** 2))


SQUARES = ("material w reflect 0.5\n"
           "quad w 0 0 0  1 0 0  1 1 0  0 1 0\n"
           "quad w 0 0 1  0 1 1  1 1 1  1 0 1\n")
# a closed unit cube, each wall meshed differently: unequal areas, so a
# transposed F would show (rows sum to 1, columns do not)
CUBE = """material w reflect 0.5
quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 1x1
quad w 0 0 1  0 1 1  1 1 1  1 0 1  mesh 2x1
quad w 0 0 0  0 1 0  0 1 1  0 0 1  mesh 2x2
quad w 1 0 0  1 0 1  1 1 1  1 1 0  mesh 3x1
quad w 0 0 0  0 0 1  1 0 1  1 0 0  mesh 1x2
quad w 0 1 0  1 1 0  1 1 1  0 1 1  mesh 2x3
"""
RHO = np.array([0.2, 0.5, 0.8])
FURNACE = CUBE.replace("reflect 0.5", "reflect 0.2 0.5 0.8 emit 1")


class Binding(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp()
        cls.cube_path = os.path.join(cls.work, "cube.scene")
        with open(cls.cube_path, "w") as f:
            f.write(CUBE)
        cls.two = radiosity.load_scene(SQUARES)
        cls.cube = radiosity.load_scene(cls.cube_path)
        cls.goral = os.path.join(radiosity.scene_dir, "goral1984-cube.scene")
        if not os.path.exists(cls.goral):  # not installed yet: the source's
            cls.goral = os.path.join(TOP, "data", "goral1984-cube.scene")
        cls.g = radiosity.load_scene(cls.goral)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work)

    def path(self, name):
        return os.path.join(self.work, name)

    # ---- scenes ------------------------------------------------------------
    def test_load_text(self):
        """load_scene(text): a Scene of 2 surfaces, material ['w'], named <string>"""
        self.assertIsInstance(self.two, radiosity.Scene)
        self.assertEqual((self.two.surfaces, self.two.materials, self.two.filename),
                         (2, ["w"], "<string>"))

    def test_load_pathlike(self):
        """load_scene takes os.PathLike and bytes paths"""
        import pathlib
        for p in (pathlib.Path(self.cube_path), os.fsencode(self.cube_path)):
            self.assertEqual(radiosity.load_scene(p).surfaces, 6)

    # ---- form factors against independent values ---------------------------
    def test_reference_closed_form(self):
        """reference: F within 1e-9 of Howell C-11, F_ii = 0, a 2 x 2 float64 array"""
        F = radiosity.form_factors(self.two, accuracy="reference")
        want = parallel_rectangles(1, 1, 1)
        self.assertEqual((F.dtype, F.shape), (np.float64, (2, 2)))
        self.assertLessEqual(abs(F[0, 1] - want), 1e-9 * want)
        self.assertLessEqual(abs(F[1, 0] - want), 1e-9 * want)
        self.assertEqual((F[0, 0], F[1, 1]), (0, 0))

    def test_classic_nine_point(self):
        """classic: the nine-point rule of eq. 13 as computed here in NumPy, to 1e-13"""
        p = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
        q = np.array([[0, 0, 1], [0, 1, 1], [1, 1, 1], [1, 0, 1]], float)
        F = radiosity.form_factors(self.two, accuracy="classic")
        self.assertAlmostEqual(F[0, 1], nine_point(p, q), delta=1e-13)

    def test_additivity_and_estimates(self):
        """mesh=(2, 2): 16 pieces sum back to C-11; errors=True gives E within the promise"""
        F, E = radiosity.form_factors(self.two, mesh=(2, 2), accuracy="reference", errors=True)
        want = parallel_rectangles(1, 1, 1)
        self.assertEqual((F.shape, E.shape), ((8, 8), (8, 8)))
        self.assertLessEqual(abs(F[:4, 4:].sum() / 4 - want), 1e-9 * want)
        self.assertTrue(np.all(E[:4, 4:] <= 1e-9 * F[:4, 4:] + 1e-15))
        self.assertTrue(np.all(E[:4, 4:] > 0))

    def test_rows_columns_reciprocity(self):
        """closed cube of unequal elements: rows sum to 1, columns do not, A_i F_ij = A_j F_ji"""
        F = radiosity.form_factors(self.cube, accuracy="reference")
        a = radiosity.elements(self.cube)["area"]
        self.assertEqual(F.shape, (18, 18))
        self.assertLessEqual(np.abs(F.sum(axis=1) - 1).max(), 18e-9)
        self.assertGreater(np.abs(F.sum(axis=0) - 1).max(), 0.1)
        self.assertLessEqual(np.abs(a[:, None] * F - (a[:, None] * F).T).max(), 1e-15)

    def test_same_as_program(self):
        """bit for bit the matrix `radiosity formfactor -o f.npy` writes (the 1984 cube, 4x4)"""
        npy = self.path("f.npy")
        subprocess.run([PROGRAM, "formfactor", "-q", "--mesh", "4x4", "-o", npy, self.goral],
                       check=True)
        F = radiosity.form_factors(self.g, mesh=(4, 4))
        self.assertEqual(F.shape, (96, 96))
        self.assertLessEqual(np.abs(F.sum(axis=1) - 1).max(), 1e-9)
        self.assertTrue(np.array_equal(np.load(npy), F))

    def test_hemicube(self):
        """method='hemicube': the program's --form-factors-method hemicube, bit for bit"""
        npy = self.path("h.npy")
        subprocess.run([PROGRAM, "formfactor", "-q", "--form-factors-method", "hemicube",
                        "--resolution", "32", "-o", npy, self.cube_path], check=True)
        F = radiosity.form_factors(self.cube, method="hemicube", resolution=32)
        self.assertTrue(np.array_equal(np.load(npy), F))

    # ---- elements and vertices ----------------------------------------------
    def test_elements(self):
        """elements(): areas sum to 6, surfaces in file order, corners average to centroids"""
        el = radiosity.elements(self.cube)
        v = radiosity.vertices(self.cube)
        self.assertAlmostEqual(el["area"].sum(), 6, delta=1e-14)
        self.assertEqual(list(el["surface"][:3]), [0, 1, 1])
        self.assertEqual(el["corners"].shape, (18, 4))
        self.assertFalse(el["obstruction"].any())
        # each element is a parallelogram: its centroid is its corners' mean
        self.assertLessEqual(np.abs(v[el["corners"]].mean(axis=1) - el["centroid"]).max(), 1e-15)
        normals = np.cross(v[el["corners"][:, 1]] - v[el["corners"][:, 0]],
                           v[el["corners"][:, 2]] - v[el["corners"][:, 1]])
        self.assertTrue(np.allclose(normals / np.linalg.norm(normals, axis=1)[:, None],
                                    el["normal"], atol=1e-15))

    def test_triangles_meshed(self):
        """mesh=(2, 2) cuts a triangle into 4 of equal area; max_element_size bounds every side"""
        s = radiosity.load_scene("material w reflect 0.5\npolygon w 3  0 0 0  1 0 0  0 1 0\n")
        el = radiosity.elements(s, mesh=(2, 2))
        self.assertEqual(len(el["area"]), 4)
        self.assertLessEqual(np.abs(el["area"] - 1 / 8).max(), 1e-16)
        el = radiosity.elements(s, max_element_size=0.3)
        v = radiosity.vertices(s, max_element_size=0.3)
        c = el["corners"]
        sides = np.linalg.norm(v[c] - v[np.roll(c, -1, axis=1)], axis=2)
        self.assertEqual(len(c), 25)  # the hypotenuse sqrt(2) in 5 parts
        self.assertLessEqual(sides.max(), 0.3)
        with self.assertWarnsRegex(RuntimeWarning, "makes no surface .* finer"):
            radiosity.elements(s, max_element_size=3)
        with self.assertRaises(ValueError):
            radiosity.elements(s, mesh=(2, 2), max_element_size=0.3)

    def test_crease(self):
        """crease=30: the two triangles of each wall meet smoothly, walls at 90 degrees do not"""
        # each wall's triangles share their diagonal, which each cuts from
        # its own end: its points agree to an ulp, not to the bit
        tris = "".join(
            "polygon %s 3  %s  %s  %s\npolygon %s 3  %s  %s  %s\n" % (m, a, b, d, m, c, d, b)
            for m, a, b, c, d in [
                ("w", "0 0 0", "1 0 0", "1 1 0", "0 1 0"), ("l", "0 0 1", "0 1 1", "1 1 1", "1 0 1"),
                ("w", "0 0 0", "0 1 0", "0 1 1", "0 0 1"), ("w", "1 0 0", "1 0 1", "1 1 1", "1 1 0"),
                ("w", "0 0 0", "0 0 1", "1 0 1", "1 0 0"), ("w", "0 1 0", "1 1 0", "1 1 1", "0 1 1")])
        s = radiosity.load_scene("material w reflect 0.5\nmaterial l reflect 0.2 emit 1\n" + tris)
        v = radiosity.vertices(s, mesh=(7, 7))
        n = radiosity.elements(s, mesh=(7, 7))
        # each vertex's surface, and the copies of each point
        surf = np.empty(len(v), int)
        for e, c in enumerate(n["corners"]):
            surf[c] = n["surface"][e]
        _, group = np.unique(np.round(v * 2**20), axis=0, return_inverse=True)
        _, Bv0 = radiosity.solve(s, mesh=(7, 7), vertices=True)
        _, Bv = radiosity.solve(s, mesh=(7, 7), vertices=True, crease=30)
        same_wall = different = 0
        ok_same, ok_diff = True, True
        for g in np.unique(group):
            idx = np.flatnonzero(group == g)
            for i in idx:
                for j in idx:
                    if i < j and surf[i] // 2 == surf[j] // 2:  # the wall's two triangles
                        same_wall += 1
                        ok_same &= np.array_equal(Bv[i], Bv[j])
                    elif i < j:
                        different += 1
                        ok_diff &= not np.array_equal(Bv[i], Bv[j]) or np.array_equal(Bv0[i], Bv0[j])
        self.assertTrue(same_wall > 0 and ok_same)
        self.assertTrue(different > 0 and ok_diff)
        self.assertFalse(all(np.array_equal(Bv0[i], Bv0[j]) for g in np.unique(group)
                             for i in np.flatnonzero(group == g) for j in np.flatnonzero(group == g)
                             if surf[i] // 2 == surf[j] // 2))
        # the merged value is a mean of the copies: within their range
        self.assertTrue(np.all(Bv <= Bv0.max(axis=0) + 1e-15) and np.all(Bv >= Bv0.min(axis=0) - 1e-15))
        # the two sides of a sheet never merge, even at 180 degrees
        sheet = radiosity.load_scene("material w reflect 0.5\nmaterial l reflect 0 emit 1\n"
                                     "polygon w 3  0 0 0  1 0 0  0 1 0\n"
                                     "polygon w 3  0 0 0  0 1 0  1 0 0\n"
                                     "polygon l 3  0 0 1  0 1 1  1 0 1\n")
        _, Bs = radiosity.solve(sheet, vertices=True, crease=180)
        self.assertTrue(Bs[:3].min() > 0 and Bs[3:6].max() == 0)
        with self.assertRaises(ValueError):
            radiosity.solve(sheet, crease=30)

    def test_crease_obj(self):
        """an OBJ model is smoothed across the faces of one object by default, never across objects"""
        # a floor of two unit squares (two triangles each) side by side under
        # a lamp; the squares share their edge x = 1 (vertices 2 and 5)
        def model(second):
            return ("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
                    "v 0 0 1\nv 0 1 1\nv 2 1 1\nv 2 0 1\n"
                    "o a\nusemtl w\nf 1 2 3\nf 1 3 4\n" + second + "usemtl w\nf 2 5 6\nf 2 6 3\n"
                    "o lamp\nusemtl l\nf 7 8 9 10\n")
        with open(self.path("m.mtl"), "w") as f:
            f.write("newmtl w\nKd 0.5 0.5 0.5\nnewmtl l\nKd 0 0 0\nKe 1 1 1\n")
        for second, joined in (("", True), ("o b\n", False)):
            path = self.path("m.obj")
            with open(path, "w") as f:
                f.write(model(second))
            s = radiosity.load_scene(path)
            v = radiosity.vertices(s, mesh=(4, 4))
            n = radiosity.elements(s, mesh=(4, 4))
            surf = np.empty(len(v), int)
            for e, c in enumerate(n["corners"]):
                surf[c] = n["surface"][e]
            _, Bv = radiosity.solve(s, mesh=(4, 4), vertices=True)
            _, Bv0 = radiosity.solve(s, mesh=(4, 4), vertices=True, crease=0)
            # the copies of each point of the shared edge x = 1, z = 0: one on
            # a surface of the first square (0, 1), one of the second (2, 3)
            on_edge = np.flatnonzero((np.abs(v[:, 0] - 1) < 1e-12) & (v[:, 2] == 0))
            pairs = [(i, j) for i in on_edge for j in on_edge
                     if surf[i] < 2 <= surf[j] and np.allclose(v[i], v[j], atol=1e-12)]
            self.assertGreaterEqual(len(pairs), 5)
            # unsmoothed, the two sides differ (each extrapolates its own elements)
            self.assertTrue(any(not np.array_equal(Bv0[i], Bv0[j]) for i, j in pairs))
            same = all(np.array_equal(Bv[i], Bv[j]) for i, j in pairs)
            self.assertEqual(same, joined, "one object" if joined else "two objects")
            # inside each square its two triangles always meet smoothly
            diag = [(i, j) for i in range(len(v)) for j in range(len(v))
                    if surf[i] == 0 and surf[j] == 1 and np.allclose(v[i], v[j], atol=1e-12)]
            self.assertTrue(diag and all(np.array_equal(Bv[i], Bv[j]) for i, j in diag))
        with self.assertRaises(TypeError):
            radiosity.solve(s, vertices=True, crease=True)

    def test_crease_edges(self):
        """faces cut into different parts along a shared edge meet without a step"""
        # two floor triangles share the edge y = 0 from x = 0 to 1; at
        # max_element_size 0.5 the first is cut in 2 parts per edge, the
        # second in 4 (nested: its extra points are hanging) or in 7 (not
        # nested: only the ends are common)
        for apex, parts in (("0.5 -1.8 0", 4), ("0.5 -3 0", 7)):
            s = radiosity.load_scene(
                "material w reflect 0.5\nmaterial l reflect 0 emit 1\n"
                "polygon w 3  0 0 0  1 0 0  0.5 0.3 0\npolygon w 3  1 0 0  0 0 0  " + apex + "\n"
                "quad l  -1 -4 2  -1 2 2  2 2 2  2 -4 2\n")
            v = radiosity.vertices(s, max_element_size=0.5)
            n = radiosity.elements(s, max_element_size=0.5)
            surf = np.empty(len(v), int)
            for e, c in enumerate(n["corners"]):
                surf[c] = n["surface"][e]
            edge = np.flatnonzero((np.abs(v[:, 1]) < 1e-12) & (v[:, 2] == 0) & (surf < 2))
            self.assertEqual(len(edge), 3 + parts + 1)
            _, Bv0 = radiosity.solve(s, max_element_size=0.5, vertices=True, crease=0)
            _, Bv = radiosity.solve(s, max_element_size=0.5, vertices=True, crease=30)
            x = v[edge, 0]

            def along(B, side):
                """side's values along the edge as a function of x (its own points, linear)"""
                k = edge[surf[edge] == side]
                order = np.argsort(v[k, 0])
                return lambda q: np.interp(q, v[k[order], 0], B[k[order], 0])
            # unsmoothed, the two sides disagree somewhere along the edge
            self.assertGreater(np.max(np.abs(along(Bv0, 0)(x) - along(Bv0, 1)(x))), 1e-4)
            # smoothed, they agree at every point of either side (to rounding)
            self.assertLess(np.max(np.abs(along(Bv, 0)(x) - along(Bv, 1)(x))), 1e-15)
            if parts == 4:  # nested: the coarse side's middle point keeps its merged value
                mid = edge[(surf[edge] == 0) & (np.abs(x - 0.5) < 1e-12)]
                self.assertNotAlmostEqual(Bv[mid[0], 0], (along(Bv, 0)(0) + along(Bv, 0)(1)) / 2, 12)

    # ---- the solve -----------------------------------------------------------
    def test_furnace(self):
        """furnace: B = E / (1 - rho) per band, within rho delta / (1 - rho) of F's row sums"""
        s = radiosity.load_scene(FURNACE)
        B, Bv = radiosity.solve(s, accuracy="reference", vertices=True)
        delta = np.abs(radiosity.form_factors(s, accuracy="reference").sum(axis=1) - 1).max()
        # B = E + rho F B with rows short of 1 by at most delta:
        # |B - B*| / B* <= rho delta / (1 - rho), plus LU's rounding
        tol = RHO * delta / (1 - RHO) + 1e-12
        self.assertEqual(B.shape, (18, 3))
        self.assertTrue(np.all(np.abs(B * (1 - RHO) - 1) <= tol))
        # smoothing a constant gives that constant at every vertex
        self.assertEqual(Bv.shape, (len(radiosity.vertices(s)), 3))
        self.assertTrue(np.all(np.abs(Bv * (1 - RHO) - 1) <= 4 * tol))

    def test_bounces(self):
        """bounces=0: B = E exactly; bounces=1: B = E + rho F E"""
        s = radiosity.load_scene(FURNACE)
        self.assertTrue(np.all(radiosity.solve(s, bounces=0) == 1))
        F = radiosity.form_factors(s)
        B1 = radiosity.solve(s, bounces=1)
        self.assertLessEqual(np.abs(B1 - (1 + RHO * F.sum(axis=1)[:, None])).max(), 1e-14)

    def test_solve_same_as_program(self):
        """solve(): bit for bit `radiosity solve --elements`, columns r, g, b"""
        table = self.path("g.tsv")
        subprocess.run([PROGRAM, "solve", "-q", "--mesh", "4x4", "--elements", table,
                        self.goral], check=True)
        t = tsv(table)
        ref = np.array([[float(v) for v in t[b]] for b in "rgb"]).T
        self.assertTrue(np.array_equal(radiosity.solve(self.g, mesh=(4, 4)), ref))

    def test_cholesky(self):
        """solver='cholesky' agrees with gauss within 1e-12"""
        B = radiosity.solve(self.g, mesh=(4, 4))
        Bc = radiosity.solve(self.g, mesh=(4, 4), solver="cholesky")
        self.assertLessEqual(np.abs(Bc - B).max(), 1e-12 * np.abs(B).max())

    # ---- closed forms --------------------------------------------------------
    def test_analytic(self):
        """analytic.*: Howell C-11, C-14, C-41 and r^2 / (r^2 + h^2), as written here"""
        an = radiosity.analytic
        for a, b, c in [(1, 1, 1), (2, 0.5, 3), (1e-3, 1, 1)]:
            self.assertAlmostEqual(an.parallel_rectangles(a, b, c),
                                   parallel_rectangles(a, b, c), delta=1e-12)
        for l, w, h in [(1, 1, 1), (2, 1, 0.5)]:
            self.assertAlmostEqual(an.perpendicular_rectangles(l, w, h),
                                   perpendicular_rectangles(l, w, h), delta=1e-12)
        self.assertAlmostEqual(an.disk_disk(1, 2, 1.5), disk_disk(1, 2, 1.5), delta=1e-12)
        self.assertAlmostEqual(an.point_disk(1, 2), 1 / 5, delta=1e-15)
        with self.assertRaises(ValueError):
            an.point_disk(-1, 2)
        with self.assertRaises(ValueError):
            an.disk_disk(1, float("inf"), 1)

    # ---- View3D's obstructions ----------------------------------------------
    def test_obstruction(self):
        """an O surface blocks (every line meets it: F = 0) but has no row; flagged last"""
        vs3 = self.path("obs.vs3")
        with open(vs3, "w") as f:
            f.write("T two unit squares, an obstruction midway covering every line\n"
                    "F 3\nV 1 0 0 0\nV 2 1 0 0\nV 3 1 1 0\nV 4 0 1 0\nV 5 0 0 1\n"
                    "V 6 1 0 1\nV 7 1 1 1\nV 8 0 1 1\nV 9 0 0 .5\nV 10 1 0 .5\n"
                    "V 11 1 1 .5\nV 12 0 1 .5\nS 1  1 2 3 4  0 0 0.9 bottom\n"
                    "S 2  5 8 7 6  0 0 0.9 top\nO 3  9 12 11 10\nE\n")
        s = radiosity.load_scene(vs3)
        F = radiosity.form_factors(s)
        self.assertEqual(F.shape, (2, 2))
        self.assertLessEqual(abs(F[0, 1]), 1e-12)
        self.assertEqual(list(radiosity.elements(s)["obstruction"]), [False, False, True])

    # ---- View3D's combined surfaces -------------------------------------------
    def test_combine(self):
        """S 3 combines with S 2 (CMB): one row for the union, F by the closed form C-11"""
        vs3 = self.path("cmb.vs3")
        with open(vs3, "w") as f:
            f.write("T a unit square under another, the upper one in two halves\n"
                    "V 1 0 0 0\nV 2 1 0 0\nV 3 1 1 0\nV 4 0 1 0\nV 5 0 0 1\nV 6 0 1 1\n"
                    "V 7 1 1 1\nV 8 1 0 1\nV 9 .5 0 1\nV 10 .5 1 1\n"
                    "S 1  1 2 3 4  0 0 0.9 bottom\nS 2  5 6 10 9  0 0 0.9 top-a\n"
                    "S 3  9 10 7 8  0 2 0.9 top-b\nE\n")
        # Howell C-11, directly opposed unit squares 1 apart
        x = math.sqrt(2)
        want = 2 / math.pi * (math.log(math.sqrt(4 / 3)) + 2 * x * math.atan(1 / x) - math.pi / 2)
        s = radiosity.load_scene(vs3)
        F, E = radiosity.form_factors(s, accuracy="reference", errors=True)
        self.assertEqual(F.shape, (2, 2))
        self.assertEqual(E.shape, (2, 2))
        self.assertAlmostEqual(F[0, 1], want, delta=1e-9 * want)
        self.assertAlmostEqual(F[1, 0], want, delta=1e-9 * want)
        self.assertEqual(list(radiosity.elements(s)["row"]), [0, 1, 1])
        self.assertEqual(radiosity.form_factors(s, mesh=(2, 2)).shape, (5, 5))

    # ---- OBJ repairs ----------------------------------------------------------
    def test_obj_repairs(self):
        """OBJ: each repair a RuntimeWarning with its line, kept in .repairs; strict refuses"""
        obj = self.path("m.obj")
        with open(obj, "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nusemtl nowhere\n"
                    "f 1 2 3 4\nf 1 2 5\n")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            m = radiosity.load_scene(obj)
        said = [str(w.message) for w in caught if w.category is RuntimeWarning]
        self.assertEqual(m.surfaces, 1)
        self.assertEqual(len(said), 2)
        self.assertTrue(said[0].startswith(obj + ":7: repaired: 1 face use a material"))
        self.assertTrue(said[1].startswith(obj + ":8: repaired: 1 face without area"))
        self.assertEqual(m.repairs, said)
        with self.assertRaisesRegex(radiosity.Error, "^" + obj + ":6: undefined material"):
            radiosity.load_scene(obj, strict=True)

    def test_format(self):
        """format='obj' reads a native file as OBJ and says where it fails"""
        with self.assertRaisesRegex(radiosity.Error, "^" + self.cube_path + ":1: "):
            radiosity.load_scene(self.cube_path, format="obj")

    # ---- errors -------------------------------------------------------------------
    def test_error_text(self):
        """bad text: radiosity.Error 'FILE:LINE: reason' with its status"""
        with self.assertRaises(radiosity.Error) as c:
            radiosity.load_scene("material w reflect 2\nquad w 0 0 0\n")
        self.assertTrue(str(c.exception).startswith("<string>:1: reflectance"))
        self.assertEqual(c.exception.status, "malformed input")

    def test_error_file(self):
        """a missing file: radiosity.Error naming it"""
        missing = self.path("none.scene")
        with self.assertRaisesRegex(radiosity.Error, "^" + missing + ": "):
            radiosity.load_scene(missing)

    def test_too_big(self):
        """a mesh too large for memory is refused before anything is allocated"""
        with self.assertRaises(radiosity.Error) as c:
            radiosity.form_factors(self.cube, mesh=(2000, 2000))
        self.assertEqual(c.exception.status, "problem too large for memory")
        self.assertIn("24000000 elements", str(c.exception))

    def test_bad_arguments(self):
        """wrong arguments: ValueError or TypeError naming the choices"""
        with self.assertRaisesRegex(ValueError, "'reference'"):
            radiosity.form_factors(self.cube, accuracy="best")
        with self.assertRaises(ValueError):
            radiosity.form_factors(self.cube, mesh=(0, 2))
        with self.assertRaises(TypeError):
            radiosity.form_factors(self.cube, mesh=[2, 2, 2])
        with self.assertRaises(TypeError):
            radiosity.form_factors("cube.scene")
        with self.assertRaisesRegex(ValueError, "'gauss'"):
            radiosity.solve(self.cube, solver="lu")
        with self.assertRaises(ValueError):
            radiosity.form_factors(self.cube, quadrature=0)
        with self.assertRaises(ValueError):
            radiosity.form_factors(self.cube, method="hemicube", resolution=33)
        with self.assertRaises(TypeError):
            radiosity.form_factors(self.cube, progress=3)
        with self.assertRaises(TypeError):
            radiosity.Scene()

    def test_limits(self):
        """the program's limits hold: threads <= 4096, bounces <= 1e9 without a solver, no bools"""
        with self.assertRaises(ValueError):
            radiosity.form_factors(self.two, threads=5000)
        with self.assertRaisesRegex(ValueError, "give solver or bounces"):
            radiosity.solve(self.two, bounces=2, solver="progressive")
        with self.assertRaises(ValueError):
            radiosity.solve(self.two, bounces=2**31)
        with self.assertRaises(ValueError):
            radiosity.solve(self.two, bounces=True)
        with self.assertRaises(TypeError):
            radiosity.form_factors(self.two, mesh=(True, True))

    def test_undecodable_name(self):
        """a file name that is not UTF-8 is named in radiosity.Error, \\xNN for its bytes"""
        bad = os.fsencode(self.work) + b"/\xff.scene"
        with self.assertRaisesRegex(radiosity.Error, r"\\xff\.scene: "):
            radiosity.load_scene(bad)

    def test_cr_text(self):
        """text with CR line ends (which scene files may have) is text, not a path"""
        self.assertEqual(radiosity.load_scene(SQUARES.replace("\n", "\r")).surfaces, 2)

    def test_absent(self):
        """absent objects: left out and numbered out, as the program does; all absent refused"""
        text = SQUARES.replace("quad w 0 0 0", "object lid absent\nquad w 0 0 0", 1)
        text = text.replace("0 1 0\n", "0 1 0\nend\n", 1)
        s = radiosity.load_scene(text)
        self.assertEqual((s.surfaces, s.objects), (2, ["lid"]))
        self.assertEqual(list(radiosity.elements(s)["surface"]), [0])
        self.assertEqual(radiosity.form_factors(s).shape, (1, 1))
        alone = radiosity.load_scene("material w reflect 0.5\nobject lid absent\n"
                                     "quad w 0 0 0  1 0 0  1 1 0  0 1 0\nend\n")
        with self.assertRaisesRegex(radiosity.Error, "every surface belongs to an absent"):
            radiosity.solve(alone)

    # ---- progress, threads, signals ---------------------------------------------
    def test_progress(self):
        """progress(stage, done, total) is called, up to done == total; it may stop the fill"""
        calls = []
        radiosity.form_factors(self.g, mesh=(3, 3),
                               progress=lambda *a: calls.append(a))
        self.assertTrue(calls and calls[-1][1] == calls[-1][2])
        self.assertEqual(calls[-1][0], "form factors")
        self.assertTrue(all(0 <= c[1] <= c[2] for c in calls))

        class Stop(Exception):
            pass

        def stop(*a):
            raise Stop

        with self.assertRaises(Stop):
            radiosity.form_factors(self.g, mesh=(6, 6), progress=stop)
        with self.assertRaisesRegex(radiosity.Error, "interrupted"):
            radiosity.form_factors(self.g, mesh=(6, 6), progress=lambda *a: True)

    def test_threads(self):
        """two threads filling at once (the GIL released) get the same matrix"""
        out = [None, None]

        def fill(k):
            out[k] = radiosity.form_factors(self.g, mesh=(3, 3))

        threads = [threading.Thread(target=fill, args=(k,)) for k in range(2)]
        for th in threads:
            th.start()
        for th in threads:
            th.join()
        self.assertTrue(out[0] is not None and np.array_equal(out[0], out[1]))

    def test_ctrl_c(self):
        """Ctrl-C (SIGINT) in a long fill: KeyboardInterrupt within a second, then usable"""
        fired = []

        def fire():
            fired.append(time.monotonic())
            os.kill(os.getpid(), signal.SIGINT)

        # Python's own handler, even when the suite was started with
        # SIGINT ignored (a background job's): the check is the binding's
        was = signal.signal(signal.SIGINT, signal.default_int_handler)
        timer = threading.Timer(0.2, fire)
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt):
                radiosity.form_factors(self.g, mesh=(20, 20), accuracy="reference")
        finally:
            signal.signal(signal.SIGINT, was)
        late = time.monotonic() - fired[0]
        timer.join()
        self.assertLess(late, 1.0)
        self.assertEqual(radiosity.form_factors(self.two).shape, (2, 2))


class Tap(unittest.TestResult):
    """Each test as one TAP line, its docstring as the description."""

    def __init__(self):
        super().__init__()
        self.n = 0

    def line(self, test, good, why=""):
        self.n += 1
        print("%s %d - %s%s" % ("ok" if good else "not ok", self.n,
                                test.shortDescription() or test.id(), why))
        sys.stdout.flush()

    def addSuccess(self, test):
        super().addSuccess(test)
        self.line(test, True)

    def addFailure(self, test, err):
        super().addFailure(test, err)
        self.line(test, False)
        print("# " + self.failures[-1][1].replace("\n", "\n# "))

    def addError(self, test, err):
        super().addError(test, err)
        self.line(test, False)
        print("# " + self.errors[-1][1].replace("\n", "\n# "))

    def addSkip(self, test, reason):
        super().addSkip(test, reason)
        self.n += 1
        print("ok %d # SKIP %s" % (self.n, reason))


if __name__ == "__main__":
    result = Tap()
    unittest.defaultTestLoader.loadTestsFromTestCase(Binding).run(result)
    print("1..%d" % result.n)
    sys.exit(0 if result.wasSuccessful() else 1)
