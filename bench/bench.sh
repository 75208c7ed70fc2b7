#!/bin/sh
# bench.sh -- the fixed benchmarks behind `make bench`.  Prints figures; it
# asserts nothing (the machines are shared: timings are not tests).
# Usage: bench/bench.sh RADIOSITY LU_RATE DATADIR FF_RATE SOLVE_RATE [RADIOSITY_MPI MPIRUN]
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -e
rad=$1 lu=$2 data=$3 ff=$4 sr=$5 rmpi=${6:-} mpirun=${7:-}
cube=$data/goral1984-cube.scene
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "== form-factor fill, cube 20x20 (2400 elements, 2,878,800 unordered pairs)"
echo "   (rad_ff_matrix only, ${BENCH_FF_REPEATS:-5} runs each, modes in turn: median and best)"
"$ff" "$cube" 20x20 ${BENCH_FF_REPEATS:-5}
echo
# The fill rate of each instruction-set clone of the kernels:
# ff_rate linked with ffgauss.c and ffcontour.c compiled for one -march
# (RAD_ONE_ISA, src/util/vecmath.h); the program above runs the clone the CPU's
# resolver picks.  Each runs only where the CPU has its instructions.
has_flags() { for f in "$@"; do grep -q -w "$f" /proc/cpuinfo 2> /dev/null || return 1; done; }
if [ -x "${ff}_base" ]; then
  echo "== form-factor fill per instruction-set clone, cube 20x20, default accuracy,"
  echo "   ${BENCH_ISA_REPEATS:-5} runs each (base: x86-64; v3: AVX2/FMA, the shipped clone; v4: AVX-512)"
  for isa in base v3 v4; do
    case $isa in
      v3) has_flags avx2 fma || { echo "-- $isa: this CPU lacks AVX2/FMA, skipped"; continue; } ;;
      v4) has_flags avx512f avx512bw avx512dq avx512vl || { echo "-- $isa: this CPU lacks AVX-512, skipped"; continue; } ;;
    esac
    echo "-- $isa"
    "${ff}_$isa" "$cube" 20x20 ${BENCH_ISA_REPEATS:-5} default | grep -v '^#'
  done
  echo
fi
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
echo "== animate: the Cornell moving box over 10 frames (George et al. 1990), one run:"
echo "   each converged frame (tolerance 1e-12) against a fresh solve of the same frame"
"$rad" animate -q --reference --report "$tmp/anim.json" \
  "$data/cornell-moving-box.scene" "$data/cornell-moving-box.changes"
awk '/"frame": [1-9]/ {
       match($0, /"t_total": [0-9.e+-]*/); t = substr($0, RSTART + 11, RLENGTH - 11)
       match($0, /"t_reference": [0-9.e+-]*/); f = substr($0, RSTART + 15, RLENGTH - 15)
       match($0, /"pairs_share": [0-9.e+-]*/); p = substr($0, RSTART + 15, RLENGTH - 15)
       match($0, /"error_eq7": [0-9.e+-]*/); e = substr($0, RSTART + 13, RLENGTH - 13)
       match($0, /"t_changed": [0-9.e+-]*/); c = substr($0, RSTART + 13, RLENGTH - 13)
       n++; r[n] = t / f; q[n] = c / f
       printf "   frame %2d: %.3f s, fresh solve %.3f s, ratio %.3f (changed pairs alone %.3f), pairs recomputed %.1f%%, eq. 7 error %.2g\n", n, t, f, t / f, c / f, 100 * p, e }
     function median(v, n,   i, j, x) {
           for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (v[j] < v[i]) { x = v[i]; v[i] = v[j]; v[j] = x }
           return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2 }
     END { printf "   median ratio %.3f (the target is at most 0.25)\n", median(r, n)
           printf "   median ratio of the changed pairs alone %.3f (computed as a fresh solve\n", median(q, n)
           printf "   computes them, which a frame equal to a fresh solve must do too)\n" }' "$tmp/anim.json"

echo
echo "== progressive refinement without a stored matrix (--matrix none --patches ${BENCH_MFREE_PATCHES:-4x4}),"
echo "   cube to unshot power < ${BENCH_MFREE_TOL:-1e-3} of the emitted (BENCH_MFREE=0 skips; ~1-3 min)"
if [ "${BENCH_MFREE:-1}" = 1 ]; then
  sh "$(dirname "$0")/matrixfree.sh" "$rad" "$data"
