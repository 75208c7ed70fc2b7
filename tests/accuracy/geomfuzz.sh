#!/bin/sh
# geomfuzz.sh -- a short fixed-seed run of the geometry fuzzer (geomfuzz.py:
# random valid scenes from the hard families through every accuracy mode
# and a solve).  Copyright (C) 2026 The radiosity authors.  GPLv3+, see
# COPYING.  The long run: `make fuzz-geometry GEOMFUZZ_SECONDS=1800` (one
# family only: GEOMFUZZ_FAMILY=room, say).
: "${RADIOSITY:?set RADIOSITY to the program}"
: "${top_srcdir:=.}"
command -v python3 > /dev/null || { echo "1..0 # SKIP python3 not found"; exit 0; }
keep=$(mktemp -d)
# two scenes of each of the eight families; a finding keeps its scene and
# names it in the failing line
python3 "$top_srcdir/tests/geomfuzz.py" "$RADIOSITY" --seed 20261201 --scenes 16 \
  --limit 60 --keep "$keep" --tap
rc=$?
[ $rc -eq 0 ] && rm -rf "$keep"
exit $rc
