#!/bin/sh
# bench.sh -- the fixed benchmarks behind `make bench`.  Prints figures; it
# asserts nothing (the machines are shared: timings are not tests).
# Usage: bench/bench.sh RADIOSITY LU_RATE DATADIR FF_RATE SOLVE_RATE
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -e
rad=$1 lu=$2 data=$3 ff=$4 sr=$5
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
echo "== LU (dgetrf) and Cholesky (dpotrf) against DGEMM, same run (GFLOP/s)"
"$lu" ${BENCH_LU_SIZES:-2000 4000}
echo
echo "== solve phase per solver on one F, cube 20x20 (2400 elements), ${BENCH_SOLVE_REPEATS:-5} rounds"
"$sr" "$cube" 20x20 ${BENCH_SOLVE_REPEATS:-5}
echo
echo "== sweep of the cube (error against the reference 20x20 solution)"
"$rad" sweep -q --meshes 1,2,3,5,7,10,20 --solvers gauss,jacobi,gauss-seidel \
  --plot "${BENCH_PLOT:-sweep.png}" "$cube"
echo "(plot: ${BENCH_PLOT:-sweep.png})"

echo
echo "== progressive refinement without a stored matrix (--matrix none --patches ${BENCH_MFREE_PATCHES:-4x4}),"
echo "   cube to unshot power < ${BENCH_MFREE_TOL:-1e-3} of the emitted (BENCH_MFREE=0 skips; ~1-3 min)"
if [ "${BENCH_MFREE:-1}" = 1 ]; then
  sh "$(dirname "$0")/matrixfree.sh" "$rad" "$data"
fi

# The solve phase of every solver on the 15,000-element cube (issue 18).
# Long (form factors ~9 s per run, gauss ~80 s, 3.6 GB): only with
# BENCH_CUBE50=1; BENCH_CUBE50_SOLVERS and BENCH_CUBE50_MESH choose.
if [ "${BENCH_CUBE50:-0}" = 1 ]; then
  mesh=${BENCH_CUBE50_MESH:-50x50}
  echo
  echo "== solve phase per solver on one F, cube $mesh, ${BENCH_CUBE50_REPEATS:-3} rounds"
  "$sr" "$cube" "$mesh" ${BENCH_CUBE50_REPEATS:-3}
  echo
  echo "== radiosity solve per solver, cube $mesh, default accuracy (s; peak memory)"
  printf 'solver\tsolve_s\tform_factors_s\tpeak_MiB\tsummary\n'
  for s in ${BENCH_CUBE50_SOLVERS:-gauss cholesky jacobi gauss-seidel cg}; do
    if command -v /usr/bin/time > /dev/null; then
      /usr/bin/time -f 'peak_kb %M' "$rad" solve --mesh "$mesh" --solver "$s" \
        --elements "$tmp/e_$s.tsv" "$cube" 2> "$tmp/log_$s" || true
    else
      "$rad" solve --mesh "$mesh" --solver "$s" --elements "$tmp/e_$s.tsv" "$cube" 2> "$tmp/log_$s" || true
    fi
    awk -v s="$s" '/form factors/ { for (k = 1; k <= NF; k++) { if ($k == "factors") ff = $(k + 1);
        if ($k == "solve") sv = $(k + 1) } }
      /^radiosity: '"$s"',/ { sub(/^radiosity: /, ""); line = $0 }
      /^peak_kb/ { mem = $2 / 1024 }
      END { printf "%s\t%s\t%s\t%.0f\t%s\n", s, sv, ff, mem, line }' "$tmp/log_$s"
  done
  # agreement with gauss: max |B - B_gauss| / max |B_gauss| over r g b
  if [ -f "$tmp/e_gauss.tsv" ]; then
    for s in ${BENCH_CUBE50_SOLVERS:-gauss cholesky jacobi gauss-seidel cg}; do
      [ "$s" = gauss ] && continue
      paste "$tmp/e_gauss.tsv" "$tmp/e_$s.tsv" | awk -F'\t' -v s="$s" '
        NR == 1 { for (k = 1; k <= NF / 2; k++) c[$k] = k; w = NF / 2; next }
        { for (b = 0; b < 3; b++) { k = c[b == 0 ? "r" : b == 1 ? "g" : "b"];
            d = $k - $(k + w); if (d < 0) d = -d; if (d > dm) dm = d;
            v = $k < 0 ? -$k : $k; if (v > vm) vm = v } }
        END { printf "%s agrees with gauss to %.3g relative\n", s, dm / vm }'
    done
  fi
fi
