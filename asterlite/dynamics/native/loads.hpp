// Loads and support motions (asterlite.dynamics.forces): tabulated
// multipliers searched from their last interval, formula programs, the
// support motion of each shock node.
#pragma once

#include "formula.hpp"
#include "layout.hpp"
#include "views.hpp"

namespace asterlite {

// The tabulated arrays of the loads or of the support motions.
struct Tables {
    F2 abscissas, ordinates;
    I2 layout;   // (count, left, right) per row
    I1 pending;  // 1: more samples follow the row's window
    I1 cursors;  // the interval found last, per row
};

// the lo with x[lo] <= t < x[lo + 1], knowing x[lo] <= t < x[hi]
inline index bisect_interval(const F2& abscissas, index row, index lo, index hi, double t) {
    while (hi - lo > 1) {
        const index mid = (lo + hi) / 2;
        if (abscissas(row, mid) <= t) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

// forces.multiplier_at: the piecewise-linear multiplier of row ``row`` at t
inline double multiplier_at(const Tables& tab, index row, double t) {
    const F2& x = tab.abscissas;
    const F2& y = tab.ordinates;
    const index count = tab.layout(row, 0), left = tab.layout(row, 1), right = tab.layout(row, 2);
    if (count == 1) return y(row, 0);
    const index last = count - 1;
    if (t <= x(row, 0)) {
        if (left == 1 && t < x(row, 0)) {
            return y(row, 0) + (t - x(row, 0)) * (y(row, 1) - y(row, 0)) / (x(row, 1) - x(row, 0));
        }
        return y(row, 0);
    }
    if (t >= x(row, last)) {
        if (right == 1 && t > x(row, last)) {
            const double slope = (y(row, last) - y(row, last - 1)) / (x(row, last) - x(row, last - 1));
            return y(row, last) + (t - x(row, last)) * slope;
        }
        return y(row, last);
    }
    index lo = tab.cursors(row);
    if (lo < 0 || lo >= last) lo = 0;
    if (x(row, lo) <= t) {
        if (x(row, lo + 1) <= t) {  // forward: a few steps, then bisection
            lo += 1;
            int steps = 0;
            while (x(row, lo + 1) <= t && steps < 8) {
                lo += 1;
                steps += 1;
            }
            if (x(row, lo + 1) <= t) lo = bisect_interval(x, row, lo, last, t);
        }
    } else {
        lo = bisect_interval(x, row, 0, lo, t);
    }
    tab.cursors(row) = lo;
    const index hi = lo + 1;
    const double width = x(row, hi) - x(row, lo);
    if (width == 0.0) return y(row, hi);
    return y(row, lo) + (t - x(row, lo)) * (y(row, hi) - y(row, lo)) / width;
}

// forces.loads_cover: every windowed row tabulated beyond t_next
inline bool loads_cover(double t_next, const Tables& tab) {
    for (index e = 0; e < tab.pending.n0; ++e) {
        if (tab.pending(e) == 1 && !(t_next < tab.abscissas(e, tab.layout(e, 0) - 1))) return false;
    }
    return true;
}

struct Loads {
    F2 vectors;  // (n_loads, n_modes)
    Tables tables;
    I2 codes;  // formula programs (formula.program_tables)
    F2 constants;
    F1 stack;
};

// forces.add_external_force: out += sum_e f_e(t) vector_e, formula rows run
// by run_program
inline void add_external_force(double t, const Loads& loads, const F1& out) {
    for (index e = 0; e < loads.vectors.n0; ++e) {
        double c;
        if (loads.codes(e, 0) > 0) {
            c = run_program(loads.codes, loads.constants, e, t, loads.stack);
        } else {
            c = multiplier_at(loads.tables, e, t);
        }
        for (index m = 0; m < out.n0; ++m) out(m) += c * loads.vectors(e, m);
    }
}

// scheme_diff_centre.external_force_into: the same sum into a zeroed out,
// the zeroing folded into the first load's pass (0.0 + x), formula rows run
// by program_value
inline void external_force_into(double t, const Loads& loads, const F1& out) {
    const index n_loads = loads.vectors.n0;
    for (index e = 0; e < n_loads; ++e) {
        double c;
        if (loads.codes(e, 0) > 0) {
            c = program_value(loads.codes, loads.constants, e, t, loads.stack);
        } else {
            c = multiplier_at(loads.tables, e, t);
        }
        if (e == 0) {
            for (index m = 0; m < out.n0; ++m) out(m) = 0.0 + c * loads.vectors(0, m);
        } else {
            for (index m = 0; m < out.n0; ++m) out(m) += c * loads.vectors(e, m);
        }
    }
    if (n_loads == 0) {
        for (index m = 0; m < out.n0; ++m) out(m) = 0.0;
    }
}

struct Supports {
    F4 shapes;  // (n_shocks, 2, 3, n_supports)
    Tables tables;  // rows 2k, 2k + 1: displacement and velocity of support k
};

// forces.support_values: (displacement, velocity) of support k at t
inline void support_values(double t, index k, const Supports& sup, double& d, double& w) {
    d = multiplier_at(sup.tables, 2 * k, t);
    w = multiplier_at(sup.tables, 2 * k + 1, t);
}

// forces.support_motion: each shock node's support motion into its drive
// slots of params (global frame)
inline void support_motion(double t, const Supports& sup, const F2& params) {
    const index n_supports = sup.shapes.n3;
    if (n_supports == 0) return;
    for (index s = 0; s < sup.shapes.n0; ++s) {
        for (index node = 0; node < 2; ++node) {
            const index base = node == 0 ? P_DRIVE1 : P_DRIVE2;
            for (index i = 0; i < 6; ++i) params(s, base + i) = 0.0;
            for (index k = 0; k < n_supports; ++k) {
                double d, w;
                support_values(t, k, sup, d, w);
                for (index i = 0; i < 3; ++i) {
                    params(s, base + i) += sup.shapes(s, node, i, k) * d;
                    params(s, base + 3 + i) += sup.shapes(s, node, i, k) * w;
                }
            }
        }
    }
}

// forces.local_support_motion: the same sums, rotated into each shock's frame
inline void local_support_motion(double t, const F3& rots, const Supports& sup, const F3& drive) {
    const index n_supports = sup.shapes.n3;
    if (n_supports == 0) return;
    for (index s = 0; s < sup.shapes.n0; ++s) {
        for (index node = 0; node < 2; ++node) {
            double dx = 0.0, dy = 0.0, dz = 0.0, wx = 0.0, wy = 0.0, wz = 0.0;
            for (index k = 0; k < n_supports; ++k) {
                double d, w;
                support_values(t, k, sup, d, w);
                dx += sup.shapes(s, node, 0, k) * d;
                dy += sup.shapes(s, node, 1, k) * d;
                dz += sup.shapes(s, node, 2, k) * d;
                wx += sup.shapes(s, node, 0, k) * w;
                wy += sup.shapes(s, node, 1, k) * w;
                wz += sup.shapes(s, node, 2, k) * w;
            }
            for (index i = 0; i < 3; ++i) {
                drive(s, node, i) = rots(s, i, 0) * dx + rots(s, i, 1) * dy + rots(s, i, 2) * dz;
                drive(s, node, 3 + i) = rots(s, i, 0) * wx + rots(s, i, 1) * wy + rots(s, i, 2) * wz;
            }
        }
    }
}

}  // namespace asterlite
