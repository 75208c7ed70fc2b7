#!/bin/sh
# scale.sh -- the scale of a scene does not matter, and what cannot be
# represented is refused, through the program.
#
# Independent references, no value copied from the program:
#   - invariance: form factors are dimensionless, so the 1984 cube scaled by
#     s gives the same B as at unit scale.  The scaled scenes are written by
#     python from the unit scene: s * x with x in {0, 1} is exact, so each is
#     exactly a cube of side s.  Moved by t = 1e12 sides the corners round
#     (to an ulp of 1e12 s: the side changes by up to 7e-5), so the
#     unit-scale counterpart is computed from the rounded corners in exact
#     rational arithmetic, (x - t) / s, and run too: the same geometry at
#     unit scale.  (Every axis rounds alike, so it is still a cube, and B is
#     also the unit cube's.)  B must agree to 1e-9 relative per
#     element and band in default mode: F's own error moves B by less than
#     2e-8 (the solve summary's bound), but that error is the same function
#     of the same geometry, so what remains is round-off, far below 1e-9.
#   - closed forms, evaluated here by python from Howell's catalogue (C-11
#     directly opposed rectangles, C-14 perpendicular rectangles with a common
#     edge): two facing unit squares one apart, F = 0.19982489569838746, and
#     two squares meeting at a right angle, F = 0.20004377607540316.  At scale
#     1e80 reference mode promises 1e-9 relative; in default mode every scale
#     must keep its error estimate a bound on the true error.
#   - linearity: B is linear in E, so emission 1e308 gives 1e308 times the
#     B of emission 1, or, where that exceeds the largest double (1.8e308;
#     the furnace B = E / (1 - rho) = 2e308), exit 1 with a message naming it.
#   - the Cornell box with its blocks (visibility through CGAL) at 1e-100
#     and 1e100 gives the F of unit scale within the error estimates, and
#     B within the bound those give (below);
#   - the race of `radiosity progress' (area-weighted RMS errors): the same
#     at scale 1e-150, 1e300 times as large at emission 1e300, never inf;
#   - the accepted range: every polygon between 2^-510 and 2^510 across
#     (3e-154 to 3.4e153; areas are then normal doubles), so the cube at
#     1e-160 and 1e160 is refused with exit 1 and a message giving the range.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found (it writes the scaled scenes exactly)"
  exit 0
fi
cube="$top_srcdir/data/goral1984-cube.scene"
scales="1e-150 1e-80 1e80 1e150"

# The scenes: cube-S (scaled), far-S (scaled and moved by 1e12 S), farunit-S
# (far-S brought back to unit scale exactly), plates-S, hinge-S.
python3 - "$cube" "$work" $scales 1 <<'EOF' || { echo "not ok 1 - python3 wrote the scenes"; echo "1..1"; exit 1; }
import sys
from fractions import Fraction
src, work, scales = sys.argv[1], sys.argv[2], sys.argv[3:]
lines = [l.split() for l in open(src) if l.strip() and not l.startswith(('#', 'camera'))]

def write(name, f):
    with open(f"{work}/{name}.scene", "w") as out:
        for t in lines:
            if t[0] == "quad":
                xs = [f(float(v)) for v in t[2:14]]
                t = t[:2] + [repr(x) for x in xs] + t[14:]
            out.write(" ".join(t) + "\n")

for name in scales:
    s = float(name)
    t = 1e12 * s
    write(f"cube-{name}", lambda x: x * s)
    write(f"far-{name}", lambda x: x * s + t)
    # the same rounded corners at unit scale: (x~ - t) / s, exactly, rounded once
    write(f"farunit-{name}", lambda x: float((Fraction(x * s + t) - Fraction(t)) / Fraction(s)))
    with open(f"{work}/plates-{name}.scene", "w") as out:
        out.write("material w reflect 0.5 emit 1\n")
        out.write("quad w 0 0 0  %r 0 0  %r %r 0  0 %r 0\n" % (s, s, s, s))
        out.write("quad w 0 0 %r  0 %r %r  %r %r %r  %r 0 %r\n" % (s, s, s, s, s, s, s, s))
    with open(f"{work}/hinge-{name}.scene", "w") as out:
        out.write("material w reflect 0.5 emit 1\n")
        out.write("quad w 0 0 0  %r 0 0  %r %r 0  0 %r 0\n" % (s, s, s, s))
        out.write("quad w 0 0 0  0 %r 0  0 %r %r  0 0 %r\n" % (s, s, s, s))
