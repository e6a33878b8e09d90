// Rotating machinery at variable speed (asterlite.dynamics.rotation): before
// every step C(t) = C + Omega(t) G and K(t) = K + Omega'(t) K_gy are written
// into the model's linear bundle (full matrices from then on), the scheme's
// operators refreshed, then the step of the scheme the dispatch code names;
// loop.time_loop around that step (rotation.rotating_step).
#pragma once

#include <cstdint>

#include "clock.hpp"
#include "dispatch.hpp"
#include "formula.hpp"
#include "loads.hpp"
#include "loop.hpp"
#include "loop_steps.hpp"
#include "model.hpp"
#include "views.hpp"

namespace asterlite {
namespace rotation {

// Rotation.bundle(): C, K at rest, G, K_gy, and the multipliers Omega (row 0)
// and Omega' (row 1) as an excitation bundle's tables and formula programs
struct Rotation {
    F2 damping0, stiffness0, gyro, rigy;
    Tables tables;  // abscissas, ordinates, layout, cursors (pending unused)
    I2 codes;
    F2 constants;
    F1 stack;
};

// rotation.multiplier_value: the formula program of row e, else its table
inline double multiplier_value(const Rotation& rot, index e, double t) {
    if (rot.codes(e, 0) > 0) return run_program(rot.codes, rot.constants, e, t, rot.stack);
    return multiplier_at(rot.tables, e, t);
}

// rotation.update_linear: C(t), K(t) into the linear bundle, its flag (the
// array ``flag`` and the model's copy of it) set to full matrices
inline void update_linear(Linear& lin, const I1& flag, const Rotation& rot, double t) {
    const double speed = multiplier_value(rot, 0, t);
    const double accel = multiplier_value(rot, 1, t);
    const index n = lin.damping.n0;
    for (index i = 0; i < n; ++i) {
        for (index j = 0; j < n; ++j) {
            lin.damping(i, j) = rot.damping0(i, j) + speed * rot.gyro(i, j);
            lin.stiffness(i, j) = rot.stiffness0(i, j) + accel * rot.rigy(i, j);
        }
    }
    flag(0) = 0;
    lin.diagonal = false;
}

// rotation.rotating_step
inline StepResult rotating_step(double t, double dt, std::int64_t step_index, const State& x,
                                const Memory& memory, Model& model, const I1& flag,
                                const Rotation& rot, std::int64_t code) {
    update_linear(model.lin, flag, rot, t);
    dispatch::refresh_operators(code, memory, model.lin, x.q.n0);
    return dispatch::scheme_step(code, t, dt, step_index, x, memory, model);
}

// loop.time_loop around rotating_step (rotation.prepare's run_loop); a
// ZeroDivisionError of numba's step returned at once as
// STATUS_ZERO_DIVISION (nothing recorded: numba raises there)
inline int rotating_loop(const Clock& c, const State& x, const Memory& memory, Model& model,
                         const ArchiveBuffers& out, const energy::Balance& balance,
                         const I1& flag, const Rotation& rot, std::int64_t code) {
    const bool active = balance.active();  // read once, as loop.time_loop does
    while (unfinished(c)) {
        const int paused = before_step(c, out, model);
        if (paused) return paused;
        double t, dt;
        plan_step(c, t, dt);
        const StepResult r =
            rotating_step(t, dt, c.counters(K_STEP), x, memory, model, flag, rot, code);
        if (r.status == STATUS_ZERO_DIVISION) return r.status;
        if (r.status != STATUS_DONE) return record_failure(c, r.status, r.shock, r.dt_used);
        after_step(c, x, out, balance, active, model, r.dt_used, r.dt_next, r.rejected);
    }
    return STATUS_DONE;
}

}  // namespace rotation
}  // namespace asterlite