fi

echo
echo "== the hemicube (Cohen & Greenberg 1985) against resolution (BENCH_HC=0 skips; ~2-5 min)"
if [ "${BENCH_HC:-1}" = 1 ]; then
  sh "$(dirname "$0")/hemicube.sh" "$rad" "$data"
fi

echo
echo "== the live viewer (radiosity view) on the moving Cornell box, from an HTTP client,"
echo "   and on the Cornell box in headless Chromium (BENCH_VIEW=0 skips; ~2 min)"
if [ "${BENCH_VIEW:-1}" = 1 ] && "$rad" view --help > /dev/null 2>&1 &&
   ! "$rad" view --method magic x 2>&1 | grep -q "built without"; then
  python3 "$(dirname "$0")/view.py" "$rad" "$data/view" \
    "$data/cornell-moving-box.scene" box 3 || echo "   (failed)"
  work=$(mktemp -d)
  python3 "$(dirname "$0")/view_browser.py" "$rad" "$data/view" \
    "$data/cornell-box.scene" "$work" 3 || echo "   (failed)"
  rm -rf "$work"
fi

echo
echo "== hidden surfaces: many small blockers between a lamp and a floor (bench/scenes.py),"
echo "   one thread, per mode (BENCH_HIDDEN=0 skips; bench/hidden.sh says the knobs)"
if [ "${BENCH_HIDDEN:-1}" = 1 ]; then
  sh "$(dirname "$0")/hidden.sh" "$rad"
fi

# Occluded pairs: the open Cornell box at 6x6 (1260 elements), default's
# fill and reference's on one thread, and every default entry above 1e-6
# against reference (the targets: within 1e-6 relative, default at most
# 1.5 times its time before, reference at most 3 times default's).  About
# half a minute; BENCH_CORNELL=0 skips.
if [ "${BENCH_CORNELL:-1}" = 1 ] && command -v /usr/bin/time > /dev/null; then
  box=$data/cornell-box.scene
  echo
  echo "== Cornell box 6x6 (1260 elements), one thread: default against reference"
  /usr/bin/time -f '%U' -o "$tmp/cb_d.t" "$rad" formfactor -q --threads 1 --mesh 6x6 "$box" \
    -o "$tmp/cb_d.npy" 2> /dev/null || true
  /usr/bin/time -f '%U' -o "$tmp/cb_r.t" "$rad" compare -q --threads 1 --mesh 6x6 --floor 1e-6 \
    --report "$tmp/cb.json" "$box" "$tmp/cb_d.npy" 2> /dev/null || true
  echo "   default fill $(tail -n 1 "$tmp/cb_d.t") s user; reference fill and comparison $(tail -n 1 "$tmp/cb_r.t") s user"
  grep -E '"(max|rms)_error"|"max_error_pair"' "$tmp/cb.json" 2> /dev/null | sed 's/^ */   /' || true
fi

# The solve phase of every solver on the 15,000-element cube.
# Long (form factors ~9 s per run, gauss ~80 s, 3.6 GB): only with
# BENCH_CUBE50=1; BENCH_CUBE50_SOLVERS and BENCH_CUBE50_MESH choose.
if [ "${BENCH_CUBE50:-0}" = 1 ]; then
  mesh=${BENCH_CUBE50_MESH:-50x50}
  echo
  echo "== solve phase per solver on one F, cube $mesh, ${BENCH_CUBE50_REPEATS:-3} rounds"
  "$sr" "$cube" "$mesh" ${BENCH_CUBE50_REPEATS:-3}
  echo
  echo "== radiosity solve per solver, cube $mesh, default accuracy (s; peak memory)"
  printf 'solver\tsolve_s\tform_factors_s\tpeak_MiB\testimate_MiB\tsummary\n'
  for s in ${BENCH_CUBE50_SOLVERS:-gauss cholesky jacobi gauss-seidel cg}; do
    if command -v /usr/bin/time > /dev/null; then
      /usr/bin/time -f 'peak_kb %M' "$rad" solve --mesh "$mesh" --solver "$s" \
        --elements "$tmp/e_$s.tsv" --report "$tmp/r_$s.json" "$cube" 2> "$tmp/log_$s" || true
    else
      "$rad" solve --mesh "$mesh" --solver "$s" --elements "$tmp/e_$s.tsv" \
        --report "$tmp/r_$s.json" "$cube" 2> "$tmp/log_$s" || true
    fi
    est=$(sed -n 's/.*"memory_bytes": *\([0-9.e+]*\).*/\1/p' "$tmp/r_$s.json" 2>/dev/null)
    awk -v s="$s" -v est="${est:-0}" '/form factors/ { for (k = 1; k <= NF; k++) { if ($k == "factors") ff = $(k + 1);
        if ($k == "solve") sv = $(k + 1) } }
      /^radiosity: '"$s"',/ { sub(/^radiosity: /, ""); line = $0 }
      /^peak_kb/ { mem = $2 / 1024 }
      END { printf "%s\t%s\t%s\t%.0f\t%.0f\t%s\n", s, sv, ff, mem, est / 1048576, line }' "$tmp/log_$s"
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

