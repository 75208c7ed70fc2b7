#!/bin/sh
# python.sh -- the Python binding (import radiosity) as a user meets it in
# the build tree: tests/python.py's checks, replayed as this script's.
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
"$RADIOSITY_PYTHON" "$top_srcdir/tests/python.py" "$RADIOSITY" "$work" > "$work/py.out" 2> "$work/py.err"
status=$?
ok $status "python.py exits 0 $(tail -c 300 "$work/py.err")"
while IFS= read -r line; do
  case $line in
    "ok "*) ok 0 "${line#* - }" ;;
    "not ok "*) ok 1 "${line#* - }" ;;
  esac
done < "$work/py.out"
grep -q '^1\.\.[1-9]' "$work/py.out"; ok $? "python.py ran to its end"
done_testing
