#!/bin/sh
# heldout.sh -- form factors of random geometry of the kinds heldout.py lists
# against an independent mpmath evaluation (tests/heldout.py).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
: "${RADIOSITY:?set RADIOSITY to the program}"
: "${top_srcdir:=.}"
if ! command -v python3 > /dev/null 2>&1 || ! python3 -c 'import mpmath' > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 with mpmath not found (Debian: python3-mpmath)"
  exit 0
fi
# Seeds and rounds: RADIOSITY_HELDOUT="SEED ROUNDS" for a longer run.
set -- ${RADIOSITY_HELDOUT:-20261201 3}
out=$(python3 "$top_srcdir/tests/heldout.py" "$RADIOSITY" "$1" "$2") || { echo "not ok 1 - heldout.py failed"; echo "1..1"; exit 1; }
printf '%s\n' "$out"
n=$(printf '%s\n' "$out" | grep -c '^\(not \)\{0,1\}ok ')
echo "1..$n"
! printf '%s\n' "$out" | grep -q '^not ok'
