#!/bin/sh
# viewer.sh -- the viewer's page in a real browser (headless Chromium,
# installed by scripts/install-deps.sh): tests/view_browser.py's checks
# (the canvas after 40 shots taken by the page's Step button against
# `radiosity progress`'s picture, the box moved by the page's own buttons
# against a fresh solve), replayed as this script's checks.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
skip_without_view
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ] || ! command -v python3 > /dev/null 2>&1; then
  echo "1..0 # SKIP no chromium or python3 (scripts/install-deps.sh installs both)"
  exit 0
fi
mkdir "$work/b"
python3 "$top_srcdir/tests/view_browser.py" "$RADIOSITY" "$top_srcdir/data/view" \
  "$top_srcdir/data/cornell-moving-box.scene" "$work/b" "$browser" \
  > "$work/b.out" 2> "$work/b.err"
status=$?
ok $status "view_browser.py exits 0 $(tail -c 300 "$work/b.err")"
replay "$work/b.out"
grep -q '^1\.\.[1-9]' "$work/b.out"; ok $? "view_browser.py ran to its end"
done_testing
