#!/bin/sh
# edgeon.sh -- the area rules' round-off, two polygons nearly edge on
# (estimates that must bound the error).  Two rectangles of
# 2^-6 x 2^-6 sqrt 2, their vertices exact in binary, stand in the plane
# x + y = 0, 1.41 apart along it, each turned by t out of it towards the
# other, so that every cosine of the area form is a difference of terms
# 1/t times larger than itself.  The rules summed those in double and
# counted no round-off: at t = 2^-18 both modes were 2.6e-11 of F off
# under estimates of 7.9e-12 of it, at 2^-26 default was 8e-9 off under
# 4.3e-10 (src/ff/ffarea.c now bounds the round-off, eqs. R1-R3, and sums
# again in long double where the bound is too large; what is left is the
# rounding of the normals, which the bound counts).
#
# The expected values are independent of the program: the area form,
# integral of (n_a . d)(-n_b . d) / (pi |d|^4) over both rectangles / A_a,
# by Gauss-Legendre product rules of 6 and of 12 points a side (agreeing
# to 25 digits) in mpmath at 40 digits, the rectangles and their normals
# exact: with h = 2^-7, rectangle e spans (0, 0, 0) +- u +- v with
# u = h (1 + t, -1 + t, 0), v = (0, 0, h), rectangle w spans
# (1, -1, 0) +- u' +- v with u' = h (1 - t, -1 - t, 0).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

pair() {
  printf 'material e reflect 0.5 emit 1\nmaterial w reflect 0.5\nquad e %s\nquad w %s\n' "$1" "$2"
}

# t = 2^-18: both modes within their promises, their estimates covering
pair "-0.007812529802322388 0.007812470197677612 -0.0078125 0.007812529802322388 -0.007812470197677612 -0.0078125 0.007812529802322388 -0.007812470197677612 0.0078125 -0.007812529802322388 0.007812470197677612 0.0078125" \
  "0.9921875298023224 -0.9921874701976776 -0.0078125 1.0078124701976776 -1.0078125298023224 -0.0078125 1.0078124701976776 -1.0078125298023224 0.0078125 0.9921875298023224 -0.9921874701976776 0.0078125" > "$work/t18.scene"
against_value "$work/t18.scene" 0 1 7.9967406146446238e-16 1e-30 "t = 2^-18:"

# t = 2^-26: default within its promise; each mode's estimate covers its
# error (reference's contour says it misses its promise: the bound of the
# normals' rounding alone is 3e-7 of F there)
pair "-0.007812500116415322 0.007812499883584678 -0.0078125 0.007812500116415322 -0.007812499883584678 -0.0078125 0.007812500116415322 -0.007812499883584678 0.0078125 -0.007812500116415322 0.007812499883584678 0.0078125" \
  "0.9921875001164153 -0.9921874998835847 -0.0078125 1.0078124998835847 -1.0078125001164153 -0.0078125 1.0078124998835847 -1.0078125001164153 0.0078125 0.9921875001164153 -0.9921874998835847 0.0078125" > "$work/t26.scene"
want=1.2202057822727686e-20
estimate_covers "$work/t26.scene" 0 1 "$want" reference "t = 2^-26:"
estimate_covers "$work/t26.scene" 0 1 "$want" default "t = 2^-26:"
close_to "$got" "$want" 1e-6
ok $? "t = 2^-26, default: within 1e-6 of $want"
done_testing
