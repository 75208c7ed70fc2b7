#!/bin/sh
# compare.sh -- `radiosity compare`: another solver's form factors against
# ours.  Every expected value here comes from an identity or from the
# perturbation the test itself makes, never from the program's own output.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
# The unit cube with a different mesh on each wall (as npy.sh): 18
# elements of unequal areas, so F is not symmetric and a transposed matrix
# would show.  Elements: wall 0 -> 0; wall 1 -> 1-2; wall 2 (x = 0, four
# elements of area 1/4) -> 3-6; wall 3 (x = 1, three of area 1/3) -> 7-9;
# wall 4 -> 10-11; wall 5 -> 12-17.
cube="$work/cube.scene"
cat > "$cube" <<'END'
material w reflect 0.5
quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 1x1
quad w 0 0 1  0 1 1  1 1 1  1 0 1  mesh 2x1
quad w 0 0 0  0 1 0  0 1 1  0 0 1  mesh 2x2
quad w 1 0 0  1 0 1  1 1 1  1 1 0  mesh 3x1
quad w 0 0 0  0 0 1  1 0 1  1 0 0  mesh 1x2
quad w 0 1 0  1 1 0  1 1 1  0 1 1  mesh 2x3
END
n=18
cmp_() { "$RADIOSITY" compare "$@" > "$work/out" 2> "$work/err"; }
json() { # json KEY FILE: a top-level number of the JSON report
  sed -n "s/^  \"$1\": \\([^,]*\\),\\{0,1\\}\$/\\1/p" "$2"
}
largest() { sed -n 's/^largest error: *[^ ]* at i = \([0-9]*\), j = \([0-9]*\)$/\1 \2/p' "$work/out"; }

"$RADIOSITY" formfactor -q --accuracy reference -o "$work/F.npy" "$cube" &&
  "$RADIOSITY" formfactor -q --accuracy reference -o "$work/F.tsv" "$cube" &&
  "$RADIOSITY" solve -q --accuracy reference --form-factors "$work/F.mtx" \
    --elements "$work/E.tsv" "$cube"
ok $? "reference matrices as .npy, TSV and Matrix Market"

# ---- the exact matrix: nothing beyond reference's own estimate ------------
# Reference mode promises 1e-9 relative error per entry; the files carry
# the doubles exactly (%.17g, float64), so our fill and theirs agree to
# that promise at worst, and no difference exceeds our own error estimate.
for f in F.npy F.tsv F.mtx; do
  cmp_ --tolerance 1e-9 --report "$work/r.json" "$cube" "$work/$f"
  ok $? "$f: the exact matrix is within 1e-9"
  [ "$(json entries_beyond_estimate "$work/r.json")" = 0 ]
  ok $? "$f: no entry differs by more than our own error estimate"
  ! grep -q "bound" "$work/out"
  ok $? "$f: our error estimates are not called bounds (radi_ff_pair estimates)"
done
# The coordinate form of Matrix Market, 1-based, zeros left out.
{ echo '%%MatrixMarket matrix coordinate real general'
  awk -F'\t' 'NR > 1 && $3 != 0 { k++ } END { print 18, 18, k }' "$work/F.tsv"
  awk -F'\t' 'NR > 1 && $3 != 0 { print $1 + 1, $2 + 1, $3 }' "$work/F.tsv"
} > "$work/C.mtx"
cmp_ --tolerance 1e-9 "$cube" "$work/C.mtx"; ok $? "Matrix Market coordinate: within 1e-9"
grep -q 'Matrix Market coordinate' "$work/out"; ok $? "the coordinate format is named"

# ---- closure: the cube is closed, every row of F sums to 1 --------------
# With each entry within 1e-9 relative, a row sum is within 1e-9 of 1
# (sum_j 1e-9 F_ij = 1e-9), plus round-off.
cmp_ --report "$work/r.json" "$cube" "$work/F.npy"
c=$(json closure_ours "$work/r.json")
awk -v c="$c" 'BEGIN { exit !(c + 0 < 2e-9) }'; ok $? "closure of ours below 2e-9 ($c)"