EOF
# closed forms (Howell, A Catalog of Radiation Heat Transfer Configuration
# Factors, C-11 and C-14), in python's doubles
parallel=$(python3 -c '
from math import atan, log, pi, sqrt
X = Y = 1.0
print(repr(2 / (pi * X * Y) * (log(sqrt((1 + X*X) * (1 + Y*Y) / (1 + X*X + Y*Y)))
    + X * sqrt(1 + Y*Y) * atan(X / sqrt(1 + Y*Y)) + Y * sqrt(1 + X*X) * atan(Y / sqrt(1 + X*X))
    - X * atan(X) - Y * atan(Y))))')
perpendicular=$(python3 -c '
from math import atan, log, pi, sqrt
H = W = 1.0
a, b, c = (1 + W*W) * (1 + H*H) / (1 + W*W + H*H), W*W * (1 + W*W + H*H) / ((1 + W*W) * (W*W + H*H)), \
    H*H * (1 + H*H + W*W) / ((1 + H*H) * (H*H + W*W))
print(repr(1 / (pi * W) * (W * atan(1 / W) + H * atan(1 / H) - sqrt(H*H + W*W) * atan(1 / sqrt(H*H + W*W))
    + 0.25 * (log(a) + W*W * log(b) + H*H * log(c)))))')
close_to "$parallel" 0.19982489569838746 1e-14; ok $? "C-11 for two unit squares one apart: $parallel"
close_to "$perpendicular" 0.20004377607540316 1e-14; ok $? "C-14 for two unit squares at a right angle: $perpendicular"

# compare_b A B TOL: two element tables (same mesh): r g b within TOL
# relative, element by element; prints the worst relative difference
compare_b() {
  paste "$1" "$2" | awk -F'\t' -v t="$3" '
    NR == 1 { for (k = 1; k <= NF / 2; k++) col[$k] = k; h = NF / 2; next }
    { for (c = 0; c < 3; c++) {
        k = col[c == 0 ? "r" : c == 1 ? "g" : "b"]
        d = $k - $(k + h); if (d < 0) d = -d; s = $k < 0 ? -$k : $k
        r = s > 0 ? d / s : d; if (r > w) w = r; if (!(r <= t)) bad = 1 }
      n++ }
    END { printf "%.3g\n", w; exit bad || n != 54 }'
}
# finite FILE: no nan or inf anywhere in a table
finite() { ! grep -qi 'nan\|inf' "$1"; }
solve() { # solve SCENE TABLE [OPTIONS]: default mode, 3x3 per wall
  solve_scene=$1 solve_table=$2; shift 2
  "$RADIOSITY" solve -q --mesh 3x3 --elements "$solve_table" "$@" "$solve_scene" 2> "$work/err"
}

solve "$cube" "$work/unit.tsv"; ok $? "solve the unit cube, 3x3 per wall"
for s in $scales; do
  solve "$work/cube-$s.scene" "$work/cube-$s.tsv"; ok $? "solve the cube scaled by $s"
  w=$(compare_b "$work/unit.tsv" "$work/cube-$s.tsv" 1e-9); ok $? "scaled by $s: B as at unit scale within 1e-9 (worst $w)"
  a=$(awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) if ($k == "area") c = k; next } { a += $c } END { printf "%.17g", a }' "$work/cube-$s.tsv")
  close_to "$a" "$(python3 -c "print(repr(6 * $s * $s))")" 1e-13; ok $? "scaled by $s: areas add up to 6 s^2 in the user's units ($a)"
  finite "$work/cube-$s.tsv"; ok $? "scaled by $s: no nan or inf in the table"
done
for s in 1 $scales; do
  solve "$work/far-$s.scene" "$work/far-$s.tsv" && solve "$work/farunit-$s.scene" "$work/farunit-$s.tsv"
  ok $? "solve the cube scaled by $s and moved by 1e12 of its sides, and the same corners at unit scale"
  w=$(compare_b "$work/farunit-$s.tsv" "$work/far-$s.tsv" 1e-9); ok $? "scaled by $s, moved by 1e12 s: B as at unit scale within 1e-9 (worst $w)"
  w=$(compare_b "$work/unit.tsv" "$work/far-$s.tsv" 1e-9); ok $? "  ... and as the unit cube within 1e-9: rounded alike on every axis, it is a cube still (worst $w)"
done

# out of range: refused, the range named, nothing written
for s in 1e-160 1e160; do
  awk -v s=$s '$1 == "quad" { for (k = 3; k <= 14; k++) $k = sprintf("%.17g", $k * s) } $1 != "camera"' \
    "$cube" > "$work/out-$s.scene"
  solve "$work/out-$s.scene" "$work/out-$s.tsv"; r=$?
  [ $r -eq 1 ] && grep -q 'outside the sizes this program accepts (2.98e-154 to 3.35e+153' "$work/err" &&
    [ ! -e "$work/out-$s.tsv" ]
  ok $? "scaled by $s: exit 1 ($r), the accepted range named, no table: $(cat "$work/err")"
done

# F against closed forms at every scale; the estimate bounds the error
for s in 1 $scales; do
  "$RADIOSITY" formfactor -q --accuracy default -o "$work/hinge-$s.tsv" "$work/hinge-$s.scene" &&
    "$RADIOSITY" formfactor -q --accuracy default -o "$work/plates-$s.tsv" "$work/plates-$s.scene"
  ok $? "formfactor, default mode, on the squares at scale $s"
  for c in "hinge $perpendicular" "plates $parallel"; do
    set -- $c
    awk -F'\t' -v f="$2" 'NR > 1 { d = $3 - f; if (d < 0) d = -d; if (!(d <= $4)) bad = 1; n++;
                               printf "error %.3g, estimate %s; ", d, $4 } END { exit bad || n != 2 }' \
      "$work/$1-$s.tsv" > "$work/msg"
    ok $? "$1 at scale $s: the error estimate bounds the true error ($(cat "$work/msg"))"
  done