# The largest solve: 50,784 elements (the cube at 92x92), F alone (19.7
# GiB) with conjugate gradients; the peak resident memory against the
# estimate checked before meshing.  Needs about 20 GiB free and 10
# minutes: only with BENCH_LARGEST=1 (BENCH_LARGEST_MESH, _SOLVER choose).
if [ "${BENCH_LARGEST:-0}" = 1 ] && command -v /usr/bin/time > /dev/null; then
  mesh=${BENCH_LARGEST_MESH:-92x92} solver=${BENCH_LARGEST_SOLVER:-cg}
  echo
  echo "== the largest solve: cube $mesh, --solver $solver"
  /usr/bin/time -f 'peak_kb %M wall %e' "$rad" solve --mesh "$mesh" --solver "$solver" \
    --report "$tmp/largest.json" --elements "$tmp/largest.npy" "$cube" 2> "$tmp/largest.log" || true
  grep '^radiosity: ' "$tmp/largest.log" || true
  est=$(sed -n 's/.*"memory_bytes": *\([0-9.e+]*\).*/\1/p' "$tmp/largest.json" 2>/dev/null)
  awk -v est="${est:-0}" '/^peak_kb/ { printf "peak %.0f MiB, estimate %.0f MiB (ratio %.4f), wall %s s\n",
      $2 / 1024, est / 1048576, est > 0 ? $2 * 1024 / est : 0, $4 }' "$tmp/largest.log"
fi

# radiosity-mpi: peak memory per process against the serial run, and wall
# time, on one machine (processes oversubscribe it beyond its cores, so
# the times say little about a cluster; the memory is the point).
if [ -n "$rmpi" ] && [ -x "$rmpi" ] && [ -n "$mpirun" ] && command -v /usr/bin/time > /dev/null; then
  mesh=${BENCH_MPI_MESH:-30x30}
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  echo
  echo "== radiosity-mpi solve, cube $mesh, one thread per process: peak memory per process"
  printf 'processes\tpeak_MiB_max\tpeak_MiB_min\twall_s\n'
  /usr/bin/time -f 'peak_kb %M wall %e' "$rad" solve -q --threads 1 --mesh "$mesh" \
    --elements "$tmp/mpi_s.tsv" "$cube" 2> "$tmp/mpi_s.log" || true
  awk '/^peak_kb/ { printf "serial\t%.0f\t%.0f\t%s\n", $2 / 1024, $2 / 1024, $4 }' "$tmp/mpi_s.log"
  for np in ${BENCH_MPI_PROCESSES:-1 2 4}; do
    "$mpirun" -np "$np" /usr/bin/time -f 'peak_kb %M wall %e' "$rmpi" solve -q --threads 1 \
      --mesh "$mesh" --elements "$tmp/mpi_$np.tsv" "$cube" 2> "$tmp/mpi_$np.log" || true
    awk -v np="$np" '/^peak_kb/ { m = $2 / 1024; if (m > hi) hi = m; if (lo == "" || m < lo) lo = m
        if ($4 > w) w = $4 } END { printf "%s\t%.0f\t%.0f\t%s\n", np, hi, lo, w }' "$tmp/mpi_$np.log"
  done
fi
