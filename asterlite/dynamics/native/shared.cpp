// The Python module asterlite.dynamics.native._shared: the two loops shared by
// every scheme, on the general model (three bundles), in place on numpy
// arrays: the variable rotation speed's (rotation.hpp: loop.time_loop around
// rotation.rotating_step) and the implicit shocks' (implicit_shocks.hpp:
// implicit_shocks.implicit_loop). asterlite.dynamics.native.shared_loops
// calls them with numba's arguments flattened.
#include <cstdint>

#include "arguments.hpp"
#include "dispatch.hpp"
#include "implicit_shocks.hpp"
#include "loop.hpp"
#include "rotation.hpp"

namespace asterlite {
namespace {

// the arrays a loop writes that read_model reads as read-only (K, C and the
// diagonal flag of the linear bundle, the shock flags), passed again writable
// before the model: the same buffers as the model's
struct Written {
    F2 stiffness, damping;
    I1 diagonal;
    I2 flags;
};

Written read_written(Arguments& in) {
    Written w;
    w.stiffness = in.f2("linear_stiffness", WRITE);
    w.damping = in.f2("linear_damping", WRITE);
    w.diagonal = in.i1("linear_diagonal", WRITE);
    w.flags = in.i2("shock_flags_written", WRITE);
    return w;
}

void check_written(Arguments& in, const Written& w, const Model& model) {
    in.require(w.stiffness.data == model.lin.stiffness.data &&
                   w.damping.data == model.lin.damping.data &&
                   w.flags.data == model.shk.flags.data && w.diagonal.n0 == 1,
               "the linear bundle and shock flags written are the model's");
}

// the checks of every loop (loop.hpp run_loop's), then the scheme's memory
// for its dispatch code
void check_common(Arguments& in, const Clock& c, const State& x, const Memory& memory,
                  const Model& model, const ArchiveBuffers& out,
                  const energy::Balance& balance, std::int64_t code, bool implicit = false) {
    check_model(in, x, model, implicit);
    check_loop(in, c, x, out);
    check_balance(in, balance, x, out.t.n0);
    if (in.failed()) return;
    const index n = x.q.n0;
    in.require(memory.rows.n0 == 0 || memory.rows.n1 == n, "memory rows");
    in.require(code >= dispatch::NEWMARK && code <= dispatch::ADAPT_ORDRE2, "scheme code");
    if (!in.failed()) {
        in.require(dispatch::memory_fits(code, memory, n), "memory of another scheme");
    }
}

// Omega (row 0) and Omega' (row 1): the tables and formula programs of
// Rotation.bundle()'s excitation
void read_multipliers(Arguments& in, rotation::Rotation& rot) {
    rot.tables.abscissas = in.f2("rotation_abscissas");
    rot.tables.ordinates = in.f2("rotation_ordinates");
    rot.tables.layout = in.i2("rotation_layout");
    rot.tables.cursors = in.i1("rotation_cursors", WRITE);
    rot.codes = in.i2("rotation_codes");
    rot.constants = in.f2("rotation_constants");
    rot.stack = in.f1("rotation_stack", WRITE);
}

void check_multipliers(Arguments& in, const rotation::Rotation& rot) {
    if (in.failed()) return;
    const Tables& tab = rot.tables;
    in.require(tab.abscissas.n0 >= 2 && tab.ordinates.n0 == tab.abscissas.n0 &&
                   tab.ordinates.n1 == tab.abscissas.n1 && tab.layout.n0 >= 2 &&
                   tab.layout.n1 >= 3 && tab.cursors.n0 >= 2,
               "rotation tables");
    in.require(rot.codes.n0 >= 2 && rot.constants.n0 >= 2 &&
                   rot.constants.n1 == rot.codes.n1 && rot.stack.n0 >= 32,
               "rotation programs");
    for (index e = 0; e < 2 && !in.failed(); ++e) {
        if (rot.codes(e, 0) > 0) {
            in.require(rot.codes(e, 0) < rot.codes.n1, "rotation program length");
        } else {
            in.require(tab.layout(e, 0) >= 1 && tab.layout(e, 0) <= tab.abscissas.n1,
                       "rotation table length");
        }
    }
}

// rotation.speed_and_acceleration: (Omega(t), Omega'(t)) from the multipliers
// (7 arrays, as rotating_loop takes them), for the matrices at a run's start
PyObject* rotation_multipliers(PyObject*, PyObject* args) {
    Arguments in(args, "rotation_multipliers");
    const double t = in.real("t");
    rotation::Rotation rot;
    read_multipliers(in, rot);
    if (!in.complete()) return nullptr;
    check_multipliers(in, rot);
    if (in.failed()) return nullptr;
    const double speed = rotation::multiplier_value(rot, 0, t);
    const double accel = rotation::multiplier_value(rot, 1, t);
    return Py_BuildValue("(dd)", speed, accel);
}

// Variable rotation speed: clock, counters, instants, the state (7), the
// memory (3), the rotation (Rotation.bundle(): C, K at rest, G, K_gy, then
// the multipliers' abscissas, ordinates, layout, cursors, codes, constants,
// stack), the scheme's code (an int64 array of one), the written arrays (4),
// the model (31), the archive (7), the energy balance (7), pas_arch, eps
PyObject* rotating_loop(PyObject*, PyObject* args) {
    Arguments in(args, "rotating_loop");
    Clock c = read_clock(in);
    State x = read_state(in);
    Memory memory = read_memory(in);
    rotation::Rotation rot;
    rot.damping0 = in.f2("rotation_damping");
    rot.stiffness0 = in.f2("rotation_stiffness");
    rot.gyro = in.f2("rotation_gyro");
    rot.rigy = in.f2("rotation_rigy");
    read_multipliers(in, rot);
    I1 code = in.i1("code");
    Written written = read_written(in);
    Model model = read_model(in);
    ArchiveBuffers out = read_archive(in);
    energy::Balance balance = read_balance(in);
    c.pas_arch = in.integer("pas_arch");
    c.eps = in.real("eps");
    if (!in.complete()) return nullptr;
    in.require(code.n0 == 1, "scheme code");
    if (in.failed()) return nullptr;
    check_common(in, c, x, memory, model, out, balance, code(0));
    check_written(in, written, model);
    if (in.failed()) return nullptr;
    const index n = x.q.n0;
    for (const F2* m : {&rot.damping0, &rot.stiffness0, &rot.gyro, &rot.rigy}) {
        in.require(m->n0 == n && m->n1 == n, "rotation matrices");
    }
    check_multipliers(in, rot);
    if (in.failed()) return nullptr;
    const I1 flag = written.diagonal;
    const std::int64_t scheme = code(0);
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = rotation::rotating_loop(c, x, memory, model, out, balance, flag, rot, scheme);
    Py_END_ALLOW_THREADS
    return loop_status(status);
}

// layouts.Treatment: 15 arrays, its backup pair flattened
implicit_shocks::Treatment read_treatment(Arguments& in) {
    implicit_shocks::Treatment tr;
    tr.stiffness0 = in.f2("stiffness0");
    tr.damping0 = in.f2("damping0");
    tr.diagonal0 = in.i1("diagonal0");
    tr.active = in.i1("active", WRITE);
    tr.trial = in.i1("trial", WRITE);
    tr.ints = in.i1("ints", WRITE);
    tr.kinematics = in.f2("kinematics", WRITE);
    tr.gradient = in.f2("gradient", WRITE);
    tr.work = in.f2("treatment_work", WRITE);
    tr.backup_rows = in.f2("backup_rows", WRITE);
    tr.backup_scalars = in.f1("backup_scalars", WRITE);
    tr.keep = in.f2("keep", WRITE);
    tr.vint_keep = in.f3("vint_keep", WRITE);
    tr.active_at_start = in.i1("active_at_start", WRITE);
    tr.planned = in.f1("planned", WRITE);
    return tr;
}

// the treatment's arrays for n modes, ns shocks, the scheme's memory and the
// internal variables' width
void check_treatment(Arguments& in, const implicit_shocks::Treatment& tr, index n, index ns,
                     const Memory& memory, index vint_width) {
    in.require(tr.stiffness0.n0 == n && tr.stiffness0.n1 == n && tr.damping0.n0 == n &&
                   tr.damping0.n1 == n && tr.diagonal0.n0 == 1,
               "K0, C0");
    in.require(tr.active.n0 == ns && tr.trial.n0 == ns && tr.active_at_start.n0 == ns &&
                   tr.ints.n0 >= implicit_shocks::N_INTS && tr.planned.n0 >= 1,
               "contact sets");
    in.require(tr.kinematics.n0 == implicit_shocks::N_KINEMATICS && tr.kinematics.n1 == ns,
               "kinematics");
    in.require(tr.gradient.n0 >= 1 && tr.gradient.n1 == n && tr.work.n0 >= 5 && tr.work.n1 >= 3,
               "treatment scratch");
    in.require(tr.backup_rows.n0 == memory.rows.n0 && tr.backup_rows.n1 == memory.rows.n1 &&
                   tr.backup_scalars.n0 == memory.scalars.n0,
               "backup of the scheme's memory");
    in.require(tr.keep.n0 == 4 && tr.keep.n1 == n && tr.vint_keep.n0 == 2 &&
                   tr.vint_keep.n1 == ns && tr.vint_keep.n2 == vint_width,
               "backup of the state");
}

// implicit_shocks.start: the shocks already in contact at the initial state
// linearised (K, C, the shock flags and parameters of the model written): q,
// v, the treatment (15 arrays), the written arrays (4), the model (31)
PyObject* implicit_start(PyObject*, PyObject* args) {
    Arguments in(args, "implicit_start");
    const F1 q = in.f1("q"), v = in.f1("v");
    implicit_shocks::Treatment tr = read_treatment(in);
    Written written = read_written(in);
    Model model = read_model(in);
    if (!in.complete()) return nullptr;
    const I2& flags = written.flags;
    const index n = q.n0, ns = flags.n0;
    in.require(v.n0 == n && model.lin.minv.n0 == n && model.shk.phis.n3 == n, "state vectors");
    in.require(flags.n1 > F_IMPLICIT, "shock flags without their treatment column");
    in.require(model.shk.params.n1 > P_LIN_SIN, "shock parameters without the linearisation");
    check_written(in, written, model);
    if (in.failed()) return nullptr;
    in.require(tr.stiffness0.n0 == n && tr.stiffness0.n1 == n && tr.damping0.n0 == n &&
                   tr.damping0.n1 == n && tr.diagonal0.n0 == 1 && tr.active.n0 == ns &&
                   tr.trial.n0 == ns && tr.ints.n0 >= implicit_shocks::N_INTS &&
                   tr.kinematics.n0 == implicit_shocks::N_KINEMATICS && tr.kinematics.n1 == ns &&
                   tr.gradient.n0 >= 1 && tr.gradient.n1 == n && tr.work.n0 >= 5 &&
                   tr.work.n1 >= 3,
               "treatment");
    if (in.failed()) return nullptr;
    Linear lin = model.lin;
    implicit_shocks::indicators(q, v, model.shk, tr.kinematics, implicit_shocks::R_GAP1, tr.trial,
                                tr.work);
    for (index s = 0; s < ns; ++s) {
        if (tr.trial(s) != tr.active(s)) {
            implicit_shocks::switch_contacts(q, model.shk, flags, lin, written.diagonal, tr);
            break;
        }
    }
    Py_RETURN_NONE;
}

// Implicit shocks: the scheme's code (an int), clock, counters, instants, the
// state (7), the memory (3), the treatment (layouts.Treatment, 15 arrays: its
// backup pair flattened), the written arrays (4), the model (31), the archive
// (7), the energy balance (7), pas_arch, eps
PyObject* implicit_loop(PyObject*, PyObject* args) {
    Arguments in(args, "implicit_loop");
    const std::int64_t code = in.integer("code");
    Clock c = read_clock(in);
    State x = read_state(in);
    Memory memory = read_memory(in);
    implicit_shocks::Treatment tr = read_treatment(in);
    Written written = read_written(in);
    Model model = read_model(in);
    ArchiveBuffers out = read_archive(in);
    energy::Balance balance = read_balance(in);
    c.pas_arch = in.integer("pas_arch");
    c.eps = in.real("eps");
    if (!in.complete()) return nullptr;
    const I2& flags = written.flags;
    in.require(flags.n1 > F_IMPLICIT, "shock flags without their treatment column");
    in.require(model.shk.params.n1 > P_LIN_SIN, "shock parameters without the linearisation");
    if (in.failed()) return nullptr;
    check_common(in, c, x, memory, model, out, balance, code, true);
    check_written(in, written, model);
    if (in.failed()) return nullptr;
    check_treatment(in, tr, x.q.n0, flags.n0, memory, x.vint.n1);
    if (in.failed()) return nullptr;
    const I1 flag = written.diagonal;
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = implicit_shocks::implicit_loop(code, c, x, memory, model, out, balance, flags, flag,
                                            tr);
    Py_END_ALLOW_THREADS
    return loop_status(status);
}

// the codes and constants of the loops, for the check against the Python side
PyObject* constants(PyObject*, PyObject*) {
    return constants_dict(
        {
        {"NEWMARK", dispatch::NEWMARK}, {"TRBDF2", dispatch::TRBDF2},
        {"DEVOGE", dispatch::DEVOGE}, {"DIFF_CENTRE", dispatch::DIFF_CENTRE},
        {"RUNGE_KUTTA", dispatch::RUNGE_KUTTA}, {"ADAPT_ORDRE1", dispatch::ADAPT_ORDRE1},
        {"ADAPT_ORDRE2", dispatch::ADAPT_ORDRE2}, {"P_LIN_GAP", P_LIN_GAP},
        {"P_LIN_COS", P_LIN_COS}, {"P_LIN_SIN", P_LIN_SIN},
        {"NORMAL_EXPLICIT", NORMAL_EXPLICIT}, {"NORMAL_LINEARISED", NORMAL_LINEARISED},
        {"NORMAL_LEFT_OUT", NORMAL_LEFT_OUT}, {"MAX_TRIES", implicit_shocks::MAX_TRIES},
        {"I_TRIES", implicit_shocks::I_TRIES}, {"I_SWITCHES", implicit_shocks::I_SWITCHES},
        {"I_CUTS", implicit_shocks::I_CUTS}, {"I_TURNS", implicit_shocks::I_TURNS},
        {"N_INTS", implicit_shocks::N_INTS}, {"R_GAP0", implicit_shocks::R_GAP0},
        {"R_GAP1", implicit_shocks::R_GAP1}, {"R_FORCE0", implicit_shocks::R_FORCE0},
        {"R_FORCE1", implicit_shocks::R_FORCE1}, {"R_COS1", implicit_shocks::R_COS1},
        {"R_SIN1", implicit_shocks::R_SIN1}, {"N_KINEMATICS", implicit_shocks::N_KINEMATICS}
        },
        {
        {"CONTACT_FORCE", implicit_shocks::CONTACT_FORCE},
        {"CUT_TOLERANCE", implicit_shocks::CUT_TOLERANCE},
        {"SHORTEST_CUT", implicit_shocks::SHORTEST_CUT},
        {"NORMAL_TURN", implicit_shocks::NORMAL_TURN}
        });
}

PyMethodDef methods[] = {
    {"rotating_loop", rotating_loop, METH_VARARGS,
     "The loop at variable rotation speed (every scheme); returns a status."},
    {"implicit_loop", implicit_loop, METH_VARARGS,
     "The loop with implicit shocks (every scheme); returns a status."},
    {"rotation_multipliers", rotation_multipliers, METH_VARARGS,
     "(speed, acceleration) of the rotation at t (rotation.speed_and_acceleration)."},
    {"implicit_start", implicit_start, METH_VARARGS,
     "Linearise the shocks in contact at the initial state (implicit_shocks.start)."},
    {"constants", constants, METH_NOARGS, "The scheme codes and constants the loops use."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_shared",
    "The loops shared by every scheme (variable rotation speed, implicit shocks) compiled "
    "when asterlite is installed (asterlite.dynamics.native).",
    -1, methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

// no KERNELS: native.shared_loops serves these loops (not native.run_loop)
PyMODINIT_FUNC PyInit__shared(void) { return asterlite::loops_module(&asterlite::module, {}); }
