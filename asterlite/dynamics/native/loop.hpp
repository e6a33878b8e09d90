// The time loop of the schemes' own loops (asterlite.dynamics.loop.time_loop)
// around a scheme's step, and the Python function that runs it.
#pragma once

#include <initializer_list>
#include <utility>

#include "arguments.hpp"
#include "loop_steps.hpp"
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
        const int paused = before_step(c, out, model);
        if (paused) return paused;
        double t, dt;
        plan_step(c, t, dt);
        const StepResult r = step(t, dt, c.counters(K_STEP), x, memory, model);
        if (r.status != STATUS_DONE) return record_failure(c, r.status, r.shock, r.dt_used);
        after_step(c, x, out, balance, active, model, r.dt_used, r.dt_next, r.rejected);
    }
    return STATUS_DONE;
}

// a loop's status for Python: the int, or the ZeroDivisionError numba's
// step raised where the loop returned STATUS_ZERO_DIVISION
inline PyObject* loop_status(int status) {
    if (status == STATUS_ZERO_DIVISION) {
        PyErr_SetString(PyExc_ZeroDivisionError, "division by zero");
        return nullptr;
    }
    return PyLong_FromLong(status);
}

// The Python function of a loop: arguments clock, counters, instants, the
// state (7), the memory (3), the model (31), the archive (7), the energy
// balance (7), pas_arch, eps (asterlite.dynamics.native.time_loop), checked
// (``check_memory(in, memory, x)``: what the scheme's memory must hold), then
// ``loop(c, x, memory, model, out, balance)`` without the GIL; returns its status.
template <class CheckMemory, class Loop>
PyObject* run_loop(PyObject* args, const char* name, CheckMemory&& check_memory, Loop&& loop) {
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
    if (!in.failed()) check_memory(in, memory, x);
    if (in.failed()) return nullptr;
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = loop(c, x, memory, model, out, balance);
    Py_END_ALLOW_THREADS
    return loop_status(status);
}

// run_loop for loop.time_loop around a scheme's step
template <class Step, class CheckMemory>
PyObject* run_time_loop(PyObject* args, const char* name, Step&& step,
                        CheckMemory&& check_memory) {
    return run_loop(args, name, check_memory,
                    [&step](const Clock& c, const State& x, const Memory& memory,
                            const Model& model, const ArchiveBuffers& out,
                            const energy::Balance& balance) {
                        return time_loop(c, x, memory, model, out, balance, step);
                    });
}

template <class Step>
PyObject* run_time_loop(PyObject* args, const char* name, Step&& step) {
    return run_time_loop(args, name, step, [](Arguments&, const Memory&, const State&) {});
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
