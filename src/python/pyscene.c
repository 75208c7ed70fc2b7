/* pyscene.c -- radiosity.Scene and radiosity.load_scene: a scene read once,
 * meshed anew by each run.  Copyright (C) 2026 The radiosity authors.
 * GPLv3+, see COPYING.
 *
 * A Scene holds the rad_scene as read.  A run never changes it: it works
 * on a copy of the scene's present part (objects not declared absent),
 * meshed as the run asks, so that one Scene can serve form_factors at
 * several meshes. */
#include <math.h>
#include <stdio.h>

#include "python/pyrad.h"

static void scene_dealloc(PyObject *self)
{
    radi_py_scene *s = (radi_py_scene *)self;
    PyTypeObject *type = Py_TYPE(self);
    if (s->loaded)
        rad_scene_free(&s->scene);
    type->tp_free(self);
    Py_DECREF(type);
}

static PyObject *scene_repr(PyObject *self)
{
    const rad_scene *sc = &((radi_py_scene *)self)->scene;
    return PyUnicode_FromFormat("<radiosity.Scene '%s': %d surfaces, %d materials>",
                                sc->filename ? sc->filename : "", sc->nsurfaces,
                                sc->nmaterials);
}

static PyObject *get_filename(PyObject *self, void *closure)
{
    (void)closure;
    const rad_scene *sc = &((radi_py_scene *)self)->scene;
    return PyUnicode_DecodeFSDefault(sc->filename ? sc->filename : "");
}

static PyObject *get_surfaces(PyObject *self, void *closure)
{
    (void)closure;
    return PyLong_FromLong(((radi_py_scene *)self)->scene.nsurfaces);
}

/* Names as the file spells them; bytes that are not UTF-8 (an OBJ's
 * material names may hold any) are kept by surrogateescape. */
static PyObject *name_list(const char *first, size_t stride, int n)
{
    PyObject *list = PyList_New(n);
    for (int k = 0; list && k < n; k++) {
        const char *name = first + (size_t)k * stride;
        PyObject *s = PyUnicode_DecodeUTF8(name, (Py_ssize_t)strlen(name), "surrogateescape");
        if (!s) {
            Py_CLEAR(list);
            break;
        }
        PyList_SET_ITEM(list, k, s);
    }
    return list;
}

static PyObject *get_materials(PyObject *self, void *closure)
{
    (void)closure;
    const rad_scene *sc = &((radi_py_scene *)self)->scene;
    return name_list(sc->nmaterials ? sc->materials[0].name : "", sizeof *sc->materials,
                     sc->nmaterials);
}

static PyObject *get_objects(PyObject *self, void *closure)
{
    (void)closure;
    const rad_scene *sc = &((radi_py_scene *)self)->scene;
    return name_list(sc->nobjects ? sc->objects[0].name : "", sizeof *sc->objects,
                     sc->nobjects);
}

static PyObject *get_repairs(PyObject *self, void *closure)
{
    (void)closure;
    const rad_scene *sc = &((radi_py_scene *)self)->scene;
    PyObject *list = PyList_New(0);
    char line[RAD_ERRMSG_MAX];
    for (int k = 0; list && k < RAD_SCENE_REPAIR_KINDS; k++) {
        if (!rad_scene_repair_text(sc, k, line, sizeof line))
            continue;
        PyObject *s = radi_py_text(line);
        if (!s || PyList_Append(list, s) != 0)
            Py_CLEAR(list);
        Py_XDECREF(s);
    }
    return list;
}

