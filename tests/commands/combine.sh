#!/bin/sh
# combine.sh -- View3D's combined surfaces (an S line's CMB): one row and
# column for each union in what `formfactor`, `compare` and the Python
# binding report, as View3D's output has them.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Independent references, never the program's own earlier output:
#   - closed forms computed here in awk from their formulas (Howell, "A
#     Catalog of Radiation Heat Transfer Configuration Factors", C-11:
#     directly opposed rectangles; C-14: perpendicular rectangles with a
#     common edge): a union's factors are those of the whole surface it
#     makes (additivity), so a box whose walls are split and combined back
#     gives the closed forms of the whole walls, whatever the mesh;
#   - the rows of a closed box sum to 1, and A_I F_IJ = A_J F_JI with the
#     unions' areas from the geometry;
#   - two faces of a corner combined see each other: the union's self
#     factor is 2 A_f F_fw / (A_f + A_w) (reciprocity), F_fw by C-14;
#   - View3D 3.2's own text output for the parallel case is written below
#     by hand, with the six decimals it prints (0.199825).
. "${top_srcdir:-.}/tests/lib.sh"

CF='function atan(x) { return atan2(x, 1) }
function c11(a, b, c,    X, Y, p) {
  X = a / c; Y = b / c; p = atan2(0, -1)
  return 2 / (p * X * Y) * (log(sqrt((1 + X*X) * (1 + Y*Y) / (1 + X*X + Y*Y))) \
    + X * sqrt(1 + Y*Y) * atan(X / sqrt(1 + Y*Y)) + Y * sqrt(1 + X*X) * atan(Y / sqrt(1 + X*X)) \
    - X * atan(X) - Y * atan(Y))
}
function c14(l, w, h,    W, H, p, s) {
  W = w / l; H = h / l; p = atan2(0, -1); s = W*W + H*H
  return 1 / (p * W) * (W * atan(1 / W) + H * atan(1 / H) - sqrt(s) * atan(1 / sqrt(s)) \
    + 0.25 * log((1 + W*W) * (1 + H*H) / (1 + s) \
      * (W*W * (1 + s) / ((1 + W*W) * s)) ^ (W*W) \
      * (H*H * (1 + s) / ((1 + H*H) * s)) ^ (H*H)))
}'
# F(from -> to) of a table, "" when absent
entry() { awk -F '\t' -v i="$2" -v j="$3" 'NR > 1 && $1 == i && $2 == j { print $3 }' "$1"; }

# ---- two parallel unit squares, the upper one in two combined halves ----
cat > "$work/par.vs3" << 'EOF'
T a unit square under another, 1 apart, the upper one in two halves
F 3
V 1 0 0 0
V 2 1 0 0
V 3 1 1 0
V 4 0 1 0
V 5 0 0 1
V 6 0 1 1
V 7 1 1 1
V 8 1 0 1
V 9 .5 0 1
V 10 .5 1 1
S 1  1 2 3 4  0 0 0.9 bottom
S 2  5 6 10 9  0 0 0.9 top-a
S 3  9 10 7 8  0 2 0.9 top-b
E
EOF
want=$(awk "$CF"' BEGIN { printf "%.17g", c11(1, 1, 1) }')
for mode in default reference; do
  tol=1e-9
  [ "$mode" = default ] && tol=1e-6
  "$RADIOSITY" formfactor --accuracy $mode "$work/par.vs3" > "$work/par.tsv" 2> "$work/err"
  ok $? "par.vs3 ($mode): formfactor runs"
  f01=$(entry "$work/par.tsv" 0 1) f10=$(entry "$work/par.tsv" 1 0)
  close_to "$f01" "$want" $tol && close_to "$f10" "$want" $tol
  ok $? "$mode: square -> union $f01, union -> square $f10, C-11 $want within $tol"
