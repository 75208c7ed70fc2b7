#!/bin/sh
# hemicube.sh -- --form-factors-method hemicube from the command line:
# usage errors, --help, identities the hemicube must keep, and the
# matrix-free shooting from hemicubes.
#   - a closed scene: every pixel of every hemicube shows some element, and
#     the deltas sum to 1 (hcdelta.c), so every row of F sums to 1 to
#     round-off; the furnace (one material, rho = 0.5, E = 1) then has
#     B = E / (1 - rho) = 2 on every element exactly as with the contour
#     (F 1 = 1 makes B = 2 solve (I - rho F) B = E);
#   - shooting without a matrix uses F'_ji = F_ij A_i / A_j (Cohen et al.
#     1988, eq. 6), whose rows sum to s_j = sum_i F_ij A_i / A_j, not 1:
#     with |s_j - 1| <= d, every B lies between E / (1 - rho (1 - d)) and
#     E / (1 - rho (1 + d)) (the maximum principle for B = E + rho F' B),
#     d measured here from the dense F's columns (equal areas: s_j is
#     column j's sum).
# The hemicube's error against the closed forms is tests/unit/hemicube/test_hemicube.c's.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

cube="$top_srcdir/data/grey-cube.scene"
furnace="$top_srcdir/data/furnace.scene"
hc="--form-factors-method hemicube"

# ---- memory: a picture of R = 4096 takes 640 MiB (40 bytes a pixel), its
# delta tables 192 MiB more (12 bytes a pixel of the top face)
if [ -n "${RADIOSITY_SANITIZE-}" ]; then
  skip "ulimit -v under AddressSanitizer (checked by make check)"
else
  (ulimit -v 400000; "$RADIOSITY" formfactor -q $hc --resolution 4096 --mesh 1x1 \
    -o "$work/big.tsv" "$cube" 2> "$work/err"); rc=$?
  [ $rc -eq 1 ] && grep -q 'needs 832 MiB, but only [0-9]* MiB are available' "$work/err" &&
    grep -q -- "--resolution" "$work/err" && [ ! -e "$work/big.tsv" ]
  ok $? "ulimit -v 400 MB and R = 4096: refused from the limit, naming --resolution (exit $rc)"
fi

"$RADIOSITY" solve $hc --resolution 8 --solver progressive --matrix none --mesh 1x1 \
  -o "$work/mf.ply" "$cube" 2> "$work/err"
grep -q "pairs from hemicube rows" "$work/err" && ! grep -q "pair integrals" "$work/err"
ok $? "the matrix-free summary does not call the hemicube's pairs integrals"

# ---- usage errors -------------------------------------------------------------
"$RADIOSITY" solve -q $hc --resolution 8 --mesh 1x1 --report "$work/rep.json" \
  -o "$work/rep.ply" "$cube"
grep -q '"accuracy": null,' "$work/rep.json" && grep -q '"quadrature": null,' "$work/rep.json" &&
  grep -q '"form_factors_method": "hemicube",' "$work/rep.json" &&
  grep -q '"hemicube_resolution": 8,' "$work/rep.json"
ok $? "solve --report with the hemicube: accuracy and quadrature null (it reads neither), the method and R"
"$RADIOSITY" solve -q --mesh 1x1 --report "$work/rep.json" -o "$work/rep.ply" "$cube"
grep -q '"accuracy": "default",' "$work/rep.json" && grep -q '"quadrature": 3,' "$work/rep.json"
ok $? "solve --report with the contour: accuracy and quadrature as used"
# memory_bytes counts the hemicube's picture: 40 bytes a pixel (render.h's
# ~37: rgb 24, depth 8, face 4, edge 1), R x R of them, over the contour's
mem() { sed -n 's/^  "memory_bytes": \([0-9.e+]*\),$/\1/p' "$1"; }
"$RADIOSITY" solve -q $hc --resolution 256 --mesh 1x1 --report "$work/rep256.json" \
  -o "$work/rep.ply" "$cube"
d=$(awk -v a="$(mem "$work/rep256.json")" -v b="$(mem "$work/rep.json")" 'BEGIN { print a - b }')
[ "$d" = 2621440 ]; ok $? "memory_bytes of a hemicube of 256 adds its picture, 40 x 256^2 bytes (+$d)"

