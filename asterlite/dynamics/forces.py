"""Right-hand side of the generalized equations of motion, compiled.

M q'' + C q' + K q = F_ext(t) + Φᵀ F_shock(Φ q, Φ q')

Bundles passed to the kernels (tuples of arrays, built by ``model.py``):

- ``lin = (minv, stiffness, damping, is_diagonal)``: (n, n) arrays and a
  (1,) int array telling whether the three matrices are diagonal;
- ``shk = (flags, params, rots, phis, polars)``: see ``contact.py``;
- ``exc = (vectors, table, grid)``: excitation e's generalized vector
  ``vectors[e]`` times its multiplier tabulated at ``grid[0] + k grid[1]``
  (linear interpolation in between, held constant outside).
"""

from __future__ import annotations

from numba import njit

from asterlite.dynamics.contact import shock_forces


@njit(cache=True)
def multiplier(table_row, t0, h, t):
    """Linear interpolation of a tabulated multiplier at time t."""
    x = (t - t0) / h
    last = table_row.shape[0] - 1
    if x <= 0.0:
        return table_row[0]
    if x >= last:
        return table_row[last]
    k = int(x)
    w = x - k
    return (1.0 - w) * table_row[k] + w * table_row[k + 1]


@njit(cache=True)
def external_force(t, exc, out):
    vectors, table, grid = exc
    for e in range(vectors.shape[0]):
        c = multiplier(table[e], grid[0], grid[1], t)
        for m in range(out.shape[0]):
            out[m] += c * vectors[e, m]


@njit(cache=True)
def total_force(t, q, v, shk, vint, exc, work, out):
    """out = F_ext(t) + Φᵀ F_shock; returns a diverging shock's index or -1."""
    out[:] = 0.0
    external_force(t, exc, out)
    flags, params, rots, phis, polars = shk
    return shock_forces(q, v, flags, params, rots, phis, polars, vint, work, out)


@njit(cache=True)
def matvec_add(a, x, coef, out, diagonal):
    """out += coef * a @ x (only the diagonal of ``a`` when ``diagonal``)."""
    n = out.shape[0]
    if diagonal:
        for i in range(n):
            out[i] += coef * a[i, i] * x[i]
    else:
        for i in range(n):
            s = 0.0
            for j in range(n):
                s += a[i, j] * x[j]
            out[i] += coef * s


@njit(cache=True)
def matvec(a, x, out, diagonal):
    out[:] = 0.0
    matvec_add(a, x, 1.0, out, diagonal)


@njit(cache=True)
def acceleration(f, q, v, lin, residual, out):
    """out = M⁻¹ (f - K q - C v); ``residual`` is scratch."""
    minv, stiffness, damping, is_diagonal = lin
    diagonal = is_diagonal[0] == 1
    residual[:] = f
    matvec_add(stiffness, q, -1.0, residual, diagonal)
    matvec_add(damping, v, -1.0, residual, diagonal)
    matvec(minv, residual, out, diagonal)


@njit(cache=True)
def all_finite(x):
    for i in range(x.shape[0]):
        if not (abs(x[i]) < 1.0e300):
            return False
    return True


@njit(cache=True)
def state_acceleration(t, q, v, out, f, residual, vint, work, model):
    """out = M⁻¹ (F_ext(t) + F_shock(q, v) - K q - C v), the shock states
    ``vint`` updated (code_aster's dtmacce). Returns a diverging shock's
    index or -1; ``f`` receives the total force."""
    lin, shk, exc = model
    shock = total_force(t, q, v, shk, vint, exc, work, f)
    acceleration(f, q, v, lin, residual, out)
    return shock