# ---- float32 .npy, as GPU solvers write it ------------------------------
# Each entry rounded to the nearest float32 by the test itself (python3's
# struct, no NumPy), row-major: the largest error compare reports is the
# largest rounding, |f32(F) - F| / max(F, 1e-6), computed here the same
# way from the exact table, give or take reference's 1e-9 between fills.
if command -v python3 > /dev/null 2>&1; then
  python3 - "$work/F.tsv" "$work/F32.npy" "$n" > "$work/f32.max" <<'PY'
import struct, sys
n = int(sys.argv[3])
F = [[0.0] * n for _ in range(n)]
for line in open(sys.argv[1]).read().splitlines()[1:]:
    i, j, f = line.split("\t")[:3]
    F[int(i)][int(j)] = float(f)
h = "{'descr': '<f4', 'fortran_order': False, 'shape': (%d, %d), }" % (n, n)
h += " " * (63 - (10 + len(h)) % 64) + "\n"
with open(sys.argv[2], "wb") as out:
    out.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(h)) + h.encode())
    worst = 0.0
    for i in range(n):
        for j in range(n):
            r = struct.unpack("<f", struct.pack("<f", F[i][j]))[0]
            worst = max(worst, abs(r - F[i][j]) / max(abs(F[i][j]), 1e-6))
            out.write(struct.pack("<f", F[i][j]))
print("%.17g" % worst)
PY
  cmp_ --report "$work/f32.json" "$cube" "$work/F32.npy"
  ok $? "a float32 .npy is read"
  grep -q 'float32' "$work/out" && grep -q '"format": "NumPy .npy float32' "$work/f32.json"
  ok $? "the report names its precision: $(grep -o 'NumPy .npy float32[^"]*' "$work/f32.json" | head -n 1)"
  e=$(json max_error "$work/f32.json"); w=$(cat "$work/f32.max")
  awk -v e="$e" -v w="$w" 'BEGIN { d = e - w; if (d < 0) d = -d; exit !(w > 0 && d <= 2e-9) }'
  ok $? "its largest error is the float32 rounding ($e against $w)"
else
  skip "python3 not found: no float32 .npy written"
fi

# ---- one entry perturbed by a relative 1e-6 ------------------------------
# F_38 (wall x = 0 to the opposite wall x = 1, far above the 1e-6 floor)
# times 1 + 1e-6: its error is 1e-6, every other entry's 0.
awk -F'\t' -v OFS='\t' 'NR > 1 && $1 == 3 && $2 == 8 { $3 = sprintf("%.17g", $3 * (1 + 1e-6)) } { print }' \
  "$work/F.tsv" > "$work/P.tsv"
cmp -s "$work/F.tsv" "$work/P.tsv"; [ $? -eq 1 ]; ok $? "the perturbed table differs"
cmp_ --tolerance 1e-7 --report "$work/p.json" "$cube" "$work/P.tsv"
ok $(($? != 1)) "perturbed by 1e-6: exit 1 with --tolerance 1e-7"
[ "$(largest)" = "3 8" ]; ok $? "the worst pair is named: i = 3, j = 8 ($(largest))"
e=$(json max_error "$work/p.json")
close_to "$e" 1e-6 1e-6; ok $? "its error is 1e-6 ($e)"
grep -q 'OUTSIDE the tolerance' "$work/out"; ok $? "the verdict says outside"
cmp_ --tolerance 1e-5 "$cube" "$work/P.tsv"; ok $? "perturbed by 1e-6: exit 0 with --tolerance 1e-5"
[ "$(json entries_beyond_estimate "$work/p.json")" = 1 ]; ok $? "one entry beyond our own estimate"
# the histogram: 323 entries with e = 0, one in bins 47 or 48 (counts[k]
# is awk field k + 3), 1e-6.25 to 1e-5.75
sed -n 's/.*"zero": \([0-9]*\), "over": \([0-9]*\), "counts": \[\(.*\)\]},$/\1 \2 \3/p' "$work/p.json" |
  tr -d ',' | awk '{ s = 0; for (k = 3; k <= NF; k++) s += $k
    exit !($1 == 323 && $2 == 0 && s == 1 && $50 + $51 == 1) }'
