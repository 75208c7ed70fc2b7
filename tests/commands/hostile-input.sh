#!/bin/sh
# hostile-input.sh -- scene, OBJ, View3D and PLY files that try to hurt the
# program: each case gives the input, the exit status expected and a
# pattern the first line of standard error must match.
# Bounded resources are part of the contract: /dev/zero and endless pipes
# are refused at once under a memory limit, and a pipe's first error is
# reported before the pipe ends.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

M='material w reflect 0.5\n'
Q1='quad w 0 0 0  1 0 0  1 1 0  0 1 0'
Q2='quad w 0 0 1  0 1 1  1 1 1  1 0 1'

# case NAME STATUS PATTERN TEXT: write TEXT (printf %b) to NAME.scene (to
# NAME itself when it has a suffix, such as x.obj or x.vs3), run
# formfactor on it; the exit status must be STATUS and the first line of
# standard error must match "radiosity: FILE:PATTERN" (a shell pattern;
# empty PATTERN: standard error must be empty).
case_() {
  case $1 in *.*) f="$work/$1" ;; *) f="$work/$1.scene" ;; esac
  printf '%b' "$4" > "$f"
  "$RADIOSITY" formfactor "$f" > "$work/out" 2> "$work/err"; rc=$?
  msg=$(head -n 1 "$work/err")
  if [ -z "$3" ]; then
    [ "$rc" -eq "$2" ] && [ -z "$msg" ]; ok $? "$1: exit $rc (want $2), no message ${msg:+(got: $msg)}"
  else
    case "$msg" in "radiosity: $f:"$3) m=0 ;; *) m=1 ;; esac
    [ "$rc" -eq "$2" ] && [ $m -eq 0 ]; ok $? "$1: exit $rc (want $2): $msg"
  fi
}
rows() { tail -n +2 "$work/out" | wc -l | tr -d ' '; }

# ---- bytes, line ends, encodings ----
case_ bom 0 '' "\357\273\277$M$Q1\n$Q2\n"
[ "$(rows)" -eq 2 ]; ok $? "bom: both quads read ($(rows) pairs)"
case_ bom-only 1 '1: the scene has no surfaces*' '\357\273\277'
case_ bom-twice 1 '1: non-ASCII character (byte 0xEF at column 1*' "\357\273\277\357\273\277$M$Q1\n"
case_ crlf 0 '' "$M\r\n$Q1\r\n$Q2\r\n"
[ "$(rows)" -eq 2 ]; ok $? "crlf: both quads read"
case_ cr-only 0 '' "${M%\\n}\r$Q1\r$Q2\r"
[ "$(rows)" -eq 2 ]; ok $? "cr-only: both quads read"
case_ cr-only-error 1 '3: unknown keyword '"'frob'"'*' "${M%\\n}\r$Q1\rfrob\r$Q2\r"
case_ mixed-ends 1 '5: unknown keyword*' "${M%\\n}\r\n$Q1\r$Q2\n\nfrob\n"
case_ nbsp 1 '2: non-ASCII character (byte 0xC2 at column 13, a UTF-8 no-break space U+00A0?)*' "${M}quad w 0 0 0\302\240 1 0 0  1 1 0  0 1 0\n"
case_ latin1 1 '1: non-ASCII character (byte 0xE9 at column 13)*' 'material caf\351 reflect 0.5\n'
case_ utf8-name 1 '1: non-ASCII character (byte 0xC3*' 'material caf\303\251 reflect 0.5\n'
case_ utf8-comment 0 '' "# Cornell box \342\200\224 caf\303\251\n$M$Q1 # \302\240\n"
case_ escape 1 '2: control character (byte 0x1B*' "${M}quad w 0 0 0  1 0 0  1 1 0  0 1 \033[31m0\n"
case_ backspace 1 '2: control character (byte 0x08*' "${M}quad\010 w\n"
case_ nul 1 '2: line contains a NUL character*' "$M\000$Q1\n"
case_ nul-late 1 '3: line contains a NUL character (byte 0x00 at column 5)*' "$M$Q1\nquad\000\n"
case_ tab-ff-vt 0 '' "material\tw\freflect\v0.5\n$Q1\n"
case_ no-final-newline 0 '' "$M$Q1"
case_ empty 1 '1: the scene has no surfaces*' ''
case_ blank-lines 1 '4: the scene has no surfaces*' '\n\n  \n\t\n'
case_ comments-only 1 '2: the scene has no surfaces*' '# a\n# b\n'
case_ utf16 1 '1: line contains a NUL character (byte 0x00 at column 4; a UTF-16 file?*' '\377\376m\000a\000'

