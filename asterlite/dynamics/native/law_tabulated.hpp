// Tabulated functions packed in the laws' parameter arrays
// (asterlite.dynamics.laws.tabulated): [n, prol_left, prol_right, x..., y...],
// linear interpolation, code_aster's prolongations (NaN outside an EXCLU side).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "views.hpp"

namespace asterlite {
namespace tabulated {

enum Prolongation : std::int64_t { CONSTANT, LINEAIRE, EXCLU };
constexpr index HEADER = 3;  // n, prol_left, prol_right

inline double nan() { return std::numeric_limits<double>::quiet_NaN(); }

// a[start:stop], as numba's view of a slice (bounds within the array here)
inline F1 part(const F1& a, index start, index stop) {
    F1 view;
    view.data = a.data + start;
    view.n0 = stop - start;
    return view;
}

// Python's int() of a float (truncation), as numba converts it
inline index to_int(double x) { return static_cast<index>(x); }

struct ValueSlope {
    double value, slope;
};

// tabulated.table_size
inline index table_size(const F1& table, index start) { return HEADER + 2 * to_int(table(start)); }

// tabulated.segment_of: the segment [x_i, x_i+1] holding x (bisection)
inline index segment_of(const F1& table, index start, index n, double x) {
    const index xs = start + HEADER;
    index lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        const index mid = (lo + hi) / 2;  // both >= 0: Python's // alike
        if (table(xs + mid) <= x) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

// tabulated.value_and_slope: (y(x), dy/dx); NaN outside an EXCLU side
inline ValueSlope value_and_slope(const F1& table, index start, double x) {
    const index n = to_int(table(start));
    const index xs = start + HEADER;
    const index ys = xs + n;
    if (n == 1) {
        if (x != table(xs) && ((x < table(xs) && to_int(table(start + 1)) == EXCLU) ||
                               (x > table(xs) && to_int(table(start + 2)) == EXCLU))) {
            return {nan(), nan()};
        }
        return {table(ys), 0.0};
    }
    if (x < table(xs)) {
        const index side = to_int(table(start + 1));
        if (side == EXCLU) return {nan(), nan()};
        if (side == CONSTANT) return {table(ys), 0.0};
    } else if (x > table(xs + n - 1)) {
        const index side = to_int(table(start + 2));
        if (side == EXCLU) return {nan(), nan()};
        if (side == CONSTANT) return {table(ys + n - 1), 0.0};
    }
    const index i = segment_of(table, start, n, x);
    const double x0 = table(xs + i), x1 = table(xs + i + 1);
    const double y0 = table(ys + i), y1 = table(ys + i + 1);
    const double slope = (y1 - y0) / (x1 - x0);
    return {y0 + slope * (x - x0), slope};
}

// tabulated.value: y(x) (NaN outside an EXCLU side)
inline double value(const F1& table, index start, double x) {
    return value_and_slope(table, start, x).value;
}

}  // namespace tabulated
}  // namespace asterlite
