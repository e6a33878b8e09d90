// The Python module asterlite.dynamics.native._ldl: the harmonic sweep's
// sparse LDLᵀ kernels (ldl.hpp) on numpy arrays, with the arguments and
// returns of asterlite/harmonic/ldl.py's numba kernels (_symbolic, _numeric,
// _solve). Index arrays int32 or int64 each (numba compiles any mix), values
// complex128, all 1-D and C-ordered; the sizes and indices the loops rely on
// are checked before they run (the arrays of one analysis always pass).
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "ldl.hpp"

namespace asterlite {
namespace {

using ldl::C1;
using ldl::Complex;

// a 1-D integer array of either width
struct Indices {
    void* data = nullptr;
    index size = 0;
    bool wide = false;  // int64, else int32

    template <class T>
    View1<T> view() const {
        View1<T> v;
        v.data = static_cast<T*>(data);
        v.n0 = size;
        return v;
    }
    std::int64_t operator[](index i) const {
        return wide ? static_cast<std::int64_t*>(data)[i] : static_cast<std::int32_t*>(data)[i];
    }
};

// ``body(view)`` on the array as a View1 of its own index type
template <class Body>
auto with_view(const Indices& a, Body&& body) {
    return a.wide ? body(a.view<std::int64_t>()) : body(a.view<std::int32_t>());
}

// The function's arguments read in order: 1-D C-ordered arrays checked for
// their type and writability (held until the call returns), integers.
class Reader {
  public:
    Reader(PyObject* args, const char* function) : args_(args), function_(function) {}
    ~Reader() {
        for (Py_buffer& buffer : held_) PyBuffer_Release(&buffer);
    }
    bool failed() const { return failed_; }

    Indices indices(const char* name, bool writable = false) {
        Indices out;
        const Py_buffer* buffer = array(name, writable);
        if (buffer == nullptr) return out;
        const char* format = skip_order(buffer->format);
        const bool integer = std::strcmp(format, "i") == 0 || std::strcmp(format, "l") == 0 ||
                             std::strcmp(format, "q") == 0;
        if (!integer || (buffer->itemsize != 4 && buffer->itemsize != 8)) {
            fail(name, "an int32 or int64 array");
            return out;
        }
        out.data = buffer->buf;
        out.size = buffer->shape[0];
        out.wide = buffer->itemsize == 8;
        return out;
    }
    C1 complex(const char* name, bool writable = false) {
        C1 out;
        const Py_buffer* buffer = array(name, writable);
        if (buffer == nullptr) return out;
        if (std::strcmp(skip_order(buffer->format), "Zd") != 0 || buffer->itemsize != 16) {
            fail(name, "a complex128 array");
            return out;
        }
        out.data = static_cast<Complex*>(buffer->buf);
        out.n0 = buffer->shape[0];
        return out;
    }
    std::int64_t integer(const char* name) {
        PyObject* item = next(name);
        if (item == nullptr) return 0;
        const long long value = PyLong_AsLongLong(item);
        if (value == -1 && PyErr_Occurred()) failed_ = true;  // TypeError, OverflowError
        return value;
    }
    // a relation the loops rely on between the arguments
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
    static const char* skip_order(const char* format) {
        if (format == nullptr) return "B";
        if (*format == '<' || *format == '=' || *format == '@') ++format;
        return format;
    }
    PyObject* next(const char* name) {
        if (failed_) return nullptr;
        if (position_ >= PyTuple_GET_SIZE(args_)) {
            PyErr_Format(PyExc_TypeError, "%s: argument %s missing", function_, name);
            failed_ = true;
            return nullptr;
        }
        return PyTuple_GET_ITEM(args_, position_++);
    }
    const Py_buffer* array(const char* name, bool writable) {
        PyObject* item = next(name);
        if (item == nullptr) return nullptr;
        Py_buffer buffer;
        const int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
        if (PyObject_GetBuffer(item, &buffer, flags) != 0) {
            PyErr_Clear();
            fail(name, writable ? "a writable C-ordered array" : "a C-ordered array");
            return nullptr;
        }
        held_.push_back(buffer);
        if (buffer.ndim != 1) {
            fail(name, "a 1-D array");
            return nullptr;
        }
        return &held_.back();
    }
    void fail(const char* name, const char* expected) {
        if (!failed_) {
            PyErr_Format(PyExc_TypeError, "%s: argument %s must be %s", function_, name, expected);
            failed_ = true;
        }
    }