# ---- numbers and words ----
case_ reflect-suffix 1 "1: '0.5abc' is not a number (reflectance)*" 'material w reflect 0.5abc\n'
case_ reflect-comma 1 "1: '0,5' is not a number (reflectance)*" 'material w reflect 0,5\n'
case_ reflect-third 1 "1: '0.5x' is not a number (reflectance)*" 'material w reflect 0.5 0.5 0.5x\n'
case_ reflect-none 1 '1: reflectance needs 1 value (grey) or 3 (R G B)*' 'material w reflect\n'
case_ reflect-two 1 '1: reflectance takes 1 value (grey) or 3 (R G B), not 2*' 'material w reflect 0.5 0.5\n'
case_ reflect-four 1 '1: reflectance takes 1 value (grey) or 3 (R G B), not 4*' 'material w reflect 0.5 0.5 0.5 0.5\n'
case_ reflect-big 1 '1: reflectance must be from 0 to 1*' 'material w reflect 1.0000001\n'
case_ reflect-nan 1 '1: reflectance must be finite*' 'material w reflect nan\n'
case_ emit-inf 1 '1: emission must be finite*' 'material w reflect 0 emit inf\n'
case_ emit-overflow 1 '1: emission must be finite*' 'material w reflect 0 emit 1e400\n'
case_ emit-negative 1 '1: emission must not be negative*' 'material w reflect 0 emit -0.1\n'
case_ emit-suffix 1 "1: '1e' is not a number (emission)*" 'material w reflect 0 emit 1e\n'
case_ coordinate-word 1 "2: 'one' is not a number (vertex 2)*" "${M}quad w 0 0 0  one 0 0  1 1 0  0 1 0\n"
case_ coordinate-nan 1 '2: vertex 1 must be finite*' "${M}quad w nan 0 0  1 0 0  1 1 0  0 1 0\n"
case_ coordinate-huge 1 '2: vertex 3 must be finite*' "${M}quad w 0 0 0  1 0 0  1 1e999 0  0 1 0\n"
case_ hex-float 0 '' "material w reflect 0x1p-1\nquad w 0 0 0  0x1p0 0 0  1 1 0  0 1 0\n"
case_ name-number 1 "1: material name '1e3' looks like a number*" 'material 1e3 reflect 0.5\n'
case_ name-long 1 '1: material name is longer than 63 characters*' "material $(printf '%064d' 0 | tr 0 a) reflect 0.5\n"
case_ duplicate 1 "2: material 'w' is already defined (line 1)*" "$M$M"
case_ undefined 1 "1: undefined material 'w'*" "$Q1\n"
case_ keyword-case 1 "1: unknown keyword 'Material'*" 'Material w reflect 0.5\n'

# ---- sizes ----
case_ mesh-huge 1 '2: mesh 100000x100000 has 10000000000 elements; at most 100000000 per surface*' "$M$Q1 mesh 100000x100000\n"
case_ mesh-over 1 "2: mesh must be NxM with whole numbers from 1 to 100000, not '100001x1'*" "$M$Q1 mesh 100001x1\n"
case_ mesh-int-overflow 1 "2: mesh must be NxM*" "$M$Q1 mesh 99999999999999999999x1\n"
case_ mesh-negative 1 "2: mesh must be NxM*" "$M$Q1 mesh -3x3\n"
case_ mesh-total 1 '3: the scene would have 120000000 elements; at most 100000000*' "$M$Q1 mesh 10000x6000\n$Q2 mesh 10000x6000\n"
case_ polygon-many 1 '2: polygon vertex count must be from 3 to 4096*' "${M}polygon w 65536 0 0 0\n"
case_ polygon-int-overflow 1 '2: polygon vertex count must be from 3 to 4096*' "${M}polygon w 99999999999999999999 0 0 0\n"
case_ disk-many 1 '2: disk vertex count must be from 3 to 4096*' "${M}disk w 0 0 0  0 0 1  1 65536\n"
case_ polygon-short 1 '2: polygon of 4 vertices needs 12 numbers, found 9*' "${M}polygon w 4  0 0 0  1 0 0  1 1 0\n"
awk 'BEGIN { printf "material w reflect 0.5\npolygon w 4096"; for (k = 0; k < 4096; k++) { t = 6.283185307179586 * k / 4096; printf " %.17g %.17g 0", cos(t), sin(t) } printf "\n" }' > "$work/k4096.scene"
"$RADIOSITY" formfactor "$work/k4096.scene" > "$work/out" 2> "$work/err"; rc=$?
[ $rc -eq 0 ]; ok $? "a polygon of 4096 vertices at full precision ($(wc -c < "$work/k4096.scene") bytes on one line) is read: exit $rc $(head -n 1 "$work/err")"

