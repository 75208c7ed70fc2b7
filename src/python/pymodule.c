/* pymodule.c -- the module `radiosity` for Python 3: its functions, its
 * exception, its state.  Copyright (C) 2026 The radiosity authors.  GPLv3+,
 * see COPYING.
 *
 * Multi-phase initialisation (PEP 489) with the exception and the Scene
 * type in the module's state (PEP 573), so that nothing here is a global
 * that two interpreters could share.  What each function takes and
 * returns is in its docstring and in radiosity-python(3). */
#include "python/pyrad.h"

PyDoc_STRVAR(load_scene_doc,
"load_scene(path_or_text, *, format=None, strict=False) -> Scene\n\n"
"Read a scene.  A str holding a line end is the scene's text in the native\n"
"format (radiosity-scene(5)); any other str, bytes or os.PathLike is a file:\n"
"by its ending (.obj Wavefront OBJ, .vs3 View3D, else native) or by format=\n"
"'scene', 'obj' or 'vs3'.  Repairs made to an OBJ file are each said by a\n"
"RuntimeWarning; strict=True refuses them instead.  Raises radiosity.Error\n"
"with the message 'FILE:LINE: reason' when the scene is wrong.");

PyDoc_STRVAR(form_factors_doc,
"form_factors(scene, *, mesh=None, accuracy='default', quadrature=3,\n"
"             method='contour', resolution=64, threads=0, errors=False,\n"
"             strict=False, progress=None, max_element_size=0) -> numpy.ndarray\n\n"
"The form factors of every pair of elements: an n x n float64 array whose\n"
"row i holds the factors from element i (F[i, j] = F_ij; rows of a closed\n"
"scene sum to 1; A_i F_ij = A_j F_ji).  mesh=(N, M) cuts every\n"
"quadrilateral into N x M elements and every triangle into max(N, M)^2\n"
"(max_element_size=L instead: no element side longer than L); accuracy\n"
"is 'classic' (Goral et al.\n"
"1984's rule alone), 'default' or 'reference' (error-controlled);\n"
"method='hemicube' computes each row by a hemicube of resolution pixels.\n"
"errors=True returns (F, E), E the estimated absolute error of each entry\n"
"(NaN where none is known).  Obstruction surfaces (View3D's O lines) block\n"
"but have no rows or columns; surfaces combined (View3D's CMB) share one\n"
"row and column, elements()['row'].  Entries that miss the mode's promise are\n"
"said by a RuntimeWarning, or raise radiosity.Error with strict=True.\n"
"progress(stage, done, total) is called now and then; an exception it\n"
"raises, or Ctrl-C, stops the fill and is raised; a true return stops it\n"
"with radiosity.Error('interrupted').");

PyDoc_STRVAR(solve_doc,
"solve(scene, *, mesh=None, accuracy='default', solver=None, bounces=None,\n"
"      quadrature=3, method='contour', resolution=64, threads=0,\n"
"      strict=False, progress=None, vertices=False, max_element_size=0,\n"
"      crease=None)\n"
"      -> numpy.ndarray\n\n"
"Mesh, form factors and the radiosity system (Goral et al. 1984, eq. 5)\n"
"band by band: B as an n x 3 float64 array, row i the radiosity of element\n"
"i in red, green and blue.  solver is 'gauss' (None: LU), 'cholesky',\n"
"'jacobi', 'gauss-seidel', 'cg' or 'progressive'; bounces=K gives exactly K\n"
"reflections instead.  vertices=True returns (B, Bv), Bv the radiosity\n"
"smoothed to each vertex of vertices(scene, mesh=...) (Goral et al. 1984,\n"
"section 3); crease=DEG smooths Bv across surfaces of one object and\n"
"material whose normals are less than DEG degrees apart where they meet\n"
"(None: 30 for an OBJ model, whose faces are parts of one shape, 0 for\n"
"the other formats; 0: never).  Raises radiosity.Error on a singular\n"
"system or an unmet promise with strict=True.");

