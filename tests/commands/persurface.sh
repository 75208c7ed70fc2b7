#!/bin/sh
# persurface.sh -- `formfactor --per-surface` on the unit cube against the
# closed forms: F between opposite unit squares a unit apart,
# 0.19982489569838746, and between adjacent ones sharing an edge,
# 0.20004377607540316 (Howell's catalogue C-11 and C-14; `radiosity
# analytic` checks both in cli.sh).  A closed room's rows sum to 1, and
# 0.19982489569838746 + 4 x 0.20004377607540316 = 1 to 1e-16.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

opp=0.19982489569838746
adj=0.20004377607540316
cube="$top_srcdir/data/grey-cube.scene"
# the walls come in opposite pairs (0,1), (2,3), (4,5) in file order
check_cube() { # check_cube TABLE TOL WHAT
  awk -F'\t' -v opp="$opp" -v adj="$adj" -v tol="$2" '
    function abs(x) { return x < 0 ? -x : x }
    NR == 1 { next }
    { S = $1; K = $2; F = $3 + 0; sum[S] += F; n++
      if (S == K) { if (F != 0) bad++; next }
      want = (int(S / 2) == int(K / 2)) ? opp : adj
      if (abs(F - want) > tol) bad++ }
    END { for (S in sum) if (abs(sum[S] - 1) > tol) bad++
          exit !(n == 36 && bad == 0) }' "$1"
  ok $? "$3: 36 pairs, opposite $opp, adjacent $adj, self 0, rows sum to 1, within $2"
}

"$RADIOSITY" formfactor -q --per-surface --mesh 3x3 -o "$work/d.tsv" "$cube"; ok $? "--per-surface exits 0"
[ "$(head -n 1 "$work/d.tsv")" = "$(printf 'S\tK\tF\terror\tS_line\tK_line\tS_area')" ]
ok $? "header S K F error S_line K_line S_area"
check_cube "$work/d.tsv" 1e-9 "default accuracy, --mesh 3x3"
# the error column bounds the distance to the closed form (it sums the
# elements' estimated absolute errors)
awk -F'\t' -v opp="$opp" -v adj="$adj" 'NR > 1 && $1 != $2 {
    want = (int($1 / 2) == int($2 / 2)) ? opp : adj; d = $3 - want; if (d < 0) d = -d
    if (d > $4) bad++ } END { exit bad > 0 }' "$work/d.tsv"
ok $? "the error column bounds |F - closed form|"
# S_line and K_line: the lines of the quads in the scene file
cut -f1,5 "$work/d.tsv" | tail -n +2 | sort -u | awk -F'\t' '{ print $2 }' | sort -n > "$work/got"
awk '/^quad/ { print NR }' "$cube" | sort -n > "$work/want"
cmp -s "$work/got" "$work/want"; ok $? "S_line is the scene-file line of each quad"
awk -F'\t' 'NR > 1 { d = $7 - 1; if (d < 0) d = -d; if (d > 1e-15) bad++ } END { exit bad > 0 }' "$work/d.tsv"
ok $? "S_area = 1 for unit walls (within 1e-15)"

"$RADIOSITY" formfactor -q --per-surface --mesh 2x4 -o "$work/m.tsv" "$cube"
check_cube "$work/m.tsv" 1e-9 "default accuracy, --mesh 2x4 (additivity over another mesh)"
"$RADIOSITY" formfactor -q --per-surface --mesh 3x3 --accuracy reference -o "$work/r.tsv" "$cube"
check_cube "$work/r.tsv" 1e-12 "reference accuracy, --mesh 3x3"
"$RADIOSITY" formfactor -q --per-surface --accuracy reference -o "$work/r1.tsv" "$cube"
check_cube "$work/r1.tsv" 1e-12 "reference accuracy, the scene's 7x7 mesh"
done_testing
