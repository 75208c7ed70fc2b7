#!/bin/sh
# eq14.sh -- the RMS error of Cohen et al. 1988, eq. 14, in `progress`'s
# table and `solve --trace`: `rms` (and each method's column) is the RMS of
# the band-averaged radiosity, `*_bands` the per-band RMS averaged over
# the bands.  Copyright (C) 2026 The radiosity authors.  GPLv3+, see
# COPYING.
#
# Independent references: a fresh gauss solve (the element table) and
# identities of the first steps.
#   - progress, step 0: every method shows B = E, so its error is that of
#     E against the gauss B; E is known from the scene written here.
#   - the trace of two facing squares, step 1: the lamp (element 0) shoots
#     first, so B_1 = rho_1 F_10 E_0 while gauss has B*_1 = rho_1 F_10 B*_0:
#     B_1 = B*_1 E_0 / B*_0 per band, and B_0 = E_0.
# The scenes are coloured so that the two readings differ by far more
# than the tolerance (1e-9 relative: %.17g output and sums of 4 terms).
. "${top_srcdir:-.}/tests/lib.sh"

# eq. 14 both ways from columns: AREA then three differences per element
# on stdin; prints "eq14 bands"
rms2() {
  awk '{ a[NR] = $1; for (b = 1; b <= 3; b++) d[NR, b] = $(b + 1); A += $1 }
    END { for (i = 1; i <= NR; i++) { m = (d[i, 1] + d[i, 2] + d[i, 3]) / 3; s += a[i] * m * m
                                      for (b = 1; b <= 3; b++) sb[b] += a[i] * d[i, b] * d[i, b] }
          printf "%.17g %.17g\n", sqrt(s / A), (sqrt(sb[1] / A) + sqrt(sb[2] / A) + sqrt(sb[3] / A)) / 3 }'
}
col() { # col FILE ROW NAME: the value of column NAME in data row ROW (1 = first)
  awk -F '\t' -v r="$2" -v n="$3" 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
    NR == r + 1 { print $c[n] }' "$1"
}

# ---- progress, step 0: a red lamp under one grey wall, a blue lamp under
# another: the red error lies on one wall, the blue on the other
cat > "$work/pairs.scene" <<'SCENE'
material red  reflect 0 emit 1 0 0
material blue reflect 0 emit 0 0 1
material grey reflect 0.5
quad red  0 0 0  1 0 0  1 1 0  0 1 0
quad grey 0 0 1  0 1 1  1 1 1  1 0 1
quad blue 5 0 0  6 0 0  6 1 0  5 1 0
quad grey 5 0 1  5 1 1  6 1 1  6 0 1
SCENE
"$RADIOSITY" solve -q --elements "$work/pairs.tsv" "$work/pairs.scene"
ok $? "gauss solve of the two lamps"
"$RADIOSITY" progress -q --steps 2 -o "$work/race.tsv" "$work/pairs.scene"
ok $? "progress on the two lamps"
# differences E - B*: E is red (1,0,0) on element 0, blue on element 2
set -- $(awk -F '\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { OFMT = "%.17g"; e = $c["element"]; er = e == 0; eb = e == 2
    print $c["area"], er - $c["r"], 0 - $c["g"], eb - $c["b"] }' "$work/pairs.tsv" | rms2)
want=$1 want_bands=$2
diag "step 0 by hand: eq. 14 $want, per band $want_bands"
awk -v a="$want" -v b="$want_bands" 'BEGIN { exit !(b > 1.2 * a) }'
ok $? "the two readings differ here by more than 20% ($want, $want_bands)"
for m in gathering shooting sorted; do
  got=$(col "$work/race.tsv" 1 "$m") gotb=$(col "$work/race.tsv" 1 "${m}_bands")
  close_to "$got" "$want" 1e-9; ok $? "step 0 $m is eq. 14 of E against gauss ($got)"
  close_to "$gotb" "$want_bands" 1e-9; ok $? "step 0 ${m}_bands is the per-band mean ($gotb)"
done

# ---- solve --trace, step 1: two facing squares, a coloured lamp and wall
cat > "$work/two.scene" <<'SCENE'
material lamp reflect 0.5 0.1 0.9 emit 1 1 1
material wall reflect 0.9 0.1 0.5
quad lamp 0 0 0  1 0 0  1 1 0  0 1 0
quad wall 0 0 1  0 1 1  1 1 1  1 0 1
SCENE
"$RADIOSITY" solve -q --elements "$work/g.tsv" "$work/two.scene"
"$RADIOSITY" solve -q --solver progressive --trace "$work/trace.tsv" -o "$work/p.ply" "$work/two.scene"
ok $? "progressive solve with a trace"
set -- $(awk -F '\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { a[NR] = $c["area"]; r[NR] = $c["r"]; g[NR] = $c["g"]; b[NR] = $c["b"] }
  END { OFMT = "%.17g" # B(1) - B*: element 0 at E = 1; element 1 at B*_1 / B*_0
    print a[2], 1 - r[2], 1 - g[2], 1 - b[2]
    print a[3], r[3] / r[2] - r[3], g[3] / g[2] - g[3], b[3] / b[2] - b[3] }' "$work/g.tsv" | rms2)
want=$1 want_bands=$2
got=$(col "$work/trace.tsv" 1 rms) gotb=$(col "$work/trace.tsv" 1 rms_bands)
[ "$(col "$work/trace.tsv" 1 shooter)" = 0 ]; ok $? "step 1 shoots the lamp"
close_to "$got" "$want" 1e-9; ok $? "trace rms after step 1 is eq. 14 ($got, by hand $want)"
close_to "$gotb" "$want_bands" 1e-9; ok $? "trace rms_bands after step 1 is the per-band mean ($gotb, by hand $want_bands)"
awk -v a="$want" -v b="$want_bands" 'BEGIN { d = (b - a) / a; exit !(d > 1e-6) }'
ok $? "and the two differ by far more than the tolerance"
done_testing
