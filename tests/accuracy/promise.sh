#!/bin/sh
# promise.sh -- the program says what it cannot stand behind.  Classic
# mode stays the paper's rule, but its summary and report name form
# factors outside [0, 1], rows of F summing above 1 and negative B, and
# point to --accuracy default.  In default and
# reference mode an entry whose own error estimate exceeds the promise is
# counted on standard error and in the report (form_factors_promise_unmet),
# and --strict makes that an error.  Each count is checked against the
# program's other outputs, recounted here: the form-factor table with its
# error column, the element table.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
json() { sed -n "s/^ *\"$2\": \([^,]*\),*$/\1/p" "$1"; }

# two unit squares 1e-9 apart: the nine-point rule gives F = 5.01
printf 'material w reflect 0.5 emit 1\nquad w 0 0 0  1 0 0  1 1 0  0 1 0\nquad w 0 0 1e-9  0 1 1e-9  1 1 1e-9  1 0 1e-9\n' > "$work/near.scene"
"$RADIOSITY" solve --accuracy classic --report "$work/c.json" --elements "$work/c.tsv" \
  "$work/near.scene" 2> "$work/c.err"
ok $? "classic on touching squares: exit 0 (the paper's rule, as it is)"
"$RADIOSITY" formfactor -q --accuracy classic -o "$work/cf.tsv" "$work/near.scene" 2> /dev/null
above=$(awk -F'\t' 'NR > 1 && $3 > 1 { n++ } END { print n + 0 }' "$work/cf.tsv")
[ "$above" -gt 0 ] && [ "$(json "$work/c.json" form_factors_above_one)" -eq "$above" ]
ok $? "the report counts the $above entries above 1 that the table shows"
grep -q "above 1.*try --accuracy default" "$work/c.err"; ok $? "the summary says so and points to --accuracy default"
rows=$(awk -F'\t' 'NR > 1 { s[$1] += $3 } END { for (i in s) if (s[i] > 1 + 1e-6) n++; print n + 0 }' "$work/cf.tsv")
[ "$rows" -gt 0 ] && [ "$(json "$work/c.json" form_factor_rows_above_one)" -eq "$rows" ] &&
  grep -q "rows of F sum to more than 1" "$work/c.err"
ok $? "rows summing above 1: $rows, counted in the report and named"
neg=$(awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { n += ($(c["r"]) < 0) + ($(c["g"]) < 0) + ($(c["b"]) < 0) } END { print n + 0 }' "$work/c.tsv")
[ "$neg" -gt 0 ] && [ "$(json "$work/c.json" b_negative)" -eq "$neg" ] && grep -q "B is negative" "$work/c.err"
ok $? "negative B: $neg values in the table, counted in the report and named"
"$RADIOSITY" solve --report "$work/d.json" "$work/near.scene" 2> "$work/d.err"
ok $? "default mode on the same squares: exit 0"
[ "$(json "$work/d.json" form_factors_above_one)" -eq 0 ] && [ "$(json "$work/d.json" b_negative)" -eq 0 ] &&
  [ "$(json "$work/d.json" form_factor_rows_above_one)" -eq 0 ] && ! grep -q warning "$work/d.err"
ok $? "default mode: nothing outside [0, 1], no negative B, no warning"

# a partly hidden pair whose estimate misses the promise
printf 'material m reflect 0.5 emit 1\nquad m 0 0 0 1 0 0 1 1 0 0 1 0\nquad m 0 0 1 0 1 1 1 1 1 1 0 1\nquad m 0.1 0.1 0.5 0.1 0.95 0.5 0.95 0.95 0.5 0.95 0.1 0.5\nquad m 0.1 0.1 0.5 0.95 0.1 0.5 0.95 0.95 0.5 0.1 0.95 0.5\n' > "$work/blk.scene"
for acc in default reference; do
  p=$([ $acc = default ] && echo 1e-6 || echo 1e-9)
  "$RADIOSITY" formfactor -q --accuracy $acc -o "$work/b.tsv" "$work/blk.scene" 2> "$work/b.err"
  miss=$(awk -F'\t' -v p=$p 'NR > 1 && $4 > p * $3 { n++ } END { print n + 0 }' "$work/b.tsv")
  "$RADIOSITY" solve -q --accuracy $acc --report "$work/b.json" "$work/blk.scene" 2> /dev/null
  got=$(json "$work/b.json" form_factors_promise_unmet)
  if [ "$miss" -gt 0 ]; then
    [ "$got" -eq "$miss" ] && grep -q "$miss form factors miss the $acc mode's promise" "$work/b.err"
    ok $? "$acc: the $miss entries whose estimate exceeds $p x F are counted and named (report: $got)"
    echo keep > "$work/keep.tsv"
    "$RADIOSITY" solve -q --strict --accuracy $acc --elements "$work/keep.tsv" \
      --report "$work/s.json" "$work/blk.scene" 2> "$work/s.err"; rc=$?
    [ $rc -eq 1 ] && grep -q '"status": "promise unmet"' "$work/s.json" &&
      [ "$(cat "$work/keep.tsv")" = keep ]
    ok $? "$acc --strict: exit 1, the report says why, no other output written"
  else
    [ "$got" -eq 0 ] && ! grep -q "promise" "$work/b.err"
    ok $? "$acc: every estimate within $p x F, and nothing is said"
    "$RADIOSITY" solve -q --strict --accuracy $acc "$work/blk.scene" 2> /dev/null
    ok $? "$acc --strict: exit 0 when every promise holds"
  fi
done
"$RADIOSITY" formfactor -q --strict -o "$work/f.tsv" "$work/near.scene"
ok $? "formfactor --strict on touching squares in default mode: the promise holds, exit 0"

# never a NaN with exit 0: two unit squares 1e155 apart (F ~ 3e-311, below
# what the fill can represent) are refused, not written as -nan
printf 'material w reflect 0.5 emit 1\nquad w 0 0 0  1 0 0  1 1 0  0 1 0\nquad w 0 0 1e155  0 1 1e155  1 1 1e155  1 0 1e155\n' > "$work/far.scene"
"$RADIOSITY" formfactor -q -o "$work/far.tsv" "$work/far.scene" 2> "$work/far.err"; rc=$?
[ $rc -eq 1 ] && grep -q 'not a finite double' "$work/far.err" && [ ! -e "$work/far.tsv" ]
ok $? "squares 1e155 apart: formfactor refuses (exit 1), writes no NaN"
"$RADIOSITY" solve -q --elements "$work/far.tsv" "$work/far.scene" 2> /dev/null; rc=$?
[ $rc -eq 1 ] && [ ! -e "$work/far.tsv" ]; ok $? "and so does solve"
done_testing
