// The generalized Zener model of DIS_VISC (asterlite.dynamics.laws.zener): its
// rates, integrated by law_rk54.hpp.
#pragma once

#include <cmath>

#include "views.hpp"

namespace asterlite {
namespace zener {

enum Unknown : index { Y_FORCE, Y_EPS_VISC, Y_EPS, Y_DISSIP };
constexpr index N_Y = 4;
enum Model : index { M_S1, M_K2, M_S3, M_C, M_ALPHA };
constexpr double OVERFLOW_GUARD = 1.0e10;

// zener.zener_rates: dy = d/dt of (sigma, eps_v, eps, W); false when the
// dashpot rate would overflow (the sub-step must be cut)
inline bool zener_rates(const F1& model, const F1& y, double strain_rate, const F1& dy) {
    const double s1 = model(M_S1), k2 = model(M_K2), s3 = model(M_S3);
    const double c = model(M_C), alpha = model(M_ALPHA);
    const double x = (y(Y_FORCE) * (1.0 + k2 * s1) - k2 * y(Y_EPS)) / c;
    const double ax = std::fabs(x);
    if (ax > OVERFLOW_GUARD && std::log10(ax) > 200.0 * alpha) return false;
    double rate_visc = std::pow(ax, 1.0 / alpha);
    if (x < 0.0) rate_visc = -rate_visc;
    dy(Y_EPS) = strain_rate;
    dy(Y_EPS_VISC) = rate_visc;
    dy(Y_DISSIP) = c * std::fabs(x * rate_visc);
    dy(Y_FORCE) = ((1.0 + k2 * s3) * strain_rate - rate_visc) / (s1 + s3 + k2 * s1 * s3);
    return true;
}

}  // namespace zener
}  // namespace asterlite
