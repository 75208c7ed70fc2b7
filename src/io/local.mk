## src/io/local.mk -- the io module: our file formats and others' matrices read: tables, Matrix Market, PLY, NumPy, View3D.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/export.c \
	%reldir%/ffread.c %reldir%/ffread.h \
	%reldir%/npy.c \
	%reldir%/npyread.c \
	%reldir%/plyread.c \
	%reldir%/vfread.c
