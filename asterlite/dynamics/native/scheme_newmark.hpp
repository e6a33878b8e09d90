// NEWMARK's own loop (scheme_newmark.fast_loop / specialised_loop): implicit
// on the linear part in displacement form, the nonlinear forces taken at
// code_aster's index 2 (the previous step's result), or at the step's start
// for code_aster 13-15 decks (force_at_step_start); the shocks in their
// local frames, the operators rebuilt when dt changes.
#pragma once

#include <cfloat>
#include <cmath>

#include "clock.hpp"
#include "loop_steps.hpp"
#include "energy.hpp"
#include "contact.hpp"
#include "forces.hpp"
#include "formula.hpp"
#include "implicit.hpp"
#include "layout.hpp"
#include "loads.hpp"
#include "model.hpp"
#include "views.hpp"

namespace asterlite {
namespace newmark {

// vector rows: index-2 displacement and velocity, right-hand side, pivots
enum Row : int { Q_INDEX2, V_INDEX2, RHS, PIVOTS };
constexpr index VECTOR_ROWS = 4;
constexpr index N_BLOCKS = 7;  // implicit.new_rows' blocks: M, K, C, K_eff, F1, F2, F3
enum Scalar : int { S_BETA, S_GAMMA, S_DT_BUILT, S_DIAGONAL };
constexpr index A1 = 4;                // a1..a8 follow
constexpr index S_FORCE_AT_START = 12;  // 1.0: code_aster 13-15's forces of the step's start
constexpr index N_SCALARS = 13;
constexpr double EPS = DBL_EPSILON;

// scheme_newmark.local_force (and start_force, its call of its own): f =
// F_ext(t) + the shock forces at (q, v) in the shocks' local frames; a
// diverging shock's index or -1
inline index local_force(double t, const F1& q, const F1& v, const F1& f, const F2& vint,
                         const Model& model) {
    for (index i = 0; i < f.n0; ++i) f(i) = 0.0;
    add_external_force(t, model.loads, f);
    local_support_motion(t, model.shk.rots, model.sup, model.local.drive);
    return local_shock_forces(q, v, model.shk, model.local.shapes, model.local.rest,
                              model.local.drive, vint, f);
}

// whether build_operators' first division, 1 / (beta dt dt), is by zero (the
// later divisors, beta dt, 2 beta and beta, vanish only when it does): BETA=0
inline bool operators_divide_by_zero(const F1& scalars, double dt) {
    return scalars(S_BETA) * dt * dt == 0.0;
}

// scheme_newmark.build_operators: a1..a8 for dt, the operators of the
// right-hand side and the effective stiffness (factored unless diagonal);
// false when a pivot vanishes
inline bool build_operators(const F2& rows, const F1& scalars, double dt, index n) {
    const double beta = scalars(S_BETA), gamma = scalars(S_GAMMA);
    double* a = scalars.data + A1;
    a[0] = 1.0 / (beta * dt * dt);
    a[1] = gamma / (beta * dt);
    a[2] = 1.0 / (beta * dt);
    a[3] = 1.0 / (2.0 * beta) - 1.0;
    a[4] = gamma / beta - 1.0;
    a[5] = (dt / 2.0) * (gamma / beta - 2.0);
    a[6] = dt * (1.0 - gamma);
    a[7] = gamma * dt;
    const F2 mass = block(rows, VECTOR_ROWS, B_MASS, n);
    const F2 stiffness = block(rows, VECTOR_ROWS, B_STIFF, n);
    const F2 damping = block(rows, VECTOR_ROWS, B_DAMP, n);
    combine(block(rows, VECTOR_ROWS, B_KEFF, n), mass, stiffness, damping, a[0], 1.0, a[1]);
    combine(block(rows, VECTOR_ROWS, B_F1, n), mass, stiffness, damping, a[2], 0.0, a[4]);
    combine(block(rows, VECTOR_ROWS, B_F2, n), mass, stiffness, damping, a[0], 0.0, a[1]);
    combine(block(rows, VECTOR_ROWS, B_F3, n), mass, stiffness, damping, a[3], 0.0, a[5]);
    const bool diagonal = scalars(S_DIAGONAL) == 1.0;
    scalars(S_DT_BUILT) = dt;
    return factor_effective(block(rows, VECTOR_ROWS, B_KEFF, n), row(rows, PIVOTS), diagonal);
}

// the step's end from the solved right-hand side ``rhs`` (the new q): a, v,
// q and their index-2 copies (scheme_newmark's update, shared by both loops)
inline void advance(const F2& rows, const F1& scalars, const F1& q, const F1& v, const F1& a,
                    const F1& rhs, double dt, index n) {
    const double* c = scalars.data + A1;
    const F1 q2 = row(rows, Q_INDEX2), v2 = row(rows, V_INDEX2);
    for (index i = 0; i < n; ++i) {
        const double a_new = -c[3] * a(i) + c[0] * (rhs(i) - q(i) - dt * v(i));
        v(i) = v(i) + c[6] * a(i) + c[7] * a_new;
        a(i) = a_new;
        q(i) = rhs(i);
        q2(i) = q(i);
        v2(i) = v(i);
    }
}

// scheme_newmark.newmark_update: the right-hand side, the solve, then a, v,
// q and the index-2 copies (the diagonal case written out in one pass)
inline void newmark_update(const F2& rows, const F1& scalars, const F1& q, const F1& v,
                           const F1& a, const F1& f, double dt, index n) {
    const bool diagonal = scalars(S_DIAGONAL) == 1.0;
    const F1 rhs = row(rows, RHS);
    const F2 f1 = block(rows, VECTOR_ROWS, B_F1, n);
    const F2 f2 = block(rows, VECTOR_ROWS, B_F2, n);
    const F2 f3 = block(rows, VECTOR_ROWS, B_F3, n);
    const F2 keff = block(rows, VECTOR_ROWS, B_KEFF, n);
    if (diagonal) {
        for (index i = 0; i < n; ++i) {
            double x = f(i);
            x += 1.0 * f1(i, i) * v(i);
            x += 1.0 * f2(i, i) * q(i);
            x += 1.0 * f3(i, i) * a(i);
            rhs(i) = x / keff(i, i);
        }
    } else {
        for (index i = 0; i < n; ++i) rhs(i) = f(i);
        apply(f1, v, 1.0, rhs, false);
        apply(f2, q, 1.0, rhs, false);
        apply(f3, a, 1.0, rhs, false);
        solve_effective(keff, row(rows, PIVOTS), rhs, false);
    }
    advance(rows, scalars, q, v, a, rhs, dt, n);
}

// scheme_newmark.specialised_loop: the status codes, archiving rules and
// operator rebuilds of the general path
inline int newmark_loop(const Clock& c, const State& x, const Memory& memory, const Model& model,
                        const ArchiveBuffers& out, const energy::Balance& balance) {
    const bool active = balance.active();  // energy balance: energy.after_step
    const index n = x.q.n0;
    const F2& rows = memory.rows;
    const F1& scalars = memory.scalars;
    const F1 q2 = row(rows, Q_INDEX2), v2 = row(rows, V_INDEX2);
    const bool at_start = scalars(S_FORCE_AT_START) == 1.0;
    while (unfinished(c)) {
        const int paused = before_step(c, out, model);
        if (paused) return paused;
        double t, dt;
        plan_step(c, t, dt);
        const double built = scalars(S_DT_BUILT);
        if (built < 0.0 || std::fabs(dt / built - 1.0) >= EPS) {
            if (operators_divide_by_zero(scalars, dt)) return STATUS_ZERO_DIVISION;
            if (!build_operators(rows, scalars, dt, n)) {
                return record_failure(c, STATUS_NOT_FINITE, -1, dt);
            }
        }
        if (!at_start) {  // else f holds F(t, q, v): the loop's start or the previous step's end
            const index shock = local_force(t + dt, q2, v2, x.f, x.vint, model);
            if (shock >= 0) return record_failure(c, STATUS_SHOCK_DIVERGED, shock, dt);
        }
        const bool diagonal = scalars(S_DIAGONAL) == 1.0;
        if (solve_divides_by_zero(block(rows, VECTOR_ROWS, B_KEFF, n), diagonal)) {
            return STATUS_ZERO_DIVISION;
        }
        newmark_update(rows, scalars, x.q, x.v, x.a, x.f, dt, n);
        if (!(all_finite(x.q) && all_finite(x.v))) {
            return record_failure(c, STATUS_NOT_FINITE, -1, dt);
        }
        if (at_start) {  // the forces of the next step's start
            const index shock = local_force(t + dt, x.q, x.v, x.f, x.vint, model);
            if (shock >= 0) return record_failure(c, STATUS_SHOCK_DIVERGED, shock, dt);
        }
        after_step(c, x, out, balance, active, model, dt, dt, 0);
    }
    return STATUS_DONE;
}

}  // namespace newmark
}  // namespace asterlite
