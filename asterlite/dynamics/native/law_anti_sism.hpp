// ANTI_SISM (asterlite.dynamics.laws.anti_sism): code_aster's seismic stop
// device (mdfdas), a saturating elastic law and a power-law viscous term.
#pragma once

#include <cfloat>
#include <cmath>

#include "views.hpp"

namespace asterlite {
namespace anti_sism {

enum Param : index { P_K1, P_K2, P_SEUIL_FX, P_C, P_ALPHA, P_DX_MAX };
constexpr index V_FORCE = 0, V_LOC1 = 1, V_LOC2 = 4, V_VN = 7;
constexpr double VELOCITY_FLOOR = DBL_EPSILON;  // code_aster's r8prem

// anti_sism.antiseismic_force: the force on node 1 along the connection normal
inline double antiseismic_force(const F1& params, double d, double v) {
    const double k1 = params(P_K1), k2 = params(P_K2);
    const double seuil = params(P_SEUIL_FX);
    double f;
    if (seuil != 0.0) {
        const double r = k1 * d / seuil;  // (k1 d / f_s) ** 2 with a literal 2: r * r
        f = -k2 * d - (k1 - k2) * d / std::sqrt(1.0 + r * r);
    } else {
        f = -k2 * d;
    }
    if (std::fabs(v) >= VELOCITY_FLOOR) {
        f -= params(P_C) * (v >= 0.0 ? 1.0 : -1.0) *
             std::pow(std::fabs(v * d / params(P_DX_MAX)), params(P_ALPHA));
    }
    return f;
}

}  // namespace anti_sism
}  // namespace asterlite
