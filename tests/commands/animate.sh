#!/bin/sh
# animate.sh -- `radiosity animate` against fresh solves of each frame's
# scene, written independently here (awk moves, turns, adds, removes and
# recolours the scene text); reversibility; the change file's errors.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
cd "$work" || exit 1

# A room (inward walls, an emitting ceiling), a floating box and an absent
# shade; coordinates are binary fractions, so moves are exact.
cat > room.scene <<'SCENE'
material white reflect 0.7 0.6 0.5
material red reflect 0.6 0.1 0.1
material lamp reflect 0.4 emit 2 1.5 1
material grey reflect 0.5
camera eye 0.5 0.5 -1.2 at 0.5 0.5 0.5 up 0 1 0 fov 50
quad red 0 0 0  0 1 0  0 1 1  0 0 1 mesh 3x3
quad white 1 0 0  1 0 1  1 1 1  1 1 0 mesh 3x3
quad white 0 0 0  0 0 1  1 0 1  1 0 0 mesh 3x3
quad lamp 0 1 0  1 1 0  1 1 1  0 1 1 mesh 3x3
quad white 0 0 0  1 0 0  1 1 0  0 1 0 mesh 3x3
quad white 0 0 1  0 1 1  1 1 1  1 0 1 mesh 3x3
object box
  quad grey 0.25 0.125 0.25  0.25 0.125 0.5  0.25 0.375 0.5  0.25 0.375 0.25 mesh 2x2
  quad grey 0.5 0.125 0.25  0.5 0.375 0.25  0.5 0.375 0.5  0.5 0.125 0.5 mesh 2x2
  quad grey 0.25 0.125 0.25  0.5 0.125 0.25  0.5 0.125 0.5  0.25 0.125 0.5 mesh 2x2
  quad grey 0.25 0.375 0.25  0.25 0.375 0.5  0.5 0.375 0.5  0.5 0.375 0.25 mesh 2x2
  quad grey 0.25 0.125 0.25  0.25 0.375 0.25  0.5 0.375 0.25  0.5 0.125 0.25 mesh 2x2
  quad grey 0.25 0.125 0.5  0.5 0.125 0.5  0.5 0.375 0.5  0.25 0.375 0.5 mesh 2x2
end
object shade absent
  quad grey 0.375 0.75 0.375  0.625 0.75 0.375  0.625 0.75 0.625  0.375 0.75 0.625 mesh 2x2
  quad grey 0.375 0.75 0.375  0.375 0.75 0.625  0.625 0.75 0.625  0.625 0.75 0.375 mesh 2x2
end
SCENE

# xform OBJ MODE ARGS < scene > scene: move (dx dy dz) or rotate about the
# z axis (degrees cx cy) the quads of OBJ; quads only, as in room.scene.
xform() {
  awk -v obj="$1" -v mode="$2" -v a="$3" -v b="$4" -v c="$5" '
    $1 == "object" { inside = ($2 == obj) }
    $1 == "end" { inside = 0 }
    inside && $1 == "quad" {
      line = "  quad " $2
      th = a * atan2(0, -1) / 180; cs = cos(th); sn = sin(th)
      for (k = 0; k < 4; k++) {
        x = $(3 + 3 * k); y = $(4 + 3 * k); z = $(5 + 3 * k)
        if (mode == "move") { x += a; y += b; z += c }
        else { vx = x - b; vy = y - c; x = b + vx * cs - vy * sn; y = c + vx * sn + vy * cs }
        line = line sprintf(" %.17g %.17g %.17g", x, y, z)
      }
      print line " " $15 " " $16; next
    }
    { print }'
}
presence() { # presence OBJ absent|present
  awk -v obj="$1" -v p="$2" '$1 == "object" && $2 == obj { print "object " obj (p == "absent" ? " absent" : ""); next } { print }'
}
recolour() { # recolour NAME NEW-DEFINITION-AFTER-NAME
  awk -v m="$1" -v d="$2" '$1 == "material" && $2 == m { print "material " m " " d; next } { print }'
}

