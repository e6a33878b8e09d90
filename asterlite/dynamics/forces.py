"""Right-hand side of the generalized equations of motion, compiled.

M q'' + C q' + K q = F_ext(t) + Φᵀ F_shock(Φ q, Φ q')

Bundles passed to the kernels (tuples of arrays, built by ``model.py``):

- ``lin = (minv, stiffness, damping, is_diagonal)``: (n, n) arrays and a
  (1,) int array telling whether the three matrices are diagonal;
- ``shk = (flags, params, rots, phis, polars)``: see ``contact.py``;
- ``exc = (vectors, abscissas, ordinates, layout)``: excitation e's
  generalized vector ``vectors[e]`` times its piecewise-linear multiplier
  (``layout[e] = (count, left, right)``, see ``model.Excitation``).
"""

from __future__ import annotations

from numba import njit

from asterlite.dynamics.contact import P_DRIVE1, P_DRIVE2, shock_forces


@njit(cache=True)
def multiplier(xs, ys, count, left, right, t):
    """Piecewise-linear multiplier at t (extension: 0 constant, 1 linear)."""
    if count == 1:
        return ys[0]
    last = count - 1
    if t <= xs[0]:
        if left == 1 and t < xs[0]:
            return ys[0] + (t - xs[0]) * (ys[1] - ys[0]) / (xs[1] - xs[0])
        return ys[0]
    if t >= xs[last]:
        if right == 1 and t > xs[last]:
            slope = (ys[last] - ys[last - 1]) / (xs[last] - xs[last - 1])
            return ys[last] + (t - xs[last]) * slope
        return ys[last]
    lo, hi = 0, last  # xs[lo] <= t < xs[hi]
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= t:
            lo = mid
        else:
            hi = mid
    width = xs[hi] - xs[lo]
    if width == 0.0:
        return ys[hi]
    return ys[lo] + (t - xs[lo]) * (ys[hi] - ys[lo]) / width


@njit(cache=True)
def external_force(t, exc, out):
    vectors, abscissas, ordinates, layout = exc[0], exc[1], exc[2], exc[3]
    for e in range(vectors.shape[0]):
        c = multiplier(abscissas[e], ordinates[e], layout[e, 0], layout[e, 1], layout[e, 2], t)
        for m in range(out.shape[0]):
            out[m] += c * vectors[e, m]


@njit(cache=True)
def support_motion(t, exc, params):
    """MULT_APPUI: write each shock node's support displacement and velocity
    Σ_k ψ_k(node) (d_k(t), v_k(t)) into its drive slots (global frame)."""
    shapes, abscissas, ordinates, layout = exc[4], exc[5], exc[6], exc[7]
    n_supports = shapes.shape[3]
    if n_supports == 0:
        return
    for s in range(shapes.shape[0]):
        for node in range(2):
            base = P_DRIVE1 if node == 0 else P_DRIVE2
            for i in range(6):
                params[s, base + i] = 0.0
            for k in range(n_supports):
                r = 2 * k
                d = multiplier(
                    abscissas[r], ordinates[r], layout[r, 0], layout[r, 1], layout[r, 2], t
                )
                r += 1
                w = multiplier(
                    abscissas[r], ordinates[r], layout[r, 0], layout[r, 1], layout[r, 2], t
                )
                for i in range(3):
                    params[s, base + i] += shapes[s, node, i, k] * d
                    params[s, base + 3 + i] += shapes[s, node, i, k] * w


@njit(cache=True)
def total_force(t, q, v, shk, vint, exc, work, out):
    """out = F_ext(t) + Φᵀ F_shock; returns a diverging shock's index or -1."""
    out[:] = 0.0
    external_force(t, exc, out)
    flags, params, rots, phis, polars = shk
    support_motion(t, exc, params)
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
