// The Python module asterlite.dynamics.native._general: DIFF_CENTRE's and
// NEWMARK's general paths (loop.time_loop around scheme_diff_centre.step and
// scheme_newmark.step on the three bundles) on numpy arrays, in place, with
// the arguments of loop.hpp's run_time_loop (asterlite.dynamics.native.time_loop).
#include "arguments.hpp"
#include "loop.hpp"
#include "scheme_diff_centre_step.hpp"
#include "scheme_newmark_step.hpp"

namespace asterlite {
namespace {

// clock, counters, instants, the state (7), the memory (3: what
// scheme_diff_centre.prepare made), the model, the archive (7), the energy
// balance (7), pas_arch, eps; returns the status
PyObject* diff_centre_step_loop(PyObject*, PyObject* args) {
    // scheme_diff_centre.prepare: one residual row of length n
    auto check_memory = [](Arguments& in, const Memory& memory, const State& x) {
        in.require(memory.rows.n0 > diff_centre::RESIDUAL && memory.rows.n1 == x.q.n0,
                   "memory rows");
    };
    return run_time_loop(args, "diff_centre_step_loop", diff_centre::step, check_memory);
}

// the same arguments, the memory of scheme_newmark.prepare; raises ZeroDivisionError
// where numba's step does (BETA=0, a zero diagonal entry of K_eff)
PyObject* newmark_step_loop(PyObject*, PyObject* args) {
    // implicit.new_rows: the vector rows, then the seven (n, n) blocks; the
    // scalars up to S_FORCE_AT_START
    auto check_memory = [](Arguments& in, const Memory& memory, const State& x) {
        const index n = x.q.n0;
        in.require(memory.rows.n1 == n &&
                       memory.rows.n0 == newmark::VECTOR_ROWS + newmark::N_BLOCKS * n,
                   "memory rows");
        in.require(memory.scalars.n0 >= newmark::N_SCALARS, "memory scalars");
    };
    return run_time_loop(args, "newmark_step_loop", newmark::step, check_memory);
}

PyMethodDef methods[] = {
    {"diff_centre_step_loop", diff_centre_step_loop, METH_VARARGS,
     "DIFF_CENTRE's general path (its step on the general model); returns a status."},
    {"newmark_step_loop", newmark_step_loop, METH_VARARGS,
     "NEWMARK's general path (its step on the general model); returns a status."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_general",
    "DIFF_CENTRE's and NEWMARK's general paths compiled when asterlite is installed "
    "(asterlite.dynamics.native).",
    -1, methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__general(void) {
    return asterlite::loops_module(&asterlite::module,
                                   {{"DIFF_CENTRE (general path)", "diff_centre_step_loop"},
                                    {"NEWMARK (general path)", "newmark_step_loop"}});
}
