## src/ff/local.mk -- the ff module: one pair's form factor: contour integral, Gauss rules, area rules, closed forms.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/analytic.c %reldir%/analytic.h \
	%reldir%/ffarea.c \
	%reldir%/ffarealong.c \
	%reldir%/ffcontour.c \
	%reldir%/ffcontour_tmpl.h \
	%reldir%/ffgauss.c \
	%reldir%/ffprim.c \
	%reldir%/formfactor.c %reldir%/formfactor.h \
	%reldir%/gauss.c \
	%reldir%/gausstab.h
