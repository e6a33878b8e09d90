// ADAPT_ORDRE1 and ADAPT_ORDRE2 (asterlite.dynamics.scheme_adapt_ordre1,
// scheme_adapt_ordre2): symplectic Euler and leapfrog with the
// apparent-frequency step control of adapt_control.hpp. Not code_aster
// 10-12's ADAPT_ORDRE2 (scheme_adapt_ordre2_v11: numba's).
#pragma once

#include <cmath>
#include <cstdint>

#include "adapt_control.hpp"
#include "forces.hpp"
#include "implicit.hpp"
#include "local_frame.hpp"
#include "loop.hpp"
#include "python_math.hpp"

namespace asterlite {
namespace adapt_ordre1 {

enum Row : int { Q_TRIAL, V_TRIAL, A_TRIAL, V_MIN, RESIDUAL };
constexpr index VECTOR_ROWS = 5;

inline StepResult step(double t, double dt, std::int64_t step_index, const State& x,
                       const Memory& memory, const Model& model) {
    const F2& rows = memory.rows;
    const F1& scalars = memory.scalars;
    const index n = x.q.n0;
    const F1 q2 = row(rows, Q_TRIAL), v2 = row(rows, V_TRIAL), a2 = row(rows, A_TRIAL);
    const F1 vmin = row(rows, V_MIN);
    const bool adaptive = scalars(S_ADAPTIVE) == 1.0;
    const std::int64_t max_trials = py_round(scalars(S_MAX_TRIALS));
    if (adaptive) copy_into(x.vint_save, x.vint);  // a rejected trial restores the shock states
    const double dt_proposed = dt;
    double dt_trial = dt;
    double dt_next = dt;
    std::int64_t trials = 1;
    while (true) {
        double p = 0.5 * (dt_proposed + dt_trial);
        if (dt_trial <= 1.0e-13) p = dt_trial;
        for (index i = 0; i < n; ++i) {
            v2(i) = x.v(i) + x.a(i) * p;
            q2(i) = x.q(i) + v2(i) * dt_trial;
        }
        const index shock =
            evaluate(t + dt_trial, q2, v2, a2, x.f, row(rows, RESIDUAL), x.vint, x.work, model);
        if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt_trial, dt_trial, trials - 1};
        if (!all_finite(a2)) {
            expose_trial(x.q, x.v, x.a, q2, v2, a2);
            return {STATUS_NOT_FINITE, -1, dt_trial, dt_trial, trials - 1};
        }
        if (!adaptive) break;
        double err = frequency_error(dt_trial, x.q, q2, x.a, a2, vmin, scalars);
        if (step_index < 5) err = 0.0;  // the error is ignored on the first five steps
        const double factor = step_factor(err, scalars);
        dt_next = py_min(scalars(S_DTMAX), dt_trial * factor);
        if (err >= 1.0 && dt_next >= scalars(S_DTMIN) && trials < max_trials) {
            dt_trial = dt_next;
            trials += 1;
            copy_into(x.vint, x.vint_save);
            continue;
        }
        if (dt_next < scalars(S_DTMIN)) {
            return {STATUS_STEP_UNDERFLOW, -1, dt_trial, dt_trial, trials - 1};
        }
        if (trials == max_trials) scalars(S_KEPT_AT_MAX_TRIALS) += 1.0;
        update_reference_velocities(v2, vmin, scalars);
        break;
    }
    copy_into(x.q, q2);
    copy_into(x.v, v2);
    copy_into(x.a, a2);
    return {STATUS_DONE, -1, dt_trial, dt_next, trials - 1};
}

}  // namespace adapt_ordre1

namespace adapt_ordre2 {

enum Row : int { Q_TRIAL, V_TRIAL, A_TRIAL, V_MIN, V_MID, V_MID_TRIAL, RESIDUAL };
constexpr index VECTOR_ROWS = 7;

// the mid-step velocity is carried in the memory (V_MID); the state's
// velocity is the one at the step's end
inline StepResult step(double t, double dt, std::int64_t, const State& x, const Memory& memory,
                       const Model& model) {
    const F2& rows = memory.rows;
    const F1& scalars = memory.scalars;
    const index n = x.q.n0;
    const F1 q2 = row(rows, Q_TRIAL), v2 = row(rows, V_TRIAL), a2 = row(rows, A_TRIAL);
    const F1 vmin = row(rows, V_MIN);
    const F1 v_mid = row(rows, V_MID), v_mid_trial = row(rows, V_MID_TRIAL);
    const bool adaptive = scalars(S_ADAPTIVE) == 1.0;
    const std::int64_t max_trials = py_round(scalars(S_MAX_TRIALS));
    double dt_proposed;
    if (scalars(S_FIRST_CALL) == 1.0) {  // the first step starts from v: half a step
        scalars(S_FIRST_CALL) = 0.0;
        copy_into(v_mid, x.v);
        dt_proposed = 0.0;
    } else {
        dt_proposed = dt;
    }
    if (adaptive) copy_into(x.vint_save, x.vint);  // a rejected trial restores the shock states
    double dt_trial = dt;
    double dt_next = dt;
    std::int64_t trials = 1;
    while (true) {
        const double p = 0.5 * (dt_proposed + dt_trial);
        const double half = 0.5 * dt_trial;
        for (index i = 0; i < n; ++i) {
            v_mid_trial(i) = v_mid(i) + x.a(i) * p;
            q2(i) = x.q(i) + v_mid_trial(i) * dt_trial;
            v2(i) = v_mid_trial(i) + half * x.a(i);
        }
        const index shock =
            evaluate(t + dt_trial, q2, v2, a2, x.f, row(rows, RESIDUAL), x.vint, x.work, model);
        if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt_trial, dt_trial, trials - 1};
        if (!all_finite(a2)) {
            expose_trial(x.q, x.v, x.a, q2, v2, a2);
            return {STATUS_NOT_FINITE, -1, dt_trial, dt_trial, trials - 1};
        }
        if (!adaptive) break;
        const double err = frequency_error(dt_trial, x.q, q2, x.a, a2, vmin, scalars);
        const double factor = step_factor(err, scalars);
        dt_next = py_min(scalars(S_DTMAX), dt_trial * factor);
        if (err >= 1.0 && dt_next >= scalars(S_DTMIN) && trials < max_trials) {
            dt_trial = dt_next;
            trials += 1;
            copy_into(x.vint, x.vint_save);
            continue;
        }
        if (dt_next < scalars(S_DTMIN)) {
            return {STATUS_STEP_UNDERFLOW, -1, dt_trial, dt_trial, trials - 1};
        }
        if (trials == max_trials) scalars(S_KEPT_AT_MAX_TRIALS) += 1.0;
        update_reference_velocities(v_mid_trial, vmin, scalars);
        break;
    }
    copy_into(x.q, q2);
    copy_into(x.v, v2);
    copy_into(x.a, a2);
    copy_into(v_mid, v_mid_trial);
    return {STATUS_DONE, -1, dt_trial, dt_next, trials - 1};
}

}  // namespace adapt_ordre2
}  // namespace asterlite
