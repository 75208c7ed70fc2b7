#!/bin/sh
# hemicube.sh -- the hemicube's error against resolution, 16 to 1024, and
# its time at 2,400 elements.  Called by bench.sh;
# prints figures, asserts nothing (tests/unit/hemicube/test_hemicube.c asserts the
# bounds at 16, 64 and 256).
# Usage: bench/hemicube.sh RADIOSITY DATADIR
#   BENCH_HC_RES     resolutions (default 16 32 64 128 256 512 1024)
#   BENCH_HC_MESHES  meshes of the cube's walls (default 1x1 8x8)
# The grey cube's per-surface factors from the floor (surface 0) to the
# ceiling (opposite, closed form 0.19982489569838746) and to a wall
# (adjacent, 0.20004377607540316; Howell C-11, C-14), by the hemicube,
# against those closed forms: the error falls with R to the centre rule's
# floor (each row from its element's centre), which falls with the mesh.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
set -e
rad=$1 data=$2
cube=$data/grey-cube.scene
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "   mesh  R      F opposite          error     F adjacent          error     seconds"
for mesh in ${BENCH_HC_MESHES:-1x1 8x8}; do
  for R in ${BENCH_HC_RES:-16 32 64 128 256 512 1024}; do
    t0=$(date +%s.%N)
    "$rad" formfactor -q --per-surface --mesh "$mesh" --form-factors-method hemicube \
      --resolution "$R" -o "$tmp/s.tsv" "$cube"
    t1=$(date +%s.%N)
    awk -F'\t' -v mesh="$mesh" -v R="$R" -v t0="$t0" -v t1="$t1" '
      function abs(x) { return x < 0 ? -x : x }
      $1 == 0 && $2 == 1 { o = $3 } $1 == 0 && $2 == 2 { a = $3 }
      END { printf "   %-5s %-5d  %.15f  %.2e  %.15f  %.2e  %.2f\n", mesh, R,
              o, abs(o - 0.19982489569838746), a, abs(a - 0.20004377607540316), t1 - t0 }' \
      "$tmp/s.tsv"
  done
done

echo
echo "   2,400 elements (the cube at 20x20), the whole matrix:"
for args in "--form-factors-method hemicube --resolution 64" "--accuracy default"; do
  t0=$(date +%s.%N)
  # shellcheck disable=SC2086
  "$rad" formfactor -q --mesh 20x20 $args -o "$tmp/F.npy" "$cube"
  t1=$(date +%s.%N)
  awk -v a="$args" -v t0="$t0" -v t1="$t1" 'BEGIN { printf "   %-50s %.2f s\n", a, t1 - t0 }'
done
