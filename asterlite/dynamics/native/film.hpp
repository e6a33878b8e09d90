// Fluid-film shocks and their two loops (asterlite.dynamics.fluid_film):
// code_aster 11's EULER (run_loop) and its ADAPT_ORDRE2 (run_adapt_loop,
// mdadap's step control of scheme_adapt_legacy.hpp), the end acceleration of
// each step found by fixed-point iterations on the film's added mass, on
// diagonal matrices given as 1-D arrays, the shocks in their local frames.
#pragma once

#include <cmath>
#include <cstdint>

#include "clock.hpp"
#include "contact.hpp"
#include "forces.hpp"
#include "layout.hpp"
#include "loads.hpp"
#include "model.hpp"
#include "python_math.hpp"
#include "scheme_adapt_legacy.hpp"
#include "views.hpp"

namespace asterlite {
namespace film {

// columns of the per-shock film rows (fluid_film.FL_*)
enum FilmColumn : int { FL_ON, FL_ALPHA, FL_BETA, FL_CHI, FL_DELTA, FL_LAYER, FL_THICKNESS };
constexpr index N_FILM = 7;
// status of a step whose fixed-point iterations did not converge
constexpr int STATUS_FILM_NOT_CONVERGED = 20;
// the film's counts: last residual ratio, iterations of the worst step, total
enum Count : int { S_RATIO, S_WORST, S_TOTAL };
// kin[]: local y, z of node 1 and node 2, then the relative position,
// velocity and acceleration (node 1 - node 2, local frame)
enum Kin : int { KIN_Y1 = 0, KIN_Z1 = 1, KIN_Y2 = 2, KIN_Z2 = 3, KIN_X = 4, KIN_V = 7, KIN_A = 10 };
constexpr index N_KIN = 13;

// the diagonals of M, K, C (integrate_film's ``linear``)
struct FilmLinear {
    F1 mass, stiffness, damping;
};

// integrate_film's ``model``: the shocks in their local frames, the film rows
// (their boundary-layer state written), the added-mass weights
struct FilmModel {
    I2 flags;
    F2 params;
    F4 shapes;
    F3 rest;
    F3 polars;
    F2 film;
    F2 weights;
};

// integrate_film's ``exc`` (excitation.Excitation.bundle()): the loads, and
// the support motions' tables, read only by loads_ready
struct FilmLoads {
    Loads loads;
    Supports sup;
};

// integrate_film's ``work``: base force, force, modified mass, kinematics
struct FilmWork {
    F1 base, f, mass_mod, kin;
};

// blend: the film force's weight in the boundary layer (ponder)
inline double blend(double gap, double thickness) {
    if (gap >= thickness) return 1.0;
    if (gap <= 0.5 * thickness) return 0.0;
    return (gap - 0.5 * thickness) / (0.5 * thickness);
}

// kinematics: local (y, z) of both nodes and the relative position, velocity
// and acceleration of shock s into kin
inline void kinematics(index s, const F1& q, const F1& v, const F1& a, const FilmModel& model,
                       const F1& kin) {
    const bool two_nodes = model.flags(s, F_TWO_NODES) == 1;
    const index nodes = two_nodes ? 2 : 1;
    for (index node = 0; node < nodes; ++node) {
        const double sign = node == 0 ? 1.0 : -1.0;
        for (index i = 0; i < 3; ++i) {
            double x = model.rest(s, node, i);
            double u = 0.0;
            double w = 0.0;
            for (index m = 0; m < q.n0; ++m) {
                x += model.shapes(s, node, i, m) * q(m);
                u += model.shapes(s, node, i, m) * v(m);
                w += model.shapes(s, node, i, m) * a(m);
            }
            if (node == 0) {
                kin(KIN_X + i) = x;
                kin(KIN_V + i) = u;
                kin(KIN_A + i) = w;
            } else {
                kin(KIN_X + i) += sign * x;
                kin(KIN_V + i) += sign * u;
                kin(KIN_A + i) += sign * w;
            }
            if (i > 0) kin(2 * node + i - 1) = x;
        }
    }
    if (!two_nodes) {
        kin(KIN_Y2) = 0.0;
        kin(KIN_Z2) = 0.0;
    }
}

inline Gap shock_gap(index s, const FilmModel& model, const F1& kin) {
    const F2& params = model.params;
    return obstacle_gap(model.flags(s, F_GEOMETRY), kin(KIN_Y1), kin(KIN_Z1), kin(KIN_Y2),
                        kin(KIN_Z2), params(s, P_GAP), params(s, P_DIST1), params(s, P_DIST2),
                        params(s, P_SIGN_Y), params(s, P_SIGN_Z), model.polars, s,
                        model.flags(s, F_NPOLAR));
}

// add_local_force: out += Phi^T f at node 1 and -Phi^T f at node 2
inline void add_local_force(index s, const FilmModel& model, double fx, double fy, double fz,
                            const F1& out) {
    const F4& shapes = model.shapes;
    for (index m = 0; m < out.n0; ++m) {
        out(m) += shapes(s, 0, 0, m) * fx + shapes(s, 0, 1, m) * fy + shapes(s, 0, 2, m) * fz;
    }
    if (model.flags(s, F_TWO_NODES) == 1) {
        for (index m = 0; m < out.n0; ++m) {
            out(m) -= shapes(s, 1, 0, m) * fx + shapes(s, 1, 1, m) * fy + shapes(s, 1, 2, m) * fz;
        }
    }
}

inline void store_positions(index s, const F1& q, const FilmModel& model, const F2& vint) {
    for (index node = 0; node < 2; ++node) {
        for (index i = 0; i < 3; ++i) {
            double x = 0.0;
            if (node == 0 || model.flags(s, F_TWO_NODES) == 1) {
                x = model.rest(s, node, i);
                for (index m = 0; m < q.n0; ++m) x += model.shapes(s, node, i, m) * q(m);
            }
            vint(s, (node == 0 ? V_LOC1 : V_LOC2) + i) = x;
        }
    }
}

// dry_shock_forces: the DIS_CHOC force of every shock without film added to
// out; a shock whose velocity diverged, or -1
inline index dry_shock_forces(const F1& q, const F1& v, const F1& a, const FilmModel& model,
                              const F2& vint, const F1& kin, const F1& out) {
    for (index s = 0; s < model.flags.n0; ++s) {
        if (model.film(s, FL_ON) != 0.0) continue;
        kinematics(s, q, v, a, model, kin);
        store_positions(s, q, model, vint);
        const Gap g = shock_gap(s, model, kin);
        const LocalForce lf = contact_law(
            model.params, model.flags(s, F_UNIDIR) == 1, vint, s, g.gap, g.cos_n, g.sin_n,
            kin(KIN_X), kin(KIN_X + 1), kin(KIN_X + 2), kin(KIN_V), kin(KIN_V + 1),
            kin(KIN_V + 2));
        if (lf.diverged) return s;
        if (lf.in_contact) add_local_force(s, model, lf.fx, lf.fy, lf.fz, out);
    }
    return -1;
}

// film_forces: every film shock's force at the acceleration iterate a added
// to f, its added-mass stand-in added to mass (M') and, times a, to f; the
// boundary-layer state updated in the film rows
inline void film_forces(const F1& q, const F1& v, const F1& a, const FilmModel& model,
                        const F2& vint, const F1& kin, const F1& f, const F1& mass) {
    const F2& film = model.film;
    const F2& params = model.params;
    for (index s = 0; s < model.flags.n0; ++s) {
        if (film(s, FL_ON) == 0.0) continue;
        kinematics(s, q, v, a, model, kin);
        store_positions(s, q, model, vint);
        const Gap g = shock_gap(s, model, kin);
        const double gap = g.gap, cos_n = g.cos_n, sin_n = g.sin_n;
        const double vn = kin(KIN_V + 1) * cos_n + kin(KIN_V + 2) * sin_n;
        const double an = kin(KIN_A + 1) * cos_n + kin(KIN_A + 2) * sin_n;
        double thickness = film(s, FL_THICKNESS);
        double f_film = 0.0;
        if (gap > 0.0) {
            const double ratio = vn / gap;
            f_film = film(s, FL_ALPHA) * an / gap + film(s, FL_BETA) * (ratio * ratio) +
                     film(s, FL_CHI) * vn / int_power(gap, 3) +
                     film(s, FL_DELTA) * vn * std::fabs(vn) / (gap * gap);
            if (film(s, FL_LAYER) == 1.0) {
                if (gap >= thickness) {  // out of the boundary layer
                    film(s, FL_LAYER) = 0.0;
                    film(s, FL_THICKNESS) = 0.0;
                    thickness = 0.0;
                }
            } else {
                thickness = f_film / params(s, P_KN);
                if (gap <= thickness) {  // into the boundary layer: its thickness is kept
                    film(s, FL_LAYER) = 1.0;
                    film(s, FL_THICKNESS) = thickness;
                }
            }
            const double weight = blend(gap, thickness);
            f_film *= weight;
            add_local_force(s, model, 0.0, f_film * cos_n, f_film * sin_n, f);
            const double added = -film(s, FL_ALPHA) * weight / gap;
            for (index m = 0; m < f.n0; ++m) {
                mass(m) += added * model.weights(s, m);
                f(m) += added * model.weights(s, m) * a(m);
            }
        }
        double f_dry = 0.0;
        if (gap <= thickness) {
            f_dry = -params(s, P_KN) * (gap - thickness) - params(s, P_CN) * vn;
            f_dry = py_max(f_dry, 0.0) * (1.0 - blend(gap, thickness));
            add_local_force(s, model, 0.0, f_dry * cos_n, f_dry * sin_n, f);
        }
        vint(s, V_FN) = f_film + f_dry;
        vint(s, V_VN) = vn;
    }
}

struct Iterate {
    double change, size;
    bool finite;
};

// film_acceleration: a <- (f - K q - C v) / M' with the film at the iterate
// a; (|a_new - a|^2, |a_new|^2, finite)
inline Iterate film_acceleration(const F1& q, const F1& v, const F1& a, const F1& base,
                                 const FilmLinear& lin, const FilmModel& model, const F2& vint,
                                 const F1& kin, const F1& f, const F1& mass_mod) {
    for (index m = 0; m < q.n0; ++m) {
        f(m) = base(m);
        mass_mod(m) = lin.mass(m);
    }
    film_forces(q, v, a, model, vint, kin, f, mass_mod);
    double change = 0.0, size = 0.0;
    bool finite = true;
    for (index m = 0; m < q.n0; ++m) {
        const double next = (f(m) - lin.stiffness(m) * q(m) - lin.damping(m) * v(m)) / mass_mod(m);
        if (!(std::fabs(next) < 1.0e300)) finite = false;
        const double d = next - a(m);
        change += d * d;
        size += next * next;
        a(m) = next;
    }
    return {change, size, finite};
}

// external_force: out = F_ext(t)
inline void external_force(double t, const Loads& loads, const F1& out) {
    for (index m = 0; m < out.n0; ++m) out(m) = 0.0;
    add_external_force(t, loads, out);
}

// start: the initial acceleration, one evaluation with a zero acceleration
// in the film law (code_aster 11 starts so); a failing shock or -1, and
// whether the acceleration is finite
inline index start(double t0, const F1& q, const F1& v, const F1& a, const FilmLinear& lin,
                   const FilmModel& model, const Loads& loads, const F2& vint,
                   const FilmWork& work, bool& finite) {
    external_force(t0, loads, work.base);
    for (index m = 0; m < a.n0; ++m) a(m) = 0.0;
    const index shock = dry_shock_forces(q, v, a, model, vint, work.kin, work.base);
    finite = film_acceleration(q, v, a, work.base, lin, model, vint, work.kin, work.f,
                               work.mass_mod)
                 .finite;
    return shock;
}

// one fixed-point iteration's bookkeeping: the counts, and whether it
// converged (``iteration``: its number from 1)
inline bool count_iteration(const Iterate& it, std::int64_t iteration, double tolerance,
                            const F1& counts) {
    counts(S_TOTAL) += 1.0;
    counts(S_RATIO) = it.size > 0.0 ? it.change / it.size : 0.0;
    if (it.change <= tolerance * it.size) {
        counts(S_WORST) = py_max(counts(S_WORST), static_cast<double>(iteration));
        return true;
    }
    return false;
}

// run_loop: the EULER loop with fluid films; the kernel's statuses and
// archiving rules, plus STATUS_FILM_NOT_CONVERGED
inline int run_loop(const Clock& c, const F1& q, const F1& v, const F1& a, const F2& vint,
                    const FilmLinear& lin, const FilmModel& model, const FilmLoads& exc,
                    const F1& controls, const F1& scalars, const FilmWork& work,
                    const ArchiveBuffers& out) {
    const std::int64_t max_iterations = static_cast<std::int64_t>(controls(0));
    const double tolerance = controls(1);
    const index n = q.n0;
    while (unfinished(c)) {
        const int paused = pause_status(c, out);
        if (paused) return paused;
        if (!adapt_legacy::loads_ready(c, exc.loads, exc.sup)) return STATUS_LOADS;
        double t, dt;
        plan_step(c, t, dt);
        for (index i = 0; i < n; ++i) {
            v(i) += dt * a(i);
            q(i) += dt * v(i);
        }
        external_force(t + dt, exc.loads, work.base);
        const index shock = dry_shock_forces(q, v, a, model, vint, work.kin, work.base);
        if (shock >= 0) return record_failure(c, STATUS_SHOCK_DIVERGED, shock, dt);
        bool converged = false;
        for (std::int64_t iteration = 1; iteration < max_iterations + 1; ++iteration) {
            const Iterate it = film_acceleration(q, v, a, work.base, lin, model, vint, work.kin,
                                                 work.f, work.mass_mod);
            if (!it.finite) return record_failure(c, STATUS_NOT_FINITE, -1, dt);
            if (count_iteration(it, iteration, tolerance, scalars)) {
                converged = true;
                break;
            }
        }
        if (!converged) return record_failure(c, STATUS_FILM_NOT_CONVERGED, -1, dt);
        advance_clock(c, q, v, a, vint, out, dt, dt, 0);
    }
    return STATUS_DONE;
}

// film_trial: one trial of mdadap's step dt with fluid films: the leapfrog
// prediction, then the end acceleration by the iterations started from the
// step's start; a shock >= 0 or an adapt_legacy::Trial code
inline index film_trial(double t, double dt, const State& x, const F2& rows, const F1& scalars,
                        const FilmLinear& lin, const FilmModel& model, const Loads& loads,
                        const F1& controls, const F1& counts, const FilmWork& work) {
    using namespace adapt_legacy;
    const F1 q2 = row(rows, Q_TRIAL), v2 = row(rows, V_TRIAL), a2 = row(rows, A_TRIAL);
    predict(dt, x, rows, scalars);
    copy_into(x.vint, x.vint_save);  // the dry shocks' states of the step's start
    copy_into(a2, x.a);
    external_force(t + dt, loads, work.base);
    const index shock = dry_shock_forces(q2, v2, a2, model, x.vint, work.kin, work.base);
    if (shock >= 0) return shock;
    const std::int64_t max_iterations = static_cast<std::int64_t>(controls(0));
    for (std::int64_t iteration = 1; iteration < max_iterations + 1; ++iteration) {
        const Iterate it = film_acceleration(q2, v2, a2, work.base, lin, model, x.vint, work.kin,
                                             work.f, work.mass_mod);
        if (!it.finite) return TRIAL_NOT_FINITE;
        if (count_iteration(it, iteration, controls(1), counts)) return TRIAL_DONE;
    }
    return TRIAL_NOT_CONVERGED;
}

// run_adapt_loop: code_aster 10-12's ADAPT_ORDRE2 with fluid films
// (adapt_step: mdadap's control around film_trial); resumable after any pause
inline int run_adapt_loop(const Clock& c, const State& x, const Memory& memory,
                          const FilmLinear& lin, const FilmModel& model, const FilmLoads& exc,
                          const F1& controls, const F1& counts, const FilmWork& work,
                          const ArchiveBuffers& out, std::int64_t pas_arch) {
    const F2& rows = memory.rows;
    const F1& scalars = memory.scalars;
    return adapt_legacy::adapt_loop(
        c, x, rows, scalars, out, pas_arch,
        [&]() { return adapt_legacy::loads_ready(c, exc.loads, exc.sup); },
        [&]() {
            return adapt_legacy::take_step(
                c, x, rows, scalars, out, STATUS_FILM_NOT_CONVERGED, [&](double t, double dt) {
                    return film_trial(t, dt, x, rows, scalars, lin, model, exc.loads, controls,
                                      counts, work);
                });
        });
}

}  // namespace film
}  // namespace asterlite