# ---- geometry keeps its messages ----
case_ zero-area 1 '2: quad has zero area*' "${M}quad w 0 0 0  1 0 0  2 0 0  3 0 0\n"
case_ non-planar 1 '2: quad is not planar*' "${M}quad w 0 0 0  1 0 0  1 1 0.1  0 1 0\n"
case_ non-convex 1 '2: quad is not convex*' "${M}quad w 0 0 0  1 0 0  0.2 0.2 0  0 1 0\n"
case_ bow-tie 1 '2: quad is self-intersecting*' "${M}quad w 0 0 0  1 1 0  1 0 0  0 1 0\n"
case_ repeated 1 '2: quad has a repeated vertex*' "${M}quad w 0 0 0  1 0 0  1 0 0  0 1 0\n"
case_ disk-far 1 '2: disk is *' "${M}disk w 1e10 0 0  0 0 1  1e-3 4096\n"

# ---- lines too long, inputs without end ----
awk 'BEGIN { printf "material w reflect 0.5\n#"; for (k = 0; k < 1048576; k++) printf "x"; printf "\n" }' > "$work/longline.scene"
"$RADIOSITY" formfactor "$work/longline.scene" > "$work/out" 2> "$work/err"; rc=$?
msg=$(head -n 1 "$work/err")
case $msg in "radiosity: $work/longline.scene:2: line longer than 1048576 bytes"*) m=0 ;; *) m=1 ;; esac
[ $rc -eq 1 ] && [ $m -eq 0 ]; ok $? "a line of 1 MiB + 1 byte (even a comment) is refused on its line: $msg"

limited() { # run a command with 1 GB of address space and ${secs_max:-20} s at most
  if [ -n "${RADIOSITY_SANITIZE-}" ]; then
    # ASan cannot start under ulimit -v (it maps terabytes of shadow); its
    # own watchdog aborts past 1 GB resident instead, and the abort is a report
    ( ASAN_OPTIONS="${ASAN_OPTIONS-}:hard_rss_limit_mb=1000"; export ASAN_OPTIONS
      exec timeout "${secs_max:-20}" "$@" )
  else
    ( ulimit -v 1000000 2>/dev/null; exec timeout "${secs_max:-20}" "$@" )
  fi
}
start=$(date +%s)
limited "$RADIOSITY" formfactor /dev/zero > "$work/out" 2> "$work/err"; rc=$?
secs=$(( $(date +%s) - start )); msg=$(head -n 1 "$work/err")
case $msg in "radiosity: /dev/zero:1: line contains a NUL character"*) m=0 ;; *) m=1 ;; esac
[ $rc -eq 1 ] && [ $m -eq 0 ] && [ $secs -le 5 ]; ok $? "/dev/zero is refused in ${secs} s under 1 GB of memory: $msg"
limited "$RADIOSITY" solve /dev/zero > "$work/out" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q '^radiosity: /dev/zero:1: line contains a NUL' "$work/err"; ok $? "solve /dev/zero: exit $rc"
start=$(date +%s)
tr '\000' 'a' < /dev/zero | limited "$RADIOSITY" formfactor - > "$work/out" 2> "$work/err"; rc=$?
secs=$(( $(date +%s) - start )); msg=$(head -n 1 "$work/err")
case $msg in "radiosity: -:1: line longer than 1048576 bytes"*) m=0 ;; *) m=1 ;; esac
[ $rc -eq 1 ] && [ $m -eq 0 ] && [ $secs -le 5 ]; ok $? "an endless line on a pipe is refused in ${secs} s: $msg"
start=$(date +%s)
tr '\000' '\r' < /dev/zero | secs_max=5 limited "$RADIOSITY" formfactor - > "$work/out" 2> "$work/err"; rc=$?
msg=$(head -n 1 "$work/err")
# endless empty (CR-only) lines: refused at the 1 GiB input limit, or by the time limit
[ $rc -ne 0 ] && [ $rc -ne 139 ]; ok $? "endless empty lines on a pipe end with exit $rc, no crash: ${msg:-timeout}"

