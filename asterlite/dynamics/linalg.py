"""Small dense linear algebra for the compiled kernels, in place and
allocation-free: LU factorisation with partial pivoting and its solve.

The implicit schemes (NEWMARK, TRBDF2) refactor their effective stiffness
only when the step changes, then solve once or twice per step.
"""

from __future__ import annotations

from asterlite.dynamics.jit import njit


@njit(cache=True)
def lu_factor(a, pivots):
    """Overwrite the square ``a`` with its LU factors (unit lower part
    implicit); ``pivots[k]`` receives the row swapped with row k. Returns
    False when a pivot vanishes."""
    n = a.shape[0]
    for k in range(n):
        p = k
        best = abs(a[k, k])
        for r in range(k + 1, n):
            if abs(a[r, k]) > best:
                best = abs(a[r, k])
                p = r
        pivots[k] = p
        if best == 0.0:
            return False
        if p != k:
            for c in range(n):
                a[k, c], a[p, c] = a[p, c], a[k, c]
        inv = 1.0 / a[k, k]
        for r in range(k + 1, n):
            a[r, k] *= inv
            factor = a[r, k]
            if factor != 0.0:
                for c in range(k + 1, n):
                    a[r, c] -= factor * a[k, c]
    return True


@njit(cache=True)
def lu_solve(lu, pivots, b):
    """Solve in place A x = b with the factors of :func:`lu_factor`."""
    n = lu.shape[0]
    for k in range(n):
        p = int(pivots[k])
        if p != k:
            b[k], b[p] = b[p], b[k]
    for r in range(1, n):
        s = b[r]
        for c in range(r):
            s -= lu[r, c] * b[c]
        b[r] = s
    for r in range(n - 1, -1, -1):
        s = b[r]
        for c in range(r + 1, n):
            s -= lu[r, c] * b[c]
        b[r] = s / lu[r, r]
