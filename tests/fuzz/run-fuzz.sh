#!/bin/sh
# run-fuzz.sh -- build the fuzz harnesses and run each for a while.
#
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: tests/fuzz/run-fuzz.sh [SECONDS] [extra libFuzzer options...]
# (default 600 seconds per harness), or `make fuzz FUZZ_SECONDS=600`.
# Builds each harness (fuzz_scene.c: the scene parser and the mesher;
# fuzz_ply.c: the PLY reader; fuzz_obj.c: the OBJ + MTL reader; fuzz_vs3.c:
# the View3D reader; fuzz_changes.c: the change file of animate) with clang, libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer, then fuzzes a copy of its seed corpus
# (corpus/ for scenes, corpus-ply/, corpus-obj/, corpus-vs3/,
# corpus-changes/) with its
# dictionary (NAME.dict).
# Everything it writes (binaries, config.h, corpus copies, crash files,
# logs) goes to a temporary directory, which it keeps and names at the end;
# the source tree is only read.
# Environment: CC (default clang), FUZZ_WORKDIR (default: mktemp -d),
# FUZZ_HARNESSES (default "scene ply obj vs3 changes matrix"; run one with
# FUZZ_HARNESSES=ply).
# Exit status: 0 no finding, 1 a finding (crash, sanitizer report, timeout,
# broken contract), 2 usage or no fuzzing compiler (it says how to get one).
set -eu

secs=${1:-600}
[ $# -gt 0 ] && shift
case $secs in
    ''|*[!0-9]*) echo "run-fuzz.sh: SECONDS must be a whole number, not '$secs'" >&2; exit 2 ;;
esac

here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
cc=${CC:-clang}
harnesses=${FUZZ_HARNESSES:-scene ply obj vs3 changes matrix}
work=${FUZZ_WORKDIR:-$(mktemp -d "${TMPDIR:-/tmp}/radiosity-fuzz.XXXXXX")}
flags="-g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined"

# A compiler that cannot build a libFuzzer program: say how to get one.
printf 'int LLVMFuzzerTestOneInput(const char *d, unsigned long n);\n
int LLVMFuzzerTestOneInput(const char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' \
    > "$work/probe.c"
if ! command -v "$cc" > /dev/null 2>&1 || ! "$cc" $flags "$work/probe.c" -o "$work/probe" > /dev/null 2>&1; then
    echo "run-fuzz.sh: '$cc' cannot build libFuzzer programs (-fsanitize=fuzzer)." >&2
    echo "run-fuzz.sh: install clang (Debian: apt-get install clang) or set CC; nothing fuzzed." >&2
    rm -rf "$work"
    exit 2
fi
printf '#define PACKAGE_VERSION "fuzz"\n' > "$work/config.h"

# The sources each harness needs, and its corpus and dictionary.
sources() {
    case $1 in
        scene) echo scene/scene.c scene/polycheck.c scene/scenebuild.c scene/objread.c scene/objrepair.c scene/vs3read.c util/readnum.c mesh/mesh.c util/status.c util/readfile.c ;;
        ply) echo io/plyread.c util/readfile.c scene/scene.c scene/polycheck.c scene/scenebuild.c scene/objread.c scene/objrepair.c scene/vs3read.c util/readnum.c util/status.c render/render.c render/plot.c cli/atomicfile.c mesh/mesh.c ;;
        obj|vs3) echo scene/scene.c scene/polycheck.c scene/scenebuild.c scene/objread.c scene/objrepair.c scene/vs3read.c util/readnum.c mesh/mesh.c util/status.c util/readfile.c ;;
        changes) echo scene/changeread.c scene/scene.c scene/polycheck.c scene/scenebuild.c scene/scenepresent.c scene/objread.c scene/objrepair.c scene/vs3read.c util/readnum.c util/status.c util/readfile.c ;;
        matrix) echo io/ffread.c io/npyread.c io/vfread.c util/readfile.c util/readnum.c util/status.c ;;
    esac
}
libs() {
    case $1 in
        ply) pkg-config --libs cairo 2>/dev/null || echo -lcairo ;;
    esac
}
cflags() {
    case $1 in
        ply) pkg-config --cflags cairo 2>/dev/null || true ;;
    esac
}
corpus() { case $1 in scene) echo corpus ;; *) echo "corpus-$1" ;; esac; }

status=0
for h in $harnesses; do
    case $h in
        scene|ply|obj|vs3|changes|matrix) ;;
        *) echo "run-fuzz.sh: unknown harness '$h' (scene, ply, obj, vs3, changes or matrix)" >&2; exit 2 ;;
    esac
    mkdir -p "$work/$h/corpus" "$work/$h/artifacts"
    cp "$here/$(corpus "$h")"/* "$work/$h/corpus/"
    srcs=
    for f in $(sources "$h"); do srcs="$srcs $top/src/$f"; done
    echo "run-fuzz.sh: building $work/fuzz_$h"
    # shellcheck disable=SC2046,SC2086
    "$cc" $flags -I"$work" -I"$here" -I"$top/include" -I"$top/src" $(cflags "$h") "$here/fuzz_$h.c" $srcs \
        $(libs "$h") -lm -o "$work/fuzz_$h"
    echo "run-fuzz.sh: fuzzing $h for $secs s; log in $work/$h/fuzz.log"
    rc=0
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ASAN_OPTIONS=abort_on_error=0:detect_leaks=1 \
    "$work/fuzz_$h" -max_total_time="$secs" -max_len=4096 -timeout=10 \
        -rss_limit_mb=2048 -print_final_stats=1 \
        -dict="$here/$h.dict" -artifact_prefix="$work/$h/artifacts/" \
        "$@" "$work/$h/corpus" > "$work/$h/fuzz.log" 2>&1 || rc=$?
    grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)' "$work/$h/fuzz.log" | tail -n 2 || true
    grep -E '^stat::' "$work/$h/fuzz.log" || true
    echo "run-fuzz.sh: $h corpus: $(ls "$work/$h/corpus" | wc -l) inputs"
    if [ "$rc" -ne 0 ] || grep -qE 'ERROR: (AddressSanitizer|libFuzzer|LeakSanitizer)|runtime error:' "$work/$h/fuzz.log"; then
        echo "run-fuzz.sh: $h FAILED (exit $rc); see $work/$h/fuzz.log"
        ls -l "$work/$h/artifacts/"
        grep -E 'ERROR:|runtime error:|SUMMARY:' "$work/$h/fuzz.log" | head -n 20
        status=1
    else
        echo "run-fuzz.sh: $h OK, no crash and no sanitizer report in $secs s"
    fi
done
echo "run-fuzz.sh: work directory $work"
exit $status
