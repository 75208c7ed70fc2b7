#!/bin/sh
# bench.sh -- the fixed benchmarks behind `make bench`.  Prints figures; it
# asserts nothing (the machines are shared: timings are not tests).
# Usage: bench/bench.sh RADIOSITY LU_RATE DATADIR
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -e
rad=$1 lu=$2 data=$3
cube=$data/goral1984-cube.scene
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "== form-factor fill, cube 20x20 (2400 elements, 2,878,800 unordered pairs)"
printf 'threads\taccuracy\tpairs_per_second\tseconds\trow_sum_min\trow_sum_max\n'
for t in 1 2; do
  for acc in classic default reference; do
    OMP_NUM_THREADS=$t "$rad" solve -q --mesh 20x20 --accuracy $acc --report "$tmp/r.json" "$cube"
    awk -v t=$t -v a=$acc -F': ' '
      /"form_factor_pairs_per_second"/ { r = $2 } /"form_factors"/ { }
      /"row_sum_min"/ { lo = $2 } /"row_sum_max"/ { hi = $2 }
      /"seconds"/ { match($0, /"form_factors": [0-9.e+-]+/); s = substr($0, RSTART + 16, RLENGTH - 16) }
      END { gsub(",", "", r); gsub(",", "", lo); gsub(",", "", hi); printf "%s\t%s\t%.3g\t%s\t%s\t%s\n", t, a, r, s, lo, hi }' "$tmp/r.json"
  done
done
echo
echo "== LU (dgetrf) against DGEMM, same run (GFLOP/s)"
"$lu" ${BENCH_LU_SIZES:-2000 4000}
echo
echo "== sweep of the cube (error against the reference 20x20 solution)"
"$rad" sweep -q --meshes 1,2,3,5,7,10,20 --solvers gauss,jacobi,gauss-seidel \
  --plot "${BENCH_PLOT:-sweep.png}" "$cube"
echo "(plot: ${BENCH_PLOT:-sweep.png})"