done
"$RADIOSITY" formfactor -q --accuracy reference -o "$work/ref.tsv" "$work/plates-1e80.scene"
ok $? "formfactor --accuracy reference on two unit-square plates at scale 1e80"
f=$(awk -F'\t' 'NR == 2 { print $3 }' "$work/ref.tsv")
close_to "$f" "$parallel" 1e-9; ok $? "plates at scale 1e80: F = $f, the closed form within 1e-9"

# the cube at 1e-80 and 1e80, every pair: F within its estimate of the unit
# cube's reference-mode F (whose own estimate is added)
"$RADIOSITY" formfactor -q --mesh 3x3 --accuracy reference -o "$work/ffref.tsv" "$cube"
ok $? "formfactor --accuracy reference on the unit cube, 3x3"
for s in 1e-80 1e80; do
  "$RADIOSITY" formfactor -q --mesh 3x3 -o "$work/ff-$s.tsv" "$work/cube-$s.scene"
  bad=$(paste "$work/ffref.tsv" "$work/ff-$s.tsv" | awk -F'\t' 'NR > 1 { n++; d = $3 - $7; if (d < 0) d = -d
          if (!(d <= $4 + $8) || $1 != $5 || $2 != $6) bad++ } END { print bad + 0 "/" n }')
  [ "$bad" = "0/2862" ]; ok $? "cube at $s: pairs whose error exceeds their estimate: $bad"
done

