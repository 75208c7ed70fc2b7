#!/bin/sh
# adaptive.sh -- progressive refinement with adaptive subdivision (--adaptive,
# Cohen et al. 1988 sec. 4), on data/blocker.scene.
#
# What each check stands on:
#   - with --max-depth 0 nothing splits and every patch is one element, so
#     the patch-element system is the element system (1988, sec. 3.4): a
#     fresh LU solve (--solver gauss) of the same mesh must agree, to the
#     convergence tolerance (unshot power 1e-12 of the emitted);
#   - with --subdivide-threshold 0 --max-depth 1 every element whose
#     radiosity differs from a neighbour's splits once (all but the lamp,
#     B = E = 1 exactly), so the limit is the patch-element solution of
#     4 x 4 patches over 8 x 8 elements, which `--patches 4x4 --mesh 8x8`
#     computes by another code path (progressive.c's patch grids, each
#     patch's factors integrated on its outline with --matrix none, as
#     here; the dense path sums its elements' factors instead, which agrees
#     only to the kernel's error, about 1e-7 here): that
#     tests the split, the gathering from earlier shots and the unshot
#     bookkeeping of adaptsplit.c;
#   - energy balance (emitted = absorbed + escaped, Goral et al. 1984,
#     sec. 2) to 1e-12 after converging to --tolerance 1e-12;
#   - accuracy against a reference solve on a uniform 32 x 32 mesh per
#     surface (reference accuracy, LU), measured as in tests/adaptive_rms.py
#     (area-weighted RMS of the band-averaged radiosity, C88 eq. 14, on the
#     reference grid, coarse solutions area-averaged onto it);
#   - no cracks: the rendered adaptive solution has background exactly
#     where a uniform mesh's picture has it, and the smoothed radiosity does
#     not jump at T-junctions (hanging vertices carry the value the larger
#     element's bilinear interpolation has there).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found"
  exit 0
fi
scene="$top_srcdir/data/blocker.scene"
py="$top_srcdir/tests/adaptive_rms.py"
ad="--solver progressive --adaptive"

# ---- usage errors (exit 2) ------------------------------------------------
usage() { # usage DESCRIPTION ARGS...: exit 2 with a message naming an option
  what=$1; shift
  "$RADIOSITY" solve -q "$@" "$scene" > "$work/u.out" 2>&1
  [ $? -eq 2 ] && grep -q -- "^radiosity: .*--[a-z]" "$work/u.out"
  ok $? "usage error: $what"
}
usage "--adaptive without --solver progressive" --adaptive
usage "--adaptive with --solver gauss" --solver gauss --adaptive
usage "--subdivide-threshold -1" $ad --subdivide-threshold -1
usage "--subdivide-threshold x" $ad --subdivide-threshold x
usage "--subdivide-threshold nan" $ad --subdivide-threshold nan
usage "--adaptive with the hemicube" $ad --form-factors-method hemicube
usage "--max-depth 9 (0 to 8)" $ad --max-depth 9
usage "--max-depth -1" $ad --max-depth -1
usage "--max-depth without --adaptive" --solver progressive --max-depth 2
usage "--subdivide-test without --adaptive" --solver progressive --subdivide-test error
usage "--subdivide-test area (difference or error)" $ad --subdivide-test area
usage "--adaptive --matrix dense" $ad --matrix dense
usage "--adaptive --patches 2x2" $ad --patches 2x2
usage "--adaptive --form-factors" $ad --form-factors "$work/f.mtx"
usage "--adaptive --bounces 2" --adaptive --bounces 2

# ---- depth 0: the element solution of LU ---------------------------------
"$RADIOSITY" solve -q $ad --max-depth 0 --mesh 4x4 --elements "$work/d0.tsv" "$scene" 2> /dev/null
ok $? "--max-depth 0 solves"
"$RADIOSITY" solve -q --solver gauss --mesh 4x4 --elements "$work/lu.tsv" "$scene" 2> /dev/null
d=$(paste "$work/d0.tsv" "$work/lu.tsv" | awk -F'\t' 'NR > 1 { for (b = 12; b <= 14; b++) {
      d = $b - $(b + 15); if (d < 0) d = -d; if (d > m) m = d } } END { printf "%.3g\n", m + 0 }')
