// DIFF_CENTRE's specialised loop (scheme_diff_centre.specialised_loop):
// v += dt a, q += dt v, then a from the equations of motion at the new
// state, the shocks in their local frames; diagonal matrices as 1-D arrays
// (template parameter) or full (n, n) ones.
#pragma once

#include <cmath>
#include <type_traits>

#include "clock.hpp"
#include "contact.hpp"
#include "layout.hpp"
#include "loads.hpp"
#include "views.hpp"

namespace asterlite {

inline bool is_finite_entry(double x) { return std::fabs(x) < 1.0e300; }

// forces.diagonal_acceleration: a = (f - k q - c v) / m in one pass
inline bool diagonal_acceleration(const F1& a, const F1& f, const F1& q, const F1& v,
                                  const F1& mass_inverse, const F1& stiffness,
                                  const F1& damping) {
    bool finite = true;
    for (index i = 0; i < a.n0; ++i) {
        const double x = (f(i) - stiffness(i) * q(i) - damping(i) * v(i)) * mass_inverse(i);
        a(i) = x;
        if (!is_finite_entry(x)) finite = false;
    }
    return finite;
}

// forces.full_acceleration: a = M^-1 (f - K q - C v)
inline bool full_acceleration(const F1& a, const F1& f, const F1& q, const F1& v,
                              const F2& mass_inverse, const F2& stiffness, const F2& damping,
                              const F1& residual) {
    const index n = a.n0;
    for (index i = 0; i < n; ++i) {
        double sk = 0.0, sc = 0.0;
        for (index j = 0; j < n; ++j) sk += stiffness(i, j) * q(j);
        for (index j = 0; j < n; ++j) sc += damping(i, j) * v(j);
        residual(i) = f(i) - sk - sc;
    }
    bool finite = true;
    for (index i = 0; i < n; ++i) {
        double s = 0.0;
        for (index j = 0; j < n; ++j) s += mass_inverse(i, j) * residual(j);
        a(i) = s;
        if (!is_finite_entry(s)) finite = false;
    }
    return finite;
}

// forces.matvec_add: out += coef a x (the diagonal of a only when diagonal)
inline void matvec_add(const F2& a, const F1& x, double coef, const F1& out, bool diagonal) {
    const index n = out.n0;
    if (diagonal) {
        for (index i = 0; i < n; ++i) out(i) += coef * a(i, i) * x(i);
    } else {
        for (index i = 0; i < n; ++i) {
            double s = 0.0;
            for (index j = 0; j < n; ++j) s += a(i, j) * x(j);
            out(i) += coef * s;
        }
    }
}

// forces.acceleration on the (n, n) matrices of the linear bundle
inline void acceleration(const F1& f, const F1& q, const F1& v, const F2& minv,
                         const F2& stiffness, const F2& damping, bool diagonal,
                         const F1& residual, const F1& out) {
    for (index i = 0; i < f.n0; ++i) residual(i) = f(i);
    matvec_add(stiffness, q, -1.0, residual, diagonal);
    matvec_add(damping, v, -1.0, residual, diagonal);
    for (index i = 0; i < out.n0; ++i) out(i) = 0.0;
    matvec_add(minv, residual, 1.0, out, diagonal);
}

// forces.total_force for DIS_CHOC shocks: out = F_ext(t) + Phi^T F_shock,
// the support motion written into the shocks' parameters
inline index total_force(double t, const F1& q, const F1& v, const Shocks& shk, const F4& phis,
                         const Loads& loads, const Supports& sup, const F2& vint,
                         const F2& work, const F1& out) {
    for (index m = 0; m < out.n0; ++m) out(m) = 0.0;
    add_external_force(t, loads, out);
    support_motion(t, sup, shk.params);
    return shock_forces(q, v, shk, phis, vint, work, out);
}

struct Local {
    F4 shapes;  // (n_shocks, 2, 3, n_modes): rot Phi
    F3 rest;    // (n_shocks, 2, 3): rot (coord - origin)
    F3 drive;   // (n_shocks, 2, 6): support motion in the local frames
};

struct State {
    F1 q, v, a, f;
    F2 vint;
    F1 residual;
};

template <class Matrix>
int diff_centre_loop(const Clock& c, const State& x, const Matrix& mass_inverse,
                     const Matrix& stiffness, const Matrix& damping, const Shocks& shk,
                     const Local& local, const Loads& loads, const Supports& sup,
                     const ArchiveBuffers& out) {
    const index n = x.q.n0;
    while (unfinished(c)) {
        const int paused = pause_status(c, out);
        if (paused) return paused;
        const double t_ahead = c.clock(C_TIME) + 2.0 * c.clock(C_STEP);
        if (!(loads_cover(t_ahead, loads.tables) && loads_cover(t_ahead, sup.tables))) {
            return STATUS_LOADS;
        }
        double t, dt;
        plan_step(c, t, dt);
        for (index i = 0; i < n; ++i) {
            x.v(i) += dt * x.a(i);
            x.q(i) += dt * x.v(i);
        }
        const double t_new = t + dt;
        external_force_into(t_new, loads, x.f);
        local_support_motion(t_new, shk.rots, sup, local.drive);
        const index shock =
            local_shock_forces(x.q, x.v, shk, local.shapes, local.rest, local.drive, x.vint, x.f);
        if (shock >= 0) return record_failure(c, STATUS_SHOCK_DIVERGED, shock, dt);
        bool finite;
        if constexpr (std::is_same_v<Matrix, F1>) {
            finite = diagonal_acceleration(x.a, x.f, x.q, x.v, mass_inverse, stiffness, damping);
        } else {
            finite = full_acceleration(x.a, x.f, x.q, x.v, mass_inverse, stiffness, damping,
                                       x.residual);
        }
        if (!finite) return record_failure(c, STATUS_NOT_FINITE, -1, dt);
        advance_clock(c, x.q, x.v, x.a, x.vint, out, dt, dt, 0);
    }
    return STATUS_DONE;
}

}  // namespace asterlite
