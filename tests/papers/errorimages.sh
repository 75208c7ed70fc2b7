#!/bin/sh
# errorimages.sh -- the pseudo-colour error images of Cohen et al. 1988,
# figures 2-5 (`progress --error-images`), the element tables behind the
# snapshots (--snapshot-elements) and the normalised, linear figure 7
# (--plot-axis linear --plot-normalised).  Copyright (C) 2026 The
# radiosity authors.  GPLv3+, see COPYING.
#
# Independent references: a fresh gauss solve of the same mesh (solve
# --elements) is the converged solution; the geometry of the Cornell box
# (the lamp's centre, 278 548.8 279.5, from data/cornell-box.scene) says
# which elements face the lamp.  An element that faces the lamp, lies
# below its plane and has B = 0 after the lamp (the first patch, all of
# its power) has shot is in shadow.  The paper's claim (section 4.2): the
# ambient term of eq. 13, uniform over the room, over-estimates there, and
# less as the unshot power shrinks.  Checked on the band-averaged
# radiosity Y that the error images colour:
#   - after 1 shot every shadowed element shows Y' > Y_converged (red);
#   - the area whose relative error exceeds 10% (a fifth of the colour
#     scale's full red at 50%) shrinks from shot 1 to shot 24.
. "${top_srcdir:-.}/tests/lib.sh"
box="$top_srcdir/data/cornell-box.scene"

"$RADIOSITY" progress -q --patches --mesh 3x3 --snapshots-at 1,24 --error-images \
  --snapshot-elements --snapshot-prefix "$work/c" -o "$work/race.tsv" "$box"
ok $? "progress --error-images --snapshot-elements on the Cornell box"
n=0
for m in gathering shooting sorted sorted_ambient; do
  for k in 000001 000024; do
    for f in "$m-$k.png" "$m-$k-error.png" "$m-$k.tsv"; do [ -s "$work/c-$f" ] && n=$((n + 1)); done
  done
done
[ "$n" -eq 24 ]; ok $? "an image, an error image and a table per method and step ($n of 24)"
head -c 8 "$work/c-sorted_ambient-000001-error.png" | od -An -c | grep -q 'P   N   G'
ok $? "the error image is a PNG"
head -n 1 "$work/c-sorted-000001.tsv" | tr '\t' '\n' | grep -qx area
ok $? "the snapshot's table is an element table"
"$RADIOSITY" solve -q --mesh 3x3 --elements "$work/conv.tsv" "$box" 2> /dev/null
ok $? "the converged solution, by a fresh gauss solve"

# shadow CONV FIRST-SHOT AMBIENT: "shadowed over share_over_10%"
shadow() {
  awk -F '\t' 'FNR == 1 { f++; for (k = 1; k <= NF; k++) c[$k] = k; next }
    { y = ($c["r"] + $c["g"] + $c["b"]) / 3 }
    f == 1 { yc[$1] = y; a[$1] = $c["area"]; n = $1 + 1
             lx = 278 - $c["cx"]; ly = 548.8 - $c["cy"]; lz = 279.5 - $c["cz"]
             front[$1] = $c["nx"] * lx + $c["ny"] * ly + $c["nz"] * lz > 0 && ly > 1e-9; next }
    f == 2 { y1[$1] = y; next }
    { ya[$1] = y }
    END { for (i = 0; i < n; i++) {
            if (front[i] && y1[i] == 0) { ns++; if (ya[i] > yc[i]) no++ }
            tot += a[i]; if (ya[i] - yc[i] > 0.1 * yc[i]) over += a[i] }
          printf "%d %d %.6f\n", ns, no, over / tot }' "$@"
}
set -- $(shadow "$work/conv.tsv" "$work/c-sorted-000001.tsv" "$work/c-sorted_ambient-000001.tsv")
s1=$1 o1=$2 a1=$3
set -- $(shadow "$work/conv.tsv" "$work/c-sorted-000001.tsv" "$work/c-sorted_ambient-000024.tsv")
a24=$3
[ "$s1" -gt 0 ] && [ "$o1" -eq "$s1" ]
ok $? "after 1 shot with the ambient term all $s1 shadowed elements are over-estimated ($o1 red)"
awk -v a="$a1" -v b="$a24" 'BEGIN { exit !(b < a) }'
ok $? "the area over-estimated by more than 10% shrinks from shot 1 to 24 ($a1 -> $a24 of the total)"

# the colour scale at the element: the error image at exposure 1 is flat,
# so its pixels are the colours of errcolour.c; checked in test_render

# ---- figure 7, normalised on a linear axis
"$RADIOSITY" progress --mesh 2x2 --steps 30 --plot "$work/lin.png" --plot-axis linear \
  --plot-normalised -o "$work/lin.tsv" "$top_srcdir/data/goral1984-cube.scene" 2> "$work/err"
ok $? "progress --plot-axis linear --plot-normalised"
head -c 8 "$work/lin.png" | od -An -c | grep -q 'P   N   G'; ok $? "the plot is a PNG"
"$RADIOSITY" solve -q --mesh 2x2 --elements "$work/cube.tsv" "$top_srcdir/data/goral1984-cube.scene"
want=$(awk -F '\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { y = ($c["r"] + $c["g"] + $c["b"]) / 3; s += $c["area"] * y * y; A += $c["area"] }
  END { printf "%.17g\n", sqrt(s / A) }' "$work/cube.tsv")
got=$(sed -n 's/.*RMS of the converged solution, //p' "$work/err")
close_to "$got" "$want" 1e-12; ok $? "the curves are divided by eq. 14 of the converged B against 0 ($got, by hand $want)"

# ---- an unwritable error picture or table is found before the work
for f in d-gathering-000001-error.png d-gathering-000001.tsv; do
  rm -rf "$work/d-"*; mkdir "$work/$f"
  "$RADIOSITY" progress -q --mesh 2x2 --snapshots-at 1 --error-images --snapshot-elements \
    --snapshot-prefix "$work/d" -o "$work/d-race.tsv" "$top_srcdir/data/goral1984-cube.scene" \
    2> "$work/err"; rc=$?
  [ $rc -eq 1 ] && [ ! -e "$work/d-race.tsv" ] && [ ! -e "$work/d-gathering-000001.png" ] &&
    grep -q "$f" "$work/err"
  ok $? "$f a directory: an error before any snapshot (exit $rc)"
done

# ---- usage errors
cube="$top_srcdir/data/goral1984-cube.scene"
for bad in "--error-images" "--snapshot-elements" "--exposure-from all" "--plot-axis linear" \
  "--plot-normalised" \
  "--plot-axis cubic --plot $work/x.png"; do
  # shellcheck disable=SC2086
  "$RADIOSITY" progress -q --mesh 2x2 $bad -o "$work/bad.tsv" "$cube" > /dev/null 2>&1; rc=$?
  [ $rc -eq 2 ] && [ ! -e "$work/bad.tsv" ]; ok $? "progress $bad: usage error (exit $rc)"
done
"$RADIOSITY" progress --help > "$work/help"
for o in --error-images --snapshot-elements --plot-axis --plot-normalised --exposure-from; do
  grep -q -- "$o" "$work/help"; ok $? "progress --help lists $o"
done
done_testing
