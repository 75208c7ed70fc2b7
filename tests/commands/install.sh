#!/bin/sh
# install.sh -- the library as a user meets it: `make install` into a
# staging directory, `pkg-config --cflags --libs radiosity` alone builds the
# example against it, and the shared library exports exactly the functions
# that the installed headers declare (nm -D against the headers).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
. "${top_srcdir:-.}/tests/lib.sh"
if ! command -v pkg-config > /dev/null 2>&1 || ! command -v nm > /dev/null 2>&1; then
  echo "1..0 # SKIP pkg-config or nm not found"; exit 0
fi
stage="$work/stage"
# a make of our own, outside the jobserver of the `make check` that runs us
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL ${MAKE:-make} -C "${top_builddir:-.}" install \
  DESTDIR="$stage" > "$work/install.log" 2>&1
ok $? "make install DESTDIR=... ($(tail -n 1 "$work/install.log"))"
pc=$(find "$stage" -name radiosity.pc | head -n 1)
[ -n "$pc" ]; ok $? "radiosity.pc is installed"
export PKG_CONFIG_PATH="$(dirname "$pc")"
flags=$(pkg-config --cflags --libs radiosity); ok $? "pkg-config --cflags --libs radiosity: $flags"
# the version configure was given, as PKG_CHECK_MODULES([R], [radiosity >= X]) asks
want=$("$RADIOSITY" --version | sed -n '1s/^radiosity //p')
have=$(pkg-config --modversion radiosity)
[ -n "$want" ] && [ "$have" = "$want" ] && pkg-config --atleast-version="$want" radiosity
ok $? "pkg-config --modversion radiosity is the program's version ($have, $want)"
# an instrumented library (make check-sanitize) needs its sanitizer runtime
# linked into the program too, as any user of such a build must
${CC:-cc} ${RADIOSITY_SANITIZE-} -o "$work/solve_cube" "$top_srcdir/examples/solve_cube.c" $flags 2> "$work/cc.err"
ok $? "the example builds with pkg-config's flags alone $(head -c 300 "$work/cc.err")"
libdir=$(pkg-config --variable=libdir radiosity)
LD_LIBRARY_PATH="$libdir" "$work/solve_cube" "$top_srcdir/data/goral1984-cube.scene" > "$work/out"
[ $? -eq 0 ] && [ "$(wc -l < "$work/out")" -eq 7 ]; ok $? "and runs against the installed library"
# rad_version() is configure's version, as the .pc file says it (two
# substitutions of one value, made apart); rad_scene_dir() is where the
# scenes went, and the installed example builds and runs from elsewhere
printf '#include <stdio.h>\n#include <radiosity.h>\nint main(void) { printf("%%s\\n%%s\\n", rad_version(), rad_scene_dir()); return 0; }\n' > "$work/ver.c"
${CC:-cc} ${RADIOSITY_SANITIZE-} -o "$work/ver" "$work/ver.c" $flags 2> "$work/cc.err" &&
  LD_LIBRARY_PATH="$libdir" "$work/ver" > "$work/ver.out"
ok $? "a program calling rad_version() and rad_scene_dir() builds and runs $(head -c 300 "$work/cc.err")"
[ "$(sed -n 1p "$work/ver.out")" = "$have" ]
ok $? "rad_version() is pkg-config's version ($(sed -n 1p "$work/ver.out"), $have)"
[ -f "$stage$(sed -n 2p "$work/ver.out")/goral1984-cube.scene" ]
ok $? "rad_scene_dir() names where make install put the scenes ($(sed -n 2p "$work/ver.out"))"
example=$(find "$stage" -path '*/examples/solve_cube.c' | head -n 1)
[ -n "$example" ] && ${CC:-cc} ${RADIOSITY_SANITIZE-} -o "$work/installed_example" "$example" $flags 2> "$work/cc.err"
ok $? "the example is installed (${example#"$stage"}) and builds $(head -c 300 "$work/cc.err")"
[ -n "$example" ] && grep -q '^## Reporting bugs' "$(dirname "$(dirname "$example")")/README.md"
ok $? "README.md, which --help names for bug reports, is installed beside the examples"
so=$(ls "$libdir"/libradiosity.so.* | head -n 1)
nm -D --defined-only "$so" | awk '$2 != "A" { print $3 }' | sort -u > "$work/exported"
incdir=$(pkg-config --variable=includedir radiosity)
# every function declaration in the installed headers: `[RAD_API] [const|unsigned]... TYPE rad_NAME(`
cat "$incdir/radiosity.h" "$incdir"/radiosity/*.h |
  sed -n -E 's/^(RAD_API )?((const |unsigned )*)[a-z_0-9]+[ *]+\**(rad_[a-z_0-9]+)\(.*/\4/p' |
  sort -u > "$work/declared"
