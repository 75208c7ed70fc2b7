#!/bin/sh
# occbeside.sh -- a light over a floor tile that a box stands 1.4e-3
# beside, against an independent reference (tests/occbeside.py): default
# within 1e-6 relative, reference within 1e-9, each within its own
# estimate, each run with --strict (tests/geomfuzz.py, seed 58 scene 71).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
: "${RADIOSITY:?set RADIOSITY to the program}"
: "${top_srcdir:=.}"
if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found"
  exit 0
fi
out=$(python3 "$top_srcdir/tests/occbeside.py" "$RADIOSITY") || { echo "not ok 1 - occbeside.py failed"; echo "1..1"; exit 1; }
printf '%s\n' "$out"
n=$(printf '%s\n' "$out" | grep -c '^\(not \)\{0,1\}ok ')
echo "1..$n"
! printf '%s\n' "$out" | grep -q '^not ok'
