// Python's max and min of two floats as numba compiles them (the later
// argument taken only when strictly greater, resp. smaller: a NaN first
// argument is kept, a NaN second one is not).
#pragma once

namespace asterlite {

inline double py_max(double a, double b) { return b > a ? b : a; }
inline double py_min(double a, double b) { return b < a ? b : a; }
inline double py_max(double a, double b, double c) { return py_max(py_max(a, b), c); }
inline double py_min(double a, double b, double c) { return py_min(py_min(a, b), c); }

}  // namespace asterlite
