## src/cli/local.mk -- the cli module: the program: options, commands, outputs written whole.
## Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
## Included by Makefile.am; %reldir% is this folder.

CLI_SOURCES += \
	%reldir%/animout.c %reldir%/animrun.h \
	%reldir%/atomicfile.c %reldir%/atomicfile.h \
	%reldir%/cli.c %reldir%/cli.h \
	%reldir%/cli_adaptive.c \
	%reldir%/cli_common.c \
	%reldir%/cli_output.c \
	%reldir%/cmd_analytic.c \
	%reldir%/cmd_animate.c \
	%reldir%/cmd_compare.c \
	%reldir%/cmd_formfactor.c \
	%reldir%/cmd_progress.c \
	%reldir%/cmd_render.c \
	%reldir%/cmd_solve.c \
	%reldir%/cmd_sweep.c \
	%reldir%/cmd_view.c \
	%reldir%/compare_print.c %reldir%/compare_print.h \
	%reldir%/progress_adaptive.c %reldir%/progress_adaptive.h \
	%reldir%/progress_snap.c %reldir%/progress_snap.h