[ -s "$work/declared" ] && diff "$work/declared" "$work/exported" > "$work/diff"
ok $? "nm -D lists exactly the $(wc -l < "$work/declared") functions the headers declare $(tr '\n' ' ' < "$work/diff" | head -c 400)"
cat "$incdir/radiosity.h" "$incdir"/radiosity/*.h | grep -q '^RAD_API'
ok $? "the headers mark what is exported (RAD_API)"
# the public prefix is the public API's alone: every function the library's
# objects define named rad_* is one the headers declare (internal ones are
# radi_*), so a reader tells them apart at the call site
core="${top_builddir:-.}/src/.libs/libradcore.a"
if [ -f "$core" ]; then
  nm --defined-only "$core" 2> /dev/null | awk '$2 ~ /^[TtWiDdRrBb]$/ { print $3 }' |
    sed 's/\..*//' | grep '^rad_' | sort -u > "$work/prefixed"
  comm -23 "$work/prefixed" "$work/declared" > "$work/internal"
  [ -s "$work/prefixed" ] && [ ! -s "$work/internal" ]
  ok $? "no internal name carries the public prefix rad_ ($(wc -l < "$work/prefixed") do, all declared; others:$(tr '\n' ' ' < "$work/internal" | head -c 300))"
else
  skip "no src/.libs/libradcore.a to read"
fi
missing=
while read -r f; do grep -q "$f" "$top_srcdir/man/radiosity.3" || missing="$missing $f"; done < "$work/declared"
[ -z "$missing" ]; ok $? "radiosity(3) names every declared function:${missing:- yes}"
# each installed header stands alone, in C and in C++ (extern "C")
bad=
for h in "$incdir/radiosity.h" "$incdir"/radiosity/*.h; do
  rel=${h#"$incdir"/}
  printf '#include <%s>\nint main(void) { return 0; }\n' "$rel" > "$work/one.c"
  ${CC:-cc} -Wall -Wextra -Werror -I"$incdir" -c "$work/one.c" -o "$work/one.o" 2>> "$work/hdr.err" || bad="$bad $rel(C)"
  if command -v ${CXX:-c++} > /dev/null 2>&1; then
    cp "$work/one.c" "$work/one.cc"
    ${CXX:-c++} -Wall -Wextra -Werror -I"$incdir" -c "$work/one.cc" -o "$work/one.o" 2>> "$work/hdr.err" || bad="$bad $rel(C++)"
  fi
done
[ -z "$bad" ]; ok $? "every installed header compiles alone in C and C++:${bad:- yes}"
# the installed headers speak of the API, not of the sources behind it:
# no .c file, no header but the public ones and the C library's
cat "$incdir/radiosity.h" "$incdir"/radiosity/*.h | grep -o '[A-Za-z0-9_]*\.[ch]\b' |
  grep -v -x -e 'radiosity\.h' -e 'std[a-z]*\.h' $(for h in "$incdir"/radiosity/*.h; do
    printf -- '-e %s ' "$(basename "$h" | sed 's/\./\\./')"; done) | sort -u > "$work/named"
[ ! -s "$work/named" ]; ok $? "the installed headers name no internal file:$(tr '\n' ' ' < "$work/named")"
# the Python module, where make install put it, imports with the staged
# library and answers (an interpreter not instrumented cannot load an
# instrumented module without preloading; python.sh covers that case)
if [ -n "${RADIOSITY_PYTHON-}" ] && [ -z "${RADIOSITY_SANITIZE-}" ]; then
  mod=$(find "$stage" -name 'radiosity*.so' -path '*-packages/*' | head -n 1)
  [ -n "$mod" ] && (cd "$work" && LD_LIBRARY_PATH="$libdir" PYTHONPATH="$(dirname "$mod")" \
    "$RADIOSITY_PYTHON" -c 'import sys, radiosity
s = radiosity.load_scene(sys.argv[1])
print(radiosity.__version__, radiosity.form_factors(s).shape)' \
    "$top_srcdir/data/goral1984-cube.scene" > "$work/py.out" 2>&1) &&
    [ "$(cat "$work/py.out")" = "$have (294, 294)" ]
  ok $? "the Python module is installed (${mod#"$stage"}), imports from there and answers: $(head -c 300 "$work/py.out")"
  [ -n "$(find "$stage" -path '*/man3/radiosity-python.3')" ]
  ok $? "radiosity-python(3) is installed"
else
  skip "the Python binding is not built here, or the build is instrumented"
fi
done_testing
