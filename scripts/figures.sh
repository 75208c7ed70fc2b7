#!/bin/sh
# figures.sh -- the pictures of Goral, Torrance, Greenberg & Battaile 1984
# (their figures 6-8) from the cube scene, with an HTML page showing them
# side by side with the exact command behind each.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: scripts/figures.sh RADIOSITY DATADIR OUTDIR
#   RADIOSITY  the program (e.g. src/radiosity)
#   DATADIR    where goral1984-cube.scene is (e.g. data)
#   OUTDIR     where the pictures and index.html go (created if needed)
#
# Figure 6: flat shading at meshes 1x1 to 7x7, each with the RGB scanline
#           plot of the middle row (the paper's intensity traces).
# Figure 7: the 5x5 mesh with direct light only (7a: one reflection on the
#           way to the eye), then 1, 2, 4 and 8 intermediate reflections
#           more (7b-7e: --bounces 2, 3, 5, 9), and solved (7f), each with
#           its RGB scanline plot.
# Figure 8: smooth (Gouraud) shading of the 3x3 and 7x7 meshes.
# And figure 6 of George, Sillion & Greenberg 1990 (cube-on-table.scene):
#           the room converged without and with the cube, and the cube put
#           on the table by redistribution against progressive refinement
#           from scratch after 2 and after 50 shots, with the error of their
#           eq. 7 under each (overall and on the 1% of patches that change
#           most).
set -eu

if [ $# -ne 3 ]; then
  echo "Usage: $0 RADIOSITY DATADIR OUTDIR" >&2
  exit 2
fi
radiosity=$1
data=$2
scene=$2/goral1984-cube.scene
out=$3
size=512
row=$((size / 2))

[ -x "$radiosity" ] || { echo "$0: $radiosity is not an executable" >&2; exit 1; }
[ -r "$scene" ] || { echo "$0: cannot read $scene" >&2; exit 1; }
mkdir -p "$out"

html_escape() { printf '%s' "$1" | sed 's/&/\&amp;/g; s/</\&lt;/g; s/>/\&gt;/g; s/"/\&quot;/g'; }

# The command line as a shell would accept it back (quoting what needs it).
shell_quote() {
  q=
  for a in "$@"; do
    case "$a" in
      '' | *[!A-Za-z0-9_./,:=+@%-]*) a="'$(printf '%s' "$a" | sed "s/'/'\\\\''/g")'" ;;
    esac
    q="${q:+$q }$a"
  done
  printf '%s' "$q"
}

cells=
# fig NAME CAPTION [PLOT] -- ARGS...: run `radiosity render ARGS... -o OUT/NAME.png`
# and add a cell (picture, optional plot, caption, command) to the current row.
fig() {
  name=$1 caption=$2 plot=$3
  shift 4
  set -- render -q "$@" -o "$out/$name.png"
  if [ -n "$plot" ]; then
    set -- "$@" --scanline "$row" --plot "$out/$name-plot.png" --profile "$out/$name-profile.tsv"
  fi
  "$radiosity" "$@" || { echo "$0: failed: $(shell_quote "$radiosity" "$@")" >&2; exit 1; }
  cmd=$(html_escape "$(shell_quote "$radiosity" "$@")")
  cell="<td><figure><img src=\"$name.png\" width=\"256\" height=\"256\" alt=\"$(html_escape "$caption")\">"
  if [ -n "$plot" ]; then
    cell="$cell<br><img src=\"$name-plot.png\" width=\"256\" alt=\"scanline $row\">"
  fi
  cell="$cell<figcaption>$(html_escape "$caption")"
  if [ -n "$plot" ]; then
    cell="$cell (<a href=\"$name-profile.tsv\">row $row, TSV</a>)"
  fi
  cells="$cells$cell<br><code>$cmd</code></figcaption></figure></td>
"
}

rows=
end_row() {
  rows="$rows<h2>$1</h2>
<p>$2</p>
<table><tr>
$cells</tr></table>
"
  cells=
}

start=$(date +%s)

for n in 1 2 3 4 5 7; do
  fig "fig6-${n}x$n" "${n}x$n elements per wall, flat" plot -- \
    "$scene" --mesh "${n}x$n" --shading flat
done
end_row "Figure 6: flat shading at increasing mesh resolution" \
  "Each element is drawn in its own radiosity; below each picture the linear R, G, B radiosity along row $row (the middle row) of the picture."

