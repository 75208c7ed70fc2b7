## src/anim/local.mk -- the anim module: redistribution through frames (George, Sillion & Greenberg 1990).
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/anim.h \
	%reldir%/animate.c \
	%reldir%/animerror.c \
	%reldir%/animframe.c \
	%reldir%/animimportance.c \
	%reldir%/animint.h \
	%reldir%/animlog.c \
	%reldir%/animpairs.c \
	%reldir%/animshoot.c