# same A.tsv B.tsv TOL: same elements (centroids within 1e-12) and every
# band within TOL relative (of the larger of the two, or 1e-300)
same() {
  awk -F '\t' -v tol="$3" '
    FNR == 1 { for (k = 1; k <= NF; k++) col[$k] = k; next }
    FNR == NR { n++; for (k = 1; k <= NF; k++) A[n, k] = $k; next }
    { m++
      for (q = 0; q < 3; q++) { k = col["cx"] + q; d = A[m, k] - $k; if (d < 0) d = -d; if (d > 1e-12) geo = 1 }
      for (q = 0; q < 3; q++) { k = col["r"] + q; d = A[m, k] - $k; if (d < 0) d = -d
        s = A[m, k] < 0 ? -A[m, k] : A[m, k]; if (s < 1e-300) s = 1e-300; if (d / s > worst) worst = d / s } }
    END { printf "%d/%d elements, worst relative difference %.3g\n", n, m, worst
          exit !(n == m && n > 0 && !geo && worst <= tol) }' "$1" "$2"
}

cat > all.changes <<'EOF2'
# one change of each kind per frame
frame
move box 0.25 0 0.125
frame
rotate box 0 0 1 30 about 0.625 0.25 0.5
frame
add shade
frame
remove box
frame
material white reflect 0.5 0.6 0.7
material lamp reflect 0.4 emit 1 2 3
EOF2
cp room.scene s0.scene
xform box move 0.25 0 0.125 < s0.scene > s1.scene
xform box rotate 30 0.625 0.25 < s1.scene > s2.scene
presence shade present < s2.scene > s3.scene
presence box absent < s3.scene > s4.scene
recolour white "reflect 0.5 0.6 0.7" < s4.scene | recolour lamp "reflect 0.4 emit 1 2 3" > s5.scene

"$RADIOSITY" animate -q --tolerance 1e-12 --elements 'a%d.tsv' --report rep.json \
  --trace trace.tsv room.scene all.changes 2> err; rc=$?
ok $rc "animate runs 5 frames, one change of each kind (exit $rc)"
[ $rc -eq 0 ] || diag "$(head -c 300 err)"
what="given move rotate add remove material"
for f in 0 1 2 3 4 5; do
  kind=$(echo "$what" | awk -v f=$f '{ print $(f + 1) }')
  "$RADIOSITY" solve -q "s$f.scene" --elements "f$f.tsv" 2> /dev/null
  r=$(same "a$f.tsv" "f$f.tsv" 1e-9); rc=$?
  ok $rc "frame $f ($kind) equals a fresh solve of its scene within 1e-9: $r"
done
grep -q '"frame": 1, "shots": [0-9]*, "redistribution_shots": [1-9]' rep.json
ok $? "the report counts redistribution shots"
grep -q '"converged": false' rep.json; [ $? -ne 0 ]
ok $? "every frame converged"
grep -q '"pairs_recomputed"' rep.json && grep -q '"pairs_share"' rep.json
ok $? "the report says how many pairs were recomputed and their share"
# --reference also times the changed pairs alone (t_changed), on the
# side: the frames stay bit for bit those of the run without it.
"$RADIOSITY" animate -q --tolerance 1e-12 --reference --elements 'd%d.tsv' --report ref.json \
  --trace rtrace.tsv room.scene all.changes 2> /dev/null
