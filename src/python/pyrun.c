/* pyrun.c -- radiosity.form_factors, radiosity.solve, radiosity.elements:
 * runs of the library on a Scene, answered as NumPy arrays.
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Each run meshes a copy of the scene (pyscene.c), releases the GIL for
 * the library's work, and lets Ctrl-C stop it: the library's progress
 * callback, called between blocks of rows on the calling thread, takes
 * the GIL back for a moment to look for a pending signal, and asks the
 * fill to stop when there is one (the run then raises KeyboardInterrupt).
 * What the program says as warnings (entries outside [0, 1], rows above
 * 1, promises not met) is said as RuntimeWarning; strict=True turns an
 * unmet promise into radiosity.Error, as --strict does. */
#include "python/pyrad.h"

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>

#include <stdarg.h>
#include <stdio.h>

int radi_py_numpy_init(void)
{
    import_array1(-1);
    return 0;
}

/* ---- options ------------------------------------------------------------ */

/* The program's limits (--threads, --bounces): more threads than this
 * make OpenMP fail to start them, more bounces than this cannot be
 * stopped in any useful time. */
#define THREADS_MAX 4096
#define BOUNCES_MAX 1000000000L

typedef struct run_args {
    PyObject *scene, *mesh;
    double max_size;            /* max_element_size, or 0 */
    PyObject *progress;         /* None, or called as progress(stage, done, total) */
    const char *accuracy, *method;
    int quadrature, resolution, threads, strict;
} run_args;

static void run_args_init(run_args *a)
{
    a->mesh = Py_None;
    a->max_size = 0;
    a->progress = Py_None;
    a->accuracy = "default";
    a->method = "contour";
    a->quadrature = 3;
    a->resolution = RAD_HEMICUBE_DEFAULT;
    a->threads = 0;
    a->strict = 0;
}

/* The library's progress callback: a pending signal's handler runs here,
 * then the caller's progress(stage, done, total); an exception from
 * either, or a true return, asks the library to stop. */
static int check_interrupt(void *user, const char *stage, double done, double total)
{
    PyObject *progress = user;
    PyGILState_STATE g = PyGILState_Ensure();
    int stop = PyErr_CheckSignals() != 0;
    if (!stop && progress != Py_None) {
        PyObject *r = PyObject_CallFunction(progress, "sdd", stage, done, total);
        stop = !r || PyObject_IsTrue(r) != 0;
        Py_XDECREF(r);
    }
    PyGILState_Release(g);
    return stop;
}

/* The form-factor options the arguments name; -1 with ValueError. */
static int ff_options(const run_args *a, rad_ff_options *ff)
{
    rad_ff_options_init(ff);
    const int acc = radi_py_choice(rad_accuracy_name, "accuracy", a->accuracy);
    const int method = acc < 0 ? -1 : radi_py_choice(rad_ff_method_name, "method", a->method);
    if (method < 0)
        return -1;
    if (a->quadrature < 1 || a->quadrature > RAD_GAUSS_MAX) {
        PyErr_Format(PyExc_ValueError, "quadrature must be 1 to %d Gauss points, not %d",
                     RAD_GAUSS_MAX, a->quadrature);
        return -1;
    }
    if (a->resolution < 2 || a->resolution > RAD_HEMICUBE_MAX || a->resolution % 2) {
        PyErr_Format(PyExc_ValueError, "resolution must be even, 2 to %d, not %d",
                     RAD_HEMICUBE_MAX, a->resolution);
        return -1;
    }
    if (a->progress != Py_None && !PyCallable_Check(a->progress)) {
        PyErr_SetString(PyExc_TypeError, "progress must be callable or None");
        return -1;
    }
    if (a->threads < 0 || a->threads > THREADS_MAX) {
        PyErr_Format(PyExc_ValueError, "threads must be 0 (all cores) to %d, not %d",
                     THREADS_MAX, a->threads);
        return -1;
    }
    ff->accuracy = (rad_accuracy)acc;
    ff->method = (rad_ff_method)method;
    ff->quadrature = a->quadrature;
    ff->resolution = a->resolution;
    ff->threads = a->threads;
    ff->progress = check_interrupt;
    ff->progress_user = a->progress;
    return 0;
}

