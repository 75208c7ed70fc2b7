#!/bin/sh
# cli.sh -- the command-line contract (radiosity(1), radiosity-scene(5),
# radiosity-files(5)): output format, exit statuses, error messages, and
# no output file on failure.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

printf 'material w reflect 0.5\nquad w 0 0 0  1 0 0  1 1 0  0 1 0\nquad w 0 0 1  0 1 1  1 1 1  1 0 1\n' > "$work/two.scene"

# formfactor: header with i, j, F; two rows; the nine-point rule's value
# (0.1998348614034, recomputed by a plain loop in tests/unit/ff/test_formfactor.c)
# in classic, and the exact C-11 value within each mode's promise otherwise.
out=$("$RADIOSITY" formfactor --accuracy classic "$work/two.scene"); rc=$?
ok $rc "formfactor --accuracy classic exits 0"
hdr=$(printf '%s\n' "$out" | head -n 1 | cut -f1-3)
[ "$hdr" = "$(printf 'i\tj\tF')" ]; ok $? "header starts i j F"
[ "$(printf '%s\n' "$out" | wc -l)" -eq 3 ]; ok $? "one row per ordered pair"
f=$(printf '%s\n' "$out" | awk -F'\t' 'NR==2 {print $3}')
close_to "$f" 0.1998348614034 1e-12; ok $? "classic F = $f (rule value 0.1998348614034)"
f=$("$RADIOSITY" formfactor "$work/two.scene" | awk -F'\t' 'NR==2 {print $3}')
close_to "$f" 0.19982489569838746 1e-6; ok $? "default F = $f within 1e-6 of the exact 0.19982489569839"
f=$("$RADIOSITY" formfactor --accuracy reference "$work/two.scene" | awk -F'\t' 'NR==2 {print $3}')
close_to "$f" 0.19982489569838746 1e-9; ok $? "reference F = $f within 1e-9 of the exact 0.19982489569839"
f=$("$RADIOSITY" formfactor --quadrature 3 --mesh 1x1 --accuracy classic "$work/two.scene" | awk -F'\t' 'NR==3 {print $3}')
close_to "$f" 0.1998348614034 1e-12; ok $? "--quadrature 3 --mesh 1x1 gives the same rule value"
n=$("$RADIOSITY" formfactor --mesh 2x3 "$work/two.scene" | tail -n +2 | wc -l)
[ "$n" -eq 132 ]; ok $? "--mesh 2x3: 12 elements, 132 ordered pairs ($n)"

# analytic: one value, %.17g
v=$("$RADIOSITY" analytic point-disk 1 1); ok $? "analytic point-disk exits 0"
[ "$v" = "0.5" ]; ok $? "point-disk 1 1 = 0.5 ($v)"
v=$("$RADIOSITY" analytic parallel-rectangles 1 1 1)
close_to "$v" 0.19982489569838746 1e-14; ok $? "parallel-rectangles 1 1 1 = $v"
v=$("$RADIOSITY" analytic perpendicular-rectangles 1 1 1)
close_to "$v" 0.20004377607540316 1e-14; ok $? "perpendicular-rectangles 1 1 1 = $v"
"$RADIOSITY" analytic point-disk 1 > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "missing parameter: exit 2"
"$RADIOSITY" analytic point-disk 1 -1 > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "negative parameter: exit 2"
"$RADIOSITY" analytic cone 1 > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "unknown case: exit 2"

