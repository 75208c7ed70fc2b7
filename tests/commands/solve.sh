#!/bin/sh
# solve.sh -- `radiosity solve` through its contract (radiosity(1),
# radiosity-files(5)): the element table by column name, Matrix Market,
# PLY, JSON report, exit statuses, and outputs that are never half-written.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
cube="$top_srcdir/data/goral1984-cube.scene"

"$RADIOSITY" solve -q --mesh 3x3 --elements "$work/e.tsv" --form-factors "$work/f.mtx" \
  --report "$work/r.json" -o "$work/s.ply" "$cube"
ok $? "solve the cube with every output"
# column lookup by name, as a user's script would do it
cols=$(head -n 1 "$work/e.tsv")
for c in element surface cx cy cz area r g b; do
  printf '%s\n' "$cols" | tr '\t' '\n' | grep -qx "$c"; ok $? "element table has column '$c'"
done
[ "$(tail -n +2 "$work/e.tsv" | wc -l)" -eq 54 ]; ok $? "54 element rows"
# the light (surface 0) has B = E = 1 (it reflects nothing)
awk -F'\t' 'NR==1 { for (k=1;k<=NF;k++) c[$k]=k; next }
  $c["surface"]==0 && ($c["r"]!=1 || $c["g"]!=1 || $c["b"]!=1) { bad=1 } END { exit bad }' "$work/e.tsv"
ok $? "the emitter's radiosity is its emission"
# energy balance from the table alone: sum A (B - E) over the grey walls is
# positive and the element areas add up to 6 (to print precision)
a=$(awk -F'\t' 'NR==1 { for (k=1;k<=NF;k++) c[$k]=k; next } { s += $c["area"] } END { printf "%.15g", s }' "$work/e.tsv")
close_to "$a" 6 1e-14; ok $? "element areas add up to 6 ($a)"
head -n 1 "$work/f.mtx" | grep -q '^%%MatrixMarket matrix array real general$'; ok $? "Matrix Market header"
[ "$(grep -v '^%' "$work/f.mtx" | head -n 1)" = "54 54" ]; ok $? "Matrix Market size line"
[ "$(grep -v '^%' "$work/f.mtx" | tail -n +2 | wc -l)" -eq 2916 ]; ok $? "54 x 54 entries"
# column-major: row sums of F (from element i) are 1 in a closed cube
awk 'BEGIN { n = 0 } /^%/ { next } n == 0 { n = $1; k = 0; next }
  { i = k % n; s[i] += $1; k++ } END { for (i = 0; i < n; i++) { d = s[i] - 1; if (d < 0) d = -d; if (d > 1e-7) bad = 1 } exit bad }' "$work/f.mtx"
ok $? "Matrix Market rows (from element i) sum to 1 within 1e-7 (default promises 1e-6 per entry)"
head -n 1 "$work/s.ply" | grep -qx ply; ok $? "PLY magic"
grep -q '^element vertex 96$' "$work/s.ply" && grep -q '^element face 54$' "$work/s.ply"; ok $? "PLY: 96 vertices, 54 faces"
grep -q '^property uchar red$' "$work/s.ply" && grep -q '^property double radiosity_r$' "$work/s.ply"; ok $? "PLY: linear radiosity and sRGB bytes"
# an adaptive mesh mixes faces of 4 to 7 vertices: they come grouped by
# count (meshio keeps one array per kind of cell), and each face's
# `element` names its row of the element table, whose B it carries
"$RADIOSITY" solve -q --solver progressive --adaptive -o "$work/a.ply" --elements "$work/a.tsv" \
  "$top_srcdir/data/goral1984-cube.scene"
awk -F '\t' 'FNR == NR { if (FNR > 1) b[$1] = $12 " " $13 " " $14; n = FNR - 1; next }
  /^end_header/ { body = 1; next }
  !body { if ($0 ~ /^element vertex /) { split($0, h, " "); nv = h[3] } next }
  ++line > nv { split($0, w, " "); k = w[1]; if (k < last) order = 1; last = k
    if (k > 4) mixed = 1
    e = w[k + 7]; if ((e in seen) || !(e in b)) bad = 1; seen[e] = 1; faces++
    if (sprintf("%.17g %.17g %.17g", w[k + 3], w[k + 4], w[k + 5]) != b[e]) bad = 1 }
  END { exit bad || order || !mixed || faces != n }' "$work/a.tsv" "$work/a.ply"
ok $? "adaptive PLY: faces grouped by vertex count, each element once, its B the table's"
grep -q '"status": "ok"' "$work/r.json" && grep -q '"residual"' "$work/r.json" && grep -q '"energy_balance_relative"' "$work/r.json"
ok $? "JSON report with status, residual and energy balance"
if command -v python3 > /dev/null; then
  python3 -c "import json,sys; r=json.load(open(sys.argv[1])); sys.exit(0 if r['elements']==54 and abs(r['row_sum_max']-1)<1e-7 else 1)" "$work/r.json"
  ok $? "the report is valid JSON"