static int warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int warn(const char *fmt, ...)
{
    char msg[RAD_ERRMSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return radi_py_warn(msg);
}

/* What the fill found that a user must hear (the program's words); -1
 * with an exception when strict refuses an unmet promise or a warning
 * became an error. */
static int ff_verdict(PyObject *module, const rad_ff_options *ff, const rad_ff_stats *st,
                      int strict)
{
    const char *mode = rad_accuracy_name(ff->accuracy);
    const char *hint = ff->accuracy == RAD_ACCURACY_CLASSIC
                           ? ": the classic rule fails for this geometry; try accuracy='default'"
                           : "";
    if ((st->negative || st->above_one) &&
        warn("%ld form factors below 0 and %ld above 1 (min %.3g, max %.3g)%s", st->negative,
             st->above_one, st->min_value, st->max_value, hint) != 0)
        return -1;
    if (st->rows_above_one && warn("%ld rows of F sum to more than 1 + %g (energy from "
                                   "nowhere)%s", st->rows_above_one, RAD_ROW_SUM_SLACK,
                                   hint) != 0)
        return -1;
    if (st->promise_unmet == 0)
        return 0;
    if (!strict)
        return warn("%ld form factors miss the %s mode's promise of %g relative error (their "
                    "own estimates say so)%s", st->promise_unmet, mode, st->promise,
                    ff->accuracy == RAD_ACCURACY_DEFAULT ? "; try accuracy='reference'" : "");
    rad_error err = {RAD_ERR_INVALID, ""};
    snprintf(err.message, sizeof err.message, "%ld form factors miss the %s mode's promise of "
             "%g relative error (their own estimates say so); strict=True makes that an error",
             st->promise_unmet, mode, st->promise);
    radi_py_raise(module, &err);
    return -1;
}

/* The mesh of the run's scene, refused before meshing when F (and E)
 * would not fit. */
static int build_mesh(PyObject *module, const rad_scene *sc, int matrices, rad_mesh *mesh)
{
    rad_error err;
    const double ne = rad_scene_element_count(sc);
    char what[96];
    snprintf(what, sizeof what, "%.0f elements (%d x 8 n^2 bytes of matrices)", ne, matrices);
    if (ne > INT_MAX) {
        err.status = RAD_ERR_TOOBIG;
        snprintf(err.message, sizeof err.message, "the scene's meshes make %.0f elements, more "
                 "than %d", ne, INT_MAX);
    } else if (rad_memory_check(8.0 * matrices * ne * ne, what, NULL, &err) == RAD_OK &&
               rad_mesh_build(mesh, sc, &err) == RAD_OK)
        return 0;
    radi_py_raise(module, &err);
    return -1;
}

/* The first k x k doubles of an n x n Fortran-ordered array (where
 * rad_mesh_reduce leaves the reported matrix), as a new array (steals a
 * reference to `full`). */
static PyObject *reported_block(PyObject *full, npy_intp n, npy_intp k)
{
    if (!full || k == n)
        return full;
    npy_intp dims[2] = {k, k};
    PyObject *out = PyArray_EMPTY(2, dims, NPY_FLOAT64, 1);
    if (out)
        memcpy(PyArray_DATA((PyArrayObject *)out), PyArray_DATA((PyArrayObject *)full),
               sizeof(double) * (size_t)k * (size_t)k);
    Py_DECREF(full);
    return out;
}

/* F (and E) reduced in place to the reported rows (rad_mesh_reported:
 * View3D's shape); their count in *k. */
static rad_status reduce(const rad_scene *sc, const rad_mesh *mesh, PyObject *F, PyObject *E,
                         int *k, rad_error *err)
{
    const int n = mesh->nelements;
    int *row = malloc(sizeof *row * ((size_t)n + 1));
    double *area = malloc(sizeof *area * ((size_t)n + 1));
    rad_status st = RAD_OK;
    if (!row || !area) {
        st = err->status = RAD_ERR_NOMEM;
        snprintf(err->message, sizeof err->message, "out of memory for %d elements", n);
    } else if ((*k = rad_mesh_reported(sc, mesh, row)) < n)
        st = rad_mesh_reduce(mesh, row, *k, PyArray_DATA((PyArrayObject *)F),
                             E ? PyArray_DATA((PyArrayObject *)E) : NULL, area, err);
    free(row);
    free(area);
    return st;
}

/* ---- form_factors ------------------------------------------------------- */

static PyObject *fill(PyObject *module, const run_args *a, int errors)
{
    rad_ff_options ff;
    rad_scene sc;
    rad_mesh mesh;
    if (ff_options(a, &ff) != 0 || radi_py_run_scene(module, a->scene, a->mesh, a->max_size, &sc) != 0)
        return NULL;
    if (build_mesh(module, &sc, errors ? 2 : 1, &mesh) != 0) {
        rad_scene_free(&sc);
        return NULL;
    }
    const npy_intp n = mesh.nelements, dims[2] = {n, n};
    PyObject *F = PyArray_ZEROS(2, dims, NPY_FLOAT64, 1);
    PyObject *E = errors ? PyArray_ZEROS(2, dims, NPY_FLOAT64, 1) : NULL;
    rad_status status = RAD_OK;
    rad_error err;
    rad_ff_stats st;
    memset(&st, 0, sizeof st);
    if (F && (E || !errors) && n > 0) {
        double *f = PyArray_DATA((PyArrayObject *)F);
        double *e = E ? PyArray_DATA((PyArrayObject *)E) : NULL;
        Py_BEGIN_ALLOW_THREADS
        status = rad_ff_matrix(&mesh, &ff, f, e, &st, &err);
        Py_END_ALLOW_THREADS
    }
    int kept = (int)n;
    if (F && (E || !errors) && status == RAD_OK)
        status = reduce(&sc, &mesh, F, E, &kept, &err);
    rad_mesh_free(&mesh);
    rad_scene_free(&sc);
    if (!F || (errors && !E) || PyErr_Occurred() || status != RAD_OK ||
        ff_verdict(module, &ff, &st, a->strict) != 0) {
        Py_XDECREF(F);
        Py_XDECREF(E);
        if (!PyErr_Occurred())
            radi_py_raise(module, &err);
        return NULL;
    }
    F = reported_block(F, n, kept);
    if (!errors)
        return F;
    E = reported_block(E, n, kept);
    if (!F || !E) {
        Py_XDECREF(F);
        Py_XDECREF(E);
        return NULL;
    }
    return Py_BuildValue("(NN)", F, E);
}

PyObject *radi_py_form_factors(PyObject *module, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"scene", "mesh", "accuracy", "quadrature", "method",
                             "resolution", "threads", "errors", "strict", "progress",
                             "max_element_size", NULL};
    run_args a;
    int errors = 0;
    run_args_init(&a);
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|$OsisiippOd:form_factors", kwlist,
                                     &a.scene, &a.mesh, &a.accuracy, &a.quadrature, &a.method,
                                     &a.resolution, &a.threads, &errors, &a.strict,
                                     &a.progress, &a.max_size))
        return NULL;
    return fill(module, &a, errors);
}

