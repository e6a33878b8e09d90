// RELA_EFFO_DEPL / RELA_EFFO_VITE (asterlite.dynamics.laws.rela_effo_depl; rela_effo_vite
// shares its law): a nodal force F(u) (or F(v)) on one component of a node.
#pragma once

#include <cfloat>
#include <cmath>

#include "law_tabulated.hpp"
#include "views.hpp"

namespace asterlite {
namespace rela_effo_depl {

constexpr index P_COMPONENT = 0;  // index in COMPONENTS (DX, DY, DZ, DRX, DRY, DRZ)
constexpr index P_FUNCTION = 1;   // packed F(u)
constexpr index V_VALUE = 0, V_FORCE = 1, V_ACTIVE = 2;
constexpr double FORCE_FLOOR = DBL_EPSILON;  // np.finfo(np.float64).eps

// rela_effo_depl.relation_force: F(value) (NaN outside an EXCLU side), archived with its value
inline double relation_force(const F1& params, double component_value, const F1& state_out) {
    const double force = tabulated::value(params, P_FUNCTION, component_value);
    state_out(V_VALUE) = component_value;
    state_out(V_FORCE) = force;
    state_out(V_ACTIVE) = std::fabs(force) <= FORCE_FLOOR ? 0.0 : 1.0;
    return force;
}

}  // namespace rela_effo_depl
}  // namespace asterlite
