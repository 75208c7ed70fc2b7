## src/adapt/local.mk -- the adapt module: adaptive subdivision (Cohen et al. 1988, section 4).
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/adapt.h \
	%reldir%/adaptive.c %reldir%/adaptive.h \
	%reldir%/adaptmesh.c %reldir%/adaptmesh.h \
	%reldir%/adaptnodes.c %reldir%/adaptnodes.h \
	%reldir%/adaptproject.c %reldir%/adaptproject.h \
	%reldir%/adaptrace.c %reldir%/adaptrace.h \
	%reldir%/adaptsplit.c \
	%reldir%/adaptstate.h
