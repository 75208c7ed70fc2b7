#!/usr/bin/env python3
"""libwords.py -- the library speaks in its own terms.

Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.

usage: libwords.py SRCDIR [--params]

Prints FILE:LINE: STRING for every string literal in the library's sources
(every module of SRCDIR/MODULES but the programs, cli and mpi) that names
a command-line option (--word), and exits 1 if there is one.  The library
names its parameters as a C caller knows them, in backquotes (`mesh`,
`max_iterations`), and the program turns those into its options.  With --params it lists
instead, one a line, every `name` the library's strings use, for the test
to hold against the program's table.
"""
import os
import re
import sys

sys.dont_write_bytecode = True  # a read-only source tree (distcheck) stays clean
from layers import read_modules  # noqa: E402 (after the flag above)

PROGRAMS = {'cli', 'mpi'}
TOKENS = re.compile(r'/\*.*?\*/|//[^\n]*|"(?:[^"\\\n]|\\.)*"|\'(?:[^\'\\\n]|\\.)*\'', re.S)
OPTION = re.compile(r'(?<![\w-])--[a-z]')
PARAM = re.compile(r'`([a-z_]+)`')


def main():
    if len(sys.argv) not in (2, 3) or (len(sys.argv) == 3 and sys.argv[2] != '--params'):
        sys.exit(__doc__.split('\n\n')[1])
    src, bad, params = sys.argv[1], 0, set()
    for mod, _ in read_modules(os.path.join(src, 'MODULES')):
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
                if tok.startswith('"'):
                    params.update(PARAM.findall(tok))
                if tok.startswith('"') and OPTION.search(tok):
                    line = text.count('\n', 0, m.start()) + 1
                    print('%s:%d: %s' % (path, line, tok))
                    bad += 1
    if len(sys.argv) == 3:
        print('\n'.join(sorted(params)))
        return 0
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