done
[ "$(($(wc -l < "$work/par.tsv") - 1))" -eq 4 ] && [ "$(entry "$work/par.tsv" 1 1)" = 0 ]
ok $? "2 x 2, as View3D reports it, the diagonal listed (a union may see itself: here 0)"
grep -q "^radiosity: 1 surfaces combined with earlier ones (View3D's CMB), one row and column a union: 2 x 2$" "$work/err"
ok $? "formfactor says so on standard error: $(cat "$work/err")"
"$RADIOSITY" formfactor -q "$work/par.vs3" > /dev/null 2> "$work/err" && [ ! -s "$work/err" ]
ok $? "... and not with -q"
"$RADIOSITY" formfactor -q -o "$work/par.npy" "$work/par.vs3" &&
  head -c 128 "$work/par.npy" | grep -q "'shape': (2, 2)"
ok $? ".npy: the 2 x 2 matrix too"
"$RADIOSITY" formfactor -q --per-surface "$work/par.vs3" > "$work/ps.tsv"
[ "$(($(wc -l < "$work/ps.tsv") - 1))" -eq 9 ]
ok $? "--per-surface keeps every input surface (3 x 3), as it keeps O surfaces"

# Unequal parts (0.3 and 0.7 of the upper square): the union's row is the
# area-weighted mean of its members' rows (a plain mean is not C-11 here),
# and so is its error estimate, which bounds the mean's error by the
# triangle inequality; its column is the members' sum, errors too.  The
# members' own entries come from the same file without the CMB.
sed -e 's/^V 9 .5 0 1$/V 9 .3 0 1/' -e 's/^V 10 .5 1 1$/V 10 .3 1 1/' "$work/par.vs3" > "$work/par2.vs3"
sed 's/ 0 2 0.9 top-b$/ 0 0 0.9 top-b/' "$work/par2.vs3" > "$work/par2u.vs3"
"$RADIOSITY" formfactor -q --accuracy reference "$work/par2.vs3" > "$work/c.tsv" &&
  "$RADIOSITY" formfactor -q --accuracy reference "$work/par2u.vs3" > "$work/u.tsv"
ok $? "unequal halves, combined and not: formfactor runs"
f01=$(entry "$work/c.tsv" 0 1) f10=$(entry "$work/c.tsv" 1 0)
close_to "$f01" "$want" 1e-9 && close_to "$f10" "$want" 1e-9
ok $? "0.3 + 0.7: square -> union $f01, union -> square $f10, C-11 $want within 1e-9"
err() { awk -F '\t' -v i="$2" -v j="$3" 'NR > 1 && $1 == i && $2 == j { print $4 }' "$1"; }
why=$(awk -v c10="$(err "$work/c.tsv" 1 0)" -v c01="$(err "$work/c.tsv" 0 1)" \
  -v a="$(err "$work/u.tsv" 1 0)" -v b="$(err "$work/u.tsv" 2 0)" \
  -v p="$(err "$work/u.tsv" 0 1)" -v q="$(err "$work/u.tsv" 0 2)" 'BEGIN {
    r = 0.3 * a + 0.7 * b; c = p + q
    printf "union -> square %s (0.3 x %s + 0.7 x %s = %.3g), square -> union %s (%.3g)", c10, a, b, r, c01, c
    # the table prints 3 digits: equal within 1% of each
    exit !(r > 0 && c > 0 && (c10 - r) ^ 2 <= (0.01 * r) ^ 2 && (c01 - c) ^ 2 <= (0.01 * c) ^ 2) }')
ok $? "the error estimates reduce as the factors do: $why"
printf 'View3D 3.2 0 0 0 2\n1 1\n0.000000 0.199825\n0.199825 0.000000\n0.900 0.900\n' > "$work/par2.vf"
"$RADIOSITY" compare -q --tolerance 1e-5 --report "$work/r.json" "$work/par2.vs3" "$work/par2.vf"
ok $? "compare takes View3D's 2 x 2 matrix for the unequal halves"
r=$(sed -n 's/.*"reciprocity_abs": \([^,]*\),.*/\1/p' "$work/r.json")
awk -v r="$r" 'BEGIN { exit !(r != "" && r + 0 <= 1e-12) }'
ok $? "its reciprocity uses the union's area 1, not its first part's 0.3 (|A_i G_ij - A_j G_ji| = $r)"

