## src/scene/local.mk -- the scene module: the scene: parser, OBJ and View3D readers, builder, polygon checks, changes.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/changeapply.c \
	%reldir%/changeread.c \
	%reldir%/objread.c %reldir%/objread.h \
	%reldir%/objrepair.c %reldir%/objrepair.h \
	%reldir%/polycheck.c %reldir%/polycheck.h \
	%reldir%/repairtext.c \
	%reldir%/scene.c \
	%reldir%/scenebuild.c %reldir%/scenebuild.h \
	%reldir%/scenepresent.c \
	%reldir%/vs3read.c %reldir%/vs3read.h
