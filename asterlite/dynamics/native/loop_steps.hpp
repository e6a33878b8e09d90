// What every time loop does around its step (asterlite.dynamics.loop's
// before_step and after_step): the checks before a step, and after an
// accepted one the clock, the archive and the energy balance.
#pragma once

#include "clock.hpp"
#include "energy.hpp"
#include "loads.hpp"
#include "model.hpp"

namespace asterlite {

// 0 to go on, else the status to return: archive full, pause, next load window
inline int before_step(const Clock& c, const ArchiveBuffers& out, const Model& model) {
    const int paused = pause_status(c, out);
    if (paused) return paused;
    const double t_next = c.clock(C_TIME) + 2.0 * c.clock(C_STEP);
    if (!(loads_cover(t_next, model.loads.tables) && loads_cover(t_next, model.sup.tables))) {
        return STATUS_LOADS;
    }
    return 0;
}

// advance the clock over an accepted step, archive when due and, when the
// balance is ``active`` (read once before the loop), add the step to it
inline void after_step(const Clock& c, const State& x, const ArchiveBuffers& out,
                       const energy::Balance& balance, bool active, const Model& model,
                       double dt_used, double dt_next, std::int64_t rejected) {
    const std::int64_t archived = c.counters(K_ARCHIVED);
    advance_clock(c, x.q, x.v, x.a, x.vint, out, dt_used, dt_next, rejected);
    if (active) {
        energy::after_step(balance, archived, c.counters(K_ARCHIVED), c.clock(C_TIME), dt_used,
                           x.q, x.v, x.a, x.vint, model);
    }
}

}  // namespace asterlite
