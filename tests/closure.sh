#!/bin/sh
# closure.sh -- rows of F sum to 1 in a closed scene with blockers (issue
# 20): a closed box with a smaller box inside it, every pair between the
# outer walls partly hidden by the inner box.  In an enclosure
# sum_j F_ij = 1 exactly (the summation relation of form factors, one of
# the identities of DESIGN.md section 3), and entries within their mode's
# relative promise move a row by at most the promise: default rows within
# 1e-6 of 1, reference rows within 1e-9.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

# Outer box [0,1]^3 facing in, inner box [0.3,0.7] x [0.25,0.6] x [0.35,0.65]
# facing out (counter-clockwise seen from the side that reflects).
cat > "$work/box.scene" <<'SCENE'
material w reflect 0.5 emit 1
quad w 1 0 0  1 1 0  0 1 0  0 0 0
quad w 0 1 1  1 1 1  1 0 1  0 0 1
quad w 0 0 1  1 0 1  1 0 0  0 0 0
quad w 1 1 0  1 1 1  0 1 1  0 1 0
quad w 0 1 0  0 1 1  0 0 1  0 0 0
quad w 1 0 1  1 1 1  1 1 0  1 0 0
quad w 0.3 0.6 0.35  0.7 0.6 0.35  0.7 0.25 0.35  0.3 0.25 0.35
quad w 0.7 0.25 0.65  0.7 0.6 0.65  0.3 0.6 0.65  0.3 0.25 0.65
quad w 0.7 0.25 0.35  0.7 0.25 0.65  0.3 0.25 0.65  0.3 0.25 0.35
quad w 0.3 0.6 0.65  0.7 0.6 0.65  0.7 0.6 0.35  0.3 0.6 0.35
quad w 0.3 0.25 0.65  0.3 0.6 0.65  0.3 0.6 0.35  0.3 0.25 0.35
quad w 0.7 0.6 0.35  0.7 0.6 0.65  0.7 0.25 0.65  0.7 0.25 0.35
SCENE

for case in "default 1e-6" "reference 1e-9"; do
  set -- $case
  for mesh in 1x1 2x2; do
    "$RADIOSITY" solve -q --accuracy "$1" --mesh "$mesh" --report "$work/r.json" "$work/box.scene"
    ok $? "box in a box, $1, --mesh $mesh: solve"
    lo=$(sed -n 's/^ *"row_sum_min": *\([^,]*\),*$/\1/p' "$work/r.json")
    hi=$(sed -n 's/^ *"row_sum_max": *\([^,]*\),*$/\1/p' "$work/r.json")
    close_to "$lo" 1 "$2" && close_to "$hi" 1 "$2"
    ok $? "box in a box, $1, --mesh $mesh: rows of F sum to 1 within $2 (min $lo, max $hi)"
  done
done
# Two blocks standing on the floor of a closed room, the floor cut into
# rectangles around their footprints (as the closed Cornell box's is):
# seen from the walls their shadows overlap, and where a vertex of one
# block passes an edge of the other the hidden part has a kink that only
# a cut of the domain along that event plane lets the rules see
# (src/occdomain.c, split_two_blockers).  Without it rows missed 1 by
# 1.6e-6 in default mode and 1.9e-8 in reference mode.
cat > "$work/two.scene" <<'SCENE'
material w reflect 0.5 emit 1
quad w 0 0 0  1 0 0  1 1 0  0 1 0
quad w 0 0 1  0 1 1  1 1 1  1 0 1
quad w 0 1 0  1 1 0  1 1 1  0 1 1
quad w 0 0 0  0 1 0  0 1 1  0 0 1
quad w 1 0 0  1 0 1  1 1 1  1 1 0
quad w 0 0 0  0 0 1  0.2 0 1  0.2 0 0
quad w 0.2 0 0  0.2 0 0.3  0.4 0 0.3  0.4 0 0
quad w 0.2 0 0.5  0.2 0 1  0.4 0 1  0.4 0 0.5
quad w 0.4 0 0  0.4 0 1  0.6 0 1  0.6 0 0
quad w 0.6 0 0  0.6 0 0.5  0.8 0 0.5  0.8 0 0
quad w 0.6 0 0.7  0.6 0 1  0.8 0 1  0.8 0 0.7
quad w 0.8 0 0  0.8 0 1  1 0 1  1 0 0
quad w 0.2 0.5 0.3  0.2 0.5 0.5  0.4 0.5 0.5  0.4 0.5 0.3
quad w 0.4 0 0.3  0.4 0.5 0.3  0.4 0.5 0.5  0.4 0 0.5
quad w 0.4 0 0.5  0.4 0.5 0.5  0.2 0.5 0.5  0.2 0 0.5
quad w 0.2 0 0.5  0.2 0.5 0.5  0.2 0.5 0.3  0.2 0 0.3
quad w 0.2 0 0.3  0.2 0.5 0.3  0.4 0.5 0.3  0.4 0 0.3
quad w 0.6 0.3 0.5  0.6 0.3 0.7  0.8 0.3 0.7  0.8 0.3 0.5
quad w 0.8 0 0.5  0.8 0.3 0.5  0.8 0.3 0.7  0.8 0 0.7
quad w 0.8 0 0.7  0.8 0.3 0.7  0.6 0.3 0.7  0.6 0 0.7
quad w 0.6 0 0.7  0.6 0.3 0.7  0.6 0.3 0.5  0.6 0 0.5
quad w 0.6 0 0.5  0.6 0.3 0.5  0.8 0.3 0.5  0.8 0 0.5
SCENE

