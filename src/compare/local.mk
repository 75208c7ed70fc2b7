## src/compare/local.mk -- the compare module: another solver's numbers against ours; RMS errors.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/compare.h \
	%reldir%/elmatch.c %reldir%/elmatch.h \
	%reldir%/ffcompare.c %reldir%/ffcompare.h \
	%reldir%/rmserror.c %reldir%/rmserror.h