# analytic at extreme ratios: values from limits derived apart
# from analytic.c.
# Two opposed strips eps x 1, 1 apart: F = (2 eps/pi) int_0^1 (1 - u)/(1 + u^2)^2 du
# = (2 eps/pi)(pi/8 + 1/4 - 1/4) = eps/4 (the kernel convolved along the
# length; the eps^3 term is below 1e-400).
v=$("$RADIOSITY" analytic parallel-rectangles 1e-200 1 1); ok $? "analytic parallel-rectangles 1e-200 1 1 exits 0"
close_to "$v" 2.5e-201 1e-13; ok $? "parallel-rectangles 1e-200 1 1 = eps/4 ($v)"
# a >> b = c: Hottel's crossed strings for infinite strips, sqrt(2) - 1,
# with an end correction of relative size c/a = 1e-150.
v=$("$RADIOSITY" analytic parallel-rectangles 1e150 1 1)
close_to "$v" 0.41421356237309505 1e-13; ok $? "parallel-rectangles 1e150 1 1 = sqrt 2 - 1 ($v)"
# c -> 0: everything but the loss through the gap, 1 - c/a - c/b.
v=$("$RADIOSITY" analytic parallel-rectangles 1 1 1e-150)
close_to "$v" 1 1e-13; ok $? "parallel-rectangles 1 1 1e-150 = 1 ($v)"
# l << w = h = 1: the large-W, H expansion of C-14,
# B = 3/4 + ln(W H / R)/2 + O(1/W^2), F = B/(pi W), W = H = 1e100.
v=$("$RADIOSITY" analytic perpendicular-rectangles 1e-100 1 1)
want=$(awk 'BEGIN { printf "%.17g", (0.75 + 0.5 * log(1e100 / sqrt(2))) / (3.141592653589793 * 1e100) }')
close_to "$v" "$want" 1e-13; ok $? "perpendicular-rectangles 1e-100 1 1 = $want ($v)"
# a small disk very close to a huge one sees it all; reciprocity gives the
# other way round (r1/r2)^2 = 1e-200.
v=$("$RADIOSITY" analytic disk-disk 1e-100 1 1e-100)
close_to "$v" 1 1e-13; ok $? "disk-disk 1e-100 1 1e-100 = 1 ($v)"
v=$("$RADIOSITY" analytic disk-disk 1 1e-100 1e-100)
close_to "$v" 1e-200 1e-13; ok $? "disk-disk 1 1e-100 1e-100 = 1e-200 ($v)"
# point to disk far away: F = (r/h)^2 / (1 + (r/h)^2) = 1e-300
v=$("$RADIOSITY" analytic point-disk 1 1e150)
close_to "$v" 1e-300 1e-13; ok $? "point-disk 1 1e150 = 1e-300 ($v)"

# standard output that fails (a full disk): exit 1 with the reason, for the
# value, the help and the version alike
for args in "analytic point-disk 1 1" "--help" "--version" "-h" "analytic --help" "solve --help" "formfactor -h"; do
  "$RADIOSITY" $args > /dev/full 2> "$work/err"; rc=$?
  msg=$(head -n 1 "$work/err")
  case "$msg" in
    "radiosity: write error on standard output: "?*) m=0 ;;
    *) m=1 ;;
  esac
  [ $rc -eq 1 ] && [ $m -eq 0 ]; ok $? "'radiosity $args' > /dev/full: exit $rc, '$msg'"
done
"$RADIOSITY" formfactor -o - "$work/two.scene" > /dev/full 2> "$work/err"; rc=$?
msg=$(head -n 1 "$work/err")
case "$msg" in *": "?*) m=0 ;; *) m=1 ;; esac
[ $rc -eq 1 ] && [ $m -eq 0 ] && [ "$(wc -l < "$work/err")" -eq 1 ]
ok $? "formfactor -o - > /dev/full: exit $rc, one message with a reason: '$msg'"
# a write error on a regular file names the file and the reason: a file
# size limit of one block (EFBIG, the signal ignored) stands in for a full
# disk; no output file may be left behind
printf 'material w reflect 0.5\nquad w 0 0 0  1 0 0  1 1 0  0 1 0 mesh 10x10\nquad w 0 0 1  0 1 1  1 1 1  1 0 1 mesh 10x10\n' > "$work/big.scene"
(trap '' XFSZ; ulimit -f 1 && exec "$RADIOSITY" formfactor -o "$work/big.tsv" "$work/big.scene") 2> "$work/err"; rc=$?
msg=$(head -n 1 "$work/err")
case "$msg" in "radiosity: $work/big.tsv"*": "?*) m=0 ;; *) m=1 ;; esac
[ $rc -eq 1 ] && [ $m -eq 0 ] && [ ! -e "$work/big.tsv" ] && [ -z "$(ls "$work" | grep '^big\.tsv.')" ]
ok $? "write error on a file: exit $rc, '$msg', no file left"

# usage and help: --help and -h alike for every command; getopt's own
# messages name the program and the command
for cmd in formfactor analytic solve render progress sweep animate compare; do
  "$RADIOSITY" $cmd --help | grep -q "Usage: radiosity $cmd"; ok $? "$cmd --help"
  "$RADIOSITY" $cmd -h > "$work/h" 2>&1; rc=$?
  [ $rc -eq 0 ] && grep -q "Usage: radiosity $cmd" "$work/h"; ok $? "$cmd -h works like --help (exit $rc)"
done
for cmd in formfactor solve render progress sweep animate compare; do
  "$RADIOSITY" $cmd --no-such-option "$work/two.scene" > /dev/null 2> "$work/err"; rc=$?
  msg=$(head -n 1 "$work/err")
  case "$msg" in "radiosity $cmd: "*"no-such-option"*) m=0 ;; *) m=1 ;; esac
  [ $rc -eq 2 ] && [ $m -eq 0 ]; ok $? "$cmd --no-such-option: exit $rc, '$msg'"
  "$RADIOSITY" $cmd -Z "$work/two.scene" > /dev/null 2> "$work/err"; rc=$?
  msg=$(head -n 1 "$work/err")
  case "$msg" in "radiosity $cmd: "*"'Z'"*) m=0 ;; *) m=1 ;; esac
  [ $rc -eq 2 ] && [ $m -eq 0 ]; ok $? "$cmd -Z: exit $rc, '$msg'"