# the first error is reported while the pipe is still open
{ printf 'material w reflect 0.5\nfrob\n'; sleep 3; } | {
  s0=$(date +%s); "$RADIOSITY" formfactor - > /dev/null 2> "$work/err"; echo "$? $(( $(date +%s) - s0 ))" > "$work/rc"; }
read -r rc secs < "$work/rc"
[ "$rc" -eq 1 ] && [ "$secs" -le 1 ] && grep -q '^radiosity: -:2: unknown keyword' "$work/err"; ok $? "a pipe's error on line 2 is reported before the pipe ends (exit $rc after ${secs} s)"

# files that are not files
mkdir "$work/dir.scene"
"$RADIOSITY" formfactor "$work/dir.scene" > "$work/out" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q "^radiosity: $work/dir.scene: Is a directory" "$work/err"; ok $? "a directory: exit $rc, $(head -n 1 "$work/err")"
"$RADIOSITY" formfactor "$work/missing.scene" > "$work/out" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q "^radiosity: $work/missing.scene: No such file" "$work/err"; ok $? "a missing file: exit $rc"
printf "$M$Q1\n$Q2\n" | "$RADIOSITY" formfactor - > "$work/out" 2> "$work/err"; rc=$?
[ $rc -eq 0 ] && [ "$(rows)" -eq 2 ]; ok $? "standard input as a scene: exit $rc"

# ---- OBJ + MTL (the reader shares the scene file's line reader) ----
SQ='v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n'
case_ obj-good.obj 0 '' "${SQ}f 1 2 3 4\n"
case_ obj-crlf-bom.obj 0 '' "\357\273\277v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n"
case_ obj-nul.obj 1 '5: line contains a NUL character*' "${SQ}f 1 2\000 3\n"
case_ obj-utf16.obj 1 '1: line contains a NUL character (byte 0x00 at column 4; a UTF-16 file?*' '\377\376v\000 \000'
# a name beyond ASCII is taken byte for byte (a repair, said), and refused
# with --strict as before
case_ obj-utf8-name.obj 0 '5: repaired: 1 name with spaces, with bytes beyond ASCII, or empty*' "${SQ}o caf\303\251\nf 1 2 3\n"
"$RADIOSITY" formfactor --strict "$work/obj-utf8-name.obj" > "$work/out" 2> "$work/err"
[ $? -eq 1 ] && grep -q "obj-utf8-name.obj:5: non-ASCII character (byte 0xC3" "$work/err"
ok $? "obj-utf8-name.obj --strict: refused at line 5 ($(head -n 1 "$work/err"))"
case_ obj-utf8-ignored.obj 0 '' "${SQ}# caf\303\251\nvt 0 0 caf\303\251\ns caf\303\251\nf 1 2 3\n"
case_ obj-index-overflow.obj 1 "5: vertex must be from -2147483647 to 2147483647, not '99999999999999999999'*" "${SQ}f 99999999999999999999 1 2\n"
case_ obj-index-min.obj 1 '5: vertex index -2147483647, but 4 have been read*' "${SQ}f -2147483647 1 2\n"
case_ obj-corners.obj 1 '5: a face has at most 4096 corners, not 5000*' "${SQ}f$(awk 'BEGIN { for (k = 0; k < 5000; k++) printf " 1" }')\n"
case_ obj-face-first.obj 1 '1: vertex index 1, but 0 have been read*' "f 1 2 3\n$SQ"
case_ obj-freeform.obj 1 "1: free-form geometry ('cstype') is not supported*" 'cstype bspline\n'
case_ obj-call.obj 1 "1: unknown OBJ statement 'call'*" 'call /etc/passwd\n'
case_ obj-mtllib-missing.obj 1 "1: cannot read the material library: $work/none.mtl: No such file*" 'mtllib none.mtl\n'
case_ obj-mtllib-dir.obj 1 "1: cannot read the material library: $work/./: Is a directory*" 'mtllib ./\n'
case_ obj-mtllib-self.obj 1 "1: unknown MTL statement 'mtllib'*" 'mtllib obj-mtllib-self.obj\n'
printf 'newmtl w\nKd 0.5\n' > "$work/m.mtl"
case_ obj-mtllib-twice.obj 0 '' "mtllib m.mtl\nmtllib m.mtl m.mtl\nusemtl w\n${SQ}f 1 2 3\n"
printf 'newmtl w\nKd 0.5 \302\240\n' > "$work/nbsp.mtl"
printf 'mtllib nbsp.mtl\n' > "$work/obj-nbsp.obj"
"$RADIOSITY" formfactor "$work/obj-nbsp.obj" > "$work/out" 2> "$work/err"; rc=$?
grep -q "^radiosity: $work/nbsp.mtl:2: non-ASCII character (byte 0xC2" "$work/err"
[ $? -eq 0 ] && [ $rc -eq 1 ]; ok $? "an MTL error names the MTL file and its line: $(head -n 1 "$work/err")"
ln -s /dev/zero "$work/zero.mtl"
printf 'mtllib zero.mtl\n' > "$work/obj-zero.obj"
start=$(date +%s)
limited "$RADIOSITY" formfactor "$work/obj-zero.obj" > "$work/out" 2> "$work/err"; rc=$?
secs=$(( $(date +%s) - start ))
grep -q "^radiosity: $work/zero.mtl:1: line contains a NUL" "$work/err"
[ $? -eq 0 ] && [ $rc -eq 1 ] && [ $secs -le 5 ]; ok $? "mtllib naming /dev/zero is refused in ${secs} s: $(head -n 1 "$work/err")"
ln -s /dev/zero "$work/zero.obj"
limited "$RADIOSITY" solve "$work/zero.obj" > "$work/out" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q "^radiosity: $work/zero.obj:1: line contains a NUL" "$work/err"; ok $? "an OBJ name for /dev/zero: exit $rc"

