#!/bin/sh
# mpi.sh -- radiosity-mpi against radiosity solve.  Copyright (C) 2026 The
# radiosity authors.  GPLv3+, see COPYING.
#
# The distributed solve fills its blocks of F to the same doubles as the
# dense fill (ffblock.c), so --form-factors must be byte-identical to the
# serial program's.  B then differs only by the factorisations' round-off:
# both are backward stable, so the difference is bounded by about
# cond(I - rho F) n eps (Higham 2002, thm. 9.5 and 10.4) -- rcond is 0.6
# for the cube and above 0.1 for the Cornell box at these meshes, n is a
# few hundred, so 1e-12 relative leaves a margin of 100.  P = 1, 2, 3
# and 4 cover the 1 x 1, 1 x 2, 1 x 3 and 2 x 2 process grids; 3 and 4
# run oversubscribed on a two-core machine.
. "${top_srcdir:-.}/tests/lib.sh"

if [ -z "${RADIOSITY_MPI:-}" ] || [ ! -x "$RADIOSITY_MPI" ] || [ -z "${MPIRUN:-}" ]; then
  echo "1..0 # SKIP radiosity-mpi not built (configure found no MPI or ScaLAPACK)"
  exit 0
fi
# Open MPI refuses to run as root (CI runs as root) unless told; this
# test says so for its own runs only.
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_ALLOW_RUN_AS_ROOT OMPI_ALLOW_RUN_AS_ROOT_CONFIRM OMPI_MCA_rmaps_base_oversubscribe \
  OMPI_MCA_btl_vader_single_copy_mechanism
# Under make check-sanitize: keep Open MPI's and PMIx's components loaded
# and unwind every allocation fully, so that LeakSanitizer attributes the
# memory they keep to their libraries (tests/lsan.supp), not to an
# unknown module.
if [ -n "${RADIOSITY_SANITIZE:-}" ]; then
  OMPI_MCA_mca_base_component_disable_dlclose=1 PMIX_MCA_mca_base_component_disable_dlclose=1
  ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}fast_unwind_on_malloc=0"
  export OMPI_MCA_mca_base_component_disable_dlclose PMIX_MCA_mca_base_component_disable_dlclose \
    ASAN_OPTIONS
fi
mpi() { # mpi P ARGS...: radiosity-mpi on P processes, one thread each
  np=$1; shift
  "$MPIRUN" -np "$np" "$RADIOSITY_MPI" "$@"
}

# max relative difference of the r g b columns of two element tables
maxrel() {
  awk -F '\t' 'FNR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
    FNR == NR { a[FNR] = $c["r"] " " $c["g"] " " $c["b"]; n++; next }
    { split(a[FNR], x, " "); m[1] = $c["r"]; m[2] = $c["g"]; m[3] = $c["b"]; rows++
      for (k = 1; k <= 3; k++) { d = x[k] - m[k]; if (d < 0) d = -d
        s = m[k] < 0 ? -m[k] : m[k]; if (s > 0 && d / s > worst) worst = d / s
        if (s == 0 && d > 0) worst = 1 } }
    END { if (rows != n) worst = 1; printf "%.3g\n", worst + 0 }' "$1" "$2"
}

check_scene() { # check_scene NAME SCENE MESH
  name=$1 scene=$2 mesh=$3
  for solver in gauss cholesky; do
    "$RADIOSITY" solve -q --threads 1 --solver "$solver" --mesh "$mesh" "$scene" \
      --elements "$work/$name-s.tsv" --form-factors "$work/$name-s.npy" 2>/dev/null
    for np in 1 2 3 4; do
      mpi "$np" solve -q --threads 1 --solver "$solver" --mesh "$mesh" "$scene" \
        --elements "$work/$name-m.tsv" --form-factors "$work/$name-m.npy" \
        --report "$work/$name-m.json" 2>/dev/null
      rc=$?
      ok $rc "$name $solver, $np processes: exit 0"
      cmp -s "$work/$name-s.npy" "$work/$name-m.npy"
      ok $? "$name $solver, $np processes: F byte-identical to radiosity solve's"
      w=$(maxrel "$work/$name-s.tsv" "$work/$name-m.tsv")
      close_to "$w" 0 1e-12
      ok $? "$name $solver, $np processes: B within 1e-12 relative of radiosity solve (max $w)"
      grep -q "\"solver\": *\"$solver\"" "$work/$name-m.json"
      ok $? "$name $solver, $np processes: the report names the solver"
      rm -f "$work/$name-m.tsv" "$work/$name-m.npy" "$work/$name-m.json"
    done
  done
}

check_scene cube "$top_srcdir/data/goral1984-cube.scene" 7x7
check_scene cornell "$top_srcdir/data/cornell-box.scene" 2x2

# Jacobi on the distributed F stops on a bound of its error (1e-12 of
# ||B||inf, mpi_jacobi.c): against the serial LU, 1e-10 relative per value
# leaves room for values 100 times below the largest.
"$RADIOSITY" solve -q --threads 1 --mesh 7x7 "$top_srcdir/data/goral1984-cube.scene" \
  --elements "$work/j-s.tsv" 2>/dev/null