for cmd in formfactor solve progress; do
  "$RADIOSITY" $cmd --resolution 32 "$cube" > "$work/out" 2> "$work/err"
  [ $? -eq 2 ] && grep -q "hemicube" "$work/err"
  ok $? "$cmd --resolution without the hemicube: usage error naming the method"
  fails=0
  for bad in 15 0 4098 -2 abc 16x; do
    "$RADIOSITY" $cmd $hc --resolution "$bad" "$cube" > "$work/out" 2> "$work/err"
    [ $? -eq 2 ] && grep -q -- "--resolution" "$work/err" || { diag "$cmd $bad"; fails=1; }
  done
  ok $fails "$cmd --resolution 15, 0, 4098, -2, abc, 16x: usage errors"
  "$RADIOSITY" $cmd $hc --accuracy reference "$cube" > "$work/out" 2> "$work/err"
  [ $? -eq 2 ] && grep -q -- "--resolution" "$work/err"
  ok $? "$cmd: --accuracy with the hemicube is a usage error pointing to --resolution"
  "$RADIOSITY" $cmd $hc --strict "$cube" > "$work/out" 2> "$work/err"
  [ $? -eq 2 ] && grep -q -- "--strict" "$work/err"
  ok $? "$cmd: --strict with the hemicube (which promises no accuracy) is a usage error"
  "$RADIOSITY" $cmd --form-factors-method hemi "$cube" > "$work/out" 2> "$work/err"
  [ $? -eq 2 ] && grep -q "contour or hemicube" "$work/err"
  ok $? "$cmd --form-factors-method hemi: usage error listing the methods"
  "$RADIOSITY" $cmd --help > "$work/help"
  grep -q -- "--form-factors-method" "$work/help" && grep -q -- "--resolution R" "$work/help"
  ok $? "$cmd --help describes --form-factors-method and --resolution"
done
for cmd in animate compare sweep; do
  "$RADIOSITY" $cmd $hc "$cube" "$cube" > "$work/out" 2> "$work/err"
  ok $(($? != 2)) "$cmd does not take the hemicube (usage error)"
done
"$RADIOSITY" solve -q $hc --solver progressive --matrix none --patches 2x2 "$cube" \
  > "$work/out" 2> "$work/err"
ok $(($? != 2)) "--patches PxQ with --matrix none and the hemicube: usage error"
man="$top_srcdir/man/radiosity.1"
grep -q 'form\\-factors\\-method' "$man" && grep -q 'THE HEMICUBE' "$man"
ok $? "radiosity(1) describes the method"

# ---- a closed room: rows sum to 1, the furnace is exact ---------------------------
"$RADIOSITY" formfactor -q --per-surface --mesh 4x4 $hc --resolution 64 -o "$work/s.tsv" "$cube"
ok $? "formfactor --per-surface with the hemicube exits 0"
awk -F'\t' 'function abs(x) { return x < 0 ? -x : x }
  NR > 1 { sum[$1] += $3; n++; if ($1 == $2 && $3 != 0) bad++ }
  END { for (s in sum) if (abs(sum[s] - 1) > 1e-12) bad++; exit !(n == 36 && !bad) }' "$work/s.tsv"
ok $? "the cube's surface rows sum to 1 within 1e-12, no self-factor"
"$RADIOSITY" solve -q $hc --resolution 32 --elements "$work/e.tsv" "$furnace"
ok $? "solve the furnace with the hemicube"
awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { for (b = 0; b < 3; b++) { v = $(c[substr("rgb", b + 1, 1)]) - 2; if (v < 0) v = -v
      if (v > 1e-12) bad++ } n++ }
  END { exit !(n == 96 && !bad) }' "$work/e.tsv"
ok $? "furnace: B = E / (1 - rho) = 2 on all 96 elements within 1e-12"

# ---- matrix-free shooting from hemicubes --------------------------------------------
"$RADIOSITY" formfactor -q $hc --resolution 32 -o "$work/F.tsv" "$furnace"
d=$(awk -F'\t' 'NR > 1 { col[$2] += $3 } END { m = 0
  for (j in col) { x = col[j] - 1; if (x < 0) x = -x; if (x > m) m = x }; printf "%.17g", m }' \
  "$work/F.tsv")
diag "largest |column sum - 1| of the hemicube's F at R = 32: $d"
"$RADIOSITY" solve -q $hc --resolution 32 --solver progressive --matrix none --tolerance 1e-13 \
  --elements "$work/p.tsv" "$furnace"
