#!/bin/sh
# figures-hemicube.sh -- what the hemicube (Cohen & Greenberg 1985) trades
# for speed: the Cornell box solved with hemicubes of 8, 16 and 64 pixels
# beside the contour integral's solution, flat shaded at one exposure, and
# the time and error of the form factors against resolution on the cube.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: scripts/figures-hemicube.sh RADIOSITY DATADIR OUTDIR
# Writes OUTDIR/hemicube-*.png, .ply and .tsv, and prints the HTML
# section for the figures page (scripts/figures.sh) on standard output.
set -eu

. "$(dirname "$0")/figlib.sh"
fig_args "$@"
radiosity=$1
box=$2/cornell-box.scene
cube=$2/grey-cube.scene
out=$3
[ -r "$box" ] && [ -r "$cube" ] || { echo "$0: cannot read $box or $cube" >&2; exit 1; }
mkdir -p "$out"

# run ARGS...: the program, or a message naming the command and exit 1
run() {
  "$radiosity" "$@" || { echo "$0: failed: $radiosity $*" >&2; exit 1; }
}

cells=
# pic NAME CAPTION SOLVE-ARGS...: solve the box to NAME.ply, draw it flat at
# exposure 1 (the same for all, so the pictures compare) to NAME.png
pic() {
  name=$1 caption=$2
  shift 2
  t0=$(date +%s)
  run solve -q "$@" -o "$out/$name.ply" "$box"
  t1=$(date +%s)
  run render -q --shading flat --exposure 1 -o "$out/$name.png" "$out/$name.ply"
  cmd=$(html_escape "radiosity solve $* -o $name.ply $box; radiosity render --shading flat --exposure 1 -o $name.png $name.ply")
  cells="$cells<td><figure><img src=\"$name.png\" width=\"256\" height=\"256\" alt=\"$(html_escape "$caption")\"><figcaption>$(html_escape "$caption") (solved in $((t1 - t0)) s)<br><code>$cmd</code></figcaption></figure></td>
"
}

pic hemicube-8 "hemicube, 8 x 8 pixels" --form-factors-method hemicube --resolution 8
pic hemicube-16 "hemicube, 16 x 16 pixels" --form-factors-method hemicube --resolution 16
pic hemicube-64 "hemicube, 64 x 64 pixels" --form-factors-method hemicube --resolution 64
pic hemicube-contour "contour integral (the default)"

# the form factors' error against resolution on the grey cube, 8 x 8 walls
run sweep -q --meshes 8 --accuracies default --resolutions 8,16,32,64,128,256 \
  -o "$out/hemicube-sweep.tsv" --plot "$out/hemicube-sweep.png" "$cube"
table=$(awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { m = $c["method"] == "hemicube" ? "hemicube " $c["resolution"] : "contour, " $c["accuracy"]
    printf "<tr><td>%s</td><td>%.3g</td><td>%.3g</td><td>%.3g</td></tr>\n", m,
      $c["seconds_formfactor"], $c["ff_error"], $c["rms_error"] }' "$out/hemicube-sweep.tsv")

cat <<EOF
<h2>The hemicube: what the 1988 paper traded for speed</h2>
<p>The Cornell box solved with form factors from hemicubes (Cohen &amp; Greenberg 1985;
Cohen et al. 1988, section 3.1) of 8, 16 and 64 pixels across the top face, beside the
contour integral.  Each pixel of a hemicube counts wholly for the element that covers its
centre, so at low resolution neighbouring elements see the light (and each other)
through different numbers of pixels: the plaid on the back wall, the ceiling and the
floor is that aliasing.  It fades as the resolution grows; what stays is that each
row of F comes from the element's centre only.  Flat shading, exposure 1 for all four.</p>
<table><tr>
$cells</tr></table>
<p>The grey cube at 8 x 8 elements per wall: the time of the form factors and their
error against the contour integral in reference mode on the same mesh (ff_error, the
largest row sum of |dF|), and the RMS error of B against the reference-mode gauss
solution on the same mesh (<a href="hemicube-sweep.tsv">TSV</a>,
<a href="hemicube-sweep.png">plot</a>).  <code>$(html_escape "radiosity sweep --meshes 8 --accuracies default --resolutions 8,16,32,64,128,256 $cube")</code></p>
<table border="1"><tr><th>method</th><th>seconds</th><th>ff_error</th><th>rms_error of B</th></tr>
$table
</table>
EOF
