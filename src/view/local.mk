## src/view/local.mk -- the view module: the live viewer's HTTP server and session.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradview_la_SOURCES += \
	%reldir%/adaptview.c \
	%reldir%/animator.c \
	%reldir%/commands.c \
	%reldir%/hemiview.c \
	%reldir%/history.c \
	%reldir%/jsonbuf.c \
	%reldir%/jsonread.c \
	%reldir%/methods.c \
	%reldir%/scenejson.c \
	%reldir%/server.c \
	%reldir%/session.c \
	%reldir%/shown.c \
	%reldir%/view.h %reldir%/viewint.h
