// Step control of the adaptive schemes (asterlite.dynamics.adapt_control):
// ADAPT_ORDRE1/2's apparent frequency, the damping cap of the schemes whose
// stages evaluate the shock forces explicitly.
#pragma once

#include <cfloat>
#include <cmath>
#include <limits>

#include "layout.hpp"
#include "python_math.hpp"
#include "model.hpp"
#include "views.hpp"

namespace asterlite {

enum ControlScalar : int {
    S_NORM_VMIN, S_POINTS, S_MAX_TRIALS, S_MULT, S_DIVI, S_DTMIN, S_DTMAX, S_ADAPTIVE,
    S_CALM_STEPS, S_FIRST_CALL, S_KEPT_AT_MAX_TRIALS,
};
constexpr double CONTROL_EPS = 100.0 * DBL_EPSILON;

inline double apparent_frequency(double dt, const F1& q1, const F1& q2, const F1& a1,
                                 const F1& a2, const F1& vmin) {
    double largest = DBL_EPSILON;
    for (index i = 0; i < q1.n0; ++i) {
        const double da = a2(i) - a1(i);
        const double reference = vmin(i) * dt;
        const double dq = std::fabs(q2(i) - q1(i));
        double b = reference >= dq ? reference : dq;
        if (b <= DBL_MIN) b = DBL_EPSILON;
        const double ratio = std::fabs(da / b);
        if (ratio >= largest) largest = ratio;
    }
    return std::sqrt(largest) / (2.0 * M_PI);
}

// the points per period times the apparent frequency times the step (>= eps)
inline double frequency_error(double dt, const F1& q1, const F1& q2, const F1& a1, const F1& a2,
                              const F1& vmin, const F1& scalars) {
    const double err = scalars(S_POINTS) * apparent_frequency(dt, q1, q2, a1, a2, vmin) * dt;
    return py_max(err, CONTROL_EPS);
}

// the factor on the step from the error, updating the calm-step counter
inline double step_factor(double err, const F1& scalars) {
    double factor = 1.0;
    if (err >= 1.0) {
        factor = 1.0 / scalars(S_DIVI);
    } else if (scalars(S_CALM_STEPS) > 4.5) {
        if (err < 0.75) {
            factor = scalars(S_MULT);
            scalars(S_CALM_STEPS) = 1.0;
        }
    } else {
        scalars(S_CALM_STEPS) += 1.0;
    }
    return factor;
}

inline void update_reference_velocities(const F1& velocity, const F1& vmin, const F1& scalars) {
    const index n = velocity.n0;
    if (scalars(S_NORM_VMIN) == 1.0) {
        double norm = 0.0;
        for (index i = 0; i < n; ++i) norm += velocity(i) * velocity(i);
        norm = std::sqrt(norm) * 0.01;
        for (index i = 0; i < n; ++i) vmin(i) = norm;
    } else {
        for (index i = 0; i < n; ++i) {
            vmin(i) = py_max(std::fabs(velocity(i) * 0.01), vmin(i));
        }
    }
}

// largest stable step of v += dt (-w2 q - c v), q += dt v
inline double explicit_step(double omega2, double damping) {
    return 4.0 / (damping + std::sqrt(damping * damping + 4.0 * omega2));
}

// adapt_control.shock_damping_step: radius/2 times the explicit step of
// every mode stiffened and damped by each damped shock (inf without)
inline double shock_damping_step(const Linear& lin, const Shocks& shk, bool modal, double radius) {
    const double tiny = DBL_EPSILON * 1.0e5;
    double best = std::numeric_limits<double>::infinity();
    for (index s = 0; s < shk.flags.n0; ++s) {
        const index nodes = shk.flags(s, F_TWO_NODES) ? 2 : 1;
        for (int pair = 0; pair < 2; ++pair) {
            const double k = pair == 0 ? shk.params(s, P_KN) : shk.params(s, P_KT);
            const double c_shock = pair == 0 ? shk.params(s, P_CN) : shk.params(s, P_CT);
            if (std::fabs(c_shock) <= tiny) continue;
            for (index node = 0; node < nodes; ++node) {
                for (index j = 0; j < lin.minv.n0; ++j) {
                    const double inverse = lin.minv(j, j);
                    if (!(inverse > 0.0 && inverse < 1.0 / tiny)) continue;
                    const double w2 = py_max(std::fabs(lin.stiffness(j, j) * inverse), 1.0e-12);
                    const double own = modal ? lin.damping(j, j) * inverse : 0.0;
                    for (index c = 0; c < 3; ++c) {
                        const double phi = shk.phis(s, node, c, j);
                        const double share = phi * phi * inverse;
                        if (share <= 0.0) continue;
                        const double step = 0.5 * radius *
                                            explicit_step(w2 + std::fabs(k) * share,
                                                          own + c_shock * share);
                        if (step < best) best = step;
                    }
                }
            }
        }
    }
    return best;
}

}  // namespace asterlite
