#!/bin/sh
# npy.sh -- `formfactor -o F.npy`: NumPy's format, read back with
# Python's standard library (tests/npy.py), equal bit for bit to the table.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found"
  exit 0
fi
# The unit cube with a different mesh on each wall: elements of unequal
# areas, so F is not symmetric (A_i F_ij = A_j F_ji) and a transposed
# matrix would show: row i (from element i) sums to 1 in a closed room,
# columns do not.  18 elements.
cube="$work/cube.scene"
cat > "$cube" <<'END'
material w reflect 0.5
quad w 0 0 0  1 0 0  1 1 0  0 1 0  mesh 1x1
quad w 0 0 1  0 1 1  1 1 1  1 0 1  mesh 2x1
quad w 0 0 0  0 1 0  0 1 1  0 0 1  mesh 2x2
quad w 1 0 0  1 0 1  1 1 1  1 1 0  mesh 3x1
quad w 0 0 0  0 0 1  1 0 1  1 0 0  mesh 1x2
quad w 0 1 0  1 1 0  1 1 1  0 1 1  mesh 2x3
END
"$RADIOSITY" formfactor -q -o "$work/f.npy" "$cube"; ok $? "formfactor -o f.npy exits 0"
"$RADIOSITY" formfactor -q -o "$work/f.tsv" "$cube"; ok $? "formfactor -o f.tsv exits 0"
head -c 6 "$work/f.npy" | od -An -c | grep -q 'N   U   M   P   Y'; ok $? "f.npy starts with NumPy's magic"
[ "$(wc -c < "$work/f.npy")" -eq $((128 + 8 * 18 * 18)) ]; ok $? "f.npy: a 128-byte header and 18 x 18 doubles"
"$RADIOSITY" formfactor -q --per-surface -o "$work/s.npy" "$cube"; ok $? "--per-surface -o s.npy exits 0"
"$RADIOSITY" formfactor -q --per-surface -o "$work/s.tsv" "$cube"; ok $? "--per-surface -o s.tsv exits 0"
# tests/npy.py's own verdicts, replayed as checks of this script
replay() { # replay WHAT PYTHON-ARGS...
  what=$1; shift
  python3 "$top_srcdir/tests/npy.py" "$@" > "$work/py.out"
  ok $? "npy.py $1 exits 0"
  while IFS= read -r line; do
    case $line in
      "ok "*) ok 0 "$what: ${line#* - }" ;;
      "not ok "*) ok 1 "$what: ${line#* - }" ;;
      "#"*) echo "$line" ;;
    esac
  done < "$work/py.out"
}
replay "element matrix" elements "$work/f.npy" "$work/f.tsv" 18
replay "surface matrix" surfaces "$work/s.npy" "$work/s.tsv" 6

# solve writes the same formats: F as formfactor does, B beside its table
printf 'material e reflect 0.3 emit 1\n' > "$work/lit.scene"
sed 's/^quad w 0 0 0  1 0 0  1 1 0  0 1 0/quad e 0 0 0  1 0 0  1 1 0  0 1 0/' "$cube" >> "$work/lit.scene"
"$RADIOSITY" solve -q --form-factors "$work/sf.npy" --elements "$work/b.npy" "$work/lit.scene" &&
  "$RADIOSITY" solve -q --elements "$work/b.tsv" "$work/lit.scene" &&
  "$RADIOSITY" formfactor -q -o "$work/lf.npy" "$work/lit.scene"
ok $? "solve --form-factors F.npy --elements B.npy exits 0"
cmp -s "$work/sf.npy" "$work/lf.npy"; ok $? "solve's F.npy is formfactor's, byte for byte"
python3 - "$top_srcdir/tests" "$work/b.npy" "$work/b.tsv" > /dev/null <<'PY'
import sys, struct
sys.path.insert(0, sys.argv[1])
import npy
(rows, cols), a = npy.read_npy(sys.argv[2])
head, body = npy.read_table(sys.argv[3])
c = [head.index(k) for k in ("r", "g", "b")]
same = (rows, cols) == (len(body), 3) and all(
    npy.bits(a[i][b]) == npy.bits(float(body[i][c[b]])) for i in range(rows) for b in range(3))
sys.exit(0 if same else 1)
PY
ok $? "solve's B.npy: shape (n, 3), equal bit for bit to the r g b columns of the table"
done_testing