ok $? "animate --reference runs"
# the trace's eq. 7 errors in frame 0 too (shot before rad_anim_create
# returns): the converged frame 0 ends on a fresh solve's B
r=$(awk -F '\t' '$1 == 0 { n++; if ($9 == "nan" || $10 == "nan") bad++; last = $9 }
      END { print n " rows, " bad + 0 " without an error, the last " last
            exit !(n > 0 && bad == 0 && last < 1e-9) }' rtrace.tsv)
ok $? "--trace --reference: frame 0's shots have their errors, the last below 1e-9: $r"
rc=0; for f in 0 1 2 3 4 5; do cmp -s "a$f.tsv" "d$f.tsv" || { rc=1; break; }; done
ok $rc "timing the changed pairs alone leaves every frame as it was"
# every frame after 0 changes pairs here (the material frame's lamp too:
# no pair, so its time is that of nothing, 0 or a few microseconds)
r=$(awk '/"frame": / {
      match($0, /"frame": [0-9]*/); f = substr($0, RSTART + 9, RLENGTH - 9) + 0
      match($0, /"pairs_changed": [0-9.e+-]*/); c = substr($0, RSTART + 17, RLENGTH - 17) + 0
      t = match($0, /"t_changed": null/) ? "null" : "time"
      if (t == "time") { match($0, /"t_changed": [0-9.e+-]*/); v = substr($0, RSTART + 13, RLENGTH - 13) + 0 }
      if (f == 0 ? t != "null" : t != "time" || (c > 0 && !(v > 0))) { print "frame " f ": changed " c ", t_changed " (t == "null" ? t : v); bad = 1 }
      n++ }
    END { if (n != 6) print n " frames"; exit bad || n != 6 }' ref.json) &&
  [ "$(grep -c '"t_changed": null' rep.json)" -eq 6 ]
ok $? "t_changed: a time in frames 1-5 (above 0 where pairs changed) with --reference, null in frame 0 and without $r"
# pairs_recomputed counts the pairs computed: both elements present.  An
# absent object that moves alters none; a removal leaves a share <= 1.
printf 'frame\nmove shade 0.125 0 0\n' > ghost.changes
"$RADIOSITY" animate -q --report ghost.json --elements 'g%d.tsv' room.scene ghost.changes 2> /dev/null &&
  grep -q '"frame": 1,.*"pairs_recomputed": 0,' ghost.json && cmp -s g0.tsv g1.tsv
ok $? "moving an absent object computes no pair and changes nothing"
r=$(awk '/"frame": / { match($0, /"pairs_share": [0-9.e+-]*/); v = substr($0, RSTART + 15, RLENGTH - 15) + 0
                      printf " %.3g", v; n++; if (v > 1) bad = 1 } END { exit bad || n != 6 }' rep.json) &&
  [ "$(grep -c '"pairs_share": [0-9]' rep.json)" -eq 6 ]
ok $? "every frame's pairs_share is at most 1 (the box's removal too):$r"
r=$(awk '/"frame": / { match($0, /"pairs_recomputed": [0-9.e+-]*/); p = substr($0, RSTART + 20, RLENGTH - 20) + 0
                      match($0, /"pairs_changed": [0-9.e+-]*/); c = substr($0, RSTART + 17, RLENGTH - 17) + 0
                      printf " %d/%d", c, p; n++; if (c > p) bad = 1 } END { exit bad || n != 6 }' rep.json)
ok $? "every frame's pairs_changed is among its pairs_recomputed (the box's removal too):$r"
head -n 1 trace.tsv | grep -q '^frame	step	shooter	kind	sign	power	unshot	redistribution_left	error	error_top1	gather$'
ok $? "the trace's header"
awk -F '\t' 'NR > 1 && $4 == "redistribute" && $5 == -1 { neg = 1 } NR > 1 && $4 == "redistribute" && $5 == 1 { pos = 1 } END { exit !(neg && pos) }' trace.tsv
ok $? "redistribution shoots both signs (newly visible and newly hidden)"

# redistribution by shooters only (the paper's) converges to the same frames
"$RADIOSITY" animate -q --no-gather --elements 'c%d.tsv' room.scene all.changes 2> /dev/null
r=$(same c3.tsv f3.tsv 1e-9); ok $? "--no-gather: the frame with the shade added equals a fresh solve: $r"
r=$(same c4.tsv f4.tsv 1e-9); ok $? "--no-gather: the frame with the box removed equals a fresh solve: $r"

# strategy 2 converges to the same frames
"$RADIOSITY" animate -q --strategy 2 --elements 'b%d.tsv' room.scene all.changes 2> /dev/null
r=$(same b2.tsv f2.tsv 1e-9); ok $? "strategy 2: the rotated frame equals a fresh solve: $r"
r=$(same b5.tsv f5.tsv 1e-9); ok $? "strategy 2: the recoloured frame equals a fresh solve: $r"

# reversibility: add then remove, move then move back
cat > back.changes <<'EOF2'
frame
add shade
frame
remove shade
frame
move box 0.25 0 0.125
frame
move box -0.25 0 -0.125
EOF2
"$RADIOSITY" animate -q --elements 'r%d.tsv' room.scene back.changes 2> /dev/null
ok $? "animate runs the reversals"
r=$(same r2.tsv r0.tsv 1e-10); ok $? "add then remove returns the original B within 1e-10: $r"
r=$(same r4.tsv r0.tsv 1e-10); ok $? "move then move back returns the original B within 1e-10: $r"
# A turn and its inverse leave the vertices a rounding error (1e-16) off:
# form factors are then recomputed on other doubles, and default mode's
# rule may take another route for a pair (within its promise of 1e-6);
# reference mode (1e-9) shows that the redistribution itself returns.
printf 'frame\nrotate box 1 1 0 40\nrotate box 1 1 0 -40\n' > turn.changes
"$RADIOSITY" animate -q --accuracy reference --elements 't%d.tsv' room.scene turn.changes 2> /dev/null
r=$(same t1.tsv t0.tsv 1e-10); ok $? "reference mode: a turn and its inverse in one frame return B within 1e-10: $r"

# partial frames: --steps K stops each frame after K shots
"$RADIOSITY" animate -q --steps 3 --report part.json --elements 'p%d.tsv' room.scene all.changes 2> /dev/null
ok $? "--steps 3 runs"
[ "$(grep -c '"shots": 3,' part.json)" -eq 5 ] && grep -q '"converged": false' part.json
ok $? "--steps 3: every later frame stops after 3 shots, unconverged"
r=$(same p0.tsv f0.tsv 1e-9); ok $? "--steps: frame 0 is still converged: $r"

# the change file's errors: FILE:LINE, before any work (no output written)
bad() { # bad DESCRIPTION CHANGES-TEXT EXPECTED-MESSAGE
  printf "$2" > bad.changes
  rm -f out0.tsv
  "$RADIOSITY" animate -q --elements 'out%d.tsv' room.scene bad.changes 2> err; rc=$?
  [ $rc -eq 1 ] && grep -q "^radiosity: bad.changes:$3" err && [ ! -e out0.tsv ]
  ok $? "$1: exit $rc, $(head -c 120 err)"
}
bad "unknown object" 'frame\nmove crate 1 0 0\n' "2: unknown object 'crate'"
bad "unknown material" 'frame\n\nmaterial glass reflect 0.5\n' "3: unknown material 'glass'"
bad "add of a present object" 'frame\nadd box\n' "2: cannot add object 'box'"
bad "remove of an absent object" 'frame\nremove shade\n' "2: cannot remove object 'shade'"
bad "presence followed through frames" 'frame\nadd shade\nframe\nremove shade\nframe\nremove shade\n' "6: cannot remove"
bad "zero rotation axis" 'frame\nrotate box 0 0 0 45\n' "2: the rotation axis must not be zero"
for axis in '0 0 1e300' '1e300 1e300 1e300' '0 0 1e-300'; do
  printf 'frame\nrotate box %s 90\n' "$axis" > axis.changes
  "$RADIOSITY" animate -q room.scene axis.changes > /dev/null 2> err
  ok $? "rotation axis $axis is an axis, not zero ($(head -c 80 err))"
done
bad "bad number" 'frame\nmove box 1 O 0\n' "2: 'O' is not a number"
bad "missing argument" 'frame\nrotate box 0 0 1\n' "2: missing number"
"$RADIOSITY" animate room.scene > /dev/null 2> err; [ $? -eq 2 ]
ok $? "animate without a change file is a usage error"
"$RADIOSITY" animate --strategy 3 room.scene all.changes > /dev/null 2> err; [ $? -eq 2 ]
ok $? "--strategy 3 is a usage error"
"$RADIOSITY" animate --exposure-from lamps room.scene all.changes > /dev/null 2> err; [ $? -eq 2 ]
ok $? "--exposure-from lamps is a usage error"
"$RADIOSITY" animate --help | grep -q -- --exposure-from; ok $? "animate --help lists --exposure-from"
"$RADIOSITY" animate --frames 'x.png' room.scene all.changes > /dev/null 2> err; [ $? -eq 2 ]
ok $? "--frames without an integer conversion is a usage error"
for p in 'x%d%d.png' 'x%s.png' 'x%n.png' 'x%ld.png' 'x%*d.png' 'x%' 'x%%d.png' 'x%2147483648d.png' 'x%100d.png'; do
  "$RADIOSITY" animate --elements "$p" room.scene all.changes > /dev/null 2> err; rc=$?
  [ $rc -eq 2 ] && [ -z "$(ls | grep '^x')" ]
  ok $? "--elements '$p' is a usage error (exit $rc) and writes nothing"
done
# two outputs naming one file: refused before the work, nothing written
"$RADIOSITY" animate -q --elements 'same%d.x' --frames 'same%d.x' room.scene all.changes > /dev/null 2> err
rc=$?; [ $rc -eq 1 ] && grep -q "same0.x: named by two outputs" err && [ -z "$(ls | grep '^same')" ]
ok $? "--elements and --frames naming the same files: exit $rc, $(head -c 80 err)"
"$RADIOSITY" animate -q --elements 'same%d.x' --trace same1.x room.scene all.changes > /dev/null 2> err
rc=$?; [ $rc -eq 1 ] && grep -q "same1.x: named by two outputs" err
ok $? "--trace naming a frame's table: exit $rc"
"$RADIOSITY" animate -q --errors same.x --log same.x room.scene all.changes > /dev/null 2> err
rc=$?; [ $rc -eq 1 ] && grep -q "same.x: named by two outputs" err && [ ! -e same.x ]
ok $? "--errors and --log naming one file: exit $rc, nothing written"
# solve's options, where they mean something for animate
"$RADIOSITY" animate -q --solver progressive --form-factors-method contour --elements 'o%d.tsv' \
  --tolerance 1e-12 room.scene all.changes 2> /dev/null && cmp -s o5.tsv a5.tsv
ok $? "--solver progressive --form-factors-method contour: accepted, the same frames"
"$RADIOSITY" animate -q --solver gauss room.scene all.changes 2> err; rc=$?
[ $rc -eq 2 ] && grep -q "takes only progressive" err
ok $? "--solver gauss: a usage error (exit $rc)"
"$RADIOSITY" animate -q --form-factors-method hemicube room.scene all.changes 2> err; rc=$?
[ $rc -eq 2 ] && grep -q "takes only contour" err
ok $? "--form-factors-method hemicube: a usage error (exit $rc)"
"$RADIOSITY" animate -q --max-iterations 7 --report mi.json room.scene all.changes 2> err; rc=$?
[ $rc -eq 1 ] && grep -q "frame 0: not converged after 7 shots" err && [ ! -e mi.json ]
ok $? "--max-iterations 7: frame 0 gives up after 7 shots (exit $rc), no report"
# the report's file names are JSON strings (RFC 8259, section 7: quote
# and backslash escaped)
cp room.scene 'q"b\\s.scene'
"$RADIOSITY" animate -q --report q.json 'q"b\\s.scene' all.changes 2> /dev/null &&
  grep -qF '"scene": "q\"b\\\\s.scene",' q.json
ok $? "--report: a scene name with a quote and two backslashes is escaped"
# a path that does not fit is refused before any work, never truncated
long=$(awk 'BEGIN { for (k = 0; k < 1400; k++) printf "d/."; }')
mkdir d && "$RADIOSITY" animate -q --elements "$long/x%d.tsv" room.scene all.changes > /dev/null 2> err
rc=$?; [ $rc -eq 1 ] && grep -q "makes a path of more than" err && [ -z "$(ls d)" ]
ok $? "an --elements path longer than 4095 bytes: exit $rc, $(head -c 100 err)"

# a run that fails at frame 2 replaces no file of frames 0 and 1 and
# leaves no temporary behind: the frames are renamed together at the end
mkdir keep && echo precious > keep/f0.tsv && echo precious > keep/f1.tsv
printf 'frame\nmove box 0.125 0 0\nframe\nmove box 1e300 0 0\n' > fail2.changes
"$RADIOSITY" animate -q --elements keep/f%d.tsv --trace keep/trace.tsv room.scene fail2.changes 2> err
rc=$?; [ $rc -eq 1 ] && [ "$(cat keep/f0.tsv keep/f1.tsv)" = "$(printf 'precious\nprecious')" ] &&
  [ "$(ls keep | tr '\n' ' ')" = "f0.tsv f1.tsv " ]
ok $? "a failure at frame 2: exit $rc, frames 0 and 1 kept, no temporary ($(ls keep | tr '\n' ' '))"
grep -q "^radiosity: fail2.changes:4: frame 2: " err
ok $? "the failure is the change file's, at its line: $(head -c 120 err)"

n=$(awk 'END { print NR - 1 }' f0.tsv)
ok $([ "$n" -eq 78 ]; echo $?) "solve leaves the absent shade out ($n elements: 54 walls, 24 box)"
# the change log (George et al. 1990, Fig. 5): partial frames carry their
# pending redistribution on; the frame that converges after them equals a
# fresh solve of its scene
"$RADIOSITY" animate -q --steps 3 --converge-last --elements 'l%d.tsv' --errors errs.tsv \
  --log all.log room.scene all.changes 2> err; rc=$?
ok $rc "--steps 3 --converge-last runs (exit $rc)"
r=$(same l5.tsv f5.tsv 1e-9); ok $? "--steps 3, last frame converged: equals a fresh solve within 1e-9: $r"
printf 'frame\nmove box 0.125 0 0\nframe\nmove box 0.125 0 0\nframe\nmove box 0.125 0 0\n' > moves.changes
xform box move 0.375 0 0 < room.scene > m3.scene
"$RADIOSITY" solve -q m3.scene --elements m3.tsv 2> /dev/null
"$RADIOSITY" animate -q --steps 2 --converge-last --elements 'mv%d.tsv' room.scene moves.changes 2> /dev/null
r=$(same mv3.tsv m3.tsv 1e-9); ok $? "three moves, 2 shots each, then converged: a fresh solve within 1e-9: $r"
# The log's final pass (after partial frames, from frame 0 on here) goes
# on numbering the frame's shots, and has --max-iterations of its own.
"$RADIOSITY" animate -q --from-scratch --steps 3 --converge-last --tolerance 1e-14 \
  --trace fp.tsv --report fp.json room.scene all.changes 2> /dev/null
n=$(awk '/"frame": 5,/ { match($0, /"shots": [0-9]*/); print substr($0, RSTART + 9, RLENGTH - 9) }' fp.json)
r=$(awk -F '\t' -v n="$n" '$1 == 5 { k++; if ($2 != k) bad = 1 }
      END { print k " rows, " n " shots"; exit !(k > 0 && k == n && !bad) }' fp.tsv) &&
  grep -q '"frame": 5,.*"log_pass": true' fp.json
ok $? "the final pass numbers its shots on: frame 5's trace steps are 1..N: $r"
"$RADIOSITY" animate -q --from-scratch --steps 3 --converge-last --tolerance 1e-14 \
  --max-iterations $((n - 1)) --elements 'fp%d.tsv' room.scene all.changes 2> err; rc=$?
ok $rc "--max-iterations $((n - 1)) (the frame's $n shots less one, the pass's shots apart): exit $rc $(head -c 100 err)"
head -n 1 errs.tsv | grep -q '^frame	shots	seconds	pairs_recomputed	pairs_share	error	error_top1$'
ok $? "--errors: the header"
awk -F '\t' 'NR > 1 { n++; if ($1 != n - 1) bad = 1 } END { exit !(n == 6 && !bad) }' errs.tsv
ok $? "--errors: one row per frame"
awk -F '\t' 'NR == 7 { exit !($2 > 0 && $6 >= 0 && $6 <= 1e-9) } NR > 1 && NR < 7 && $2 == 3 && !($6 > 0) { exit 1 }' errs.tsv
ok $? "--errors: partial frames have an error, the converged last frame none (<= 1e-9, as the fresh solve above)"

# an interrupted animation resumes from its log: the frames after equal
# the uninterrupted run's within 1e-10
awk '/^frame/ { n++ } n <= 2' all.changes > first2.changes
"$RADIOSITY" animate -q --steps 3 --log two.log room.scene first2.changes 2> /dev/null
ok $? "the first two frames, with --log"
# the log after two partial frames holds pending redistribution, one
# entry per pair (the series of changes merged), and the final pass ran
awk '$1 == "pending" { m = $2; on = 1; next } $1 == "end" { on = 0 }
     on { k++; if (seen[$1 " " $2]++) dup = 1 }
     END { exit !(m > 0 && k == m && !dup) }' two.log
ok $? "the log after partial frames: pending entries, one per pair"
"$RADIOSITY" animate -q --steps 3 --converge-last --resume two.log --elements 'z%d.tsv' \
  room.scene all.changes 2> err; rc=$?
ok $rc "--resume from frame 2 runs (exit $rc)"
[ ! -e z2.tsv ] && [ -e z3.tsv ]; ok $? "--resume runs the frames after the log's only"
for f in 3 4 5; do
  r=$(same "z$f.tsv" "l$f.tsv" 1e-10); ok $? "resumed frame $f equals the uninterrupted run's within 1e-10: $r"
done
r=$(same z5.tsv f5.tsv 1e-9); ok $? "the resumed last frame equals a fresh solve within 1e-9: $r"
"$RADIOSITY" animate -q --resume room.scene room.scene all.changes 2> err; rc=$?
[ $rc -eq 1 ] && grep -q '^radiosity: room.scene:1: not an animation log' err
ok $? "--resume of a file that is no log: exit $rc, $(head -c 100 err)"
# the paper's importance estimate orders the shots differently; converged
# frames are the same fresh solves
"$RADIOSITY" animate -q --importance paper --elements 'ip%d.tsv' room.scene all.changes 2> err; rc=$?
ok $rc "--importance paper runs (exit $rc)"
r=$(same ip1.tsv f1.tsv 1e-9); ok $? "--importance paper: the moved frame equals a fresh solve: $r"
r=$(same ip3.tsv f3.tsv 1e-9); ok $? "--importance paper: the frame with the shade added equals a fresh solve: $r"
"$RADIOSITY" animate -q --importance paper --steps 2 --converge-last --elements 'iq%d.tsv' room.scene moves.changes 2> /dev/null
r=$(same iq3.tsv m3.tsv 1e-9); ok $? "--importance paper, three partial moves then converged: a fresh solve: $r"
"$RADIOSITY" animate --importance guess room.scene all.changes > /dev/null 2> err; [ $? -eq 2 ]
ok $? "--importance guess is a usage error"
# a per-frame pattern must make files: frame 1's path here is a FIFO (were
# it opened, the run would block with no reader: timeout ends it)
mkfifo fifo1.tsv
timeout 60 "$RADIOSITY" animate -q --elements 'fifo%d.tsv' room.scene all.changes 2> err; rc=$?
[ $rc -eq 1 ] && grep -q "frame 1's path 'fifo1.tsv' names a descriptor, device or FIFO" err &&
  [ ! -e fifo0.tsv ] && [ -p fifo1.tsv ]
ok $? "--elements whose frame 1 is a FIFO: refused before any frame (exit $rc), $(head -c 100 err)"
rm -f fifo1.tsv
# a damaged log is refused naming its line, before any frame is written
badlog() { # badlog DESCRIPTION EXPECTED-MESSAGE (the log in bad.log)
  rm -f y3.tsv
  "$RADIOSITY" animate -q --resume bad.log --elements 'y%d.tsv' room.scene all.changes 2> err; rc=$?
  [ $rc -eq 1 ] && grep -q "^radiosity: bad.log:$2" err && [ ! -e y3.tsv ]
  ok $? "$1: exit $rc, $(head -c 120 err)"
}
head -n 50 two.log > bad.log; badlog "a log cut short" "51: the state ends early"
sed 's/^elements	86$/elements	85/' two.log > bad.log; badlog "another element count" "3: 85 elements, the scene has 86"
sed '12s/^\([0-9]*	[01]	\)[^	]*/\1x/' two.log > bad.log; badlog "a bad number" "12: expected"
sed 's/^changed	box$/changed	crate/' two.log > bad.log; badlog "an unknown object" "7: unknown object"
sed 's/^frame	2$/frame	9/' two.log > bad.log; badlog "a frame beyond the change file" "2: frame 9 is beyond"

# Classic mode: a pair the moved box cannot block, but whose surfaces have
# the box among their candidate blockers, is integrated on other cells by
# a fresh fill; classic has no estimate to keep that within, so such pairs
# are recomputed too (animpairs.c), unless the pair's own route (snap and
# shaft blockers) is the same before and after.  Before that, frames 2
# and 5 of the Cornell moving box were 8e-8 and 1e-6 off fresh classic
# solves; every frame is checked (the box crosses the room).
cmb="$top_srcdir/data/cornell-moving-box.scene"
"$RADIOSITY" animate -q --accuracy classic --elements 'cm%d.tsv' "$cmb" \
  "$top_srcdir/data/cornell-moving-box.changes" 2> /dev/null; rc=$?
ok $rc "animate --accuracy classic, the Cornell moving box (exit $rc)"
for k in 1 2 3 4 5 6 7 8 9 10; do
  xform box move $((40 * k)) 0 0 < "$cmb" > cmb$k.scene
  "$RADIOSITY" solve -q --accuracy classic --elements cf$k.tsv cmb$k.scene 2> /dev/null
  r=$(same cm$k.tsv cf$k.tsv 1e-9); ok $? "classic, frame $k equals a fresh classic solve: $r"
done
# ... every kind of change in classic mode (the turn, the shade that comes
# and the box that goes renumber the scenes the routes are read in).
# Frames 1, 4 and 5 are exact in binary, so their scene text here is the
# program's scene to the bit.  Frames 2 and 3 hold the turned box, whose
# vertices awk here and the program round differently (1 ulp), and
# classic, with no estimate, moves by 6e-7 on that; so frame 3 is checked
# against F filled afresh on the program's own frame-2 scene instead: the
# change log's resume (animlog.c) fills F anew, then adds the shade.
"$RADIOSITY" animate -q --accuracy classic --tolerance 1e-12 --elements 'ca%d.tsv' \
  room.scene all.changes 2> /dev/null
ok $? "animate --accuracy classic, one change of each kind"
for f in 1 4 5; do
  "$RADIOSITY" solve -q --accuracy classic --elements "cs$f.tsv" "s$f.scene" 2> /dev/null
  r=$(same "ca$f.tsv" "cs$f.tsv" 1e-9); ok $? "classic, frame $f of the room equals a fresh classic solve: $r"
done
awk '/^frame/ { n++ } n <= 2' all.changes > turn2.changes
"$RADIOSITY" animate -q --accuracy classic --tolerance 1e-12 --log turn2.log room.scene \
  turn2.changes 2> /dev/null &&
  "$RADIOSITY" animate -q --accuracy classic --tolerance 1e-12 --resume turn2.log \
    --elements 'cr%d.tsv' room.scene all.changes 2> /dev/null
r=$(same cr3.tsv ca3.tsv 1e-12); ok $? "classic, frame 3 after the turn: as with F filled afresh at frame 2: $r"
# ... and a pair whose blockers lose a block's faces when a moved fin meets
# the block's top edge at a fold: the fold makes the block's faces one
# group, which is not convex, so the block is no longer a solid
# (occsolid.c), and pairs that never list the fin change their route.
# The scene: the room's materials, camera, side and back walls and lamp;
# a floor and a front wall in pieces around a block; the fin.
{ sed -n '1,7p;9,10p' room.scene; cat <<'SCENE'
quad white 0 0 1  0 0.5 1  0.375 0.5 1  0.375 0 1 mesh 2x2
quad white 0.375 0 1  0.375 0.5 1  1 0.5 1  1 0 1 mesh 2x2
quad white 0 0.5 1  0 1 1  1 1 1  1 0.5 1 mesh 3x2
quad white 0 0 0  0 0 0.25  0.375 0 0.25  0.375 0 0 mesh 2x2
quad white 0.375 0 0  0.375 0 0.25  1 0 0.25  1 0 0 mesh 2x2
quad white 0 0 0.25  0 0 1  0.25 0 1  0.25 0 0.25 mesh 2x2
quad white 0.5 0 0.25  0.5 0 1  1 0 1  1 0 0.25 mesh 2x2
quad white 0.25 0 0.5  0.25 0 1  0.5 0 1  0.5 0 0.5 mesh 2x2
quad grey 0.25 0 0.25  0.25 0 0.5  0.25 0.25 0.5  0.25 0.25 0.25 mesh 2x2
quad grey 0.5 0 0.25  0.5 0.25 0.25  0.5 0.25 0.5  0.5 0 0.5 mesh 2x2
quad grey 0.25 0.25 0.25  0.25 0.25 0.5  0.5 0.25 0.5  0.5 0.25 0.25 mesh 2x2
quad grey 0.25 0 0.25  0.25 0.25 0.25  0.5 0.25 0.25  0.5 0 0.25 mesh 2x2
quad grey 0.25 0 0.5  0.5 0 0.5  0.5 0.25 0.5  0.25 0.25 0.5 mesh 2x2
object fin
  quad grey 0.75 0.25 0.5  0.75 0.25 0.75  0.875 0.1875 0.75  0.875 0.1875 0.5 mesh 1x1
end
SCENE
} > fin.scene
printf 'frame\nmove fin -0.25 0 -0.25\n' > fin.changes
"$RADIOSITY" animate -q --accuracy classic --elements 'fn%d.tsv' fin.scene fin.changes 2> /dev/null &&
  xform fin move -0.25 0 -0.25 < fin.scene > fin1.scene &&
  "$RADIOSITY" solve -q --accuracy classic --elements ff1.tsv fin1.scene 2> /dev/null
r=$(same fn1.tsv ff1.tsv 1e-9); ok $? "classic, a fin moved onto a block's edge: a fresh classic solve: $r"
done_testing
