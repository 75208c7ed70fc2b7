#!/bin/sh
# figures-adaptive.sh -- the adaptive mesh of progressive refinement with
# subdivision (Cohen, Chen, Wallace & Greenberg 1988, section 4) on the
# blocker scene and the Cornell box, element edges drawn, with a page
# adaptive.html showing them with the command behind each.  Called by
# scripts/figures.sh; runs alone as well.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: scripts/figures-adaptive.sh RADIOSITY DATADIR OUTDIR
#
# Blocker: the receiver (z = 1) and the blocker's lower face seen from below
#          and aside, adaptive from 4x4 (--subdivide-test error, threshold
#          0.0102, depth 3; the run of tests/papers/adaptive.sh), beside the uniform
#          16x16 mesh whose error it beats.
# Cornell: adaptive from 3x3 per quad (default threshold 0.1, depth 3),
#          converged to 1e-3 of the emitted power; the exposure is set by
#          hand because the lamp is 10 to 50 times brighter than the walls.
set -eu

. "$(dirname "$0")/figlib.sh"
fig_args "$@"
radiosity=$1
data=$2
out=$3
size=512
mkdir -p "$out"

rows=""
figure() { # figure FILE CAPTION COMMAND...
  file=$1 caption=$2
  shift 2
  "$@" -q -o "$out/$file" 2> "$out/$file.log" || { cat "$out/$file.log" >&2; exit 1; }
  rm -f "$out/$file.log"
  rows="$rows<figure><img src=\"$file\" width=\"$((size / 2))\" alt=\"$(html_escape "$caption")\">
<figcaption>$(html_escape "$caption")<br><code>$(html_escape "$*") -o $file</code></figcaption></figure>
"
}

view="--eye 0.5,-0.5,0.05 --at 0.5,0.5,0.75 --up 0,0,1 --fov 70 --width $size --height $size"
# shellcheck disable=SC2086
figure adaptive-blocker.png "Blocker, adaptive from 4x4 (Cohen et al. 1988, sec. 4): the receiver above, the blocker's lower face below; elements split where the radiosity differs from a neighbour's by more than about 1% of the brightest reflected radiosity times the ratio of the element's side to a patch's (--subdivide-test error), down to 1/8 of a patch; 508 elements" \
  "$radiosity" render "$data/blocker.scene" --solver progressive --adaptive --mesh 4x4 \
  --subdivide-test error --subdivide-threshold 0.0102 --max-depth 3 --edges $view
# shellcheck disable=SC2086
figure adaptive-blocker-uniform.png "Blocker, uniform 16x16 (LU), for comparison: a larger area-weighted RMS error against a 32x32 reference than the adaptive mesh, with more elements (tests/papers/adaptive.sh)" \
  "$radiosity" render "$data/blocker.scene" --mesh 16x16 --edges $view
figure adaptive-cornell.png "Cornell box, adaptive from 3x3 per quad: look for small elements along the contact shadows of the boxes on the floor and where the walls meet the ceiling near the lamp" \
  "$radiosity" render "$data/cornell-box.scene" --solver progressive --adaptive --mesh 3x3 \
  --tolerance 1e-3 --edges --exposure 0.15 --width "$size" --height "$size"

version=$("$radiosity" --version | head -n 1)
cat > "$out/adaptive.html.tmp" <<EOF
<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>radiosity: adaptive subdivision (Cohen et al. 1988)</title>
<style>
body { font-family: sans-serif; margin: 1em 2em; }
figure { margin: 4px; width: $((size / 2))px; display: inline-block; vertical-align: top; }
figcaption { font-size: 85%; }
code { font-size: 80%; word-break: break-all; }
</style>
</head>
<body>
<h1>Adaptive subdivision: Cohen, Chen, Wallace &amp; Greenberg (1988), section 4</h1>
<p>The mesh given shoots as fixed patches; after each shot, elements whose
radiosity differs from a neighbour's by more than the threshold split into
four, and the new elements receive from every patch that has shot.  Element
edges are drawn in black.  Made by $(html_escape "$version").</p>
$rows</body>
</html>
EOF
mv "$out/adaptive.html.tmp" "$out/adaptive.html"
echo "figures: $out/adaptive.html"