diag "depth 0 against LU: largest |dB| $d"
close_to "$d" 0 1e-10; ok $? "--max-depth 0 = LU on the same mesh within 1e-10 ($d)"
lv=$(awk -F'\t' 'NR == 1 { print $NF } NR > 1 && $NF != 0 { bad++ } END { print bad + 0 }' "$work/d0.tsv" | tr '\n' ' ')
[ "$lv" = "level 0 " ]; ok $? "element table ends with the column level, all 0 at depth 0 ($lv)"
[ "$(head -n 1 "$work/lu.tsv" | awk -F'\t' '{ print $NF }')" = b ]
ok $? "without --adaptive the table has no level column"

# ---- threshold 0, depth 1: the patch-grid solution -----------------------
"$RADIOSITY" solve -q $ad --subdivide-threshold 0 --max-depth 1 --mesh 4x4 \
  --elements "$work/t0.tsv" "$scene" 2> /dev/null
"$RADIOSITY" solve -q --solver progressive --patches 4x4 --mesh 8x8 --matrix none \
  --elements "$work/grid.tsv" "$scene" 2> /dev/null
set -- $(python3 "$py" rms "$work/grid.tsv" "$work/t0.tsv")
diag "threshold 0 depth 1 against --patches 4x4 --mesh 8x8: RMS $1, $2 elements"
close_to "$1" 0 1e-10 && [ "$2" -eq $((16 + 3 * 64)) ]
ok $? "every element but the lamp's splits once and the solution is the patch grid's (RMS $1, $2 = 16 + 3 x 64 elements)"

# ---- energy balance ------------------------------------------------------
"$RADIOSITY" solve -q $ad --tolerance 1e-12 --mesh 4x4 --subdivide-threshold 0.038 \
  --report "$work/a.json" --elements "$work/a.tsv" --output "$work/a.ply" "$scene" 2> /dev/null
ok $? "adaptive solve from 4x4 (threshold 0.038, depth 3) with every output"
bal=$(sed -n 's/.*"energy_balance_relative": *\[\([^]]*\)\].*/\1/p' "$work/a.json" | tr -d ' ')
echo "$bal" | awk -F, '{ for (k = 1; k <= 3; k++) { b = $k + 0; if (b < 0) b = -b
    if (!($k == $k + 0) || b > 1e-12) exit 1 } }'
ok $? "energy balance (emitted - absorbed - escaped)/emitted within 1e-12: ${bal:-missing}"

# ---- accuracy against the 32 x 32 reference -------------------------------
"$RADIOSITY" solve -q --mesh 32x32 --accuracy reference --elements "$work/ref.tsv" "$scene" 2> /dev/null
ok $? "reference: uniform 32x32, reference accuracy, LU"
"$RADIOSITY" solve -q --mesh 16x16 --elements "$work/u16.tsv" "$scene" 2> /dev/null
"$RADIOSITY" solve -q --mesh 4x4 --elements "$work/u4.tsv" "$scene" 2> /dev/null
set -- $(python3 "$py" rms "$work/ref.tsv" "$work/u16.tsv") \
       $(python3 "$py" rms "$work/ref.tsv" "$work/a.tsv") \
       $(python3 "$py" rms "$work/ref.tsv" "$work/u4.tsv")
r16=$1 n16=$2 ra=$3 na=$4 r4=$5
diag "area-weighted RMS against 32x32: uniform 4x4 $r4, uniform 16x16 $r16 ($n16 elements), adaptive $ra ($na elements)"
awk -v a="$ra" -v u="$r16" -v na="$na" -v nu="$n16" 'BEGIN { exit !(a <= u && na < nu) }'
ok $? "adaptive from 4x4: RMS $ra <= 16x16's $r16 with fewer elements ($na < $n16)"
# The error-weighted test (--subdivide-test error, adaptsplit.c) spends its
# elements where a split gains most in this very measure.
"$RADIOSITY" solve -q $ad --tolerance 1e-9 --mesh 4x4 --subdivide-test error \
  --subdivide-threshold 0.0102 --elements "$work/e.tsv" "$scene" 2> /dev/null
