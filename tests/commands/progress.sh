#!/bin/sh
# progress.sh -- progressive refinement through the command line: `radiosity
# progress` (the race of Cohen et al. 1988, figure 7: table by column name,
# plot, snapshots, exit statuses) and `radiosity solve --solver progressive`
# (agreement with gauss, the trace, no answer when it gives up).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
cube="$top_srcdir/data/goral1984-cube.scene"

# ---- radiosity progress ----------------------------------------------------
"$RADIOSITY" progress -q --mesh 3x3 -o "$work/race.tsv" --plot "$work/race.png" "$cube"
ok $? "progress on the cube with a table and a plot"
cols=$(head -n 1 "$work/race.tsv")
for c in step gathering shooting sorted sorted_ambient; do
  printf '%s\n' "$cols" | tr '\t' '\n' | grep -qx "$c"; ok $? "race table has column '$c'"
done
# default --steps: 2 x 54 elements, rows for steps 0..108
[ "$(tail -n +2 "$work/race.tsv" | wc -l)" -eq 109 ]; ok $? "109 rows: steps 0 to 2 x 54"
# the paper's order at every step, by column name: sorted + ambient below
# sorted, sorted at most shooting (they tie while the 9 light elements
# shoot), shooting below gathering
awk -F'\t' 'NR==1 { for (k=1;k<=NF;k++) c[$k]=k; next } $c["step"] > 0 {
  g=$c["gathering"]; s=$c["shooting"]; o=$c["sorted"]; a=$c["sorted_ambient"]
  if (!(a < o && o <= s && s < g)) bad=1; if ($c["step"] > 9 && !(o < s)) bad=1 } END { exit bad }' "$work/race.tsv"
ok $? "every step: sorted_ambient < sorted <= shooting < gathering; sorted < shooting after the lights"
head -c 8 "$work/race.png" | od -An -c | grep -q 'P   N   G'; ok $? "the plot is a PNG"
"$RADIOSITY" progress -q --mesh 2x2 --steps 5 "$cube" > "$work/stdout.tsv"
[ "$(wc -l < "$work/stdout.tsv")" -eq 7 ]; ok $? "no --output: the table goes to standard output"
"$RADIOSITY" progress --mesh 2x2 --steps 400 -o "$work/r.tsv" "$cube" 2> "$work/summary"
grep -q 'first step within 1e-06' "$work/summary"; ok $? "the summary says when each method is within 1e-6"
"$RADIOSITY" progress -q --mesh 2x2 --steps 20 --patches -o "$work/p.tsv" "$cube"
ok $? "--patches"
"$RADIOSITY" progress -q --mesh 2x2 --steps 8 --snapshots 4 --snapshot-prefix "$work/snap" -o "$work/discard.tsv" "$cube"
[ "$(ls "$work" | grep -c '^snap-.*-00000[048]\.png$')" -eq 12 ]; ok $? "--snapshots 4: 3 images of each of the 4 methods"
[ -s "$work/snap-sorted_ambient-000004.png" ]; ok $? "snapshots are named PREFIX-METHOD-STEP.png"

"$RADIOSITY" progress -q --mesh 2x2 --steps 4 --snapshots-at 1,3 --snapshot-prefix "$work/at" -o "$work/discard.tsv" "$cube"
[ "$(ls "$work" | grep -c '^at-.*-00000[13]\.png$')" -eq 8 ] && [ "$(ls "$work" | grep -c '^at-')" -eq 8 ]
ok $? "--snapshots-at 1,3: images at steps 1 and 3 of each of the 4 methods, no others"
"$RADIOSITY" progress -q --mesh 2x2 --snapshots-at 60 --snapshot-prefix "$work/late" -o "$work/late.tsv" "$cube"
[ "$(tail -n +2 "$work/late.tsv" | wc -l)" -eq 61 ] && [ -s "$work/late-sorted_ambient-000060.png" ]
ok $? "--snapshots-at 60 beyond the default 48 steps: the race runs to step 60"

# errors
for l in '1,,3' ',1' '1,' '3,1' '1,1' '-1' '1e1'; do
  "$RADIOSITY" progress -q --mesh 2x2 --steps 4 --snapshots-at "$l" --snapshot-prefix "$work/bad" -o "$work/bad.tsv" "$cube" 2> "$work/err"
  rc=$?; [ $rc -eq 2 ] && [ ! -e "$work/bad.tsv" ]; ok $? "--snapshots-at '$l' is a usage error (exit $rc)"
