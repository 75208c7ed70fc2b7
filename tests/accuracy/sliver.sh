#!/bin/sh
# sliver.sh -- a sliver triangle and the triangle it shares its long edge
# with, at about 120 degrees: the degenerate geometry of triangulated
# models (a sliver 1e-3, 1e-6 and 1e-9 of its length high).
#
# The expected values are independent of the program: tests/sliverref.py
# integrates Lambert's point-to-polygon factor over the sliver by graded
# Gauss-Legendre rules, with 12 and 20 points a panel; their difference,
# plus 1e-15, is the slack allowed.  Default mode must be within its
# promise (1e-6 of the value) and its estimate must cover its error.
# Reference mode must be within 1e-9 where its estimate says it is, and
# say so where its estimate says otherwise (1e-9 thin: an estimate of
# 3.3e-7 of the value, an error of 3.9e-8); its estimate must cover its
# error too.  Classic mode's nine-point rule has no answer here (2.5e7 at
# 1e-9 thin) and must say so.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found"
  exit 0
fi
for h in 1e-3 1e-6 1e-9; do
  cat > "$work/s.scene" <<EOF
material w reflect 0.5
polygon w 3  0 0 0  1 0 0  0.5 $h 0
polygon w 3  0 0 0  0.3 -0.5 0.866  1 0 0
EOF
  ref=$(python3 "$top_srcdir/tests/sliverref.py" "$h")
  ok $? "independent F(sliver $h -> triangle) = $ref"
  set -- $ref
  want=$2
  slack=$(awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; printf "%.3g", d + 1e-15 }')
  for mode in default reference; do
    tol=1e-9
    [ "$mode" = default ] && tol=1e-6
    "$RADIOSITY" formfactor --threads 1 --accuracy "$mode" "$work/s.scene" \
      > "$work/f.tsv" 2> "$work/f.err"
    ok $? "$mode, $h: formfactor runs"
    row=$(awk -F '\t' '$1 == 0 && $2 == 1 { printf "%.17g %.3g\n", $3, $4 }' "$work/f.tsv")
    got=${row%% *}
    est=${row##* }
    if awk -v g="$got" -v e="$est" -v t="$tol" 'BEGIN { exit !(e <= t * g) }'; then
      close_to "$got" "$want" "$tol" "$slack"
      ok $? "$mode, $h: within $tol of $want ($got, estimate $est)"
    else
      grep -q "miss the $mode mode's promise" "$work/f.err"
      ok $? "$mode, $h: its estimate $est of $got misses the promise, and it says so"
    fi
    awk -v g="$got" -v e="$est" -v w="$want" -v s="$slack" \
      'BEGIN { d = g - w; if (d < 0) d = -d; exit !(g == g + 0 && d <= e + s) }'
    ok $? "$mode, $h: its estimate $est covers its error ($got against $want)"
  done
done
"$RADIOSITY" formfactor --accuracy classic "$work/s.scene" > /dev/null 2> "$work/c.err"
grep -q "the classic rule fails for this geometry" "$work/c.err"
ok $? "classic, 1e-9: says that its rule fails here"
done_testing
