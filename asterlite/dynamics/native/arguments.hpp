// Reading the loops' arguments from Python: numpy arrays checked for their
// type, dimensions and writability, and the bundles every loop receives
// (asterlite.dynamics.native.bundle_arguments writes them in this order).
#pragma once

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <cstring>
#include <initializer_list>
#include <vector>

#include "clock.hpp"
#include "energy.hpp"
#include "laws.hpp"
#include "model.hpp"

namespace asterlite {

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

inline Tables read_tables(Arguments& in, const char* abscissas, const char* ordinates,
                          const char* layout, const char* pending, const char* cursors) {
    Tables tab;
    tab.abscissas = in.f2(abscissas);
    tab.ordinates = in.f2(ordinates);
    tab.layout = in.i2(layout);
    tab.pending = in.i1(pending);
    tab.cursors = in.i1(cursors, WRITE);
    return tab;
}

// The model: the linear bundle (M^-1, K, C, diagonal flag), the shocks
// (flags, params, rots, phis, polars, laws, rphis, law scratch), the loads
// (vectors, 5 table arrays, codes, constants, stack), the support motions
// (shapes, 5 table arrays), whether the shocks are taken in their local
// frames, and those frames (shapes, rest, drive; empty otherwise): 31 arrays.
inline Model read_model(Arguments& in) {
    Model model;
    model.lin.minv = in.f2("minv");
    model.lin.stiffness = in.f2("stiffness");
    model.lin.damping = in.f2("damping");
    I1 diagonal = in.i1("diagonal");
    model.lin.diagonal = diagonal.data != nullptr && diagonal.n0 == 1 && diagonal(0) == 1;
    model.shk.flags = in.i2("shock_flags");
    model.shk.params = in.f2("shock_params", WRITE);
    model.shk.rots = in.f3("shock_rots");
    model.shk.phis = in.f4("shock_phis");
    model.shk.polars = in.f3("shock_polars");
    model.shk.laws = in.f2("shock_laws");
    model.shk.rphis = in.f4("shock_rphis");
    model.shk.law_scratch = in.f2("law_scratch", WRITE);
    model.loads.vectors = in.f2("load_vectors");
    model.loads.tables = read_tables(in, "load_abscissas", "load_ordinates", "load_layout",
                                     "load_pending", "load_cursors");
    model.loads.codes = in.i2("load_codes");
    model.loads.constants = in.f2("load_constants");
    model.loads.stack = in.f1("load_stack", WRITE);
    model.sup.shapes = in.f4("support_shapes");
    model.sup.tables = read_tables(in, "support_abscissas", "support_ordinates",
                                   "support_layout", "support_pending", "support_cursors");
    I1 local_frames = in.i1("local_frames");
    model.local_frames =
        local_frames.data != nullptr && local_frames.n0 == 1 && local_frames(0) == 1;
    model.local.shapes = in.f4("local_shapes");
    model.local.rest = in.f3("local_rest");
    model.local.drive = in.f3("local_drive", WRITE);
    return model;
}

// layouts.State: q, v, a, f, vint, vint_save, work
inline State read_state(Arguments& in) {
    State x;
    x.q = in.f1("q", WRITE);
    x.v = in.f1("v", WRITE);
    x.a = in.f1("a", WRITE);
    x.f = in.f1("f", WRITE);
    x.vint = in.f2("vint", WRITE);
    x.vint_save = in.f2("vint_save", WRITE);
    x.work = in.f2("work", WRITE);
    return x;
}

// a scheme's memory: rows, scalars, table
inline Memory read_memory(Arguments& in) {
    Memory memory;
    memory.rows = in.f2("rows", WRITE);
    memory.scalars = in.f1("scalars", WRITE);
    memory.table = in.f2("table");
    return memory;
}

// clock, counters, instants (the first three arguments of a loop)
inline Clock read_clock(Arguments& in) {
    Clock c;
    c.clock = in.f1("clock", WRITE);
    c.counters = in.i1("counters", WRITE);
    c.instants = in.f1("instants");
    return c;
}

// layouts.Archive: times, order, q, v, a, vint, info
inline ArchiveBuffers read_archive(Arguments& in) {
    ArchiveBuffers out;
    out.t = in.f1("out_t", WRITE);
    out.order = in.i1("out_order", WRITE);
    out.q = in.f2("out_q", WRITE);
    out.v = in.f2("out_v", WRITE);
    out.a = in.f2("out_a", WRITE);
    out.vint = in.f3("out_vint", WRITE);
    out.info = in.f2("out_info", WRITE);
    return out;
}

// layouts.Balance: acc, matrices, vectors, vint_copy, work, rows, local (the
// energy balance; empty arrays and acc[A_ON] = 0 when it is not asked)
inline energy::Balance read_balance(Arguments& in) {
    energy::Balance balance;
    balance.acc = in.f1("energy_acc", WRITE);
    balance.matrices = in.f3("energy_matrices");
    balance.vectors = in.f2("energy_vectors", WRITE);
    balance.vint_copy = in.f2("energy_vint_copy", WRITE);
    balance.work = in.f2("energy_work", WRITE);
    balance.rows = in.f2("energy_rows", WRITE);
    balance.local = in.f3("energy_local", WRITE);
    return balance;
}

// an active balance's arrays against the state and the archive's capacity
inline void check_balance(Arguments& in, const energy::Balance& balance, const State& x,
                          index capacity) {
    if (in.failed()) return;
    in.require(balance.acc.n0 > energy::A_E_TAN0, "energy accumulators");
    if (in.failed() || !balance.active()) return;
    const index n = x.q.n0, ns = x.vint.n0;
    in.require(balance.matrices.n0 == 3 && balance.matrices.n1 == n && balance.matrices.n2 == n,
               "energy matrices");
    in.require(balance.vectors.n0 >= 3 && balance.vectors.n1 == n, "energy vectors");
    in.require(balance.vint_copy.n0 == ns && balance.vint_copy.n1 == x.vint.n1,
               "energy internal variables");
    in.require(balance.work.n0 >= 5 && balance.work.n1 >= 3, "energy work");
    in.require(balance.rows.n0 >= capacity && balance.rows.n1 > energy::C_RESIDU, "energy rows");
    in.require(balance.local.n0 == 2 && balance.local.n1 == ns &&
                   balance.local.n2 > energy::L_DRIVE,
               "energy shock quantities");
}

// what the loads' evaluation relies on, for n modes
inline void check_loads(Arguments& in, const Loads& loads, index n) {
    in.require(loads.vectors.n1 == n || loads.vectors.n0 == 0, "load vectors");
    in.require(loads.tables.layout.n0 >= loads.vectors.n0, "load layout");
    in.require(loads.codes.n0 >= loads.vectors.n0 && loads.constants.n0 >= loads.vectors.n0,
               "load programs");
    in.require(loads.stack.n0 >= 32, "formula stack");
}

// what every loop relies on in the state and the model; ``implicit``: the
// loop of the implicit treatment, the only one reading the shocks' treatment
// flags (the others refuse a shock whose normal is not explicit)
inline void check_model(Arguments& in, const State& x, const Model& model, bool implicit = false) {
    if (in.failed()) return;
    const index n = x.q.n0;
    const Shocks& shk = model.shk;
    const index ns = shk.flags.n0;
    in.require(x.v.n0 == n && x.a.n0 == n && x.f.n0 == n, "state vectors");
    in.require(x.vint.n0 == ns && x.vint.n1 > V_VT_OLD + 1, "internal variables");
    in.require(x.vint_save.n0 == ns && x.vint_save.n1 == x.vint.n1, "saved internal variables");
    in.require(x.work.n0 >= 5 && x.work.n1 >= 3, "work");
    const Linear& lin = model.lin;
    in.require(lin.minv.n0 == n && lin.minv.n1 == n && lin.stiffness.n0 == n &&
                   lin.stiffness.n1 == n && lin.damping.n0 == n && lin.damping.n1 == n,
               "matrices");
    in.require(shk.flags.n1 > F_LAW, "shock flags without their law column");
    for (index s = 0; s < ns && !in.failed(); ++s) {
        const std::int64_t law = shk.flags(s, F_LAW);
        // the relations of laws/ run on the general model only (laws.kernel)
        in.require(law == 0 || (!model.local_frames && law > 0 && law <= laws::LAST_CODE),
                   "a relation the loop does not evaluate");
        if (shk.flags.n1 > F_IMPLICIT) {
            const std::int64_t mode = shk.flags(s, F_IMPLICIT);
            in.require(implicit ? mode >= NORMAL_EXPLICIT && mode <= NORMAL_LEFT_OUT
                                : mode == NORMAL_EXPLICIT,
                       "a shock of the implicit treatment");
        }
        in.require(shk.flags(s, F_NPOLAR) <= shk.polars.n1, "polar facets");
    }
    in.require(shk.params.n0 == ns && shk.params.n1 > P_DRIVE2 + 5, "shock parameters");
    in.require(shk.rots.n0 == ns && shk.rots.n1 == 3 && shk.rots.n2 == 3, "shock frames");
    in.require(shk.phis.n0 == ns && shk.phis.n1 == 2 && shk.phis.n2 == 3 && shk.phis.n3 == n,
               "mode shapes");
    in.require(shk.polars.n0 >= ns || ns == 0, "shock polars");
    in.require(shk.laws.n0 == ns, "law parameters");
    in.require(shk.rphis.n0 == ns && shk.rphis.n1 == 2 && shk.rphis.n2 == 3 &&
                   (shk.rphis.n3 == n || shk.rphis.n3 == 0),
               "rotation shapes");
    in.require(shk.laws.n1 == 0 || (shk.law_scratch.n0 >= laws::SCRATCH_ROWS &&
                                    shk.law_scratch.n1 >= laws::SCRATCH_COLS),
               "law scratch");
    check_loads(in, model.loads, n);
    const Supports& sup = model.sup;
    in.require(sup.shapes.n3 == 0 || (sup.shapes.n0 == ns && sup.shapes.n1 == 2 &&
                                       sup.shapes.n2 == 3 &&
                                       sup.tables.layout.n0 >= 2 * sup.shapes.n3),
               "support motions");
    if (!model.local_frames) return;
    const Local& local = model.local;
    in.require(local.shapes.n0 == ns && local.shapes.n1 == 2 && local.shapes.n2 == 3 &&
                   local.shapes.n3 == n,
               "local shapes");
    in.require(local.rest.n0 == ns && local.rest.n1 == 2 && local.rest.n2 == 3, "rest positions");
    in.require(local.drive.n0 == ns && local.drive.n1 == 2 && local.drive.n2 == 6, "drive");
}

inline void check_loop(Arguments& in, const Clock& c, const State& x, const ArchiveBuffers& out) {
    if (in.failed()) return;
    const index n = x.q.n0;
    in.require(c.clock.n0 > C_ORIGIN && c.counters.n0 > K_GRID, "clock and counters");
    in.require(c.pas_arch >= 1, "pas_arch below 1");
    in.require(c.counters(K_INSTANT) >= 0 && c.counters(K_ARCHIVED) >= 0, "counters");
    const index cap = out.t.n0;
    in.require(out.order.n0 == cap && out.q.n0 == cap && out.v.n0 == cap && out.a.n0 == cap &&
                   out.vint.n0 == cap && out.info.n0 == cap,
               "archive rows");
    in.require(out.q.n1 == n && out.v.n1 == n && out.a.n1 == n && out.info.n1 > INFO_REJECTED,
               "archive columns");
    in.require(out.vint.n1 == x.vint.n0 && out.vint.n2 == x.vint.n1, "archived internal variables");
}

// A dict of named constants for Python (the ``layout()``/``constants()`` a
// module reports, checked against the Python side's values)
struct IntegerConstant {
    const char* name;
    long long value;
};
struct RealConstant {
    const char* name;
    double value;
};

inline PyObject* constants_dict(std::initializer_list<IntegerConstant> integers,
                                std::initializer_list<RealConstant> reals) {
    PyObject* dict = PyDict_New();
    if (dict == nullptr) return nullptr;
    bool ok = true;
    for (const IntegerConstant& entry : integers) {
        PyObject* value = PyLong_FromLongLong(entry.value);
        ok = ok && value != nullptr && PyDict_SetItemString(dict, entry.name, value) == 0;
        Py_XDECREF(value);
    }
    for (const RealConstant& entry : reals) {
        PyObject* value = PyFloat_FromDouble(entry.value);
        ok = ok && value != nullptr && PyDict_SetItemString(dict, entry.name, value) == 0;
        Py_XDECREF(value);
    }
    if (!ok) {
        Py_DECREF(dict);
        return nullptr;
    }
    return dict;
}

}  // namespace asterlite
