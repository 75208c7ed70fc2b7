## src/render/local.mk -- the render module: camera, z-buffer, PNG, plots, exposure, error colours.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/render.h \
	%reldir%/errcolour.c %reldir%/errcolour.h \
	%reldir%/exposure.c \
	%reldir%/plot.c %reldir%/plot.h \
	%reldir%/plotxy.c %reldir%/plotxy.h \
	%reldir%/render.c