ok $? "histogram: 323 entries exact, one near 1e-6"
# the same perturbation in Matrix Market: entry (i, j) is value i + j n of
# the column-major list, after the banner, a comment and the size line
awk -v k=$((3 + 8 * n + 4)) 'NR == k { printf "%.17g\n", $1 * (1 + 1e-6); next } { print }' \
  "$work/F.mtx" > "$work/P.mtx"
cmp_ --tolerance 1e-7 "$cube" "$work/P.mtx"; ok $(($? != 1)) "Matrix Market perturbed: exit 1"
[ "$(largest)" = "3 8" ]; ok $? "Matrix Market: the worst pair is i = 3, j = 8"

# ---- reciprocity: a defect made by hand ----------------------------------
# Ours is reciprocal (each pair computed once, the other entry by
# A_i F_ij = A_j F_ji), so scaling F_38 by 1 + d leaves the defect
# |A_3 F_38 (1 + d) - A_8 F_83| = A_3 F_38 d, relative to the larger term
# d / (1 + d); A_3 = 1/4 (wall x = 0 in 2 x 2).  Row 3 then sums to
# 1 + F_38 d: the closure error of theirs and the row sums' difference.
d=1e-3
f38=$(awk -F'\t' 'NR > 1 && $1 == 3 && $2 == 8 { print $3 }' "$work/F.tsv")
awk -F'\t' -v OFS='\t' -v d=$d 'NR > 1 && $1 == 3 && $2 == 8 { $3 = sprintf("%.17g", $3 * (1 + d)) } { print }' \
  "$work/F.tsv" > "$work/D.tsv"
cmp_ --report "$work/d.json" "$cube" "$work/D.tsv"; ok $? "defective matrix: exit 0 without --tolerance"
r=$(json reciprocity_rel "$work/d.json")
close_to "$r" "$(awk -v d=$d 'BEGIN { printf "%.17g", d / (1 + d) }')" 1e-6
ok $? "relative reciprocity defect d/(1+d) ($r)"
a=$(json reciprocity_abs "$work/d.json")
close_to "$a" "$(awk -v f="$f38" -v d=$d 'BEGIN { printf "%.17g", 0.25 * f * d }')" 1e-6
ok $? "absolute reciprocity defect A_3 F_38 d ($a)"
grep -q '"reciprocity_rel_pair": \[3, 8\]' "$work/d.json"; ok $? "the defective pair is (3, 8)"
t=$(json closure_theirs "$work/d.json")
close_to "$t" "$(awk -v f="$f38" -v d=$d 'BEGIN { printf "%.17g", f * d }')" 1e-3
ok $? "closure of theirs: F_38 d ($t)"
[ "$(json closure_theirs_row "$work/d.json")" = 3 ]; ok $? "in row 3"
r=$(json reciprocity_rel "$work/r.json")
awk -v r="$r" 'BEGIN { exit !(r + 0 < 1e-14) }'; ok $? "the exact matrix is reciprocal ($r)"

# ---- another element order, matched by centroid --------------------------
# Their element k is our element p(k) = (5k + 3) mod 18 (5 is prime to 18),
# so our element i is their q(i) = 11 (i - 3) mod 18 (5 * 11 = 1 mod 18).
# Their matrix is ours renumbered, their table our centroids renumbered.
q='function q(i) { return ((11 * (i - 3)) % 18 + 18) % 18 }'
awk -F'\t' -v OFS='\t' "$q"' NR == 1 { print; next } { print q($1), q($2), $3, $4 }' \
  "$work/F.tsv" > "$work/Q.tsv"
