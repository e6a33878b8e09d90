// The Python module asterlite.dynamics.native._trbdf2: TRBDF2's own loop
// (loop.time_loop around scheme_trbdf2.step, shocks in their local frames),
// run in place on the arguments of asterlite/dynamics/native/__init__.py.
#include "loop.hpp"
#include "scheme_trbdf2.hpp"

namespace asterlite {
namespace {

PyObject* trbdf2_loop(PyObject*, PyObject* args) {
    return run_time_loop(args, "trbdf2_loop", trbdf2::step);
}

PyMethodDef methods[] = {
    {"trbdf2_loop", trbdf2_loop, METH_VARARGS,
     "TRBDF2's loop on the shocks' local frames; returns a status."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_trbdf2",
    "TRBDF2's time loop compiled when asterlite is installed (asterlite.dynamics.native).", -1,
    methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__trbdf2(void) {
    return asterlite::loops_module(&asterlite::module, {{"TRBDF2", "trbdf2_loop"},
                                {"TRBDF2 (general path)", "trbdf2_loop"}});
}
