// CHOC_ELAS_TRAC (asterlite.dynamics.laws.choc_elas_trac): a nonlinear elastic
// shock along the axis of two nodes, its force read on the user's curve.
#pragma once

#include "law_tabulated.hpp"
#include "views.hpp"

namespace asterlite {
namespace choc_elas_trac {

constexpr index P_REST = 0;  // L0 - d1 - d2
constexpr index P_FX = 1;    // packed force curve f(crushing)
constexpr index V_FORCE = 0, V_LENGTH = 1, V_LOC1 = 2, V_LOC2 = 5;

// choc_elas_trac.elastic_shock_force: the axial force on node 1 (-F in contact)
inline double elastic_shock_force(const F1& params, double axial_elongation,
                                  const F1& state_out) {
    const double length = params(P_REST) + axial_elongation;
    double force = 0.0;
    if (length <= 0.0) force = tabulated::value(params, P_FX, -length);
    state_out(V_FORCE) = force;
    state_out(V_LENGTH) = length;
    return -force;
}

}  // namespace choc_elas_trac
}  // namespace asterlite
