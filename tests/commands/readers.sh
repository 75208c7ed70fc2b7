#!/bin/sh
# readers.sh -- OBJ + MTL and View3D input through the program.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Independent references, never the program's own earlier output:
#   - the Cornell box as OBJ + MTL (data/cornell-box.obj) is the same scene
#     as data/cornell-box.scene, so with the same --mesh the element tables
#     (centroids, areas, B) must agree to 1e-12 relative;
#   - the unit cube's wall-to-wall factors have closed forms (Hottel and
#     Sarofim 1967, eq. 2-30, and closure): opposite 0.19982489569838746,
#     adjacent (1 - opposite) / 4 = 0.20004377607540316; every row of a
#     closed enclosure sums to 1.  The default mode is held to 1e-9 (its
#     three-point rule has about 4e-10 here), reference mode to 1e-12;
#   - View3D's combined surfaces add up: the row of the two halves of a
#     wall combined (A_a F_aj + A_b F_bj) / (A_a + A_b) is the whole
#     wall's (additivity), in reference mode to 1e-12 (more in
#     tests/commands/combine.sh);
#   - an obstruction the size of two aligned unit squares, midway, hides
#     each from the other entirely (every segment between them crosses it),
#     and sees the lower one as `radiosity analytic parallel-rectangles
#     1 1 0.5` says.
. "${top_srcdir:-.}/tests/lib.sh"
data="$top_srcdir/data"
OPP=0.19982489569838746
ADJ=0.20004377607540316

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

# ---- View3D: the unit cube ----
cat > "$work/cube.vs3" << 'EOF'
T unit cube, six walls facing in
C encl=1 list=0 eps=1.0e-6
F 3
!  n    x   y   z
V  1    0.  0.  0.
V  2    1.  0.  0.
V  3    1.  1.  0.
V  4    0.  1.  0.
V  5    0.  0.  1.
V  6    1.  0.  1.
V  7    1.  1.  1.
V  8    0.  1.  1.
!  n   v1  v2  v3  v4  base cmb  emit  name
S  1    1   2   3   4   0   0   0.90  z0
S  2    1   4   8   5   0   0   0.90  x0
S  3    1   5   6   2   0   0   0.90  y0
S  4    7   6   5   8   0   0   0.90  z1
S  5    7   3   2   6   0   0   0.90  x1
S  6    7   8   4   3   0   0   0.90  y1
End of data
EOF
# check_cube FILE TOL: 30 pairs, opposite (i, i+3 mod 6) and adjacent
# factors and row sums within TOL.
check_cube() {
  awk -F '\t' -v opp=$OPP -v adj=$ADJ -v tol="$2" '
    NR == 1 { next }
    { n++; want = (($1 - $2 + 6) % 6 == 3) ? opp : adj
      d = $3 - want; if (d < 0) d = -d; if (d > worst) worst = d
      sum[$1] += $3 }
    END { for (i = 0; i < 6; i++) { d = sum[i] - 1; if (d < 0) d = -d; if (d > wsum) wsum = d }
          printf "%d pairs, worst factor error %.3g, worst row sum error %.3g\n", n, worst, wsum
          exit !(n == 30 && worst <= tol && wsum <= tol) }' "$1"
}
"$RADIOSITY" formfactor "$work/cube.vs3" > "$work/ff.tsv" 2> "$work/err"
why=$(check_cube "$work/ff.tsv" 1e-9); ok $? "cube.vs3, default mode, factors and row sums within 1e-9: $why"
"$RADIOSITY" formfactor --accuracy reference "$work/cube.vs3" > "$work/ff.tsv" 2> "$work/err"
why=$(check_cube "$work/ff.tsv" 1e-12); ok $? "cube.vs3, reference mode, within 1e-12: $why"
"$RADIOSITY" formfactor --mesh 2x2 "$work/cube.vs3" > "$work/ff.tsv" 2> "$work/err"
[ "$(($(wc -l < "$work/ff.tsv") - 1))" -eq $((24 * 23)) ]; ok $? "--mesh 2x2 meshes the View3D quads: 24 elements"

# The floor split in two halves that View3D would combine (CMB = 1).
awk '/^S  1 / { print "S  1    1   9  10   4   0   0   0.90  z0a"; next }
     /^End/ { print "S  7    9   2   3  10   0   1   0.90  z0b" }
     { print }
     /^V  8/ { print "V  9   .5   0.  0."; print "V 10   .5   1.  0." }' \
  "$work/cube.vs3" > "$work/split.vs3"
