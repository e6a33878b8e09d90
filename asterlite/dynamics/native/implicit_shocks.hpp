// Shocks treated implicitly (asterlite.dynamics.implicit_shocks): the DIS_CHOC
// shocks in contact linearised into K and C, each step saved, integrated,
// checked for a change of contact configuration and, when the switch lies
// inside the step, integrated again up to it; the scheme's step through the
// dispatch (dispatch.hpp) on the general model.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

#include "clock.hpp"
#include "contact.hpp"
#include "dispatch.hpp"
#include "loop.hpp"
#include "loop_steps.hpp"
#include "model.hpp"
#include "python_math.hpp"
#include "views.hpp"

namespace asterlite {
namespace implicit_shocks {

constexpr double CONTACT_FORCE = DBL_EPSILON;  // code_aster's r8prem
constexpr double CUT_TOLERANCE = 0.01;  // a switch within 1 % of a step from its end is made there
constexpr double SHORTEST_CUT = 1.0e-10;  // s: no shorter re-integrated step
constexpr std::int64_t MAX_TRIES = 100;   // re-integrations of one step
constexpr double NORMAL_TURN = 1.0e-3;    // rad
enum Int : index { I_TRIES, I_SWITCHES, I_CUTS, I_TURNS };
constexpr index N_INTS = 4;
enum Kinematics : index {
    R_GAP0, R_VN0, R_FORCE0, R_COS0, R_SIN0, R_GAP1, R_VN1, R_FORCE1, R_COS1, R_SIN1,
};
constexpr index N_KINEMATICS = 10;

// layouts.Treatment (implicit_shocks.prepare)
struct Treatment {
    F2 stiffness0, damping0;
    I1 diagonal0;
    I1 active, trial, ints;
    F2 kinematics, gradient, work;
    F2 backup_rows;
    F1 backup_scalars;
    F2 keep;
    F3 vint_keep;
    I1 active_at_start;
    F1 planned;
};

struct Kinematic {
    double gap, cos_n, sin_n, vn;
};

// implicit_shocks.shock_kinematics: (gap, cos_n, sin_n, normal velocity) of
// DIS_CHOC s at (q, v); work rows 0-3 as there
inline Kinematic shock_kinematics(index s, const F1& q, const F1& v, const Shocks& shk,
                                  const F2& work) {
    double* loc1 = &work(0, 0);
    double* vel1 = &work(1, 0);
    double* loc2 = &work(2, 0);
    double* vel2 = &work(3, 0);
    const F2& params = shk.params;
    local_state(shk, s, 0, P_COORD1, P_DRIVE1, q, v, loc1, vel1);
    const bool two_nodes = shk.flags(s, F_TWO_NODES) == 1;
    if (two_nodes) {
        local_state(shk, s, 1, P_COORD2, P_DRIVE2, q, v, loc2, vel2);
    } else {
        for (index i = 0; i < 3; ++i) {
            loc2[i] = 0.0;
            vel2[i] = 0.0;
        }
    }
    const Gap g = obstacle_gap(shk.flags(s, F_GEOMETRY), loc1[1], loc1[2], loc2[1], loc2[2],
                               params(s, P_GAP), params(s, P_DIST1), params(s, P_DIST2),
                               params(s, P_SIGN_Y), params(s, P_SIGN_Z), shk.polars, s,
                               shk.flags(s, F_NPOLAR));
    double vy = vel1[1], vz = vel1[2];
    if (two_nodes) {
        vy -= vel2[1];
        vz -= vel2[2];
    }
    return {g.gap, g.cos_n, g.sin_n, vy * g.cos_n + vz * g.sin_n};
}

// implicit_shocks.indicators: gap, normal velocity, unclipped normal force
// and normal of every DIS_CHOC into kinematics[first_row:first_row + 5], and
// whether each is in contact
inline void indicators(const F1& q, const F1& v, const Shocks& shk, const F2& kinematics,
                       index first_row, const I1& in_contact, const F2& work) {
    const F2& params = shk.params;
    for (index s = 0; s < shk.flags.n0; ++s) {
        in_contact(s) = 0;
        if (shk.flags(s, F_LAW) != 0) continue;
        const Kinematic k = shock_kinematics(s, q, v, shk, work);
        const double force = -params(s, P_KN) * k.gap - params(s, P_CN) * k.vn;
        kinematics(first_row, s) = k.gap;
        kinematics(first_row + 1, s) = k.vn;
        kinematics(first_row + 2, s) = force;
        kinematics(first_row + 3, s) = k.cos_n;
        kinematics(first_row + 4, s) = k.sin_n;
        if (k.gap <= 0.0 && force > CONTACT_FORCE) in_contact(s) = 1;
    }
}

// implicit_shocks.switch_fraction: the fraction of the step at which the
// first shock that changed state did so
inline double switch_fraction(const I1& active, const I1& trial, const F2& kinematics) {
    double ratio = 1.0;
    for (index s = 0; s < active.n0; ++s) {
        if (active(s) == trial(s)) continue;
        const double gap0 = kinematics(R_GAP0, s), gap1 = kinematics(R_GAP1, s);
        const double force0 = kinematics(R_FORCE0, s), force1 = kinematics(R_FORCE1, s);
        double x0, x1;
        if (trial(s) == 1) {  // entry: distance to the switch, positive at the start
            if (gap0 > 0.0) {
                x0 = gap0;
                x1 = gap1;
            } else {
                x0 = -force0;
                x1 = -force1;
            }
        } else if (gap1 <= 0.0 || force1 <= 0.0) {  // exit through the force
            if (force1 <= 0.0) {
                x0 = force0;
                x1 = force1;
            } else {
                x0 = -gap0;
                x1 = -gap1;
            }
        } else {
            x0 = -gap0;
            x1 = -gap1;
        }
        if (x0 - x1 > 0.0) ratio = py_min(ratio, x0 / (x0 - x1));
    }
    return ratio;
}

// implicit_shocks.normal_turned: whether a linearised shock's normal turned
// by more than NORMAL_TURN since its linearisation
inline bool normal_turned(const I1& active, const F2& params, const F2& kinematics) {
    for (index s = 0; s < active.n0; ++s) {
        if (active(s) == 0) continue;
        const double cross = params(s, P_LIN_COS) * kinematics(R_SIN1, s) -
                             params(s, P_LIN_SIN) * kinematics(R_COS1, s);
        const double dot = params(s, P_LIN_COS) * kinematics(R_COS1, s) +
                           params(s, P_LIN_SIN) * kinematics(R_SIN1, s);
        if (std::fabs(cross) > NORMAL_TURN || dot < 0.0) return true;
    }
    return false;
}

// implicit_shocks.switch (a C++ keyword): linearise the shocks in contact at
// q (tr.trial): K = K0 + sum k_n g g^T, C = C0 + sum c_n g g^T into the
// model's bundle, the gap term and normal into each shock's parameters,
// every DIS_CHOC's treatment flag set (``flags``: the writable shock flags);
// they become the active set. ``flag``: the bundle's diagonal flag (array),
// copied into the model
inline void switch_contacts(const F1& q, const Shocks& shk, const I2& flags, Linear& lin,
                            const I1& flag, const Treatment& tr) {
    const F2& params = shk.params;
    const index n = q.n0;
    copy_into(lin.stiffness, tr.stiffness0);
    copy_into(lin.damping, tr.damping0);
    const F1 gradient = row(tr.gradient, 0);
    double* normal = &tr.work(4, 0);
    std::int64_t linearised = 0;
    for (index s = 0; s < flags.n0; ++s) {
        tr.active(s) = tr.trial(s);
        if (flags(s, F_LAW) != 0 || tr.trial(s) == 0) continue;
        linearised += 1;
        const Kinematic k = shock_kinematics(s, q, q, shk, tr.work);
        normal[0] = 0.0;
        normal[1] = k.cos_n;
        normal[2] = k.sin_n;
        for (index i = 0; i < gradient.n0; ++i) gradient(i) = 0.0;
        add_generalized_force(shk.rots, shk.phis, s, 0, normal, 1.0, gradient);
        if (flags(s, F_TWO_NODES) == 1) {
            add_generalized_force(shk.rots, shk.phis, s, 1, normal, -1.0, gradient);
        }
        double projected = 0.0;
        for (index i = 0; i < n; ++i) projected += gradient(i) * q(i);
        params(s, P_LIN_GAP) = k.gap - projected;
        params(s, P_LIN_COS) = k.cos_n;
        params(s, P_LIN_SIN) = k.sin_n;
        const double k_n = params(s, P_KN), c_n = params(s, P_CN);
        for (index i = 0; i < n; ++i) {
            for (index j = 0; j < n; ++j) {
                lin.stiffness(i, j) += k_n * gradient(i) * gradient(j);
                lin.damping(i, j) += c_n * gradient(i) * gradient(j);
            }
        }
    }
    for (index s = 0; s < flags.n0; ++s) {
        if (flags(s, F_LAW) != 0) continue;
        if (linearised == 0) {
            flags(s, F_IMPLICIT) = NORMAL_EXPLICIT;
        } else if (tr.active(s) == 1) {
            flags(s, F_IMPLICIT) = NORMAL_LINEARISED;
        } else {
            flags(s, F_IMPLICIT) = NORMAL_LEFT_OUT;
        }
    }
    flag(0) = linearised == 0 ? tr.diagonal0(0) : 0;
    lin.diagonal = flag(0) == 1;  // read_model's reading of the flag
    tr.ints(I_SWITCHES) += 1;
}

// what save/restore copy besides the treatment's arrays: the clock and counters
struct ClockCopy {
    std::vector<double> clock;
    std::vector<std::int64_t> counters;
};

// implicit_shocks.save: the scheme's rows and scalars, the clock, the
// counters, q v a f, the internal variables and their save
inline void save(const Clock& c, const State& x, const Memory& memory, const Treatment& tr,
                 ClockCopy& copy) {
    copy_into(tr.backup_rows, memory.rows);
    copy_into(tr.backup_scalars, memory.scalars);
    for (index i = 0; i < c.clock.n0; ++i) copy.clock[i] = c.clock(i);
    for (index i = 0; i < c.counters.n0; ++i) copy.counters[i] = c.counters(i);
    copy_into(row(tr.keep, 0), x.q);
    copy_into(row(tr.keep, 1), x.v);
    copy_into(row(tr.keep, 2), x.a);
    copy_into(row(tr.keep, 3), x.f);
    copy_into(slice(tr.vint_keep, 0), x.vint);
    copy_into(slice(tr.vint_keep, 1), x.vint_save);
}

// implicit_shocks.restore: the reverse
inline void restore(const Clock& c, const State& x, const Memory& memory, const Treatment& tr,
                    const ClockCopy& copy) {
    copy_into(memory.rows, tr.backup_rows);
    copy_into(memory.scalars, tr.backup_scalars);
    for (index i = 0; i < c.clock.n0; ++i) c.clock(i) = copy.clock[i];
    for (index i = 0; i < c.counters.n0; ++i) c.counters(i) = copy.counters[i];
    copy_into(x.q, row(tr.keep, 0));
    copy_into(x.v, row(tr.keep, 1));
    copy_into(x.a, row(tr.keep, 2));
    copy_into(x.f, row(tr.keep, 3));
    copy_into(x.vint, slice(tr.vint_keep, 0));
    copy_into(x.vint_save, slice(tr.vint_keep, 1));
}

// implicit_shocks.implicit_loop: the time loop of the scheme ``code`` with
// the implicit treatment. ``flags``: the shock flags (writable), ``flag``:
// the linear bundle's diagonal flag (array). A ZeroDivisionError of numba's
// step is returned at once as STATUS_ZERO_DIVISION (numba raises there)
inline int implicit_loop(std::int64_t code, const Clock& c, const State& x, const Memory& memory,
                         Model& model, const ArchiveBuffers& out,
                         const energy::Balance& balance, const I2& flags, const I1& flag,
                         const Treatment& tr) {
    ClockCopy copy{std::vector<double>(c.clock.n0), std::vector<std::int64_t>(c.counters.n0)};
    const index n = x.q.n0;
    const bool active_balance = balance.active();
    const I1 &active = tr.active, &trial = tr.trial, &ints = tr.ints;
    const F2& kinematics = tr.kinematics;
    while (unfinished(c)) {
        const int paused = before_step(c, out, model);
        if (paused) return paused;
        save(c, x, memory, tr, copy);
        double t, dt;
        plan_step(c, t, dt);
        const StepResult r =
            dispatch::scheme_step(code, t, dt, c.counters(K_STEP), x, memory, model);
        if (r.status == STATUS_ZERO_DIVISION) return r.status;
        if (r.status != STATUS_DONE) return record_failure(c, r.status, r.shock, r.dt_used);
        indicators(x.q, x.v, model.shk, kinematics, R_GAP1, trial, tr.work);
        bool changed = false;
        for (index s = 0; s < trial.n0; ++s) {
            if (trial(s) != active(s)) changed = true;
        }
        if (changed) {
            if (ints(I_TRIES) == 0) tr.planned(0) = r.dt_used;  // the step before any cut
            indicators(row(tr.keep, 0), row(tr.keep, 1), model.shk, kinematics, R_GAP0,
                       tr.active_at_start, tr.work);
            const double ratio = switch_fraction(active, trial, kinematics);
            const double early = ratio * r.dt_used, late = (1.0 - ratio) * r.dt_used;
            if (late > CUT_TOLERANCE * tr.planned(0)) {  // not at the end of the step
                if (ints(I_TRIES) >= MAX_TRIES) {
                    return record_failure(c, STATUS_SWITCH_NOT_LOCATED, -1, dt);
                }
                restore(c, x, memory, tr, copy);
                ints(I_TRIES) += 1;
                ints(I_CUTS) += 1;
                if (early > CUT_TOLERANCE * tr.planned(0) && early > SHORTEST_CUT) {
                    c.clock(C_STEP) = early;  // integrate up to the switch
                } else {  // the switch is at the start: the whole step in the new configuration
                    switch_contacts(x.q, model.shk, flags, model.lin, flag, tr);
                    dispatch::refresh_operators(code, memory, model.lin, n);
                }
                continue;
            }
        }
        const std::int64_t archived = c.counters(K_ARCHIVED);
        advance_clock(c, x.q, x.v, x.a, x.vint, out, r.dt_used, r.dt_next, r.rejected);
        if (changed || normal_turned(active, model.shk.params, kinematics)) {
            switch_contacts(x.q, model.shk, flags, model.lin, flag, tr);
            dispatch::refresh_operators(code, memory, model.lin, n);
            if (!changed) {
                ints(I_SWITCHES) -= 1;
                ints(I_TURNS) += 1;
            }
        }
        if (ints(I_TRIES) > 0) {  // after a cut step, the user's step again
            c.clock(C_STEP) = c.clock(C_STEP0);
            ints(I_TRIES) = 0;
        }
        if (active_balance) {
            energy::after_step(balance, archived, c.counters(K_ARCHIVED), c.clock(C_TIME),
                               r.dt_used, x.q, x.v, x.a, x.vint, model);
        }
    }
    return STATUS_DONE;
}

}  // namespace implicit_shocks
}  // namespace asterlite
