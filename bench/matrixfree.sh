#!/bin/sh
# matrixfree.sh -- progressive refinement without a stored matrix at
# 10^4..10^5 elements: peak resident memory against N with a
# least-squares line, seconds per shot, and pair integrals per second
# inside the shots.  Called by bench.sh; prints figures, asserts nothing
# (timings on a shared machine are not tests).
# Usage: bench/matrixfree.sh RADIOSITY DATADIR
#   BENCH_MFREE_MESHES   quad meshes of the cube (default 60x60 100x100
#                        130x130: 21,600, 60,000 and 101,400 elements)
#   BENCH_MFREE_PATCHES  the shooting patch grid per surface (default 4x4)
#   BENCH_MFREE_TOL      unshot power / emitted power at the stop (1e-3)
#   BENCH_MFREE_THREADS  --threads (default: all cores; columns of at
#                        least 16384 entries are split among them)
# The scene is the 1984 cube: a convex enclosure, so no pair needs
# visibility and the pair rate is the kernel's alone.  Peak memory is
# /usr/bin/time's maximum resident set size; CPU seconds are user + system
# of the whole run (mesh and output included: the rate per CPU second is a
# lower bound).  The dense matrix at 101,400 elements would be 82 GB
# (8 N^2) and its solve 164 GB (rad_solve_bytes).  OMP_WAIT_POLICY is
# passive unless set: threads waiting at a shot's barrier sleep instead of
# spinning, so the CPU seconds count work (on a loaded machine spinning
# doubled them).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -e
rad=$1 data=$2
cube=$data/goral1984-cube.scene
patches=${BENCH_MFREE_PATCHES:-4x4}
tol=${BENCH_MFREE_TOL:-1e-3}
OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
export OMP_WAIT_POLICY
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ! command -v /usr/bin/time > /dev/null 2>&1; then
  echo "(no /usr/bin/time: install the Debian package time; skipped)"
  exit 0
fi
printf 'mesh\telements\tshots\tstatus\tsolve_s\tcpu_s\tpeak_MiB\tpairs\tpairs_per_s\tpairs_per_cpu_s\ts_per_shot\tcpu_s_per_shot\n'
for mesh in ${BENCH_MFREE_MESHES:-60x60 100x100 130x130}; do
  /usr/bin/time -f 'peak_kb %M cpu %U %S' "$rad" solve --mesh "$mesh" --solver progressive \
    ${BENCH_MFREE_THREADS:+--threads "$BENCH_MFREE_THREADS"} \
    --patches "$patches" --matrix none --tolerance "$tol" --report "$tmp/r.json" \
    --elements "$tmp/e.tsv" "$cube" > "$tmp/log" 2>&1 || true
  awk -v mesh="$mesh" '
    /matrix none/ { for (k = 1; k <= NF; k++) { if ($k == "elements,") n = $(k - 1)
        if ($k == "solve") t = $(k + 1); if ($k == "pair") p = $(k - 1) } }
    /shooting steps/ { for (k = 1; k <= NF; k++) if ($k == "shooting") s = $(k - 1) }
    /^peak_kb/ { mem = $2 / 1024; cpu = $4 + $5 }
    END { st = (s > 0) ? "ok" : "failed"
      printf "%s\t%s\t%d\t%s\t%.3g\t%.3g\t%.1f\t%.0f\t%.3g\t%.3g\t%.3g\t%.3g\n", mesh, n, s, st, t, cpu,
        mem, p, (t > 0 ? p / t : 0), (cpu > 0 ? p / cpu : 0), (s > 0 ? t / s : 0),
        (s > 0 ? cpu / s : 0) }' \
    "$tmp/log" | tee -a "$tmp/table"
  grep -q 'matrix none' "$tmp/log" || sed 's/^/# /' "$tmp/log"