done
"$RADIOSITY" progress -q --mesh 2x2 --steps 4 --snapshots-at 2,10 --snapshot-prefix "$work/beyond" -o "$work/beyond.tsv" "$cube" 2> "$work/err"
rc=$?; [ $rc -eq 2 ] && grep -q "beyond --steps 4" "$work/err"
ok $? "--snapshots-at 10 with --steps 4: usage error, not a silently missing image (exit $rc)"
"$RADIOSITY" progress -q --mesh 2x2 --snapshots-at 1,3 --snapshot-prefix "$work/nodir/s" -o "$work/nodir.tsv" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q "nodir/s-" "$work/err" && [ "$(wc -l < "$work/err")" -eq 1 ] && [ ! -e "$work/nodir.tsv" ]
ok $? "a missing snapshot directory is found before the race: exit $rc, $(head -c 100 "$work/err")"
"$RADIOSITY" progress -q --snapshots 2 "$top_srcdir/data/furnace.scene" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q camera "$work/err"; ok $? "snapshots need a camera: exit 1"
"$RADIOSITY" progress -q --mesh 2x2 -o "$work/missing/dir.tsv" "$cube" 2> /dev/null; [ $? -eq 1 ]
ok $? "unwritable output: exit 1"
echo precious > "$work/keep.tsv"
"$RADIOSITY" progress -q -o "$work/keep.tsv" "$work/no-such.scene" 2> /dev/null; rc=$?
[ $rc -eq 1 ] && [ "$(cat "$work/keep.tsv")" = precious ]; ok $? "missing scene: exit 1, output untouched"
for bad in "--steps 0" "--steps x" "--reach 2" "--snapshots 0" "--snapshot-prefix p" "--bogus" \
  "--snapshots-at 3,2" "--snapshots-at x" "--snapshots-at 1,-2" "--snapshots-at 1," \
  "--exposure-from lamp"; do
  # shellcheck disable=SC2086
  "$RADIOSITY" progress $bad "$cube" > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "progress $bad: exit 2"
done
"$RADIOSITY" progress > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "no scene: exit 2"
"$RADIOSITY" progress "$cube" "$cube" > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "two scenes: exit 2"
"$RADIOSITY" progress --help > "$work/help"; ok $? "progress --help"
for o in --steps --output --plot --reach --patches --snapshots --snapshots-at --snapshot-prefix \
  --exposure-from --matrix --mesh --quadrature --accuracy --quiet; do
  grep -q -- "$o" "$work/help"; ok $? "progress --help lists $o"
done

# ---- radiosity solve --solver progressive ------------------------------------
"$RADIOSITY" solve -q --mesh 3x3 --elements "$work/g.tsv" "$cube"
"$RADIOSITY" solve -q --mesh 3x3 --solver progressive --trace "$work/trace.tsv" \
  --report "$work/rep.json" --elements "$work/p.tsv" "$cube"
ok $? "solve --solver progressive --trace"
paste "$work/g.tsv" "$work/p.tsv" | awk -F'\t' 'NR==1 { for (k=1;k<=NF/2;k++) c[$k]=k; h=NF/2; next }
  { split("r g b", t, " "); for (i=1;i<=3;i++) { k=c[t[i]]; d=$k-$(k+h); if (d<0) d=-d; if (d>1e-10) bad=1 } } END { exit bad }'
ok $? "progressive agrees with gauss to 1e-10"
cols=$(head -n 1 "$work/trace.tsv")
for c in step shooter unshot rms rms_ambient; do
  printf '%s\n' "$cols" | tr '\t' '\n' | grep -qx "$c"; ok $? "trace has column '$c'"
done
rows=$(tail -n +2 "$work/trace.tsv" | wc -l)
last=$(tail -n 1 "$work/trace.tsv" | cut -f 1)
[ "$rows" -gt 54 ] && [ "$rows" -eq "$last" ]; ok $? "the trace has one row per step ($rows)"
"$RADIOSITY" solve -q --mesh 3x3 --solver progressive --patches --elements "$work/pp.tsv" "$cube"
paste "$work/g.tsv" "$work/pp.tsv" | awk -F'\t' 'NR==1 { for (k=1;k<=NF/2;k++) c[$k]=k; h=NF/2; next }
  { split("r g b", t, " "); for (i=1;i<=3;i++) { k=c[t[i]]; d=$k-$(k+h); if (d<0) d=-d; if (d>1e-10) bad=1 } } END { exit bad }'
ok $? "--patches: the same B to 1e-10"
"$RADIOSITY" solve -q --mesh 3x3 --solver progressive --max-iterations 5 --elements "$work/nc.tsv" \
  --trace "$work/nctrace.tsv" "$cube" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'did not converge in 5 shooting steps' "$work/err" && [ ! -e "$work/nc.tsv" ]
ok $? "5 shooting steps are not enough: exit 1, says so, no element table"
[ "$(tail -n +2 "$work/nctrace.tsv" | wc -l)" -eq 5 ]; ok $? "the trace of the 5 steps is kept"
done_testing