fi

# the report is written last and states the time of the other outputs
"$RADIOSITY" solve -q --mesh 6x6 --form-factors "$work/t.mtx" --report "$work/t.json" "$cube"
out_s=$(sed -n 's/.*"output": *\([^}]*\)}.*/\1/p' "$work/t.json")
awk -v t="${out_s:-x}" 'BEGIN { exit !(t + 0 == t && t > 0 && t < 60) }'
ok $? "the report's output time is that of the matrix written before it ($out_s s)"

# solvers agree through the CLI too (table values, 1e-10)
for s in cholesky jacobi gauss-seidel cg; do
  "$RADIOSITY" solve -q --mesh 3x3 --solver $s --elements "$work/e_$s.tsv" "$cube"
  paste "$work/e.tsv" "$work/e_$s.tsv" | awk -F'\t' 'NR > 1 { for (k = 12; k <= 14; k++) { d = $k - $(k + 14); if (d < 0) d = -d; if (d > 1e-10) bad = 1 } } END { exit bad }'
  ok $? "--solver $s agrees with gauss to 1e-10"
done
"$RADIOSITY" solve -q --mesh 2x2 --bounces 0 --elements "$work/b0.tsv" "$cube"
awk -F'\t' 'NR > 1 && $2 != 0 && ($12 != 0 || $13 != 0 || $14 != 0) { bad = 1 } END { exit bad }' "$work/b0.tsv"
ok $? "--bounces 0: only the emitter is lit"
"$RADIOSITY" solve -q --mesh 2x2 --bounces 3 --report "$work/b3.json" "$cube"
grep -q '"solver": "jacobi"' "$work/b3.json" && grep -q '"bounces": 3,' "$work/b3.json"
ok $? "--bounces 3: the report says jacobi, 3 bounces"

# errors
printf 'material w reflect 1 emit 1\nquad w 0 0 0  1 0 0  1 1 0  0 1 0\nquad w 0 0 1  0 1 1  1 1 1  1 0 1\nquad w 0 0 0  0 1 0  0 1 1  0 0 1\nquad w 1 0 0  1 0 1  1 1 1  1 1 0\nquad w 0 0 0  0 0 1  1 0 1  1 0 0\nquad w 0 1 0  1 1 0  1 1 1  0 1 1\n' > "$work/white.scene"
"$RADIOSITY" solve -q -o "$work/white.ply" "$work/white.scene" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q singular "$work/err" && [ ! -e "$work/white.ply" ]
ok $? "closed box with reflectance 1: exit 1, 'singular', no output"
"$RADIOSITY" solve -q --solver jacobi --max-iterations 2 --elements "$work/nc.tsv" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'did not converge' "$work/err" && [ ! -e "$work/nc.tsv" ]
ok $? "jacobi stopped early: exit 1, says so, writes no table"
"$RADIOSITY" solve --solver lu "$cube" > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "unknown solver: exit 2"
"$RADIOSITY" solve --solver cholesky --tolerance 1e-9 "$cube" > /dev/null 2>&1; [ $? -eq 2 ]
ok $? "--tolerance with cholesky: exit 2"
# the iterative summary states its error bound, and it is met
"$RADIOSITY" solve --mesh 3x3 --solver cg "$cube" 2> "$work/cg.err"
sed -n 's/.*error <= \([^ ]*\) relative.*/\1/p' "$work/cg.err" | awk '{ n++; if (!($1 <= 1e-12)) bad = 1 } END { exit bad || n != 1 }'
ok $? "cg: the summary reports an error bound <= 1e-12"

# the report's iteration_error_bound bounds the true error: stopped at a
# loose tolerance, Jacobi and Gauss-Seidel must be within their reported
# bound of gauss (whose own error is round-off, 1e-15 here)
for s in jacobi gauss-seidel cg; do
  "$RADIOSITY" solve -q --mesh 3x3 --solver $s --tolerance 1e-5 --elements "$work/t_$s.tsv" \
    --report "$work/t_$s.json" "$cube"
  bound=$(sed -n 's/.*"iteration_error_bound": *\([^,]*\),.*/\1/p' "$work/t_$s.json")
  paste "$work/e.tsv" "$work/t_$s.tsv" | awk -F'\t' -v bound="${bound:-x}" 'NR > 1 {
      for (k = 12; k <= 14; k++) { d = $k - $(k + 14); if (d < 0) d = -d; if (d > dm) dm = d
        v = $k < 0 ? -$k : $k; if (v > vm) vm = v } }
    END { e = dm / vm; printf "# %s: true error %.3g, reported bound %s\n", "'$s'", e, bound
      exit !(bound + 0 == bound && bound <= 1e-5 && e <= bound + 1e-14) }'
  ok $? "--solver $s --tolerance 1e-5: the report's iteration_error_bound ($bound) covers the error against gauss"
