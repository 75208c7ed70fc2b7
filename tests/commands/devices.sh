#!/bin/sh
# devices.sh -- runs after every other test (Makefile.am orders it last) and
# asserts that the suite left the machine's devices as it found them: no
# output was ever renamed over /dev/null or /dev/full.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
[ -c /dev/null ]; ok $? "/dev/null is still a character device"
[ -c /dev/full ]; ok $? "/dev/full is still a character device"
[ -c /dev/zero ]; ok $? "/dev/zero is still a character device"
done_testing
