#!/bin/sh
# render.sh -- `radiosity render`: the picture of the 1984 cube, its scanline
# profiles, the PLY round trip, and the error cases.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Geometry used below (shipped camera: eye 0.5 0.5 -1.2, looking along +z,
# fov 45, 512 x 512): f = 256 / tan(22.5 deg) = 618.04 pixels.  The back wall
# (depth 2.2, half-width 0.5) spans 256 +- 140.5, so pixel columns and rows
# 116..395 are the back wall; world x = 0 (red) is on the RIGHT.  The side
# walls reach the image border (their near edges at depth 1.2 project to
# 256 +- 257.5), so every pixel is a wall.  The four creases along z (walls
# meeting floor and ceiling) project onto the image diagonals.
. "${top_srcdir:-.}/tests/lib.sh"

cube="$top_srcdir/data/goral1984-cube.scene"
col() { # col FILE.tsv X FIELD: the value of column FIELD (r g b = 2 3 4) at pixel X
  awk -F'\t' -v x="$2" -v f="$3" 'NR > 1 && $1 == x { print $f }' "$1"
}
png_size() { # png_size FILE: "WIDTH HEIGHT" from the IHDR chunk (bytes 16-23, big-endian)
  od -An -tu1 -j16 -N8 "$1" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }'
}

# ---- the picture -------------------------------------------------------------
"$RADIOSITY" render -q "$cube" -o "$work/cube.png" --scanline 256 --profile "$work/mid.tsv" \
  --plot "$work/mid-plot.png"; rc=$?
ok $rc "render the cube with a profile and a plot: exit $rc"
[ "$(png_size "$work/cube.png")" = "512 512" ]; ok $? "default size 512 x 512 ($(png_size "$work/cube.png"))"
[ "$(od -An -c -N4 "$work/cube.png" | tr -d ' ')" = '211PNG' ]; ok $? "PNG signature"
[ "$(png_size "$work/mid-plot.png")" = "720 405" ]; ok $? "the plot is a 720 x 405 PNG"
[ "$(head -n 1 "$work/mid.tsv")" = "$(printf 'x\tr\tg\tb')" ] && [ "$(wc -l < "$work/mid.tsv")" -eq 513 ]
ok $? "profile: header x r g b and one line per pixel column"
"$RADIOSITY" render -q "$cube" -o "$work/small.png" --width 320 --height 200
[ "$(png_size "$work/small.png")" = "320 200" ]; ok $? "--width 320 --height 200 gives $(png_size "$work/small.png")"

# colour bleeding on the back wall: R/B near the red wall (right, columns
# 376-391) against near the blue wall (left, columns 120-135); the walls
# reflect 0.8 of their own band and 0.1 of the other, so the ratio must
# differ clearly (measured 1.22 against 0.82); 1.2x is the margin.
rb() { awk -F'\t' -v a="$2" -v b="$3" 'NR > 1 && $1 >= a && $1 <= b { r += $2; bl += $4 } END { printf "%.6f\n", r / bl }' "$1"; }
right=$(rb "$work/mid.tsv" 376 391); left=$(rb "$work/mid.tsv" 120 135)
awk -v r="$right" -v l="$left" 'BEGIN { exit !(r > 1.2 * l && r > 1 && l < 1) }'
ok $? "colour bleeding on the back wall: R/B $right near the red wall, $left near the blue wall"
# the red wall itself (column 500) is red, the blue wall (column 10) blue
awk -v r="$(col "$work/mid.tsv" 500 2)" -v b="$(col "$work/mid.tsv" 500 4)" 'BEGIN { exit !(r > 4 * b) }'
ok $? "the red wall is on the right of the picture"
awk -v r="$(col "$work/mid.tsv" 10 2)" -v b="$(col "$work/mid.tsv" 10 4)" 'BEGIN { exit !(b > 4 * r) }'
ok $? "the blue wall is on the left"