done
# --vertex-rule: extrapolate is the default; corner changes corner vertices only
"$RADIOSITY" solve -q --mesh 3x3 -o "$work/v0.ply" "$cube"
"$RADIOSITY" solve -q --mesh 3x3 --vertex-rule extrapolate -o "$work/v1.ply" "$cube"
"$RADIOSITY" solve -q --mesh 3x3 --vertex-rule corner -o "$work/v2.ply" "$cube"
cmp -s "$work/v0.ply" "$work/v1.ply" && ! cmp -s "$work/v0.ply" "$work/v2.ply"
ok $? "--vertex-rule extrapolate is the default; corner gives other vertex values"
"$RADIOSITY" solve --vertex-rule nearest "$cube" 2> "$work/err"; [ $? -eq 2 ] &&
  grep -q 'extrapolate or corner' "$work/err"
ok $? "--vertex-rule with an unknown rule: exit 2 naming the rules"
"$RADIOSITY" solve --bounces -1 "$cube" > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "negative bounces: exit 2"
"$RADIOSITY" solve --help | grep -q -- '--bounces'; ok $? "solve --help lists --bounces"

# a run killed while writing never leaves a partial file under the target name
echo precious > "$work/big.mtx"
"$RADIOSITY" solve -q --mesh 12x12 --form-factors "$work/big.mtx" "$cube" &
pid=$!
i=0
while [ $i -lt 200 ] && ! ls "$work" | grep -q 'big.mtx.tmp'; do sleep 0.05; i=$((i + 1)); done
kill -9 $pid 2> /dev/null; wait $pid 2> /dev/null
# SIGKILL cannot be caught: the temporary may stay, but the target is the
# old file or, when the run finished before the kill, the whole new matrix
# (its % comment lines, the size line, 864 x 864 entries): never a partial one
lines=$(wc -l < "$work/big.mtx")
[ "$(cat "$work/big.mtx")" = precious ] ||
  [ "$lines" -eq $(($(grep -c '^%' "$work/big.mtx") + 1 + 864 * 864)) ]
ok $? "killed mid-write: the target is the old file or the whole new one ($lines lines)"
# a scene where nothing emits: said, not a balance of 0 / 0
printf 'material w reflect 0.5\nquad w 0 0 0  1 0 0  1 1 0  0 1 0\nquad w 0 0 1  0 1 1  1 1 1  1 0 1\n' > "$work/dark.scene"
"$RADIOSITY" solve -o "$work/dark.ply" "$work/dark.scene" 2> "$work/err"; rc=$?
[ $rc -eq 0 ] && grep -q 'warning: every radiosity is 0: no surface of the scene emits' "$work/err" &&
  grep -q 'energy balance: nothing is emitted' "$work/err" && ! grep -q 'emitted: 0 0 0' "$work/err"
ok $? "nothing emits: a warning, and no balance of 0 / 0"
printf 'material w reflect 0.5 emit 1 0 0\nquad w 0 0 0  1 0 0  1 1 0  0 1 0\nquad w 0 0 1  0 1 1  1 1 1  1 0 1\n' > "$work/red.scene"
"$RADIOSITY" solve -o "$work/red.ply" "$work/red.scene" 2> "$work/err"
grep -q 'emitted: [-0-9.e]* - -$' "$work/err" && ! grep -q 'every radiosity is 0' "$work/err"
ok $? "a band that emits nothing has no ratio: '-'"
# --mesh cuts triangles too: each into 4 x 4 = 16 similar triangles, with
# nothing to warn about
cat > "$work/tri.scene" <<'END'
material lamp reflect 0 emit 1
material white reflect 0.5
polygon lamp 3  0 1 0  1 1 0  0 1 1
polygon white 3  0 0 0  0 0 1  1 0 0
END
"$RADIOSITY" solve -q --mesh 4x4 --elements "$work/tri.tsv" -o "$work/tri.ply" "$work/tri.scene" 2> "$work/err"
[ $? -eq 0 ] && [ ! -s "$work/err" ] && [ "$(awk 'NR > 1' "$work/tri.tsv" | wc -l)" -eq 32 ] &&
  awk -F '\t' 'NR > 1 { a[$2] += $11 } END { exit !(a[0] > 0.5 - 1e-15 && a[0] < 0.5 + 1e-15 && a[1] > 0.5 - 1e-15 && a[1] < 0.5 + 1e-15) }' "$work/tri.tsv"
ok $? "--mesh 4x4 on triangles: 16 triangles each, their areas summing to each triangle's 1/2 ($(head -c 200 "$work/err"))"
"$RADIOSITY" solve -q --mesh 2x2 -o "$work/m22.ply" "$top_srcdir/data/goral1984-cube.scene" 2> "$work/err"
[ $? -eq 0 ] && ! grep -q 'applies to quadrilaterals' "$work/err"
ok $? "--mesh on quadrilaterals: no such warning"
done_testing
