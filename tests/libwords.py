#!/usr/bin/env python3
"""libwords.py -- the library speaks in its own terms.

Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.

usage: libwords.py SRCDIR

Prints FILE:LINE: STRING for every string literal in the library's sources
(every module of SRCDIR/MODULES but the programs, cli and mpi) that names
a command-line option (--word), and exits 1 if there is one.  The library
names its parameters as a C caller knows them, in backquotes (`mesh`,
`max_iterations`), and the program turns those into its options.
"""
import os
import re
import sys

PROGRAMS = {'cli', 'mpi'}
TOKENS = re.compile(r'/\*.*?\*/|//[^\n]*|"(?:[^"\\\n]|\\.)*"|\'(?:[^\'\\\n]|\\.)*\'', re.S)
OPTION = re.compile(r'(?<![\w-])--[a-z]')


def modules(src):
    with open(os.path.join(src, 'MODULES')) as f:
        for line in f:
            line = line.split('--')[0].split('#')[0].strip()
            if line:
                yield line.split()[0]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.split('\n\n')[1])
    src, bad = sys.argv[1], 0
    for mod in modules(src):
        if mod in PROGRAMS:
            continue
        folder = os.path.join(src, mod)
        for fn in sorted(os.listdir(folder)):
            if not re.search(r'\.(c|h|cc)$', fn):
                continue
            path = os.path.join(folder, fn)
            text = open(path, errors='replace').read()
            for m in TOKENS.finditer(text):
                tok = m.group(0)
                if tok.startswith('"') and OPTION.search(tok):
                    line = text.count('\n', 0, m.start()) + 1
                    print('%s:%d: %s' % (path, line, tok))
                    bad += 1
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