# Any mesh: the union is one row wherever its elements are (at its first
# element), every other element its own.  --mesh 2x2: the square's 4
# elements, then the union: 5 x 5; the union's row to the 4 is C-11.
"$RADIOSITY" formfactor -q --accuracy reference --mesh 2x2 "$work/par.vs3" > "$work/m.tsv"
why=$(awk -F '\t' -v want="$want" 'NR > 1 { n++; if ($1 == 4 && $2 < 4) u += $3; if ($2 == 4 && $1 < 4) s += $3 / 4 }
  END { d = u - want; e = s - want; d = d < 0 ? -d : d; e = e < 0 ? -e : e
        printf "%d entries, union -> square %.17g, square -> union %.17g", n, u, s
        exit !(n == 25 && d <= 1e-9 * want && e <= 1e-9 * want) }' "$work/m.tsv")
ok $? "--mesh 2x2: 5 x 5, the union's row and column add up to C-11: $why"

# ---- compare: View3D's matrix, ours, wrong shapes ----
printf 'View3D 3.2 0 0 0 2\n1 1\n0.000000 0.199825\n0.199825 0.000000\n0.900 0.900\n' > "$work/par.vf"
"$RADIOSITY" compare --tolerance 1e-5 "$work/par.vs3" "$work/par.vf" > "$work/out" 2> "$work/err"
ok $? "compare reads View3D's 2 x 2 matrix of the combined scene (within 1e-5)"
grep -q "^radiosity: their matrix has one row and column for each union of combined surfaces (1 joined, View3D's CMB), as View3D's has: compared on 2 rows with the unions' areas$" "$work/err"
ok $? "... and says so on standard error"
"$RADIOSITY" compare --tolerance 1e-9 "$work/par.vs3" "$work/par.vf" > "$work/out" 2> "$work/err"
[ $? -eq 1 ]; ok $? "... whose six decimals are not within 1e-9: exit 1"
"$RADIOSITY" formfactor -q --accuracy reference -o "$work/par.tsv" "$work/par.vs3" &&
  "$RADIOSITY" compare -q --tolerance 1e-12 "$work/par.vs3" "$work/par.tsv" 2> "$work/err" &&
  [ ! -s "$work/err" ]
ok $? "compare reads our own combined table (its diagonal too), within 1e-12, quiet with -q"
"$RADIOSITY" formfactor -q --accuracy reference -o "$work/par.npy" "$work/par.vs3" &&
  "$RADIOSITY" compare -q --tolerance 1e-12 "$work/par.vs3" "$work/par.npy"
ok $? "... and our .npy"
printf 'View3D 3.2 0 0 0 4\n1 1 1 1\n0 0 0 0\n0 0 0 0\n0 0 0 0\n0 0 0 0\n1 1 1 1\n' > "$work/four.vf"
"$RADIOSITY" compare "$work/par.vs3" "$work/four.vf" > "$work/out" 2> "$work/err"
[ $? -eq 1 ] && grep -q "(View3D's shape for the scene: 2 rows, its 1 combined surfaces joined; or one per element: 3)$" "$work/err"
ok $? "a 4 x 4 matrix for it is refused, naming both shapes: $(head -c 300 "$work/err")"
"$RADIOSITY" compare --mesh 2x2 "$work/par.vs3" "$work/par.vf" > "$work/out" 2> "$work/err"
[ $? -eq 1 ] && grep -q "par.vf:1: .*(View3D's shape for the scene: 5 rows.*; or one per element: 12)" "$work/err"
ok $? "with --mesh 2x2 (5 rows, 12 elements) the 2 x 2 matrix is refused: $(head -c 300 "$work/err")"
printf 'element\tcx\tcy\tcz\n' > "$work/el.tsv"
"$RADIOSITY" compare --elements "$work/el.tsv" "$work/par.vs3" "$work/par.vf" > "$work/out" 2> "$work/err"
[ $? -eq 2 ] && grep -q "keeps View3D's order" "$work/err"
ok $? "--elements with combined surfaces: a usage error ($(head -c 200 "$work/err"))"

# ---- a closed 2 x 1 x 1.5 box: floor in 2 halves, ceiling in 4 quarters,
# a wall in 2, each combined back; rows: floor, ceiling, x0, x2, y0, y1
cat > "$work/box.vs3" << 'EOF'
T a 2 x 1 x 1.5 box, walls split and combined back (CMB)
F 3
V 1  0 0 0
V 2  2 0 0
V 3  2 1 0
V 4  0 1 0
V 5  0 0 1.5
V 6  2 0 1.5
V 7  2 1 1.5
V 8  0 1 1.5
V 9  1 0 0
V 10 1 1 0
V 11 1 0 1.5
V 12 1 1 1.5
V 13 0 .5 1.5
V 14 2 .5 1.5
V 15 1 .5 1.5
!  n  v1 v2 v3 v4  base cmb emit name
S  1   1  9 10  4   0   0  0.9  floor-a
S  2  15 11  5 13   0   0  0.9  ceiling-1
S  3   1  4  8  5   0   0  0.9  x0
S  4   7  3  2  6   0   0  0.9  x2
S  5   1  5 11  9   0   0  0.9  y0-a
S  6   7  8  4  3   0   0  0.9  y1
S  7   9  2  3 10   0   1  0.9  floor-b
S  8  14  6 11 15   0   2  0.9  ceiling-2
S  9   7 14 15 12   0   2  0.9  ceiling-3
S 10  12 15 13  8   0   2  0.9  ceiling-4
S 11   9 11  6  2   0   5  0.9  y0-b
End
EOF
# box_check TABLE TOL ROWS: row r of the table is wall w = ROWS[r] (0-5 as
# above, 9 for an element of a wall that is not combined); every entry
# between whole walls against C-11 or C-14, the rows of whole walls summed
# to 1 and reciprocity with the walls' areas, each within TOL
box_check() {
  awk -F '\t' -v tol="$2" -v rows="$3" "$CF"'
    BEGIN { D["x"] = 2; D["y"] = 1; D["z"] = 1.5
            split("z z x x y y", ax, " "); split(rows, w, " ")
            for (r in w) wall[r - 1] = w[r] }
    function want(I, J,   a, b, t) {
      a = ax[I + 1]; b = ax[J + 1]
      if (a == b) {
        if (a == "x") return c11(D["y"], D["z"], D["x"])
        if (a == "y") return c11(D["x"], D["z"], D["y"])
        return c11(D["x"], D["y"], D["z"])
      }
      t = (a != "x" && b != "x") ? "x" : (a != "y" && b != "y") ? "y" : "z"
      return c14(D[t], D[b], D[a])
    }
    function area(I,   a) { a = ax[I + 1]; return a == "x" ? D["y"] * D["z"] : a == "y" ? D["x"] * D["z"] : D["x"] * D["y"] }
    function bad(d, s) { d = d < 0 ? -d : d; return d > tol * s }
    NR > 1 { I = wall[$1]; J = wall[$2]; n++
             if (I != 9) sum[I] += $3
             if (I == 9 || J == 9) next
             F[I, J] = $3; m++
             if (I != J && bad($3 - want(I, J), want(I, J))) { worst = "F(" I " -> " J ") " $3 " vs " want(I, J); fail = 1 }
             if (I == J && $3 != 0) { worst = "F(" I " -> " I ") = " $3; fail = 1 } }
    END { for (I = 0; I < 6; I++) {
            if (I in sum && bad(sum[I] - 1, 1)) { worst = "row " I " sums to " sum[I]; fail = 1 }
            for (J = 0; J < 6; J++)
              if ((I, J) in F && (J, I) in F && bad(area(I) * F[I, J] - area(J) * F[J, I], area(I) * F[I, J])) {
                worst = "reciprocity " I ", " J; fail = 1 } }
          printf "%d entries, %d between whole walls; %s", n, m, fail ? worst : "all within tolerance"
          exit fail }' "$1"
}
"$RADIOSITY" formfactor --accuracy reference "$work/box.vs3" > "$work/box.tsv" 2> "$work/err"
why=$(box_check "$work/box.tsv" 1e-9 "0 1 2 3 4 5")
ok $? "box, reference: the 6 x 6 unions' matrix is the closed forms', rows sum to 1, reciprocity: $why"
grep -q "5 surfaces combined with earlier ones.*: 6 x 6" "$work/err"; ok $? "... 5 surfaces combined"
"$RADIOSITY" formfactor -q --accuracy default "$work/box.vs3" > "$work/box.tsv"
why=$(box_check "$work/box.tsv" 1e-6 "0 1 2 3 4 5"); ok $? "box, default: within 1e-6: $why"
# --mesh 2x2: x0, x2 and y1 are not combined: 4 rows each, of a quarter
# wall; the sums of their rows are 1 too, and the unions' entries to one
# another are still the closed forms
"$RADIOSITY" formfactor -q --accuracy reference --mesh 2x2 "$work/box.vs3" > "$work/box.tsv"
why=$(box_check "$work/box.tsv" 1e-9 "0 1 9 9 9 9 9 9 9 9 4 9 9 9 9")
ok $? "box --mesh 2x2: the unions' entries and row sums: $why"
n=$(awk 'END { print NR - 1 }' "$work/box.tsv")
[ "$n" -eq 225 ] && awk -F '\t' 'NR > 1 { s[$1] += $3 }
  END { for (i in s) { d = s[i] - 1; if (d < 0) d = -d; if (d > 1e-9) exit 1 } }' "$work/box.tsv"
ok $? "box --mesh 2x2: 15 x 15 ($n entries), every row sums to 1"
"$RADIOSITY" formfactor -q --accuracy reference -o "$work/box.npy" "$work/box.vs3" &&
  "$RADIOSITY" compare -q --tolerance 1e-12 "$work/box.vs3" "$work/box.npy"
ok $? "box: compare accepts our own 6 x 6 .npy within 1e-12"

# ---- two faces of a corner, combined: the union sees itself ----
cat > "$work/corner.vs3" << 'EOF'
T a 1 x 2 floor and a 1 x 0.5 wall along its edge of length 1, combined
V 1 0 0 0
V 2 1 0 0
V 3 1 2 0
V 4 0 2 0
V 5 0 0 .5
V 6 1 0 .5
S 1  1 2 3 4  0 0 0.9 floor
S 2  1 5 6 2  0 1 0.9 wall
E
EOF
want=$(awk "$CF"' BEGIN { printf "%.17g", 2 * 2 * c14(1, 2, 0.5) / (2 + 0.5) }')
"$RADIOSITY" formfactor -q --accuracy reference "$work/corner.vs3" > "$work/c.tsv"
f00=$(entry "$work/c.tsv" 0 0)
[ "$(($(wc -l < "$work/c.tsv") - 1))" -eq 1 ] && close_to "$f00" "$want" 1e-9 &&
  awk -v f="$f00" 'BEGIN { exit !(f > 0) }'
ok $? "corner: one row, F_00 = $f00 > 0, 2 A_f F_fw / (A_f + A_w) = $want by C-14"

# ---- the reader still refuses what View3D refuses, at FILE:LINE ----
refused() { # refused FILE LINE WHAT
  "$RADIOSITY" formfactor "$1" > /dev/null 2> "$work/err"
  [ $? -eq 1 ] && grep -q "^radiosity: $1:$2: .*$3" "$work/err"
  ok $? "refused at line $2: $(head -c 200 "$work/err")"
}
sed 's/^S 3  9 10 7 8  0 2 0.9 top-b$/S 3  9 10 7 8  0 3 0.9 top-b/' "$work/par.vs3" > "$work/fwd.vs3"
refused "$work/fwd.vs3" 15 "combine surface must be from 0 to 2"
sed 's/^S 3  9 10 7 8  0 2 0.9 top-b$/S 3  9 10 7 8  0 2 0.9 top-b\
V 11 2 2 2\
S 4  9 10 7 8  0 3 0.9 chained/' "$work/par.vs3" > "$work/chain.vs3"
refused "$work/chain.vs3" 17 "surface 4 combines with 3, which itself combines with 2"
sed 's/^S 2  5 6 10 9  0 0 0.9 top-a$/O 2  5 6 10 9/' "$work/par.vs3" > "$work/obs.vs3"
refused "$work/obs.vs3" 15 "surface 3 follows an obstruction surface"

done_testing
