# notebook.py -- the radiosity Python binding, a cell at a time (each "# %%"
# starts a cell in Jupyter, VS Code or Spyder; `python3 notebook.py` runs
# them all).  Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Goral, Torrance, Greenberg & Battaile 1984 computed the form factors of a
# meshed cube by a contour integral (their eq. 13) and solved the radiosity
# system once per colour band (eq. 5).  Here is the same computation, with
# checks a validator would make of any view-factor code.

# %% The 1984 cube: six walls, a white emitting top (installed with the
# program; give another scene file as the first argument)
import sys

import numpy as np

import radiosity

path = sys.argv[1] if len(sys.argv) > 1 else radiosity.scene_dir + "/goral1984-cube.scene"
cube = radiosity.load_scene(path)
print(cube, "materials:", cube.materials)

# %% Form factors: F[i, j] is the fraction of the energy leaving element i
# that reaches element j.  Reference mode promises 1e-9 relative error.
F, E = radiosity.form_factors(cube, mesh=(4, 4), accuracy="reference", errors=True)
el = radiosity.elements(cube, mesh=(4, 4))
area = el["area"]
print("elements:", F.shape[0])
print("closure, max |sum_j F_ij - 1|:        %.2e" % np.abs(F.sum(axis=1) - 1).max())
print("reciprocity, max |A_i F_ij - A_j F_ji|: %.2e" % np.abs(area[:, None] * F
                                                              - (area[:, None] * F).T).max())
print("largest estimated error of an entry:    %.2e" % np.nanmax(E))

# %% A closed form to hold it against: two opposite walls of a unit cube
# are directly opposed unit squares one apart (Howell's catalogue C-11).
walls = el["surface"]
opposite = [(s, t) for s in range(6) for t in range(6)
            if np.allclose(el["normal"][walls == s][0], -el["normal"][walls == t][0])]
s, t = opposite[0]
rows, cols = walls == s, walls == t
whole = (area[rows, None] * F[np.ix_(rows, cols)]).sum() / area[rows].sum()
exact = radiosity.analytic.parallel_rectangles(1, 1, 1)
print("wall %d to wall %d: %.12f, closed form %.12f" % (s, t, whole, exact))

# %% The classic rule (the paper's nine points per edge pair) against the
# reference: where does it lose accuracy?  At the walls' shared edges, where
# its rows overshoot 1 (the binding says so in a RuntimeWarning).
Fc = radiosity.form_factors(cube, mesh=(4, 4), accuracy="classic")
worst = np.unravel_index(np.abs(Fc - F).argmax(), F.shape)
print("classic's worst entry: F[%d, %d] = %.6f, reference %.6f" % (worst + (Fc[worst], F[worst])))

# %% Radiosity per element and band (red, green, blue), and smoothed to the
# vertices as the paper renders it.
B, Bv = radiosity.solve(cube, mesh=(4, 4), vertices=True)
print("brightest element:", B.sum(axis=1).argmax(), "B =", B[B.sum(axis=1).argmax()])
print("vertices: %d, Bv from %.4f to %.4f" % (len(radiosity.vertices(cube, mesh=(4, 4))),
                                            Bv.min(), Bv.max()))