/* ---- solve -------------------------------------------------------------- */

/* An n x RAD_BANDS array holding a copy of the library's column-major
 * values. */
static PyObject *bands(const double *v, int n)
{
    const npy_intp dims[2] = {n, RAD_BANDS};
    PyObject *out = PyArray_EMPTY(2, dims, NPY_FLOAT64, 1);
    if (out && n > 0)
        memcpy(PyArray_DATA((PyArrayObject *)out), v, sizeof *v * (size_t)n * RAD_BANDS);
    return out;
}

static PyObject *run_solve(PyObject *module, const run_args *a, const char *solver,
                           PyObject *bounces, int vertices, double crease)
{
    rad_pipeline_options po;
    rad_pipeline_options_init(&po);
    if (solver && bounces != Py_None) {
        PyErr_SetString(PyExc_ValueError, "bounces=K is its own solver (Jacobi from B = E, "
                                          "exactly K reflections): give solver or bounces");
        return NULL;
    }
    const int s = solver ? radi_py_choice(rad_solver_name, "solver", solver) : 0;
    if (s < 0 || ff_options(a, &po.ff) != 0)
        return NULL;
    po.solve.solver = (rad_solver)s;
    po.crease = vertices ? crease : 0; /* no Bv asked: nothing to smooth */
    if (bounces != Py_None) {
        const long k = PyBool_Check(bounces) ? -2 : PyLong_AsLong(bounces);
        if (k == -1 && PyErr_Occurred())
            return NULL;
        if (k < 0 || k > BOUNCES_MAX) {
            PyErr_Format(PyExc_ValueError, "bounces must be a whole number from 0 to %ld, "
                                           "not %R", BOUNCES_MAX, bounces);
            return NULL;
        }
        po.solve.bounces = (int)k;
    }
    rad_scene sc;
    if (radi_py_run_scene(module, a->scene, a->mesh, a->max_size, &sc) != 0)
        return NULL;
    rad_result res;
    rad_error err;
    rad_status status;
    Py_BEGIN_ALLOW_THREADS
    status = rad_pipeline_run(&sc, &po, &res, &err);
    Py_END_ALLOW_THREADS
    PyObject *B = NULL;
    if (!PyErr_Occurred() && (!res.ff_done || ff_verdict(module, &po.ff, &res.ff,
                                                          a->strict) == 0)) {
        if (status != RAD_OK)
            radi_py_raise(module, &err);
        else if (!res.b_negative || warn("B is negative in %ld element-band values: no "
                                         "physical solution", res.b_negative) == 0) {
            B = bands(res.B, res.mesh.nelements);
            if (B && vertices) {
                PyObject *Bv = bands(res.Bv, res.mesh.nvertices);
                if (Bv)
                    B = Py_BuildValue("(NN)", B, Bv);
                else
                    Py_CLEAR(B);
            }
        }
    }
    rad_result_free(&res);
    rad_scene_free(&sc);
    return B;
}

