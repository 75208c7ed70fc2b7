#!/bin/sh
# example.sh -- examples/solve_cube, linked against the shared library as
# a user's program would be, runs and prints the centre element of each
# wall of the 1984 cube.  Its values are held against what they must be:
# the light reflects nothing, so its B equals its emission E = 1 exactly
# (B = E + rho F B with rho = 0); every other wall lies between 0 and the
# furnace bound E_max / (1 - rho_max); and each agrees with the element
# table of `radiosity solve` (the same library reached another way).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
ex="${top_builddir:-.}/examples/solve_cube"
cube="$top_srcdir/data/goral1984-cube.scene"
"$ex" "$cube" > "$work/out"; ok $? "the example runs"
[ "$(awk 'NR > 1' "$work/out" | wc -l)" -eq 6 ]; ok $? "one line per wall"
awk -F'\t' 'NR == 2 { exit !($1 == 0 && $3 == 1 && $4 == 1 && $5 == 1) }' "$work/out"
ok $? "the light's centre element: B = E = 1 (it reflects nothing)"
awk -F'\t' 'NR > 2 { for (b = 3; b <= 5; b++) if (!($b > 0 && $b < 1 / (1 - 0.8))) bad = 1 }
  END { exit bad }' "$work/out"
ok $? "the walls lie between 0 and the furnace bound 1/(1 - 0.8)"
"$RADIOSITY" solve -q --elements "$work/e.tsv" "$cube"
awk -F'\t' 'NR == FNR { if (FNR > 1) { r[$2] = $3; g[$2] = $4; b[$2] = $5 } next }
  FNR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  ($(c["element"]) in r) { e = $(c["element"]); n++
    if ((r[e] - $(c["r"]))^2 > 1e-12 || (g[e] - $(c["g"]))^2 > 1e-12 || (b[e] - $(c["b"]))^2 > 1e-12) bad = 1 }
  END { exit bad || n != 6 }' "$work/out" "$work/e.tsv"
ok $? "each value equals the element table of radiosity solve (to the 6 decimals printed)"
done_testing
