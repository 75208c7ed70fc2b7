#!/bin/sh
# progress_adaptive.sh -- `radiosity progress --adaptive`: the race of
# Cohen et al. 1988 (figure 7) with adaptive subdivision (section 4), on
# data/blocker.scene meshed 4 x 4 (threshold 0.07, depth 2: about 480
# elements at convergence, a couple of seconds).
#
# What each check stands on:
#   - the sorted run is `solve --solver progressive --adaptive` with the
#     same options, step for step: at the step the solve reports
#     converging (its report's sweeps) the snapshot's element table is the
#     solve's, element for element and level for level, to round-off;
#   - the error of a step is eq. 14 against the converged solution
#     projected onto the step's elements; tests/progress_adaptive.py
#     recomputes it from the tables alone (containment by surface, level,
#     gi, gj; area means), for the sorted run against the solve's table and
#     for the file-order run against its own converged snapshot; the two
#     must agree to round-off;
#   - at convergence the error is 0 (<= 1e-9), and no later row moves;
#     on this scene no step raises the error by more than 1 %;
#   - the error picture of the converged step is all grey (error 0) and
#     that of step 1 is not;
#   - the snapshots show the mesh of their step: 64 starting elements, all
#     level 0, at step 0, more and deeper ones later, and different
#     pictures;
#   - gathering is left out (no column, no snapshot); the refusals are
#     solve's.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found"
  exit 0
fi
scene="$top_srcdir/data/blocker.scene"
py="$top_srcdir/tests/progress_adaptive.py"
opts="--mesh 4x4 --subdivide-threshold 0.07 --max-depth 2"

# ---- usage errors (exit 2, a message naming an option) --------------------
usage() { # usage DESCRIPTION ARGS...
  what=$1; shift
  "$RADIOSITY" progress -q "$@" "$scene" > "$work/u.out" 2>&1
  [ $? -eq 2 ] && grep -q -- "^radiosity: .*--[a-z]" "$work/u.out"
  ok $? "usage error: $what"
}
usage "--subdivide-threshold without --adaptive" --subdivide-threshold 0.2
usage "--max-depth without --adaptive" --max-depth 2
usage "--adaptive --patches" --adaptive --patches
usage "--adaptive --matrix dense" --adaptive --matrix dense
usage "--adaptive with the hemicube" --adaptive --form-factors-method hemicube
usage "--max-depth 9 (0 to 8)" --adaptive --max-depth 9
usage "--subdivide-threshold -1" --adaptive --subdivide-threshold -1
usage "--subdivide-threshold x" --adaptive --subdivide-threshold x

# ---- the converged solve, and the race ------------------------------------
"$RADIOSITY" solve -q --solver progressive --adaptive $opts --elements "$work/solve.tsv" \
  --report "$work/solve.json" "$scene"
ok $? "solve --solver progressive --adaptive"
K=$(sed -n 's/.*"sweeps": *\([0-9]*\).*/\1/p' "$work/solve.json" | head -n 1)
diag "the solve converges after $K steps"
# 5000: past both orders' convergence (--steps grows to it): the file-order
# snapshot there is its converged solution
"$RADIOSITY" progress --adaptive $opts --snapshots-at "0,1,24,$K,5000" --snapshot-elements \
  --error-images --snapshot-prefix "$work/s" -o "$work/race.tsv" --plot "$work/race.png" \
  "$scene" 2> "$work/summary"
ok $? "progress --adaptive with snapshots, tables, error images and a plot"
[ "$(head -n 1 "$work/race.tsv")" = "$(printf 'step\tshooting\tsorted\tsorted_ambient\tshooting_bands\tsorted_bands\tsorted_ambient_bands')" ]
ok $? "the table's columns: no gathering"
[ "$(tail -n +2 "$work/race.tsv" | wc -l)" -eq 5001 ]; ok $? "rows for steps 0 to 5000"
grep -q 'gathering left out' "$work/summary"; ok $? "the summary says gathering is left out"
n=$(ls "$work" | grep -c '^s-gathering')
[ "$n" -eq 0 ]; ok $? "no gathering snapshots ($n)"

