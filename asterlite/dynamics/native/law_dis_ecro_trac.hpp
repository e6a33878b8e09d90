// DIS_ECRO_TRAC (asterlite.dynamics.laws.dis_ecro_trac): the discrete element
// with a hardening force-displacement curve, integrated over each step by law_rk54.hpp.
#pragma once

#include "law_discrete_hardening.hpp"
#include "law_rk54.hpp"
#include "law_tabulated.hpp"
#include "views.hpp"

namespace asterlite {
namespace dis_ecro_trac {

constexpr index N_Y = discrete_hardening::N_Y;
constexpr index P_AXIAL = 0, P_ITER_MAX = 1, P_RESI = 2, P_SCALES = 3;
constexpr index P_CURVE = P_SCALES + N_Y;
constexpr index V_LOC1 = 0, V_LOC2 = 3, V_STATE = 6, V_FORCE = 6;

struct Force {
    double fx, fy, fz;
    bool converged;
};

// dis_ecro_trac.hardening_force: the local force on node 1 at the end of the
// step; relative_velocity = v1 - v2 in the local frame (3)
inline Force hardening_force(const F1& params, const F1& relative_velocity, double dt,
                             const F1& state_in, const F1& state_out, const F1& rate,
                             const F2& work) {
    const bool axial = params(P_AXIAL) == 1.0;
    rate(0) = axial ? -relative_velocity(0) : 0.0;
    rate(1) = axial ? 0.0 : -relative_velocity(1);
    rate(2) = axial ? 0.0 : -relative_velocity(2);
    const bool converged = rk54::adaptive_integrate(
        rk54::HARDENING, tabulated::part(params, P_CURVE, params.n0),
        tabulated::part(state_in, V_STATE, V_STATE + N_Y), rate, dt,
        tabulated::to_int(params(P_ITER_MAX)), params(P_RESI),
        tabulated::part(params, P_SCALES, P_SCALES + N_Y),
        tabulated::part(state_out, V_STATE, V_STATE + N_Y), work);
    const F1 f = tabulated::part(state_out, V_FORCE, V_FORCE + 3);
    if (axial) return {f(0), 0.0, 0.0, converged};
    return {0.0, f(1), f(2), converged};
}

}  // namespace dis_ecro_trac
}  // namespace asterlite
