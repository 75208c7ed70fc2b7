## src/solve/local.mk -- the solve module: the radiosity system: LU, Cholesky, iterations, CG, progressive refinement, matrix-free.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/solve.h \
	%reldir%/balance.c \
	%reldir%/cg.c \
	%reldir%/cholesky.c \
	%reldir%/fpass.c %reldir%/fpass.h \
	%reldir%/iterate.c \
	%reldir%/lu.c %reldir%/lu.h \
	%reldir%/lusolve.c \
	%reldir%/progressive.c %reldir%/progressive.h \
	%reldir%/scale.c \
	%reldir%/solve.c \
	%reldir%/solvefree.c %reldir%/solvefree.h \
	%reldir%/solvers.h
