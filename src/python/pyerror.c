/* pyerror.c -- the binding's shared helpers: the module's state, the
 * library's errors raised as radiosity.Error, names of enum values read.
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING. */
#include "python/pyrad.h"

radi_py_state *radi_py_state_of(PyObject *module)
{
    return PyModule_GetState(module);
}

PyObject *radi_py_text(const char *s)
{
    return PyUnicode_DecodeUTF8(s, (Py_ssize_t)strlen(s), "backslashreplace");
}

int radi_py_warn(const char *message)
{
    PyObject *msg = radi_py_text(message);
    if (!msg)
        return -1;
    const int r = PyErr_WarnEx(PyExc_RuntimeWarning, PyUnicode_AsUTF8(msg), 1);
    Py_DECREF(msg);
    return r;
}

PyObject *radi_py_raise(PyObject *module, const rad_error *err)
{
    const radi_py_state *st = radi_py_state_of(module);
    PyObject *msg = radi_py_text(err->message);
    PyObject *exc = msg ? PyObject_CallOneArg(st->error, msg) : NULL;
    Py_XDECREF(msg);
    if (!exc)
        return NULL;
    PyObject *status = PyUnicode_FromString(rad_strstatus(err->status));
    if (status && PyObject_SetAttrString(exc, "status", status) == 0)
        PyErr_SetObject(st->error, exc);
    Py_XDECREF(status);
    Py_DECREF(exc);
    return NULL;
}

int radi_py_choice(const char *(*namefn)(int), const char *what, const char *given)
{
    char choices[160] = "";
    for (int k = 0; namefn(k); k++) {
        if (strcmp(namefn(k), given) == 0)
            return k;
        size_t used = strlen(choices);
        snprintf(choices + used, sizeof choices - used, "%s'%s'", k ? ", " : "", namefn(k));
    }
    PyErr_Format(PyExc_ValueError, "%s must be one of %s, not '%s'", what, choices, given);
    return -1;
}
