// The Python module asterlite.dynamics.native._loops: numpy arrays in, the
// loops of the headers run on them in place. Arguments come as one tuple in
// the order asterlite/dynamics/native/__init__.py writes them; each array's
// type, dimensions and writability is checked before any loop runs.
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <cstring>
#include <vector>

#include "diff_centre.hpp"

namespace asterlite {
namespace {

enum Kind { REAL, INTEGER };
enum Access { READ, WRITE };

class Arguments {
  public:
    Arguments(PyObject* args, const char* function) : args_(args), function_(function) {}
    ~Arguments() {
        for (Py_buffer& buffer : held_) PyBuffer_Release(&buffer);
    }
    bool failed() const { return failed_; }

    // the next argument as a C-ordered array of ndim dimensions
    void* array(const char* name, int ndim, Kind kind, Access access, index* shape) {
        PyObject* item = next(name);
        if (item == nullptr) return nullptr;
        Py_buffer buffer;
        int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (access == WRITE ? PyBUF_WRITABLE : 0);
        if (PyObject_GetBuffer(item, &buffer, flags) != 0) {
            PyErr_Clear();
            return fail(name, access == WRITE ? "a writable C-ordered array" : "a C-ordered array");
        }
        held_.push_back(buffer);
        const char* format = buffer.format ? buffer.format : "B";
        if (*format == '<' || *format == '=' || *format == '@') ++format;
        const bool real = std::strcmp(format, "d") == 0;
        const bool integer = std::strcmp(format, "l") == 0 || std::strcmp(format, "q") == 0;
        if (buffer.itemsize != 8 || (kind == REAL ? !real : !integer)) {
            return fail(name, kind == REAL ? "float64 values" : "int64 values");
        }
        if (buffer.ndim != ndim) return fail(name, "another number of dimensions");
        for (int d = 0; d < ndim; ++d) shape[d] = buffer.shape[d];
        return buffer.buf;
    }

    F1 f1(const char* name, Access access = READ) {
        F1 view;
        view.data = static_cast<double*>(array(name, 1, REAL, access, &view.n0));
        return view;
    }
    F2 f2(const char* name, Access access = READ) {
        index shape[2] = {0, 0};
        F2 view;
        view.data = static_cast<double*>(array(name, 2, REAL, access, shape));
        view.n0 = shape[0];
        view.n1 = shape[1];
        return view;
    }
    F3 f3(const char* name, Access access = READ) {
        index shape[3] = {0, 0, 0};
        F3 view;
        view.data = static_cast<double*>(array(name, 3, REAL, access, shape));
        view.n0 = shape[0];
        view.n1 = shape[1];
        view.n2 = shape[2];
        return view;
    }
    F4 f4(const char* name, Access access = READ) {
        index shape[4] = {0, 0, 0, 0};
        F4 view;
        view.data = static_cast<double*>(array(name, 4, REAL, access, shape));
        view.n0 = shape[0];
        view.n1 = shape[1];
        view.n2 = shape[2];
        view.n3 = shape[3];
        return view;
    }
    I1 i1(const char* name, Access access = READ) {
        I1 view;
        view.data = static_cast<std::int64_t*>(array(name, 1, INTEGER, access, &view.n0));
        return view;
    }
    I2 i2(const char* name, Access access = READ) {
        index shape[2] = {0, 0};
        I2 view;
        view.data = static_cast<std::int64_t*>(array(name, 2, INTEGER, access, shape));
        view.n0 = shape[0];
        view.n1 = shape[1];
        return view;
    }
    double real(const char* name) {
        PyObject* item = next(name);
        if (item == nullptr) return 0.0;
        const double value = PyFloat_AsDouble(item);
        if (value == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            fail(name, "a float");
        }
        return value;
    }
    std::int64_t integer(const char* name) {
        PyObject* item = next(name);
        if (item == nullptr) return 0;
        const long long value = PyLong_AsLongLong(item);
        if (value == -1 && PyErr_Occurred()) {
            PyErr_Clear();
            fail(name, "an integer");
        }
        return value;
    }

    // a relation between shapes the loops rely on
    void require(bool holds, const char* what) {
        if (!holds && !failed_) {
            PyErr_Format(PyExc_ValueError, "%s: inconsistent arrays: %s", function_, what);
            failed_ = true;
        }
    }

