#!/usr/bin/env python3
"""scenes.py -- writes the generated scenes of `make bench`'s hidden-surface
section to standard output, in the native scene format.

Usage: scenes.py squares N     N x N small squares at staggered heights
       scenes.py torus T       a torus of about T triangles in a room
       scenes.py torusbox T    the torus in a closed box (walls facing in)
       scenes.py split N FILE  FILE's quads each written as N x N separate
                               quads (its mesh options dropped)
       scenes.py meshed N FILE FILE with every quad meshed N x N
       scenes.py vs3 FILE      FILE's elements as a View3D 3.2 input file

Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.

Both stand a cloud of small blockers between a lamp and a floor, so that
most pairs of floor and lamp elements are partly hidden, by blockers at
different depths whose shadows overlap: what a triangulated model makes.

squares: a 6 x 6 floor (y = 0, facing up), a 2 x 2 lamp 3 above it (facing
down) and N x N squares of side 0.15, square (i, j) with its corner at
x = -1 + 2i/N + 0.05j, z = -1 + 2j/N + 0.05i, y = 1 + (iN + j)/N^2: no two
at one height, each shifted against the grid so shadows never line up.

split and meshed: one scene two ways, as a View3D file lists its
elements (each a surface of its own) and as the program's own meshed
surfaces: the same elements (bilinear, as mesh.c cuts a quad) and the same
blockers, in many pieces or in few.

torusbox: the same torus in a closed box, the lamp a square of its
ceiling: every row of F sums to 1 (tests/accuracy/closure.sh).

vs3: the elements of a scene written by this script (its quads cut as
their mesh option says, its polygons of 3 or 4 corners) as the surfaces
of a View3D input file (F 3), so that a peer program can be timed on the
same faces.  View3D's emissivity is 1 - reflectance; its control line
asks for eps = 1e-6, every factor, no enclosure adjustment.

torus: the same floor and lamp, and a torus (major radius 0.8, minor 0.3,
its axis tilted 30 degrees from the vertical, its centre 0.9 above the
floor) cut into U x V quadrilaterals of two triangles each, U = 5V,
2UV >= T: a closed model of small flat triangles, as a modelling tool
exports one.  Every triangle is a separate surface of one element, which
is what an OBJ model becomes.
"""
import math
import sys


def room(out):
    out.write("material floor reflect 0.6\n")
    out.write("material lamp reflect 0 emit 10\n")
    out.write("material model reflect 0.5\n")
    out.write("quad floor  -3 0 -3  -3 0 3  3 0 3  3 0 -3  mesh 6x6\n")
    out.write("quad lamp  -1 3 -1  1 3 -1  1 3 1  -1 3 1  mesh 2x2\n")
    out.write("camera eye 0 4 9 at 0 0.8 0 up 0 1 0 fov 45\n")


def squares(n, out):
    out.write("# %d x %d staggered squares under a lamp (bench/scenes.py)\n" % (n, n))
    room(out)
    s = 0.15
    for i in range(n):
        for j in range(n):
            x = -1 + 2.0 * i / n + 0.05 * j
            z = -1 + 2.0 * j / n + 0.05 * i
            y = 1 + (i * n + j) / float(n * n)
            # facing up: counter-clockwise seen from above
            out.write("quad model  %.17g %.17g %.17g  %.17g %.17g %.17g  %.17g %.17g %.17g"
                      "  %.17g %.17g %.17g\n"
                      % (x, y, z, x, y, z + s, x + s, y, z + s, x + s, y, z))


def closed_room(out):
    out.write("material wall reflect 0.6\n")
    out.write("material lamp reflect 0 emit 10\n")
    out.write("material model reflect 0.5\n")
    # [-3, 3] x [0, 3] x [-3, 3], every wall facing in
    out.write("quad wall  -3 0 -3  -3 0 3  3 0 3  3 0 -3  mesh 2x2\n")
    out.write("quad lamp  -1 3 -1  1 3 -1  1 3 1  -1 3 1\n")
    out.write("quad wall  -3 3 -3  -1 3 -3  -1 3 3  -3 3 3\n")
    out.write("quad wall  1 3 -3  3 3 -3  3 3 3  1 3 3\n")
    out.write("quad wall  -1 3 -3  1 3 -3  1 3 -1  -1 3 -1\n")
    out.write("quad wall  -1 3 1  1 3 1  1 3 3  -1 3 3\n")
    out.write("quad wall  -3 0 -3  3 0 -3  3 3 -3  -3 3 -3  mesh 2x1\n")
    out.write("quad wall  -3 0 3  -3 3 3  3 3 3  3 0 3  mesh 2x1\n")
    out.write("quad wall  -3 0 -3  -3 3 -3  -3 3 3  -3 0 3  mesh 1x2\n")
    out.write("quad wall  3 0 -3  3 0 3  3 3 3  3 3 -3  mesh 1x2\n")
    out.write("camera eye 0 2 2.9 at 0 0.8 0 up 0 1 0 fov 90\n")


