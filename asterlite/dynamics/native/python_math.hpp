// Python's max and min of two floats as numba compiles them (the later
// argument taken only when strictly greater, resp. smaller: a NaN first
// argument is kept, a NaN second one is not).
#pragma once

#include <cmath>
#include <cstdint>

namespace asterlite {

inline double py_max(double a, double b) { return b > a ? b : a; }
inline double py_min(double a, double b) { return b < a ? b : a; }
inline double py_max(double a, double b, double c) { return py_max(py_max(a, b), c); }
inline double py_min(double a, double b, double c) { return py_min(py_min(a, b), c); }

// x ** n for a literal integer n >= 0, as numba computes it: binary powering
// from 1.0 (x ** 2 = x * x, x ** 3 = x * (x * x), x ** 4 = (x * x) * (x * x))
inline double int_power(double x, int n) {
    double r = 1.0;
    while (n != 0) {
        if (n & 1) r *= x;
        n >>= 1;
        x *= x;
    }
    return r;
}

// Python's int(round(x)): ties to even (llvm.rint), then an integer
inline std::int64_t py_round(double x) { return static_cast<std::int64_t>(std::nearbyint(x)); }

}  // namespace asterlite