PyObject *radi_py_solve(PyObject *module, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"scene", "mesh", "accuracy", "solver", "bounces", "quadrature",
                             "method", "resolution", "threads", "strict", "progress",
                             "vertices", "max_element_size", "crease", NULL};
    run_args a;
    const char *solver = NULL; /* gauss, unless bounces are asked for */
    PyObject *bounces = Py_None;
    int vertices = 0;
    PyObject *crease_arg = Py_None;
    double crease = RAD_CREASE_AUTO; /* None: the scene's format decides */
    run_args_init(&a);
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|$OszOisiipOpdO:solve", kwlist, &a.scene,
                                     &a.mesh, &a.accuracy, &solver, &bounces, &a.quadrature,
                                     &a.method, &a.resolution, &a.threads, &a.strict,
                                     &a.progress, &vertices, &a.max_size, &crease_arg))
        return NULL;
    if (crease_arg != Py_None) {
        if (PyBool_Check(crease_arg)) {
            PyErr_SetString(PyExc_TypeError, "crease is an angle in degrees, not a bool");
            return NULL;
        }
        crease = PyFloat_AsDouble(crease_arg);
        if (crease == -1 && PyErr_Occurred())
            return NULL;
    }
    if (crease_arg != Py_None && (!(crease >= 0 && crease <= 180) || (crease > 0 && !vertices))) {
        PyErr_SetString(PyExc_ValueError, crease > 0 && crease <= 180
                                              ? "crease smooths the vertex radiosity: ask for "
                                                "it with vertices=True"
                                              : "crease must be 0 to 180 degrees");
        return NULL;
    }
    return run_solve(module, &a, solver, bounces, vertices, crease);
}

/* ---- elements ----------------------------------------------------------- */

static PyObject *column(const rad_mesh *mesh, const char *what)
{
    const npy_intp n = mesh->nelements;
    const int width = strcmp(what, "surface") == 0 || strcmp(what, "area") == 0 ? 1 : 3;
    const npy_intp dims[2] = {n, 3};
    PyObject *out = PyArray_EMPTY(width == 1 ? 1 : 2, dims,
                                  strcmp(what, "surface") == 0 ? NPY_INT : NPY_FLOAT64, 0);
    if (!out)
        return NULL;
    void *data = PyArray_DATA((PyArrayObject *)out);
    for (npy_intp i = 0; i < n; i++) {
        const rad_element *e = &mesh->elements[i];
        if (strcmp(what, "surface") == 0) {
            ((int *)data)[i] = e->surface;
            continue;
        }
        double *row = (double *)data + i * width;
        const rad_vec3 *v = strcmp(what, "centroid") == 0 ? &e->centroid
                            : strcmp(what, "normal") == 0 ? &e->normal
                                                          : NULL;
        const double *band = strcmp(what, "reflect") == 0 ? e->reflect : e->emit;
        if (width == 1)
            row[0] = e->area;
        else if (v) {
            row[0] = v->x;
            row[1] = v->y;
            row[2] = v->z;
        } else
            for (int b = 0; b < RAD_BANDS; b++)
                row[b] = band[b];
    }
    return out;
}

/* Each element's vertex indices (counter-clockwise about its front), as
 * rows of an n x K int array padded with -1 (K the most corners). */
