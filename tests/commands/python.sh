#!/bin/sh
# python.sh -- the Python binding (import radiosity) as a user meets it in
# the build tree: tests/python.py's unittest cases, replayed as this
# script's checks, and examples/notebook.py run through.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
if [ -z "${RADIOSITY_PYTHON-}" ]; then
  echo "1..0 # SKIP the binding is not built (configure found no Python 3 with headers and NumPy)"
  exit 0
fi
# the module links the library of this build tree, not an installed one
LD_LIBRARY_PATH="$RADIOSITY_LIBDIR${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
PYTHONPATH="$RADIOSITY_PYTHONPATH"
export LD_LIBRARY_PATH PYTHONPATH
if [ -n "${RADIOSITY_SANITIZE-}" ]; then
  # an instrumented library in an interpreter that is not: the sanitizer
  # runtimes must be loaded first, and the interpreter's own allocations,
  # alive at its exit by design, are not leaks of ours
  LD_PRELOAD="$(${CC:-cc} -print-file-name=libasan.so) $(${CC:-cc} -print-file-name=libubsan.so)"
  ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
  export LD_PRELOAD ASAN_OPTIONS
fi
"$RADIOSITY_PYTHON" "$top_srcdir/tests/python.py" > "$work/py.out" 2> "$work/py.err"
status=$?
ok $status "python.py exits 0 $(tail -c 300 "$work/py.err")"
replay "$work/py.out"
grep -q '^1\.\.[1-9]' "$work/py.out"; ok $? "python.py ran to its end"
# the example: its closure and its two walls against Howell's C-11
(cd "$work" && "$RADIOSITY_PYTHON" "$top_srcdir/examples/notebook.py" \
  "$top_srcdir/data/goral1984-cube.scene") > "$work/nb.out" 2> "$work/nb.err"
ok $? "examples/notebook.py runs $(tail -c 300 "$work/nb.err" | grep -v -e RuntimeWarning -e '^  ')"
awk '/^closure/ { c = $NF } /^wall .* closed form/ { w = $(NF - 3) + 0; f = $NF + 0 }
  END { d = w - f; if (d < 0) d = -d; exit !(c + 0 < 1e-9 && w > 0 && d < 1e-11) }' "$work/nb.out"
ok $? "notebook.py: rows sum to 1 and two opposite walls match C-11 ($(grep -e '^closure' -e '^wall' "$work/nb.out" | tr '\n' ' '))"
done_testing
