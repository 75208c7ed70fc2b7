#!/bin/sh
# figures-view.sh -- the race of Cohen et al. 1988 (their figures 2-5 and
# 8) as the live viewer shows it: `radiosity view` on the Cornell box,
# each method stepped to 1, 2, 24 and 100 steps through the server's
# requests, and the page's still (?still=1) taken by headless Chromium.
# Prints the section of figures.sh's index.html (a paragraph saying why
# when the viewer or a browser is missing).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: scripts/figures-view.sh RADIOSITY DATADIR OUTDIR
set -eu

. "$(dirname "$0")/figlib.sh"
fig_args "$@"
radiosity=$1
box=$2/cornell-box.scene
out=$3
assets=$2/view
browser=$(command -v chromium || command -v chromium-browser || true)
if "$radiosity" view --method magic x 2>&1 | grep -q "built without" ||
   [ -z "$browser" ] || ! command -v curl > /dev/null 2>&1; then
  echo "<h2>The live viewer</h2><p>Not drawn: this build has no viewer (libmicrohttpd), or"
  echo "chromium or curl is missing (scripts/install-deps.sh installs them).</p>"
  exit 0
fi
mkdir -p "$out"
tmp=$(mktemp -d)
"$radiosity" view -q --paused --assets "$assets" "$box" > "$tmp/url" 2> "$tmp/err" &
pid=$!
trap 'kill $pid 2> /dev/null || true; rm -rf "$tmp"' EXIT
i=0
while [ ! -s "$tmp/url" ] && [ $i -lt 600 ] && kill -0 $pid 2> /dev/null; do
  sleep 0.5
  i=$((i + 1))
done
url=$(head -n 1 "$tmp/url")
[ -n "$url" ] || { echo "$0: the viewer did not start: $(cat "$tmp/err")" >&2; exit 1; }
api() { curl -sf -X POST "${url}api/control?$1" > /dev/null; }
# "STEP BUSY" of the state ({..."busy":false,"step":40,...})
step_of() { curl -sf "${url}api/state" | sed -n 's/.*"busy":\([a-z]*\),"step":\([0-9]*\).*/\2 \1/p'; }
rowsv=
for m in gathering shooting sorted sorted_ambient; do
  cells=
  api "action=reset&method=$m"
  done_steps=0
  for k in 1 2 24 100; do
    api "action=step&steps=$((k - done_steps))"
    done_steps=$k
    i=0
    until [ "$(step_of)" = "$k false" ] || [ $i -gt 600 ]; do sleep 0.1; i=$((i + 1)); done
    name=view-$m-$k
    "$browser" --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
      --force-device-scale-factor=1 --force-color-profile=srgb --window-size=512,512 \
      --hide-scrollbars --virtual-time-budget=10000 --user-data-dir="$tmp/chrome" \
      --screenshot="$out/$name.png" "${url}?still=1" > /dev/null 2>&1
    cells="$cells<td><figure><img src=\"$name.png\" width=\"192\" height=\"192\" alt=\"$m, step $k\"><figcaption>$m, step $k</figcaption></figure></td>"
  done
  rowsv="$rowsv<tr>$cells</tr>"
done
api "action=stop"
wait $pid || true
cat <<EOF
<h2>The race as the live viewer shows it</h2>
<p>Cohen et al. 1988, figures 2-5 and 8, taken from the page of
<code>radiosity view</code>: the Cornell box, its elements shooting (the paper's
figures shoot from patches: <code>radiosity progress --patches</code>), each method stepped through the server's requests
(<code>POST /api/control?action=step&amp;steps=K</code>) to 1, 2, 24 and 100 steps,
and the page's still drawn by headless Chromium in WebGL (<code>?still=1</code>:
the renderer's camera, exposure and sRGB rules; tests/commands/viewer.sh checks such
a still against <code>radiosity progress</code>'s picture).  Rows: gathering
(Gauss-Seidel, one element a step), shooting in file order, sorted shooting, and
sorted shooting shown with the ambient term.  Gathering has lit a handful of
elements after 100 steps; sorted shooting with the ambient term looks finished after
24.  <code>$(html_escape "radiosity view $box")</code></p>
<table>$rowsv</table>
EOF
