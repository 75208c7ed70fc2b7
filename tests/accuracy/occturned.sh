#!/bin/sh
# occturned.sh -- a furnished room turned and scaled gives the form
# factors it gives upright (the answer once depended on where the scene
# sat).  Form factors are invariant under rotation and uniform
# scaling, so the room's table upright is the independent value for the
# table turned: each entry above 1e-6 within the mode's promise (1e-6
# default, 1e-9 reference) of the upright one, and the two estimates
# together at or above every difference.
#
# The room is one the geometry fuzzer's first room family made
# (tests/geomfuzz.py at af114e8, seed 99, scene 79, before its random
# turn): two boxes on a floor cut around them, one pushed against the
# wall x = 0, so that edges of the
# box, of the wall and of the floor cells lie in common planes.  An event
# of three edges two of which are coplanar is a pair of planes; with
# coordinates rounded by the turn its conic became a hyperbola hugging
# them, and its sharp turn was cut into strip after strip
# (src/occ/occeee.c, coplanar_lines): turned by 40 degrees about (1, 2, 3) and
# scaled by 36000, default mode took 29 s and 1.7 GB where the upright
# room took 1.4 s and 11 MB (randomly turned: 2.5 GB, out of memory).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

cat > "$work/upright.scene" <<'SCENE'
material e reflect 0.4 emit 1
material w reflect 0.6 0.5 0.3
quad e 0 1 1 1 1 1 1 0 1 0 0 1 mesh 1x2
quad w 0 0 1 1 0 1 1 0 0 0 0 0 mesh 1x2
quad w 1 1 0 1 1 1 0 1 1 0 1 0 mesh 2x1
quad w 0 1 0 0 1 1 0 0 1 0 0 0 mesh 1x1
quad w 1 0 1 1 1 1 1 1 0 1 0 0 mesh 2x2
quad w 0.0 0.0 0.0 0.15481013140253214 0.0 0.0 0.15481013140253214 0.03110605483489685 0.0 0.0 0.03110605483489685 0.0 mesh 1x1
quad w 0.0 0.43853026678753354 0.0 0.15481013140253214 0.43853026678753354 0.0 0.15481013140253214 0.7004915575471549 0.0 0.0 0.7004915575471549 0.0 mesh 1x1
quad w 0.0 0.7004915575471549 0.0 0.15481013140253214 0.7004915575471549 0.0 0.15481013140253214 1.0 0.0 0.0 1.0 0.0 mesh 1x1
quad w 0.15481013140253214 0.0 0.0 0.55 0.0 0.0 0.55 0.03110605483489685 0.0 0.15481013140253214 0.03110605483489685 0.0 mesh 1x1
quad w 0.15481013140253214 0.03110605483489685 0.0 0.55 0.03110605483489685 0.0 0.55 0.3672212078440013 0.0 0.15481013140253214 0.3672212078440013 0.0 mesh 1x1
quad w 0.15481013140253214 0.3672212078440013 0.0 0.55 0.3672212078440013 0.0 0.55 0.43853026678753354 0.0 0.15481013140253214 0.43853026678753354 0.0 mesh 1x1
quad w 0.15481013140253214 0.43853026678753354 0.0 0.55 0.43853026678753354 0.0 0.55 0.7004915575471549 0.0 0.15481013140253214 0.7004915575471549 0.0 mesh 1x1
quad w 0.15481013140253214 0.7004915575471549 0.0 0.55 0.7004915575471549 0.0 0.55 1.0 0.0 0.15481013140253214 1.0 0.0 mesh 1x1
quad w 0.55 0.0 0.0 0.6751069432379597 0.0 0.0 0.6751069432379597 0.03110605483489685 0.0 0.55 0.03110605483489685 0.0 mesh 1x1
quad w 0.55 0.03110605483489685 0.0 0.6751069432379597 0.03110605483489685 0.0 0.6751069432379597 0.3672212078440013 0.0 0.55 0.3672212078440013 0.0 mesh 1x1
quad w 0.55 0.7004915575471549 0.0 0.6751069432379597 0.7004915575471549 0.0 0.6751069432379597 1.0 0.0 0.55 1.0 0.0 mesh 1x1
quad w 0.6751069432379597 0.0 0.0 1.0 0.0 0.0 1.0 0.03110605483489685 0.0 0.6751069432379597 0.03110605483489685 0.0 mesh 1x1
quad w 0.6751069432379597 0.03110605483489685 0.0 1.0 0.03110605483489685 0.0 1.0 0.3672212078440013 0.0 0.6751069432379597 0.3672212078440013 0.0 mesh 1x1
quad w 0.6751069432379597 0.3672212078440013 0.0 1.0 0.3672212078440013 0.0 1.0 0.43853026678753354 0.0 0.6751069432379597 0.43853026678753354 0.0 mesh 1x1
quad w 0.6751069432379597 0.43853026678753354 0.0 1.0 0.43853026678753354 0.0 1.0 0.7004915575471549 0.0 0.6751069432379597 0.7004915575471549 0.0 mesh 1x1
quad w 0.6751069432379597 0.7004915575471549 0.0 1.0 0.7004915575471549 0.0 1.0 1.0 0.0 0.6751069432379597 1.0 0.0 mesh 1x1
quad w 0.0 0.03110605483489684 0.3123131355466956 0.15481013140253214 0.03110605483489684 0.3123131355466956 0.15481013140253214 0.43853026678753354 0.3123131355466956 0.0 0.43853026678753354 0.3123131355466956 mesh 1x1
quad w 0.0 0.03110605483489684 0.0 0.15481013140253214 0.03110605483489684 0.0 0.15481013140253214 0.03110605483489684 0.3123131355466956 0.0 0.03110605483489684 0.3123131355466956 mesh 1x1
quad w 0.0 0.43853026678753354 0.0 0.0 0.43853026678753354 0.3123131355466956 0.15481013140253214 0.43853026678753354 0.3123131355466956 0.15481013140253214 0.43853026678753354 0.0 mesh 1x1
quad w 0.0 0.03110605483489684 0.0 0.0 0.03110605483489684 0.3123131355466956 0.0 0.43853026678753354 0.3123131355466956 0.0 0.43853026678753354 0.0 mesh 1x1
quad w 0.15481013140253214 0.03110605483489684 0.0 0.15481013140253214 0.43853026678753354 0.0 0.15481013140253214 0.43853026678753354 0.3123131355466956 0.15481013140253214 0.03110605483489684 0.3123131355466956 mesh 1x1
quad w 0.55 0.3672212078440013 0.15286854391851176 0.6751069432379597 0.3672212078440013 0.15286854391851176 0.6751069432379597 0.7004915575471549 0.15286854391851176 0.55 0.7004915575471549 0.15286854391851176 mesh 1x1
quad w 0.55 0.3672212078440013 0.0 0.6751069432379597 0.3672212078440013 0.0 0.6751069432379597 0.3672212078440013 0.15286854391851176 0.55 0.3672212078440013 0.15286854391851176 mesh 1x1
quad w 0.55 0.7004915575471549 0.0 0.55 0.7004915575471549 0.15286854391851176 0.6751069432379597 0.7004915575471549 0.15286854391851176 0.6751069432379597 0.7004915575471549 0.0 mesh 1x1
quad w 0.55 0.3672212078440013 0.0 0.55 0.3672212078440013 0.15286854391851176 0.55 0.7004915575471549 0.15286854391851176 0.55 0.7004915575471549 0.0 mesh 1x1
quad w 0.6751069432379597 0.3672212078440013 0.0 0.6751069432379597 0.7004915575471549 0.0 0.6751069432379597 0.7004915575471549 0.15286854391851176 0.6751069432379597 0.3672212078440013 0.15286854391851176 mesh 1x1
SCENE