static PyGetSetDef scene_getset[] = {
    {"filename", get_filename, NULL, "the file it was read from ('<string>' for text)", NULL},
    {"surfaces", get_surfaces, NULL, "number of surfaces, obstructions included", NULL},
    {"materials", get_materials, NULL, "the materials' names, in file order", NULL},
    {"objects", get_objects, NULL, "the objects' names, in file order", NULL},
    {"repairs", get_repairs, NULL,
     "what reading a foreign format (OBJ) repaired: one line per kind", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

static PyType_Slot scene_slots[] = {
    {Py_tp_dealloc, (void *)scene_dealloc},
    {Py_tp_repr, (void *)scene_repr},
    {Py_tp_getset, scene_getset},
    {Py_tp_doc, (void *)"A scene as read by radiosity.load_scene()."},
    {0, NULL}};

static PyType_Spec scene_spec = {"radiosity.Scene", sizeof(radi_py_scene), 0,
                                 Py_TPFLAGS_DEFAULT | Py_TPFLAGS_DISALLOW_INSTANTIATION,
                                 scene_slots};

int radi_py_scene_init(PyObject *module, radi_py_state *st)
{
    st->scene_type = (PyTypeObject *)PyType_FromModuleAndSpec(module, &scene_spec, NULL);
    if (!st->scene_type)
        return -1;
    return PyModule_AddObjectRef(module, "Scene", (PyObject *)st->scene_type);
}

/* Each repair said as a RuntimeWarning; -1 when a warning became an error. */
static int warn_repairs(const rad_scene *sc)
{
    char line[RAD_ERRMSG_MAX];
    for (int k = 0; k < RAD_SCENE_REPAIR_KINDS; k++)
        if (rad_scene_repair_text(sc, k, line, sizeof line) && radi_py_warn(line) != 0)
            return -1;
    return 0;
}

static int format_of(PyObject *format)
{
    static const char *const names[] = {"scene", "obj", "vs3"};
    static const rad_scene_format value[] = {RAD_SCENE_FORMAT_SCENE, RAD_SCENE_FORMAT_OBJ,
                                             RAD_SCENE_FORMAT_VS3};
    if (format == Py_None)
        return RAD_SCENE_FORMAT_AUTO;
    const char *given = PyUnicode_Check(format) ? PyUnicode_AsUTF8(format) : NULL;
    for (int k = 0; given && k < 3; k++)
        if (strcmp(given, names[k]) == 0)
            return value[k];
    if (given || PyUnicode_Check(format))
        PyErr_Format(PyExc_ValueError, "format must be 'scene', 'obj', 'vs3' or None, not %R",
                     format);
    else
        PyErr_Format(PyExc_TypeError, "format must be a str or None, not %s",
                     Py_TYPE(format)->tp_name);
    return -1;
}

/* A str holding a line end (LF or CR: radiosity-scene(5) reads both) is
 * a scene's text; a path with a line end in it is given as a Path. */
static int is_text(PyObject *s)
{
    const Py_ssize_t n = PyUnicode_GetLength(s);
    return PyUnicode_FindChar(s, '\n', 0, n, 1) >= 0 || PyUnicode_FindChar(s, '\r', 0, n, 1) >= 0;
}

/* Text in the native format, or a file by name. */
static rad_status read_scene(PyObject *source, int format, int strict, rad_scene *sc,
                             rad_error *err, int *failed)
{
    *failed = 0;
    if (PyUnicode_Check(source) && is_text(source)) {
        Py_ssize_t len;
        const char *text = PyUnicode_AsUTF8AndSize(source, &len);
        if (!text || (format != RAD_SCENE_FORMAT_AUTO && format != RAD_SCENE_FORMAT_SCENE)) {
            if (text)
                PyErr_SetString(PyExc_ValueError, "scene text is read in the native format: "
                                                  "give an OBJ or View3D file by its path");
            *failed = 1;
            return RAD_ERR_INVALID;
        }
        rad_status st;
        Py_BEGIN_ALLOW_THREADS
        st = rad_scene_parse(sc, text, (size_t)len, "<string>", err);
        Py_END_ALLOW_THREADS
        return st;
    }
    PyObject *path = NULL;
    if (!PyUnicode_FSConverter(source, &path)) {
        *failed = 1;
        return RAD_ERR_INVALID;
    }
    rad_status st;
    Py_BEGIN_ALLOW_THREADS
    st = rad_scene_load_format(sc, PyBytes_AS_STRING(path), (rad_scene_format)format,
                               strict ? RAD_SCENE_STRICT : 0, err);
    Py_END_ALLOW_THREADS
    Py_DECREF(path);
    return st;
}

PyObject *radi_py_load_scene(PyObject *module, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"path_or_text", "format", "strict", NULL};
    PyObject *source, *format_obj = Py_None;
    int strict = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|$Op:load_scene", kwlist, &source,
                                     &format_obj, &strict))
        return NULL;
    const int format = format_of(format_obj);
    if (format < 0)
        return NULL;
    radi_py_state *st = radi_py_state_of(module);
    radi_py_scene *self = PyObject_New(radi_py_scene, st->scene_type);
    if (!self)
        return NULL;
    self->loaded = 0;
    rad_error err;
    int failed;
    if (read_scene(source, format, strict, &self->scene, &err, &failed) != RAD_OK) {
        Py_DECREF(self);
        return failed ? NULL : radi_py_raise(module, &err);
    }
    self->loaded = 1;
    if (warn_repairs(&self->scene) != 0) {
        Py_DECREF(self);
        return NULL;
    }
    return (PyObject *)self;
}

