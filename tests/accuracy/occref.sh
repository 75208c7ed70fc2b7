#!/bin/sh
# occref.sh -- partly hidden pairs (two parallel rectangles, an opaque
# axis-aligned rectangle between them) against an independent mpmath
# reference (tests/occref.py): default within 1e-6 relative, reference
# within 1e-9, every estimate at or above the true error, and every run
# with --strict: the estimates confirm the promise.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
: "${RADIOSITY:?set RADIOSITY to the program}"
: "${top_srcdir:=.}"
if ! command -v python3 > /dev/null 2>&1 || ! python3 -c 'import mpmath' > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 with mpmath not found (Debian: python3-mpmath)"
  exit 0
fi
out=$(python3 "$top_srcdir/tests/occref.py" "$RADIOSITY") || { echo "not ok 1 - occref.py failed"; echo "1..1"; exit 1; }
printf '%s\n' "$out"
n=$(printf '%s\n' "$out" | grep -c '^\(not \)\{0,1\}ok ')
echo "1..$n"
! printf '%s\n' "$out" | grep -q '^not ok'