# emission at the top of the range: linear, or refused
sed 's/emit 1 1 1/emit 1e308 1e308 1e308/' "$cube" > "$work/bright.scene"
solve "$work/bright.scene" "$work/bright.tsv"; ok $? "solve the cube emitting 1e308: exit 0"
finite "$work/bright.tsv"; ok $? "emission 1e308: no nan or inf in the table"
w=$(paste "$work/unit.tsv" "$work/bright.tsv" | awk -F'\t' '
    NR == 1 { for (k = 1; k <= NF / 2; k++) col[$k] = k; h = NF / 2; next }
    { for (c = 0; c < 3; c++) { k = col[c == 0 ? "r" : c == 1 ? "g" : "b"]
        d = $k * 1e308 - $(k + h); if (d < 0) d = -d; s = $(k + h); r = s > 0 ? d / s : d
        if (r > w) w = r; if (!(r <= 1e-9)) bad = 1 } }
    END { printf "%.3g\n", w; exit bad }')
ok $? "emission 1e308: B is 1e308 times B at emission 1 within 1e-9 (worst $w)"
printf 'material w reflect 0.5 emit 1e308\n' > "$work/furnace.scene"
grep '^quad' "$top_srcdir/data/furnace.scene" >> "$work/furnace.scene"
for solver in gauss jacobi gauss-seidel progressive; do
  rm -f "$work/f.tsv" "$work/f.json"
  solve "$work/furnace.scene" "$work/f.tsv" --solver $solver --report "$work/f.json"; r=$?
  [ $r -eq 1 ] && grep -q 'largest double (1.8e+308)' "$work/err" && [ ! -e "$work/f.tsv" ] &&
    grep -q '"status": "error"' "$work/f.json" && ! grep -qi 'nan\|inf' "$work/f.json"
  ok $? "furnace emitting 1e308 (B = 2e308), $solver: exit 1 ($r), the limit named, no table: $(cat "$work/err")"
done
sed 's/emit 1e308/emit 8e307/' "$work/furnace.scene" > "$work/furnace8.scene"
solve "$work/furnace8.scene" "$work/f8.tsv" --solver progressive --trace "$work/trace.tsv"; r=$?
[ $r -eq 1 ] && grep -q 'largest double' "$work/err"
ok $? "furnace emitting 8e307, progressive with a trace (power 4.8e308): exit 1 ($r): $(cat "$work/err")"
solve "$work/furnace8.scene" "$work/f8.tsv"
awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) col[$k] = k; next }
  { d = $(col["r"]) / 1.6e308 - 1; if (d < 0) d = -d; if (!(d <= 1e-9)) bad = 1 } END { exit bad }' "$work/f8.tsv"
ok $? "furnace emitting 8e307: B = E / (1 - rho) = 1.6e308 within 1e-9"

# hidden surfaces (CGAL) too: the Cornell box with its two blocks at 1e-100
# and 1e100, 2x2 per quad, against unit scale.  Decimal scales round the
# corners (relative 1e-16), and the visibility clipping's tolerances are
# relative to the scene, so the two runs can cut their integration domains
# differently where an event "happens" at a vertex up to round-off
# (src/occ/occeee.c), and then agree only within their integration error, not
# round-off.  So the promise is the estimates': every entry of F differs
# from unit scale's by at most the two error estimates together, and B
# by at most what that difference can make of it: from B = E + rho F B at
# each scale,
#     B_u - B_s = (I - rho F_u)^-1 rho (F_u - F_s) B_s,
# and (I - rho F_u)^-1 = sum (rho F_u)^k has no negative entry, so
#     |B_u - B_s| <= (I - rho F_u)^-1 rho (e_u + e_s) B_s,
# e the estimates' matrices; solved here by python (partial pivoting),
# plus 1e-12 of B for the solves' round-off.  That bound is as loose as
# the estimates (up to 4e-4 of B here, where some pairs of this coarse
# mesh miss the promise), so B must also stay within 1e-7 relative: an
# observed ceiling (1.1e-8 was seen, from domains cut differently), there
# to catch a change that inflates the estimates and so the bound.
box="$top_srcdir/data/cornell-box.scene"
"$RADIOSITY" solve -q --mesh 2x2 --elements "$work/box.tsv" "$box" 2> "$work/err" &&
  "$RADIOSITY" formfactor -q --mesh 2x2 -o "$work/box-F.tsv" "$box" 2> "$work/err"
