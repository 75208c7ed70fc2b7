#!/bin/sh
# examples.sh -- every example that a command's --help shows runs as shown
# (in a directory where data/ is the shipped scenes), and exits 0.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
mkdir "$work/run" && ln -s "$top_srcdir/data" "$work/run/data"
cd "$work/run" || exit 1
for cmd in formfactor solve render analytic progress sweep animate compare; do
  "$RADIOSITY" $cmd --help | sed -n 's/^  radiosity \([^(]*\).*/\1/p' > "../$cmd.examples"
  [ -s "../$cmd.examples" ]; ok $? "$cmd --help shows examples"
  while IFS= read -r line; do
    # shellcheck disable=SC2086
    "$RADIOSITY" $line > /dev/null 2> "../err"; rc=$?
    [ $rc -eq 0 ] || diag "$(head -c 300 ../err)"
    ok $rc "radiosity $line"
  done < "../$cmd.examples"
done
done_testing
