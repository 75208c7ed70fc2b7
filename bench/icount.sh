#!/bin/sh
# icount.sh -- `make bench-check`: the instructions of fixed form-factor
# fills, counted by valgrind (callgrind, only inside rad_ff_matrix), against
# the counts recorded in bench/icount.baseline.  Counts do not move with
# the machine's load, so a few percent is a real change: the check fails
# when any count grows more than BENCH_ICOUNT_SLACK percent (default 3)
# above its baseline.  The baseline changes only by a commit that says why
# (`bench/icount.sh RADIOSITY DATADIR BASELINE --write` prints a new one).
# Usage: bench/icount.sh RADIOSITY DATADIR BASELINE [--write]
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -u
rad=$1 data=$2 base=$3 write=${4:-}
here=$(dirname "$0")
slack=${BENCH_ICOUNT_SLACK:-3}
command -v valgrind > /dev/null || { echo "icount: valgrind is not installed (scripts/install-deps.sh installs it)"; exit 1; }
# The counts are of the kernels' x86-64-v3 clone (AVX2 and FMA), which the
# CPU's resolver picks where it can (src/util/vecmath.h); elsewhere other
# code runs and the baseline does not apply.
grep -q -w avx2 /proc/cpuinfo 2> /dev/null && grep -q -w fma /proc/cpuinfo 2> /dev/null ||
  { echo "icount: this CPU lacks AVX2/FMA: the baseline (x86-64-v3 clone) does not apply; skipped"; exit 0; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 "$here/scenes.py" squares 4 > "$tmp/squares.scene" || exit 1
count() { # SCENE MESH MODE
  valgrind --tool=callgrind --callgrind-out-file=/dev/null --collect-atstart=no \
    --toggle-collect=rad_ff_matrix "$rad" solve -q --threads 1 --accuracy "$3" $2 \
    -o "$tmp/i.png" "$1" 2>&1 | sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'
}
fail=0
{
  for mode in classic default reference; do
    echo "cube-10x10 $mode $(count "$data/goral1984-cube.scene" "--mesh 10x10" "$mode")"
    echo "squares-4 $mode $(count "$tmp/squares.scene" "" "$mode")"
  done
} > "$tmp/now"
if [ "$write" = --write ]; then
  echo "# fill counts (instructions inside rad_ff_matrix, valgrind callgrind):"
  echo "# the 1984 cube at --mesh 10x10 and bench/scenes.py squares 4, one thread"
  cat "$tmp/now"
  exit 0
fi
printf 'fill\tmode\tbaseline\tnow\tchange\n'
while read -r name mode n; do
  b=$(awk -v k="$name" -v m="$mode" '$1 == k && $2 == m { print $3 }' "$base")
  if [ -z "$n" ] || [ -z "$b" ]; then
    printf '%s\t%s\t%s\t%s\tno count\n' "$name" "$mode" "${b:--}" "${n:--}"
    fail=1
    continue
  fi
  awk -v k="$name" -v m="$mode" -v b="$b" -v n="$n" -v s="$slack" 'BEGIN {
    c = 100 * (n - b) / b; over = c > s ? "  (over +" s "%)" : ""
    printf "%s\t%s\t%.0f\t%.0f\t%+.2f%%%s\n", k, m, b, n, c, over
    exit c > s }' || fail=1
done < "$tmp/now"
[ $fail = 0 ] && echo "icount: every fill within +$slack% of its baseline" ||
  echo "icount: a fill grew beyond +$slack% of its baseline (or was not counted)"
exit $fail
