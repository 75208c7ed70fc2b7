#!/bin/sh
# figures.sh -- the pictures of Goral, Torrance, Greenberg & Battaile 1984
# (their figures 6-8) from the cube scene, of Cohen, Chen, Wallace &
# Greenberg 1988 (figures 2-5, 7 and 8) from the Cornell box, and of
# George, Sillion & Greenberg 1990 (figure 6), with an HTML page showing
# them side by side, each captioned with its paper, its figure and what to
# look for, and the exact command behind it.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: scripts/figures.sh RADIOSITY DATADIR OUTDIR
#   RADIOSITY  the program (e.g. src/radiosity)
#   DATADIR    where goral1984-cube.scene, cornell-box.scene and
#              cube-on-table.scene are (e.g. data)
#   OUTDIR     where the pictures and index.html go (created if needed)
#
# Figure 6: flat shading at meshes 1x1 to 7x7, each with the RGB scanline
#           plot of the middle row (the paper's intensity traces).
# Figure 7: the 5x5 mesh with direct light only (7a: one reflection on the
#           way to the eye), then 1, 2, 4 and 8 intermediate reflections
#           more (7b-7e: --bounces 2, 3, 5, 9), and solved (7f), each with
#           its RGB scanline plot.
# Figure 8: smooth (Gouraud) shading of the 3x3 and 7x7 meshes.
# Cohen et al. 1988, on data/cornell-box.scene (one `radiosity progress`
# run, its surfaces shooting as patches, 100 steps per method):
#           figures 2-5: sorted shooting shown with the ambient term after
#           1, 2, 24 and 100 shots, each with its pseudo-colour error image
#           (grey accurate, red over, blue under the converged solution);
#           figure 7: the RMS error of eq. 14 of the four methods divided
#           by the RMS of the converged solution, on a linear axis;
#           figure 8: the four methods after 2 steps side by side.
# And figure 6 of George, Sillion & Greenberg 1990 (cube-on-table.scene):
#           the room converged without and with the cube, and the cube put
#           on the table by redistribution against progressive refinement
#           from scratch after 2 and after 50 shots, with the error of their
#           eq. 7 under each (overall and on the 1% of patches that change
#           most).
# figures-hemicube.sh adds the hemicube's aliasing, figures-view.sh the
# race as the live viewer draws it (headless Chromium on its page), and
# figures-adaptive.sh the adaptive meshes.
set -eu

. "$(dirname "$0")/figlib.sh"
fig_args "$@"
radiosity=$1
data=$2
scene=$2/goral1984-cube.scene
out=$3
size=512
row=$((size / 2))

[ -r "$scene" ] || { echo "$0: cannot read $scene" >&2; exit 1; }
mkdir -p "$out"

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
end_row "Goral et al. 1984, figure 6: flat shading at increasing mesh resolution" \
  "The cube of data/goral1984-cube.scene, seen through its emitting front wall (the red wall, x = 0, on the right, the blue on the left; the reflectances are this project's choice, see the scene file).  Each element is drawn in its own radiosity; below each picture the linear R, G, B radiosity along row $row (the middle row).  Look for: the staircase of the coarse meshes smoothing out as the mesh refines, and the red and blue bleeding onto the grey walls next to them (the R and B curves parting near the coloured walls)."