# the paper's 7a-7e: direct light, then 1, 2, 4 and 8 intermediate reflections
for pair in a:1:0 b:2:1 c:3:2 d:5:4 e:9:8; do
  letter=${pair%%:*} rest=${pair#*:} k=${rest%%:*} inter=${rest#*:}
  if [ "$inter" = 0 ]; then what="direct light only"
  else what="$inter intermediate reflection$([ "$inter" = 1 ] || echo s)"; fi
  fig "fig7$letter-bounces-$k" "7$letter: $what (--bounces $k)" plot -- \
    "$scene" --mesh 5x5 --shading flat --bounces "$k"
done
fig "fig7f-solved" "7f: solved (all reflections)" plot -- "$scene" --mesh 5x5 --shading flat
end_row "Figure 7: the light after K reflections" \
  "As in the paper: 7a is the direct light alone (light that reflects once, off a wall, on its way to the eye: B = E + rho F E), 7b-7e add 1, 2, 4 and 8 intermediate reflections (B = sum over m = 0..K of (rho F)^m E with K = 2, 3, 5, 9: Jacobi from B = E without a convergence test), 7f is the solution of the full system.  In 7a the grey walls are grey (equal R, G and B); colour bleeds onto them from 7b on, and 7e is within 0.1% of 7f on the grey walls' mean.  Below each picture the linear R, G, B radiosity along row $row.  The exposure of each picture maps its brightest element to white."

for n in 3 7; do
  fig "fig8-${n}x$n-smooth" "${n}x$n elements per wall, smooth" "" -- \
    "$scene" --mesh "${n}x$n" --shading smooth
  fig "fig8-${n}x$n-flat" "${n}x$n elements per wall, flat" "" -- \
    "$scene" --mesh "${n}x$n" --shading flat
done
end_row "Figure 8: smooth shading" \
  "Vertex radiosity (the mean of the elements around each vertex) interpolated bilinearly across each element (Gouraud shading), next to the flat picture of the same mesh."

# ---- George, Sillion & Greenberg 1990, figure 6 ----------------------------
cot=$data/cube-on-table.scene
[ -r "$cot" ] || { echo "$0: cannot read $cot" >&2; exit 1; }
sed 's/^object cube absent$/object cube/' "$cot" > "$out/george6-with-cube.scene"
printf '# no changes: frame 0 alone\n' > "$out/george6-none.changes"

# anim NAME ARGS...: radiosity animate ARGS, a picture and a table per frame
# ($out/NAME-F.png, $out/NAME-F.tsv); the command goes to $anim_cmd.
anim() {
  name=$1
  shift
  set -- animate -q --width "$size" --height "$size" --frames "$out/$name-%d.png" \
    --elements "$out/$name-%d.tsv" "$@"
  "$radiosity" "$@" || { echo "$0: failed: $(shell_quote "$radiosity" "$@")" >&2; exit 1; }
  anim_cmd=$(html_escape "$(shell_quote "$radiosity" "$@")")
}

# eq7 TABLE: the error of George et al. 1990, eq. 7, of TABLE against the
# converged frame with the cube, overall (normalised by sum A Yref), and on
# the 1% of patches whose luminance the cube changes most (by A |Yref -
# Yprev|, Yprev the converged room without the cube: its 411 elements come
# first, in the same order), normalised there by the change itself, sum A
# |Yref - Yprev| (the patches the cube shadows have Yref near 0): 1 is the
# error of not updating at all (rad_anim_error_changed, animate.h).
eq7() {
  awk -F '\t' '
    FNR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; f++; next }
    { y = 0.2126 * $(c["r"]) + 0.7152 * $(c["g"]) + 0.0722 * $(c["b"]) }
    f == 1 { yp[$1] = y; next }
    f == 2 { yr[$1] = y; a[$1] = $(c["area"]); n = $1 + 1; next }
    { ya[$1] = y }
    END {
      for (i = 0; i < n; i++) { d = ya[i] - yr[i]; num += a[i] * (d < 0 ? -d : d); den += a[i] * yr[i]
                                ch = yr[i] - yp[i]; w[i] = a[i] * (ch < 0 ? -ch : ch) }
      k = int(n / 100); if (k < 1) k = 1
      for (q = 0; q < k; q++) { best = -1; for (i = 0; i < n; i++) if (!(i in used) && (best < 0 || w[i] > w[best])) best = i
                                used[best] = 1; d = ya[best] - yr[best]; tn += a[best] * (d < 0 ? -d : d); td += w[best] }
      printf "%.3g %.3g\n", num / den, tn / td }' "$out/george6-conv-0.tsv" "$out/george6-conv-1.tsv" "$1"
}

