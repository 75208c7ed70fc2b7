#!/bin/sh
# layers.sh -- the module order of src/ holds (src/MODULES, tests/layers.py):
# no file includes a folder above its own or a header private to another
# folder, and every include spells its folder.  The checker is itself
# checked: scratch copies with a misplaced include must fail it.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found"
  exit 0
fi
src="$top_srcdir/src"
check="$top_srcdir/tests/layers.py"
python3 "$check" "$src" > "$work/out" 2>&1
ok $? "src/ keeps the order of src/MODULES"
[ -s "$work/out" ] && sed 's/^/# /' "$work/out" | head -n 40

# the lowest module, its first file, given an include of the highest
first=$(awk '!/^#/ && NF { print $1; exit }' "$src/MODULES")
last=$(awk '!/^#/ && NF { m = $1 } END { print m }' "$src/MODULES")
face=$(awk -v m="$last" '$1 == m { print $2 }' "$src/MODULES")
victim=$(cd "$src/$first" && ls *.c | head -n 1)
scratch() { # a fresh copy of src/ in $work/src
  rm -rf "$work/src"
  cp -R "$src" "$work/src"
}
scratch
printf '#include "%s/%s"\n' "$last" "${face:-x.h}" >> "$work/src/$first/$victim"
python3 "$check" "$work/src" > "$work/up" 2>&1
[ $? -eq 1 ] && grep -q "^$work/src/$first/$victim:[0-9]*: .*reaches up" "$work/up"
ok $? "an include of $last/ from $first/$victim is refused, naming the file and line"

scratch
printf '#include "status.h"\n' >> "$work/src/$first/$victim"
python3 "$check" "$work/src" > "$work/bare" 2>&1
[ $? -eq 1 ] && grep -q "does not spell its folder" "$work/bare"
ok $? "an include without its folder is refused"

# a header of a lower folder that is not among its faces
priv=$(awk '!/^#/ && NF { print $1 }' "$src/MODULES" | while read -r m; do
  for h in "$src/$m"/*.h; do
    [ -f "$h" ] || continue
    b=${h##*/}
    awk -v m="$m" -v b="$b" '$1 == m { for (k = 2; k <= NF && $k != "--"; k++) if ($k == b) f = 1 } END { exit f }' "$src/MODULES" &&
      { echo "$m/$b"; exit 0; }
  done
done | head -n 1)
if [ -n "$priv" ]; then
  scratch
  printf '#include "%s"\n' "$priv" >> "$work/src/$last/$(cd "$src/$last" && ls *.c | head -n 1)"
  python3 "$check" "$work/src" > "$work/priv" 2>&1
  [ $? -eq 1 ] && grep -q "is private to" "$work/priv"
  ok $? "an include of $priv, private to its folder, from $last/ is refused"
else
  skip "every header is a face"
fi

scratch
mkdir "$work/src/stray" && cp "$src/$first/$victim" "$work/src/stray/"
python3 "$check" "$work/src" > "$work/stray" 2>&1
[ $? -eq 1 ] && grep -q "stray: a folder that MODULES does not list" "$work/stray"
ok $? "a folder MODULES does not list is refused"
# a module with a second face
scratch
ownface=$(awk -v m="$first" '$1 == m { print $2 }' "$src/MODULES")
second=$(cd "$src/$first" && ls *.h | grep -vx "$ownface" | head -n 1)
awk -v m="$first" -v h="$second" '$1 == m { $2 = $2 " " h } { print }' "$src/MODULES" > "$work/src/MODULES"
python3 "$check" "$work/src" > "$work/second" 2>&1
[ $? -eq 1 ] && grep -q "MODULES: $first has 2 faces" "$work/second"
ok $? "a second face of $first/ ($second) is refused"

# a file its folder's local.mk does not list (it would be left out of
# the build and the tarball)
scratch
cp "$top_srcdir/Makefile.am" "$work/Makefile.am"
grep -v "%reldir%/$ownface" "$src/$first/local.mk" > "$work/src/$first/local.mk"
python3 "$check" "$work/src" > "$work/unlisted" 2>&1
[ $? -eq 1 ] && grep -q "src/$first/$ownface: not listed in" "$work/unlisted"
ok $? "$first/$ownface left out of $first/local.mk is refused"

# two headers of one folder that include each other
pair=$(cd "$src/$first" && ls *.h | head -n 2 | tr '\n' ' ')
set -- $pair
if [ $# -eq 2 ]; then
  scratch
  printf '#include "%s/%s"\n' "$first" "$2" >> "$work/src/$first/$1"
  printf '#include "%s/%s"\n' "$first" "$1" >> "$work/src/$first/$2"
  python3 "$check" "$work/src" > "$work/circle" 2>&1
  [ $? -eq 1 ] && grep -q "include each other in a circle: src/$first/$1 src/$first/$2" "$work/circle"
  ok $? "$first/$1 and $first/$2 including each other are refused"
else
  skip "$first/ has fewer than two headers"
fi

# README.md's Layout lists the module folders, in the order of src/MODULES
awk '!/^#/ && NF { print $1 }' "$src/MODULES" > "$work/modules"
awk '/^## Layout/ { on = 1; next } /^## / { on = 0 } on && $1 ~ /^src\/[a-z0-9_]+\/$/ {
  sub(/^src\//, "", $1); sub(/\/$/, "", $1); print $1 }' "$top_srcdir/README.md" > "$work/readme"
(cd "$src" && for d in */; do echo "${d%/}"; done) | sort > "$work/folders"
cmp -s "$work/modules" "$work/readme" && sort "$work/modules" | cmp -s - "$work/folders"
ok $? "README.md's Layout lists src/'s folders as src/MODULES orders them ($(tr '\n' ' ' < "$work/readme"))"
# the calls, from the build's object files: none reaches a module after its
# own, no files call each other in a circle
python3 "$check" "$src" "${top_builddir:-.}" > "$work/calls" 2>&1
ok $? "no object of a module calls one of a module after it; no call circles"
[ -s "$work/calls" ] && sed 's/^/# /' "$work/calls" | head -n 40
if command -v "${CC:-cc}" > /dev/null 2>&1; then
  fake="$work/build"
  mkdir -p "$fake/src/$first" "$fake/src/$last"
  printf 'int high(void);\nint low(void) { return high(); }\n' > "$work/low.c"
  printf 'int low(void);\nint high(void) { return 1; }\nint other(void) { return low(); }\n' > "$work/high.c"
  "${CC:-cc}" -c "$work/low.c" -o "$fake/src/$first/low.o" &&
    "${CC:-cc}" -c "$work/high.c" -o "$fake/src/$last/high.o"
  python3 "$check" "$src" "$fake" > "$work/fake" 2>&1
  [ $? -eq 1 ] && grep -q "src/$first/low: calls high of src/$last/high, a module after $first" "$work/fake" &&
    grep "in a circle:" "$work/fake" | grep "src/$first/low" | grep -q "src/$last/high"
  ok $? "a call from $first/ up into $last/, and the circle it closes, are refused"
else
  skip "no C compiler to build the objects of a wrong call"
fi
done_testing
