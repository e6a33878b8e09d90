// The Python module asterlite.dynamics.native._legacy: code_aster 10-12's
// ADAPT_ORDRE2 (scheme_adapt_ordre2_v11.run_loop, mdadap) on the general
// model (shocks in the global frame), with the arguments of loop.hpp's
// run_loop (asterlite.dynamics.native.time_loop).
#include "arguments.hpp"
#include "loop.hpp"
#include "scheme_adapt_legacy.hpp"

namespace asterlite {
namespace {

// clock, counters, instants (not read), the state (7), the memory (3: what
// scheme_adapt_ordre2_v11.prepare made), the model (31, without local
// frames), the archive (7), the energy balance (7, not read: mdadap had
// none), pas_arch, eps (not read); returns the status
PyObject* adapt_legacy_loop(PyObject*, PyObject* args) {
    return run_loop(
        args, "adapt_legacy_loop", adapt_legacy::check_memory,
        [](const Clock& c, const State& x, const Memory& memory, const Model& model,
           const ArchiveBuffers& out, const energy::Balance&) {
            return adapt_legacy::run_loop(c, x, memory, model, out);
        });
}

PyMethodDef methods[] = {
    {"adapt_legacy_loop", adapt_legacy_loop, METH_VARARGS,
     "code_aster 10-12's ADAPT_ORDRE2 loop on the general model; returns a status."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_legacy",
    "code_aster 10-12's ADAPT_ORDRE2 time loop compiled when asterlite is installed "
    "(asterlite.dynamics.native).",
    -1, methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__legacy(void) {
    return asterlite::loops_module(&asterlite::module,
                                   {{"ADAPT_ORDRE2 (code_aster 10-12)", "adapt_legacy_loop"}});
}
