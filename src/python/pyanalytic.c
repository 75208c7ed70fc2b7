/* pyanalytic.c -- radiosity.analytic: the closed forms of the library.
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The four configurations `radiosity analytic` prints, each a function of
 * positive finite lengths (any one unit) returning a float; a length that
 * is not positive and finite raises ValueError, as the program refuses it. */
#include <math.h>

#include "python/pyrad.h"

typedef double (*closed2)(double, double);
typedef double (*closed3)(double, double, double);

/* Parse k positive finite floats of `name`; 0, or -1 with ValueError. */
static int lengths(PyObject *args, const char *format, const char *name, double *x, int k)
{
    if (!PyArg_ParseTuple(args, format, &x[0], &x[1], &x[2]))
        return -1;
    for (int i = 0; i < k; i++)
        if (!(x[i] > 0) || !isfinite(x[i])) {
            PyErr_Format(PyExc_ValueError, "%s: every length must be positive and finite",
                         name);
            return -1;
        }
    return 0;
}

static PyObject *value_or_error(double f, const char *name)
{
    if (!isfinite(f)) {
        PyErr_Format(PyExc_ValueError, "%s: no finite value for these lengths", name);
        return NULL;
    }
    return PyFloat_FromDouble(f);
}

static PyObject *point_disk(PyObject *self, PyObject *args)
{
    (void)self;
    double x[3] = {0, 0, 0};
    if (lengths(args, "dd:point_disk", "point_disk", x, 2) != 0)
        return NULL;
    return value_or_error(rad_analytic_point_disk(x[0], x[1]), "point_disk");
}

static PyObject *disk_disk(PyObject *self, PyObject *args)
{
    (void)self;
    double x[3];
    if (lengths(args, "ddd:disk_disk", "disk_disk", x, 3) != 0)
        return NULL;
    return value_or_error(rad_analytic_disk_disk(x[0], x[1], x[2]), "disk_disk");
}

static PyObject *parallel_rectangles(PyObject *self, PyObject *args)
{
    (void)self;
    double x[3];
    if (lengths(args, "ddd:parallel_rectangles", "parallel_rectangles", x, 3) != 0)
        return NULL;
    return value_or_error(rad_analytic_parallel_rectangles(x[0], x[1], x[2]), "parallel_rectangles");
}

static PyObject *perpendicular_rectangles(PyObject *self, PyObject *args)
{
    (void)self;
    double x[3];
    if (lengths(args, "ddd:perpendicular_rectangles", "perpendicular_rectangles", x, 3) != 0)
        return NULL;
    return value_or_error(rad_analytic_perpendicular_rectangles(x[0], x[1], x[2]),
                  "perpendicular_rectangles");
}

static PyMethodDef functions[] = {
    {"point_disk", point_disk, METH_VARARGS,
     "point_disk(r, h): from a differential area to a coaxial parallel disk of\n"
     "radius r at distance h."},
    {"disk_disk", disk_disk, METH_VARARGS,
     "disk_disk(r1, r2, h): from a disk of radius r1 to a coaxial parallel disk\n"
     "of radius r2, h apart."},
    {"parallel_rectangles", parallel_rectangles, METH_VARARGS,
     "parallel_rectangles(a, b, c): between directly opposed a x b rectangles,\n"
     "c apart."},
    {"perpendicular_rectangles", perpendicular_rectangles, METH_VARARGS,
     "perpendicular_rectangles(l, w, h): from the l x w rectangle to the l x h\n"
     "rectangle that shares its edge of length l at a right angle."},
    {NULL, NULL, 0, NULL}};

int radi_py_analytic_init(PyObject *module)
{
    PyObject *sub = PyModule_New("radiosity.analytic");
    if (!sub)
        return -1;
    if (PyModule_AddFunctions(sub, functions) != 0 ||
        PyModule_SetDocString(sub, "Closed-form view factors: the cases of `radiosity "
                                   "analytic`.") != 0 ||
        PyModule_AddObjectRef(module, "analytic", sub) != 0) {
        Py_DECREF(sub);
        return -1;
    }
    Py_DECREF(sub);
    return 0;
}
