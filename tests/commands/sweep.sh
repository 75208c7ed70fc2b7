#!/bin/sh
# sweep.sh -- radiosity sweep: the table's rows and the solvers it races.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Every solver solves the same system on the same F, so at one mesh and
# accuracy their errors against the truth differ only by what each solver
# leaves: round-off for gauss and cholesky, at most the tolerance (1e-12,
# a bound on the relative error of B) for the iterative ones.  The error
# of an RMS against a truth of size ~1 moves by no more than that, so
# 1e-9 absolute is a margin of 1000.
. "${top_srcdir:-.}/tests/lib.sh"
scene="$top_srcdir/data/grey-cube.scene"

"$RADIOSITY" sweep -q --meshes 1,2 --accuracies default \
  --solvers gauss,cholesky,jacobi,gauss-seidel,cg,progressive -o "$work/s.tsv" "$scene"
ok $? "sweep with all six solvers: exit 0"
rows=$(awk 'NR > 1' "$work/s.tsv" | wc -l)
[ "$rows" -eq 12 ]; ok $? "2 meshes x 6 solvers = 12 rows ($rows)"
awk -F '\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  $c["solver"] == "gauss" { g[$c["mesh"]] = $c["rms_error"] }
  { e[NR] = $c["rms_error"]; m[NR] = $c["mesh"]; s[NR] = $c["solver"] }
  END { for (k in e) { d = e[k] - g[m[k]]; if (d < 0) d = -d
      if (!(m[k] in g) || d > 1e-9) { print "# " s[k] " " m[k] " differs by " d; bad = 1 } }
    exit bad }' "$work/s.tsv"
ok $? "every solver's error equals gauss's within 1e-9 at each mesh"
for s in cholesky cg progressive; do
  grep -q "	$s	" "$work/s.tsv"; ok $? "the table has $s rows"
done

# closure: the grey cube is a closed convex enclosure, so every row of F
# sums to 1 (Goral et al. 1984, eq. 3) within the mode's promise summed
# over a row (1e-6 default, 1e-9 reference)
"$RADIOSITY" sweep -q --meshes 1,3 --accuracies default,reference -o "$work/c.tsv" "$scene"
awk -F '\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { t = $c["accuracy"] == "reference" ? 1e-9 : 1e-6; n++
    for (k = 0; k < 2; k++) { v = k ? $c["row_sum_max"] : $c["row_sum_min"]; d = v - 1
      if (d < 0) d = -d; if (!(v + 0 == v) || d > t) bad = 1 } }
  END { exit bad || n != 4 }' "$work/c.tsv"
ok $? "the closed cube's rows sum to 1 within each mode's promise (row_sum_min, row_sum_max)"

# the truth is finer than every row: on the 1984 cube (no closed form),
# meshes 1 and 2 are held against reference mode on 4 x 4, so the finest
# row keeps its discretisation error (a piecewise-constant 2 x 2 solution
# is no 4 x 4 one: percents, not the round-off a truth of its own mesh
# gave it)
"$RADIOSITY" sweep -q --meshes 1,2 --accuracies reference -o "$work/t.tsv" \
  "$top_srcdir/data/goral1984-cube.scene"
awk -F '\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { n++; if ($c["truth"] != "reference-4x4") bad = 1
    if ($c["mesh"] == "2x2" && !($c["rms_error"] > 1e-4)) bad = 1 }
  END { exit bad || n != 2 }' "$work/t.tsv"
ok $? "the truth is twice the finest mesh (reference-4x4), and the 2x2 row keeps its error ($(awk -F '\t' 'NR > 1 { printf "%s %s; ", $1, $8 }' "$work/t.tsv"))"

"$RADIOSITY" sweep -q --meshes 1 --solvers gauss,lu "$scene" > "$work/o" 2> "$work/err"
[ $? -eq 2 ] && grep -q 'cholesky' "$work/err"
ok $? "an unknown solver is a usage error that lists the six"
"$RADIOSITY" sweep --help | grep -q 'gauss,cholesky,jacobi,gauss-seidel,cg,progressive'
ok $? "sweep --help lists the six solvers"

done_testing
