// DIFF_CENTRE's specialised loop (scheme_diff_centre.specialised_loop):
// v += dt a, q += dt v, then a from the equations of motion at the new
// state, the shocks in their local frames; diagonal matrices as 1-D arrays
// (template parameter) or full (n, n) ones.
#pragma once

#include <type_traits>

#include "clock.hpp"
#include "loop_steps.hpp"
#include "contact.hpp"
#include "energy.hpp"
#include "forces.hpp"
#include "layout.hpp"
#include "loads.hpp"
#include "model.hpp"
#include "views.hpp"

namespace asterlite {

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

// ``Matrix``: F1 for diagonal matrices (model.LinearSystem.kernel_matrices), else F2
template <class Matrix>
int diff_centre_loop(const Clock& c, const State& x, const F1& residual,
                     const Matrix& mass_inverse, const Matrix& stiffness, const Matrix& damping,
                     const Model& model, const ArchiveBuffers& out,
                     const energy::Balance& balance) {
    const index n = x.q.n0;
    const Local& local = model.local;
    const bool active = balance.active();  // energy balance: energy.after_step
    while (unfinished(c)) {
        const int paused = before_step(c, out, model);
        if (paused) return paused;
        double t, dt;
        plan_step(c, t, dt);
        for (index i = 0; i < n; ++i) {
            x.v(i) += dt * x.a(i);
            x.q(i) += dt * x.v(i);
        }
        const double t_new = t + dt;
        external_force_into(t_new, model.loads, x.f);
        local_support_motion(t_new, model.shk.rots, model.sup, local.drive);
        const index shock = local_shock_forces(x.q, x.v, model.shk, local.shapes, local.rest,
                                               local.drive, x.vint, x.f);
        if (shock >= 0) return record_failure(c, STATUS_SHOCK_DIVERGED, shock, dt);
        bool finite;
        if constexpr (std::is_same_v<Matrix, F1>) {
            finite = diagonal_acceleration(x.a, x.f, x.q, x.v, mass_inverse, stiffness, damping);
        } else {
            finite = full_acceleration(x.a, x.f, x.q, x.v, mass_inverse, stiffness, damping,
                                       residual);
        }
        if (!finite) return record_failure(c, STATUS_NOT_FINITE, -1, dt);
        after_step(c, x, out, balance, active, model, dt, dt, 0);
    }
    return STATUS_DONE;
}

}  // namespace asterlite
