// The Python module asterlite.dynamics.native._newmark: NEWMARK's own loop
// (scheme_newmark.fast_loop) on numpy arrays, in place, with the arguments
// of loop.hpp's run_time_loop (asterlite.dynamics.native.time_loop).
#include "arguments.hpp"
#include "loop.hpp"
#include "scheme_newmark.hpp"

namespace asterlite {
namespace {

// clock, counters, instants, the state (7), the memory (3: what
// scheme_newmark.prepare made), the model (27), the archive (7), the energy
// balance (7), pas_arch, eps; returns the status
PyObject* newmark_loop(PyObject*, PyObject* args) {
    Arguments in(args, "newmark_loop");
    Clock c = read_clock(in);
    State x = read_state(in);
    Memory memory = read_memory(in);
    Model model = read_model(in);
    ArchiveBuffers out = read_archive(in);
    energy::Balance balance = read_balance(in);
    c.pas_arch = in.integer("pas_arch");
    c.eps = in.real("eps");
    if (!in.complete()) return nullptr;
    check_model(in, x, model);
    check_loop(in, c, x, out);
    check_balance(in, balance, x, out.t.n0);
    const index n = x.q.n0;
    // implicit.new_rows: the vector rows, then the seven (n, n) blocks
    in.require(memory.rows.n1 == n &&
                   memory.rows.n0 == newmark::VECTOR_ROWS + newmark::N_BLOCKS * n,
               "memory rows");
    in.require(memory.scalars.n0 >= newmark::N_SCALARS, "memory scalars");
    if (in.failed()) return nullptr;
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = newmark::newmark_loop(c, x, memory, model, out, balance);
    Py_END_ALLOW_THREADS
    return PyLong_FromLong(status);
}

PyMethodDef methods[] = {
    {"newmark_loop", newmark_loop, METH_VARARGS,
     "NEWMARK's own loop on the shocks' local frames; returns a status."},
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
    return asterlite::loops_module(&asterlite::module, {{"NEWMARK", "newmark_loop"}});
}