# rows SCENE MODE MESH TOL WHAT: solve, and rows of F within TOL of 1
rows() {
  "$RADIOSITY" solve -q --accuracy "$2" --mesh "$3" --report "$work/r.json" "$1"
  ok $? "$5, $2, --mesh $3: solve"
  lo=$(sed -n 's/^ *"row_sum_min": *\([^,]*\),*$/\1/p' "$work/r.json")
  hi=$(sed -n 's/^ *"row_sum_max": *\([^,]*\),*$/\1/p' "$work/r.json")
  close_to "$lo" 1 "$4" && close_to "$hi" 1 "$4"
  ok $? "$5, $2, --mesh $3: rows of F sum to 1 within $4 (min $lo, max $hi)"
}
rows "$work/two.scene" default 1x1 1e-6 "two blocks on the floor"
rows "$work/two.scene" reference 1x1 1e-9 "two blocks on the floor"

# Each entry, not only each row: with 6 and 8 blockers the pairs of this
# room start with about a thousand pieces of domain, once more than the
# adaptive rule's whole budget of cells, so none was split and default
# mode missed its promise in 6 entries (src/occhidden.c, integrate),
# F(3 -> 11) by 2.9e-6.  The expected value is tests/pairref.py's for the
# wall x = 0, the floor strip 0.8 < x < 1 and the two blocks as solids
# (tests/closure-two.spec), at its tolerance 1e-8:
# `python3 tests/pairref.py tests/closure-two.spec 1e-8` prints
# 0.0072460216848951849 and its estimate 7.25e-11 (after ten minutes, so
# the value is stated here).
want=0.0072460216848951849
"$RADIOSITY" formfactor -q --threads 1 --accuracy default "$work/two.scene" -o "$work/two.tsv" \
  2> "$work/two.err"
ok $? "two blocks on the floor, default: formfactor"
grep -q promise "$work/two.err"
ok $((!$?)) "two blocks on the floor, default: no entry misses its promise by its own estimate"
row=$(awk -F '\t' '$1 == 3 && $2 == 11 { printf "%.17g %.3g", $3, $4 }' "$work/two.tsv")
close_to "${row% *}" "$want" 1e-6
ok $? "two blocks on the floor, default: F(3 -> 11) = ${row% *} within 1e-6 of $want"
awk -v g="${row% *}" -v e="${row#* }" -v w="$want" \
  'BEGIN { d = g - w; if (d < 0) d = -d; exit !(g == g + 0 && d <= e + 7.25e-11) }'
ok $? "two blocks on the floor, default: its estimate ${row#* } and pairref's cover the difference"

# The closed Cornell box (issue 20), on meshes that make check can afford:
# default within its 1e-6 (it missed by 6.8e-6 on this mesh before the
# two-blocker cuts; 1.8e-7 after, 6.2e-9 since the events of three edges
# are cut too).  Reference mode on the 2x2 mesh missed by 3.7e-7 before
# those cuts, 3.2e-8 after them, 2.8e-9 with the conics of the events of
# three edges cut along one chord, and 6.0e-10 now that strongly curved
# ones are followed by strips (src/occeee.c): within the issue's 1e-9.
closed="${top_srcdir}/data/cornell-box-closed.scene"
rows "$closed" default 3x3 1e-6 "closed Cornell box"
rows "$closed" reference 2x2 1e-9 "closed Cornell box"
done_testing