# floor and ceiling mirror each other: the scene and the camera are symmetric
# under y -> 1 - y, so row k and row 511 - k agree to round-off (measured
# below 1e-14; tolerance 1e-9 on values of O(0.1)), except where a pixel
# centre lies exactly on a crease between two walls (columns k and 511 - k,
# on the image diagonals), where either wall may win the depth tie.
"$RADIOSITY" solve -q "$cube" --output "$work/sol.ply"; ok $? "solve --output a PLY"
mirror_ok=0
for k in 20 60 100 200; do
  k2=$((511 - k))
  "$RADIOSITY" render "$work/sol.ply" -o "$work/x.png" --scanline $k --profile "$work/top.tsv"
  "$RADIOSITY" render "$work/sol.ply" -o "$work/x.png" --scanline $k2 --profile "$work/bot.tsv"
  d=$(paste "$work/top.tsv" "$work/bot.tsv" | awk -F'\t' -v k=$k 'NR > 1 && $1 != k && $1 != 511 - k {
      for (b = 2; b <= 4; b++) { d = $b - $(b + 4); if (d < 0) d = -d; if (d > m) m = d } } END { printf "%.3g\n", m }')
  awk -v d="$d" 'BEGIN { exit !(d <= 1e-9) }' || mirror_ok=1
  diag "rows $k and $k2: largest difference $d"
done
ok $mirror_ok "floor and ceiling mirror each other (rows k and 511-k, k = 20 60 100 200)"

# the PLY round trip draws the same picture, byte for byte (%.17g is exact)
"$RADIOSITY" render "$work/sol.ply" -o "$work/fromply.png"
cmp -s "$work/cube.png" "$work/fromply.png"; ok $? "render SOLUTION.ply = render SCENE, byte for byte"
# the cube's front wall emits: the default exposure leaves it out (the PLY
# says which faces emit), --exposure-from all counts it, so the pictures
# differ, and each survives the PLY round trip
grep -q '^property uchar emitting$' "$work/sol.ply"; ok $? "the PLY marks the emitting faces"
"$RADIOSITY" render -q "$cube" --exposure-from all -o "$work/all.png"
"$RADIOSITY" render "$work/sol.ply" --exposure-from all -o "$work/allply.png"
! cmp -s "$work/cube.png" "$work/all.png" && cmp -s "$work/all.png" "$work/allply.png"
ok $? "--exposure-from all differs from the default and survives the PLY round trip"
"$RADIOSITY" render -q "$cube" --exposure-from reflectors -o "$work/refl.png"
cmp -s "$work/cube.png" "$work/refl.png"; ok $? "--exposure-from reflectors is the default"

# deterministic
"$RADIOSITY" render -q "$cube" -o "$work/cube2.png"
cmp -s "$work/cube.png" "$work/cube2.png"; ok $? "two runs give byte-identical PNGs"
"$RADIOSITY" render -q "$cube" -o "$work/x.png" --scanline 256 --plot "$work/mid-plot2.png"
cmp -s "$work/mid-plot.png" "$work/mid-plot2.png"; ok $? "and byte-identical plots"

# flat and smooth: from further out (eye z = -3) the cube's open front shows
# background around it; both shadings cover the same pixels and differ only
# inside the surfaces.  Flat shading of the middle row crosses the back wall's
# 7 element columns: 7 distinct values there (columns 116..395 at eye -1.2).
for sh in flat smooth; do
  "$RADIOSITY" render "$work/sol.ply" --shading $sh --eye 0.5,0.5,-3 -o "$work/$sh.png" \
    --scanline 300 --profile "$work/$sh.tsv"
done
same_bg=$(paste "$work/flat.tsv" "$work/smooth.tsv" | awk -F'\t' 'NR > 1 {
    bf = ($2 == 0 && $3 == 0 && $4 == 0); bs = ($6 == 0 && $7 == 0 && $8 == 0)
    if (bf != bs) bad++; if (bf) bg++; else if ($2 != $6) diff++ }
    END { printf "%d %d %d\n", bad, bg, diff }')
