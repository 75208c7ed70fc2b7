#!/bin/sh
# matrixfree.sh -- progressive refinement without a stored matrix:
# `solve --solver progressive --matrix none|dense|auto` and `--patches PxQ`.
#   - none takes the steps of dense and gives its B bit for bit (the rows
#     are the dense fill's own values, ffrow.h), with and without
#     visibility, by elements and by surface patches;
#   - converged to 1e-10 it agrees with gauss within 1e-8 relative per
#     element, in the same number of shots as dense (the check at
#     2,400 elements runs with RADIOSITY_LONG_TESTS=1; a 150-element cube
#     here);
#   - auto says what it chose, and chooses none when the dense matrix would
#     not fit in half the memory allowed;
#   - patch grids: none (patch outlines integrated directly) and dense (sums
#     of element columns) agree to the kernel's accuracy;
#   - bad values are usage errors.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
cube="$top_srcdir/data/goral1984-cube.scene"
blocker="$top_srcdir/data/blocker.scene"

# max over elements and bands of |B1 - B2| / |B2| (0 where both are 0);
# "bad" (which close_to refuses) when a file is missing or empty, the row
# counts differ, or a value is not a number (awk would read nan or an empty
# field as 0, and the comparison could not fail)
relerr() {
  [ -s "$1" ] && [ -s "$2" ] && [ "$(wc -l < "$1")" -eq "$(wc -l < "$2")" ] || { echo bad; return; }
  paste "$1" "$2" | awk -F'\t' 'NR==1 { for (k=1;k<=NF/2;k++) c[$k]=k; h=NF/2; next }
    { split("r g b", t, " "); for (i=1;i<=3;i++) { k=c[t[i]]
        if ($k !~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/ || $(k+h) !~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/) bad = 1
        d=$k-$(k+h); if (d<0) d=-d
        s=$(k+h); if (s<0) s=-s; if (s > 0) { d /= s } else if (d > 0) { d = 1e300 }
        if (d>m) m=d } } END { if (bad || NR < 2) print "bad"; else printf "%.3g\n", m }'
}
# the JSON report's value of KEY (a number or a string)
key() { sed -n 's/^ *"'"$2"'": *"\{0,1\}\([^",]*\)"\{0,1\},\{0,1\}$/\1/p' "$1"; }

# ---- none against dense and gauss --------------------------------------------
check_mesh() { # MESH LABEL
  "$RADIOSITY" solve -q --mesh "$1" --elements "$work/g.tsv" "$cube"
  for m in dense none; do
    "$RADIOSITY" solve -q --mesh "$1" --solver progressive --matrix $m --tolerance 1e-10 \
      --elements "$work/$m.tsv" --report "$work/$m.json" "$cube"
    ok $? "$2: --matrix $m converges to 1e-10"
  done
  cmp -s "$work/dense.tsv" "$work/none.tsv"; ok $? "$2: --matrix none gives dense's B bit for bit"
  sd=$(key "$work/dense.json" sweeps) sn=$(key "$work/none.json" sweeps)
  [ -n "$sn" ] && [ "$sn" = "$sd" ]; ok $? "$2: the same number of shots ($sn, dense $sd)"
  e=$(relerr "$work/none.tsv" "$work/g.tsv")
  close_to "$e" 0 1e-8; ok $? "$2: none agrees with gauss within 1e-8 per element ($e)"
  [ "$(key "$work/none.json" matrix)" = none ] && [ "$(key "$work/dense.json" matrix)" = dense ]
  ok $? "$2: the report says which matrix was used"
}
check_mesh 5x5 "cube 5x5 (150 elements)"
if [ "${RADIOSITY_LONG_TESTS:-0}" = 1 ]; then
  check_mesh 20x20 "cube 20x20 (2,400 elements)"
else
  skip "the cube at 20x20 (2,400 elements, minutes): set RADIOSITY_LONG_TESTS=1"
fi

# with visibility: the same pairs and hidden parts as the dense fill
for p in "" --patches; do
  for m in dense none; do
    "$RADIOSITY" solve -q --mesh 2x2 --solver progressive $p --matrix $m \
      --elements "$work/v$m.tsv" "$blocker" 2> "$work/err"
  done
  cmp -s "$work/vdense.tsv" "$work/vnone.tsv"
  ok $? "blocker scene (visibility) ${p:-elements}: none gives dense's B bit for bit"
done

# ---- auto ------------------------------------------------------------------------
"$RADIOSITY" solve --mesh 3x3 --solver progressive --report "$work/a.json" \
  --elements "$work/a.tsv" "$cube" 2> "$work/a.err"
[ "$(key "$work/a.json" matrix)" = dense ] && grep -q 'matrix dense' "$work/a.err"
ok $? "auto on a small mesh: dense, in the report and the summary"
"$RADIOSITY" solve -q --mesh 3x3 --report "$work/g.json" --elements "$work/gg.tsv" "$cube"
[ "$(key "$work/g.json" matrix)" = dense ]; ok $? "gauss: the report says dense"
# 30 x 30: 5400 elements, the dense peak 233 MB (F alone: progressive keeps
# no working matrix, rad_solve_bytes_for); an address space of 400 MB
# leaves it more than half: auto must do without (not under the
# sanitizers: ASan cannot start under ulimit -v)
if [ -n "${RADIOSITY_SANITIZE-}" ]; then
  skip "ulimit -v under the sanitizers"