ok $? "adaptive solve from 4x4, --subdivide-test error, threshold 0.0102"
set -- $(python3 "$py" rms "$work/ref.tsv" "$work/e.tsv")
re=$1 ne=$2
diag "--subdivide-test error: RMS $re with $ne elements"
# The best any subdivision can do (adaptive_rms.py oracle): the fewest
# leaves of any quadtree from 4x4 down to the reference's cells whose
# exact area averages of the reference reach 16x16's RMS.  No solver's
# element values beat those averages in this measure, so no adaptive
# scheme can reach 16x16's error with fewer elements.
set -- $(python3 "$py" oracle "$work/ref.tsv" "4:$r16" "$scene")
nmin=$1 omin=$2 oshare=$3 onear=$4 osub=$5
diag "the fewest elements any quadtree from 4x4 needs for 16x16's RMS $r16: $nmin (RMS $omin); its share near the shadow boundary $oshare ($onear of $osub)"
awk -v a="$re" -v u="$r16" -v n="$ne" -v m="$nmin" 'BEGIN { exit !(a <= u && n <= 1.5 * m) }'
ok $? "--subdivide-test error: RMS $re <= 16x16's $r16 with $ne elements, within 1.5 times the fewest possible ($nmin)"
awk -v a="$ne" -v b="$na" 'BEGIN { exit !(a < b) }'
ok $? "--subdivide-test error needs fewer elements than difference for 16x16's RMS ($ne < $na)"
# The target is at most a third of 16x16's elements at that error.  On
# this scene the lamp is as large as the receiver, so the penumbra covers
# all of it and the blocker's lower face is lit unevenly too: the gradients
# are spread, and even the best quadtree (above) needs more than a third.
if [ "$ne" -le $((n16 / 3)) ]; then
  ok 0 "adaptive within a third of 16x16's elements ($ne <= $((n16 / 3)))"
else
  tap_n=$((tap_n + 1)); echo "not ok $tap_n - adaptive within a third of 16x16's elements ($ne > $((n16 / 3))) # TODO unreachable on this scene: the best possible quadtree needs $nmin"
fi
set -- $(python3 "$py" shadow "$scene" "$work/e.tsv")
diag "--subdivide-test error: subdivided elements within one parent width of the shadow's critical lines: $2 of $3 ($1; the best quadtree above: $oshare)"
set -- $(python3 "$py" shadow "$scene" "$work/a.tsv")
diag "--subdivide-test difference: subdivided elements within one parent width of the shadow's critical lines: $2 of $3 ($1)"
[ "$3" -gt 0 ]; ok $? "the run subdivides ($3 elements below level 0; $2 near the shadow boundary)"

# ---- a sharp shadow: most splits along it --------------------------------
# data/blocker.scene's lamp is as large as its receiver, so its penumbra is
# everywhere and even the best quadtree puts only about a third of its
# splits near the critical lines.  With a lamp of 0.2 x 0.2 under a
# blocker of 0.3 x 0.3 the receiver has an umbra [0.3, 0.7]^2 and a
# penumbra 0.2 wide around it (critical lines at 0.1, 0.3, 0.7 and 0.9 in
# x and in y, adaptive_rms.py shadow): the light changes there and nowhere
# else, and that is where the splits must go.
cat > "$work/small.scene" << 'EOF'
material light reflect 0 emit 1
material white reflect 0.7
material grey  reflect 0.5
quad light  0.4 0.4 0  0.6 0.4 0  0.6 0.6 0  0.4 0.6 0
quad white  0 0 1  0 1 1  1 1 1  1 0 1
quad grey   0.35 0.35 0.5  0.35 0.65 0.5  0.65 0.65 0.5  0.65 0.35 0.5
quad grey   0.35 0.35 0.5  0.65 0.35 0.5  0.65 0.65 0.5  0.35 0.65 0.5
EOF
"$RADIOSITY" solve -q --mesh 32x32 --accuracy reference --elements "$work/sref.tsv" "$work/small.scene" 2> /dev/null &&
"$RADIOSITY" solve -q --mesh 16x16 --elements "$work/s16.tsv" "$work/small.scene" 2> /dev/null &&
"$RADIOSITY" solve -q $ad --tolerance 1e-9 --mesh 4x4 --subdivide-test error \
  --subdivide-threshold 0.021 --elements "$work/s.tsv" "$work/small.scene" 2> /dev/null
