// The clock of the time loops (asterlite.dynamics.kernel): step planning on
// the requested instants, code_aster's archiving rules (dtmcalc), the
// fixed-step grid, status codes.
#pragma once

#include <cmath>
#include <cstdint>

#include "layout.hpp"
#include "views.hpp"

namespace asterlite {

struct ArchiveBuffers {
    F1 t;
    I1 order;
    F2 q, v, a;
    F3 vint;
    F2 info;
};

struct Clock {
    F1 clock;
    I1 counters;
    F1 instants;
    std::int64_t pas_arch;
    double eps;
};

inline void archive(const ArchiveBuffers& out, index n, double t, std::int64_t step, const F1& q,
                    const F1& v, const F1& a, const F2& vint, double dt, std::int64_t rejected) {
    out.t(n) = t;
    out.order(n) = step;
    out.info(n, INFO_STEP) = dt;
    out.info(n, INFO_REJECTED) = static_cast<double>(rejected);
    for (index i = 0; i < q.n0; ++i) {
        out.q(n, i) = q(i);
        out.v(n, i) = v(i);
        out.a(n, i) = a(i);
    }
    for (index s = 0; s < vint.n0; ++s) {
        for (index j = 0; j < vint.n1; ++j) out.vint(n, s, j) = vint(s, j);
    }
}

// code_aster's loop test: the remaining time exceeds i * eps
inline bool unfinished(const Clock& c) {
    const std::int64_t i = c.counters(K_STEP) + 1;
    return (c.clock(C_END) - c.clock(C_TIME)) > static_cast<double>(i) * c.eps;
}

inline int pause_status(const Clock& c, const ArchiveBuffers& out) {
    if (c.counters(K_ARCHIVED) >= out.t.n0) return STATUS_FULL;
    if (c.counters(K_STEP) >= c.counters(K_PAUSE_AT)) return STATUS_PAUSE;
    return 0;
}

// the stored step, shortened to land on the next requested instant
inline void plan_step(const Clock& c, double& t, double& dt) {
    const double ieps = static_cast<double>(c.counters(K_STEP) + 1) * c.eps;
    t = c.clock(C_TIME);
    dt = c.clock(C_STEP);
    const std::int64_t k = c.counters(K_INSTANT);
    if (k < c.instants.n0) {
        const double target = c.instants(k);
        if (t + dt - target > ieps) {
            c.clock(C_NEWDT) = target - t;
            dt = c.clock(C_NEWDT);
            c.counters(K_FORCE) = 1;
        } else if (std::fabs(t + dt - target) < ieps) {
            c.clock(C_NEWDT) = dt;
            c.counters(K_FORCE) = 1;
        }
    }
}

// kernel.expose_trial: a non-finite trial copied into the state before the
// step returns STATUS_NOT_FINITE, for the driver to say which quantity went wrong
inline void expose_trial(const F1& q, const F1& v, const F1& a, const F1& q_trial,
                         const F1& v_trial, const F1& a_trial) {
    for (index i = 0; i < q.n0; ++i) {
        q(i) = q_trial(i);
        v(i) = v_trial(i);
        a(i) = a_trial(i);
    }
}

inline int record_failure(const Clock& c, int status, std::int64_t shock, double dt) {
    c.clock(C_STEP) = dt;
    c.counters(K_SHOCK) = shock;
    return status;
}

// the end t of a fixed step, replaced by t0 + n dt when the step completes
// grid interval n; elsewhere a new grid starts
inline double grid_instant(const Clock& c, double t) {
    const std::int64_t n = c.counters(K_GRID) + 1;
    const double node = c.clock(C_ORIGIN) + static_cast<double>(n) * c.clock(C_STEP0);
    if (std::fabs(t - node) <= GRID_TOLERANCE * c.clock(C_STEP0)) {
        c.counters(K_GRID) = n;
        return node;
    }
    c.clock(C_ORIGIN) = t;
    c.counters(K_GRID) = 0;
    return t;
}

inline std::int64_t python_mod(std::int64_t a, std::int64_t b) {
    const std::int64_t r = a % b;
    return (r != 0 && ((r < 0) != (b < 0))) ? r + b : r;
}

// kernel.advance_clock: advance over an accepted step, choose the next step,
// archive when due
inline void advance_clock(const Clock& c, const F1& q, const F1& v, const F1& a, const F2& vint,
                          const ArchiveBuffers& out, double dt_used, double dt_next,
                          std::int64_t rejected) {
    const std::int64_t i = c.counters(K_STEP) + 1;
    const double ieps = static_cast<double>(i) * c.eps;
    const bool adaptive = c.counters(K_ADAPTIVE) == 1;
    const double dt_stored = c.clock(C_STEP);
    c.counters(K_REJECTED) += rejected;
    if (dt_used < c.clock(C_MIN_STEP)) c.clock(C_MIN_STEP) = dt_used;
    if (dt_used > c.clock(C_MAX_STEP)) c.clock(C_MAX_STEP) = dt_used;
    double t = c.clock(C_TIME) + dt_used;
    c.clock(C_STEP) = adaptive ? dt_next : dt_stored;
    c.counters(K_STEP) = i;
    const std::int64_t k = c.counters(K_INSTANT);
    if (c.counters(K_FORCE) == 2) {
        c.counters(K_FORCE) = 0;
        if (!adaptive) c.clock(C_STEP) = c.clock(C_STEP0);
    }
    const bool landing = c.counters(K_FORCE) == 1 && std::fabs(t - c.instants(k)) <= ieps;
    if (!adaptive) {
        if (landing) {  // a step not cut short to land there completes its interval
            if (std::fabs(dt_stored - c.clock(C_NEWDT)) <= ieps) c.counters(K_GRID) += 1;
        } else {
            t = grid_instant(c, t);
        }
    }
    if (c.counters(K_FORCE) == 1) {
        if (landing) {
            t = c.instants(k);
            archive(out, c.counters(K_ARCHIVED), t, i, q, v, a, vint, dt_used,
                    c.counters(K_REJECTED));
            c.counters(K_ARCHIVED) += 1;
            c.counters(K_INSTANT) = k + 1;
            c.counters(K_FORCE) = 0;
            if (std::fabs(dt_stored - c.clock(C_NEWDT)) > ieps) {
                c.counters(K_IRREGULAR) += 1;
                c.clock(C_STEP) = dt_stored - c.clock(C_NEWDT);
                c.counters(K_FORCE) = 2;
            } else if (!adaptive) {
                c.clock(C_STEP) = c.clock(C_STEP0);
            }
        }
    } else if (python_mod(i - c.counters(K_IRREGULAR), c.pas_arch) == 0) {
        archive(out, c.counters(K_ARCHIVED), t, i, q, v, a, vint, dt_used, c.counters(K_REJECTED));
        c.counters(K_ARCHIVED) += 1;
    }
    c.clock(C_TIME) = t;
}

}  // namespace asterlite
