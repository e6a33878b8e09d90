// The Python module asterlite.dynamics.native._newmark: NEWMARK's own loop
// (scheme_newmark.fast_loop) and its general path (loop.time_loop around
// scheme_newmark.step on the three bundles) on numpy arrays, in place, with
// the arguments of loop.hpp's run_time_loop (asterlite.dynamics.native.time_loop).
#include "arguments.hpp"
#include "loop.hpp"
#include "scheme_newmark.hpp"
#include "scheme_newmark_step.hpp"

namespace asterlite {
namespace {

// scheme_newmark.prepare's memory (implicit.new_rows: the vector rows, then
// the seven (n, n) blocks; the scalars up to S_FORCE_AT_START)
void check_memory(Arguments& in, const Memory& memory, const State& x) {
    const index n = x.q.n0;
    in.require(memory.rows.n1 == n &&
                   memory.rows.n0 == newmark::VECTOR_ROWS + newmark::N_BLOCKS * n,
               "memory rows");
    in.require(memory.scalars.n0 >= newmark::N_SCALARS, "memory scalars");
}

// clock, counters, instants, the state (7), the memory (3: what
// scheme_newmark.prepare made), the model (31), the archive (7), the energy
// balance (7), pas_arch, eps; returns the status (ZeroDivisionError where
// numba's loop raises it: BETA=0, a zero diagonal entry of K_eff)
PyObject* newmark_loop(PyObject*, PyObject* args) {
    return run_loop(args, "newmark_loop", check_memory, newmark::newmark_loop);
}

// the general path: the same arguments
PyObject* newmark_step_loop(PyObject*, PyObject* args) {
    return run_time_loop(args, "newmark_step_loop", newmark::step, check_memory);
}

PyMethodDef methods[] = {
    {"newmark_loop", newmark_loop, METH_VARARGS,
     "NEWMARK's own loop on the shocks' local frames; returns a status."},
    {"newmark_step_loop", newmark_step_loop, METH_VARARGS,
     "NEWMARK's general path (its step on the general model); returns a status."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_newmark",
    "NEWMARK's time loop compiled when asterlite is installed (asterlite.dynamics.native).", -1,
    methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__newmark(void) {
    return asterlite::loops_module(&asterlite::module,
                                   {{"NEWMARK", "newmark_loop"},
                                    {"NEWMARK (general path)", "newmark_step_loop"}});
}
