/* pyrad.h -- the Python binding's shared parts: the module's state, the
 * scene object, and how the library's errors become Python exceptions.
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The binding is a client of the installed library: it includes only the
 * installed headers and links libradiosity, as any user's program would.
 * It keeps no state of its own outside the module object (the exception
 * and the Scene type live in the module's state, PEP 573); NumPy's C API
 * table, which import_array() fills once per process, is NumPy's own.
 *
 * Conventions of the arrays it returns: float64; F is n x n with row i the
 * form factors from element i (F[i, j] = F_ij, the library's column-major
 * buffer viewed in Fortran order, so no copy); per-element values are
 * n x 3, one column per colour band (red, green, blue). */
#ifndef RADI_PYRAD_H
#define RADI_PYRAD_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <limits.h>
#include <string.h>

#include "radiosity.h"

typedef struct radi_py_state {
    PyObject *error;            /* radiosity.Error */
    PyTypeObject *scene_type;   /* radiosity.Scene */
} radi_py_state;

/* A loaded scene, as read: runs mesh a copy of it. */
typedef struct radi_py_scene {
    PyObject_HEAD
    rad_scene scene;
    int loaded;                 /* 0 until rad_scene_* filled it */
} radi_py_scene;

/* pyerror.c */
radi_py_state *radi_py_state_of(PyObject *module);
/* A message of the library as a str: its bytes are UTF-8 but for file
 * and material names, which may hold any (shown as \xNN). */
PyObject *radi_py_text(const char *s);
/* Say a message as a RuntimeWarning; -1 when a filter made it an error. */
int radi_py_warn(const char *message);
/* Raise radiosity.Error with the library's message ("FILE:LINE: reason");
 * returns NULL. */
PyObject *radi_py_raise(PyObject *module, const rad_error *err);
/* The value of the enum whose name (namefn(k) for k = 0, 1, ...) is
 * `given`; raises ValueError naming the choices and returns -1 if none. */
int radi_py_choice(const char *(*namefn)(int), const char *what, const char *given);

/* pyscene.c */
int radi_py_scene_init(PyObject *module, radi_py_state *st);
PyObject *radi_py_load_scene(PyObject *module, PyObject *args, PyObject *kw);
/* The scene a run works on: the present part of `obj` (a Scene), meshed
 * as rad_scene_set_mesh does when `mesh` is a pair (N, M), not None, or
 * so that no element side exceeds max_size when that is not 0.
 * Returns 0, or -1 with an exception set. */
int radi_py_run_scene(PyObject *module, PyObject *obj, PyObject *mesh, double max_size,
                      rad_scene *out);

/* pyanalytic.c: the submodule radiosity.analytic */
int radi_py_analytic_init(PyObject *module);

/* pyrun.c */
int radi_py_numpy_init(void);
PyObject *radi_py_form_factors(PyObject *module, PyObject *args, PyObject *kw);
PyObject *radi_py_solve(PyObject *module, PyObject *args, PyObject *kw);
PyObject *radi_py_elements(PyObject *module, PyObject *args, PyObject *kw);
PyObject *radi_py_vertices(PyObject *module, PyObject *args, PyObject *kw);

#endif /* RADI_PYRAD_H */