/* (N, M) with 1 <= N, M; 0 with both set, -1 with an exception. */
static int mesh_of(PyObject *mesh, int *n, int *m)
{
    if (!PyTuple_Check(mesh) || PyTuple_GET_SIZE(mesh) != 2) {
        PyErr_SetString(PyExc_TypeError, "mesh must be a pair (N, M) or None");
        return -1;
    }
    long v[2];
    for (int k = 0; k < 2; k++) {
        if (PyBool_Check(PyTuple_GET_ITEM(mesh, k))) {
            PyErr_SetString(PyExc_TypeError, "mesh must be two whole numbers, not bools");
            return -1;
        }
        v[k] = PyLong_AsLong(PyTuple_GET_ITEM(mesh, k));
        if (v[k] == -1 && PyErr_Occurred())
            return -1;
        if (v[k] < 1 || v[k] > INT_MAX) {
            PyErr_Format(PyExc_ValueError, "mesh must be two counts of at least 1, not %R",
                         mesh);
            return -1;
        }
    }
    *n = (int)v[0];
    *m = (int)v[1];
    return 0;
}

int radi_py_run_scene(PyObject *module, PyObject *obj, PyObject *mesh, double max_size,
                      rad_scene *out)
{
    radi_py_state *st = radi_py_state_of(module);
    if (!PyObject_TypeCheck(obj, st->scene_type)) {
        PyErr_Format(PyExc_TypeError, "scene must be a radiosity.Scene (from load_scene), "
                                      "not %s", Py_TYPE(obj)->tp_name);
        return -1;
    }
    int n = 0, m = 0;
    if (mesh != Py_None && mesh_of(mesh, &n, &m) != 0)
        return -1;
    if (max_size != 0 && (n > 0 || !(max_size > 0) || !isfinite(max_size))) {
        PyErr_SetString(PyExc_ValueError, n > 0 ? "give mesh or max_element_size, not both"
                                                : "max_element_size must be a positive length");
        return -1;
    }
    const rad_scene *in = &((radi_py_scene *)obj)->scene;
    rad_error err;
    if (rad_scene_present_copy(in, NULL, out, &err) != RAD_OK) {
        radi_py_raise(module, &err);
        return -1;
    }
    if (out->nsurfaces == 0) { /* nothing to mesh: refused as a run refuses it */
        err.status = RAD_ERR_INVALID;
        snprintf(err.message, sizeof err.message, "%s: %s", in->filename ? in->filename : "-",
                 in->nsurfaces ? "every surface belongs to an absent object" : "no surfaces");
        rad_scene_free(out);
        radi_py_raise(module, &err);
        return -1;
    }
    if (n > 0)
        rad_scene_set_mesh(out, n, m);
    if (max_size > 0 && rad_scene_set_max_element_size(out, max_size) == 0) {
        char msg[RAD_ERRMSG_MAX]; /* said as the program says it */
        snprintf(msg, sizeof msg, "max_element_size %g makes no surface of %s finer: every "
                 "element is already that small", max_size, in->filename ? in->filename : "-");
        if (radi_py_warn(msg) != 0) {
            rad_scene_free(out);
            return -1;
        }
    }
    return 0;
}