PyDoc_STRVAR(elements_doc,
"elements(scene, *, mesh=None, max_element_size=0) -> dict\n\n"
"The elements a run with this mesh makes, in the order of the rows of F\n"
"and B: 'surface' (int: the surface's index in file order, surfaces of\n"
"absent objects left out, as the program's tables number them), 'area',\n"
"'centroid' and 'normal' (n x 3), 'reflect' and 'emit' (n x 3, per band),\n"
"'corners' (n x K int: vertex indices, counter-clockwise, padded with -1),\n"
"'obstruction' (bool: left out of form_factors' rows; they come last),\n"
"'row' (int: the element's row in form_factors, -1 for an obstruction;\n"
"View3D's combined surfaces share one).");

PyDoc_STRVAR(vertices_doc,
"vertices(scene, *, mesh=None, max_element_size=0) -> numpy.ndarray\n\n"
"The mesh's vertices as an nv x 3 float64 array: the rows of the Bv that\n"
"solve(..., vertices=True) returns, indexed by elements()['corners'].\n"
"Vertices are shared inside a surface, never across surfaces.");

static PyMethodDef functions[] = {
    {"load_scene", (PyCFunction)(void (*)(void))radi_py_load_scene,
     METH_VARARGS | METH_KEYWORDS, load_scene_doc},
    {"form_factors", (PyCFunction)(void (*)(void))radi_py_form_factors,
     METH_VARARGS | METH_KEYWORDS, form_factors_doc},
    {"solve", (PyCFunction)(void (*)(void))radi_py_solve, METH_VARARGS | METH_KEYWORDS,
     solve_doc},
    {"elements", (PyCFunction)(void (*)(void))radi_py_elements,
     METH_VARARGS | METH_KEYWORDS, elements_doc},
    {"vertices", (PyCFunction)(void (*)(void))radi_py_vertices,
     METH_VARARGS | METH_KEYWORDS, vertices_doc},
    {NULL, NULL, 0, NULL}};

static int exec_module(PyObject *module)
{
    radi_py_state *st = radi_py_state_of(module);
    if (radi_py_numpy_init() != 0)
        return -1;
    st->error = PyErr_NewExceptionWithDoc(
        "radiosity.Error",
        "What the library refused: str(e) is its message ('FILE:LINE: reason' for a\n"
        "scene), e.status a short name of the kind ('parse error', ...).",
        PyExc_Exception, NULL);
    if (!st->error || PyModule_AddObjectRef(module, "Error", st->error) != 0)
        return -1;
    if (radi_py_scene_init(module, st) != 0 || radi_py_analytic_init(module) != 0)
        return -1;
    if (PyModule_AddStringConstant(module, "__version__", rad_version()) != 0 ||
        PyModule_AddStringConstant(module, "scene_dir", rad_scene_dir()) != 0)
        return -1;
    return 0;
}

static int traverse(PyObject *module, visitproc visit, void *arg)
{
    radi_py_state *st = radi_py_state_of(module);
    Py_VISIT(st->error);
    Py_VISIT(st->scene_type);
    return 0;
}

static int clear(PyObject *module)
{
    radi_py_state *st = radi_py_state_of(module);
    Py_CLEAR(st->error);
    Py_CLEAR(st->scene_type);
    return 0;
}

static void free_module(void *module)
{
    clear(module);
}

static PyModuleDef_Slot slots[] = {{Py_mod_exec, (void *)exec_module}, {0, NULL}};

PyDoc_STRVAR(module_doc,
"Diffuse global illumination the classic way (Goral et al. 1984; Cohen et\n"
"al. 1988): form factors by the contour integral and the radiosity system,\n"
"as NumPy arrays.\n\n"
"    s = radiosity.load_scene('cube.scene')\n"
"    F = radiosity.form_factors(s, mesh=(4, 4), accuracy='reference')\n"
"    B = radiosity.solve(s, mesh=(4, 4))\n\n"
"See radiosity-python(3).");

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT, "radiosity", module_doc, sizeof(radi_py_state), functions, slots,
    traverse, clear, free_module};

PyMODINIT_FUNC PyInit_radiosity(void);
PyMODINIT_FUNC PyInit_radiosity(void)
{
    return PyModuleDef_Init(&module_def);
}
