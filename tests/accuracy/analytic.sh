#!/bin/sh
# analytic.sh -- the closed forms over the whole positive double range
# against the printed formulas in mpmath (tests/analytic.py).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
: "${RADIOSITY:?set RADIOSITY to the program}"
: "${top_srcdir:=.}"
if ! command -v python3 > /dev/null 2>&1 || ! python3 -c 'import mpmath, ctypes' > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 with mpmath not found (Debian: python3-mpmath)"
  exit 0
fi
# the library libtool built beside the program (ctypes needs a shared one)
lib=$(dirname "$RADIOSITY")/.libs/libradiosity.so
if [ ! -f "$lib" ]; then
  echo "1..0 # SKIP no shared library at $lib (configured --disable-shared?)"
  exit 0
fi
# An instrumented library (make check-sanitize) needs the ASan runtime first
# in the process: python3 is not instrumented, so preload the runtime the
# program links.  LeakSanitizer is off there: python3 keeps its own objects
# at exit, and the program's leaks are checked by every other test.
if [ -n "${RADIOSITY_SANITIZE-}" ]; then
  asan=$(ldd "$RADIOSITY" | awk '$1 ~ /^libasan/ { print $3 }')
  LD_PRELOAD="$asan${LD_PRELOAD:+:$LD_PRELOAD}"; export LD_PRELOAD
  ASAN_OPTIONS="${ASAN_OPTIONS-}:detect_leaks=0"; export ASAN_OPTIONS
fi
out=$(python3 "$top_srcdir/tests/analytic.py" "$lib") || { printf '%s\n' "$out"; echo "not ok 1 - analytic.py failed"; echo "1..1"; exit 1; }
printf '%s\n' "$out"
n=$(printf '%s\n' "$out" | grep -c '^\(not \)\{0,1\}ok ')
echo "1..$n"
! printf '%s\n' "$out" | grep -q '^not ok'
