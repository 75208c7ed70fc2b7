#!/bin/sh
# trimesh.sh -- a room of triangles, as a modelling tool exports it, meshed
# by --mesh and --max-element-size: closed (rows of F sum to 1) and
# converging to the radiosity of the same room written as quadrilaterals.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# The quads' own convergence is the yardstick: their floor's mean B at
# element sides h = 1/8 and 1/16 gives Richardson's estimate of the limit,
# B* = q(h/2) + (q(h/2) - q(h)) / 3 (the error is O(h^2): Goral et al.'s
# constant elements, smoothed nothing), and (4/3) |q(h) - q(h/2)| the
# quads' own error at h.  The triangles at the same largest side must come
# within that of B*, and their error must fall about 4 times when h halves
# (at least 3): the same limit, at the same order.
. "${top_srcdir:-.}/tests/lib.sh"
cat > "$work/quads.scene" <<'END'
material w reflect 0.5
material l reflect 0.2 emit 1
quad w 0 0 0  1 0 0  1 1 0  0 1 0
quad l 0 0 1  0 1 1  1 1 1  1 0 1
quad w 0 0 0  0 1 0  0 1 1  0 0 1
quad w 1 0 0  1 0 1  1 1 1  1 1 0
quad w 0 0 0  0 0 1  1 0 1  1 0 0
quad w 0 1 0  1 1 0  1 1 1  0 1 1
END
# each quad as two triangles (v1 v2 v3, v1 v3 v4), as exporters write them
awk '$1 == "quad" { printf "polygon %s 3  %s %s %s  %s %s %s  %s %s %s\n", $2, $3, $4, $5, $6, $7, $8, $9, $10, $11
                    printf "polygon %s 3  %s %s %s  %s %s %s  %s %s %s\n", $2, $3, $4, $5, $9, $10, $11, $12, $13, $14; next }
     { print }' "$work/quads.scene" > "$work/tris.scene"
# the floor's (z = 0) area-weighted mean B, red band
floor_b() { # floor_b SCENE OPTIONS...
  s=$1; shift
  "$RADIOSITY" solve -q "$@" --elements - "$s" 2> "$work/err" |
    awk -F '\t' 'NR > 1 && $7 == 0 { b += $11 * $12; a += $11 } END { if (a > 0) printf "%.15g\n", b / a }'
}
"$RADIOSITY" formfactor -q --accuracy reference --mesh 2x2 "$work/tris.scene" > "$work/ff.tsv"
ok $? "formfactor --mesh 2x2 on 12 triangles runs"
awk -F '\t' 'NR > 1 { s[$1] += $3 } END { n = 0; w = 0; for (i in s) { n++; d = s[i] - 1; if (d < 0) d = -d; if (d > w) w = d }
  printf "%d %.3g\n", n, w; exit !(n == 48 && w <= 48e-9) }' "$work/ff.tsv" > "$work/rows"
ok $? "48 triangles, every row of F sums to 1 within 48 x 1e-9 (elements, worst: $(cat "$work/rows"))"
q1=$(floor_b "$work/quads.scene" --max-element-size 0.125)
q2=$(floor_b "$work/quads.scene" --max-element-size 0.0625)
q0=$(floor_b "$work/quads.scene" --max-element-size 0.25)
t0=$(floor_b "$work/tris.scene" --max-element-size 0.25)
t1=$(floor_b "$work/tris.scene" --max-element-size 0.125)
diag "floor B: quads $q0 $q1 $q2 (h = 1/4, 1/8, 1/16); triangles $t0 $t1 (h = 1/4, 1/8)"
awk -v q0="$q0" -v q1="$q1" -v q2="$q2" -v t0="$t0" -v t1="$t1" 'function abs(x) { return x < 0 ? -x : x }
  BEGIN { if (q0 == "" || t1 == "") exit 1
    lim = q2 + (q2 - q1) / 3
    e0 = abs(t0 - lim); e1 = abs(t1 - lim)
    printf "B* %.9g; triangles off by %.3g, %.3g; the quads own error %.3g, %.3g\n", lim, e0, e1,
      4 / 3 * abs(q0 - q1), 4 / 3 * abs(q1 - q2) > "/dev/stderr"
    exit !(e0 <= 4 / 3 * abs(q0 - q1) && e1 <= 4 / 3 * abs(q1 - q2) && e0 >= 3 * e1) }' 2> "$work/why"
ok $? "triangles converge to the quads' limit within the quads' own error, at second order: $(cat "$work/why")"
# --crease: accepted from 0 to 180 degrees
"$RADIOSITY" solve -q --crease 30 --max-element-size 0.5 -o "$work/c.ply" "$work/tris.scene" 2> "$work/err"
ok $? "solve --crease 30 runs on the room of triangles $(head -c 120 "$work/err")"
"$RADIOSITY" solve -q --crease 200 -o "$work/c.ply" "$work/tris.scene" 2> "$work/err"
[ $? -eq 2 ] && grep -q 'from 0 to 180 degrees' "$work/err"
ok $? "--crease 200: a usage error"
"$RADIOSITY" solve -q --crease 30 --solver progressive --adaptive -o "$work/c.ply" "$work/tris.scene" 2> "$work/err"
[ $? -eq 2 ] && grep -q 'hanging vertices' "$work/err"
ok $? "--crease with --adaptive: a usage error (it would crack the adaptive mesh)"
# --max-element-size that cuts nothing says so
"$RADIOSITY" formfactor -q --max-element-size 10 -o "$work/f.tsv" "$work/tris.scene" 2> "$work/err"
[ $? -eq 0 ] && grep -q 'warning: --max-element-size 10 makes no surface .* finer' "$work/err"
ok $? "--max-element-size larger than every surface: a warning ($(head -c 120 "$work/err"))"
"$RADIOSITY" formfactor -q --max-element-size 0 "$work/tris.scene" > /dev/null 2> "$work/err"
[ $? -eq 2 ] && grep -q 'takes a positive length' "$work/err"
ok $? "--max-element-size 0: a usage error"
"$RADIOSITY" formfactor -q --mesh 2x2 --max-element-size 0.5 "$work/tris.scene" > /dev/null 2> "$work/err"
[ $? -eq 2 ] && grep -q 'not both' "$work/err"
ok $? "--mesh with --max-element-size: a usage error"
done_testing