ok $? "progressive --matrix none with the hemicube converges"
awk -F'\t' -v d="$d" 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { lo = 1 / (1 - 0.5 * (1 - d)); hi = 1 / (1 - 0.5 * (1 + d)); v = $(c["r"])
    if (v < lo * (1 - 1e-12) || v > hi * (1 + 1e-12)) bad++; n++ }
  END { exit !(n == 96 && !bad && d < 0.1) }' "$work/p.tsv"
ok $? "... and every B lies within the bounds that its rows' sums (d = $d) allow"
"$RADIOSITY" progress -q $hc --resolution 16 --steps 20 --matrix none -o "$work/race.tsv" "$furnace"
ok $? "progress --matrix none with the hemicube runs"
# ---- sweep: the resolution as an axis ------------------------------------------------
"$RADIOSITY" sweep -q --meshes 2,4 --accuracies default --resolutions 16,32 -o "$work/sw.tsv" \
  "$furnace"
ok $? "sweep --resolutions 16,32 exits 0"
awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  $c["method"] == "hemicube" { if (!(($c["mesh"] " " $c["resolution"]) in h)) nh++
    h[$c["mesh"] " " $c["resolution"]] = 1
    for (k = 0; k < 2; k++) { v = (k ? $c["row_sum_max"] : $c["row_sum_min"]) - 1
      if (v < 0) v = -v; if (v > 1e-12) bad++ }
    if ($c["accuracy"] != "-" || !($c["rms_error"] + 0 <= 1e-12)) bad++
    if (!($c["ff_error"] + 0 > 0)) bad++ }
  $c["method"] == "contour" { if ($c["resolution"] != "-") bad++; nc++ }
  END { exit !(nh == 4 && nc == 2 && !bad) }' "$work/sw.tsv"
ok $? "sweep: a hemicube row per mesh and resolution, rows of F summing to 1 within 1e-12, the furnace's B exact (rms_error <= 1e-12), ff_error measured"
fails=0
for bad in 15 0 16,abc 8192; do
  "$RADIOSITY" sweep -q --meshes 1 --resolutions "$bad" "$furnace" > "$work/out" 2> "$work/err"
  [ $? -eq 2 ] && grep -q -- "--resolutions" "$work/err" || { diag "$bad"; fails=1; }
done
ok $fails "sweep --resolutions 15, 0, 16,abc, 8192: usage errors"
"$RADIOSITY" sweep -q --meshes 1 --solvers gauss,cholesky,jacobi,gauss-seidel,cg,progressive \
  --resolutions 2,4 --plot "$work/sw.png" -o "$work/sw30.tsv" "$furnace" 2> "$work/err"
[ $? -eq 2 ] && grep -q "at most 24 curves" "$work/err" && [ ! -e "$work/sw30.tsv" ]
ok $? "sweep --plot with 30 curves (the hemicube's would be dropped): usage error"
"$RADIOSITY" sweep --help | grep -q -- "--resolutions LIST"
ok $? "sweep --help describes --resolutions"

# The energy balance: emitted = absorbed + escaped holds to round-off for
# reciprocal factors (A_i F_ij = A_j F_ji, which the contour integral
# keeps), so a balance off by more than 1e-2 says the factors are not.
# The hemicube at 2 x 2 pixels on the 1984 cube (2x2 mesh) is off by 12%
# in its report: the warning names the hemicube; the contour integral on
# the same mesh gives no warning at all.
gcube="$top_srcdir/data/goral1984-cube.scene"
"$RADIOSITY" solve -q --form-factors-method hemicube --resolution 2 --mesh 2x2 \
  --report "$work/hb.json" -o "$work/hb.ply" "$gcube" 2> "$work/err"
rc=$?
b=$(tr -d '\n ' < "$work/hb.json" | sed -n 's/.*"energy_balance_relative":\[\([^],]*\).*/\1/p')
[ $rc -eq 0 ] && awk -v b="$b" 'BEGIN { exit !(b < -0.01 || b > 0.01) }' &&
  grep -q 'warning: energy balance off by .*hemicube samples each element from its centre' "$work/err"
ok $? "hemicube 2 x 2: balance $b in the report, and a warning that names the hemicube"
"$RADIOSITY" solve -q --mesh 2x2 -o "$work/hc.ply" "$gcube" 2> "$work/err"
[ $? -eq 0 ] && [ ! -s "$work/err" ]; ok $? "the contour integral on the same mesh: no warning"
done_testing