# ---- View3D (the same line reader; nothing after End is read) ----
V3='V 1 0 0 0\nV 2 1 0 0\nV 3 1 1 0\nV 4 0 1 0\n'
case_ vs3-good.vs3 0 '' "T t\nC encl=1\nF 3\n${V3}S 1 1 2 3 4 0 0 0.5 a\nEnd\n"
case_ vs3-cr-only.vs3 0 '' "$(printf '%b' "${V3}S 1 1 2 3 4 0 0 0.5 a\n" | tr '\n' '\r')"
case_ vs3-after-end.vs3 0 '' "${V3}S 1 1 2 3 4 0 0 0.5 a\nEnd of data\n\000\377\376 V S O garbage\n"
case_ vs3-title-utf8.vs3 0 '' "T caf\303\251 \302\240\n${V3}S 1 1 2 3 4 0 0 0.5 a ! caf\303\251\n"
case_ vs3-nul.vs3 1 '5: line contains a NUL character*' "${V3}S 1\000 1 2 3 4 0 0 0.5 a\n"
case_ vs3-nbsp.vs3 1 '5: non-ASCII character (byte 0xC2*' "${V3}S 1 1 2 3 4 0 0\302\2400.5 a\n"
case_ vs3-number-overflow.vs3 1 "1: vertex number must be from 1 to 2147483647, not '99999999999999999999'*" 'V 99999999999999999999 0 0 0\n'
case_ vs3-vertex-ref.vs3 1 "5: vertex 4 of the surface must be from 0 to 4, not '2147483648'*" "${V3}S 1 1 2 3 2147483648 0 0 0.5\n"
case_ vs3-comma.vs3 1 "1: 'encl=1,list=2' holds a comma*" 'C encl=1,list=2\n'
case_ vs3-3a.vs3 1 '1: geometry format 3a (BLAST surfaces) is not supported*' 'F 3a\n'
case_ vs3-mask.vs3 1 '5: masking surfaces (M) are not supported*' "${V3}M 1 1 2 3 4 1 0 0.5\n"
case_ vs3-empty.vs3 1 '1: the View3D file has no surfaces*' ''
case_ vs3-unknown.vs3 1 "1: unknown View3D line 'Q'*" 'Q\n'
ln -s /dev/zero "$work/zero.vs3"
limited "$RADIOSITY" formfactor "$work/zero.vs3" > "$work/out" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q "^radiosity: $work/zero.vs3:1: line contains a NUL" "$work/err"; ok $? "a View3D name for /dev/zero: exit $rc"