ok $? "small lamp: reference 32x32, uniform 16x16, adaptive from 4x4 (--subdivide-test error, threshold 0.021)"
set -- $(python3 "$py" rms "$work/sref.tsv" "$work/s16.tsv") $(python3 "$py" rms "$work/sref.tsv" "$work/s.tsv")
sr16=$1 sn16=$2 sra=$3 sna=$4
set -- $(python3 "$py" oracle "$work/sref.tsv" "4:$sr16" "$work/small.scene")
snmin=$1 soshare=$3
set -- $(python3 "$py" shadow "$work/small.scene" "$work/s.tsv")
diag "small lamp: 16x16 RMS $sr16; adaptive $sra with $sna elements (the fewest possible $snmin, a third of 16x16 is $((sn16 / 3))); near the shadow boundary: $2 of $3 subdivided ($1; the best quadtree's $soshare)"
awk -v a="$sra" -v u="$sr16" -v n="$sna" -v m="$snmin" 'BEGIN { exit !(a <= u && n <= 1.5 * m) }'
ok $? "small lamp: RMS $sra <= 16x16's $sr16 with $sna elements, within 1.5 times the fewest possible ($snmin)"
awk -v s="$1" 'BEGIN { exit !(s > 0.5) }'
ok $? "small lamp: most subdivided elements lie within one parent width of the shadow boundary ($2 of $3)"

# ---- no cracks -----------------------------------------------------------
set -- $(python3 "$py" seams "$work/a.ply" -)
diag "T-junctions: $2 hanging vertices, largest jump of the smoothed radiosity $1"
[ "$2" -gt 0 ] && close_to "$1" 0 1e-12
ok $? "smoothed radiosity continuous across $2 T-junctions (jump $1)"
for sh in flat smooth; do
  "$RADIOSITY" render -q $ad --tolerance 1e-12 --mesh 4x4 --subdivide-threshold 0.038 \
    --shading $sh -o "$work/a-$sh.png" "$scene" 2> /dev/null
  "$RADIOSITY" render -q --mesh 4x4 --shading $sh -o "$work/u-$sh.png" "$scene" 2> /dev/null
  set -- $(python3 "$py" cracks "$work/a-$sh.png" "$work/u-$sh.png")
  [ "$1" -eq 0 ] && [ "$2" -gt 1000 ]
  ok $? "render $sh: no background pixel inside the silhouette ($1 of $2 background pixels)"
done
"$RADIOSITY" render -q "$work/a.ply" -o "$work/fromply.png" 2> /dev/null
cmp -s "$work/fromply.png" "$work/a-smooth.png"
ok $? "render SOLUTION.ply of the adaptive mesh = render SCENE --adaptive, byte for byte"

# the trace: no reference on a mesh that changes, so every RMS column is
# nan (radiosity(1)), not 0
"$RADIOSITY" solve -q $ad --mesh 2x2 --max-iterations 5 --trace "$work/t.tsv" "$scene" 2> /dev/null
awk -F'\t' 'NR > 1 { for (k = 5; k <= 8; k++) if ($k != "nan") bad++; n++ }
  END { exit !(n == 5 && bad == 0) }' "$work/t.tsv"
ok $? "--trace with --adaptive: rms, rms_ambient, rms_bands, rms_ambient_bands are nan on all 5 rows"

done_testing
