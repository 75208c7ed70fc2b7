#!/bin/sh
# run-fuzz.sh -- build the scene-parser fuzzer and run it for a while.
#
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: tests/fuzz/run-fuzz.sh [SECONDS] [extra libFuzzer options...]
# (default 600 seconds).  Builds tests/fuzz/fuzz_scene.c with clang,
# libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer, then fuzzes a
# copy of tests/fuzz/corpus.  Everything it writes (binary, config.h, corpus
# copy, crash files, log) goes to a temporary directory, which it keeps and
# names at the end; the source tree is only read.
# Environment: CC (default clang), FUZZ_WORKDIR (default: mktemp -d).
set -eu

secs=${1:-600}
[ $# -gt 0 ] && shift
case $secs in
    ''|*[!0-9]*) echo "run-fuzz.sh: SECONDS must be a whole number, not '$secs'" >&2; exit 2 ;;
esac

here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
cc=${CC:-clang}
work=${FUZZ_WORKDIR:-$(mktemp -d "${TMPDIR:-/tmp}/radiosity-fuzz.XXXXXX")}
mkdir -p "$work/corpus" "$work/artifacts"

printf '#define PACKAGE_VERSION "fuzz"\n' > "$work/config.h"
cp "$here"/corpus/*.scene "$work/corpus/"

echo "run-fuzz.sh: building $work/fuzz_scene"
"$cc" -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I"$work" -I"$top/src" \
    "$here/fuzz_scene.c" "$top/src/scene.c" "$top/src/mesh.c" "$top/src/status.c" "$top/src/readfile.c" \
    -lm -o "$work/fuzz_scene"

echo "run-fuzz.sh: fuzzing for $secs s; log in $work/fuzz.log"
status=0
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
ASAN_OPTIONS=abort_on_error=0:detect_leaks=1 \
"$work/fuzz_scene" -max_total_time="$secs" -max_len=4096 -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 \
    -dict="$here/scene.dict" -artifact_prefix="$work/artifacts/" \
    "$@" "$work/corpus" > "$work/fuzz.log" 2>&1 || status=$?

grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)' "$work/fuzz.log" | tail -n 2 || true
grep -E '^stat::' "$work/fuzz.log" || true
if [ "$status" -ne 0 ] || grep -qE 'ERROR: (AddressSanitizer|libFuzzer|LeakSanitizer)|runtime error:' "$work/fuzz.log"; then
    echo "run-fuzz.sh: FAILED (exit $status); see $work/fuzz.log"
    ls -l "$work/artifacts/"
    grep -E 'ERROR:|runtime error:|SUMMARY:' "$work/fuzz.log" | head -n 20
    exit 1
fi
echo "run-fuzz.sh: OK, no crash and no sanitizer report in $secs s ($work)"
