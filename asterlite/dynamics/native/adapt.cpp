// The Python module asterlite.dynamics.native._adapt: ADAPT_ORDRE1's and
// ADAPT_ORDRE2's loops (loop.time_loop around their steps, on the shocks'
// local frames), arguments as loop.hpp's run_time_loop reads them.
#include "loop.hpp"
#include "scheme_adapt.hpp"

namespace asterlite {
namespace {

PyObject* adapt_ordre1_loop(PyObject*, PyObject* args) {
    return run_time_loop(args, "adapt_ordre1_loop", adapt_ordre1::step);
}

PyObject* adapt_ordre2_loop(PyObject*, PyObject* args) {
    return run_time_loop(args, "adapt_ordre2_loop", adapt_ordre2::step);
}

PyMethodDef methods[] = {
    {"adapt_ordre1_loop", adapt_ordre1_loop, METH_VARARGS,
     "ADAPT_ORDRE1's loop on the shocks' local frames; returns a status."},
    {"adapt_ordre2_loop", adapt_ordre2_loop, METH_VARARGS,
     "ADAPT_ORDRE2's loop on the shocks' local frames; returns a status."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_adapt",
    "ADAPT_ORDRE1/2's time loops compiled when asterlite is installed "
    "(asterlite.dynamics.native).",
    -1, methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__adapt(void) {
    return asterlite::loops_module(
        &asterlite::module,
        {{"ADAPT_ORDRE1", "adapt_ordre1_loop"},
         {"ADAPT_ORDRE1 (general path)", "adapt_ordre1_loop"},
         {"ADAPT_ORDRE2", "adapt_ordre2_loop"},
         {"ADAPT_ORDRE2 (general path)", "adapt_ordre2_loop"}});
}
