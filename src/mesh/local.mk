## src/mesh/local.mk -- the mesh module: equal elements, shooting patches, vertex smoothing.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/crease.c \
	%reldir%/creaseedge.c \
	%reldir%/mesh.c %reldir%/mesh.h \
	%reldir%/meshgeom.c \
	%reldir%/meshtri.c \
	%reldir%/patchgrid.c %reldir%/patchgrid.h \
	%reldir%/reported.c \
	%reldir%/smooth.c