done
# peak memory = a + b N, least squares over the sizes run
awk -F'\t' '$4 == "ok" { n++; x[n] = $2; y[n] = $7 * 1048576 }
  END { if (n < 2) { print "(fewer than two sizes: no fit)"; exit }
    for (k = 1; k <= n; k++) { sx += x[k]; sy += y[k] }
    mx = sx / n; my = sy / n
    for (k = 1; k <= n; k++) { sxx += (x[k] - mx) ^ 2; sxy += (x[k] - mx) * (y[k] - my); syy += (y[k] - my) ^ 2 }
    b = sxy / sxx; a = my - b * mx; r2 = (syy > 0 ? sxy * sxy / (sxx * syy) : 1)
    printf "peak RSS = %.1f MiB + %.0f bytes x N (least squares over %d sizes, R^2 = %.5f)\n", a / 1048576, b, n, r2
    printf "(the dense path: 16 N^2 bytes, %.3g GB at N = %d)\n", 16 * x[n] * x[n] / 1e9, x[n] }' "$tmp/table"
# element shooting (no patches): element-element pairs, as the dense fill
# integrates them; a fixed number of shots (the run stops short of
# convergence on purpose, exit 1, its report still written)
mesh=${BENCH_MFREE_ELEMENT_MESH:-60x60} shots=${BENCH_MFREE_ELEMENT_SHOTS:-100}
/usr/bin/time -f 'peak_kb %M cpu %U %S' "$rad" solve -q --mesh "$mesh" --solver progressive \
  ${BENCH_MFREE_THREADS:+--threads "$BENCH_MFREE_THREADS"} \
  --matrix none --max-iterations "$shots" --report "$tmp/el.json" "$cube" > "$tmp/el.log" 2>&1 || true
awk -v mesh="$mesh" -v shots="$shots" '
  /"elements":/ { gsub(/[^0-9]/, "", $2); n = $2 }
  /"solve":/ { for (k = 1; k <= NF; k++) if ($k ~ /"solve":/) { t = $(k + 1); gsub(/[,}]/, "", t) } }
  /^peak_kb/ { cpu = $4 + $5 }
  END { p = shots * (n - 1)
    printf "element shooting, %s (%d elements), %d shots: %.3g pairs/s, %.3g pairs per CPU second, %.3g s per shot\n",
      mesh, n, shots, (t > 0 ? p / t : 0), (cpu > 0 ? p / cpu : 0), (shots > 0 ? t / shots : 0) }' \
  "$tmp/el.json" "$tmp/el.log"

# the same pair integrals in the dense fill and in matrix-free shots, on
# one core, back to back (user CPU seconds: the dense run's output and
# the page faults of its matrix are system time): the target is the
# dense path's rate
mesh=${BENCH_MFREE_PAIR_MESH:-30x30} shots=${BENCH_MFREE_PAIR_SHOTS:-2000}
for round in 1 2 3; do
  /usr/bin/time -f 'dense_user %U' "$rad" formfactor -q --threads 1 --mesh "$mesh" \
    -o "$tmp/F.npy" "$cube" 2>> "$tmp/pair.log" || true
  rm -f "$tmp/F.npy"
  /usr/bin/time -f 'free_user %U' "$rad" solve -q --threads 1 --mesh "$mesh" --solver progressive \
    --matrix none --max-iterations "$shots" --report "$tmp/pr.json" "$cube" 2>> "$tmp/pair.log" || true
done
n=$(sed -n 's/.*"elements": *\([0-9]*\).*/\1/p' "$tmp/pr.json" | head -n 1)
awk -v n="$n" -v shots="$shots" -v mesh="$mesh" '
  function med(x, m,   i, j, t) { for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
    return m % 2 ? x[(m + 1) / 2] : (x[m / 2] + x[m / 2 + 1]) / 2 }
  /^dense_user/ { d[++nd] = $2 } /^free_user/ { f[++nf] = $2 }
  END { if (nd == 0 || nf == 0 || n == "") { print "(pair rates: a run failed)"; exit }
    dr = n * (n - 1) / 2 / med(d, nd); fr = shots * (n - 1) / med(f, nf)
    printf "pair rate on one core, cube %s (%d elements), medians of %d: dense fill %.3g pairs per CPU second, matrix-free shots %.3g (ratio %.2f)\n",
      mesh, n, nd, dr, fr, fr / dr }' "$tmp/pair.log"