    PyObject* args_;
    const char* function_;
    Py_ssize_t position_ = 0;
    std::vector<Py_buffer> held_;
    bool failed_ = false;
};

// a CSC column pointer of n columns: nondecreasing from 0 or more, within
// ``size`` entries
bool pointers_within(const Indices& ptr, index n, index size) {
    if (ptr.size < n + 1 || ptr[0] < 0 || ptr[n] > size) return false;
    for (index k = 0; k < n; ++k) {
        if (ptr[k + 1] < ptr[k]) return false;
    }
    return true;
}

// the entries ptr[0]..ptr[n] of ``rows`` in [0, n)
bool rows_within(const Indices& ptr, const Indices& rows, index n) {
    return with_view(rows, [&](auto view) {
        for (index p = ptr[0]; p < ptr[n]; ++p) {
            if (view(p) < 0 || view(p) >= n) return false;
        }
        return true;
    });
}

// the status of numeric and solve for Python
bool raised(index status) {
    if (status == ldl::ZERO_DIVISION) {
        PyErr_SetString(PyExc_ZeroDivisionError, "complex division by zero");
        return true;
    }
    if (status == ldl::INCONSISTENT) {
        PyErr_SetString(PyExc_ValueError,
                        "numeric: parent and lp are not the analysis of this pattern");
        return true;
    }
    return false;
}

// a new 1-D numpy array of n int64 (numpy.empty)
PyObject* new_int64_array(index n) {
    PyObject* numpy = PyImport_ImportModule("numpy");
    if (numpy == nullptr) return nullptr;
    PyObject* result = PyObject_CallMethod(numpy, "empty", "ns", static_cast<Py_ssize_t>(n),
                                           "int64");
    Py_DECREF(numpy);
    return result;
}

// a writable int64 view of an array just made
bool int64_view(PyObject* array, I1& view, Py_buffer& buffer) {
    if (PyObject_GetBuffer(array, &buffer, PyBUF_C_CONTIGUOUS | PyBUF_WRITABLE) != 0) return false;
    view.data = static_cast<std::int64_t*>(buffer.buf);
    view.n0 = buffer.shape ? buffer.shape[0] : buffer.len / 8;
    return true;
}

// _symbolic(n, ap, ai, limit) -> (parent, lnz, total)
PyObject* symbolic(PyObject*, PyObject* args) {
    Reader in(args, "symbolic");
    const index n = in.integer("n");
    const Indices ap = in.indices("ap");
    const Indices ai = in.indices("ai");
    const std::int64_t limit = in.integer("limit");
    if (!in.complete()) return nullptr;
    in.require(n >= 0, "n");
    in.require(in.failed() || pointers_within(ap, n, ai.size), "ap");
    in.require(in.failed() || rows_within(ap, ai, n), "ai");
    if (in.failed()) return nullptr;
    PyObject* parent = new_int64_array(n);
    PyObject* lnz = parent ? new_int64_array(n) : nullptr;
    if (lnz == nullptr) {
        Py_XDECREF(parent);
        return nullptr;
    }
    I1 parent_view, lnz_view;
    Py_buffer parent_buffer, lnz_buffer;
    if (!int64_view(parent, parent_view, parent_buffer)) {
        Py_DECREF(parent);
        Py_DECREF(lnz);
        return nullptr;
    }
    if (!int64_view(lnz, lnz_view, lnz_buffer)) {
        PyBuffer_Release(&parent_buffer);
        Py_DECREF(parent);
        Py_DECREF(lnz);
        return nullptr;
    }
    index total;
    Py_BEGIN_ALLOW_THREADS
    total = with_view(ap, [&](auto p) {
        return with_view(ai, [&](auto i) {
            return ldl::symbolic(n, p, i, limit, parent_view, lnz_view);
        });
    });
    Py_END_ALLOW_THREADS
    PyBuffer_Release(&parent_buffer);
    PyBuffer_Release(&lnz_buffer);
    return Py_BuildValue("(NNL)", parent, lnz, static_cast<long long>(total));
}

// _numeric(n, ap, ai, ax, lp, parent, li, lx, d) -> -1 or the column of a
// zero pivot (li, lx, d written)
PyObject* numeric(PyObject*, PyObject* args) {
    Reader in(args, "numeric");
    const index n = in.integer("n");
    const Indices ap = in.indices("ap");
    const Indices ai = in.indices("ai");
    const C1 ax = in.complex("ax");
    const Indices lp = in.indices("lp");
    const Indices parent = in.indices("parent");
    const Indices li = in.indices("li", true);
    const C1 lx = in.complex("lx", true);
    const C1 d = in.complex("d", true);
    if (!in.complete()) return nullptr;
    in.require(n >= 0, "n");
    in.require(in.failed() || pointers_within(ap, n, std::min(ai.size, ax.n0)), "ap");
    in.require(in.failed() || rows_within(ap, ai, n), "ai");
    in.require(in.failed() || pointers_within(lp, n, std::min(li.size, lx.n0)), "lp");
    in.require(parent.size >= n && d.n0 >= n, "parent, d");
    if (in.failed()) return nullptr;
    index status;
    Py_BEGIN_ALLOW_THREADS
    status = with_view(ap, [&](auto vap) {
        return with_view(ai, [&](auto vai) {
            return with_view(lp, [&](auto vlp) {
                return with_view(parent, [&](auto vparent) {
                    return with_view(li, [&](auto vli) {
                        return ldl::numeric(n, vap, vai, ax, vlp, vparent, vli, lx, d);
                    });
                });
            });
        });
    });
    Py_END_ALLOW_THREADS
    if (raised(status)) return nullptr;
    return PyLong_FromLongLong(status);
}

// _solve(n, lp, li, lx, d, x) -> None (x solved in place)
PyObject* solve(PyObject*, PyObject* args) {
    Reader in(args, "solve");
    const index n = in.integer("n");
    const Indices lp = in.indices("lp");
    const Indices li = in.indices("li");
    const C1 lx = in.complex("lx");
    const C1 d = in.complex("d");
    const C1 x = in.complex("x", true);
    if (!in.complete()) return nullptr;
    in.require(n >= 0, "n");
    in.require(in.failed() || pointers_within(lp, n, std::min(li.size, lx.n0)), "lp");
    in.require(in.failed() || rows_within(lp, li, n), "li");
    in.require(d.n0 >= n && x.n0 >= n, "d, x");
    if (in.failed()) return nullptr;
    index status;
    Py_BEGIN_ALLOW_THREADS
    status = with_view(lp, [&](auto vlp) {
        return with_view(li, [&](auto vli) { return ldl::solve(n, vlp, vli, lx, d, x); });
    });
    Py_END_ALLOW_THREADS
    if (raised(status)) return nullptr;
    Py_RETURN_NONE;
}

PyMethodDef methods[] = {
    {"symbolic", symbolic, METH_VARARGS,
     "symbolic(n, ap, ai, limit) -> (parent, lnz, total): harmonic.ldl._symbolic"},
    {"numeric", numeric, METH_VARARGS,
     "numeric(n, ap, ai, ax, lp, parent, li, lx, d) -> -1 or a zero pivot's column: "
     "harmonic.ldl._numeric"},
    {"solve", solve, METH_VARARGS, "solve(n, lp, li, lx, d, x): harmonic.ldl._solve, in place"},
    {nullptr, nullptr, 0, nullptr},
};

PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_ldl", "Sparse LDLᵀ kernels of asterlite.harmonic.ldl", -1,
    methods, nullptr, nullptr, nullptr, nullptr,
};

}  // namespace
}  // namespace asterlite

PyMODINIT_FUNC PyInit__ldl() { return PyModule_Create(&asterlite::module); }
