#!/bin/sh
# bench.sh -- the fixed benchmarks behind `make bench`.  Prints figures; it
# asserts nothing (the machines are shared: timings are not tests).
# Usage: bench/bench.sh RADIOSITY LU_RATE DATADIR FF_RATE
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -e
rad=$1 lu=$2 data=$3 ff=$4
cube=$data/goral1984-cube.scene
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "== form-factor fill, cube 20x20 (2400 elements, 2,878,800 unordered pairs)"
echo "   (rad_ff_matrix only, ${BENCH_FF_REPEATS:-5} runs each, modes in turn: median and best)"
"$ff" "$cube" 20x20 ${BENCH_FF_REPEATS:-5}
echo
echo "== form-factor fill, cube 7x7 (294 elements, as shipped): the cost of default's error control"
"$ff" "$cube" 7x7 ${BENCH_FF_SMALL_REPEATS:-51}
echo
echo "== LU (dgetrf) against DGEMM, same run (GFLOP/s)"
"$lu" ${BENCH_LU_SIZES:-2000 4000}
echo
echo "== sweep of the cube (error against the reference 20x20 solution)"
"$rad" sweep -q --meshes 1,2,3,5,7,10,20 --solvers gauss,jacobi,gauss-seidel \
  --plot "${BENCH_PLOT:-sweep.png}" "$cube"
echo "(plot: ${BENCH_PLOT:-sweep.png})"