awk -F'\t' -v OFS='\t' "$q"' NR == 1 { for (c = 1; c <= NF; c++) h[$c] = c; print "cz", "element", "cx", "cy"; next }
  { print $h["cz"], q($h["element"]), $h["cx"], $h["cy"] }' "$work/E.tsv" > "$work/QE.tsv"
cmp_ --tolerance 1e-5 "$cube" "$work/Q.tsv"
ok $(($? != 1)) "renumbered, matched by order: outside 1e-5"
cmp_ --tolerance 1e-9 --report "$work/q.json" --elements "$work/QE.tsv" "$cube" "$work/Q.tsv"
ok $? "renumbered, matched by centroid: within 1e-9"
[ "$(json entries_beyond_estimate "$work/q.json")" = 0 ]; ok $? "matched: nothing beyond our estimate"
# a centroid moved by 0.01 matches no element
awk -F'\t' -v OFS='\t' 'NR == 5 { $3 += 0.01 } { print }' "$work/QE.tsv" > "$work/bad-e.tsv"
cmp_ --elements "$work/bad-e.tsv" "$cube" "$work/Q.tsv"; rc=$?
[ $rc -eq 1 ] && grep -q "bad-e.tsv:5:.*no element" "$work/err"
ok $? "an unmatched centroid: exit 1 naming the table's line ($(cat "$work/err"))"

# ---- View3D's view-factor files ---------------------------------------------
# Text (format 0): header, areas, rows with six decimals, emissivities.
# With --floor 1 the error is the absolute difference (F <= 1), and %.6f
# rounds by at most 5e-7.
awk -F'\t' 'NR > 1 { F[$1, $2] = $3 } END {
  printf "%-30s\n", "View3D 3.2 0 1 0 18"
  for (i = 0; i < 18; i++) printf "%s%g", i ? " " : "", 1; print ""
  for (i = 0; i < 18; i++) { for (j = 0; j < 18; j++) printf "%s%.6f", j ? " " : "", F[i, j] + 0; print "" }
  for (i = 0; i < 18; i++) printf "%s%.3f", i ? " " : "", 0.9; print "" }' "$work/F.tsv" > "$work/v.txt"
cmp_ --floor 1 --tolerance 5.0000001e-7 "$cube" "$work/v.txt"; ok $? "View3D text: within 5e-7 absolute"
grep -q '(View3D text)' "$work/out"; ok $? "View3D text is recognised"
cmp_ --floor 1 --tolerance 1e-9 "$cube" "$work/v.txt"; ok $(($? != 1)) "View3D text: not within 1e-9"

if command -v python3 > /dev/null 2>&1; then
  # Binary (format 1): a 32-byte header ended by CR LF, float32 areas,
  # rows and emissivities.  float32 rounds by 2^-24 relative: e <= 6e-8.
  python3 - "$work/F.tsv" "$work/v.bin" <<'PY'
import struct, sys
F = {}
for line in open(sys.argv[1]).read().splitlines()[1:]:
    i, j, f = line.split("\t")[:3]
    F[int(i), int(j)] = float(f)
n = 18
with open(sys.argv[2], "wb") as out:
    out.write(("View3D 3.2 1 1 0 %d" % n).ljust(30).encode() + b"\r\n")
    out.write(struct.pack("<%df" % n, *([1.0] * n)))
    for i in range(n):
        out.write(struct.pack("<%df" % n, *[F.get((i, j), 0.0) for j in range(n)]))
    out.write(struct.pack("<%df" % n, *([0.9] * n)))
PY
  cmp_ --tolerance 6e-8 "$cube" "$work/v.bin"; ok $? "View3D binary: within float32 rounding"
  grep -q '(View3D binary)' "$work/out"; ok $? "View3D binary is recognised"
  cmp_ --tolerance 1e-12 "$cube" "$work/v.bin"; ok $(($? != 1)) "View3D binary: float32 shows"

  # .npy: the perturbation in C order, and arrays that are not n x n float64
  python3 - "$work" <<'PY'
