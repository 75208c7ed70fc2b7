#!/bin/sh
# closure.sh -- rows of F sum to 1 in a closed scene with blockers: a
# closed box with a smaller box inside it, every pair between the outer
# walls partly hidden by the inner box.  In an enclosure
# sum_j F_ij = 1 exactly (the summation relation of form factors, one of
# the identities of doc/design.md, "Tests and benchmarks"), and entries
# within their mode's relative promise move a row by at most the promise:
# default rows within 1e-6 of 1, reference rows within 1e-9.
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
# (src/occ/occdomain.c, split_two_blockers).  Without it rows missed 1 by
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
# mode missed its promise in 6 entries (src/occ/occhidden.c, integrate),
# F(3 -> 11) by 2.9e-6.  The expected value is tests/pairref.py's for the
# wall x = 0, the floor strip 0.8 < x < 1 and the two blocks as solids
# (tests/closure-two.spec), at its tolerance 1e-8:
# `python3 tests/pairref.py tests/closure-two.spec 1e-8` prints
# 0.0072460216848951849 and its estimate 7.25e-11, then the unoccluded
# factor (after ten minutes, so the value is stated here).
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

# A fuzzed room (tests/geomfuzz.py seed 62, scene 1231): 2.9e-5 across,
# turned, two boxes open at the bottom standing on its floor, one of
# them 4.4e-9 (1.5e-4 of the room) in front of a wall.  Every row but
# the floor's (element 13, which sees into the boxes through their
# footprints, where the boxes' inner faces turn their backs) sums to 1.
# Seen from the wall behind the box, the planes of the box's near face
# cut the domain of the hidden part into 95,000 pieces, and the slivers
# those cuts dropped lost 6.8e-9 of the wall element's area where four
# fifths of the floor is hidden: its reference row summed to 1 + 2.3e-9
# under estimates of 5e-10 (src/occ/occspace.c, occ_cut_piece).
cat > "$work/fuzz1231.scene" <<'SCENE'
material e reflect 0.4 emit 1
material w reflect 0.6 0.5 0.3
quad e 1.0714006045183713e-06 1.5289311429048283e-05 2.493908235411467e-05 2.172157944394384e-05 1.387363862835314e-05 2.4919837389376312e-05 2.034013975522608e-05 -6.2118517543455995e-06 2.0113686494897135e-05 -3.1003908419938584e-07 -4.796178953650458e-06 2.0132931459635493e-05 mesh 1x2
quad w -3.1003908419938584e-07 -4.796178953650458e-06 2.0132931459635493e-05 2.034013975522608e-05 -6.2118517543455995e-06 2.0113686494897135e-05 2.0650178839425467e-05 -1.4156728006951418e-06 -1.92449647383562e-08 0.0 0.0 0.0 mesh 2x2
quad w 2.2031618528143227e-05 1.8669817582003597e-05 4.786905929740823e-06 2.172157944394384e-05 1.387363862835314e-05 2.4919837389376312e-05 1.0714006045183713e-06 1.5289311429048283e-05 2.493908235411467e-05 1.3814396887177573e-06 2.008549038269874e-05 4.806150894479179e-06 mesh 2x2
quad w 1.3814396887177573e-06 2.008549038269874e-05 4.806150894479179e-06 1.0714006045183713e-06 1.5289311429048283e-05 2.493908235411467e-05 -3.1003908419938584e-07 -4.796178953650458e-06 2.0132931459635493e-05 0.0 0.0 0.0 mesh 1x2
quad w 2.034013975522608e-05 -6.2118517543455995e-06 2.0113686494897135e-05 2.172157944394384e-05 1.387363862835314e-05 2.4919837389376312e-05 2.2031618528143227e-05 1.8669817582003597e-05 4.786905929740823e-06 2.0650178839425467e-05 -1.4156728006951418e-06 -1.92449647383562e-08 mesh 1x1
quad w 2.0650178839425467e-05 -1.4156728006951418e-06 -1.92449647383562e-08 2.2031618528143227e-05 1.8669817582003597e-05 4.786905929740823e-06 1.3814396887177573e-06 2.008549038269874e-05 4.806150894479179e-06 0.0 0.0 0.0 mesh 1x1
quad w 3.5008442674091734e-06 7.36588387574061e-06 8.952747607214298e-06 5.5857291960822894e-06 8.635321939959984e-06 9.287266599345242e-06 2.889836736947545e-06 1.2811729955315981e-05 1.0240678090089218e-05 8.049518082744292e-07 1.154229189109661e-05 9.906159097958274e-06 mesh 1x1
quad w 3.604928827472636e-06 8.976029827711315e-06 2.1938342296468046e-06 5.689813756145752e-06 1.024546789193069e-05 2.5283532217777493e-06 5.5857291960822894e-06 8.635321939959984e-06 9.287266599345242e-06 3.5008442674091734e-06 7.36588387574061e-06 8.952747607214298e-06 mesh 1x1
quad w 9.090363683378916e-07 1.3152437843067316e-05 3.1472457203907803e-06 8.049518082744292e-07 1.154229189109661e-05 9.906159097958274e-06 2.889836736947545e-06 1.2811729955315981e-05 1.0240678090089218e-05 2.9939212970110075e-06 1.4421875907286687e-05 3.4817647125217246e-06 mesh 1x1
quad w 3.604928827472636e-06 8.976029827711315e-06 2.1938342296468046e-06 3.5008442674091734e-06 7.36588387574061e-06 8.952747607214298e-06 8.049518082744292e-07 1.154229189109661e-05 9.906159097958274e-06 9.090363683378916e-07 1.3152437843067316e-05 3.1472457203907803e-06 mesh 1x1
quad w 5.689813756145752e-06 1.024546789193069e-05 2.5283532217777493e-06 2.9939212970110075e-06 1.4421875907286687e-05 3.4817647125217246e-06 2.889836736947545e-06 1.2811729955315981e-05 1.0240678090089218e-05 5.5857291960822894e-06 8.635321939959984e-06 9.287266599345242e-06 mesh 1x1
quad w 1.2987215879697602e-05 8.97101367009073e-07 7.68189751438315e-06 1.8380609825736834e-05 5.273572997923644e-07 7.676871132911169e-06 1.9144403030887315e-05 1.1632555160916614e-05 1.0334175267222237e-05 1.375100908484808e-05 1.2002299228133323e-05 1.0339201648694218e-05 mesh 1x1
quad w 1.3093108388986935e-05 2.535215560625126e-06 8.055817843317601e-07 1.8486502335026168e-05 2.1654714934084174e-06 8.005554028597787e-07 1.8380609825736834e-05 5.273572997923644e-07 7.676871132911169e-06 1.2987215879697602e-05 8.97101367009073e-07 7.68189751438315e-06 mesh 1x1
quad w 1.3856901594137416e-05 1.3640413421749374e-05 3.4628859186428297e-06 1.375100908484808e-05 1.2002299228133323e-05 1.0339201648694218e-05 1.9144403030887315e-05 1.1632555160916614e-05 1.0334175267222237e-05 1.925029554017665e-05 1.3270669354532667e-05 3.457859537170848e-06 mesh 1x1
quad w 1.3093108388986935e-05 2.535215560625126e-06 8.055817843317601e-07 1.2987215879697602e-05 8.97101367009073e-07 7.68189751438315e-06 1.375100908484808e-05 1.2002299228133323e-05 1.0339201648694218e-05 1.3856901594137416e-05 1.3640413421749374e-05 3.4628859186428297e-06 mesh 1x1
quad w 1.8486502335026168e-05 2.1654714934084174e-06 8.005554028597787e-07 1.925029554017665e-05 1.3270669354532667e-05 3.457859537170848e-06 1.9144403030887315e-05 1.1632555160916614e-05 1.0334175267222237e-05 1.8380609825736834e-05 5.273572997923644e-07 7.676871132911169e-06 mesh 1x1
SCENE
# rows_but SCENE MODE TOL SKIP WHAT: every row of F but row SKIP within TOL of 1
rows_but() {
  "$RADIOSITY" formfactor -q --threads 1 --accuracy "$2" "$1" -o "$work/rows.tsv" 2> /dev/null
  ok $? "$5, $2: formfactor"
  worst=$(awk -F '\t' -v skip="$4" 'NR > 1 && $1 != skip { s[$1] += $3 }
    END { w = 0; for (i in s) { d = s[i] - 1; if (d < 0) d = -d; if (d > w) { w = d; wi = i } }
          printf "%.3g %d", w, wi }' "$work/rows.tsv")
  close_to "${worst% *}" 0 "$3"
  ok $? "$5, $2: rows of F but $4 sum to 1 within $3 (worst row ${worst#* }, off by ${worst% *})"
}
rows_but "$work/fuzz1231.scene" default 1e-6 13 "fuzzed room 62:1231"
rows_but "$work/fuzz1231.scene" reference 1e-9 13 "fuzzed room 62:1231"

# The closed Cornell box, on meshes that make check can afford:
# default within its 1e-6 (it missed by 6.8e-6 on this mesh before the
# two-blocker cuts; 1.8e-7 after, 6.2e-9 since the events of three edges
# are cut too).  Reference mode on the 2x2 mesh missed by 3.7e-7 before
# those cuts, 3.2e-8 after them, 2.8e-9 with the conics of the events of
# three edges cut along one chord, and 6.0e-10 now that strongly curved
# ones are followed by strips (src/occ/occeee.c): within reference's 1e-9.
closed="${top_srcdir}/data/cornell-box-closed.scene"
rows "$closed" default 3x3 1e-6 "closed Cornell box"
rows "$closed" reference 2x2 1e-9 "closed Cornell box"
# The same box written as 144 separate quadrilaterals (each quad's 2 x 2
# elements a surface of its own, as View3D files list them): the coplanar
# pieces are merged into patches and the blocks found as solids again
# (src/occ/occflat.c, occsolid.c); a patch or a cull that let light
# through a block, or hid an element from its own face, moves a row.
if command -v python3 > /dev/null 2>&1; then
  python3 "$top_srcdir/bench/scenes.py" split 2 "$closed" > "$work/split.scene"
  rows "$work/split.scene" default 1x1 1e-6 "closed Cornell box as 144 quads"
fi
done_testing