# col NAME STEP: the table's value
col() { awk -F'\t' -v n="$1" -v k="$2" 'NR == 1 { for (c = 1; c <= NF; c++) if ($c == n) x = c; next }
  $1 == k { print $x }' "$work/race.tsv"; }

# ---- the error: 0 at convergence, falling, and what it is measured against -
for m in sorted sorted_ambient; do
  e=$(col $m "$K")
  close_to "$e" 0 1e-9; ok $? "$m at the converged step $K: error $e <= 1e-9"
done
e=$(col shooting 5000)
close_to "$e" 0 1e-9; ok $? "shooting (file order) converged by step 5000: error $e"
bad=$(awk -F'\t' -v K="$K" 'NR > 2 && $1 > K { for (c = 2; c <= NF; c++) if ($c != p[c] && c != 2 && c != 5) n++ }
  NR > 1 { for (c = 2; c <= NF; c++) p[c] = $c } END { print n + 0 }' "$work/race.tsv")
[ "$bad" -eq 0 ]; ok $? "after the sorted run converges its rows stay ($bad changes)"
up=$(awk -F'\t' 'NR > 2 { for (c = 2; c <= NF; c++) if ($c > 1.01 * p[c] + 1e-300) n++ }
  NR > 1 { for (c = 2; c <= NF; c++) p[c] = $c } END { print n + 0 }' "$work/race.tsv")
[ "$up" -eq 0 ]; ok $? "no step raises any error column by more than 1% ($up)"
e0=$(col sorted 0); e8=$(col sorted 24)
awk -v a="$e0" -v b="$e8" 'BEGIN { exit !(a > 0.01 && b < 0.7 * a) }'
ok $? "the error starts large and falls (step 0 $e0, step 24 $e8)"
for step in 1 24; do
  k=$(printf '%06d' "$step")
  set -- $(python3 "$py" project "$work/s-sorted-$k.tsv" "$work/solve.tsv")
  e=$(col sorted "$step")
  close_to "$1" "$e" 1e-9
  ok $? "sorted step $k: eq. 14 against the solve's table projected ($1, $2 elements) = the table's $e"
  set -- $(python3 "$py" project "$work/s-shooting-$k.tsv" "$work/s-shooting-005000.tsv")
  e=$(col shooting "$step")
  close_to "$1" "$e" 1e-9
  ok $? "shooting step $k: eq. 14 against its own converged table projected ($1) = the table's $e"
done

# ---- the converged step is the solve ---------------------------------------
t="$work/s-sorted-$(printf '%06d' "$K").tsv"
[ "$(wc -l < "$t")" -eq "$(wc -l < "$work/solve.tsv")" ]
ok $? "sorted snapshot at step $K: as many elements as the solve ($(wc -l < "$t") lines)"
d=$(paste "$t" "$work/solve.tsv" | awk -F'\t' 'NR == 1 { w = NF / 2; next }
  { for (c = 1; c <= w; c++) { a = $c; b = $(c + w); d = a - b; if (d < 0) d = -d
      s = b < 0 ? -b : b; if (c <= 4 || c == w) { if (a != b) bad++ } else if (d > 1e-12 * (s > 1 ? s : 1)) bad++ } }
  END { print bad + 0 }')
[ "$d" -eq 0 ]; ok $? "... element for element: surface, gi, gj, level equal, numbers within 1e-12 ($d differ)"

# ---- snapshots: the mesh of their step --------------------------------------
for m in shooting sorted sorted_ambient; do
  [ "$(head -n 1 "$work/s-$m-000024.tsv" | awk -F'\t' '{ print $NF }')" = level ]
  ok $? "$m's snapshot table ends with the column level"
done
set -- $(awk -F'\t' 'NR > 1 { n++; if ($NF != 0) deep++ } END { print n + 0, deep + 0 }' "$work/s-sorted-000000.tsv")
[ "$1" -eq 64 ] && [ "$2" -eq 0 ]; ok $? "step 0: the 64 starting elements, all level 0 ($1, $2)"
set -- $(awk -F'\t' 'NR > 1 { n++; if ($NF > 0) deep++ } END { print n + 0, deep + 0 }' "$work/s-sorted-000024.tsv")
[ "$1" -gt 64 ] && [ "$2" -gt 0 ]; ok $? "step 24: split ($1 elements, $2 below level 0)"
n=0
for m in shooting sorted sorted_ambient; do
  for k in 000000 000001 000024 005000; do
    for f in "$m-$k.png" "$m-$k-error.png" "$m-$k.tsv"; do [ -s "$work/s-$f" ] && n=$((n + 1)); done
  done
done
[ "$n" -eq 36 ]; ok $? "a picture, an error picture and a table per method and step ($n of 36)"
! cmp -s "$work/s-sorted-000001.png" "$work/s-sorted-000024.png"; ok $? "the pictures of steps 1 and 24 differ"
! cmp -s "$work/s-sorted-000024.png" "$work/s-sorted-$(printf '%06d' "$K").png"
ok $? "the pictures of step 24 and of convergence differ"
set -- $(python3 "$py" grey "$work/s-sorted-$(printf '%06d' "$K")-error.png")
[ "$1" -eq 0 ]; ok $? "error picture at convergence: every element grey (error 0; $1 of $2 pixels not)"
set -- $(python3 "$py" grey "$work/s-sorted-000001-error.png")
[ "$1" -gt 0 ]; ok $? "error picture after one shot: not all grey ($1 of $2 pixels)"
head -c 8 "$work/race.png" | od -An -c | grep -q 'P   N   G'; ok $? "the plot is a PNG"

done_testing