set -- $same_bg
[ "$1" -eq 0 ] && [ "$2" -gt 100 ] && [ "$3" -gt 100 ]
ok $? "flat vs smooth: same background ($2 pixels, $1 differ), different inside ($3 pixels)"
! cmp -s "$work/flat.png" "$work/smooth.png"; ok $? "flat and smooth pictures differ"
"$RADIOSITY" render "$work/sol.ply" --shading flat -o "$work/x.png" --scanline 256 --profile "$work/f.tsv"
n=$(awk -F'\t' 'NR > 1 && $1 >= 116 && $1 <= 395 { v[$2] = 1 } END { print length(v) }' "$work/f.tsv")
[ "$n" -eq 7 ]; ok $? "flat: the back wall's 7 element columns give 7 values in the middle row ($n)"
"$RADIOSITY" render "$work/sol.ply" --edges -o "$work/edges.png"
! cmp -s "$work/edges.png" "$work/fromply.png"; ok $? "--edges draws lines"

# camera options
printf 'material w reflect 0.5 emit 1\nquad w 0 0 0  0 1 0  1 1 0  1 0 0\n' > "$work/nocam.scene"
"$RADIOSITY" render -q "$work/nocam.scene" -o "$work/nocam.png" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'no camera' "$work/err" && [ ! -e "$work/nocam.png" ]
ok $? "a scene without a camera: exit $rc, '$(head -n 1 "$work/err")'"
"$RADIOSITY" render -q "$work/nocam.scene" -o "$work/nocam.png" --eye 0.5,0.5,-2 --at 0.5,0.5,0 --width 64 --height 64 \
  --scanline 32 --profile "$work/nocam.tsv"
[ $? -eq 0 ] && awk -v r="$(col "$work/nocam.tsv" 32 2)" 'BEGIN { exit !(r == 1) }'
ok $? "--eye and --at give the camera; the emitter is drawn at radiosity 1"
"$RADIOSITY" render "$work/sol.ply" -o "$work/x.png" --eye 0.5,0.5,3 --at 0.5,0.5,0 2> "$work/err"
ok $? "--eye and --at override the PLY's camera"
"$RADIOSITY" render "$work/sol.ply" -o "$work/x.png" --eye 0.5,0.5,0 --at 0.5,0.5,0 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'eye and at must differ' "$work/err"; ok $? "eye = at: exit $rc"

# ---- usage and errors -----------------------------------------------------------
"$RADIOSITY" render --help > "$work/help"; rc=$?
ok $rc "render --help exits 0"
missing=
for o in -o --output --width --height --eye --at --up --fov --shading --edges --exposure --exposure-from \
         --scanline --profile --plot --help --mesh --bounces --solver; do
  grep -q -- "$o" "$work/help" || missing="$missing $o"
done
[ -z "$missing" ]; ok $? "render --help lists every option${missing:+ (missing:$missing)}"
usage() { # usage DESCRIPTION ARGS...: exit 2
  d=$1; shift
  "$RADIOSITY" render "$@" > /dev/null 2>&1; rc=$?
  [ $rc -eq 2 ]; ok $? "$d: exit $rc"
}
usage "no -o" "$cube"
usage "no input" -o "$work/x.png"
usage "bad --shading" --shading phong "$cube" -o "$work/x.png"
usage "bad --width" --width 0 "$cube" -o "$work/x.png"
usage "bad --eye" --eye 1,2 "$cube" -o "$work/x.png"
usage "bad --fov" --fov 180 "$cube" -o "$work/x.png"
usage "bad --exposure" --exposure -1 "$cube" -o "$work/x.png"
usage "bad --exposure-from" --exposure-from lamps "$cube" -o "$work/x.png"
usage "--scanline outside the picture" --scanline 512 --profile "$work/p.tsv" "$cube" -o "$work/x.png"
usage "--profile without --scanline" --profile "$work/p.tsv" "$cube" -o "$work/x.png"
usage "--mesh with a PLY" --mesh 2x2 "$work/sol.ply" -o "$work/x.png"
usage "unknown option" --frobnicate "$cube" -o "$work/x.png"

printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double zz\nend_header\n' > "$work/bad.ply"
rm -f "$work/x.png"
"$RADIOSITY" render "$work/bad.ply" -o "$work/x.png" 2> "$work/err"; rc=$?
case "$(head -n 1 "$work/err")" in "radiosity: $work/bad.ply:3: "*) m=0 ;; *) m=1 ;; esac
[ $rc -eq 1 ] && [ $m -eq 0 ] && [ ! -e "$work/x.png" ]
ok $? "malformed PLY: exit $rc, '$(head -n 1 "$work/err")', no picture"
"$RADIOSITY" render "$work/missing.ply" -o "$work/x.png" 2> /dev/null; rc=$?
[ $rc -eq 1 ] && [ ! -e "$work/x.png" ]; ok $? "missing PLY: exit $rc"
echo precious > "$work/keep.png"
"$RADIOSITY" render "$work/bad.ply" -o "$work/keep.png" 2> /dev/null
[ "$(cat "$work/keep.png")" = precious ]; ok $? "a failed run leaves an existing picture untouched"
"$RADIOSITY" render "$work/sol.ply" -o "$work/nodir/x.png" 2> "$work/err"; rc=$?
[ $rc -eq 1 ]; ok $? "unwritable output: exit $rc, '$(head -n 1 "$work/err")'"
[ -z "$(ls "$work" | grep tmp)" ]; ok $? "no temporary files left behind"

# the picture does not depend on the unit of length (render.c, eye_frame):
# the cube scaled by 2^500 and 2^-500 (exact) draws the same bytes as the
# unit cube; scaled by 1e150 and moved 1e12 away (rounded), the same
# radiosity along a row within 1e-9 but for a pixel or two at the edges
scaled() { # scaled FACTOR SHIFT: the 1984 cube, every length times FACTOR, moved by SHIFT
  awk -v f="$1" -v d="$2" '
    $1 == "quad" { for (k = 3; k <= 14; k++) $k = sprintf("%.17g", $k * f + d) }
    $1 == "camera" { for (k = 3; k <= 5; k++) $k = sprintf("%.17g", $k * f + d)
                     for (k = 7; k <= 9; k++) $k = sprintf("%.17g", $k * f + d) }
    { print }' "$top_srcdir/data/goral1984-cube.scene"
}
pic() { # pic NAME FACTOR SHIFT
  scaled "$2" "$3" > "$work/$1.scene"
  "$RADIOSITY" render -q --mesh 4x4 --width 96 --height 96 --scanline 48 \
    --profile "$work/$1.tsv" -o "$work/$1.png" "$work/$1.scene"
}
pic unit 1 0 && pic up 3.2733906078961419e150 0 && pic down 3.0549363634996047e-151 0
ok $? "the cube drawn at 1, 2^500 and 2^-500"
cmp -s "$work/unit.png" "$work/up.png" && cmp -s "$work/unit.png" "$work/down.png"
ok $? "scaled by 2^500 or 2^-500 (exact): the same PNG, byte for byte"
pic big 1e150 0 && pic far 1 1e12
ok $? "the cube drawn at 1e150, and 1e12 away"
# 1e12 away, every coordinate is rounded to 2^-13 (1.2e-4 of the cube's
# side): the geometry itself moves by that much, so the tolerance is 1e-3
for v in big:1e-9 far:1e-3; do
  tol=${v#*:}; v=${v%%:*}
  awk -F'\t' -v tol="$tol" 'NR == FNR { v[FNR] = $2 + $3 + $4; next }
    FNR > 1 { d = $2 + $3 + $4 - v[FNR]; if (d < 0) d = -d
              if (d > tol * (v[FNR] > 0 ? v[FNR] : 1)) bad++ }
    END { exit bad > 2 }' "$work/unit.tsv" "$work/$v.tsv"
  ok $? "$v: the row's radiosity as at unit scale (all but at most 2 edge pixels within $tol)"
done
# pictures are PNG: a path naming another format is a usage error, nothing written
"$RADIOSITY" render -q "$top_srcdir/data/goral1984-cube.scene" -o "$work/cube.jpg" 2> "$work/err"; rc=$?
[ $rc -eq 2 ] && grep -q 'PNG only' "$work/err" && [ ! -e "$work/cube.jpg" ]
ok $? "render -o cube.jpg: exit 2, said, nothing written"
"$RADIOSITY" sweep -q --plot "$work/s.GIF" "$top_srcdir/data/goral1984-cube.scene" 2> "$work/err"; rc=$?
[ $rc -eq 2 ] && grep -q 'PNG only' "$work/err" && [ ! -e "$work/s.GIF" ]
ok $? "sweep --plot s.GIF: exit 2 too"
done_testing
