## src/python/local.mk -- the python module: the binding, import radiosity, answers as NumPy arrays.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

# A Python extension module (PEP 489), built when configure found a Python
# 3 with its headers and NumPy.  It links the shared library as any user's
# program would, and is named as that interpreter imports extensions
# (EXT_SUFFIX, e.g. radiosity.cpython-311-x86_64-linux-gnu.so).
if HAVE_PYTHON
pyexec_LTLIBRARIES = %reldir%/radiosity.la
endif
%canon_reldir%_radiosity_la_SOURCES = %reldir%/pymodule.c %reldir%/pyscene.c \
	%reldir%/pyrun.c %reldir%/pyerror.c %reldir%/pyanalytic.c \
	%reldir%/pyrad.h
%canon_reldir%_radiosity_la_CPPFLAGS = $(AM_CPPFLAGS) $(PYTHON_CPPFLAGS)
# Python's argument parser takes its keyword lists as char *[] before 3.13:
# string literals stay char[] here
%canon_reldir%_radiosity_la_CFLAGS = $(WARN_CFLAGS) -Wno-write-strings -fvisibility=hidden
%canon_reldir%_radiosity_la_LDFLAGS = -module -avoid-version -shared \
	-shrext $(PYTHON_EXT_SUFFIX)
%canon_reldir%_radiosity_la_LIBADD = src/libradiosity.la
