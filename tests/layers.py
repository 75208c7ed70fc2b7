#!/usr/bin/env python3
"""layers.py -- check the module order of src/ (src/MODULES).

Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.

usage: layers.py SRCDIR [BUILDDIR]

SRCDIR/MODULES lists the modules lowest first, one a line:
    NAME  [FACE.h]   -- what the module owns
(one face header at most: the module's interface to those after it).
Every folder SRCDIR/NAME holds one module.  A file of module M may include
    - the installed headers ("radiosity.h", "radiosity/...") and config.h;
    - any header of its own folder, spelled "M/x.h";
    - the face header of a module listed before M, spelled "N/x.h".
Anything else -- a folder above M, a header that is private to its folder,
a name without its folder, a folder that MODULES does not list, headers
that include each other in a circle, a file that neither its folder's
local.mk nor Makefile.am lists -- is printed as FILE:LINE: what is
wrong, and the exit status is 1.

With BUILDDIR, the calls are checked too, from the object files that the
build left in BUILDDIR/src/M/ (nm): an include rule alone cannot see a
call that goes through the installed headers, which every module may
include.  No object of module M may use a symbol that an object of a
module after M defines, and no files may call each other in a circle.
"""
import os
import re
import subprocess
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def read_modules(path):
    """[(name, set of face headers)] in the order of the file."""
    out = []
    with open(path) as f:
        for n, line in enumerate(f, 1):
            line = line.split('--')[0].split('#')[0].strip()
            if not line:
                continue
            words = line.split()
            if not re.fullmatch(r'[a-z][a-z0-9_]*', words[0]):
                sys.exit('%s:%d: bad module name %r' % (path, n, words[0]))
            out.append((words[0], set(words[1:])))
    return out


def check(src):
    modules = read_modules(os.path.join(src, 'MODULES'))
    rank = {name: k for k, (name, _) in enumerate(modules)}
    faces = dict(modules)
    bad = []
    folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d))
                     and not d.startswith('.'))
    for d in folders:
        if d not in rank:
            bad.append('%s/%s: a folder that MODULES does not list' % (src, d))
    for name, face in modules:
        if len(face) > 1:
            bad.append('%s/MODULES: %s has %d faces (%s); a module has one'
                       % (src, name, len(face), ' '.join(sorted(face))))
        for h in face:
            if not os.path.isfile(os.path.join(src, name, h)):
                bad.append('%s/MODULES: %s names %s, which is not in %s/%s'
                           % (src, name, h, src, name))
    includes = {}
    for d in folders:
        if d not in rank:
            continue
        for fn in sorted(os.listdir(os.path.join(src, d))):
            if not re.search(r'\.(c|h|cc)$', fn):
                continue
            path = os.path.join(src, d, fn)
            with open(path, errors='replace') as f:
                for n, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if m:
                        includes.setdefault('%s/%s' % (d, fn), set()).add(m.group(1))
                        why = verdict(m.group(1), d, rank, faces)
                        if why:
                            bad.append('%s:%d: "%s" %s' % (path, n, m.group(1), why))
    am = os.path.join(src, os.pardir, 'Makefile.am')
    top_am = open(am).read() if os.path.isfile(am) else ''
    for d in folders:
        mk = os.path.join(src, d, 'local.mk')
        listed = set(re.findall(r'%reldir%/([\w.]+)', open(mk).read())) if os.path.isfile(mk) else set()
        listed |= set(re.findall(r'\bsrc/%s/([\w.]+)' % d, top_am))
        for fn in sorted(os.listdir(os.path.join(src, d))):
            if re.search(r'\.(c|h|cc)$', fn) and fn not in listed:
                bad.append('%s/%s/%s: not listed in %s, so not built or distributed'
                           % (src, d, fn, mk))
    for cycle in circles(includes):
        bad.append('headers that include each other in a circle: %s'
                   % ' '.join('src/' + h for h in cycle))
    return bad


def verdict(inc, mod, rank, faces):
    if inc in ('config.h', 'radiosity.h') or inc.startswith('radiosity/'):
        return None
    if '/' not in inc:
        return 'does not spell its folder (write "FOLDER/%s")' % inc
    folder, header = inc.split('/', 1)
    if folder not in rank:
        return 'names a folder that MODULES does not list'
    if folder == mod:
        return None
    if rank[folder] > rank[mod]:
        return 'reaches up: %s comes after %s in MODULES' % (folder, mod)
    if header not in faces[folder]:
        return 'is private to %s (its faces: %s)' % (folder, ' '.join(sorted(faces[folder])))
    return None


def objects(build, rank):
    """{(module, file): (defined, used)} from the object files under
    BUILD/src/MODULE/ (libtool's .libs/ too); one entry per source file,
    whatever prefix automake gave its object."""
    out = {}
    for mod in rank:
        for root, _, names in os.walk(os.path.join(build, 'src', mod)):
            for fn in names:
                if not fn.endswith('.o'):
                    continue
                stem = re.sub(r'^(lib\w+_la|radiosity_mpi|radiosity)-', '', fn[:-2])
                nm = subprocess.run(['nm', os.path.join(root, fn)], capture_output=True,
                                    text=True).stdout
                d, u = out.setdefault((mod, stem), (set(), set()))
                for line in nm.splitlines():
                    w = line.split()
                    if len(w) == 3 and w[1] in 'TDBRWVi':
                        d.add(w[2])
                    elif len(w) == 2 and w[0] == 'U':
                        u.add(w[1])
    return out


def check_calls(src, build):
    rank = {name: k for k, (name, _) in enumerate(read_modules(os.path.join(src, 'MODULES')))}
    objs = objects(build, rank)
    if not objs:
        return ['%s: no object files under %s/src (build first)' % (build, build)]
    owner = {}
    for key, (d, _) in objs.items():
        for sym in d:
            if sym != 'main':
                owner.setdefault(sym, set()).add(key)
    bad, edges = [], {}
    for (mod, stem), (_, used) in sorted(objs.items()):
        for sym in sorted(used):
            for (m2, s2) in owner.get(sym, ()):
                if (m2, s2) == (mod, stem):
                    continue
                edges.setdefault((mod, stem), set()).add((m2, s2))
                if rank[m2] > rank[mod]:
                    bad.append('src/%s/%s: calls %s of src/%s/%s, a module after %s'
                               % (mod, stem, sym, m2, s2, mod))
    for cycle in circles(edges):
        bad.append('files that call each other in a circle: %s'
                   % ' '.join('src/%s/%s' % k for k in cycle))
    return bad


def circles(edges):
    """The strongly connected components of more than one node (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__.split('\n\n')[1])
    bad = check(sys.argv[1])
    if len(sys.argv) == 3:
        bad += check_calls(sys.argv[1], sys.argv[2])
    for b in bad:
        print(b)
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
