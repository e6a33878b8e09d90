// ADAPT_ORDRE2 as code_aster 10 to 12 ran it (mdadap;
// asterlite.dynamics.scheme_adapt_ordre2_v11): the leapfrog of ADAPT_ORDRE2
// with mdadap's step control, its archive grid (the nearer end of the step
// bracketing each archive time) and the final state in the slots left. Its
// pieces (predict, judge, accept, take_step) serve the loop with fluid films
// too (film.hpp), whose trials iterate on the end acceleration.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstdint>

#include "adapt_control.hpp"
#include "clock.hpp"
#include "forces.hpp"
#include "layout.hpp"
#include "loop.hpp"
#include "model.hpp"
#include "python_math.hpp"
#include "views.hpp"

namespace asterlite {
namespace adapt_legacy {

enum Row : int { Q_TRIAL, V_TRIAL, A_TRIAL, V_MIN, V_MID, V_MID_TRIAL, RESIDUAL };
constexpr index VECTOR_ROWS = 7;
// scalars after adapt_control's
enum Scalar : int {
    S_PREVIOUS_STEP = S_KEPT_AT_MAX_TRIALS + 1, S_CALM, S_NEXT_ARCHIVE, S_SPACING, S_SLOTS,
};
constexpr index N_SCALARS = S_SLOTS + 1;
constexpr double CALM_BEFORE_GROWTH = 5.0;  // mdadap's NPAS
constexpr double CALM_ERROR = 0.75;
constexpr double MACHINE_EPS = DBL_EPSILON;

// what a trial returns besides a diverging shock's index (>= 0)
enum Trial : index { TRIAL_DONE = -1, TRIAL_NOT_FINITE = -2, TRIAL_NOT_CONVERGED = -3 };

// planned_slots: the archive slots code_aster allocated (int() truncates)
inline std::int64_t planned_slots(double t0, double t_end, double spacing) {
    std::int64_t slots = static_cast<std::int64_t>((t_end - t0) / spacing) + 1;
    if (t_end - (t0 + static_cast<double>(slots - 1) * spacing) >= MACHINE_EPS) slots += 1;
    return slots;
}

inline void start(const Clock& c, const State& x, const F2& rows, const F1& scalars,
                  std::int64_t pas_arch) {
    scalars(S_FIRST_CALL) = 0.0;
    copy_into(row(rows, V_MID), x.v);
    scalars(S_PREVIOUS_STEP) = 0.0;
    scalars(S_CALM) = 0.0;
    const double spacing = scalars(S_DTMAX) * static_cast<double>(pas_arch > 1 ? pas_arch : 1);
    scalars(S_SPACING) = spacing;
    scalars(S_NEXT_ARCHIVE) = c.clock(C_TIME) + spacing;
    scalars(S_SLOTS) = static_cast<double>(planned_slots(c.clock(C_TIME), c.clock(C_END), spacing));
}

// predict: the leapfrog prediction of the step dt into the trial rows (the
// end acceleration is the caller's)
inline void predict(double dt, const State& x, const F2& rows, const F1& scalars) {
    const F1 q2 = row(rows, Q_TRIAL), v2 = row(rows, V_TRIAL);
    const F1 v_mid = row(rows, V_MID), v_mid2 = row(rows, V_MID_TRIAL);
    const double p = 0.5 * (scalars(S_PREVIOUS_STEP) + dt);
    for (index i = 0; i < x.q.n0; ++i) {
        v_mid2(i) = v_mid(i) + x.a(i) * p;
        q2(i) = x.q(i) + dt * v_mid2(i);
        v2(i) = v_mid2(i) + 0.5 * dt * x.a(i);
    }
}

// trial: one trial of the step dt from t on the 3-bundle model
// (forces.state_acceleration): a diverging shock, TRIAL_NOT_FINITE or TRIAL_DONE
inline index trial(double t, double dt, const State& x, const F2& rows, const F1& scalars,
                   const Model& model) {
    predict(dt, x, rows, scalars);
    copy_into(x.vint, x.vint_save);
    const F1 a2 = row(rows, A_TRIAL);
    const index shock = general_evaluate(t + dt, row(rows, Q_TRIAL), row(rows, V_TRIAL), a2, x.f,
                                         row(rows, RESIDUAL), x.vint, x.work, model);
    if (shock >= 0) return shock;
    if (!all_finite(a2)) return TRIAL_NOT_FINITE;
    return TRIAL_DONE;
}

inline void store(const Clock& c, const ArchiveBuffers& out, double t, std::int64_t step,
                  const F1& q, const F1& v, const F1& a, const F2& vint, double dt) {
    const std::int64_t n = c.counters(K_ARCHIVED);
    archive(out, n, t, step, q, v, a, vint, dt, c.counters(K_REJECTED));
    c.counters(K_ARCHIVED) = n + 1;
}

// archive_nearest: the step [t, t_new] bracketing the next archive time
// stores its nearer end (the start: the state before the step)
inline void archive_nearest(const Clock& c, const State& x, const F2& rows, const F1& scalars,
                            const ArchiveBuffers& out, double t_new, double dt_next) {
    const double t = c.clock(C_TIME);
    const double target = scalars(S_NEXT_ARCHIVE);
    if (!(t <= target && t_new >= target)) return;
    const std::int64_t step = c.counters(K_STEP);
    if (t_new - target <= target - t) {
        store(c, out, t_new, step, row(rows, Q_TRIAL), row(rows, V_TRIAL), row(rows, A_TRIAL),
              x.vint, dt_next);
    } else {
        store(c, out, t, step - 1, x.q, x.v, x.a, x.vint_save, dt_next);
    }
    scalars(S_NEXT_ARCHIVE) = target + scalars(S_SPACING);
}

// the step a new step starts its trials with (clipped at the end)
inline double first_trial_step(const Clock& c) {
    double dt = c.clock(C_STEP);
    if (c.clock(C_TIME) + dt > c.clock(C_END)) dt = c.clock(C_END) - c.clock(C_TIME);
    return dt;
}

// judge: the error of the trial of step ``tried``, the next trial's step
// and whether it fell to the lower bound before the end
inline void judge(const Clock& c, double tried, const State& x, const F2& rows,
                  const F1& scalars, double& err, double& dt, bool& underflow) {
    const double t = c.clock(C_TIME), t_end = c.clock(C_END);
    const double freq = apparent_frequency(tried, x.q, row(rows, Q_TRIAL), x.a,
                                           row(rows, A_TRIAL), row(rows, V_MIN));
    err = scalars(S_POINTS) * freq * tried;
    dt = tried;
    if (err > 1.0) dt = dt / scalars(S_DIVI);
    underflow = dt <= scalars(S_DTMIN) && std::fabs(t_end - (t + dt)) > MACHINE_EPS;
}

// accept: close a step whose last trial is kept (of step dt: the trial's,
// or that step divided once more when every trial failed)
inline void accept(const Clock& c, const State& x, const F2& rows, const F1& scalars,
                   const ArchiveBuffers& out, double dt, double err, std::int64_t trials) {
    const double t = c.clock(C_TIME), t_end = c.clock(C_END);
    if (err > 1.0) scalars(S_KEPT_AT_MAX_TRIALS) += 1.0;
    c.counters(K_REJECTED) += trials - 1;
    scalars(S_PREVIOUS_STEP) = dt;
    const double t_new = t + dt;
    const double dt_used = dt;
    if (err < CALM_ERROR) {
        if (scalars(S_CALM) == CALM_BEFORE_GROWTH) {
            dt = py_min(scalars(S_MULT) * dt, scalars(S_DTMAX));
            scalars(S_CALM) = CALM_BEFORE_GROWTH - 1.0;
        }
        scalars(S_CALM) += 1.0;
    } else {
        scalars(S_CALM) = 0.0;
    }
    if (t + dt > t_end) dt = t_end - t;  // mdadap clips against the step's start here
    c.counters(K_STEP) += 1;
    archive_nearest(c, x, rows, scalars, out, t_new, dt);
    update_reference_velocities(row(rows, V_MID_TRIAL), row(rows, V_MIN), scalars);
    c.clock(C_TIME) = t_new;
    c.clock(C_STEP) = dt;
    c.clock(C_MIN_STEP) = py_min(c.clock(C_MIN_STEP), dt_used);
    c.clock(C_MAX_STEP) = py_max(c.clock(C_MAX_STEP), dt_used);
    copy_into(x.q, row(rows, Q_TRIAL));
    copy_into(x.v, row(rows, V_TRIAL));
    copy_into(x.a, row(rows, A_TRIAL));
    copy_into(row(rows, V_MID), row(rows, V_MID_TRIAL));
}

// take_step (and fluid_film.adapt_step around its film_trial): one accepted
// step, trials included; ``try_step(t, dt)`` is the trial (a shock >= 0 or a
// Trial code); a status, ``status_not_converged`` for TRIAL_NOT_CONVERGED
// (only the film's trials iterate)
template <class TryStep>
int take_step(const Clock& c, const State& x, const F2& rows, const F1& scalars,
              const ArchiveBuffers& out, int status_not_converged, TryStep&& try_step) {
    const double t = c.clock(C_TIME);
    double dt = first_trial_step(c);
    const std::int64_t max_trials = py_round(scalars(S_MAX_TRIALS));
    double err = 100.0;
    std::int64_t trials = 0;
    copy_into(x.vint_save, x.vint);  // the shock states of the step's start
    while (err > 1.0 && trials < max_trials) {
        const double tried = dt;
        const index failed = try_step(t, tried);
        if (failed >= 0) return record_failure(c, STATUS_SHOCK_DIVERGED, failed, tried);
        if (failed == TRIAL_NOT_FINITE) {
            expose_trial(x.q, x.v, x.a, row(rows, Q_TRIAL), row(rows, V_TRIAL),
                         row(rows, A_TRIAL));
            return record_failure(c, STATUS_NOT_FINITE, -1, tried);
        }
        if (failed == TRIAL_NOT_CONVERGED) {  // mdadap stops the run (ALGORITH15_99)
            return record_failure(c, status_not_converged, -1, tried);
        }
        bool underflow;
        judge(c, tried, x, rows, scalars, err, dt, underflow);
        if (underflow) return record_failure(c, STATUS_STEP_UNDERFLOW, -1, dt);
        trials += 1;
    }
    accept(c, x, rows, scalars, out, dt, err, trials);
    return STATUS_DONE;
}

// fill_slots: the slots code_aster allocated and left unused hold the final
// state; STATUS_FULL when the buffers must grow first
inline int fill_slots(const Clock& c, const State& x, const F1& scalars,
                      const ArchiveBuffers& out) {
    while (scalars(S_SLOTS) > static_cast<double>(c.counters(K_ARCHIVED))) {
        if (c.counters(K_ARCHIVED) >= out.t.n0) return STATUS_FULL;
        store(c, out, c.clock(C_TIME), c.counters(K_STEP), x.q, x.v, x.a, x.vint,
              c.clock(C_STEP));
    }
    return STATUS_DONE;
}

// the time loop of run_loop and fluid_film.run_adapt_loop (resumable after
// any pause): ``ready()`` tells whether the loads cover the next step,
// ``step()`` takes one step and returns its status
template <class Ready, class Step>
int adapt_loop(const Clock& c, const State& x, const F2& rows, const F1& scalars,
               const ArchiveBuffers& out, std::int64_t pas_arch, Ready&& ready, Step&& step) {
    if (scalars(S_FIRST_CALL) == 1.0) start(c, x, rows, scalars, pas_arch);
    while (c.clock(C_TIME) < c.clock(C_END)) {
        const int paused = pause_status(c, out);
        if (paused) return paused;
        if (!ready()) return STATUS_LOADS;
        const int status = step();
        if (status != STATUS_DONE) return status;
    }
    return fill_slots(c, x, scalars, out);
}

// forces.loads_ready: the windowed multipliers of the loads and the support
// motions cover the next step (two stored steps ahead)
inline bool loads_ready(const Clock& c, const Loads& loads, const Supports& sup) {
    const double t_next = c.clock(C_TIME) + 2.0 * c.clock(C_STEP);
    return loads_cover(t_next, loads.tables) && loads_cover(t_next, sup.tables);
}

// run_loop: the whole loop on the 3-bundle model (the archiving instants and
// eps are not read: code_aster 10-12's ADAPT archived on its own grid)
inline int run_loop(const Clock& c, const State& x, const Memory& memory, const Model& model,
                    const ArchiveBuffers& out) {
    const F2& rows = memory.rows;
    const F1& scalars = memory.scalars;
    return adapt_loop(
        c, x, rows, scalars, out, c.pas_arch,
        [&]() { return loads_ready(c, model.loads, model.sup); },
        [&]() {
            // its trials never report TRIAL_NOT_CONVERGED: no status for it
            return take_step(c, x, rows, scalars, out, STATUS_DONE, [&](double t, double dt) {
                return trial(t, dt, x, rows, scalars, model);
            });
        });
}

// what run_loop needs of the scheme's memory (scheme_adapt_ordre2_v11.prepare)
inline void check_memory(Arguments& in, const Memory& memory, const State& x) {
    in.require(memory.rows.n0 >= VECTOR_ROWS && memory.rows.n1 == x.q.n0, "memory rows");
    in.require(memory.scalars.n0 >= N_SCALARS, "memory scalars");
}

}  // namespace adapt_legacy
}  // namespace asterlite