    bool complete() {
        if (!failed_ && position_ != PyTuple_GET_SIZE(args_)) {
            PyErr_Format(PyExc_TypeError, "%s: %zd arguments given, %zd read", function_,
                         PyTuple_GET_SIZE(args_), position_);
            failed_ = true;
        }
        return !failed_;
    }

  private:
    PyObject* next(const char* name) {
        if (failed_) return nullptr;
        if (position_ >= PyTuple_GET_SIZE(args_)) {
            PyErr_Format(PyExc_TypeError, "%s: argument %s missing", function_, name);
            failed_ = true;
            return nullptr;
        }
        return PyTuple_GET_ITEM(args_, position_++);
    }
    void* fail(const char* name, const char* expected) {
        if (!failed_) {
            PyErr_Format(PyExc_TypeError, "%s: argument %s must be %s", function_, name, expected);
            failed_ = true;
        }
        return nullptr;
    }

    PyObject* args_;
    const char* function_;
    Py_ssize_t position_ = 0;
    std::vector<Py_buffer> held_;
    bool failed_ = false;
};

Shocks read_shocks(Arguments& in) {
    Shocks shk;
    shk.flags = in.i2("shock_flags");
    shk.params = in.f2("shock_params", WRITE);
    shk.rots = in.f3("shock_rots");
    shk.polars = in.f3("shock_polars");
    return shk;
}

Tables read_tables(Arguments& in, const char* abscissas, const char* ordinates,
                   const char* layout, const char* pending, const char* cursors) {
    Tables tab;
    tab.abscissas = in.f2(abscissas);
    tab.ordinates = in.f2(ordinates);
    tab.layout = in.i2(layout);
    tab.pending = in.i1(pending);
    tab.cursors = in.i1(cursors, WRITE);
    return tab;
}

Loads read_loads(Arguments& in) {
    Loads loads;
    loads.vectors = in.f2("load_vectors");
    loads.tables = read_tables(in, "load_abscissas", "load_ordinates", "load_layout",
                               "load_pending", "load_cursors");
    loads.codes = in.i2("load_codes");
    loads.constants = in.f2("load_constants");
    loads.stack = in.f1("load_stack", WRITE);
    return loads;
}

Supports read_supports(Arguments& in) {
    Supports sup;
    sup.shapes = in.f4("support_shapes");
    sup.tables = read_tables(in, "support_abscissas", "support_ordinates", "support_layout",
                             "support_pending", "support_cursors");
    return sup;
}

// what every loop relies on in the shocks, loads and supports
void check_model(Arguments& in, index n, const Shocks& shk, const Loads& loads,
                 const Supports& sup, const F2& vint) {
    const index ns = shk.flags.n0;
    in.require(shk.flags.n1 > F_LAW, "shock flags without their law column");
    for (index s = 0; s < ns && !in.failed() && shk.flags.n1 > F_LAW; ++s) {
        in.require(shk.flags(s, F_LAW) == 0, "a shock of another relation than DIS_CHOC");
        if (shk.flags.n1 > F_IMPLICIT) {
            in.require(shk.flags(s, F_IMPLICIT) == 0, "a shock of the implicit treatment");
        }
    }
    in.require(shk.params.n0 == ns && shk.params.n1 > P_DRIVE2 + 5, "shock parameters");
    in.require(shk.rots.n0 == ns && shk.rots.n1 == 3 && shk.rots.n2 == 3, "shock frames");
    in.require(shk.polars.n0 == ns || ns == 0 || shk.polars.n0 >= ns, "shock polars");
    in.require(vint.n0 == ns && vint.n1 > V_VT_OLD + 1, "internal variables");
    in.require(loads.vectors.n1 == n || loads.vectors.n0 == 0, "load vectors");
    in.require(loads.tables.layout.n0 >= loads.vectors.n0, "load layout");
    in.require(loads.codes.n0 >= loads.vectors.n0 && loads.constants.n0 >= loads.vectors.n0,
               "load programs");
    in.require(loads.stack.n0 >= 32, "formula stack");
    in.require(sup.shapes.n3 == 0 || (sup.shapes.n0 == ns && sup.shapes.n1 == 2 &&
                                       sup.shapes.n2 == 3 && sup.tables.layout.n0 >= 2 * sup.shapes.n3),
               "support motions");
}

PyObject* diff_centre_loop(PyObject*, PyObject* args) {
    Arguments in(args, "diff_centre_loop");
    Clock c;
    c.clock = in.f1("clock", WRITE);
    c.counters = in.i1("counters", WRITE);
    c.instants = in.f1("instants");
    State x;
    x.q = in.f1("q", WRITE);
    x.v = in.f1("v", WRITE);
    x.a = in.f1("a", WRITE);
    x.f = in.f1("f", WRITE);
    x.vint = in.f2("vint", WRITE);
    x.residual = in.f1("residual", WRITE);
    const char* matrix_names[3] = {"mass_inverse", "stiffness", "damping"};
    // diagonal matrices come as 1-D arrays (model.LinearSystem.kernel_matrices)
    PyObject* first_matrix = PyTuple_GET_SIZE(args) > 9 ? PyTuple_GET_ITEM(args, 9) : nullptr;
    Py_buffer probe;
    bool diagonal = false;
    if (first_matrix != nullptr) {
        if (PyObject_GetBuffer(first_matrix, &probe, PyBUF_ND) == 0) {
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
            d[k] = in.f1(matrix_names[k]);
        } else {
            full[k] = in.f2(matrix_names[k]);
        }
    }
    Shocks shk = read_shocks(in);
    Local local;
    local.shapes = in.f4("shock_shapes");
    local.rest = in.f3("shock_rest");
    local.drive = in.f3("shock_drive", WRITE);
    Loads loads = read_loads(in);
    Supports sup = read_supports(in);
    ArchiveBuffers out;
    out.t = in.f1("out_t", WRITE);
    out.order = in.i1("out_order", WRITE);
    out.q = in.f2("out_q", WRITE);
    out.v = in.f2("out_v", WRITE);
    out.a = in.f2("out_a", WRITE);
    out.vint = in.f3("out_vint", WRITE);
    out.info = in.f2("out_info", WRITE);
    c.pas_arch = in.integer("pas_arch");
    c.eps = in.real("eps");
    if (!in.complete()) return nullptr;

    const index n = x.q.n0;
    in.require(c.clock.n0 > C_ORIGIN && c.counters.n0 > K_GRID, "clock and counters");
    in.require(c.pas_arch >= 1, "pas_arch below 1");
    in.require(x.v.n0 == n && x.a.n0 == n && x.f.n0 == n && x.residual.n0 == n, "state");
    for (int k = 0; k < 3; ++k) {
        in.require(diagonal ? d[k].n0 == n : (full[k].n0 == n && full[k].n1 == n), "matrices");
    }
    check_model(in, n, shk, loads, sup, x.vint);
    const index ns = shk.flags.n0;
    in.require(local.shapes.n0 == ns && local.shapes.n1 == 2 && local.shapes.n2 == 3 &&
                   local.shapes.n3 == n,
               "local shapes");
    in.require(local.rest.n0 == ns && local.rest.n1 == 2 && local.rest.n2 == 3, "rest positions");
    in.require(local.drive.n0 == ns && local.drive.n1 == 2 && local.drive.n2 == 6, "drive");
    const index cap = out.t.n0;
    in.require(out.order.n0 == cap && out.q.n0 == cap && out.v.n0 == cap && out.a.n0 == cap &&
                   out.vint.n0 == cap && out.info.n0 == cap,
               "archive rows");
    in.require(out.q.n1 == n && out.v.n1 == n && out.a.n1 == n && out.info.n1 > INFO_REJECTED,
               "archive columns");
    in.require(out.vint.n1 == ns && out.vint.n2 == x.vint.n1, "archived internal variables");
    in.require(c.counters(K_INSTANT) >= 0 && c.counters(K_ARCHIVED) >= 0, "counters");
    if (in.failed()) return nullptr;

    int status;
    Py_BEGIN_ALLOW_THREADS
    if (diagonal) {
        status = diff_centre_loop(c, x, d[0], d[1], d[2], shk, local, loads, sup, out);
    } else {
        status = diff_centre_loop(c, x, full[0], full[1], full[2], shk, local, loads, sup, out);
    }
    Py_END_ALLOW_THREADS
    return PyLong_FromLong(status);
}

// forces.total_force then forces.acceleration at the start of a run:
// returns a diverging shock's index or -1
PyObject* start(PyObject*, PyObject* args) {
    Arguments in(args, "start");
    const double t = in.real("t");
    State x;
    x.q = in.f1("q", WRITE);
    x.v = in.f1("v", WRITE);
    x.a = in.f1("a", WRITE);
    x.f = in.f1("f", WRITE);
    x.vint = in.f2("vint", WRITE);
    x.residual = in.f1("residual", WRITE);
    F2 work = in.f2("work", WRITE);
    F2 minv = in.f2("minv");
    F2 stiffness = in.f2("stiffness");
    F2 damping = in.f2("damping");
    I1 diagonal = in.i1("diagonal");
    Shocks shk = read_shocks(in);
    F4 phis = in.f4("shock_phis");
    Loads loads = read_loads(in);
    Supports sup = read_supports(in);
    if (!in.complete()) return nullptr;
    const index n = x.q.n0;
    in.require(x.v.n0 == n && x.a.n0 == n && x.f.n0 == n && x.residual.n0 == n, "state");
    in.require(work.n0 >= 5 && work.n1 >= 3, "work");
    in.require(minv.n0 == n && minv.n1 == n && stiffness.n0 == n && stiffness.n1 == n &&
                   damping.n0 == n && damping.n1 == n,
               "matrices");
    in.require(diagonal.n0 == 1, "diagonal flag");
    check_model(in, n, shk, loads, sup, x.vint);
    in.require(phis.n0 == shk.flags.n0 && phis.n1 == 2 && phis.n2 == 3 && phis.n3 == n,
               "mode shapes");
    if (in.failed()) return nullptr;
    const index shock = total_force(t, x.q, x.v, shk, phis, loads, sup, x.vint, work, x.f);
    acceleration(x.f, x.q, x.v, minv, stiffness, damping, diagonal(0) == 1, x.residual, x.a);
    return PyLong_FromLongLong(shock);
}

// the positions of layout.hpp, for the check against the Python side
PyObject* layout(PyObject*, PyObject*) {
    struct Entry {
        const char* name;
        long value;
    };
    static const Entry entries[] = {
        {"STATUS_DONE", STATUS_DONE}, {"STATUS_NOT_FINITE", STATUS_NOT_FINITE},
        {"STATUS_SHOCK_DIVERGED", STATUS_SHOCK_DIVERGED}, {"STATUS_FULL", STATUS_FULL},
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
        {"SELECT", SELECT}, {"IDENTITY", IDENTITY},
    };
    PyObject* dict = PyDict_New();
    if (dict == nullptr) return nullptr;
    for (const Entry& entry : entries) {
        PyObject* value = PyLong_FromLong(entry.value);
        if (value == nullptr || PyDict_SetItemString(dict, entry.name, value) != 0) {
            Py_XDECREF(value);
            Py_DECREF(dict);
            return nullptr;
        }
        Py_DECREF(value);
    }
    PyObject* reals[][2] = {
        {PyUnicode_FromString("GRID_TOLERANCE"), PyFloat_FromDouble(GRID_TOLERANCE)},
        {PyUnicode_FromString("SLIP_VELOCITY_FLOOR"), PyFloat_FromDouble(SLIP_VELOCITY_FLOOR)},
        {PyUnicode_FromString("EPS"), PyFloat_FromDouble(EPS)},
        {PyUnicode_FromString("VELOCITY_DIVERGENCE"), PyFloat_FromDouble(VELOCITY_DIVERGENCE)},
    };
    bool ok = true;
    for (auto& pair : reals) {
        ok = ok && pair[0] && pair[1] && PyDict_SetItem(dict, pair[0], pair[1]) == 0;
        Py_XDECREF(pair[0]);
        Py_XDECREF(pair[1]);
    }
    if (!ok) {
        Py_DECREF(dict);
        return nullptr;
    }
    return dict;
}

PyMethodDef methods[] = {
    {"diff_centre_loop", diff_centre_loop, METH_VARARGS,
     "DIFF_CENTRE's specialised loop on diagonal or full matrices; returns a status."},
    {"start", start, METH_VARARGS,
     "The total force and the acceleration at the start of a run; a diverging shock or -1."},
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

PyMODINIT_FUNC PyInit__loops(void) { return PyModule_Create(&asterlite::module); }
