// The blocks of the implicit schemes' memory (asterlite.dynamics.implicit):
// M, K, C, the effective stiffness and the operators on the right-hand side,
// stored as n x n blocks of the memory rows after the vector rows.
#pragma once

#include "forces.hpp"
#include "linalg.hpp"
#include "views.hpp"

namespace asterlite {

enum ImplicitBlock : int { B_MASS, B_STIFF, B_DAMP, B_KEFF, B_F1, B_F2, B_F3 };

// implicit.block: rows[vector_rows + which n : ... + n]
inline F2 block(const F2& rows, index vector_rows, index which, index n) {
    F2 view;
    view.data = rows.data + (vector_rows + which * n) * rows.n1;
    view.n0 = n;
    view.n1 = rows.n1;
    return view;
}

// implicit.combine: out = cm M + ck K + cc C
inline void combine(const F2& out, const F2& mass, const F2& stiffness, const F2& damping,
                    double cm, double ck, double cc) {
    for (index i = 0; i < out.n0; ++i) {
        for (index j = 0; j < out.n0; ++j) {
            out(i, j) = cm * mass(i, j) + ck * stiffness(i, j) + cc * damping(i, j);
        }
    }
}

inline bool factor_effective(const F2& keff, const F1& pivots, bool diagonal) {
    if (diagonal) return true;
    return lu_factor(keff, pivots);
}

// whether solve_effective's diagonal case divides by a zero entry of K_eff
// (numba raises ZeroDivisionError there; lu_factor refused a zero pivot of
// a full one, so lu_solve never divides by 0)
inline bool solve_divides_by_zero(const F2& keff, bool diagonal) {
    if (!diagonal) return false;
    for (index i = 0; i < keff.n0; ++i) {
        if (keff(i, i) == 0.0) return true;
    }
    return false;
}

inline void solve_effective(const F2& keff, const F1& pivots, const F1& rhs, bool diagonal) {
    if (diagonal) {
        for (index i = 0; i < rhs.n0; ++i) rhs(i) /= keff(i, i);
    } else {
        lu_solve(keff, pivots, rhs);
    }
}

// implicit.apply: out += coef op x
inline void apply(const F2& op, const F1& x, double coef, const F1& out, bool diagonal) {
    matvec_add(op, x, coef, out, diagonal);
}

}  // namespace asterlite
