#!/bin/sh
# twisted.sh -- a polygon of five vertices, one of them 5e-7 off the plane
# of the others (2.6e-7 of its size; the scene accepts 1e-6), facing a
# plate (estimates that must bound the error).
#   - 5 from the plate, at 30 degrees to it: the area rules took the
#     polygon's one normal where its surface turns, and reference was
#     5e-7 of F off under an estimate of 2e-12 of it (src/ff/ffarea.c now
#     integrates a twisted polygon over its fan of triangles, each with
#     its own normal);
#   - 0.05 from the plate, hinged to it at 179.9 degrees: the plate was
#     clipped to the front of the pentagon's mean plane, which the twist
#     leaves uncertain, and both modes were 1e-6 of F off the contour
#     integral of the two polygons under estimates of 1e-16 of it
#     (src/ff/formfactor.c, pair_setup: that doubt is now in the estimate;
#     the promise cannot be kept there, and --strict says so).
#
# The expected values are independent of the program: the contour
# integral of the two polygons as given (Stokes: any surface spanning a
# contour gives it) in mpmath, as tests/heldout.py computes it (the inner
# integral in closed form, the outer by tanh-sinh; 25 and 40 digits
# agreeing to 1e-17), and for the first pair also an area-area rule in
# numpy over the pentagon's fan of triangles, each with its own normal,
# to the plate by the point-to-polygon closed form (Lambert 1760): the two
# agree within 3e-18 (2e-14 of F).  F is taken from the plate (element 1)
# to the pentagon (element 0): the plate's area is the same in every
# reading of the twist.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

# pentagon X0 X1 Z1: the pentagon, and the plate from (X0, y, 0) to
# (X1, y, Z1), y from -0.2 to 1.2
pentagon() {
  cat <<EOF
material e reflect 0.4 emit 1
material w reflect 0.5
polygon e 5 0 0 0 1 0 0 1.3 0.6 5e-7 0.5 1.1 0 -0.3 0.6 0
quad w $1 -0.2 0 $2 -0.2 $3 $2 1.2 $3 $1 1.2 0
EOF
}

pentagon 6.2999999999999998 7.1660254037844382 0.49999999999999994 > "$work/far.scene"
against_value "$work/far.scene" 1 0 0.00016666306407547152 3e-18 "5 apart, at 30 degrees:"

# 0.05 apart, hinged at 179.9 degrees: each mode's estimate covers the
# difference from the contour integral, and --strict refuses the result
pentagon 1.3500000000000001 2.3499984769132878 0.0017453283658983088 > "$work/hinge.scene"
for mode in default reference; do
  estimate_covers "$work/hinge.scene" 1 0 1.3186002976515879e-07 "$mode" "hinged at 179.9 degrees:"
done
"$RADIOSITY" formfactor -q --strict --accuracy reference "$work/hinge.scene" > "$work/strict.out" 2>&1
ok $(($? == 0)) "hinged at 179.9 degrees: --strict refuses what the twist leaves undecided"
"$RADIOSITY" formfactor -q --accuracy default "$work/hinge.scene" > "$work/default.out" 2> "$work/default.err"
grep -q "cannot lift a twisted polygon's doubt" "$work/default.err"
ok $? "hinged at 179.9 degrees: default's warning does not promise that reference mode helps"
done_testing