# ---- PLY solutions given to render ----
ply_head='ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nproperty double radiosity_r\nproperty double radiosity_g\nproperty double radiosity_b\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
ply_data='0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n'
ply() { # ply NAME STATUS PATTERN TEXT
  f="$work/$1.ply"
  printf '%b' "$4" > "$f"
  rm -f "$work/p.png"
  "$RADIOSITY" render --eye 0.2,0.2,3 --at 0.2,0.2,0 --width 16 --height 16 -o "$work/p.png" "$f" > /dev/null 2> "$work/err"; rc=$?
  msg=$(head -n 1 "$work/err")
  if [ -z "$3" ]; then
    [ "$rc" -eq "$2" ] && [ -s "$work/p.png" ]; ok $? "PLY $1: exit $rc (want $2), picture written ${msg:+($msg)}"
  else
    case "$msg" in "radiosity: $f:"$3) m=0 ;; *) m=1 ;; esac
    [ "$rc" -eq "$2" ] && [ $m -eq 0 ] && [ ! -e "$work/p.png" ]; ok $? "PLY $1: exit $rc (want $2): $msg"
  fi
}
ply good 0 '' "$ply_head$ply_data"
ply crlf 0 '' "$(printf '%b' "$ply_head$ply_data" | sed 's/$/\r/')\n"
ply cr-only 0 '' "$(printf '%b' "$ply_head$ply_data" | tr '\n' '\r')"
ply bom 0 '' "\357\273\277$ply_head$ply_data"
ply utf8-comment 0 '' "ply\ncomment caf\303\251 \302\240\n${ply_head#ply\\n}$ply_data"
ply nbsp 1 '14: non-ASCII character (byte 0xC2*' "$ply_head${ply_data%%\\n*}\n1\302\2400 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n"
ply nul 1 '14: line contains a NUL character (byte 0x00 at column 2)*' "$ply_head${ply_data%%\\n*}\n1\0000 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n"
ply huge-count 1 "3: element 'vertex' count 400000000 is more than the rest of the file*" "$(printf '%b' "$ply_head" | sed 's/vertex 3/vertex 400000000/')\n$ply_data"
ply truncated 1 "15: unexpected end of file*" "$ply_head${ply_data%3 0 1 2\\n}"
ply big-face 1 '16: face 0 has 5000 vertices; a face needs 3 to 4096*' "$(printf '%b' "$ply_head" | sed 's/uchar int/ushort int/')\n${ply_data%3 0 1 2\\n}5000 0 1 2\n"
ply binary 1 '2: binary_little_endian PLY is not supported*' 'ply\nformat binary_little_endian 1.0\nend_header\n\001\002'
start=$(date +%s)
limited "$RADIOSITY" render --eye 0,0,3 --at 0,0,0 -o "$work/p.png" /dev/zero > /dev/null 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q '^radiosity: /dev/zero:1: line contains a NUL' "$work/err"; ok $? "render /dev/zero: exit $rc in $(( $(date +%s) - start )) s"
{ printf 'ply\nformat ascii 1.0\nelement vertex 300000000\nproperty double x\nproperty double y\nproperty double z\nelement face 1\nproperty list uchar int vertex_indices\nproperty double red\nproperty double green\nproperty double blue\nend_header\n0 0 0\n'; } > "$work/claim.ply"
mkfifo "$work/fifo.ply"
cat "$work/claim.ply" > "$work/fifo.ply" &
limited "$RADIOSITY" render --eye 0,0,3 --at 0,0,0 -o "$work/p.png" "$work/fifo.ply" > /dev/null 2> "$work/err"; rc=$?
# a program that died before opening the FIFO leaves the writer blocked in
# open(2) for ever: end it rather than wait on it
kill $! 2> /dev/null; wait
[ $rc -eq 1 ] && grep -q "^radiosity: $work/fifo.ply:13: unexpected end of file: element 'vertex' has 1 of its 300000000" "$work/err"; ok $? "a piped PLY claiming 3e8 vertices costs what it holds, not what it claims: exit $rc, $(head -n 1 "$work/err")"

done_testing