ok $? "solve the Cornell box, 2x2 per quad (visibility needed), and its form factors"
for s in 1e-100 1e100; do
  awk -v s=$s '$1 == "quad" { for (k = 3; k <= 14; k++) $k = sprintf("%.17g", $k * s) } $1 != "camera"' \
    "$box" > "$work/box-$s.scene"
  "$RADIOSITY" solve -q --mesh 2x2 --elements "$work/box-$s.tsv" "$work/box-$s.scene" \
    2> "$work/err" &&
    "$RADIOSITY" formfactor -q --mesh 2x2 -o "$work/box-F-$s.tsv" "$work/box-$s.scene" \
      2> "$work/err"
  ok $? "solve the Cornell box scaled by $s, and its form factors"
  w=$(python3 - "$box" "$work/box-F.tsv" "$work/box-F-$s.tsv" "$work/box.tsv" \
        "$work/box-$s.tsv" <<'PY'
import sys
scene, fu, fs, bu, bs = sys.argv[1:]
rho, surf = {}, []
for line in open(scene):
    t = line.split()
    if t and t[0] == "material":  # reflect R G B, or one value for grey
        r = []
        for x in t[t.index("reflect") + 1:]:
            try:
                r.append(float(x))
            except ValueError:
                break
        rho[t[1]] = r * 3 if len(r) == 1 else r[:3]
    elif t and t[0] == "quad":
        surf.append(rho[t[1]])
def table(path):
    rows = [l.rstrip("\n").split("\t") for l in open(path)]
    col = {k: i for i, k in enumerate(rows[0])}
    return col, rows[1:]
def ff(path):
    col, rows = table(path)
    return {(int(r[0]), int(r[1])): (float(r[2]), float(r[3])) for r in rows}
Fu, Fs = ff(fu), ff(fs)
cu, ru = table(bu)
cs, rs = table(bs)
n = len(ru)
# every ratio is counted, so that a NaN fails (max() would pass over it)
bad, worst_f = 0, 0.0
for k, (f, e) in Fu.items():
    g, es = Fs[k]
    r = abs(f - g) / (e + es + 1e-15)
    bad += not r <= 1
    worst_f = max(worst_f, r)
worst_b, worst_rel = 0.0, 0.0
for band in "rgb":
    b = [float(r[cs[band]]) for r in rs]
    p = [surf[int(r[cu["surface"]])]["rgb".index(band)] for r in ru]
    # (I - rho F_u) x = rho (e_u + e_s) B_s, Gaussian elimination
    a = [[(1.0 if i == j else 0.0) - (p[i] * Fu[i, j][0] if i != j else 0.0)
          for j in range(n)] for i in range(n)]
    x = [p[i] * sum((Fu[i, j][1] + Fs[i, j][1]) * b[j] for j in range(n) if j != i)
         for i in range(n)]
    for c in range(n):
        m = max(range(c, n), key=lambda r: abs(a[r][c]))
        a[c], a[m], x[c], x[m] = a[m], a[c], x[m], x[c]
        for r in range(c + 1, n):
            f = a[r][c] / a[c][c]
            if f:
                for j in range(c, n):
                    a[r][j] -= f * a[c][j]
                x[r] -= f * x[c]
    for c in range(n - 1, -1, -1):
        x[c] = (x[c] - sum(a[c][j] * x[j] for j in range(c + 1, n))) / a[c][c]
    for i in range(n):
        d = abs(float(ru[i][cu[band]]) - b[i])
        r, rel = d / (x[i] + 1e-12 * abs(b[i]) + 1e-300), d / abs(b[i]) if b[i] else d
        bad += not (r <= 1 and rel <= 1e-7)
        worst_b, worst_rel = max(worst_b, r), max(worst_rel, rel)
print("%.3g %.3g, B within %.3g relative" % (worst_f, worst_b, worst_rel))
sys.exit(0 if bad == 0 and n >= 100 else 1)
PY
)
  ok $? "Cornell box scaled by $s: F within the two estimates of unit scale's, B within the bound they give and 1e-7 (worst shares of the bounds: $w)"
done

# the race of Cohen et al. 1988 weighs errors by area: the same curves at
# scale 1e-150, and 1e300 times them at emission 1e300 (linearity)
"$RADIOSITY" progress -q --mesh 2x2 --steps 20 -o "$work/race.tsv" "$cube" &&
  "$RADIOSITY" progress -q --mesh 2x2 --steps 20 -o "$work/race-small.tsv" "$work/cube-1e-150.scene" &&
  sed 's/emit 1 1 1/emit 1e300 1e300 1e300/' "$cube" > "$work/bright300.scene" &&
  "$RADIOSITY" progress -q --mesh 2x2 --steps 20 -o "$work/race-bright.tsv" "$work/bright300.scene"
ok $? "progress on the unit cube, at scale 1e-150 and at emission 1e300"
for c in "race-small 1" "race-bright 1e300"; do
  set -- $c
  # the two tables side by side: column k of one is column k + NF/2 of the other
  w=$(paste "$work/race.tsv" "$work/$1.tsv" | awk -F'\t' -v f="$2" 'NR > 1 { h = NF / 2; for (k = 2; k <= h; k++) {
        r = $(k + h) / ($k * f) - 1; if (r < 0) r = -r; if (r > w) w = r; if (!(r <= 1e-9)) bad = 1 }; n++ }
      END { printf "%.3g\n", w; exit bad || n != 21 }')
  ok $? "$1: every RMS error is $2 times the unit cube's within 1e-9, finite (worst $w)"
done
done_testing