else
  (ulimit -v 400000 2> /dev/null &&
    "$RADIOSITY" solve --mesh 30x30 --solver progressive --tolerance 0.05 --threads 1 \
      --report "$work/big.json" --elements "$work/big.tsv" "$cube" 2> "$work/big.err")
  rc=$?
  if [ $rc -eq 0 ] || [ -s "$work/big.err" ]; then
    [ $rc -eq 0 ] && [ "$(key "$work/big.json" matrix)" = none ] && grep -q 'matrix none' "$work/big.err"
    ok $? "auto with the dense matrix over half the memory allowed: none"
  else
    skip "ulimit -v is not available here"
  fi
fi

# ---- patch grids -------------------------------------------------------------
for m in dense none; do
  "$RADIOSITY" solve -q --mesh 6x6 --solver progressive --patches 2x3 --matrix $m \
    --tolerance 1e-10 --elements "$work/p$m.tsv" --report "$work/p$m.json" "$cube"
  ok $? "--patches 2x3 --matrix $m"
done
e=$(relerr "$work/pnone.tsv" "$work/pdense.tsv")
close_to "$e" 0 1e-6; ok $? "--patches 2x3: patch outlines (none) and summed element columns (dense) agree within 1e-6 ($e)"
"$RADIOSITY" solve -q --mesh 6x6 --solver progressive --patches=2x3 --matrix none \
  --tolerance 1e-10 --elements "$work/peq.tsv" "$cube"
cmp -s "$work/pnone.tsv" "$work/peq.tsv"; ok $? "--patches=2x3 is --patches 2x3"
# the limit of substructuring is not the element solution, but near it
"$RADIOSITY" solve -q --mesh 6x6 --elements "$work/g6.tsv" "$cube"
e=$(relerr "$work/pnone.tsv" "$work/g6.tsv")
close_to "$e" 0 0.2 && ! close_to "$e" 0 1e-8
ok $? "--patches 2x3 converges to the patch-element solution, near gauss's ($e)"
# one patch per element: substructuring is element shooting
"$RADIOSITY" solve -q --mesh 3x3 --solver progressive --patches 3x3 --matrix none \
  --tolerance 1e-10 --elements "$work/p33.tsv" "$cube"
"$RADIOSITY" solve -q --mesh 3x3 --elements "$work/g3.tsv" "$cube"
e=$(relerr "$work/p33.tsv" "$work/g3.tsv")
close_to "$e" 0 1e-8; ok $? "--patches 3x3 on a 3x3 mesh agrees with gauss within 1e-8 ($e)"

# ---- radiosity progress --matrix ------------------------------------------------
for m in dense none; do
  "$RADIOSITY" progress --matrix $m --mesh 3x3 --steps 60 -o "$work/race_$m.tsv" "$cube" \
    2> "$work/race_$m.err"
  ok $? "progress --matrix $m"
  grep -q "matrix $m" "$work/race_$m.err"; ok $? "progress --matrix $m: the summary says so"
done
# the same steps; only the reference differs (gauss, or shooting to 1e-12)
paste "$work/race_dense.tsv" "$work/race_none.tsv" | awk -F'\t' 'NR > 1 { h = NF / 2
  for (k = 2; k <= h; k++) { d = $k - $(k + h); if (d < 0) d = -d; if (d > m) m = d
    if ($k > s) s = $k } } END { exit !(NR == 62 && m <= 1e-9 * s) }'
ok $? "progress: the race without a matrix is the race with it (to 1e-9 of the largest error)"
"$RADIOSITY" progress --matrix full "$cube" > /dev/null 2>&1; [ $? -eq 2 ]
ok $? "progress --matrix full: exit 2"
"$RADIOSITY" progress --help | grep -q -- "--matrix MODE"; ok $? "progress --help lists --matrix"

# ---- usage -------------------------------------------------------------------
usage() { "$RADIOSITY" solve "$@" "$cube" > /dev/null 2>&1; [ $? -eq 2 ]; }
usage --solver progressive --matrix sparse; ok $? "--matrix sparse: exit 2"
usage --solver progressive --matrix; ok $? "--matrix without a value: exit 2"
usage --solver gauss --matrix none; ok $? "--matrix with gauss: exit 2"
usage --matrix dense; ok $? "--matrix without --solver progressive: exit 2"
usage --solver progressive --matrix none --form-factors "$work/F.mtx"
ok $? "--matrix none --form-factors: exit 2"
usage --solver progressive --patches 0x2; ok $? "--patches 0x2: exit 2"
usage --solver progressive --patches=4; ok $? "--patches=4: exit 2"
"$RADIOSITY" solve --solver progressive --patches 0x2 "$cube" 2>&1 > /dev/null |
  grep -q -- "--patches takes PxQ"
ok $? "--patches 0x2 (two words) gets the --patches message"
usage --solver gauss --patches 2x2; ok $? "--patches 2x2 with gauss: exit 2"
"$RADIOSITY" solve --help > "$work/help"
for o in "--matrix MODE" "--patches\[=PxQ\]"; do
  grep -q -- "$o" "$work/help"; ok $? "solve --help lists $o"
done
done_testing
