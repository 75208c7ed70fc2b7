#!/bin/sh
# outputs.sh -- what an output path names decides how it is written
# (radiosity-files(5), HOW OUTPUTS ARE WRITTEN): a regular file or an
# absent path is replaced whole through a temporary file and rename; a
# FIFO or a device is written in place and stays what it was; a symbolic
# link is followed, its target replaced and the link kept; a failed run
# leaves the old file whole.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"

printf 'material w reflect 0.5 emit 1\nquad w 0 0 0  1 0 0  1 1 0  0 1 0\nquad w 0 0 1  0 1 1  1 1 1  1 0 1\n' > "$work/two.scene"
scene="$work/two.scene"
rows() { awk 'NR > 1' "$1" | wc -l; }
no_debris() { ! ls -a "$1" | grep -q '\.tmp'; }

# a regular file is replaced whole, with its permission bits kept
echo old > "$work/f.tsv"; chmod 640 "$work/f.tsv"
"$RADIOSITY" formfactor -o "$work/f.tsv" "$scene"; ok $? "formfactor -o FILE: exit 0"
[ "$(rows "$work/f.tsv")" -eq 2 ]; ok $? "the regular file holds the new table"
[ "$(stat -c %a "$work/f.tsv")" = 640 ]; ok $? "the replaced file keeps its permission bits"
no_debris "$work"; ok $? "no temporary file is left"

# a symbolic link is followed: its target is replaced, the link kept
mkdir "$work/d"; echo old > "$work/d/target.tsv"
ln -s d/target.tsv "$work/link.tsv"
"$RADIOSITY" formfactor -o "$work/link.tsv" "$scene"; ok $? "-o LINK: exit 0"
[ -L "$work/link.tsv" ]; ok $? "the link is still a link"
[ "$(readlink "$work/link.tsv")" = d/target.tsv ]; ok $? "the link still names its target"
[ "$(rows "$work/d/target.tsv")" -eq 2 ]; ok $? "the link's target holds the new table"
no_debris "$work" && no_debris "$work/d"; ok $? "no temporary beside the link or the target"
ln -s d/absent.tsv "$work/dangling.tsv"
"$RADIOSITY" formfactor -o "$work/dangling.tsv" "$scene" && [ -L "$work/dangling.tsv" ] &&
  [ "$(rows "$work/d/absent.tsv")" -eq 2 ]; ok $? "a dangling link: its target is created, the link kept"
ln -s loop2 "$work/loop1"; ln -s loop1 "$work/loop2"
"$RADIOSITY" formfactor -o "$work/loop1" "$scene" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'loop1:.*symbolic links' "$work/err"; ok $? "a loop of links: exit 1, named"

# a FIFO is written in place and stays a FIFO
if mkfifo "$work/fifo" 2> /dev/null; then
  cat "$work/fifo" > "$work/from-fifo" & reader=$!
  "$RADIOSITY" formfactor -o "$work/fifo" "$scene"; rc=$?
  wait $reader
  [ $rc -eq 0 ]; ok $? "-o FIFO: exit 0"
  [ -p "$work/fifo" ]; ok $? "the FIFO is still a FIFO"
  [ "$(rows "$work/from-fifo")" -eq 2 ]; ok $? "the reader got the whole table through the FIFO"
  no_debris "$work"; ok $? "no temporary beside the FIFO"
else
  for k in 1 2 3 4; do skip "mkfifo failed"; done
fi

# a character device (a private null device, made with mknod as root)
if [ "$(id -u)" -eq 0 ] && mknod -m 666 "$work/null" c 1 3 2> /dev/null; then
  "$RADIOSITY" formfactor -o "$work/null" "$scene"; ok $? "-o DEVICE: exit 0"
  [ -c "$work/null" ]; ok $? "the device is still a character device"
  "$RADIOSITY" solve -q --elements "$work/null" --report "$work/null" -o "$work/null" "$scene"
  [ $? -eq 0 ] && [ -c "$work/null" ]; ok $? "solve's three outputs to a device: it stays a device"
  no_debris "$work"; ok $? "no temporary beside the device"
  if mknod -m 666 "$work/full" c 1 7 2> /dev/null; then
    "$RADIOSITY" formfactor -o "$work/full" "$scene" 2> "$work/err"; rc=$?
    [ $rc -eq 1 ] && [ -c "$work/full" ] && grep -q 'full: No space left on device' "$work/err"
    ok $? "a full device: exit 1 with the reason, and it stays a device"
  else
    skip "mknod of a full device failed"
  fi
else
  for k in 1 2 3 4 5; do skip "not root, no private device"; done
fi

# descriptors the process holds are written directly
"$RADIOSITY" formfactor -o - "$scene" > "$work/stdout.tsv"
[ "$(rows "$work/stdout.tsv")" -eq 2 ]; ok $? "-o -: standard output"
# (through /proc/self/fd: no test names a system device as an output, see
# doc/design.md, "Tests and benchmarks"; /dev/stdout and /dev/fd/N take
# the same branch of atomicfile.c)
"$RADIOSITY" formfactor -o /proc/self/fd/1 "$scene" > "$work/fd1.tsv"; rc=$?
[ $rc -eq 0 ] && [ "$(rows "$work/fd1.tsv")" -eq 2 ] && [ -f "$work/fd1.tsv" ]
ok $? "-o /proc/self/fd/1 writes into the shell's redirection"
"$RADIOSITY" formfactor -o /proc/self/fd/3 "$scene" 3> "$work/fd3.tsv"
[ "$(rows "$work/fd3.tsv")" -eq 2 ]; ok $? "-o /proc/self/fd/3 writes into descriptor 3"

# nothing is lost when the run fails
echo keep > "$work/keep.tsv"
"$RADIOSITY" formfactor -o "$work/keep.tsv" "$work/no-such.scene" 2> /dev/null; rc=$?
[ $rc -eq 1 ] && [ "$(cat "$work/keep.tsv")" = keep ]; ok $? "a failed run leaves the old output whole"
"$RADIOSITY" formfactor -o "$work" "$scene" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'Is a directory' "$work/err"; ok $? "a directory as output: exit 1, named"

# two outputs naming one file: refused before any work, the file untouched
echo keep > "$work/same.tsv"
"$RADIOSITY" solve -q --elements "$work/same.tsv" --report "$work/same.tsv" "$scene" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'named by two outputs' "$work/err" && [ "$(cat "$work/same.tsv")" = keep ]
ok $? "--elements and --report on one path: exit 1, said, the file kept"
"$RADIOSITY" solve -q --elements "$work/same.tsv" --report "$work/../$(basename "$work")/same.tsv" "$scene" 2> "$work/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'named by two outputs' "$work/err" && [ "$(cat "$work/same.tsv")" = keep ]
ok $? "the same file by two spellings: exit 1 too"

# the machine's own devices are still devices (checked last)
[ -c /dev/null ] && [ -c /dev/full ]; ok $? "/dev/null and /dev/full are still character devices"
done_testing
