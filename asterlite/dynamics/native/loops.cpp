// The Python module asterlite.dynamics.native._loops: numpy arrays in, the
// loops of the headers run on them in place (arguments in the order of
// asterlite/dynamics/native/__init__.py, checked before any loop runs).
#include "arguments.hpp"
#include "diff_centre.hpp"
#include "forces.hpp"
#include "loop.hpp"
#include "scheme_diff_centre_step.hpp"
#include "scheme_runge_kutta.hpp"

namespace asterlite {
namespace {

// DIFF_CENTRE's specialised loop: clock, counters, instants, the state (7),
// the residual row, M^-1, K, C as model.LinearSystem.kernel_matrices gives
// them (1-D diagonals or (n, n)), the model (31), the archive (7), the energy
// balance (7), pas_arch, eps
PyObject* diff_centre_loop(PyObject*, PyObject* args) {
    Arguments in(args, "diff_centre_loop");
    Clock c = read_clock(in);
    State x = read_state(in);
    F1 residual = in.f1("residual", WRITE);
    const char* names[3] = {"mass_inverse", "stiffness", "damping"};
    // diagonal matrices come as 1-D arrays
    const Py_ssize_t first = 11;
    bool diagonal = false;
    if (PyTuple_GET_SIZE(args) > first) {
        Py_buffer probe;
        if (PyObject_GetBuffer(PyTuple_GET_ITEM(args, first), &probe, PyBUF_ND) == 0) {
            diagonal = probe.ndim == 1;
            PyBuffer_Release(&probe);
        } else {
            PyErr_Clear();  // refused by name below
        }
    }
    F1 d[3];
    F2 full[3];
    for (int k = 0; k < 3; ++k) {
        if (diagonal) {
            d[k] = in.f1(names[k]);
        } else {
            full[k] = in.f2(names[k]);
        }
    }
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
    in.require(residual.n0 == n, "residual");
    for (int k = 0; k < 3; ++k) {
        in.require(diagonal ? d[k].n0 == n : (full[k].n0 == n && full[k].n1 == n), "matrices");
    }
    if (in.failed()) return nullptr;
    int status;
    Py_BEGIN_ALLOW_THREADS
    if (diagonal) {
        status = diff_centre_loop(c, x, residual, d[0], d[1], d[2], model, out, balance);
    } else {
        status = diff_centre_loop(c, x, residual, full[0], full[1], full[2], model, out,
                                  balance);
    }
    Py_END_ALLOW_THREADS
    return loop_status(status);
}

// forces.total_force then forces.acceleration at the start of a run: t, the
// state (7), a residual row, the model (31); a diverging shock's index or -1
PyObject* start(PyObject*, PyObject* args) {
    Arguments in(args, "start");
    const double t = in.real("t");
    State x = read_state(in);
    F1 residual = in.f1("residual", WRITE);
    Model model = read_model(in);
    if (!in.complete()) return nullptr;
    check_model(in, x, model);
    in.require(residual.n0 == x.q.n0, "residual");
    if (in.failed()) return nullptr;
    const index shock = total_force(t, x.q, x.v, model, x.vint, x.work, x.f);
    acceleration(x.f, x.q, x.v, model.lin, residual, x.a);
    return PyLong_FromLongLong(shock);
}

// energy.start: the balance at the initial state (row 0): t, the state (7),
// the model (31), the balance (7)
PyObject* energy_start(PyObject*, PyObject* args) {
    Arguments in(args, "energy_start");
    const double t = in.real("t");
    State x = read_state(in);
    Model model = read_model(in);
    energy::Balance balance = read_balance(in);
    if (!in.complete()) return nullptr;
    check_model(in, x, model, true);  // a run with implicit shocks starts its balance too
    check_balance(in, balance, x, 1);
    in.require(balance.active(), "the energy balance is not asked");
    if (in.failed()) return nullptr;
    energy::start(balance, t, x.q, x.v, x.a, x.vint, model);
    Py_RETURN_NONE;
}

// DIFF_CENTRE's general path (loop.time_loop around scheme_diff_centre.step
// on the three bundles): clock, counters, instants, the state (7), the memory
// (3: what scheme_diff_centre.prepare made), the model, the archive (7), the energy
// balance (7), pas_arch, eps; returns the status
PyObject* diff_centre_step_loop(PyObject*, PyObject* args) {
    // scheme_diff_centre.prepare: one residual row of length n
    auto check_memory = [](Arguments& in, const Memory& memory, const State& x) {
        in.require(memory.rows.n0 > diff_centre::RESIDUAL && memory.rows.n1 == x.q.n0,
                   "memory rows");
    };
    return run_time_loop(args, "diff_centre_step_loop", diff_centre::step, check_memory);
}

PyObject* runge_kutta_loop(PyObject*, PyObject* args) {
    return run_time_loop(args, "runge_kutta_loop", runge_kutta::step);
}

// the positions of layout.hpp, for the check against the Python side
PyObject* layout(PyObject*, PyObject*) {
    return constants_dict(
        {
        {"STATUS_DONE", STATUS_DONE}, {"STATUS_NOT_FINITE", STATUS_NOT_FINITE},
        {"STATUS_SHOCK_DIVERGED", STATUS_SHOCK_DIVERGED},
        {"STATUS_STEP_UNDERFLOW", STATUS_STEP_UNDERFLOW}, {"STATUS_REJECTED", STATUS_REJECTED},
        {"STATUS_SWITCH_NOT_LOCATED", STATUS_SWITCH_NOT_LOCATED}, {"STATUS_FULL", STATUS_FULL},
        {"STATUS_LOADS", STATUS_LOADS}, {"STATUS_PAUSE", STATUS_PAUSE},
        {"C_TIME", C_TIME}, {"C_STEP", C_STEP}, {"C_STEP0", C_STEP0}, {"C_END", C_END},
        {"C_NEWDT", C_NEWDT}, {"C_MIN_STEP", C_MIN_STEP}, {"C_MAX_STEP", C_MAX_STEP},
        {"C_ORIGIN", C_ORIGIN}, {"K_STEP", K_STEP}, {"K_ARCHIVED", K_ARCHIVED},
        {"K_INSTANT", K_INSTANT}, {"K_FORCE", K_FORCE}, {"K_IRREGULAR", K_IRREGULAR},
        {"K_REJECTED", K_REJECTED}, {"K_ADAPTIVE", K_ADAPTIVE}, {"K_SHOCK", K_SHOCK},
        {"K_PAUSE_AT", K_PAUSE_AT}, {"K_GRID", K_GRID}, {"INFO_STEP", INFO_STEP},
        {"INFO_REJECTED", INFO_REJECTED}, {"PLAN_Y", PLAN_Y}, {"PLAN_Z", PLAN_Z},
        {"CERCLE", CERCLE}, {"DISCRET", DISCRET}, {"BI_PLAN_Y", BI_PLAN_Y},
        {"BI_PLAN_Z", BI_PLAN_Z}, {"BI_CERCLE", BI_CERCLE}, {"BI_CERC_INT", BI_CERC_INT},
        {"P_GAP", P_GAP}, {"P_DIST1", P_DIST1}, {"P_DIST2", P_DIST2}, {"P_KN", P_KN},
        {"P_CN", P_CN}, {"P_KT", P_KT}, {"P_CT", P_CT}, {"P_MU_DYN", P_MU_DYN},
        {"P_MU_STAT", P_MU_STAT}, {"P_SIGN_Y", P_SIGN_Y}, {"P_SIGN_Z", P_SIGN_Z},
        {"P_ORIGIN", P_ORIGIN}, {"P_COORD1", P_COORD1}, {"P_COORD2", P_COORD2},
        {"P_DRIVE1", P_DRIVE1}, {"P_DRIVE2", P_DRIVE2}, {"F_GEOMETRY", F_GEOMETRY},
        {"F_TWO_NODES", F_TWO_NODES}, {"F_UNIDIR", F_UNIDIR}, {"F_NPOLAR", F_NPOLAR},
        {"F_LAW", F_LAW}, {"F_IMPLICIT", F_IMPLICIT}, {"V_FN", V_FN}, {"V_FT1", V_FT1},
        {"V_FT2", V_FT2}, {"V_LOC1", V_LOC1}, {"V_LOC2", V_LOC2}, {"V_VN", V_VN},
        {"V_VT1", V_VT1}, {"V_VT2", V_VT2}, {"V_STICK", V_STICK}, {"V_FT_REF", V_FT_REF},
        {"V_X_REF", V_X_REF}, {"V_VT_OLD", V_VT_OLD}, {"PUSH_CONSTANT", PUSH_CONSTANT},
        {"PUSH_TIME", PUSH_TIME}, {"ADD", ADD}, {"SUB", SUB}, {"MUL", MUL}, {"DIV", DIV},
        {"POW", POW}, {"MOD", MOD}, {"FLOOR_DIV", FLOOR_DIV}, {"NEG", NEG}, {"SIN", SIN},
        {"COS", COS}, {"TAN", TAN}, {"ASIN", ASIN}, {"ACOS", ACOS}, {"ATAN", ATAN},
        {"SINH", SINH}, {"COSH", COSH}, {"TANH", TANH}, {"ASINH", ASINH}, {"ACOSH", ACOSH},
        {"ATANH", ATANH}, {"EXP", EXP}, {"LOG", LOG}, {"LOG10", LOG10}, {"SQRT", SQRT},
        {"ABS", ABS}, {"FLOOR", FLOOR}, {"CEIL", CEIL}, {"TRUNC", TRUNC},
        {"DEGREES", DEGREES}, {"RADIANS", RADIANS}, {"SIGN", SIGN}, {"ATAN2", ATAN2},
        {"HYPOT", HYPOT}, {"MINIMUM", MINIMUM}, {"MAXIMUM", MAXIMUM},
        {"COPYSIGN", COPYSIGN}, {"LESS", LESS}, {"LESS_EQUAL", LESS_EQUAL},
        {"GREATER", GREATER}, {"GREATER_EQUAL", GREATER_EQUAL}, {"EQUAL", EQUAL},
        {"NOT_EQUAL", NOT_EQUAL}, {"AND", AND}, {"OR", OR}, {"NOT", NOT},
        {"SELECT", SELECT}, {"IDENTITY", IDENTITY}
        },
        {{"GRID_TOLERANCE", GRID_TOLERANCE}, {"SLIP_VELOCITY_FLOOR", SLIP_VELOCITY_FLOOR}, {"EPS", EPS}, {"VELOCITY_DIVERGENCE", VELOCITY_DIVERGENCE}});
}

PyMethodDef methods[] = {
    {"diff_centre_loop", diff_centre_loop, METH_VARARGS,
     "DIFF_CENTRE's specialised loop on diagonal or full matrices; returns a status."},
    {"diff_centre_step_loop", diff_centre_step_loop, METH_VARARGS,
     "DIFF_CENTRE's general path (its step on the general model); returns a status."},
    {"runge_kutta_loop", runge_kutta_loop, METH_VARARGS,
     "RUNGE_KUTTA_32/54's loop on the shocks' local frames; returns a status."},
    {"start", start, METH_VARARGS,
     "The total force and the acceleration at the start of a run; a diverging shock or -1."},
    {"energy_start", energy_start, METH_VARARGS,
     "The energy balance at the initial state, its first archived row."},
    {"layout", layout, METH_NOARGS, "The positions and constants the loops were built with."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_loops",
    "The time loops compiled when asterlite is installed (asterlite.dynamics.native).", -1,
    methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__loops(void) {
    return asterlite::loops_module(&asterlite::module,
                                   {{"DIFF_CENTRE (general path)", "diff_centre_step_loop"},
                                    {"RUNGE_KUTTA", "runge_kutta_loop"},
                                    {"RUNGE_KUTTA (general path)", "runge_kutta_loop"}});
}
