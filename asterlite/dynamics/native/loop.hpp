// The time loop of the schemes' own loops (asterlite.dynamics.loop.time_loop)
// around a scheme's step, and the Python function that runs it.
#pragma once

#include <initializer_list>
#include <utility>

#include "arguments.hpp"
#include "clock.hpp"
#include "model.hpp"

namespace asterlite {

// what a step returns (loop.py: status, shock, dt_used, dt_next, rejected)
struct StepResult {
    int status;
    index shock;
    double dt_used, dt_next;
    std::int64_t rejected;
};

// Step: StepResult(double t, double dt, std::int64_t index, const State&,
// const Memory&, const Model&)
template <class Step>
int time_loop(const Clock& c, const State& x, const Memory& memory, const Model& model,
              const ArchiveBuffers& out, const energy::Balance& balance, Step&& step) {
    const bool active = balance.active();  // read once, as loop.time_loop does
    while (unfinished(c)) {
        const int paused = pause_status(c, out);
        if (paused) return paused;
        const double t_next = c.clock(C_TIME) + 2.0 * c.clock(C_STEP);
        if (!(loads_cover(t_next, model.loads.tables) && loads_cover(t_next, model.sup.tables))) {
            return STATUS_LOADS;
        }
        double t, dt;
        plan_step(c, t, dt);
        const StepResult r = step(t, dt, c.counters(K_STEP), x, memory, model);
        if (r.status != STATUS_DONE) return record_failure(c, r.status, r.shock, r.dt_used);
        const std::int64_t archived = c.counters(K_ARCHIVED);
        advance_clock(c, x.q, x.v, x.a, x.vint, out, r.dt_used, r.dt_next, r.rejected);
        if (active) {
            energy::after_step(balance, archived, c.counters(K_ARCHIVED), c.clock(C_TIME),
                               r.dt_used, x.q, x.v, x.a, x.vint, model);
        }
    }
    return STATUS_DONE;
}

// The Python function of a scheme's loop: arguments clock, counters,
// instants, the state (7), the memory (3), the model (27), the archive (7),
// the energy balance (7), pas_arch, eps (asterlite.dynamics.native.time_loop);
// returns the status.
template <class Step>
PyObject* run_time_loop(PyObject* args, const char* name, Step&& step) {
    Arguments in(args, name);
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
    in.require(memory.rows.n0 == 0 || memory.rows.n1 == x.q.n0, "memory rows");
    if (in.failed()) return nullptr;
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = time_loop(c, x, memory, model, out, balance, step);
    Py_END_ALLOW_THREADS
    return PyLong_FromLong(status);
}

// The module object of an extension of this folder, with its ``KERNELS``
// dict: the scheme kernel (schemes.Scheme.kernel) each of its functions
// runs the loop of, called with the arguments run_time_loop reads
// (asterlite.dynamics.native finds them there).
inline PyObject* loops_module(PyModuleDef* definition,
                              std::initializer_list<std::pair<const char*, const char*>> kernels) {
    PyObject* module = PyModule_Create(definition);
    if (module == nullptr) return nullptr;
    PyObject* table = PyDict_New();
    bool ok = table != nullptr;
    for (const auto& [kernel, function] : kernels) {
        if (!ok) break;
        PyObject* name = PyUnicode_FromString(function);
        ok = name != nullptr && PyDict_SetItemString(table, kernel, name) == 0;
        Py_XDECREF(name);
    }
    if (!ok || PyModule_AddObject(module, "KERNELS", table) != 0) {
        Py_XDECREF(table);
        Py_DECREF(module);
        return nullptr;
    }
    return module;
}

}  // namespace asterlite
