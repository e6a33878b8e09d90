// DIS_VISC (asterlite.dynamics.laws.dis_visc): the generalized Zener viscous
// element between two nodes, integrated over each step by law_rk54.hpp.
#pragma once

#include "law_rk54.hpp"
#include "law_tabulated.hpp"
#include "views.hpp"

namespace asterlite {
namespace dis_visc {

constexpr index P_MODEL = 0, P_ITER_MAX = 5, P_RESI = 6;
constexpr index V_LOC1 = 0, V_LOC2 = 3, V_VREL = 6, V_FORCE = 7, V_EPS_VISC = 8, V_EPS = 9;
constexpr index V_DISSIP = 10;
constexpr index N_Y = 4;

struct Force {
    double sigma;
    bool converged;
};

// dis_visc.zener_force: sigma on node 1 along +x at the end of the step dt;
// rate: 3 floats of scratch, work: (N_WORK, >= 4) scratch
inline Force zener_force(const F1& params, double relative_axial_velocity, double dt,
                         const F1& state_in, const F1& state_out, const F1& rate,
                         const F2& work) {
    rate(0) = -relative_axial_velocity;
    rate(1) = 0.0;
    rate(2) = 0.0;
    const bool converged = rk54::adaptive_integrate(
        rk54::ZENER, tabulated::part(params, P_MODEL, P_MODEL + 5),
        tabulated::part(state_in, V_FORCE, V_FORCE + N_Y), rate, dt,
        tabulated::to_int(params(P_ITER_MAX)), params(P_RESI), tabulated::part(params, 0, 0),
        tabulated::part(state_out, V_FORCE, V_FORCE + N_Y), work);
    state_out(V_VREL) = relative_axial_velocity;
    return {state_out(V_FORCE), converged};
}

}  // namespace dis_visc
}  // namespace asterlite
