/* radiosity/base.h -- what every part of the API shares: export marks, bands, status and errors, vectors, memory.
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 * Everything public starts with `rad_`.  The library keeps no global
 * mutable state: every function works on the objects it is given, so
 * separate objects may be used from separate threads.
 *
 * Conventions, stated once:
 *   - lengths are in the user's unit; radiosity B and emission E share one
 *     radiometric unit (power per area); form factors are dimensionless;
 *   - polygons run counter-clockwise seen from their front side, the side
 *     that reflects and emits; the front normal follows the right-hand rule;
 *   - colour bands are RAD_BANDS = 3 (red, green, blue), index 0, 1, 2;
 *   - matrices are double, column-major (LAPACK): entry (i, j) of an n x n
 *     matrix M is M[i + j*n]; F[i + j*n] is the form factor FROM element i
 *     TO element j (row i = from element i);
 *   - a function that can fail returns a rad_status and, when given a
 *     rad_error, fills it with a message of the form "FILE:LINE: reason"
 *     for input errors, or a plain reason otherwise.  Library code never
 *     prints.
 */
#ifndef RADIOSITY_BASE_H
#define RADIOSITY_BASE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* RAD_API marks what the shared library exports; it is built with hidden
 * visibility, so nothing else leaves it (Drepper, "How to Write Shared
 * Libraries", 2011, section 2.2). */
#if defined(__GNUC__) && __GNUC__ >= 4
#define RAD_API __attribute__((visibility("default")))
#else
#define RAD_API
#endif

#define RAD_BANDS 3

/* ---- status and errors -------------------------------------------------- */

typedef enum rad_status {
    RAD_OK = 0,
    RAD_ERR_NOMEM,      /* allocation failed */
    RAD_ERR_IO,         /* a file could not be read or written */
    RAD_ERR_PARSE,      /* malformed input (message names file and line) */
    RAD_ERR_INVALID,    /* an argument out of its domain */
    RAD_ERR_TOOBIG,     /* the problem does not fit in memory */
    RAD_ERR_SINGULAR,   /* the radiosity system is (numerically) singular */
    RAD_ERR_NOCONV      /* an iteration stopped without converging */
} rad_status;

#define RAD_ERRMSG_MAX 512

typedef struct rad_error {
    rad_status status;
    char message[RAD_ERRMSG_MAX];
} rad_error;

/* A short English name of a status ("singular system", ...). */
RAD_API const char *rad_strstatus(rad_status status);

/* ---- the library -------------------------------------------------------- */

/* The library's version, as configure was given it ("0.1.0"): the same
 * as `radiosity --version` and `pkg-config --modversion radiosity`. */
RAD_API const char *rad_version(void);
/* The folder where `make install` put the shipped scenes (the 1984 cube
 * is goral1984-cube.scene there), without a trailing slash. */
RAD_API const char *rad_scene_dir(void);

/* ---- geometry ----------------------------------------------------------- */

typedef struct rad_vec3 {
    double x, y, z;
} rad_vec3;

/* ---- memory ------------------------------------------------------------- */

/* Bytes of memory available now (Linux MemAvailable), 0 if unknown. */
RAD_API double rad_memory_available(void);
/* Refuse (RAD_ERR_TOOBIG) when `need` bytes exceed what the machine allows
 * now (rad_memory_limit); `what` names the need in the message.  *have
 * (may be NULL) receives the limit, 0 if unknown. */
RAD_API rad_status rad_memory_check(double need, const char *what, double *have, rad_error *err);

/* The smallest of the memory available now (MemAvailable), the address
 * space and data limits (RLIMIT_AS, RLIMIT_DATA) and the cgroup's
 * memory.max less its memory.current; 0 if none is known. */
RAD_API double rad_memory_limit(void);

#ifdef __cplusplus
}
#endif

#endif /* RADIOSITY_BASE_H */
