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
skip_without_view() { # the whole script skipped when the viewer is not built
  if "$RADIOSITY" view --method magic x 2>&1 | grep -q "built without the live viewer"; then
    echo "1..0 # SKIP the viewer is not built (configure found no libmicrohttpd)"
    exit 0
  fi
}
replay() { # replay FILE: the TAP lines another program wrote, as our checks
  while IFS= read -r line; do
    case $line in
      "ok "*) ok 0 "${line#* - }" ;;
      "not ok "*) ok 1 "${line#* - }" ;;
    esac
  done < "$1"
}
done_testing() { echo "1..$tap_n"; [ "$tap_failed" -eq 0 ]; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# close_to GOT WANT RELTOL [SLACK]: |GOT - WANT| <= RELTOL |WANT| (|WANT| taken as 1
# when 0) plus an absolute SLACK (default 0)
close_to() { awk -v g="$1" -v w="$2" -v t="$3" -v a="${4:-0}" 'BEGIN { d = g - w; if (d < 0) d = -d; s = w < 0 ? -w : w; if (s == 0) s = 1; exit !(g == g + 0 && d <= t * s + a) }'; }
# estimate_covers SCENE I J WANT MODE WHAT: F(I -> J) of SCENE in MODE (left
# in $got) and its error estimate at or above the difference from WANT, an
# independent value, whatever the promise.  One check.
estimate_covers() {
  row=$("$RADIOSITY" formfactor -q --threads 1 --accuracy "$5" "$1" 2> "$work/covers.err" |
    awk -F '\t' -v i="$2" -v j="$3" '$1 == i && $2 == j { printf "%.17g %.3g\n", $3, $4 }')
  got=${row%% *}
  est=${row##* }
  awk -v g="$got" -v e="$est" -v w="$4" \
    'BEGIN { d = g - w; if (d < 0) d = -d; exit !(g == g + 0 && d <= e) }'
  ok $? "$6 F($2 -> $3), $5: $got, its estimate $est covers the difference from $4"
}
# against_value SCENE I J WANT SLACK WHAT: F(I -> J) of SCENE in default and
# reference modes within their promises (1e-6, 1e-9) of WANT, an
# independent value known to SLACK (absolute), plus SLACK, and each mode's
# error estimate, with SLACK, at or above the difference.  Four checks.
against_value() {
  for mode in default reference; do
    tol=1e-9
    [ "$mode" = default ] && tol=1e-6
    row=$("$RADIOSITY" formfactor -q --threads 1 --accuracy "$mode" "$1" |
      awk -F '\t' -v i="$2" -v j="$3" '$1 == i && $2 == j { printf "%.17g %.3g\n", $3, $4 }')
    got=${row%% *}
    est=${row##* }
    close_to "$got" "$4" "$tol" "$5"
    ok $? "$6 F($2 -> $3), $mode: within $tol of $4 ($got)"
    awk -v g="$got" -v e="$est" -v w="$4" -v s="$5" \
      'BEGIN { d = g - w; if (d < 0) d = -d; exit !(g == g + 0 && d <= e + s) }'
    ok $? "$6 F($2 -> $3), $mode: its estimate $est covers the difference"
  done
}
# against_pairref SCENE SPEC I J WHAT: F(I -> J) of SCENE in reference and
# default modes within their promises (1e-9, 1e-6) of tests/pairref.py's
# value for SPEC (to 1e-9 of the value: with 1e-10 the value moved by
# 6e-11), and each mode's error estimate, with pairref's own, at or above
# the difference: the estimates bound the error.  A promise is relative
# to the value, or to 1e-4 of the unoccluded factor (pairref's third
# number) for a pair hidden beyond that.  Five checks, or one skip
# without python3.
against_pairref() {
  if ! command -v python3 > /dev/null 2>&1; then
    skip "python3 not found"
    return
  fi
  ref=$(python3 "$top_srcdir/tests/pairref.py" "$2" 1e-9)
  ok $? "$5: independent F($3 -> $4) = $ref"
  set -- "$@" $ref
  want=$6
  wanterr=$7
  unocc=$8
  for mode in reference default; do
    tol=1e-9
    [ "$mode" = default ] && tol=1e-6
    row=$("$RADIOSITY" formfactor -q --accuracy "$mode" "$1" |
      awk -F '\t' -v i="$3" -v j="$4" '$1 == i && $2 == j { printf "%.17g %.3g\n", $3, $4 }')
    got=${row%% *}
    awk -v g="$got" -v w="$want" -v u="$unocc" -v t="$tol" \
      'BEGIN { d = g - w; if (d < 0) d = -d; s = w < 0 ? -w : w; if (s < 1e-4 * u) s = 1e-4 * u;
               exit !(g == g + 0 && d <= t * s) }'
    ok $? "$5, $mode: within $tol of it ($got)"
    awk -v g="$got" -v e="${row##* }" -v w="$want" -v we="$wanterr" \
      'BEGIN { d = g - w; if (d < 0) d = -d; exit !(g == g + 0 && d <= e + we) }'
    ok $? "$5, $mode: its estimate ${row##* } and pairref's $wanterr cover the difference"
  done
}
