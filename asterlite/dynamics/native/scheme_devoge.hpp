// DEVOGE (asterlite.dynamics.scheme_devoge): the Devogelaere-Fu scheme of
// order 4 on whole steps and half steps, C' = M^-1 C implicit (H1, H2), the
// shock forces explicit, code_aster's step control on the half-step
// displacement, the step capped by the shocks' damping.
#pragma once

#include <cfloat>
#include <cmath>

#include "adapt_control.hpp"
#include "forces.hpp"
#include "implicit.hpp"
#include "linalg.hpp"
#include "local_frame.hpp"
#include "loop.hpp"
#include "python_math.hpp"

namespace asterlite {
namespace devoge {

// the memory rows of scheme_devoge (vectors, pivots, diagonals, then blocks)
enum Row : index {
    Q2, V2, R2, R1, Q3, V3, R3, Q4, V4, R4, X1, Q2E, Q1P, V1P, R1P, Q3E, X2,
    P0, P1, P2,  // the pivots of H0, H1, H2's LU factors (full damping)
    D_MINV, D_C, D_K, D_H1, D_H2,
};
constexpr index MATRIX_ROWS = 25;  // then invm_c, invm_k, H1, H2, H0: n rows each
enum Scalar : index {
    S_READY, S_DTOLD, S_OLDPAS1, S_OLDPAS2, S_ADAPTIVE, S_TOL, S_ALPHA, S_DTMIN, S_DTMAX, S_HDT,
    S_CAP,
};
constexpr index MEMORY_SCALARS = 11;
constexpr double STAGE_RADIUS = 2.0;
constexpr double EPS = DBL_EPSILON;  // np.finfo(np.float64).eps
inline index memory_rows(index n) { return MATRIX_ROWS + 5 * n; }

struct Operators {
    F2 invm_c, invm_k, h1, h2;
};

// scheme_devoge.operators: views of the blocks after the vector rows
inline Operators operators(const F2& mem, index n) {
    return {block(mem, MATRIX_ROWS, 0, n), block(mem, MATRIX_ROWS, 1, n),
            block(mem, MATRIX_ROWS, 2, n), block(mem, MATRIX_ROWS, 3, n)};
}

// H0's block (built and factored once per run, by start)
inline F2 start_operator(const F2& mem, index n) { return block(mem, MATRIX_ROWS, 4, n); }

// (a @ x)[i], from a's diagonal row when the system is diagonal
inline double times(const F2& a, const F1& a_diagonal, const F1& x, index i, bool diagonal) {
    if (diagonal) return a_diagonal(i) * x(i);
    return matvec_row(a, x, i);
}

// H1 = 4I + dt C', H2 = 6I + dt C' (and their diagonal rows), LU-factored in
// place when full; false when one is singular
inline bool update_implicit_operators(const F2& mem, const F2& invm_c, const F2& h1, const F2& h2,
                                      double dt, bool diagonal) {
    const index n = invm_c.n0;
    for (index i = 0; i < n; ++i) {
        for (index j = 0; j < n; ++j) {
            h1(i, j) = dt * invm_c(i, j);
            h2(i, j) = dt * invm_c(i, j);
        }
        h1(i, i) += 4.0;
        h2(i, i) += 6.0;
        mem(D_H1, i) = h1(i, i);
        mem(D_H2, i) = h2(i, i);
    }
    if (diagonal) return true;
    return lu_factor(h1, row(mem, P1)) && lu_factor(h2, row(mem, P2));
}

// out = H^-1 rhs, H diagonal or LU-factored; false where numba's division
// by a zero diagonal entry raises ZeroDivisionError (error_model "python")
inline bool solve_with(const F2& h, const F1& h_diagonal, const F1& pivots, const F1& rhs,
                       const F1& out, bool diagonal) {
    if (diagonal) {
        for (index i = 0; i < out.n0; ++i) {
            if (h_diagonal(i) == 0.0) return false;
            out(i) = rhs(i) / h_diagonal(i);
        }
    } else {
        for (index i = 0; i < out.n0; ++i) out(i) = rhs(i);
        lu_solve(h, pivots, out);
    }
    return true;
}

// out = M^-1 f - M^-1 K q
inline void reduced_force(const F1& f, const F1& q, const F2& minv, const F2& invm_k,
                          const F2& mem, const F1& out, bool diagonal) {
    const F1 d_minv = row(mem, D_MINV), d_k = row(mem, D_K);
    for (index i = 0; i < out.n0; ++i) {
        out(i) = times(minv, d_minv, f, i, diagonal) - times(invm_k, d_k, q, i, diagonal);
    }
}

// the half-step state at t - dt/2 from (q, v, F) at t: STATUS_DONE, or
// STATUS_NOT_FINITE when an implicit operator is singular (numba's False),
// or STATUS_ZERO_DIVISION
inline int start(double dt, const F1& q, const F1& v, const F1& f, const F2& mem,
                  const F1& smem, const F2& minv, const F2& invm_c, const F2& invm_k,
                  const F2& h1, const F2& h2, bool diagonal) {
    const index n = q.n0;
    const F1 q2 = row(mem, Q2), v2 = row(mem, V2), r2 = row(mem, R2), r1 = row(mem, R1);
    const F1 x1 = row(mem, X1), x2 = row(mem, X2);
    if (!update_implicit_operators(mem, invm_c, h1, h2, dt, diagonal)) return STATUS_NOT_FINITE;
    smem(S_HDT) = dt;
    copy_into(row(mem, Q1P), q);
    copy_into(row(mem, V1P), v);
    copy_into(row(mem, R1P), f);  // code_aster keeps the raw force here on the first step
    smem(S_OLDPAS1) = dt;
    smem(S_OLDPAS2) = dt;
    smem(S_DTOLD) = dt;
    const double half = dt / 2.0;
    const F1 d_c = row(mem, D_C);
    reduced_force(f, q, minv, invm_k, mem, r1, diagonal);
    for (index i = 0; i < n; ++i) {
        q2(i) = q(i) - half * v(i) + (half / 4.0) * (r1(i) - times(invm_c, d_c, v, i, diagonal));
    }
    reduced_force(f, q2, minv, invm_k, mem, r2, diagonal);
    // v2 from H0 v2 = H1 v1 - dt (r1 + r2), H0 = 4I - dt C'
    const F2 h0 = start_operator(mem, n);
    const F1 h0_diagonal = x1;  // free here
    for (index i = 0; i < n; ++i) {
        for (index j = 0; j < n; ++j) h0(i, j) = -dt * invm_c(i, j);
        h0(i, i) += 4.0;
        h0_diagonal(i) = h0(i, i);
    }
    for (index i = 0; i < n; ++i) {
        x2(i) = 4.0 * v(i) + dt * times(invm_c, d_c, v, i, diagonal) - dt * (r1(i) + r2(i));
    }
    if (!(diagonal || lu_factor(h0, row(mem, P0)))) return STATUS_NOT_FINITE;
    if (!solve_with(h0, h0_diagonal, row(mem, P0), x2, v2, diagonal)) return STATUS_ZERO_DIVISION;
    if (smem(S_ADAPTIVE) == 1.0) {
        for (index i = 0; i < n; ++i) {
            mem(Q2E, i) = (2.0 * q2(i) - q(i)) + half * (2.0 * v2(i) - v(i)) +
                          (half * half / 24.0) * 13.0 * r1(i);
        }
    }
    smem(S_READY) = 1.0;
    return STATUS_DONE;
}

inline double step_factor(double err) {
    if (err < int_power(0.9 / 1.5, 4)) return 1.5;
    if (err > int_power(0.9 / 0.5, 4)) return 0.5;
    return 0.9 * std::pow(err, -0.25);
}

// code_aster's error estimate on the half-step displacement, divided by the
// tolerance; > 1 rejects the step
inline double relative_error(double dt, const F1& q, const F1& v, const F2& mem, const F1& smem,
                             std::int64_t attempts, index n) {
    const double half = dt / 2.0;
    const F1 q2 = row(mem, Q2), r2 = row(mem, R2), r1 = row(mem, R1);
    const F1 q3 = row(mem, Q3), v3 = row(mem, V3), r3 = row(mem, R3);
    const F1 q4 = row(mem, Q4), v4 = row(mem, V4), r4 = row(mem, R4);
    const F1 q2e = row(mem, Q2E), q3e = row(mem, Q3E);
    const double oldpas1 = smem(S_OLDPAS1), oldpas2 = smem(S_OLDPAS2);
    const bool same_as_last = std::fabs(dt - oldpas2) <= EPS;
    const bool last_two_same = std::fabs(oldpas2 - oldpas1) <= EPS;
    int which;  // the Python's ``case``
    if (same_as_last && last_two_same) {
        which = 0;
    } else if (!same_as_last && last_two_same) {
        which = 1;
    } else if (!same_as_last) {
        which = 3;
    } else {
        which = 0;  // code_aster's second-step case is unreachable
    }
    const double c24 = half * half / 24.0;
    for (index i = 0; i < n; ++i) {
        if (which == 0) {
            q3e(i) = q4(i) - half * v4(i) + c24 * (7.0 * r4(i) + 6.0 * r3(i) - r1(i));
        } else {
            q3e(i) = q(i) + half * v(i) + c24 * (7.0 * r1(i) + 6.0 * r3(i) - r4(i));
        }
    }
    const double pas0 = oldpas1 / 2.0, pas1 = oldpas2 / 2.0;
    if (attempts == 1) {
        for (index i = 0; i < n; ++i) {
            q2e(i) = mem(Q1P, i) + pas1 * mem(V1P, i) +
                     (pas1 * pas1 / 24.0) * (7.0 * mem(R1P, i) + 6.0 * r2(i) - r1(i));
        }
    }
    double w_new = 1.0, w_old = 1.0, beta;
    if (which == 0) {
        beta = 45.0 * half / 4.0;
    } else if (which == 1) {
        const double c1 = half / pas1;
        w_old = int_power(c1, 3) * (2.0 + c1) / 3.0;
        beta = 5.0 * pas1 * (12.0 + 7.0 * c1 - c1 * c1) / (8.0 * c1);
    } else {
        const double c0 = pas1 / pas0;
        const double c1 = half / pas1;
        w_old = int_power(c1, 3) * (2.0 + c1) / 3.0;
        w_new = (1.0 + 2.0 / c0) / 3.0;
        beta = 5.0 * half *
               (c0 * c0 * (12.0 + 7.0 * c1 - c1 * c1) + c0 * (20.0 + 12.0 * c1 - 2.0 * c1 * c1) +
                2.0 * c1 + 4.0) /
               (24.0 * c0 * c0 * c1 * c1);
    }
    double total = 0.0;
    double magnitude = 0.0;
    for (index i = 0; i < n; ++i) {
        const double e = (w_new * (q3e(i) - q3(i)) - w_old * (q2e(i) - q2(i))) / beta;
        total += e * e;
        const double m = py_max(std::fabs(q3(i)), std::fabs(v3(i) * dt));
        magnitude += m * m;
    }
    const double count = static_cast<double>(n);
    const double err_displacement = std::sqrt(total) * half / count;
    const double scale = smem(S_TOL) * (std::sqrt(magnitude) / count + smem(S_ALPHA));
    if (scale <= EPS) return int_power(0.9, 4);
    return err_displacement / scale;
}

// one step (scheme_devoge.step): the forces through total_force_at on the
// shocks' local frames
inline StepResult step(double t, double dt, std::int64_t, const State& x, const Memory& memory,
                       const Model& model) {
    const F1 &q = x.q, &v = x.v, &a = x.a, &f = x.f;
    const F2 &vint = x.vint, &vint_save = x.vint_save;
    const F2& mem = memory.rows;
    const F1& smem = memory.scalars;
    const F2& minv = model.lin.minv;
    const bool diagonal = model.lin.diagonal;
    const index n = q.n0;
    const Operators ops = operators(mem, n);
    const F2 &invm_c = ops.invm_c, &invm_k = ops.invm_k, &h1 = ops.h1, &h2 = ops.h2;
    const bool adaptive = smem(S_ADAPTIVE) == 1.0;
    if (smem(S_CAP) < 0.0) {
        smem(S_CAP) = shock_damping_step(model.lin, model.shk, false, STAGE_RADIUS);
    }
    const double dt_max = py_min(smem(S_DTMAX), smem(S_CAP));
    if (adaptive && dt > dt_max) dt = dt_max;
    if (smem(S_READY) == 0.0) {
        const int started = start(dt, q, v, f, mem, smem, minv, invm_c, invm_k, h1, h2, diagonal);
        if (started != STATUS_DONE) return {started, -1, dt, dt, 0};
    }
    const F1 q2 = row(mem, Q2), v2 = row(mem, V2), r2 = row(mem, R2), r1 = row(mem, R1);
    const F1 q3 = row(mem, Q3), v3 = row(mem, V3), r3 = row(mem, R3);
    const F1 q4 = row(mem, Q4), v4 = row(mem, V4), r4 = row(mem, R4);
    const F1 x1 = row(mem, X1), x2 = row(mem, X2);
    const F1 d_c = row(mem, D_C), d_h1 = row(mem, D_H1), d_h2 = row(mem, D_H2);
    if (adaptive) copy_into(vint_save, vint);  // a rejected trial restores the shock states
    double dtold = smem(S_DTOLD);
    std::int64_t attempts = 0;
    double dtnew = dt;
    while (true) {
        const double half = dt / 2.0;
        const double coeff = dt / dtold;
        if (std::fabs(coeff - 1.0) >= EPS) {
            if (dt != smem(S_HDT)) {
                if (!update_implicit_operators(mem, invm_c, h1, h2, dt, diagonal)) {
                    return {STATUS_NOT_FINITE, -1, dt, dt, attempts};
                }
                smem(S_HDT) = dt;
            }
            if (attempts > 0) {  // retry with a smaller step: rescale the half-step state
                for (index i = 0; i < n; ++i) {
                    r2(i) = r1(i) + coeff * (r2(i) - r1(i));
                    q2(i) = q(i) + coeff * (q2(i) - q(i));
                    v2(i) = v(i) + coeff * (v2(i) - v(i));
                }
            }
        }
        // --- t + dt/2
        for (index i = 0; i < n; ++i) x1(i) = 4.0 * v(i) - v2(i);
        for (index i = 0; i < n; ++i) {
            const double damped = times(invm_c, d_c, x1, i, diagonal);
            q3(i) = q(i) + half * v(i) + (dt * dt / 24.0) * (4.0 * r1(i) - r2(i) - damped);
            v3(i) = (q3(i) - q(i)) / half;
        }
        index shock = total_force_at(t + half, q3, v3, vint, x.work, f, model);
        if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, attempts};
        reduced_force(f, q3, minv, invm_k, mem, r3, diagonal);
        for (index i = 0; i < n; ++i) {
            const double damped = times(invm_c, d_c, v, i, diagonal);
            x1(i) = 4.0 * (v(i) + (dt / 4.0) * (r1(i) + r3(i) - damped));
        }
        if (!solve_with(h1, d_h1, row(mem, P1), x1, v3, diagonal)) {
            return {STATUS_ZERO_DIVISION, -1, dt, dt, attempts};
        }
        // --- t + dt
        for (index i = 0; i < n; ++i) x1(i) = v(i) + 2.0 * v3(i);
        for (index i = 0; i < n; ++i) {
            const double damped = times(invm_c, d_c, x1, i, diagonal);
            q4(i) = q(i) + dt * v(i) + (dt * dt / 6.0) * (r1(i) + 2.0 * r3(i) - damped);
            v4(i) = (q4(i) - q3(i)) / half;
        }
        shock = total_force_at(t + dt, q4, v4, vint, x.work, f, model);
        if (shock >= 0) return {STATUS_SHOCK_DIVERGED, shock, dt, dt, attempts};
        reduced_force(f, q4, minv, invm_k, mem, r4, diagonal);
        for (index i = 0; i < n; ++i) x1(i) = 4.0 * v3(i) + v(i);
        for (index i = 0; i < n; ++i) {
            const double damped = times(invm_c, d_c, x1, i, diagonal);
            x2(i) = 6.0 * (v(i) + (dt / 6.0) * (r4(i) + 4.0 * r3(i) + r1(i) - damped));
        }
        if (!solve_with(h2, d_h2, row(mem, P2), x2, v4, diagonal)) {
            return {STATUS_ZERO_DIVISION, -1, dt, dt, attempts};
        }
        if (!(all_finite(q4) && all_finite(v4))) {
            copy_into(q, q4);  // kernel.expose_trial(q, v, a, q4, v4, a)
            copy_into(v, v4);
            return {STATUS_NOT_FINITE, -1, dt, dt, attempts};
        }
        if (!adaptive) break;
        const double err = relative_error(dt, q, v, mem, smem, attempts, n);
        attempts += 1;
        dtnew = py_min(py_max(step_factor(err) * dt, smem(S_DTMIN)), dt_max);
        if (err < 1.0 && std::fabs(dtnew / dt - 1.0) < 0.15) dtnew = dt;
        if (err > 1.0 && attempts < 25) {
            if (std::fabs(dtnew / dt - 1.0) < EPS) {
                return {STATUS_STEP_UNDERFLOW, -1, dt, dt, attempts};
            }
            dtold = dt;
            dt = dtnew;
            copy_into(vint, vint_save);
            continue;
        }
        copy_into(row(mem, Q1P), q);
        copy_into(row(mem, V1P), v);
        copy_into(row(mem, R1P), r1);
        copy_into(row(mem, Q2E), row(mem, Q3E));
        smem(S_OLDPAS1) = smem(S_OLDPAS2);
        smem(S_OLDPAS2) = dt;
        break;
    }
    // --- shift: half step 3 -> 2, whole step 4 -> 1
    for (index i = 0; i < n; ++i) {
        a(i) = r4(i) - times(invm_c, d_c, v4, i, diagonal);
        q2(i) = q3(i);
        v2(i) = v3(i);
        r2(i) = r3(i);
        q(i) = q4(i);
        v(i) = v4(i);
        r1(i) = r4(i);
    }
    smem(S_DTOLD) = dt;
    const std::int64_t rejected = attempts > 0 ? attempts - 1 : 0;
    return {STATUS_DONE, -1, dt, dtnew, rejected};
}

}  // namespace devoge
}  // namespace asterlite
