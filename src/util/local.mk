## src/util/local.mk -- the util module: errors, vectors, polygons, line and number readers, memory limits, exact printing, the version.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/util.h \
	%reldir%/blasthreads.c \
	%reldir%/fmtdouble.c %reldir%/fmtdouble.h \
	%reldir%/jsonstr.c %reldir%/jsonstr.h \
	%reldir%/lapack.h \
	%reldir%/polygon.c %reldir%/polygon.h \
	%reldir%/pow10tab.h \
	%reldir%/readfile.c %reldir%/readfile.h \
	%reldir%/readnum.c %reldir%/readnum.h \
	%reldir%/status.c %reldir%/status.h \
	%reldir%/sysmem.c \
	%reldir%/vec.h \
	%reldir%/vecmath.h \
	%reldir%/version.c
