#!/bin/sh
# occsolid.sh -- blocks as solids (src/occsolid.c): a pair leaves out the
# faces of a convex block that its other faces make redundant, and gets the
# same form factor; where the rule's conditions fail, it leaves out nothing.
#
# Independent references: tests/pairref.py (the blocks as convex hulls,
# shadows by projection, its own adaptive rule) for a pair behind both
# blocks of the Cornell box; and enclosure, for floor elements that a box
# covers (they see nothing above: F = 0).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

# A ceiling element and a floor element of the 6x6 Cornell box (160 and
# 432) with the ten faces of the two blocks between them, hidden to 1.1%
# of the unoccluded factor: seen from the ceiling the pair needs three of
# them (tests/occeee.sh checks the pair with those three alone).
cat > "$work/pair.scene" <<EOF
material white reflect 0.725 0.71 0.68
quad white 485 548.8 262  520.5 548.8 262  520.5 548.8 279.5  485 548.8 279.5
quad white 130 0 239.27848101265823  130 0 292.59873417721519  148.33333333333334 0 297.14338959212381  148.33333333333334 0 244.73206751054852
quad white 130 165 65  82 165 225  240 165 272  290 165 114
quad white 290 0 114  290 165 114  240 165 272  240 0 272
quad white 130 0 65  130 165 65  290 165 114  290 0 114
quad white 82 0 225  82 165 225  130 165 65  130 0 65
quad white 240 0 272  240 165 272  82 165 225  82 0 225
quad white 423 330 247  265 330 296  314 330 456  472 330 406
quad white 423 0 247  423 330 247  472 330 406  472 0 406
quad white 472 0 406  472 330 406  314 330 456  314 0 456
quad white 314 0 456  314 330 456  265 330 296  265 0 296
quad white 265 0 296  265 330 296  423 330 247  423 0 247
EOF
against_pairref "$work/pair.scene" "$top_srcdir/tests/cornell-pair.spec" 0 1 "the pair behind both blocks"

# box ROWS: a 4x4 floor of unit elements, a ceiling at 3 (2x2), and a
# box of footprint [1,3] x [1,3], four sides and a top with outward
# normals and no bottom: standing on the floor with ROWS "0 1", floating
# above it with "1 2".
box() {
  set -- $1
  cat <<EOF
material white reflect 0.5
material lamp reflect 0.5 emit 1
quad white 0 0 0  0 0 4  4 0 4  4 0 0  mesh 4x4
quad lamp 0 3 0  4 3 0  4 3 4  0 3 4  mesh 2x2
quad white 1 $2 1  1 $2 3  3 $2 3  3 $2 1
quad white 1 $1 1  1 $2 1  3 $2 1  3 $1 1
quad white 3 $1 1  3 $2 1  3 $2 3  3 $1 3
quad white 3 $1 3  3 $2 3  1 $2 3  1 $1 3
quad white 1 $1 3  1 $2 3  1 $2 1  1 $1 1
EOF
}
# Floor elements 5, 6, 9 and 10 lie under the footprint; the ceiling's are
# 16 to 19.  A box standing on an uncut floor encloses them: the rule must
# not take them for points outside the solid (it would leave out the top
# and the sides that hide everything), so F = 0.
box "0 1" > "$work/box.scene"
for mode in reference default classic; do
  "$RADIOSITY" formfactor -q --accuracy "$mode" "$work/box.scene" > "$work/box.tsv"
  awk -F '\t' 'NR > 1 && ($1 == 5 || $1 == 6 || $1 == 9 || $1 == 10) &&
               $2 >= 16 && $2 <= 19 && $3 != 0 { bad++ } END { exit bad > 0 }' "$work/box.tsv"
  ok $? "box on the floor, $mode: the floor under it sees nothing of the ceiling"
done
# A floating box shows its open bottom to those elements (they see the
# ceiling through the gap below it): the rule must see that they face the
# open side, or it leaves out the top.  Element 5 ([1,2] x [1,2]) to
# ceiling element 16 ([0,2] x [0,2]), against tests/pairref.py.
box "1 2" > "$work/box.scene"
cat > "$work/box.spec" <<EOF
outer 1 0 1  1 0 2  2 0 2  2 0 1
inner 0 3 0  2 3 0  2 3 2  0 3 2
solid 1 1 1  3 1 1  3 1 3  1 1 3  1 2 1  3 2 1  3 2 3  1 2 3
EOF
against_pairref "$work/box.scene" "$work/box.spec" 5 16 "floating box"

done_testing
