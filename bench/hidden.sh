#!/bin/sh
# hidden.sh -- `make bench`'s hidden-surface section: scenes of many small
# blockers between a lamp and a floor (bench/scenes.py), one thread, per
# accuracy mode: the fill's time, its pairs by route, the candidate
# blockers a blockable pair, the evaluations of the hidden part a partly
# hidden pair, the partly hidden pairs' share of the time, and the growth
# of the time and of the evaluations with the number of blockers (the
# slope of their logs against log blockers between the two largest
# sizes).  Prints figures; asserts nothing.
# Usage: bench/hidden.sh RADIOSITY
# BENCH_HIDDEN_SQUARES (default "4 6 10"): the N of the N x N squares;
# BENCH_HIDDEN_TORUS (default "60 250"): torus triangle counts asked of
# scenes.py (60 gives 90), two sizes so that each mode has a growth;
# BENCH_HIDDEN_SPLIT (default "6"): the closed Cornell box with each quad
# meshed N x N, and the same as N x N separate quads (as a View3D file
# lists elements), and the time of the second over the first;
# BENCH_HIDDEN_MODES (default "classic default reference");
# BENCH_HIDDEN_TIMEOUT (default 300): seconds before a run is given up;
# BENCH_VIEW3D: a View3D 3.2 program, built by the user from its public
# source (never part of this project), timed on the same elements written
# as a .vs3 file (scenes.py vs3; eps=1e-6), for the squares and the torus,
# with each mode's time over View3D's.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -e
rad=$1
here=$(dirname "$0")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
limit=${BENCH_HIDDEN_TIMEOUT:-300}
printf 'scene\tblockers\tmode\tseconds\tpairs_tested\tunblocked\tfully_hidden\tpartly_hidden\tvisibility_s\tms_per_partial\tcandidates_per_pair\tevals_per_partial\n'
run() { # NAME BLOCKERS SCENE
  for mode in ${BENCH_HIDDEN_MODES:-classic default reference}; do
    if timeout "$limit" "$rad" solve -q --threads 1 --accuracy "$mode" \
         --report "$tmp/r.json" -o "$tmp/i.png" "$3" 2> /dev/null; then
      awk -v name="$1" -v nb="$2" -v mode="$mode" '
        function num(key,   s) { s = $0; if (!match(s, "\"" key "\": [0-9.e+-]*")) return 0
          s = substr(s, RSTART + length(key) + 4, RLENGTH - length(key) - 4); return s + 0 }
        { t = num("form_factors") ; if (t > 0) ff = t
          if (index($0, "\"visibility\"")) { pt = num("pairs_tested"); pb = num("pairs_blockable")
            hid = num("pairs_blocked"); par = num("pairs_partial"); vs = num("seconds")
            cand = num("candidates"); ev = num("evaluations") } }
        END { printf "%s\t%s\t%s\t%.3f\t%d\t%d\t%d\t%d\t%.3f\t%.3f\t%.2f\t%.0f\n", name, nb, mode,
                ff, pt, pt - hid - par, hid, par, vs, (par > 0 ? 1000 * vs / par : 0),
                (pb > 0 ? cand / pb : 0), (par > 0 ? ev / par : 0) }' "$tmp/r.json" \
        | tee -a "$tmp/all"
    else
      printf '%s\t%s\t%s\tover %s s\n' "$1" "$2" "$mode" "$limit"
    fi
  done
}
view3d() { # NAME BLOCKERS SCENE: View3D's time on the same elements
  [ -n "${BENCH_VIEW3D-}" ] || return 0
  python3 "$here/scenes.py" vs3 "$3" > "$tmp/v.vs3"
  t0=$(date +%s.%N)
  if (cd "$tmp" && timeout "$limit" "$BENCH_VIEW3D" v.vs3 v.out > /dev/null 2>&1); then
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" -v n="$1" -v k="$2" 'BEGIN { printf "%s\t%s\tview3d\t%.3f\n", n, k, b - a }' \
      | tee -a "$tmp/v3d"
  else
    printf '%s\t%s\tview3d\tfailed or over %s s\n' "$1" "$2" "$limit"
  fi
}
for n in ${BENCH_HIDDEN_SQUARES-4 6 10}; do
  python3 "$here/scenes.py" squares "$n" > "$tmp/s.scene"
  run "squares-$n" $((n * n)) "$tmp/s.scene"
  view3d "squares-$n" $((n * n)) "$tmp/s.scene"
done
for t in ${BENCH_HIDDEN_TORUS-60 250}; do
  python3 "$here/scenes.py" torus "$t" > "$tmp/t.scene"
  nb=$(grep -c '^polygon' "$tmp/t.scene")
  run "torus-$nb" "$nb" "$tmp/t.scene"
  view3d "torus-$nb" "$nb" "$tmp/t.scene"
done
# each mode's time over View3D's on the same scene
[ -f "$tmp/v3d" ] && [ -f "$tmp/all" ] && awk -F '\t' '
  FNR == NR { v[$1] = $4; next }
  ($1 in v) && v[$1] > 0 { printf "%s, %s over View3D: %.1f\n", $1, $3, $4 / v[$1] }' \
  "$tmp/v3d" "$tmp/all"
for n in ${BENCH_HIDDEN_SPLIT-6}; do
  for how in meshed split; do
    python3 "$here/scenes.py" "$how" "$n" "$here/../data/cornell-box-closed.scene" > "$tmp/b.scene"
    run "box$how-$n" "$(grep -c '^quad' "$tmp/b.scene")" "$tmp/b.scene"
  done
done
# separate quads against meshed surfaces, per mode
[ -f "$tmp/all" ] && awk -F '\t' '
  $1 ~ /^boxmeshed-/ { n = substr($1, 11); m[n, $3] = $4 }
  $1 ~ /^boxsplit-/ { n = substr($1, 10); if (m[n, $3] > 0)
    printf "box as %s separate quads over meshed, %s: %.2f\n", $2, $3, $4 / m[n, $3] }' "$tmp/all"
# growth: log(t2 / t1) / log(n2 / n1) for each mode between its two
# largest finished scenes of one kind; and the same of the evaluations of
# the hidden part (partly hidden pairs times evaluations a pair), which
# do not depend on the machine's load as the time does
[ -f "$tmp/all" ] && awk -F '\t' '
  { split($1, k, "-"); key = k[1] " " $3; n[key]++; b[key, n[key]] = $2; s[key, n[key]] = $4
    e[key, n[key]] = $8 * $12 }
  END { for (key in n) if (n[key] >= 2) { i = n[key]; j = i - 1
          if (s[key, j] > 0 && b[key, i] != b[key, j]) {
            printf "growth %s: time ~ blockers^%.2f", key,
              log(s[key, i] / s[key, j]) / log(b[key, i] / b[key, j])
            if (e[key, j] > 0 && e[key, i] > 0)
              printf ", evaluations ~ blockers^%.2f",
                log(e[key, i] / e[key, j]) / log(b[key, i] / b[key, j])
            printf " (%s to %s)\n", b[key, j], b[key, i] } } }' \
  "$tmp/all" | sort
