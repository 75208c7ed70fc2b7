#!/bin/sh
# early.sh -- what can be found wrong is found before the work: outputs that
# could not be written, a camera that cannot be used, a mesh that does not
# fit in memory, and options the chosen solver would ignore (a usage
# error, exit 2).  "Before" is checked by what is printed: the summary of a
# solve (its "N elements" line) must not appear.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
cube="$top_srcdir/data/goral1984-cube.scene"
furnace="$top_srcdir/data/furnace.scene"
solved() { grep -q 'elements,.*MiB of matrices' "$1"; }

# outputs that cannot be written are refused before the solve
for opt in --elements --form-factors --report -o; do
  "$RADIOSITY" solve --mesh 12x12 $opt "$work/missing/out" "$cube" 2> "$work/err"; rc=$?
  [ $rc -eq 1 ] && grep -q 'missing/out: No such file or directory' "$work/err" && ! solved "$work/err"
  ok $? "solve $opt in a missing directory: exit 1 before solving"
done
"$RADIOSITY" solve --solver progressive --trace "$work/missing/t.tsv" "$cube" 2> "$work/err"
[ $? -eq 1 ] && ! solved "$work/err"; ok $? "solve --trace in a missing directory: exit 1 before solving"
"$RADIOSITY" render --mesh 12x12 -o "$work/missing/x.png" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'missing/x.png' "$work/err" && ! solved "$work/err"
ok $? "render -o in a missing directory: exit 1 before solving"
"$RADIOSITY" render --mesh 12x12 --scanline 3 --profile "$work/missing/p.tsv" -o "$work/x.png" "$cube" 2> "$work/err"
[ $? -eq 1 ] && ! solved "$work/err" && [ ! -e "$work/x.png" ]
ok $? "render --profile in a missing directory: exit 1 before solving, no picture"
"$RADIOSITY" solve --elements "$work" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'Is a directory' "$work/err" && ! solved "$work/err"
ok $? "an output that is a directory: exit 1 before solving"
if [ "$(id -u)" -ne 0 ]; then
  mkdir "$work/ro"; chmod 555 "$work/ro"
  "$RADIOSITY" solve --elements "$work/ro/e.tsv" "$cube" 2> "$work/err"; rc=$?
  [ $rc -eq 1 ] && grep -q 'Permission denied' "$work/err"; ok $? "an unwritable directory: exit 1 before solving"
else
  skip "root may write anywhere"
fi
"$RADIOSITY" sweep --meshes 2 -o "$work/missing/s.tsv" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'missing/s.tsv' "$work/err"; ok $? "sweep -o in a missing directory: exit 1"

# the camera is checked before the solve
"$RADIOSITY" render --mesh 12x12 -o "$work/c.png" "$furnace" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'no camera' "$work/err" && ! solved "$work/err"
ok $? "render of a scene without a camera: exit 1 before solving"
"$RADIOSITY" render --mesh 12x12 -o "$work/c.png" --up 0,0,1 "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && ! solved "$work/err" && [ ! -e "$work/c.png" ]
ok $? "render --up along the view direction: exit 1 before solving"
"$RADIOSITY" render --mesh 12x12 -o "$work/c.png" --eye 0.5,0.5,0.5 --at 0.5,0.5,0.5 "$cube" 2> "$work/err"
[ $? -eq 1 ] && ! solved "$work/err"; ok $? "render --eye equal to --at: exit 1 before solving"

# memory: refused from the scene's mesh specification, before meshing
timeout 20 "$RADIOSITY" solve --mesh 4000x4000 "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q '96000000 elements.* need [0-9]* MiB, but only [0-9]* MiB are available' "$work/err"
ok $? "--mesh 4000x4000: refused with both numbers ($(head -c 200 "$work/err"))"
grep -q 'use a coarser --mesh, or --solver progressive with --matrix none (no stored matrix: [0-9]* MiB)' "$work/err"
ok $? "and offers the way without a stored matrix, with its need"
# the need follows the solver: LU and Cholesky hold F and a working
# matrix, the iterative solvers F alone (8 N^2 bytes each, N = 96e6)
need() { sed -n 's/.* need \([0-9]*\) MiB.*/\1/p' "$1"; }
cp "$work/err" "$work/err_gauss"
timeout 20 "$RADIOSITY" solve --solver jacobi --mesh 4000x4000 "$cube" 2> "$work/err_jacobi"
grep -q '1 x 8 N^2 bytes of matrices for jacobi' "$work/err_jacobi" &&
  grep -q '2 x 8 N^2 bytes of matrices for gauss' "$work/err_gauss" &&
  awk -v g="$(need "$work/err_gauss")" -v j="$(need "$work/err_jacobi")" \
    'BEGIN { r = g / j; exit !(j > 0 && r > 1.999 && r < 2.001) }'
ok $? "the need names the solver: gauss $(need "$work/err_gauss") MiB = 2 x jacobi's $(need "$work/err_jacobi") MiB"
timeout 20 "$RADIOSITY" render --mesh 4000x4000 -o "$work/m.png" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'MiB are available' "$work/err"; ok $? "render --mesh 4000x4000: refused"
timeout 20 "$RADIOSITY" formfactor --mesh 4000x4000 -o "$work/ff.tsv" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'MiB, but only [0-9]* MiB are available' "$work/err" && [ ! -e "$work/ff.tsv" ]
ok $? "formfactor --mesh 4000x4000: refused with both numbers, before meshing"
"$RADIOSITY" formfactor --mesh 12x12 -o "$work/missing/ff.tsv" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'missing/ff.tsv' "$work/err"; ok $? "formfactor -o in a missing directory: exit 1"
# a process limit counts too (ulimit -v: address space, KiB)
if [ -n "${RADIOSITY_SANITIZE-}" ]; then
  # ASan maps terabytes of shadow at start-up: under any ulimit -v or -d
  # the instrumented program cannot start at all (make check-sanitize)
  skip "ulimit -v under AddressSanitizer (checked by make check)"
else
  (ulimit -v 1000000; "$RADIOSITY" solve --mesh 60x60 "$cube" 2> "$work/err"); rc=$?
  [ $rc -eq 1 ] && grep -q 'MiB are available' "$work/err"
  ok $? "ulimit -v 1 GB and 21600 elements (7 GB): refused from the limit"
fi

# options the chosen solver would ignore are usage errors
usage() { "$RADIOSITY" solve "$@" "$cube" > /dev/null 2> "$work/err"; [ $? -eq 2 ]; }
usage --solver gauss --trace "$work/t.tsv"; ok $? "--trace with gauss: exit 2"
usage --solver jacobi --error-bounds; ok $? "--error-bounds with jacobi: exit 2"
usage --tolerance 1e-6; ok $? "--tolerance with gauss (the default): exit 2"
usage --solver gauss --max-iterations 5; ok $? "--max-iterations with gauss: exit 2"
usage --bounces 2 --solver jacobi; ok $? "--bounces with --solver: exit 2"
usage --bounces 2 --tolerance 1e-3; ok $? "--bounces with --tolerance: exit 2"
usage --patches; ok $? "--patches with gauss: exit 2"
grep -q 'progressive' "$work/err"; ok $? "the message names the solver the option is for"
"$RADIOSITY" solve -q --mesh 2x2 --solver jacobi --tolerance 1e-10 "$cube" 2> /dev/null
ok $? "--tolerance with jacobi is still fine"
done_testing