# the paper's 7a-7e: direct light, then 1, 2, 4 and 8 intermediate reflections
for pair in a:1:0 b:2:1 c:3:2 d:5:4 e:9:8; do
  letter=${pair%%:*} rest=${pair#*:} k=${rest%%:*} inter=${rest#*:}
  if [ "$inter" = 0 ]; then what="direct light only"
  else what="$inter intermediate reflection$([ "$inter" = 1 ] || echo s)"; fi
  fig "fig7$letter-bounces-$k" "7$letter: $what (--bounces $k)" plot -- \
    "$scene" --mesh 5x5 --shading flat --bounces "$k"
done
fig "fig7f-solved" "7f: solved (all reflections)" plot -- "$scene" --mesh 5x5 --shading flat
end_row "Goral et al. 1984, figure 7: the light after K reflections" \
  "As in the paper: 7a is the direct light alone (light that reflects once, off a wall, on its way to the eye: B = E + rho F E), 7b-7e add 1, 2, 4 and 8 intermediate reflections (B = sum over m = 0..K of (rho F)^m E with K = 2, 3, 5, 9: Jacobi from B = E without a convergence test), 7f is the solution of the full system.  Look for: in 7a the grey walls are grey (equal R, G and B: their three scanline curves coincide); colour bleeds onto them from 7b on and their mean rises with every reflection; 7e is within 0.1% of 7f on the grey walls' mean (tests/papers/figure7.sh checks 0.5%).  Below each picture the linear R, G, B radiosity along row $row.  The exposure of each picture maps its brightest non-emitting element to white (--exposure-from reflectors, the default)."

for n in 3 7; do
  fig "fig8-${n}x$n-smooth" "${n}x$n elements per wall, smooth" "" -- \
    "$scene" --mesh "${n}x$n" --shading smooth
  fig "fig8-${n}x$n-flat" "${n}x$n elements per wall, flat" "" -- \
    "$scene" --mesh "${n}x$n" --shading flat
done
end_row "Goral et al. 1984, figure 8: smooth shading" \
  "Vertex radiosity (the mean of the elements around each vertex) interpolated bilinearly across each element (Gouraud shading), next to the flat picture of the same mesh.  Look for: the element boundaries of the flat pictures gone in the smooth ones, and the 3x3 smooth picture already close to the 7x7 one."

# ---- Cohen, Chen, Wallace & Greenberg 1988, figures 2-5, 7 and 8 -----------
box=$data/cornell-box.scene
[ -r "$box" ] || { echo "$0: cannot read $box" >&2; exit 1; }
set -- progress -q --patches --steps 100 --snapshots-at 1,2,24,100 --error-images \
  --snapshot-prefix "$out/c88" -o "$out/c88-race.tsv" \
  --plot "$out/c88-fig7.png" --plot-axis linear --plot-normalised "$box"
"$radiosity" "$@" || { echo "$0: failed: $(shell_quote "$radiosity" "$@")" >&2; exit 1; }
c88_cmd=$(html_escape "$(shell_quote "$radiosity" "$@")")

# c88cell PICTURE CAPTION [WIDTH]: a cell with the progress command
c88cell() {
  cells="$cells<td><figure style=\"width: ${3:-256}px\"><img src=\"$1.png\" width=\"${3:-256}\" alt=\"$(html_escape "$2")\"><figcaption>$(html_escape "$2")</figcaption></figure></td>
"
}
# c88rms STEP COLUMN: the race table's eq. 14 error at STEP
c88rms() {
  awk -F '\t' -v k="$1" -v m="$2" 'NR == 1 { for (j = 1; j <= NF; j++) c[$j] = j; next }
    $1 == k { printf "%.3g", $c[m] }' "$out/c88-race.tsv"
}

for k in 1 2 24 100; do
  f=$(printf '%06d' "$k")
  c88cell "c88-sorted_ambient-$f" "$k shot$([ "$k" = 1 ] || echo s), with the ambient term (RMS error $(c88rms "$k" sorted_ambient))"
done
end_row "Cohen et al. 1988, figures 2-5: progressive refinement after 1, 2, 24 and 100 shots" \
  "The Cornell box (data/cornell-box.scene, 2603 elements; each surface shoots as one patch, the patch with the most unshot power first, and its elements receive), shown with the ambient term of eq. 13, which stands in for the light not shot yet.  The RMS error is that of eq. 14 (band-averaged radiosity, area-weighted) against the converged gauss solution.  Look for: after one shot (the lamp) every surface is already lit, the shadows by the ambient term alone; the picture changes little after 24 shots.  Exposure: the converged solution's brightest non-emitting element is white.  Command: <code>$c88_cmd</code>"
for k in 1 2 24 100; do
  f=$(printf '%06d' "$k")
  c88cell "c88-sorted_ambient-$f-error" "error after $k shot$([ "$k" = 1 ] || echo s)"
done
end_row "Cohen et al. 1988, figures 2-5: the pseudo-colour error images" \
  "Each element coloured by the relative error e = (Y - Yc) / Yc of its band-averaged radiosity Y as displayed above against the converged Yc: grey (128, 128, 128) where e = 0, shading linearly to red (255, 0, 0) at e = +50% or more (over-estimate) and to blue (0, 0, 255) at -50% or less (under-estimate); flat shading.  Look for: after 1 shot the regions the lamp does not reach (the shadows of the blocks, the block faces turned away from it, the corners) are red, as the uniform ambient term over-estimates there, while the ceiling around the lamp, lit in the end by the bright floor, is blue; the red shrinks by 24 shots and the picture is nearly all grey after 100 (tests/papers/errorimages.sh checks the first two on a coarse mesh).  The front face of the short block, which looks out through the open front of the box, stays red longest: eq. 9 approximates every element's view of the room by the others' share of the total area, as if each saw a closed room, and this face sees mostly the opening (data/cornell-box-closed.scene, with a front wall, does not show it)."
c88cell c88-fig7 "RMS error (eq. 14) of each method divided by the RMS of the converged solution, linear axis (table: c88-race.tsv)" 640
end_row "Cohen et al. 1988, figure 7: the convergence of the four methods" \
  "Gathering (Gauss-Seidel, one element row per step), shooting in file order, sorted shooting, and sorted shooting displayed with the ambient term, from B = E.  The error is divided by the RMS of the converged solution (eq. 14 against B = 0), as a fraction of it, on a linear axis.  Look for: gathering hardly moves in 100 steps (one row of 2603 per step), shooting in file order falls in steps, sorted shooting falls fastest, and the ambient term lowers its error further from the first step.  After 100 steps: gathering $(c88rms 100 gathering), shooting $(c88rms 100 shooting), sorted $(c88rms 100 sorted), sorted + ambient $(c88rms 100 sorted_ambient) (not normalised, the unit of B)."
for m in gathering:gathering shooting:"shooting, file order" sorted:"shooting, sorted" sorted_ambient:"sorted + ambient"; do
  c88cell "c88-${m%%:*}-000002" "${m#*:}, 2 steps (RMS error $(c88rms 2 "${m%%:*}"))"
done
end_row "Cohen et al. 1988, figure 8: the four methods after 2 steps" \
  "The same run, each method after two steps from B = E.  Look for: gathering has updated two elements of 2603 and shows little more than the lamp; shooting in file order has shot the lamp (the first surface in the file) and then a piece of ceiling that had received nothing, so it shows the direct light alone; sorted shooting has shot the lamp and then the patch holding the most of the power it received, so the ceiling and the shadows begin to fill; the ambient term fills the shadows with an estimate of the light still to come."

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
  "The room of data/cube-on-table.scene converged without the cube (frame 0) and with it (frame 1: the cube added, its form factors and the pairs it can shadow recomputed, the energy redistributed and propagated to convergence).  Each animation's pictures share frame 0's exposure.  Look for: the cube's shadow on the table and the light the cube reflects onto its surroundings."
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
# The least error any two steps can leave on the most changed 1%
# (tests/redist_oracle.py tries every sequence of two redistribution
# shots, gathers and propagation shots, from the form factors before and
# after the change).
step_words() { # R7, G7, P7: a step of the oracle in words
  case $1 in
    R*) echo "the redistribution shot of element ${1#R}" ;;
    G*) echo "the gather by element ${1#G}" ;;
    *) echo "the propagation shot of element ${1#P}" ;;
  esac
}
oracle=
py=$(dirname "$0")/../tests/redist_oracle.py
if command -v python3 > /dev/null 2>&1 && [ -r "$py" ]; then
  sed '/^object cube absent$/,/^end$/d' "$cot" > "$out/george6-without-cube.scene"
  for k in 0 1; do
    [ $k = 0 ] && s="$out/george6-without-cube.scene" || s="$out/george6-with-cube.scene"
    "$radiosity" formfactor -q "$s" -o "$out/george6-F$k.npy" ||
      { echo "$0: failed: $(shell_quote "$radiosity" formfactor -q "$s" -o "$out/george6-F$k.npy")" >&2; exit 1; }
  done
  best=$(python3 "$py" best "$out/george6-with-cube.scene" "$out/george6-F0.npy" \
    "$out/george6-F1.npy" "$out/george6-conv-0.tsv" "$out/george6-conv-1.tsv") ||
    { echo "$0: the two-step oracle failed (tests/redist_oracle.py)" >&2; exit 1; }
  set -- $(printf '%s\n' "$best" | sed -n 's/^best //p')
  case ${2:-none} in
    none) how="no step at all" ;;
    *) how=$(step_words "$2"); [ -z "${3:-}" ] || how="$how then $(step_words "$3")" ;;
  esac
  oracle=" No two steps can do better there: tried exhaustively (tests/redist_oracle.py), the best, $how, leaves $(awk -v x="$1" 'BEGIN { printf "%.3g", x }') on the most changed 1%."
  rm -f "$out/george6-F0.npy" "$out/george6-F1.npy"