static PyObject *corner_table(const rad_mesh *mesh)
{
    int k = 0;
    for (int i = 0; i < mesh->nelements; i++)
        k = mesh->elements[i].nverts > k ? mesh->elements[i].nverts : k;
    const npy_intp dims[2] = {mesh->nelements, k};
    PyObject *out = PyArray_EMPTY(2, dims, NPY_INT, 0);
    if (!out)
        return NULL;
    int *row = PyArray_DATA((PyArrayObject *)out);
    for (int i = 0; i < mesh->nelements; i++, row += k) {
        const rad_element *e = &mesh->elements[i];
        for (int v = 0; v < k; v++)
            row[v] = v < e->nverts ? mesh->vindex[e->first + v] : -1;
    }
    return out;
}

/* The mesh that f(scene, *, mesh=None, max_element_size=0) asks for
 * (format: "O|$Od:f"), and the scene it was made of; -1 with an
 * exception. */
static int mesh_of_args(PyObject *module, PyObject *args, PyObject *kw, const char *format,
                        rad_scene *sc, rad_mesh *mesh)
{
    static char *kwlist[] = {"scene", "mesh", "max_element_size", NULL};
    PyObject *scene, *mesh_obj = Py_None;
    double max_size = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, format, kwlist, &scene, &mesh_obj, &max_size) ||
        radi_py_run_scene(module, scene, mesh_obj, max_size, sc) != 0)
        return -1;
    if (build_mesh(module, sc, 0, mesh) != 0) {
        rad_scene_free(sc);
        return -1;
    }
    return 0;
}

PyObject *radi_py_elements(PyObject *module, PyObject *args, PyObject *kw)
{
    static const char *const names[] = {"surface", "area", "centroid", "normal", "reflect",
                                        "emit"};
    rad_scene sc;
    rad_mesh mesh;
    if (mesh_of_args(module, args, kw, "O|$Od:elements", &sc, &mesh) != 0)
        return NULL;
    PyObject *dict = PyDict_New();
    for (size_t k = 0; dict && k < sizeof names / sizeof *names; k++) {
        PyObject *col = column(&mesh, names[k]);
        if (!col || PyDict_SetItemString(dict, names[k], col) != 0)
            Py_CLEAR(dict);
        Py_XDECREF(col);
    }
    const npy_intp n = mesh.nelements;
    PyObject *corners = dict ? corner_table(&mesh) : NULL;
    if (dict && (!corners || PyDict_SetItemString(dict, "corners", corners) != 0))
        Py_CLEAR(dict);
    Py_XDECREF(corners);
    /* each element's row in form_factors (View3D's shape), -1: none */
    PyObject *row = dict ? PyArray_EMPTY(1, &n, NPY_INT, 0) : NULL;
    PyObject *obstruction = row ? PyArray_ZEROS(1, &n, NPY_BOOL, 0) : NULL;
    if (obstruction) {
        int *r = PyArray_DATA((PyArrayObject *)row);
        npy_bool *o = PyArray_DATA((PyArrayObject *)obstruction);
        rad_mesh_reported(&sc, &mesh, r);
        for (npy_intp i = 0; i < n; i++)
            o[i] = r[i] < 0;
    }
    if (dict && (!obstruction || PyDict_SetItemString(dict, "obstruction", obstruction) != 0 ||
                 PyDict_SetItemString(dict, "row", row) != 0))
        Py_CLEAR(dict);
    Py_XDECREF(obstruction);
    Py_XDECREF(row);
    rad_mesh_free(&mesh);
    rad_scene_free(&sc);
    return dict;
}

/* ---- vertices ----------------------------------------------------------- */

PyObject *radi_py_vertices(PyObject *module, PyObject *args, PyObject *kw)
{
    rad_scene sc;
    rad_mesh mesh;
    if (mesh_of_args(module, args, kw, "O|$Od:vertices", &sc, &mesh) != 0)
        return NULL;
    const npy_intp dims[2] = {mesh.nvertices, 3};
    PyObject *out = PyArray_EMPTY(2, dims, NPY_FLOAT64, 0);
    if (out) {
        double *p = PyArray_DATA((PyArrayObject *)out);
        for (int v = 0; v < mesh.nvertices; v++, p += 3) {
            p[0] = mesh.vertices[v].x;
            p[1] = mesh.vertices[v].y;
            p[2] = mesh.vertices[v].z;
        }
    }
    rad_mesh_free(&mesh);
    rad_scene_free(&sc);
    return out;
}