done
"$RADIOSITY" -h | grep -q '^Usage: radiosity'; ok $? "-h"
"$RADIOSITY" --version | head -n 1 | grep -q '^radiosity [0-9]'; ok $? "--version"
"$RADIOSITY" --help | grep -q '^Usage: radiosity'; ok $? "--help"
# where bugs go, and the README that says what to send is in the tarball
"$RADIOSITY" --help | tail -n 3 | grep -q '^Report bugs to the issue tracker'
ok $? "--help ends saying where to report bugs"
grep -q '^## Reporting bugs' "${top_srcdir:-.}/README.md"
ok $? "README.md says how to report a bug"
"$RADIOSITY" frobnicate > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "unknown command: exit 2"
"$RADIOSITY" formfactor --no-such-option "$work/two.scene" > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "unknown option: exit 2"
"$RADIOSITY" formfactor --mesh 0x3 "$work/two.scene" > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "bad --mesh: exit 2"
"$RADIOSITY" formfactor --accuracy sloppy "$work/two.scene" > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "bad --accuracy: exit 2"
"$RADIOSITY" formfactor > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "no scene: exit 2"

# bad scenes: "radiosity: FILE:LINE: reason", exit 1, no output file
bad() { # bad NAME LINE REASON-PATTERN TEXT
  printf '%b' "$4" > "$work/$1.scene"
  rm -f "$work/out.tsv"
  "$RADIOSITY" formfactor -o "$work/out.tsv" "$work/$1.scene" 2> "$work/err" > /dev/null; rc=$?
  msg=$(head -n 1 "$work/err")
  case "$msg" in
    "radiosity: $work/$1.scene:$2: "*"$3"*) m=0 ;;
    *) m=1 ;;
  esac
  [ $rc -eq 1 ] && [ $m -eq 0 ] && [ ! -e "$work/out.tsv" ]
  ok $? "$1: exit $rc, '$msg', no output file"
}
M='material w reflect 0.5\n'
bad keyword 1 "unknown keyword" 'lamp 1 2 3\n'
bad missing 2 "missing number" "${M}quad w 0 0 0 1 0 0 1 1 0 0 1\n"
bad extra 2 "unexpected" "${M}quad w 0 0 0 1 0 0 1 1 0 0 1 0 9\n"
bad notnum 2 "not a number" "${M}quad w 0 0 0 1 0 0 1 1 0 0 1 x\n"
bad nan 2 "finite" "${M}quad w 0 0 0 1 0 0 1 1 0 0 1 NaN\n"
bad reflect 1 "reflectance" 'material w reflect 2\n'
bad emit 1 "emission" 'material w reflect 0.5 emit -1\n'
bad undefined 2 "undefined material" "${M}quad v 0 0 0 1 0 0 1 1 0 0 1 0\n"
bad duplicate 2 "already defined" "${M}${M}"
bad mesh 2 "mesh must be NxM" "${M}quad w 0 0 0 1 0 0 1 1 0 0 1 0 mesh 3xx\n"
bad planar 2 "not planar" "${M}quad w 0 0 0 1 0 0 1 1 1 0 1 0\n"
bad convex 2 "not convex" "${M}quad w 0 0 0 1 0 0 0.3 0.3 0 0 1 0\n"
bad bowtie 2 "self-intersecting" "${M}quad w 0 0 0 1 1 0 1 0 0 0 1 0\n"
bad zeroarea 2 "zero area" "${M}quad w 0 0 0 1 0 0 2 0 0 3 0 0\n"
bad fewverts 2 "vertex count" "${M}polygon w 2 0 0 0 1 0 0\n"
bad empty 1 "no surfaces" "${M}"
# an existing output survives a failed run
echo precious > "$work/keep.tsv"
"$RADIOSITY" formfactor -o "$work/keep.tsv" "$work/empty.scene" 2> /dev/null
[ "$(cat "$work/keep.tsv")" = precious ]; ok $? "a failed run leaves an existing output untouched"
"$RADIOSITY" formfactor "$work/nonexistent.scene" > /dev/null 2>&1; [ $? -eq 1 ]; ok $? "missing scene file: exit 1"
"$RADIOSITY" formfactor -o "$work/ok.tsv" "$work/two.scene" && [ "$(wc -l < "$work/ok.tsv")" -eq 3 ] && [ -z "$(ls "$work" | grep tmp)" ]
ok $? "-o writes the table and leaves no temporary file"
done_testing
