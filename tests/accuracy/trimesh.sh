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
# ---- the room as a modelling tool exports it: OBJ, 8 shared vertices ---------
cat > "$work/room.mtl" <<'END'
newmtl w
Kd 0.5 0.5 0.5
newmtl l
Kd 0.2 0.2 0.2
Ke 1 1 1
END
awk 'BEGIN { print "mtllib room.mtl"; print "o room" }
  $1 == "quad" { for (k = 0; k < 4; k++) { p = $(3 + 3 * k) " " $(4 + 3 * k) " " $(5 + 3 * k)
                   if (!(p in id)) { id[p] = ++n; print "v " p }; c[k] = id[p] }
                 printf "usemtl %s\nf %d %d %d\nf %d %d %d\n", $2, c[0], c[1], c[2], c[0], c[2], c[3] }' \
  "$work/quads.scene" > "$work/room.obj"
o0=$(floor_b "$work/room.obj" --max-element-size 0.25)
awk -v a="$o0" -v b="$t0" 'BEGIN { d = a - b; exit !(a != "" && d * d <= 1e-24) }'
ok $? "the OBJ room's floor B is the triangle scene's ($o0, $t0): the same faces"
# It renders smooth: the quads' picture is continuous (their elements share
# vertices, Gouraud-shaded), so its largest step between neighbouring
# pixels across the back wall is the field's own slope; the OBJ room's two
# triangles per wall, smoothed across their diagonal by default (one
# object, one material, coplanar), must stay within twice that.  Without
# smoothing (--crease 0) the diagonal is a visible step, which the same
# measure must catch.  Camera inside the room, the scanline across the
# back wall (y = 1) and its diagonal; columns 160-350 are that wall.
cam="--eye 0.5,0.02,0.5 --at 0.5,1,0.4 --up 0,0,1 --fov 100 --scanline 256"
step() { # step SCENE OPTIONS...: the largest red step between neighbouring pixels on the wall
  s=$1; shift
  "$RADIOSITY" render -q "$s" $cam --max-element-size 0.125 "$@" -o "$work/p.png" \
    --profile "$work/p.tsv" 2> "$work/err" &&
    awk -F '\t' 'NR > 2 && $1 >= 160 && $1 <= 350 { d = $2 - p; if (d < 0) d = -d; if (d > m) m = d }
      NR > 1 { p = $2 } END { printf "%.3g\n", m }' "$work/p.tsv"
}
sq=$(step "$work/quads.scene"); so=$(step "$work/room.obj"); s0=$(step "$work/room.obj" --crease 0)
awk -v q="$sq" -v o="$so" 'BEGIN { exit !(q > 0 && o <= 2 * q) }'
ok $? "the OBJ room renders smooth: largest step $so, the quads' $sq $(head -c 200 "$work/err")"
awk -v q="$sq" -v o="$s0" 'BEGIN { exit !(q > 0 && o > 4 * q) }'
ok $? "with --crease 0 its triangles' diagonal shows: step $s0 against the quads' $sq"
# a wall that is its own object is still smooth inside (its two triangles)
awk '/^f 4 3 7$/ { print "o back" } { print }' "$work/room.obj" > "$work/room2.obj"
s2=$(step "$work/room2.obj")
awk -v q="$sq" -v o="$s2" 'BEGIN { exit !(q > 0 && o <= 2 * q) }'
ok $? "a wall that is its own object is smooth inside: step $s2"
# Separate objects never mix: the floor's two triangles as two objects keep
# their own values along the diagonal they share, as one object they take
# one value there.  The PLY's vertices at each point of the floor's
# diagonal (z = 0, x = y, the room's corners left out, where walls meet it
# at 90 degrees): how many points hold different values.
split_points() { # split_points SCENE OPTIONS...
  s=$1; shift
  "$RADIOSITY" solve -q --max-element-size 0.25 "$@" -o "$work/v.ply" "$s" 2> "$work/err" &&
    awk '/^end_header/ { body = 1; next } body && NF == 9 && $3 == 0 && $1 == $2 && $1 > 0 && $1 < 1 {
           k = sprintf("%.9f", $1); if (k in v && v[k] != $4) d[k] = 1; v[k] = $4 }
         END { n = 0; for (k in d) n++; print n }' "$work/v.ply"
}
awk '/^f 1 3 4$/ { print "o floor2" } { print }' "$work/room.obj" > "$work/room3.obj"
one=$(split_points "$work/room.obj"); two=$(split_points "$work/room3.obj")
[ "$one" = 0 ] && [ "${two:-0}" -gt 0 ]
ok $? "one object: one value per point of the floor's diagonal ($one differ); two objects: their own ($two differ)"
# a scene file is never smoothed across surfaces unless asked: its PLY is
# the one --crease 0 writes
"$RADIOSITY" solve -q --max-element-size 0.25 -o "$work/d.ply" "$work/tris.scene" &&
  "$RADIOSITY" solve -q --max-element-size 0.25 --crease 0 -o "$work/z.ply" "$work/tris.scene" &&
  cmp -s "$work/d.ply" "$work/z.ply" && [ "$(split_points "$work/tris.scene")" -gt 0 ]
ok $? "a scene file's default is --crease 0 (the same PLY, its diagonals split)"

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
