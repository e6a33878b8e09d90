// Every GENE scheme behind one integer code (asterlite.dynamics.dispatch),
// for the loops whose linear operators change during a run (rotation.hpp:
// variable rotation speed, implicit_shocks.hpp: implicit shocks): the step of
// the scheme a code names, on the general model (three bundles), and the
// refresh of its operators after K and C of the model were rewritten.
#pragma once

#include <cstdint>

#include "forces.hpp"
#include "implicit.hpp"
#include "loop.hpp"
#include "model.hpp"
#include "scheme_adapt.hpp"
#include "scheme_devoge.hpp"
#include "scheme_diff_centre_step.hpp"
#include "scheme_newmark_step.hpp"
#include "scheme_runge_kutta.hpp"
#include "scheme_trbdf2.hpp"
#include "views.hpp"

namespace asterlite {
namespace dispatch {

// schemes.py's codes (Scheme.code)
enum Code : std::int64_t {
    NEWMARK, TRBDF2, DEVOGE, DIFF_CENTRE, RUNGE_KUTTA, ADAPT_ORDRE1, ADAPT_ORDRE2,
};

// dispatch.scheme_step: the step of the scheme ``code``
inline StepResult scheme_step(std::int64_t code, double t, double dt, std::int64_t step_index,
                              const State& x, const Memory& memory, const Model& model) {
    if (code == NEWMARK) return newmark::step(t, dt, step_index, x, memory, model);
    if (code == TRBDF2) return trbdf2::step(t, dt, step_index, x, memory, model);
    if (code == DEVOGE) return devoge::step(t, dt, step_index, x, memory, model);
    if (code == DIFF_CENTRE) return diff_centre::step(t, dt, step_index, x, memory, model);
    if (code == RUNGE_KUTTA) return runge_kutta::step(t, dt, step_index, x, memory, model);
    if (code == ADAPT_ORDRE1) return adapt_ordre1::step(t, dt, step_index, x, memory, model);
    return adapt_ordre2::step(t, dt, step_index, x, memory, model);  // ADAPT_ORDRE2
}

// dispatch.copy_blocks: K, C of the bundle into an implicit scheme's matrix
// blocks (its effective operators are rebuilt on the next step)
inline void copy_blocks(const F2& rows, index vector_rows, const Linear& lin, index n) {
    const F2 stiffness = block(rows, vector_rows, B_STIFF, n);
    const F2 damping = block(rows, vector_rows, B_DAMP, n);
    for (index i = 0; i < n; ++i) {
        for (index j = 0; j < n; ++j) {
            stiffness(i, j) = lin.stiffness(i, j);
            damping(i, j) = lin.damping(i, j);
        }
    }
}

// scheme_devoge.fill_diagonal_rows: the rows D_MINV, D_C, D_K from M^-1 and
// the M^-1 C, M^-1 K blocks
inline void fill_diagonal_rows(const F2& mem, const F2& minv, index n) {
    const devoge::Operators ops = devoge::operators(mem, n);
    for (index i = 0; i < n; ++i) {
        mem(devoge::D_MINV, i) = minv(i, i);
        mem(devoge::D_C, i) = ops.invm_c(i, i);
        mem(devoge::D_K, i) = ops.invm_k(i, i);
    }
}

// dispatch.devoge_operators: M^-1 C, M^-1 K and, once the scheme has
// started, H1, H2 for the step it stands at (always LU-factored: numba's
// call passes diagonal=False; its result is not checked there either: a
// singular H1 or H2 makes the step non-finite)
inline void devoge_operators(const F2& mem, const F1& smem, const Linear& lin, index n) {
    const F2 &minv = lin.minv, &stiffness = lin.stiffness, &damping = lin.damping;
    const devoge::Operators ops = devoge::operators(mem, n);
    for (index i = 0; i < n; ++i) {
        for (index j = 0; j < n; ++j) {
            double sc = 0.0;
            double sk = 0.0;
            for (index k = 0; k < n; ++k) {
                sc += minv(i, k) * damping(k, j);
                sk += minv(i, k) * stiffness(k, j);
            }
            ops.invm_c(i, j) = sc;
            ops.invm_k(i, j) = sk;
        }
    }
    fill_diagonal_rows(mem, minv, n);
    if (smem(devoge::S_READY) == 1.0) {
        devoge::update_implicit_operators(mem, ops.invm_c, ops.h1, ops.h2, smem(devoge::S_HDT),
                                          false);
    }
}

// dispatch.refresh_operators: make the scheme use the K and C now in ``lin``
// from its next step
inline void refresh_operators(std::int64_t code, const Memory& memory, const Linear& lin,
                              index n) {
    if (code == NEWMARK) {
        copy_blocks(memory.rows, newmark::VECTOR_ROWS, lin, n);
        memory.scalars(newmark::S_DT_BUILT) = -1.0;
    } else if (code == TRBDF2) {
        copy_blocks(memory.rows, trbdf2::VECTOR_ROWS, lin, n);
        memory.scalars(trbdf2::S_DT_BUILT) = -1.0;
    } else if (code == DEVOGE) {
        devoge_operators(memory.rows, memory.scalars, lin, n);
    }
}

// the memory the step of ``code`` indexes without checks, as the scheme's
// prepare makes it (rows of length n already checked); false otherwise
inline bool memory_fits(std::int64_t code, const Memory& memory, index n) {
    const index rows = memory.rows.n0, scalars = memory.scalars.n0;
    switch (code) {
        case NEWMARK:
            return rows == newmark::VECTOR_ROWS + newmark::N_BLOCKS * n &&
                   scalars >= newmark::N_SCALARS;
        case TRBDF2:  // implicit.new_rows with six blocks
            return rows == trbdf2::VECTOR_ROWS + 6 * n && scalars > trbdf2::S_A2;
        case DEVOGE:
            return rows == devoge::memory_rows(n) && scalars >= devoge::MEMORY_SCALARS;
        case DIFF_CENTRE:
            return rows > diff_centre::RESIDUAL;
        case RUNGE_KUTTA: {  // the stages' rows after the vector rows; the tableau
            const index s = memory.table.n0 - 2;
            return s >= 1 && memory.table.n1 >= s + 1 &&
                   rows >= runge_kutta::VECTOR_ROWS + 2 * s &&
                   scalars > runge_kutta::S_CAP;
        }
        case ADAPT_ORDRE1:
            return rows >= adapt_ordre1::VECTOR_ROWS && scalars > S_KEPT_AT_MAX_TRIALS;
        case ADAPT_ORDRE2:
            return rows >= adapt_ordre2::VECTOR_ROWS && scalars > S_KEPT_AT_MAX_TRIALS;
        default:
            return false;
    }
}

}  // namespace dispatch
}  // namespace asterlite
