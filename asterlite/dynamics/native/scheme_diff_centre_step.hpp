// DIFF_CENTRE's general path (scheme_diff_centre.step, run by loop.time_loop
// on the three bundles): v += dt a, q += dt v, then a from the equations of
// motion at the new state (forces.state_acceleration: the shocks in the
// global frame, the relations of laws/).
#pragma once

#include "forces.hpp"
#include "local_frame.hpp"
#include "loop.hpp"
#include "model.hpp"
#include "views.hpp"

namespace asterlite {
namespace diff_centre {

enum Row : int { RESIDUAL };  // memory row: residual scratch (scheme_diff_centre.prepare)

// scheme_diff_centre.step; forces.state_acceleration inlined there is
// local_frame.hpp's evaluate on the general model (forces.evaluate: the same
// total force, then the same acceleration)
inline StepResult step(double t, double dt, std::int64_t, const State& x, const Memory& memory,
                       const Model& model) {
    for (index i = 0; i < x.q.n0; ++i) {
        x.v(i) += dt * x.a(i);
        x.q(i) += dt * x.v(i);
    }
    const index shock = evaluate(t + dt, x.q, x.v, x.a, x.f, row(memory.rows, RESIDUAL), x.vint,
                                 x.work, model);
    if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, 0};
    if (!all_finite(x.a)) return {STATUS_NOT_FINITE, -1, dt, dt, 0};
    return {STATUS_DONE, -1, dt, dt, 0};
}

}  // namespace diff_centre
}  // namespace asterlite
