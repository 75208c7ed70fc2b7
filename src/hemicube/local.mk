## src/hemicube/local.mk -- the hemicube module: the hemicube of Cohen & Greenberg 1985: delta factors, item buffers.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/hcdelta.c \
	%reldir%/hemicube.c %reldir%/hemicube.h
