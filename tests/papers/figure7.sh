#!/bin/sh
# figure7.sh -- the numbers behind Figure 7 of Goral et al. 1984 (make
# figures): direct light, then 1, 2, 4 and 8 intermediate reflections,
# then the solution, on the cube at 5x5.  Copyright (C) 2026 The radiosity
# authors.  GPLv3+, see COPYING.
#
# Independent facts checked: the light is white and the grey walls reflect
# every band alike (rho = 0.6), so with direct light alone (7a, --bounces
# 1: B = E + rho F E) their R, G and B are the same number; every further
# reflection adds light (rho F >= 0 entrywise), so the grey walls' mean
# rises with K; and the terms left out after K reflections shrink like
# q^(K+1), q = ||rho F||inf = 0.8 here, most of it on the coloured walls:
# on the grey walls 7e (K = 9) is within 0.5% of 7f.
. "${top_srcdir:-.}/tests/lib.sh"
cube="$top_srcdir/data/goral1984-cube.scene"

# area-weighted mean R G B over the grey walls (surfaces 1, 4 and 5)
grey_mean() {
  awk -F '\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
    $c["surface"] == 1 || $c["surface"] == 4 || $c["surface"] == 5 {
      a = $c["area"]; r += a * $c["r"]; g += a * $c["g"]; b += a * $c["b"]; s += a }
    END { printf "%.17g %.17g %.17g\n", r / s, g / s, b / s }' "$1"
}

prev=0
for k in 1 2 3 5 9; do
  "$RADIOSITY" solve -q --mesh 5x5 --bounces $k --elements "$work/b$k.tsv" "$cube"
  ok $? "--bounces $k: exit 0"
  set -- $(grey_mean "$work/b$k.tsv")
  awk -v r="$1" -v p="$prev" 'BEGIN { exit !(r > p) }'
  ok $? "--bounces $k: the grey walls' mean red rises ($prev -> $1)"
  prev=$1
done
set -- $(grey_mean "$work/b1.tsv")
[ "$1" = "$2" ] && [ "$2" = "$3" ]
ok $? "7a (direct light only): the grey walls' R, G and B are equal ($1 $2 $3)"
awk -F '\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  $c["surface"] == 1 || $c["surface"] == 4 || $c["surface"] == 5 {
    if ($c["r"] != $c["g"] || $c["g"] != $c["b"]) bad = 1 }
  END { exit bad }' "$work/b1.tsv"
ok $? "7a: every grey element has R = G = B"
"$RADIOSITY" solve -q --mesh 5x5 --elements "$work/full.tsv" "$cube"
set -- $(grey_mean "$work/b9.tsv") $(grey_mean "$work/full.tsv")
awk -v a="$1" -v b="$2" -v c="$3" -v x="$4" -v y="$5" -v z="$6" 'BEGIN {
  e = (x - a) / x; f = (y - b) / y; g = (z - c) / z
  printf "# 7e against 7f on the grey walls: %.3g %.3g %.3g\n", e, f, g
  exit !(e >= 0 && f >= 0 && g >= 0 && e < 0.005 && f < 0.005 && g < 0.005) }'
ok $? "7e (--bounces 9) is within 0.5% below 7f on the grey walls' mean, in every band"

done_testing
