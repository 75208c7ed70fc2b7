# lib.sh -- TAP helpers for the shell tests.  Copyright (C) 2026 The radiosity
# authors.  GPLv3+, see COPYING.  Sourced; expects $RADIOSITY and $top_srcdir.
: "${RADIOSITY:?set RADIOSITY to the program}"
: "${top_srcdir:=.}"
tap_n=0
tap_failed=0
ok() { # ok CONDITION-STATUS DESCRIPTION
  tap_n=$((tap_n + 1))
  if [ "$1" -eq 0 ]; then echo "ok $tap_n - $2"; else echo "not ok $tap_n - $2"; tap_failed=$((tap_failed + 1)); fi
}
skip() { # skip WHY: one check that cannot run here
  tap_n=$((tap_n + 1)); echo "ok $tap_n # SKIP $*"
}
diag() { printf '# %s\n' "$*"; }
done_testing() { echo "1..$tap_n"; [ "$tap_failed" -eq 0 ]; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# expect_num GOT WANT RELTOL: relative comparison with awk
close_to() { awk -v g="$1" -v w="$2" -v t="$3" 'BEGIN { d = g - w; if (d < 0) d = -d; s = w < 0 ? -w : w; if (s == 0) s = 1; exit !(g == g + 0 && d <= t * s) }'; }
