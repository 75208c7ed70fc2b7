#!/bin/sh
# libwords.sh -- no string of the library names a command-line option
# (tests/libwords.py): a C caller of rad_pipeline_run has no --mesh.  The
# library's messages name parameters in backquotes, and the program turns
# them into its options; both halves are checked here.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found"
  exit 0
fi
check="$top_srcdir/tests/libwords.py"
python3 "$check" "$top_srcdir/src" > "$work/out" 2>&1
ok $? "no library string names a command-line option"
[ -s "$work/out" ] && sed 's/^/# /' "$work/out" | head -n 20

# the check can fail: a scratch copy with one such string
cp -R "$top_srcdir/src" "$work/src"
printf 'static const char *const bad = "use a coarser --mesh";\n' >> "$work/src/solve/solve.c"
python3 "$check" "$work/src" > "$work/bad" 2>&1
[ $? -eq 1 ] && grep -q 'solve/solve.c:[0-9]*: "use a coarser --mesh"' "$work/bad"
ok $? "a library string naming --mesh is found, with its file and line"

# every parameter the library names is one the program can translate
python3 "$check" "$top_srcdir/src" --params > "$work/params"
missing=
while read -r name; do
  grep -q "{\".*\`$name\`.*\"," "$top_srcdir/src/cli/cli_common.c" || missing="$missing $name"
done < "$work/params"
[ -s "$work/params" ] && [ -z "$missing" ]
ok $? "the program's table turns every parameter the library names into its option ($(wc -l < "$work/params") names)${missing:+; missing:$missing}"

# the program speaks of its options: the library's `max_iterations` and
# `solver` reach the user as --max-iterations and --solver
cat > "$work/open.scene" <<'END'
material lamp reflect 0.5 emit 1
material wall reflect 0.9
quad lamp 0 0 0  1 0 0  1 1 0  0 1 0
quad wall 0 0 1  0 1 1  1 1 1  1 0 1
END
"$RADIOSITY" solve -q --solver jacobi --max-iterations 1 --tolerance 1e-15 \
  "$work/open.scene" > /dev/null 2> "$work/noconv.err"
[ $? -ne 0 ] && grep -q -- 'raise --max-iterations or use --solver gauss' "$work/noconv.err" &&
  ! grep -q '`' "$work/noconv.err"
ok $? "a library message reaches the user with option names ($(head -c 160 "$work/noconv.err"))"
"$RADIOSITY" solve -q --solver cg --patches 2x2 --form-factors-method hemicube \
  "$work/open.scene" > /dev/null 2> "$work/patch.err"
if grep -q 'patch grid' "$work/patch.err"; then
  grep -q -- '(--patches PxQ) needs the contour integral' "$work/patch.err" &&
    ! grep -q '`' "$work/patch.err"
  ok $? "a renamed parameter reaches the user as its option ($(head -c 160 "$work/patch.err"))"
fi
done_testing
