// NEWMARK's general path (scheme_newmark.step, run by loop.time_loop on the
// three bundles): the operators of scheme_newmark.hpp, the forces through
// total_force_at (forces.total_force_at on the general model: the shocks in
// the global frame, the relations of laws/), at code_aster's index 2 or at
// the step's start (force_at_step_start).
#pragma once

#include <cmath>

#include "forces.hpp"
#include "implicit.hpp"
#include "local_frame.hpp"
#include "loop.hpp"
#include "model.hpp"
#include "scheme_newmark.hpp"
#include "views.hpp"

namespace asterlite {
namespace newmark {

// scheme_newmark.step: I.apply and I.solve_effective as called there (not
// newmark_update's one-pass diagonal case: the same bits, kept as written)
inline StepResult step(double t, double dt, std::int64_t, const State& x, const Memory& memory,
                       const Model& model) {
    const F2& rows = memory.rows;
    const F1& scalars = memory.scalars;
    const F1 &q = x.q, &v = x.v, &a = x.a, &f = x.f;
    const index n = q.n0;
    const bool diagonal = scalars(S_DIAGONAL) == 1.0;
    const double built = scalars(S_DT_BUILT);
    if (built < 0.0 || std::fabs(dt / built - 1.0) >= EPS) {
        if (operators_divide_by_zero(scalars, dt)) return {STATUS_ZERO_DIVISION, -1, dt, dt, 0};
        if (!build_operators(rows, scalars, dt, n)) return {STATUS_NOT_FINITE, -1, dt, dt, 0};
    }
    const F1 q2 = row(rows, Q_INDEX2), v2 = row(rows, V_INDEX2), rhs = row(rows, RHS);
    const bool at_start = scalars(S_FORCE_AT_START) == 1.0;
    if (!at_start) {  // else f holds F(t, q, v): the loop's start or the previous step's end
        const index shock = total_force_at(t + dt, q2, v2, x.vint, x.work, f, model);
        if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, 0};
    }
    copy_into(rhs, f);
    apply(block(rows, VECTOR_ROWS, B_F1, n), v, 1.0, rhs, diagonal);
    apply(block(rows, VECTOR_ROWS, B_F2, n), q, 1.0, rhs, diagonal);
    apply(block(rows, VECTOR_ROWS, B_F3, n), a, 1.0, rhs, diagonal);
    const F2 keff = block(rows, VECTOR_ROWS, B_KEFF, n);
    if (solve_divides_by_zero(keff, diagonal)) return {STATUS_ZERO_DIVISION, -1, dt, dt, 0};
    solve_effective(keff, row(rows, PIVOTS), rhs, diagonal);
    advance(rows, scalars, q, v, a, rhs, dt, n);
    if (!(all_finite(q) && all_finite(v))) return {STATUS_NOT_FINITE, -1, dt, dt, 0};
    if (at_start) {  // the forces of the next step's start
        const index shock = total_force_at(t + dt, q, v, x.vint, x.work, f, model);
        if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, 0};
    }
    return {STATUS_DONE, -1, dt, dt, 0};
}

}  // namespace newmark
}  // namespace asterlite
