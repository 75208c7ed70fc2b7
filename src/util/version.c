/* version.c -- what the library is and where its data was installed.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Both strings are fixed when the library is built: the version is the
 * one configure was given (the same as `radiosity --version` and
 * `pkg-config --modversion radiosity`), the folder is where `make
 * install` puts the shipped scenes ($(pkgdatadir)/scenes, passed by
 * Makefile.am as RAD_SCENEDIR).
 */
#include <config.h>

#include "radiosity/base.h"

#ifndef RAD_SCENEDIR
#error "RAD_SCENEDIR (the installed scenes' folder) is set by Makefile.am"
#endif

const char *rad_version(void)
{
    return PACKAGE_VERSION;
}

const char *rad_scene_dir(void)
{
    return RAD_SCENEDIR;
}
