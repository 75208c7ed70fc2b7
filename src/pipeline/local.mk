## src/pipeline/local.mk -- the pipeline module: the whole run, scene to smoothed radiosity, as one call; accuracy against a reference.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

src_libradcore_la_SOURCES += \
	%reldir%/accuracy.c \
	%reldir%/pipeline.c
