// The state's acceleration with the shocks in their local frames
// (asterlite.dynamics.local_frame), and what the steps call as ``evaluate``
// and ``total_force_at``: the local frames' on a scheme's own loop, the
// general model's (forces.py) on a general path.
#pragma once

#include "contact.hpp"
#include "forces.hpp"
#include "loads.hpp"
#include "model.hpp"
#include "views.hpp"

namespace asterlite {

// local_frame.local_total_force: f = F_ext(t) + the shock forces at (q, v)
inline index local_total_force(double t, const F1& q, const F1& v, const F2& vint, const F1& f,
                               const Model& model) {
    external_force_into(t, model.loads, f);
    local_support_motion(t, model.shk.rots, model.sup, model.local.drive);
    return local_shock_forces(q, v, model.shk, model.local.shapes, model.local.rest,
                              model.local.drive, vint, f);
}

// local_frame.diagonal_acceleration: forces.acceleration on diagonal (n, n)
// matrices in one pass, the same operations in the same order
inline void local_diagonal_acceleration(const F1& f, const F1& q, const F1& v, const Linear& lin,
                                        const F1& residual, const F1& out) {
    for (index i = 0; i < f.n0; ++i) {
        double x = f(i);
        x += -1.0 * lin.stiffness(i, i) * q(i);
        x += -1.0 * lin.damping(i, i) * v(i);
        residual(i) = x;
        out(i) = 0.0 + 1.0 * lin.minv(i, i) * x;
    }
}

// local_frame.evaluate: out = M^-1 (F_ext(t) + F_shock(q, v) - K q - C v),
// vint updated, f the total force; a diverging shock's index or -1. On a
// model with local frames local_evaluate, else forces.evaluate (``work``:
// the state's scratch for the shocks in the global frame)
inline index evaluate(double t, const F1& q, const F1& v, const F1& out, const F1& f,
                      const F1& residual, const F2& vint, const F2& work, const Model& model) {
    if (!model.local_frames) return general_evaluate(t, q, v, out, f, residual, vint, work, model);
    const index shock = local_total_force(t, q, v, vint, f, model);
    if (model.lin.diagonal) {
        local_diagonal_acceleration(f, q, v, model.lin, residual, out);
    } else {
        acceleration(f, q, v, model.lin, residual, out);
    }
    return shock;
}

// local_frame.total_force_at: local_total_force on a model with local
// frames, else forces.total_force_at
inline index total_force_at(double t, const F1& q, const F1& v, const F2& vint, const F2& work,
                            const F1& f, const Model& model) {
    if (!model.local_frames) return total_force(t, q, v, model, vint, work, f);
    return local_total_force(t, q, v, vint, f, model);
}

}  // namespace asterlite
