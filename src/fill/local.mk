## src/fill/local.mk -- the fill module: the matrix F: dense fill, blocks, rows per shot, hemicube matrix, per-surface sums.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/fill.h \
	%reldir%/ffblock.c %reldir%/ffblock.h \
	%reldir%/ffmatrix.c \
	%reldir%/ffpairs.h \
	%reldir%/ffrow.c %reldir%/ffrow.h \
	%reldir%/hcmatrix.c \
	%reldir%/persurface.c %reldir%/persurface.h
