#!/bin/sh
# examples.sh -- every example that a command's --help shows runs as shown
# (in a directory where data/ is the shipped scenes), and exits 0; and
# every line of every --help fits in 80 columns (GNU coding standards).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
mkdir "$work/run" && ln -s "$top_srcdir/data" "$work/run/data"
cd "$work/run" || exit 1
for cmd in formfactor solve render analytic progress sweep animate compare; do
  # an example may go on over lines ending in " \" (80 columns)
  "$RADIOSITY" $cmd --help | awk '/^  radiosity / {
      line = $0
      while (line ~ / \\$/ && (getline more) > 0) {
        sub(/ \\$/, "", line); sub(/^ +/, " ", more); line = line more
      }
      sub(/^  radiosity /, "", line); sub(/\(.*/, "", line); print line }' > "../$cmd.examples"
  [ -s "../$cmd.examples" ]; ok $? "$cmd --help shows examples"
  wide=$("$RADIOSITY" $cmd --help | awk 'length > 79' | head -n 2)
  [ -z "$wide" ]; ok $? "$cmd --help fits in 80 columns${wide:+: $wide}"
  while IFS= read -r line; do
    # shellcheck disable=SC2086
    "$RADIOSITY" $line > /dev/null 2> "../err"; rc=$?
    [ $rc -eq 0 ] || diag "$(head -c 300 ../err)"
    ok $rc "radiosity $line"
  done < "../$cmd.examples"
done
# the manual pages, rendered at 80 columns, keep within them
if command -v man > /dev/null 2>&1 && command -v col > /dev/null 2>&1 &&
  command -v python3 > /dev/null 2>&1; then
  for page in "$top_srcdir"/man/*.[135] "${top_builddir:-.}/man/radiosity.1"; do
    [ -f "$page" ] || continue
    wide=$(MANWIDTH=80 man -l "$page" 2> /dev/null | col -bx | python3 -c '
import sys
text = sys.stdin.buffer.read().decode("utf-8", "replace")
print("".join("%d: %s" % (len(l), l.strip()) for l in text.split("\n") if len(l) > 80)[:200])')
    [ -z "$wide" ]; ok $? "man ${page##*/} fits in 80 columns${wide:+: $wide}"
  done
else
  skip "man, col or python3 not found"
fi
done_testing