# turn by 40 degrees about (1, 2, 3) / sqrt 14 (Rodrigues), scale by 36000
awk -v S=36000 'BEGIN { a = 40 * atan2(0, -1) / 180; c = cos(a); s = sin(a); t = 1 - c
    n = sqrt(14); x = 1 / n; y = 2 / n; z = 3 / n
    m[1,1] = t*x*x + c; m[1,2] = t*x*y - s*z; m[1,3] = t*x*z + s*y
    m[2,1] = t*x*y + s*z; m[2,2] = t*y*y + c; m[2,3] = t*y*z - s*x
    m[3,1] = t*x*z - s*y; m[3,2] = t*y*z + s*x; m[3,3] = t*z*z + c }
  $1 == "quad" { out = $1 " " $2
    for (k = 0; k < 4; k++)
      for (i = 1; i <= 3; i++) {
        v = 0
        for (j = 1; j <= 3; j++) v += m[i,j] * $(3 + 3 * k + j - 1)
        out = out " " sprintf("%.17g", S * v)
      }
    print out " " $15 " " $16; next }
  { print }' "$work/upright.scene" > "$work/turned.scene"

for case in "default 1e-6" "reference 1e-9"; do
  set -- $case
  for s in upright turned; do
    # a guard, not a measurement: before the fix the turned room took
    # minutes and gigabytes
    (ulimit -t 120; "$RADIOSITY" formfactor -q --threads 1 --accuracy "$1" "$work/$s.scene" \
      -o "$work/$s-$1.tsv")
    ok $? "$1: the room $s: formfactor"
  done
  awk -F '\t' -v tol="$2" '
    FNR == 1 { next }
    NR == FNR { f[$1 " " $2] = $3; e[$1 " " $2] = $4; next }
    { k = $1 " " $2; d = $3 - f[k]; if (d < 0) d = -d
      if (f[k] > 1e-6 && d > tol * f[k]) bad++
      if (d > $4 + e[k]) miss++
      n++ }
    END { printf "%d %d %d\n", n, bad, miss; exit !(n > 0 && bad == 0 && miss == 0) }' \
    "$work/upright-$1.tsv" "$work/turned-$1.tsv" > "$work/cmp"
  ok $? "$1: turned and scaled, every entry above 1e-6 within $2 of upright, estimates covering (entries, off, uncovered: $(cat "$work/cmp"))"
  # and a check that does not lean on the upright room: every element
  # sees only the inside of the closed room, so its row sums to 1 (the
  # summation relation), but for the box's face pressed against the wall
  # x = 0 (element 30, which sees nothing) and the wall's element 6 behind
  # it (which cannot see through the box)
  awk -F '\t' -v tol="$2" 'NR > 1 && $1 != 6 && $1 != 30 { r[$1] += $3 }
    END { w = 0; for (i in r) { d = r[i] - 1; if (d < 0) d = -d; if (d > w) w = d }
          printf "%.3g\n", w; exit !(w <= tol) }' "$work/turned-$1.tsv" > "$work/rows"
  ok $? "$1: turned and scaled, rows of F sum to 1 within $2 (worst $(cat "$work/rows"))"
done
done_testing
