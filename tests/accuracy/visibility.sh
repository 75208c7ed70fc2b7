#!/bin/sh
# visibility.sh -- hidden surfaces through the command line: the shipped
# Cornell box scenes (size, orientation of every face, closure of the closed
# variant) and the blocker scene's shadow.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
open="$top_srcdir/data/cornell-box.scene"
closed="$top_srcdir/data/cornell-box-closed.scene"
blocker="$top_srcdir/data/blocker.scene"

# Elements of a scene from its text: N*M per `mesh NxM` quad, one per polygon.
count() {
  awk '$1 == "quad" { m = "1x1"; for (k = 1; k <= NF; k++) if ($k == "mesh") m = $(k + 1)
                      split(m, a, "x"); n += a[1] * a[2] }
       $1 == "polygon" || $1 == "disk" { n++ } END { print n }' "$1"
}
nc=$(count "$closed")
no=$(count "$open")
[ "$nc" -ge 2700 ] && [ "$nc" -le 3300 ]; ok $? "closed Cornell box: about 3000 elements ($nc)"
[ $((nc - no)) -eq 420 ]; ok $? "the open box is the closed one without its 420-element front wall"

# Orientation: every element's front normal (element table, by column name)
# points into the room for the room's faces and away from the block for the
# blocks' faces.  Room faces lie on the box 556 x 548.8 x 559.2; the rest
# belong to the short block (centre 186 82.5 168.5) or the tall block
# (centre 368.5 165 351.5), told apart by x + z.
"$RADIOSITY" solve -q --mesh 1x1 --elements "$work/e1.tsv" "$closed"
ok $? "solve the closed box at --mesh 1x1"
awk -F'\t' 'function abs(v) { return v < 0 ? -v : v }
  NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { x = $c["cx"]; y = $c["cy"]; z = $c["cz"]; nx = $c["nx"]; ny = $c["ny"]; nz = $c["nz"]
    room = abs(x) < 1e-9 || abs(x - 556) < 1e-9 || abs(y) < 1e-9 || abs(y - 548.8) < 1e-9 ||
           abs(z) < 1e-9 || abs(z - 559.2) < 1e-9
    if (room) d = (278 - x) * nx + (274.4 - y) * ny + (279.6 - z) * nz
    else if (x + z < 600) d = (x - 186) * nx + (y - 82.5) * ny + (z - 168.5) * nz
    else d = (x - 368.5) * nx + (y - 165) * ny + (z - 351.5) * nz
    n++; if (!(d > 0)) { bad++; print "# wrong way round: element " $1 " surface " $2 } }
  END { if (n != 36) bad++; exit bad > 0 }' "$work/e1.tsv"
ok $? "every face of the Cornell box is counter-clockwise seen from the side that reflects"

# The closed box at its shipped mesh: every row of F sums to 1.
start=$(date +%s)
"$RADIOSITY" solve -q --report "$work/r.json" --elements "$work/e.tsv" "$closed"
ok $? "solve the closed Cornell box ($nc elements, default accuracy)"
diag "closed Cornell box: solve took $(($(date +%s) - start)) s"
lo=$(sed -n 's/^ *"row_sum_min": *\([^,]*\),*$/\1/p' "$work/r.json")
hi=$(sed -n 's/^ *"row_sum_max": *\([^,]*\),*$/\1/p' "$work/r.json")
close_to "$lo" 1 1e-3 && close_to "$hi" 1 1e-3
ok $? "closed Cornell box: rows of F sum to 1 within 1e-3 (min $lo, max $hi)"
[ "$(tail -n +2 "$work/e.tsv" | wc -l)" -eq "$nc" ]; ok $? "the element table has $nc rows"

# The blocker's shadow: without it the middle of the top square would be
# its brightest part; with it the middle is in the penumbra (its centre in
# the umbra) and gets less than half of what the corners get.
"$RADIOSITY" solve -q --mesh 4x4 --bounces 1 --elements "$work/b.tsv" "$blocker"
ok $? "solve the blocker scene"
awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  $c["surface"] == 1 { r = $c["r"]; x = $c["cx"]; y = $c["cy"]
    if (x > 0.25 && x < 0.75 && y > 0.25 && y < 0.75) { mid = r > mid ? r : mid }
    else if ((x < 0.25 || x > 0.75) && (y < 0.25 || y > 0.75)) { corner = corner == "" || r < corner ? r : corner } }
  END { exit !(mid < 0.5 * corner) }' "$work/b.tsv"
ok $? "blocker scene, one bounce: the top square is darker behind the blocker than at its corners"

# A picture of the open box (coarse mesh: the check is that it renders).
"$RADIOSITY" render -q --mesh 2x2 --width 64 --height 64 "$open" -o "$work/box.png"
ok $? "render the open Cornell box"
[ "$(head -c 4 "$work/box.png" | tail -c 3)" = PNG ]; ok $? "the picture is a PNG"

# A two-sided blocker (a disk and its reverse, the same 24-gon) hides
# exactly what the one-sided disk hides: the reversed twin adds nothing
# (occshaft.c), so every form factor between the plates is the same double
# in both scenes, in default and reference mode.
plates='material m reflect 0.5 emit 1
quad m 0 0 0 1 0 0 1 1 0 0 1 0 mesh 2x2
quad m 0 0 1 0 1 1 1 1 1 1 0 1 mesh 2x2
disk m 0.5 0.5 0.5 0 0 1 0.2 24'
printf '%s\n' "$plates" > "$work/one.scene"
printf '%s\ndisk m 0.5 0.5 0.5 0 0 -1 0.2 24\n' "$plates" > "$work/two.scene"
for mode in default reference; do
  "$RADIOSITY" formfactor -q --accuracy $mode "$work/one.scene" 2> /dev/null |
    awk -F'\t' 'NR > 1 && $1 < 8 && $2 < 8' > "$work/one.tsv"
  "$RADIOSITY" formfactor -q --accuracy $mode "$work/two.scene" 2> /dev/null |
    awk -F'\t' 'NR > 1 && $1 < 8 && $2 < 8' > "$work/two.tsv"
  [ -s "$work/one.tsv" ] && cmp -s "$work/one.tsv" "$work/two.tsv" &&
    awk -F'\t' '$3 > 0 && $3 < 0.2 { n++ } END { exit !(n > 0) }' "$work/one.tsv"
  ok $? "$mode: a two-sided disk blocker gives the one-sided disk's plate-to-plate factors, bit for bit"
done
done_testing