fi
end_row "George et al. 1990, figure 6: redistribution against progressive refinement from scratch" \
  "Left of each pair: the converged room without the cube, the cube added, and K shots of redistribution and propagation (strategy 1).  Right: the room with the cube solved by progressive refinement from B = E, K shots (largest unshot power first).  The error is that of eq. 7 (luminance, area-weighted, normalised by the converged frame with the cube) over all patches, and over the 1% whose luminance the cube changes most, normalised there by that change (1: as wrong as the picture without the cube).$claim  Those 1% are the table patches the cube covers (it rests 0.01 above them): progressive refinement from scratch never lights them, so it gets them right at once, while redistribution has to take back, shooter by shooter, the light that every patch of the room had sent them, or gather it back one patch per step.$oracle"

rows="$rows$(sh "$(dirname "$0")/figures-hemicube.sh" "$radiosity" "$data" "$out")"
rows="$rows$(sh "$(dirname "$0")/figures-view.sh" "$radiosity" "$data" "$out")"

version=$("$radiosity" --version | head -n 1)
cat > "$out/index.html.tmp" <<EOF
<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>radiosity: the figures of Goral et al. 1984, Cohen et al. 1988 and George et al. 1990</title>
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
<h1>The figures of three radiosity papers</h1>
<p>Goral, Torrance, Greenberg &amp; Battaile, "Modeling the Interaction of Light
Between Diffuse Surfaces", SIGGRAPH 1984 (figures 6-8, the colour-bleeding cube
<code>$(html_escape "$scene")</code>: a unit cube seen through its emitting front
wall; the red wall (x = 0) is on the right, the blue wall on the left);
Cohen, Chen, Wallace &amp; Greenberg, "A Progressive Refinement Approach to Fast
Radiosity Image Generation", SIGGRAPH 1988 (figures 2-5, 7 and 8, on the Cornell
box <code>$(html_escape "$box")</code>); George, Sillion &amp; Greenberg,
"Radiosity Redistribution for Dynamic Environments", IEEE CG&amp;A 1990 (figure 6).
Each section names its paper and figure and says what to look for.  Pictures
are ${size} x ${size}, shown at half size; the command under each picture (or in
its section) made it.  Automatic exposures map the brightest element that
emits nothing to white (lamps clip).  Made by $(html_escape "$version").</p>
$rows</body>
</html>
EOF
mv "$out/index.html.tmp" "$out/index.html"
sh "$(dirname "$0")/figures-adaptive.sh" "$radiosity" "$data" "$out"
echo "figures: $out/index.html ($(( $(date +%s) - start )) s)"
