#!/bin/sh
# areaorders.sh -- the area rules' orders agreeing by chance (an estimate
# below its error; found by tests/geomfuzz.py, seed 43, scene 368).  A
# square of side 1.6e-5 faces a unit plate, meshed 1 x 2, from 0.90
# above it.  The rule on the plate's half (cut 3 x 2) gave
# differences of 3.7e-15 and then 1.03e-19 between 2, 3 and 4 points a
# side; 4 points were taken with an estimate of 1.03e-19, where their S
# erred by 1.74e-19 (3.2e-9 of it, about the rho^-8 the rule converges
# at): default was 3.2e-9 of F off under an estimate of 1.9e-9 of it
# (src/ff/ffarea.c now floors the differences at that convergence rate).
#
# The expected values are independent of the program: the closed form of
# a point at height h on the normal through a corner of a parallel
# rectangle of sides a, b,
#   F = (X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2))
#        + Y / sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2))) / (2 pi),
# X = a/h, Y = b/h, summed with signs over the four corner rectangles, in
# mpmath at 40 digits, averaged over the square by a 12 x 12
# Gauss-Legendre rule (the integrand varies on the scale of 0.9, the
# square is 1.6e-5 wide).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

cat > "$work/s43_368.scene" <<EOF
material e reflect 0.4 emit 1
material w reflect 0.6 0.5 0.3
quad e 0.0 0.0 0.0 1.0 0.0 0.0 1.0 1.0 0.0 0.0 1.0 0.0 mesh 1x2
quad w 0.6456964239713755 0.5079949527754593 0.9012753253664447 0.6456964239713755 0.5080108649700842 0.9012753253664447 0.6457123361660004 0.5080108649700842 0.9012753253664447 0.6457123361660004 0.5079949527754593 0.9012753253664447 mesh 1x1
EOF
against_value "$work/s43_368.scene" 2 1 0.13678594564103176 1e-16 "43:368, the square to the far half:"
against_value "$work/s43_368.scene" 2 0 0.13478473491065924 1e-16 "43:368, the square to the near half:"
done_testing
