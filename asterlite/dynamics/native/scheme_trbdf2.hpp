// TRBDF2 (asterlite.dynamics.scheme_trbdf2): a trapezoidal stage to t + γ dt
// then a BDF2 stage to t + dt, implicit on the linear part (one effective
// stiffness for both, rebuilt when the step changes), the shock forces taken
// explicitly from the state held at index 2.
#pragma once

#include <cfloat>
#include <cmath>

#include "forces.hpp"
#include "implicit.hpp"
#include "local_frame.hpp"
#include "loop.hpp"

namespace asterlite {
namespace trbdf2 {

enum Row : int { Q_INDEX2, V_INDEX2, A_INDEX2, DELTA_ROW, R_Q, R_V, RESIDUAL, PIVOTS };
constexpr index VECTOR_ROWS = 8;
enum Scalar : int { S_DT_BUILT, S_DIAGONAL, S_A1, S_A2 };
// the module's constants as Python computes them (sqrt is correctly rounded;
// (1 - γ) ** 2 is the product, checked equal in tests/test_native_trbdf2.py)
const double STAGE_FRACTION = 2.0 - std::sqrt(2.0);
const double G1 = 1.0 / STAGE_FRACTION / (2.0 - STAGE_FRACTION);
const double G2 =
    -((1.0 - STAGE_FRACTION) * (1.0 - STAGE_FRACTION)) / STAGE_FRACTION / (2.0 - STAGE_FRACTION);
const double G3 = (1.0 - STAGE_FRACTION) / (2.0 - STAGE_FRACTION);
constexpr double EPS = DBL_EPSILON;  // np.finfo(np.float64).eps

// K_eff, F1, F2 for the step dt, K_eff factored; false when a pivot vanishes
inline bool build_operators(const F2& rows, const F1& scalars, double dt, index n) {
    const double h = STAGE_FRACTION * dt;
    const double a1 = 4.0 / (h * h), a2 = 2.0 / h;
    scalars(S_A1) = a1;
    scalars(S_A2) = a2;
    const F2 mass = block(rows, VECTOR_ROWS, B_MASS, n);
    const F2 stiffness = block(rows, VECTOR_ROWS, B_STIFF, n);
    const F2 damping = block(rows, VECTOR_ROWS, B_DAMP, n);
    combine(block(rows, VECTOR_ROWS, B_KEFF, n), mass, stiffness, damping, a1, 1.0, a2);
    combine(block(rows, VECTOR_ROWS, B_F1, n), mass, stiffness, damping, a2, 0.0, 0.0);
    combine(block(rows, VECTOR_ROWS, B_F2, n), mass, stiffness, damping, a1, 0.0, a2);
    scalars(S_DT_BUILT) = dt;
    const bool diagonal = scalars(S_DIAGONAL) == 1.0;
    return factor_effective(block(rows, VECTOR_ROWS, B_KEFF, n), row(rows, PIVOTS), diagonal);
}

inline StepResult step(double t, double dt, std::int64_t, const State& x, const Memory& memory,
                       const Model& model) {
    const F2& rows = memory.rows;
    const F1& scalars = memory.scalars;
    const index n = x.q.n0;
    const bool diagonal = scalars(S_DIAGONAL) == 1.0;
    const double built = scalars(S_DT_BUILT);
    if (built < 0.0 || std::fabs(dt / built - 1.0) >= EPS) {
        if (!build_operators(rows, scalars, dt, n)) return {STATUS_NOT_FINITE, -1, dt, dt, 0};
    }
    const F2 keff = block(rows, VECTOR_ROWS, B_KEFF, n);
    const F2 f1 = block(rows, VECTOR_ROWS, B_F1, n);
    const F2 f2 = block(rows, VECTOR_ROWS, B_F2, n);
    const F1 q2 = row(rows, Q_INDEX2), v2 = row(rows, V_INDEX2), a2 = row(rows, A_INDEX2);
    const F1 delta = row(rows, DELTA_ROW), r_q = row(rows, R_Q), r_v = row(rows, R_V);
    const F1 residual = row(rows, RESIDUAL), pivots = row(rows, PIVOTS);
    const double h = STAGE_FRACTION * dt;
    // --- trapezoidal stage to t + h
    index shock = evaluate(t + h, q2, v2, a2, x.f, residual, x.vint, x.work, model);
    if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, 0};
    for (index i = 0; i < n; ++i) r_v(i) = 0.5 * (x.a(i) + a2(i));
    for (index i = 0; i < delta.n0; ++i) delta(i) = 0.0;
    apply(f2, x.v, h, delta, diagonal);
    apply(f1, r_v, h, delta, diagonal);
    if (solve_divides_by_zero(keff, diagonal)) return {STATUS_ZERO_DIVISION, -1, dt, dt, 0};
    solve_effective(keff, pivots, delta, diagonal);
    // the acceleration at t + dt of the same state, for the BDF2 stage
    shock = evaluate(t + dt, q2, v2, a2, x.f, residual, x.vint, x.work, model);
    if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, 0};
    for (index i = 0; i < n; ++i) {
        q2(i) = x.q(i) + delta(i);
        v2(i) = x.v(i) + 2.0 * (delta(i) / h - x.v(i));
    }
    // --- BDF2 stage to t + dt
    for (index i = 0; i < n; ++i) {
        r_q(i) = x.q(i) - G1 * q2(i) - G2 * x.q(i) - G3 * dt * x.v(i);
        r_v(i) = x.v(i) - G1 * v2(i) - G2 * x.v(i) - G3 * dt * a2(i);
    }
    for (index i = 0; i < delta.n0; ++i) delta(i) = 0.0;
    apply(f1, r_v, -1.0, delta, diagonal);
    apply(f2, r_q, -1.0, delta, diagonal);
    solve_effective(keff, pivots, delta, diagonal);
    for (index i = 0; i < n; ++i) {
        q2(i) = x.q(i) + delta(i);
        v2(i) = x.v(i) + (delta(i) + r_q(i)) / G3 / dt;
    }
    shock = evaluate(t + dt, q2, v2, a2, x.f, residual, x.vint, x.work, model);
    if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, 0};
    copy_into(x.q, q2);
    copy_into(x.v, v2);
    copy_into(x.a, a2);
    if (!(all_finite(x.q) && all_finite(x.v) && all_finite(x.a))) {
        return {STATUS_NOT_FINITE, -1, dt, dt, 0};
    }
    return {STATUS_DONE, -1, dt, dt, 0};
}

}  // namespace trbdf2
}  // namespace asterlite