"$RADIOSITY" formfactor --accuracy reference "$work/split.vs3" > "$work/ff.tsv" 2> "$work/err"
ok $? "a View3D file with combined surfaces (CMB) runs"
why=$(awk -F '\t' -v opp=$OPP -v adj=$ADJ '
  NR > 1 && $1 == 0 { f[$2] = $3 }
  END { e1 = f[3] - opp; e2 = f[1] - adj; e1 = e1 < 0 ? -e1 : e1; e2 = e2 < 0 ? -e2 : e2
        printf "to the opposite wall %.17g (error %.3g), to x0 %.17g (error %.3g)\n", f[3], e1, f[1], e2
        exit !(e1 <= 1e-12 && e2 <= 1e-12) }' "$work/ff.tsv")
ok $? "the halves' combined row is the whole floor's: $why"

# ---- View3D: an obstruction-only surface ----
cat > "$work/obs.vs3" << 'EOF'
T two unit squares facing each other, an obstruction midway
F 3
V 1 0 0 0
V 2 1 0 0
V 3 1 1 0
V 4 0 1 0
V 5 0 0 1
V 6 1 0 1
V 7 1 1 1
V 8 0 1 1
V 9 0 0 .5
V 10 1 0 .5
V 11 1 1 .5
V 12 0 1 .5
S 1  1 2 3 4  0 0 0.9 bottom
S 2  5 8 7 6  0 0 0.9 top
O 3  9 12 11 10
E
EOF
want=$("$RADIOSITY" analytic parallel-rectangles 1 1 0.5)
"$RADIOSITY" formfactor "$work/obs.vs3" > "$work/ff.tsv" 2> "$work/err"
f01=$(awk -F '\t' '$1 == 0 && $2 == 1 { print $3 }' "$work/ff.tsv")
f10=$(awk -F '\t' '$1 == 1 && $2 == 0 { print $3 }' "$work/ff.tsv")
"$RADIOSITY" formfactor --per-surface "$work/obs.vs3" > "$work/ps.tsv" 2> "$work/err"
f02=$(awk -F '\t' '$1 == 0 && $2 == 2 { print $3 }' "$work/ps.tsv")
[ "$f01" = 0 ] && [ "$f10" = 0 ]; ok $? "the O surface hides the squares from each other (F = $f01, $f10)"
close_to "$f02" "$want" 1e-12; ok $? "the lower square sees the O surface as the closed form says ($f02 vs $want; --per-surface keeps it)"
[ "$(($(wc -l < "$work/ff.tsv") - 1))" -eq 2 ]; ok $? "the O surface has no rows or columns, as in View3D (reported: 2 elements)"

# Two O plates facing opposite ways, each over half of the aperture: their
# union is the whole unit square at z = 0.5, so every segment between the
# squares crosses it and F = 0 exactly.  View3D 3.2 gives 0.099912 here
# (built from its public source, eps=1e-6; its text output is written
# below as it printed it): compare reads View3D's 2 x 2 matrix for the
# scene's 4 surfaces and flags the entry.
cat > "$work/two.vs3" << 'END'
T two squares, two plates between them facing opposite ways
F 3
V 1 0 0 0
V 2 1 0 0
V 3 1 1 0
V 4 0 1 0
V 5 0 0 1
V 6 0 1 1
V 7 1 1 1
V 8 1 0 1
V 9 0 0 .5
V 10 0 1 .5
V 11 .5 1 .5
V 12 .5 0 .5
V 13 .5 0 .5
V 14 1 0 .5
V 15 1 1 .5
V 16 .5 1 .5
S 1  1 2 3 4  0 0 0.9 bottom
S 2  5 6 7 8  0 0 0.9 top
O 3  9 10 11 12
O 4  13 14 15 16
E
END
printf 'View3D 3.2 0 0 0 2\n1 1\n0.000000 0.099912\n0.099912 0.000000\n0.900 0.900\n' > "$work/two.vf"
printf 'View3D 3.2 0 0 0 2\n1 1\n0.000000 0.000000\n0.000000 0.000000\n0.900 0.900\n' > "$work/exact.vf"
"$RADIOSITY" formfactor "$work/two.vs3" > "$work/ff.tsv" 2> "$work/err"
[ "$(awk -F '\t' 'NR > 1 { n++; if ($3 != 0) bad = 1 } END { print n + 0, bad + 0 }' "$work/ff.tsv")" = "2 0" ]
ok $? "two half plates facing opposite ways: 2 elements, F = 0 both ways"
"$RADIOSITY" compare --tolerance 1e-3 --report "$work/two.json" "$work/two.vs3" "$work/two.vf" > "$work/out" 2> "$work/err"
[ $? -eq 1 ] && grep -q '"max_error": 99912' "$work/two.json" && grep -q 'leaves out the 2 elements of the O surfaces' "$work/err"
ok $? "compare reads View3D's 2 x 2 matrix and flags its 0.099912 where F = 0 ($(grep -m1 '"max_error"' "$work/two.json"))"
"$RADIOSITY" compare --tolerance 1e-9 "$work/two.vs3" "$work/exact.vf" > "$work/out" 2> "$work/err"
ok $? "the exact 2 x 2 matrix passes at 1e-9"

# --format: standard input and other names in any of the three formats,
# the same scene as read by its name (mtllib relative to the current
# folder for standard input)
(cd "$data" && "$RADIOSITY" solve -q --format obj --elements "$work/fo.tsv" -o "$work/fo.ply" - \
  < cornell-box.obj) && "$RADIOSITY" solve -q --elements "$work/fn.tsv" -o "$work/fn.ply" "$data/cornell-box.obj" &&
  cmp -s "$work/fo.tsv" "$work/fn.tsv"
ok $? "--format obj: the OBJ on standard input gives the element table of the file"
cp "$work/cube.vs3" "$work/cube.txt"
"$RADIOSITY" formfactor --format vs3 "$work/cube.txt" > "$work/fv.tsv" &&
  "$RADIOSITY" formfactor "$work/cube.vs3" > "$work/fw.tsv" && cmp -s "$work/fv.tsv" "$work/fw.tsv"
ok $? "--format vs3: a View3D file named .txt reads as its .vs3 twin"
"$RADIOSITY" formfactor --format scene - < "$data/grey-cube.scene" > "$work/fs.tsv" &&
  "$RADIOSITY" formfactor "$data/grey-cube.scene" > "$work/ft.tsv" && cmp -s "$work/fs.tsv" "$work/ft.tsv"
ok $? "--format scene: standard input as the native format"
"$RADIOSITY" solve --format ply - < /dev/null > /dev/null 2> "$work/err"
[ $? -eq 2 ] && grep -q "format takes scene, obj or vs3, not 'ply'" "$work/err"
ok $? "--format ply: a usage error naming the three formats"
"$RADIOSITY" solve -q --format vs3 -o "$work/fv.ply" "$data/grey-cube.scene" 2> "$work/err"
[ $? -eq 1 ] && grep -q 'grey-cube.scene:[0-9]*: ' "$work/err"
ok $? "--format vs3 on a native file: refused with FILE:LINE ($(head -c 120 "$work/err"))"

# ---- what an OBJ reader repaired, in the report as on standard error ----
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nusemtl nowhere\nf 1 2 3 4\nf 1 2 5\n' > "$work/rep.obj"
"$RADIOSITY" solve -q --report "$work/rep.json" -o "$work/rep.ply" "$work/rep.obj" 2> "$work/err"
said=$(sed -n 's/^radiosity: //p' "$work/err" | grep ': repaired: ')
if command -v python3 > /dev/null 2>&1; then
  printf '%s\n' "$said" > "$work/said"
  python3 -c 'import json, sys
r = json.load(open(sys.argv[1]))["repairs"]
said = open(sys.argv[2]).read().splitlines()
want = {"undefined_materials": 1, "spaced_names": 0, "degenerate_faces": 1,
        "split_faces": 0, "split_triangles": 0}
sys.exit(not (all(r[k] == v for k, v in want.items()) and r["said"] == said and len(said) == 2))' \
    "$work/rep.json" "$work/said"
  ok $? "--report's repairs: 1 undefined material, 1 face without area, the 2 lines said on standard error"
else
  skip "python3 not found to read the report"
fi

# ---- OBJ files as exporters write them (Debian's assimp-testmodels) ----
# Every file there that holds faces loads and solves, its repairs said on
# standard error; --strict refuses each repaired one; those that hold no
# faces, a number like 3.1+e2, a missing library or UTF-16 are refused
# with FILE:LINE.  (The hemicube at 4 pixels: the solve is the point, not
# its accuracy, and it keeps the 3,732-triangle model to seconds.)
models=/usr/share/assimp/models/OBJ
if [ -d "$models" ]; then
  loaded=0 repaired=0 refused=0 bad=
  for f in "$models"/*.obj; do
    b=$(basename "$f")
    case $b in
      box_UTF16BE.obj|cube_mtllib_after_g.obj|number_formats.obj|point_cloud.obj|testline.obj|testpoints.obj)
        (cd "$models" && "$RADIOSITY" solve -q -o "$work/m.ply" "$b") > /dev/null 2> "$work/err"
        if [ $? -eq 1 ] && grep -q "^radiosity: [^ ]*:[0-9]*: " "$work/err"; then
          refused=$((refused + 1))
        else bad="$bad $b(not refused)"; fi
        continue ;;
    esac
    (cd "$models" && "$RADIOSITY" solve -q --form-factors-method hemicube --resolution 4 \
      -o "$work/m.ply" "$b") > /dev/null 2> "$work/err" || { bad="$bad $b($(head -c 100 "$work/err"))"; continue; }
    loaded=$((loaded + 1))
    if grep -q ': repaired: ' "$work/err"; then
      repaired=$((repaired + 1))
      (cd "$models" && "$RADIOSITY" formfactor -q --strict -o "$work/m.tsv" "$b") > /dev/null 2>&1
      [ $? -eq 1 ] || bad="$bad $b(--strict took it)"
    fi
  done
  [ -z "$bad" ] && [ $loaded -eq 16 ] && [ $refused -eq 6 ]
  ok $? "assimp-testmodels: $loaded files with faces solve ($repaired repaired, each refused by --strict), $refused refused with FILE:LINE${bad:+; wrong:$bad}"
else
  skip "assimp-testmodels is not installed (scripts/install-deps.sh installs it)"
fi

done_testing
