// RUNGE_KUTTA_32 and RUNGE_KUTTA_54 (asterlite.dynamics.scheme_runge_kutta):
// an explicit embedded pair given by its tableau (memory.table), the step
// adapted on the scaled error, capped by the shocks' damping.
#pragma once

#include <cfloat>
#include <cmath>

#include "adapt_control.hpp"
#include "forces.hpp"
#include "implicit.hpp"
#include "local_frame.hpp"
#include "loop.hpp"
#include "python_math.hpp"

namespace asterlite {
namespace runge_kutta {

enum Row : int { Q_STAGE, V_STAGE, A_STAGE, RESIDUAL };
constexpr index VECTOR_ROWS = 4;
enum Scalar : int { S_TOL, S_ALPHA, S_DTMIN, S_DTMAX, S_ADAPTIVE, S_EXPONENT, S_RADIUS, S_CAP };
constexpr double EPS = 100.0 * DBL_EPSILON;
constexpr double HUGE_VALUE = DBL_MAX;

// one trial step of length dt from (q, v, a): stage values in the rows, the
// solution in the stage rows; a diverging shock or -1
inline index attempt(double t, double dt, const State& x, const Memory& memory,
                     const Model& model, index s) {
    const F2& rows = memory.rows;
    const F2& table = memory.table;
    const index n = x.q.n0;
    const F1 qs = row(rows, Q_STAGE), vs = row(rows, V_STAGE), acc = row(rows, A_STAGE);
    copy_into(vs, x.v);
    copy_into(acc, x.a);
    for (index stage = 0; stage < s; ++stage) {
        copy_into(row(rows, VECTOR_ROWS + stage), vs);
        copy_into(row(rows, VECTOR_ROWS + s + stage), acc);
        for (index i = 0; i < n; ++i) {
            double dq = 0.0, dv = 0.0;
            for (index k = 0; k < stage + 1; ++k) {
                dq += table(stage, k) * rows(VECTOR_ROWS + k, i);
                dv += table(stage, k) * rows(VECTOR_ROWS + s + k, i);
            }
            qs(i) = x.q(i) + dt * dq;
            vs(i) = x.v(i) + dt * dv;
        }
        const double t_stage = t + dt * table(s, stage + 1);
        const index shock =
            evaluate(t_stage, qs, vs, acc, x.f, row(rows, RESIDUAL), x.vint, x.work, model);
        if (shock >= 0) return shock;
    }
    return -1;
}

inline double scaled_error(double dt, const F1& q, const F1& v, const Memory& memory, index s) {
    const F2& rows = memory.rows;
    const F2& table = memory.table;
    const double tol = memory.scalars(S_TOL), alpha = memory.scalars(S_ALPHA);
    const F1 qs = row(rows, Q_STAGE), vs = row(rows, V_STAGE), acc = row(rows, A_STAGE);
    const index n = q.n0;
    double err_q = 0.0, err_v = 0.0;
    for (index i = 0; i < n; ++i) {
        double eq = table(s + 1, s) * vs(i);
        double ev = table(s + 1, s) * acc(i);
        for (index k = 0; k < s; ++k) {
            eq += table(s + 1, k) * rows(VECTOR_ROWS + k, i);
            ev += table(s + 1, k) * rows(VECTOR_ROWS + s + k, i);
        }
        const double dq = std::fabs(qs(i) - q(i));
        const double dv = std::fabs(vs(i) - v(i));
        const double scale_q = py_max(tol * std::fabs(q(i) + alpha), tol * (dq + alpha), EPS);
        const double scale_v = py_max(tol * std::fabs(v(i) + alpha), tol * (dv + alpha), EPS);
        const double rq = eq / scale_q, rv = ev / scale_v;
        err_q += rq * rq;
        err_v += rv * rv;
    }
    return py_max(dt * std::sqrt((err_q + err_v) / static_cast<double>(2 * n)), EPS);
}

inline StepResult step(double t, double dt, std::int64_t, const State& x, const Memory& memory,
                       const Model& model) {
    const F2& rows = memory.rows;
    const F1& scalars = memory.scalars;
    const index s = memory.table.n0 - 2;
    const bool adaptive = scalars(S_ADAPTIVE) == 1.0;
    const double p = scalars(S_EXPONENT);
    if (scalars(S_CAP) < 0.0) {
        scalars(S_CAP) = shock_damping_step(model.lin, model.shk, true, scalars(S_RADIUS));
    }
    const double dt_max = py_min(scalars(S_DTMAX), scalars(S_CAP));
    if (adaptive && dt > dt_max) dt = dt_max;
    const double low = std::pow(0.9 / 5.0, p), high = std::pow(0.9 / 0.2, p);
    if (adaptive) copy_into(x.vint_save, x.vint);  // a rejected trial restores the shock states
    double previous_error = HUGE_VALUE;
    std::int64_t rejected = 0;
    double dt_next = dt;
    const F1 qs = row(rows, Q_STAGE), vs = row(rows, V_STAGE), acc = row(rows, A_STAGE);
    while (true) {
        const index shock = attempt(t, dt, x, memory, model, s);
        if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, rejected};
        if (!(all_finite(qs) && all_finite(vs))) {
            expose_trial(x.q, x.v, x.a, qs, vs, acc);
            return {STATUS_NOT_FINITE, -1, dt, dt, rejected};
        }
        if (!adaptive) break;
        double err = scaled_error(dt, x.q, x.v, memory, s);
        if (err * 1.01 > previous_error) err = 0.99;  // refining does not help: proceed as is
        double factor;
        if (err < low) {
            factor = 5.0;
        } else if (err > high) {
            factor = 0.2;
        } else {
            factor = 0.9 * std::pow(err, -1.0 / p);
        }
        dt_next = py_min(dt_max, dt * factor);
        if (err >= 1.0 && dt_next >= scalars(S_DTMIN)) {
            dt = dt_next;
            previous_error = err;
            rejected += 1;
            copy_into(x.vint, x.vint_save);
            continue;
        }
        if (dt_next < scalars(S_DTMIN)) return {STATUS_STEP_UNDERFLOW, -1, dt, dt, rejected};
        break;
    }
    copy_into(x.q, qs);
    copy_into(x.v, vs);
    copy_into(x.a, acc);
    return {STATUS_DONE, -1, dt, dt_next, rejected};
}

}  // namespace runge_kutta
}  // namespace asterlite
