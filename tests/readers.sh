#!/bin/sh
# readers.sh -- OBJ + MTL input through the program (issue 19).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Independent references, never the program's own earlier output:
#   - the Cornell box as OBJ + MTL (data/cornell-box.obj) is the same scene
#     as data/cornell-box.scene, so with the same --mesh the element tables
#     (centroids, areas, B) must agree to 1e-12 relative.
. "${top_srcdir:-.}/tests/lib.sh"
data="$top_srcdir/data"

# same_table A B TOL: same header, same rows, every field equal within TOL
# relative (absolute below 1).
same_table() {
  awk -F '\t' -v tol="$3" '
    NR == FNR { a[FNR] = $0; n = FNR; next }
    { if (FNR > n) { bad = "extra row " FNR; exit }
      split(a[FNR], x, "\t")
      if (FNR == 1) { if ($0 != a[1]) { bad = "headers differ"; exit } ; next }
      for (k = 1; k <= NF; k++) {
        d = x[k] - $k; if (d < 0) d = -d
        s = x[k] < 0 ? -x[k] : x[k]; if (s < 1) s = 1
        if (d > tol * s) { bad = "row " FNR " column " k ": " x[k] " vs " $k; exit }
      }
      rows = FNR }
    END { if (bad == "" && rows != n) bad = "rows " rows " vs " n
          if (bad != "") { print bad; exit 1 } }' "$1" "$2"
}

# ---- OBJ: the Cornell box ----
for m in 1x1 2x2; do
  "$RADIOSITY" solve --mesh $m --elements "$work/scene.tsv" "$data/cornell-box.scene" 2> "$work/err1" &&
  "$RADIOSITY" solve --mesh $m --elements "$work/obj.tsv" "$data/cornell-box.obj" 2> "$work/err2"
  ok $? "Cornell box solves from .scene and from .obj with --mesh $m"
  why=$(same_table "$work/scene.tsv" "$work/obj.tsv" 1e-12); r=$?
  rows=$(($(wc -l < "$work/obj.tsv") - 1))
  [ $r -eq 0 ] && [ "$rows" -gt 30 ]
  ok $? "Cornell box --mesh $m: OBJ and scene element tables agree to 1e-12 ($rows elements) $why"
done

# mtllib is found beside the OBJ file, wherever the program runs
mkdir -p "$work/a/b" "$work/elsewhere"
cp "$data/cornell-box.obj" "$data/cornell-box.mtl" "$work/a/b/"
(cd "$work/elsewhere" && "$RADIOSITY" solve --elements "$work/moved.tsv" ../a/b/cornell-box.obj 2> "$work/err")
ok $? "mtllib is read relative to the OBJ file, not the working directory"
"$RADIOSITY" solve --elements "$work/obj1.tsv" "$data/cornell-box.obj" 2> "$work/err"
same_table "$work/obj1.tsv" "$work/moved.tsv" 0 > "$work/why"
ok $? "... and gives the same B"
rm "$work/a/b/cornell-box.mtl"
"$RADIOSITY" formfactor "$work/a/b/cornell-box.obj" > "$work/out" 2> "$work/err"; rc=$?
case $(head -n 1 "$work/err") in
  "radiosity: $work/a/b/cornell-box.obj:12: cannot read the material library: $work/a/b/cornell-box.mtl: "*) m=0 ;;
  *) m=1 ;;
esac
[ $rc -eq 1 ] && [ $m -eq 0 ]; ok $? "a missing mtllib is an error at its line: $(head -n 1 "$work/err")"

done_testing
