// Right-hand side of the generalized equations (asterlite.dynamics.forces):
// products with the (n, n) matrices, the acceleration, the total force of
// the general path (shocks in the global frame).
#pragma once

#include <cmath>

#include "contact.hpp"
#include "laws.hpp"
#include "loads.hpp"
#include "model.hpp"
#include "views.hpp"

namespace asterlite {

// forces.all_finite's test of one entry
inline bool is_finite_entry(double x) { return std::fabs(x) < 1.0e300; }

inline bool all_finite(const F1& x) {
    for (index i = 0; i < x.n0; ++i) {
        if (!is_finite_entry(x(i))) return false;
    }
    return true;
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

// forces.matvec_row: (a x)[i] summed as matvec_add sums it
inline double matvec_row(const F2& a, const F1& x, index i) {
    double s = 0.0;
    for (index j = 0; j < x.n0; ++j) s += a(i, j) * x(j);
    return s;
}

// forces.acceleration: out = M^-1 (f - K q - C v); residual is scratch
inline void acceleration(const F1& f, const F1& q, const F1& v, const Linear& lin,
                         const F1& residual, const F1& out) {
    for (index i = 0; i < f.n0; ++i) residual(i) = f(i);
    matvec_add(lin.stiffness, q, -1.0, residual, lin.diagonal);
    matvec_add(lin.damping, v, -1.0, residual, lin.diagonal);
    for (index i = 0; i < out.n0; ++i) out(i) = 0.0;
    matvec_add(lin.minv, residual, 1.0, out, lin.diagonal);
}

// forces.copy_into / local_frame.copy_vector: target = source
inline void copy_into(const F1& target, const F1& source) {
    for (index i = 0; i < source.n0; ++i) target(i) = source(i);
}
inline void copy_into(const F2& target, const F2& source) {
    const index size = source.n0 * source.n1;
    for (index i = 0; i < size; ++i) target.data[i] = source.data[i];
}

// forces.total_force: out = F_ext(t) + Phi^T F_shock, shocks in the global
// frame, the support motion written into the shocks' parameters, then the
// relations of laws/ (rows with a law) when no shock diverged
inline index total_force(double t, const F1& q, const F1& v, const Model& model, const F2& vint,
                         const F2& work, const F1& out) {
    for (index m = 0; m < out.n0; ++m) out(m) = 0.0;
    add_external_force(t, model.loads, out);
    support_motion(t, model.sup, model.shk.params);
    const index shock = shock_forces(q, v, model.shk, vint, work, out);
    if (shock < 0 && model.shk.laws.n1 > 0) law_forces(t, q, v, model.shk, vint, out);
    return shock;
}

// forces.evaluate (state_acceleration) on the general model: out = M^-1 (f - K q - C v)
// with f the total force; a diverging shock's index or -1
inline index general_evaluate(double t, const F1& q, const F1& v, const F1& out, const F1& f,
                              const F1& residual, const F2& vint, const F2& work,
                              const Model& model) {
    const index shock = total_force(t, q, v, model, vint, work, f);
    acceleration(f, q, v, model.lin, residual, out);
    return shock;
}

}  // namespace asterlite
