## src/occ/local.mk -- the occ module: hidden surfaces: shafts, blockers, solids, the hidden part's integral; CGAL only here.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/occclosed.c \
	%reldir%/occdomain.c \
	%reldir%/occeee.c \
	%reldir%/occevent.c \
	%reldir%/occflat.c \
	%reldir%/occhidden.c \
	%reldir%/occleaves.c \
	%reldir%/occlusion.c %reldir%/occlusion.h \
	%reldir%/occmesh.c \
	%reldir%/occpoint.c \
	%reldir%/occrule.c \
	%reldir%/occshaft.c \
	%reldir%/occsolid.c \
	%reldir%/occspace.c %reldir%/occspace.h \
	%reldir%/occsplit.c \
	%reldir%/occtree.c \
	%reldir%/occunion.c \
	%reldir%/visibility.cc %reldir%/visibility.h