def torus(t, out, closed=False):
    v = 1
    while 2 * 5 * v * v < t:
        v += 1
    u = 5 * v
    out.write("# a torus of %d triangles (%d x %d) under a lamp (bench/scenes.py)\n"
              % (2 * u * v, u, v))
    (closed_room if closed else room)(out)
    big, small, tilt = 0.8, 0.3, math.radians(30)
    ct, st = math.cos(tilt), math.sin(tilt)

    def point(a, b):
        # indices taken modulo the grid, so that the seam's vertices are
        # the same numbers on both sides: the model is watertight
        ang_u = 2 * math.pi * (a % u) / u
        ang_v = 2 * math.pi * (b % v) / v
        r = big + small * math.cos(ang_v)
        x, y, z = r * math.cos(ang_u), small * math.sin(ang_v), r * math.sin(ang_u)
        # tilt about the x axis, then lift
        return (x, y * ct - z * st + 0.9, y * st + z * ct)

    def tri(p, q, r):
        out.write("polygon model 3  %s\n" % "  ".join(
            "%.17g %.17g %.17g" % w for w in (p, q, r)))

    for a in range(u):
        for b in range(v):
            p00, p10 = point(a, b), point(a + 1, b)
            p01, p11 = point(a, b + 1), point(a + 1, b + 1)
            # outward normals: (d/dv) x (d/du) points out of the tube
            tri(p00, p01, p11)
            tri(p00, p11, p10)


def split(n, path, out, meshed):
    for line in open(path):
        w = line.split()
        if not w or w[0] != "quad":
            out.write(line)
            continue
        mat = w[1]
        c = [tuple(float(x) for x in w[2 + 3 * k:5 + 3 * k]) for k in range(4)]
        if meshed:
            out.write("quad %s  %s  mesh %dx%d\n" % (mat, "  ".join(
                "%.17g %.17g %.17g" % p for p in c), n, n))
            continue

        def at(s, t):
            return bilinear(c, s, t)
        for i in range(n):
            for j in range(n):
                q = [at(i / n, j / n), at((i + 1) / n, j / n), at((i + 1) / n, (j + 1) / n),
                     at(i / n, (j + 1) / n)]
                out.write("quad %s  %s\n" % (mat, "  ".join("%.17g %.17g %.17g" % p for p in q)))


def bilinear(c, s, t):
    """The point (s, t) of the quad c, as mesh.c cuts a quad."""
    return tuple((1 - s) * (1 - t) * c[0][d] + s * (1 - t) * c[1][d] +
                 s * t * c[2][d] + (1 - s) * t * c[3][d] for d in range(3))


def vs3(path, out):
    reflect, faces = {}, []
    for line in open(path):
        w = line.split()
        if not w or w[0].startswith("#"):
            continue
        if w[0] == "material":
            reflect[w[1]] = float(w[w.index("reflect") + 1])
        elif w[0] == "quad":
            c = [tuple(float(x) for x in w[2 + 3 * k:5 + 3 * k]) for k in range(4)]
            nu, nv = 1, 1
            if "mesh" in w:
                nu, nv = (int(x) for x in w[w.index("mesh") + 1].split("x"))
            for i in range(nu):
                for j in range(nv):
                    faces.append((w[1], [bilinear(c, i / nu, j / nv),
                                         bilinear(c, (i + 1) / nu, j / nv),
                                         bilinear(c, (i + 1) / nu, (j + 1) / nv),
                                         bilinear(c, i / nu, (j + 1) / nv)]))
        elif w[0] == "polygon" and w[2] in ("3", "4"):
            k = int(w[2])
            faces.append((w[1], [tuple(float(x) for x in w[3 + 3 * i:6 + 3 * i])
                                 for i in range(k)]))
        elif w[0] not in ("camera",):
            sys.stderr.write("scenes.py: vs3: cannot write '%s'\n" % w[0])
            sys.exit(1)
    out.write("T %s (bench/scenes.py vs3)\n" % path)
    out.write("C eps=1e-6 maxU=8 maxO=8 minO=0 row=0 col=0 encl=0 emit=0 out=0 list=0\n")
    out.write("F 3\n")
    nv = 0
    for _, pts in faces:
        for p in pts:
            nv += 1
            out.write("V %d %.17g %.17g %.17g\n" % ((nv,) + p))
    nv = 0
    for k, (mat, pts) in enumerate(faces):
        ids = list(range(nv + 1, nv + 1 + len(pts))) + [0] * (4 - len(pts))
        nv += len(pts)
        out.write("S %d %d %d %d %d 0 0 %.17g %s\n" % ((k + 1,) + tuple(ids) + (
            1 - reflect[mat], mat)))
    out.write("End of data\n")


def main(argv):
    kinds = ("squares", "torus", "torusbox", "split", "meshed", "vs3")
    if len(argv) == 3 and argv[1] == "vs3":
        vs3(argv[2], sys.stdout)
        return 0
    if (len(argv) not in (3, 4) or argv[1] not in kinds or not argv[2].isdigit() or
            (len(argv) == 4) != (argv[1] in ("split", "meshed"))):
        sys.stderr.write("usage: scenes.py squares N | torus T | torusbox T | split N FILE | "
                         "meshed N FILE | vs3 FILE\n")
        return 2
    n = int(argv[2])
    if n < 1:
        sys.stderr.write("scenes.py: N must be at least 1\n")
        return 2
    if argv[1] in ("split", "meshed"):
        split(n, argv[3], sys.stdout, argv[1] == "meshed")
    elif argv[1] == "squares":
        squares(n, sys.stdout)
    else:
        torus(n, sys.stdout, argv[1] == "torusbox")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
