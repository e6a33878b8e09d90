// The Python module asterlite.dynamics.native._devoge: DEVOGE's loop
// (loop.time_loop around scheme_devoge.step) on the shocks' local frames.
#include "loop.hpp"
#include "scheme_devoge.hpp"

namespace asterlite {
namespace {

// the memory's rows and scalars (arguments 10 and 11) have the sizes
// scheme_devoge.prepare gives them: the step indexes them without checks
// (arrays of another kind are left to run_time_loop, which refuses them by name)
bool memory_fits(PyObject* args) {
    const Py_ssize_t rows_at = 10, scalars_at = 11;
    if (PyTuple_GET_SIZE(args) <= scalars_at) return true;
    Py_buffer rows, scalars;
    if (PyObject_GetBuffer(PyTuple_GET_ITEM(args, rows_at), &rows, PyBUF_ND) != 0) {
        PyErr_Clear();
        return true;
    }
    if (PyObject_GetBuffer(PyTuple_GET_ITEM(args, scalars_at), &scalars, PyBUF_ND) != 0) {
        PyErr_Clear();
        PyBuffer_Release(&rows);
        return true;
    }
    bool fits = true;
    if (rows.ndim == 2 && scalars.ndim == 1) {
        fits = rows.shape[0] == devoge::memory_rows(rows.shape[1]) &&
               scalars.shape[0] >= devoge::MEMORY_SCALARS;
    }
    PyBuffer_Release(&scalars);
    PyBuffer_Release(&rows);
    return fits;
}

PyObject* devoge_loop(PyObject*, PyObject* args) {
    if (!memory_fits(args)) {
        PyErr_SetString(PyExc_ValueError,
                        "devoge_loop: inconsistent arrays: memory of another size than DEVOGE's");
        return nullptr;
    }
    return run_time_loop(args, "devoge_loop", devoge::step);
}

PyMethodDef methods[] = {
    {"devoge_loop", devoge_loop, METH_VARARGS,
     "DEVOGE's loop on the shocks' local frames; returns a status."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_devoge", "DEVOGE's time loop compiled (asterlite.dynamics.native).",
    -1, methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__devoge(void) {
    return asterlite::loops_module(&asterlite::module, {{"DEVOGE", "devoge_loop"},
                                {"DEVOGE (general path)", "devoge_loop"}});
}
