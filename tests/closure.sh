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
done_testing
