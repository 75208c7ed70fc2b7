#!/bin/sh
# view.sh -- `radiosity view`, the live viewer: tests/view.py's checks of
# its requests (the numbers against a fresh solve and one shot computed
# from F, every class of hostile request refused with the state unchanged,
# a clean stop), replayed as this script's checks.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
skip_without_view
if ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP python3 not found"
  exit 0
fi
mkdir "$work/api"
python3 "$top_srcdir/tests/view.py" "$RADIOSITY" "$top_srcdir/data/view" "$work/api" \
  > "$work/api.out" 2> "$work/api.err"
status=$?
ok $status "view.py exits 0 $(tail -c 300 "$work/api.err")"
replay "$work/api.out"
grep -q '^1\.\.[1-9]' "$work/api.out"; ok $? "view.py ran to its end"
done_testing
