## src/mpi/local.mk -- the mpi module: the distributed solve over MPI and ScaLAPACK.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradmpi_la_SOURCES += \
	%reldir%/mpi_jacobi.c %reldir%/mpi_jacobi.h \
	%reldir%/mpi_layout.c %reldir%/mpi_layout.h \
	%reldir%/mpi_solve.c %reldir%/mpi_solve.h \
	%reldir%/scalapack.h