acell() { # acell PICTURE CAPTION: a cell with the last command
  cells="$cells<td><figure><img src=\"$1.png\" width=\"256\" height=\"256\" alt=\"$(html_escape "$2")\"><figcaption>$(html_escape "$2")<br><code>$anim_cmd</code></figcaption></figure></td>
"
}

anim george6-conv "$cot" "$data/cube-on-table.changes"
acell george6-conv-0 "converged, without the cube"
acell george6-conv-1 "converged, with the cube (redistribution to tolerance 1e-12)"
end_row "George et al. 1990, figure 6: the cube put on the table" \
  "The room of data/cube-on-table.scene converged without the cube (frame 0) and with it (frame 1: the cube added, its form factors and the pairs it can shadow recomputed, the energy redistributed and propagated to convergence).  Each animation's pictures share frame 0's exposure."
claim=
for k in 2 50; do
  anim "george6-redist$k" --steps "$k" "$cot" "$data/cube-on-table.changes"
  set -- $(eq7 "$out/george6-redist$k-1.tsv"); re=$1 rt=$2
  acell "george6-redist$k-1" "redistribution, $k shots after the change: eq. 7 error $re, on the most changed 1% $rt"
  anim "george6-scratch$k" --from-scratch --steps "$k" "$out/george6-with-cube.scene" "$out/george6-none.changes"
  set -- $(eq7 "$out/george6-scratch$k-0.tsv"); pe=$1 pt=$2
  acell "george6-scratch$k-0" "progressive refinement from scratch, $k shots: eq. 7 error $pe, on the most changed 1% $pt"
  verdict=$(awk -v a="$re" -v b="$pe" -v c="$rt" -v d="$pt" 'BEGIN { print (a < b && c < d) ? "below" : "NOT below" }')
  echo "figures: George et al. 1990, fig. 6, $k shots: redistribution $re ($rt on the top 1%), from scratch $pe ($pt): $verdict"
  claim="$claim After $k shots redistribution's error is $verdict that of progressive refinement from scratch ($re against $pe overall, $rt against $pt on the most changed 1%)."
done
end_row "George et al. 1990, figure 6: redistribution against progressive refinement from scratch" \
  "Left of each pair: the converged room without the cube, the cube added, and K shots of redistribution and propagation (strategy 1).  Right: the room with the cube solved by progressive refinement from B = E, K shots (largest unshot power first).  The error is that of eq. 7 (luminance, area-weighted, normalised by the converged frame with the cube) over all patches, and over the 1% whose luminance the cube changes most, normalised there by that change (1: as wrong as the picture without the cube).$claim  Those 1% are the table patches the cube covers (it rests 0.01 above them): progressive refinement from scratch never lights them, so it gets them right at once, while redistribution has to take back, shooter by shooter, the light that every patch of the room had sent them."

version=$("$radiosity" --version | head -n 1)
cat > "$out/index.html.tmp" <<EOF
<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>radiosity: the figures of Goral et al. 1984</title>
<style>
body { font-family: sans-serif; margin: 1em 2em; }
table { border-collapse: collapse; }
td { vertical-align: top; padding: 4px; }
figure { margin: 0; width: 260px; }
figcaption { font-size: 85%; }
code { font-size: 80%; word-break: break-all; }
</style>
</head>
<body>
<h1>The colour-bleeding cube of Goral, Torrance, Greenberg &amp; Battaile (1984)</h1>
<p>Scene <code>$(html_escape "$scene")</code>: a unit cube seen through its emitting front
wall; the red wall (x = 0) is on the right, the blue wall on the left.  The
reflectances are this project's choice (see the scene file).  Pictures are
${size} x ${size}, shown at half size; the command under each picture made it.
Made by $(html_escape "$version").</p>
$rows</body>
</html>
EOF
mv "$out/index.html.tmp" "$out/index.html"
sh "$(dirname "$0")/figures-adaptive.sh" "$radiosity" "$data" "$out"
echo "figures: $out/index.html ($(( $(date +%s) - start )) s)"