import struct, sys
w = sys.argv[1]
raw = open(w + "/F.npy", "rb").read()
(hlen,) = struct.unpack("<H", raw[8:10])
data = 10 + hlen
n = 18
vals = list(struct.unpack("<%dd" % (n * n), raw[data:]))   # Fortran order
C = [vals[i + j * n] for i in range(n) for j in range(n)]  # row-major
C[3 * n + 8] *= 1 + 1e-6
def npy(path, descr, order, shape, payload):
    h = "{'descr': '%s', 'fortran_order': %s, 'shape': %s, }" % (descr, order, shape)
    h = h.ljust(64 * ((10 + len(h) + 1 + 63) // 64) - 10 - 1) + "\n"
    with open(path, "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(h)) + h.encode() + payload)
npy(w + "/P.npy", "<f8", "False", "(18, 18)", struct.pack("<%dd" % (n * n), *C))
npy(w + "/rect.npy", "<f8", "False", "(3, 4)", struct.pack("<12d", *([0.0] * 12)))
npy(w + "/be4.npy", ">f4", "False", "(18, 18)", struct.pack(">%df" % (n * n), *C))
npy(w + "/cube.npy", "<f8", "False", "(18, 18, 1)", struct.pack("<%dd" % (n * n), *C))
npy(w + "/short.npy", "<f8", "False", "(18, 18)", struct.pack("<%dd" % (n * n - 1), *C[1:]))
N = list(C); N[5] = float("nan")
npy(w + "/nan.npy", "<f8", "False", "(18, 18)", struct.pack("<%dd" % (n * n), *N))
N = list(C); N[7] = float("inf")
npy(w + "/inf.npy", "<f8", "False", "(18, 18)", struct.pack("<%dd" % (n * n), *N))
open(w + "/stub.npy", "wb").write(b"\x93NUMPY")
PY
  cmp_ --tolerance 1e-7 "$cube" "$work/P.npy"; ok $(($? != 1)) "C-order .npy perturbed: exit 1"
  [ "$(largest)" = "3 8" ]; ok $? "C-order .npy: the worst pair is i = 3, j = 8 ($(largest))"
  cmp_ --tolerance 1e-5 "$cube" "$work/P.npy"; ok $? "C-order .npy perturbed: exit 0 with 1e-5"
  for bad in rect be4 cube short nan inf stub; do
    cmp_ "$cube" "$work/$bad.npy"; rc=$?
    [ $rc -eq 1 ] && grep -q "$bad.npy" "$work/err"
    ok $? "$bad.npy refused with the file named ($(cat "$work/err"))"
  done
  grep -q "ends in its preamble" "$work/err"; ok $? "a .npy cut in its preamble is called so"
  grep -q "not square" "$work/err" || cmp_ "$cube" "$work/rect.npy"
  grep -q "not square" "$work/err"; ok $? "a 3 x 4 array is called not square"
else
  for k in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15; do skip "python3 not found"; done
fi

# ---- refused inputs ------------------------------------------------------------
# the matrix of the 6-element cube against the 18-element scene
"$RADIOSITY" formfactor -q --mesh 1x1 -o "$work/six.npy" "$cube"
"$RADIOSITY" formfactor -q --mesh 1x1 -o "$work/six.tsv" "$cube"
for f in six.npy six.tsv; do
  cmp_ "$cube" "$work/$f"; rc=$?
  [ $rc -eq 1 ] && grep -q "$f.*18 elements" "$work/err"
  ok $? "$f: a size mismatch is refused naming the file ($(cat "$work/err"))"
done
awk -F'\t' 'NR > 1 && $3 != 0 { k++ } END { print "%%MatrixMarket matrix array real general"; print 6, 6 }' \
  "$work/F.tsv" > "$work/six.mtx"
cmp_ "$cube" "$work/six.mtx"; rc=$?
[ $rc -eq 1 ] && grep -q "six.mtx:2:" "$work/err"; ok $? "six.mtx: refused at its size line"
printf 'hello, world\n' > "$work/garbage.txt"
cmp_ "$cube" "$work/garbage.txt"; rc=$?
[ $rc -eq 1 ] && grep -q "garbage.txt:1: not a form-factor matrix" "$work/err"
ok $? "a garbage file is refused at its line 1"
head -c 4000 "$RADIOSITY" > "$work/garbage.bin"
cmp_ "$cube" "$work/garbage.bin"; rc=$?
[ $rc -eq 1 ] && grep -q "garbage.bin" "$work/err"; ok $? "binary garbage is refused naming the file"
{ head -n 3 "$work/F.tsv"; sed -n 3p "$work/F.tsv"; } > "$work/dup.tsv"
cmp_ "$cube" "$work/dup.tsv"; rc=$?
[ $rc -eq 1 ] && grep -q "dup.tsv:4: entry .* given twice" "$work/err"; ok $? "a repeated entry: FILE:LINE"
awk 'NR == 10 { $1 = "x" } { print }' "$work/F.mtx" > "$work/nan.mtx"
cmp_ "$cube" "$work/nan.mtx"; rc=$?
[ $rc -eq 1 ] && grep -q "nan.mtx:10:" "$work/err"; ok $? "a value that is not a number: FILE:LINE"
head -n 100 "$work/F.mtx" > "$work/cut.mtx"
cmp_ "$cube" "$work/cut.mtx"; rc=$?
[ $rc -eq 1 ] && grep -q "cut.mtx:.*ends after" "$work/err"; ok $? "a cut file: refused"
printf '%-30s\n1 2 0.5\n' "View3D 3.2 2 1 0 18" > "$work/sparse.txt"
cmp_ "$cube" "$work/sparse.txt"; rc=$?
[ $rc -eq 1 ] && grep -q "sparse.txt:1: View3D format 2" "$work/err"; ok $? "View3D's sparse format 2: refused by name"
sed '1s/general/symmetric/' "$work/F.mtx" > "$work/sym.mtx"
cmp_ "$cube" "$work/sym.mtx"; rc=$?
[ $rc -eq 1 ] && grep -q "sym.mtx:1: .*symmetric" "$work/err"; ok $? "symmetric Matrix Market: refused"
cmp_ "$cube" "$work/absent.npy"; rc=$?
[ $rc -eq 1 ] && grep -q "absent.npy" "$work/err"; ok $? "a missing file: exit 1 naming it"

# ---- usage, outputs ------------------------------------------------------------
cmp_ "$cube"; ok $(($? != 2)) "no MATRIX: usage error (2)"
cmp_ --tolerance x "$cube" "$work/F.npy"; ok $(($? != 2)) "--tolerance x: usage error (2)"
cmp_ --worst -1 "$cube" "$work/F.npy"; ok $(($? != 2)) "--worst -1: usage error (2)"
"$RADIOSITY" compare -h > "$work/out"; ok $? "-h exits 0"
grep -q '^Usage: radiosity compare' "$work/out"; ok $? "-h prints the usage"
cmp_ -q --plot "$work/h.png" --report "$work/h.json" "$cube" "$work/P.tsv"; ok $? "--plot and --report"
[ ! -s "$work/out" ]; ok $? "-q prints nothing"
head -c 8 "$work/h.png" | od -An -c | grep -q 'P   N   G'; ok $? "--plot writes a PNG"
grep -q '"worst_pairs"' "$work/h.json"; ok $? "--report writes the JSON report"
# View3D's six decimals make most entries differ: N of them are listed
cmp_ --worst 3 "$cube" "$work/v.txt"
[ "$(sed -n '/^worst pairs/,/^$/p' "$work/out" | grep -c '^ *[0-9]')" -eq 3 ]; ok $? "--worst 3 lists 3 pairs"
cmp_ "$cube" "$work/F.npy"
! grep -q '^worst pairs' "$work/out"; ok $? "the exact matrix has no worst pairs (e = 0 is not listed)"
done_testing
