// Small dense linear algebra in place (asterlite.dynamics.linalg): LU with
// partial pivoting and its solve, as the implicit schemes use them.
#pragma once

#include <cmath>

#include "views.hpp"

namespace asterlite {

// linalg.lu_factor: a overwritten by its LU factors, pivots[k] the row
// swapped with row k; false when a pivot vanishes. ``a`` is the n x n block
// of rows starting at ``a.data`` (any row count above n is not touched).
inline bool lu_factor(const F2& a, const F1& pivots) {
    const index n = a.n1;
    for (index k = 0; k < n; ++k) {
        index p = k;
        double best = std::fabs(a(k, k));
        for (index r = k + 1; r < n; ++r) {
            if (std::fabs(a(r, k)) > best) {
                best = std::fabs(a(r, k));
                p = r;
            }
        }
        pivots(k) = static_cast<double>(p);
        if (best == 0.0) return false;
        if (p != k) {
            for (index c = 0; c < n; ++c) {
                const double swap = a(k, c);
                a(k, c) = a(p, c);
                a(p, c) = swap;
            }
        }
        const double inv = 1.0 / a(k, k);
        for (index r = k + 1; r < n; ++r) {
            a(r, k) *= inv;
            const double factor = a(r, k);
            if (factor != 0.0) {
                for (index c = k + 1; c < n; ++c) a(r, c) -= factor * a(k, c);
            }
        }
    }
    return true;
}

// linalg.lu_solve: b overwritten by the solution of A x = b
inline void lu_solve(const F2& lu, const F1& pivots, const F1& b) {
    const index n = lu.n1;
    for (index k = 0; k < n; ++k) {
        const index p = static_cast<index>(pivots(k));
        if (p != k) {
            const double swap = b(k);
            b(k) = b(p);
            b(p) = swap;
        }
    }
    for (index r = 1; r < n; ++r) {
        double s = b(r);
        for (index c = 0; c < r; ++c) s -= lu(r, c) * b(c);
        b(r) = s;
    }
    for (index r = n - 1; r >= 0; --r) {
        double s = b(r);
        for (index c = r + 1; c < n; ++c) s -= lu(r, c) * b(c);
        b(r) = s / lu(r, r);
    }
}

}  // namespace asterlite
