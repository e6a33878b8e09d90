// The Python module asterlite.dynamics.native._film: the loops with fluid
// films (fluid_film.run_loop, code_aster 11's EULER, and
// fluid_film.run_adapt_loop, its ADAPT_ORDRE2) and their start
// (fluid_film.start) on numpy arrays, in place,
// each taking numba's arguments with the tuples flattened
// (asterlite.dynamics.native.film_loops). No KERNELS: integrate_film calls them.
#include "arguments.hpp"
#include "film.hpp"

namespace asterlite {
namespace {

using film::FilmLinear;
using film::FilmLoads;
using film::FilmModel;
using film::FilmWork;

// integrate_film's ``linear``: the diagonals of M, K, C
FilmLinear read_linear(Arguments& in) {
    FilmLinear lin;
    lin.mass = in.f1("mass");
    lin.stiffness = in.f1("stiffness");
    lin.damping = in.f1("damping");
    return lin;
}

// integrate_film's ``model``: flags, params, local shapes, rest positions,
// polars, the film rows (written: the boundary layer), the mass weights
FilmModel read_film_model(Arguments& in) {
    FilmModel model;
    model.flags = in.i2("shock_flags");
    model.params = in.f2("shock_params");
    model.shapes = in.f4("local_shapes");
    model.rest = in.f3("local_rest");
    model.polars = in.f3("shock_polars");
    model.film = in.f2("film", WRITE);
    model.weights = in.f2("weights");
    return model;
}

// excitation.Excitation.bundle(): the 15 arrays in the order of layouts.Loads
FilmLoads read_film_loads(Arguments& in) {
    FilmLoads exc;
    exc.loads.vectors = in.f2("load_vectors");
    exc.loads.tables.abscissas = in.f2("load_abscissas");
    exc.loads.tables.ordinates = in.f2("load_ordinates");
    exc.loads.tables.layout = in.i2("load_layout");
    exc.sup.shapes = in.f4("support_shapes");
    exc.sup.tables.abscissas = in.f2("support_abscissas");
    exc.sup.tables.ordinates = in.f2("support_ordinates");
    exc.sup.tables.layout = in.i2("support_layout");
    exc.loads.tables.pending = in.i1("load_pending");
    exc.loads.tables.cursors = in.i1("load_cursors", WRITE);
    exc.sup.tables.pending = in.i1("support_pending");
    exc.sup.tables.cursors = in.i1("support_cursors", WRITE);
    exc.loads.codes = in.i2("load_codes");
    exc.loads.constants = in.f2("load_constants");
    exc.loads.stack = in.f1("load_stack", WRITE);
    return exc;
}

// integrate_film's ``work``: base force, force, modified mass, kinematics
FilmWork read_work(Arguments& in) {
    FilmWork work;
    work.base = in.f1("base", WRITE);
    work.f = in.f1("f", WRITE);
    work.mass_mod = in.f1("mass_mod", WRITE);
    work.kin = in.f1("kin", WRITE);
    return work;
}

// what the film functions rely on in the state, the model, the loads, the work
void check_film(Arguments& in, const F1& q, const F1& v, const F1& a, const F2& vint,
                const FilmLinear& lin, const FilmModel& model, const FilmLoads& exc,
                const FilmWork& work) {
    if (in.failed()) return;
    const index n = q.n0, ns = model.flags.n0;
    in.require(v.n0 == n && a.n0 == n, "state vectors");
    in.require(lin.mass.n0 == n && lin.stiffness.n0 == n && lin.damping.n0 == n, "matrices");
    in.require(vint.n0 == ns && vint.n1 > V_VT_OLD + 1, "internal variables");
    in.require(model.flags.n1 > F_NPOLAR, "shock flags");
    for (index s = 0; s < ns && !in.failed(); ++s) {
        in.require(model.flags(s, F_NPOLAR) <= model.polars.n1, "polar facets");
    }
    in.require(model.params.n0 == ns && model.params.n1 > P_SIGN_Z, "shock parameters");
    in.require(model.shapes.n0 == ns && model.shapes.n1 == 2 && model.shapes.n2 == 3 &&
                   model.shapes.n3 == n,
               "local shapes");
    in.require(model.rest.n0 == ns && model.rest.n1 == 2 && model.rest.n2 == 3, "rest positions");
    in.require(model.polars.n0 >= ns || ns == 0, "shock polars");
    in.require(model.film.n0 == ns && model.film.n1 >= film::N_FILM, "film rows");
    in.require(model.weights.n0 == ns && model.weights.n1 == n, "film weights");
    check_loads(in, exc.loads, n);
    const Loads& loads = exc.loads;
    in.require(loads.tables.pending.n0 <= loads.tables.layout.n0 &&
                   exc.sup.tables.pending.n0 <= exc.sup.tables.layout.n0,
               "pending windows");
    in.require(work.base.n0 == n && work.f.n0 == n && work.mass_mod.n0 == n &&
                   work.kin.n0 >= film::N_KIN,
               "work");
}

// and what the loops rely on in the controls, the counts and the archive
void check_film_loop(Arguments& in, const F1& q, const F2& vint, const F1& controls,
                     const F1& counts, const ArchiveBuffers& out) {
    if (in.failed()) return;
    const index n = q.n0;
    in.require(controls.n0 >= 2 && counts.n0 > film::S_TOTAL, "film controls and counts");
    const index cap = out.t.n0;
    in.require(out.order.n0 == cap && out.q.n0 == cap && out.v.n0 == cap && out.a.n0 == cap &&
                   out.vint.n0 == cap && out.info.n0 == cap,
               "archive rows");
    in.require(out.q.n1 == n && out.v.n1 == n && out.a.n1 == n && out.info.n1 > INFO_REJECTED,
               "archive columns");
    in.require(out.vint.n1 == vint.n0 && out.vint.n2 == vint.n1, "archived internal variables");
}

void check_clock(Arguments& in, const Clock& c) {
    if (in.failed()) return;
    in.require(c.clock.n0 > C_ORIGIN && c.counters.n0 > K_GRID, "clock and counters");
    in.require(c.counters(K_INSTANT) >= 0 && c.counters(K_ARCHIVED) >= 0, "counters");
}

// fluid_film.start: t0, q, v, a, linear (3), model (7), exc (15), vint, work
// (4); (a failing shock or -1, whether the acceleration is finite)
PyObject* film_start(PyObject*, PyObject* args) {
    Arguments in(args, "film_start");
    const double t0 = in.real("t0");
    const F1 q = in.f1("q"), v = in.f1("v"), a = in.f1("a", WRITE);
    const FilmLinear lin = read_linear(in);
    const FilmModel model = read_film_model(in);
    const FilmLoads exc = read_film_loads(in);
    const F2 vint = in.f2("vint", WRITE);
    const FilmWork work = read_work(in);
    if (!in.complete()) return nullptr;
    check_film(in, q, v, a, vint, lin, model, exc, work);
    if (in.failed()) return nullptr;
    bool finite;
    const index shock = film::start(t0, q, v, a, lin, model, exc.loads, vint, work, finite);
    return Py_BuildValue("(LO)", static_cast<long long>(shock), finite ? Py_True : Py_False);
}

// fluid_film.run_loop: clock, counters, q, v, a, vint, linear (3), model (7),
// exc (15), controls, scalars, work (4), archive (7), instants, pas_arch, eps
PyObject* film_loop(PyObject*, PyObject* args) {
    Arguments in(args, "film_loop");
    Clock c;
    c.clock = in.f1("clock", WRITE);
    c.counters = in.i1("counters", WRITE);
    const F1 q = in.f1("q", WRITE), v = in.f1("v", WRITE), a = in.f1("a", WRITE);
    const F2 vint = in.f2("vint", WRITE);
    const FilmLinear lin = read_linear(in);
    const FilmModel model = read_film_model(in);
    const FilmLoads exc = read_film_loads(in);
    const F1 controls = in.f1("controls");
    const F1 scalars = in.f1("scalars", WRITE);
    const FilmWork work = read_work(in);
    const ArchiveBuffers out = read_archive(in);
    c.instants = in.f1("instants");
    c.pas_arch = in.integer("pas_arch");
    c.eps = in.real("eps");
    if (!in.complete()) return nullptr;
    check_clock(in, c);
    check_film(in, q, v, a, vint, lin, model, exc, work);
    check_film_loop(in, q, vint, controls, scalars, out);
    in.require(c.pas_arch >= 1, "pas_arch below 1");
    if (in.failed()) return nullptr;
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = film::run_loop(c, q, v, a, vint, lin, model, exc, controls, scalars, work, out);
    Py_END_ALLOW_THREADS
    return PyLong_FromLong(status);
}

// fluid_film.run_adapt_loop: clock, counters, the state (7), the memory (3:
// scheme_adapt_ordre2_v11.prepare's), linear (3), model (7), exc (15),
// controls, counts, work (4), archive (7), pas_arch
PyObject* film_adapt_loop(PyObject*, PyObject* args) {
    Arguments in(args, "film_adapt_loop");
    Clock c;
    c.clock = in.f1("clock", WRITE);
    c.counters = in.i1("counters", WRITE);
    const State x = read_state(in);
    const Memory memory = read_memory(in);
    const FilmLinear lin = read_linear(in);
    const FilmModel model = read_film_model(in);
    const FilmLoads exc = read_film_loads(in);
    const F1 controls = in.f1("controls");
    const F1 counts = in.f1("counts", WRITE);
    const FilmWork work = read_work(in);
    const ArchiveBuffers out = read_archive(in);
    const std::int64_t pas_arch = in.integer("pas_arch");
    if (!in.complete()) return nullptr;
    check_clock(in, c);
    check_film(in, x.q, x.v, x.a, x.vint, lin, model, exc, work);
    check_film_loop(in, x.q, x.vint, controls, counts, out);
    if (!in.failed()) {
        in.require(x.vint_save.n0 == x.vint.n0 && x.vint_save.n1 == x.vint.n1,
                   "saved internal variables");
        adapt_legacy::check_memory(in, memory, x);
    }
    if (in.failed()) return nullptr;
    int status;
    Py_BEGIN_ALLOW_THREADS
    status = film::run_adapt_loop(c, x, memory, lin, model, exc, controls, counts, work, out,
                                  pas_arch);
    Py_END_ALLOW_THREADS
    return PyLong_FromLong(status);
}

PyMethodDef methods[] = {
    {"film_start", film_start, METH_VARARGS,
     "The initial acceleration with fluid films (fluid_film.start); (shock or -1, finite)."},
    {"film_loop", film_loop, METH_VARARGS,
     "code_aster 11's EULER loop with fluid films (fluid_film.run_loop); returns a status."},
    {"film_adapt_loop", film_adapt_loop, METH_VARARGS,
     "code_aster 10-12's ADAPT_ORDRE2 loop with fluid films (fluid_film.run_adapt_loop); "
     "returns a status."},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_film",
    "The loops with fluid films compiled when asterlite is installed "
    "(asterlite.dynamics.native).",
    -1, methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__film(void) { return PyModule_Create(&asterlite::module); }
