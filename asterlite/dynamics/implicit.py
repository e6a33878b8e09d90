"""Effective operators of the schemes implicit on the linear part (NEWMARK,
TRBDF2), kept in a scheme's memory rows and rebuilt in place when the step
changes.

Layout of the rows: the scheme's vector rows first, then five (n, n)
blocks: M, K, C, the effective stiffness (LU-factored, or its diagonal
when M, K and C are all diagonal) and scratch operators.
"""

from __future__ import annotations

import numpy as np

from asterlite.dynamics.forces import matvec_add
from asterlite.dynamics.jit import njit
from asterlite.dynamics.linalg import lu_factor, lu_solve

N_BLOCKS = 6  # M, K, C, K_eff, F1, F2 (NEWMARK adds F3 in the scratch block)
B_MASS, B_STIFF, B_DAMP, B_KEFF, B_F1, B_F2, B_F3 = range(7)


def new_rows(vector_rows: int, system, blocks: int = 7) -> np.ndarray:
    n = system.n_modes
    rows = np.zeros((vector_rows + blocks * n, n))
    # block()'s slices, written here without the kernel (no numba for the C++ loops)
    for which, matrix in ((B_MASS, system.mass), (B_STIFF, system.stiffness),
                          (B_DAMP, system.damping)):  # fmt: skip
        start = vector_rows + which * n
        rows[start : start + n] = matrix
    return rows


@njit(cache=True, inline="always")
def block(rows, vector_rows, which, n):
    start = vector_rows + which * n
    return rows[start : start + n]


@njit(cache=True)
def combine(out, mass, stiffness, damping, cm, ck, cc):
    """out = cm M + ck K + cc C."""
    n = out.shape[0]
    for i in range(n):
        for j in range(n):
            out[i, j] = cm * mass[i, j] + ck * stiffness[i, j] + cc * damping[i, j]


@njit(cache=True)
def factor_effective(keff, pivots, diagonal):
    if diagonal:
        return True
    return lu_factor(keff, pivots)


@njit(cache=True)
def solve_effective(keff, pivots, rhs, diagonal):
    if diagonal:
        for i in range(rhs.shape[0]):
            rhs[i] /= keff[i, i]
    else:
        lu_solve(keff, pivots, rhs)


@njit(cache=True)
def apply(op, x, coef, out, diagonal):
    """out += coef * op @ x."""
    matvec_add(op, x, coef, out, diagonal)
