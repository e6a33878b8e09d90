// The discrete element with isotropic or kinematic hardening of DIS_ECRO_TRAC
// (asterlite.dynamics.laws.discrete_hardening, code_aster's disc_isotr): its
// rates, integrated by law_rk54.hpp.
#pragma once

#include <cmath>
#include <limits>

#include "law_tabulated.hpp"
#include "views.hpp"

namespace asterlite {
namespace discrete_hardening {

constexpr index Y_F = 0, Y_U = 3, Y_W = 6, Y_P = 7, Y_UP = 8, Y_X = 11;
constexpr index N_Y = 14;
constexpr index C_KINEMATIC = 0, C_FX0 = 1, C_DX0 = 2, C_N = 3, C_POINTS = 4;

struct Threshold {
    double radius, slope;
};

// discrete_hardening.threshold: (R(p), R'(p)) on the curve against the plastic
// displacement; NaN beyond the last point
inline Threshold threshold(const F1& curve, double p) {
    const index n = tabulated::to_int(curve(C_N));
    const index xs = C_POINTS;
    const index ys = C_POINTS + n;
    const double k = curve(ys + 1) / curve(xs + 1);
    for (index i = 2; i < n; ++i) {
        if (p < curve(xs + i) - curve(ys + i) / k) {
            const double f0 = curve(ys + i - 1), f1 = curve(ys + i);
            const double p0 = curve(xs + i - 1) - f0 / k;
            const double p1 = curve(xs + i) - f1 / k;
            const double slope = (f1 - f0) / (p1 - p0);
            return {f0 + slope * (p - p0), slope};
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan};
}

// discrete_hardening.hardening_rates: dy = d/dt of the 14 unknowns for the
// imposed displacement rates; false when the curve is exhausted
inline bool hardening_rates(const F1& curve, const F1& y, const F1& rate, const F1& dy) {
    const double k = curve(C_FX0) / curve(C_DX0);
    const bool kinematic = curve(C_KINEMATIC) == 1.0;
    double radius, hardening;
    if (kinematic) {
        const Threshold th = threshold(curve, 0.0);
        hardening = th.slope;
        radius = curve(C_FX0);
    } else {
        const Threshold th = threshold(curve, y(Y_P));
        radius = th.radius;
        hardening = th.slope;
    }
    if (std::isnan(radius)) return false;
    const double fx = y(Y_F) - y(Y_X);
    const double fy = y(Y_F + 1) - y(Y_X + 1);
    const double fz = y(Y_F + 2) - y(Y_X + 2);
    const double feq = std::sqrt(fx * fx + fy * fy + fz * fz);
    for (index i = 0; i < N_Y; ++i) dy(i) = 0.0;
    for (index i = 0; i < 3; ++i) dy(Y_U + i) = rate(i);
    if (feq - radius > 0.0) {
        const double loading = fx * rate(0) + fy * rate(1) + fz * rate(2);
        if (loading > 0.0) {
            const double dp = k * loading / (feq * (k + hardening));
            dy(Y_P) = dp;
            dy(Y_UP) = dp * fx / feq;
            dy(Y_UP + 1) = dp * fy / feq;
            dy(Y_UP + 2) = dp * fz / feq;
            if (kinematic) {
                for (index i = 0; i < 3; ++i) dy(Y_X + i) = hardening * dy(Y_UP + i);
            }
        }
    }
    for (index i = 0; i < 3; ++i) dy(Y_F + i) = k * (dy(Y_U + i) - dy(Y_UP + i));
    dy(Y_W) = dy(Y_P) * feq;
    return true;
}

}  // namespace discrete_hardening
}  // namespace asterlite