for np in 2 4; do
  mpi "$np" solve -q --threads 1 --solver jacobi --mesh 7x7 \
    "$top_srcdir/data/goral1984-cube.scene" --elements "$work/j-m.tsv" --report "$work/j.json" 2>/dev/null
  ok $? "cube jacobi, $np processes: exit 0"
  w=$(maxrel "$work/j-s.tsv" "$work/j-m.tsv")
  close_to "$w" 0 1e-10
  ok $? "cube jacobi, $np processes: B within 1e-10 relative of serial LU (max $w)"
  b=$(sed -n 's/.*"iteration_error_bound": *\([^,]*\),.*/\1/p' "$work/j.json")
  awk -v b="${b:-x}" 'BEGIN { exit !(b + 0 == b && b <= 1e-12) }'
  ok $? "cube jacobi, $np processes: the report's error bound $b is below the tolerance"
done

# The energy balance (emitted - absorbed - escaped) / emitted is, with
# escaped = sum A_i B_i (1 - sum_j F_ij) and absorbed = sum A_i (1 - rho_i)
# H_i, H = F B, the area-weighted residual of the solve in disguise: a
# backward-stable solve keeps it at a few n eps, 1e-12 with room.  It is
# made from the distributed H and row sums, so it tests their reduction.
mpi 2 solve -q --threads 1 --mesh 3x3 "$top_srcdir/data/cornell-box-closed.scene" \
  --report "$work/closed.json" 2>/dev/null
ok $? "closed Cornell box on 2 processes: exit 0"
bal=$(sed -n 's/.*"energy_balance_relative": *\[\([^]]*\)\].*/\1/p' "$work/closed.json" | tr -d ' ')
r=0
for b in $(echo "${bal:-1,1,1}" | tr ',' ' '); do close_to "$b" 0 1e-12 || r=1; done
ok $r "closed Cornell box on 2 processes: energy balance ${bal:-missing} within 1e-12"

# Usage and input errors are rank 0's, with the serial program's statuses;
# the other ranks leave quietly.
mpi 2 solve --solver gauss-seidel "$top_srcdir/data/grey-cube.scene" 2>"$work/err"
[ $? -eq 2 ] && grep -q '^radiosity-mpi: the distributed solve takes --solver gauss, cholesky (ScaLAPACK) or jacobi' "$work/err"
ok $? "gauss-seidel is a usage error (exit 2) naming the solvers"
grep -q "Try 'radiosity-mpi solve --help'" "$work/err"
ok $? "the usage hint names radiosity-mpi's own --help"
mpi 2 solve --form-factors-method hemicube "$top_srcdir/data/grey-cube.scene" 2>"$work/err"
[ $? -eq 2 ] && grep -q 'hemicube' "$work/err"
ok $? "the hemicube is a usage error (exit 2): the blocks of F are filled by pairs"
printf 'material m reflect 0.5\nquad m 0 0 0 1 0 0 1 1\n' >"$work/bad.scene"
mpi 2 solve "$work/bad.scene" 2>"$work/err"
[ $? -eq 1 ] && grep -q "bad.scene:2:" "$work/err"
ok $? "a malformed scene: exit 1 with FILE:LINE"
[ "$(grep -c 'bad.scene:2:' "$work/err")" -eq 1 ]
ok $? "the message is printed once, by rank 0"
echo keep >"$work/keep.tsv"
mpi 2 solve --mesh 2x2 "$work/bad.scene" --elements "$work/keep.tsv" 2>/dev/null
[ "$(cat "$work/keep.tsv")" = keep ]
ok $? "a failed run leaves an existing output as it was"
ls "$work" | grep -q '^\.\?keep\.tsv\..' && r=1 || r=0
ok $r "and no temporary beside it"
"$RADIOSITY_MPI" --version | grep -q '^radiosity-mpi '
ok $? "--version names radiosity-mpi"
"$RADIOSITY_MPI" --help | grep -q 'mpirun -np P radiosity-mpi solve'
ok $? "--help shows how to run it"
# the help lists only what the program takes: the options it refuses
# (check() in mpi_main.c) are not offered as options
"$RADIOSITY_MPI" --help > "$work/help"
! grep -q -e '^ *--trace' -e '^ *--patches' -e '^ *--adaptive' -e '^ *--bounces' \
  -e '^ *--matrix' -e '^ *--error-bounds' -e '^ *--form-factors-method' -e 'gauss-seidel, cg' \
  "$work/help"
ok $? "--help offers no option the distributed solve refuses"
# every message starts with the program's own name
mpi 2 solve --mesh 0x0 "$top_srcdir/data/grey-cube.scene" 2> "$work/err"
[ $? -eq 2 ] && grep -q '^radiosity-mpi: ' "$work/err" && ! grep -q '^radiosity: ' "$work/err"
ok $? "a usage error says radiosity-mpi: ($(head -n 1 "$work/err"))"

done_testing
