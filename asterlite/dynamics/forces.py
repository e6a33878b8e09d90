"""Right-hand side of the generalized equations of motion, compiled.

M q'' + C q' + K q = F_ext(t) + Φᵀ F_shock(Φ q, Φ q')

Bundles passed to the kernels (tuples of arrays, built by ``model.py``):

- ``lin = (minv, stiffness, damping, is_diagonal)``: (n, n) arrays and a
  (1,) int array telling whether the three matrices are diagonal;
- ``shk = (flags, params, rots, phis, polars, laws, rphis, scratch)``: see
  ``contact.py``; the last three serve the relations other than DIS_CHOC
  (``laws.kernel``: law parameter rows, (0, 0)-shaped without such
  relations, rotation mode shapes, scratch);
- ``exc = (vectors, abscissas, ordinates, layout)``: excitation e's
  generalized vector ``vectors[e]`` times its piecewise-linear multiplier
  (``layout[e] = (count, left, right)``, see ``excitation.Excitation``).
"""

from __future__ import annotations

import numpy as np

from asterlite.dynamics.contact import P_DRIVE1, P_DRIVE2, shock_forces
from asterlite.dynamics.formula import run_program
from asterlite.dynamics.jit import njit
from asterlite.dynamics.kernel import C_STEP, C_TIME
from asterlite.dynamics.laws.kernel import law_forces
from asterlite.dynamics.layouts import LINEAR, LOADS, SHOCKS


@njit(cache=True)
def multiplier(xs, ys, count, left, right, t):
    """Piecewise-linear multiplier at t (extension: 0 constant, 1 linear)."""
    cursor = np.zeros(1, dtype=np.int64)
    table_x = xs.reshape((1, xs.shape[0]))
    table_y = ys.reshape((1, ys.shape[0]))
    return multiplier_at(table_x, table_y, 0, count, left, right, t, cursor)


@njit(cache=True, inline="always")
def multiplier_at(abscissas, ordinates, row, count, left, right, t, cursors):
    """Piecewise-linear multiplier of table row ``row`` at t (extension: 0
    constant, 1 linear).

    ``cursors[row]`` keeps the interval found last time and the search
    starts from it: O(1) per call for increasing (or slowly moving) times.
    The interval is the unique ``lo`` with xs[lo] <= t < xs[lo + 1], so the
    value does not depend on where the search starts.
    """
    if count == 1:
        return ordinates[row, 0]
    last = count - 1
    if t <= abscissas[row, 0]:
        if left == 1 and t < abscissas[row, 0]:
            return ordinates[row, 0] + (t - abscissas[row, 0]) * (
                ordinates[row, 1] - ordinates[row, 0]
            ) / (abscissas[row, 1] - abscissas[row, 0])
        return ordinates[row, 0]
    if t >= abscissas[row, last]:
        if right == 1 and t > abscissas[row, last]:
            slope = (ordinates[row, last] - ordinates[row, last - 1]) / (
                abscissas[row, last] - abscissas[row, last - 1]
            )
            return ordinates[row, last] + (t - abscissas[row, last]) * slope
        return ordinates[row, last]
    lo = cursors[row]
    if lo < 0 or lo >= last:
        lo = 0
    if abscissas[row, lo] <= t:
        if abscissas[row, lo + 1] <= t:  # move forward: a few steps, then bisection
            lo += 1
            steps = 0
            while abscissas[row, lo + 1] <= t and steps < 8:
                lo += 1
                steps += 1
            if abscissas[row, lo + 1] <= t:
                lo = bisect_interval(abscissas, row, lo, last, t)
    else:
        lo = bisect_interval(abscissas, row, 0, lo, t)
    cursors[row] = lo
    hi = lo + 1
    width = abscissas[row, hi] - abscissas[row, lo]
    if width == 0.0:
        return ordinates[row, hi]
    return (
        ordinates[row, lo]
        + (t - abscissas[row, lo]) * (ordinates[row, hi] - ordinates[row, lo]) / width
    )


@njit(cache=True, inline="always")
def bisect_interval(abscissas, row, lo, hi, t):
    """The ``lo`` with x[lo] <= t < x[lo + 1] (x = ``abscissas[row]``),
    knowing x[lo] <= t < x[hi]."""
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if abscissas[row, mid] <= t:
            lo = mid
        else:
            hi = mid
    return lo


@njit(cache=True, inline="always")
def loads_cover(t_next, abscissas, layout, pending):
    """Whether every windowed multiplier row (``pending[e] == 1``: more
    samples follow its window) is tabulated beyond ``t_next``."""
    for e in range(pending.shape[0]):
        if pending[e] == 1 and not (t_next < abscissas[e, layout[e, 0] - 1]):
            return False
    return True


@njit(cache=True, inline="always")  # a call would pass the excitation's 15 arrays each step
def loads_ready(clock, exc):
    """Whether the windowed multipliers cover the next step (two stored
    steps ahead of the current time); otherwise the loop pauses with
    STATUS_LOADS and the driver tabulates the next window."""
    t_next = clock[C_TIME] + 2.0 * clock[C_STEP]
    return loads_cover(t_next, exc.abscissas, exc.layout, exc.pending) and loads_cover(
        t_next, exc.drive_abscissas, exc.drive_layout, exc.drive_pending
    )


@njit(cache=True, inline="always")
def external_force(t, exc, out):
    vectors, abscissas, ordinates, layout, cursors = (
        exc.vectors,
        exc.abscissas,
        exc.ordinates,
        exc.layout,
        exc.cursors,
    )
    codes, constants, stack = exc.codes, exc.constants, exc.stack
    add_external_force(
        t, vectors, abscissas, ordinates, layout, cursors, codes, constants, stack, out
    )


@njit(cache=True, inline="always")
def add_external_force(
    t, vectors, abscissas, ordinates, layout, cursors, codes, constants, stack, out
):
    """out += Σ_e f_e(t) vector_e; f_e is row e's formula program when it
    has one (``codes[e, 0] > 0``), else its piecewise-linear table."""
    for e in range(vectors.shape[0]):
        if codes[e, 0] > 0:
            c = run_program(codes, constants, e, t, stack)
        else:
            c = multiplier_at(
                abscissas, ordinates, e, layout[e, 0], layout[e, 1], layout[e, 2], t, cursors
            )
        for m in range(out.shape[0]):
            out[m] += c * vectors[e, m]


@njit(cache=True, inline="always")
def support_motion(t, exc, params):
    """Multiple supports: write each shock node's support displacement and velocity
    Σ_k ψ_k(node) (d_k(t), v_k(t)) into its drive slots (global frame)."""
    shapes, abscissas, ordinates, layout, cursors = (
        exc.drive_shapes,
        exc.drive_abscissas,
        exc.drive_ordinates,
        exc.drive_layout,
        exc.drive_cursors,
    )
    n_supports = shapes.shape[3]
    if n_supports == 0:
        return
    for s in range(shapes.shape[0]):
        for node in range(2):
            base = P_DRIVE1 if node == 0 else P_DRIVE2
            for i in range(6):
                params[s, base + i] = 0.0
            for k in range(n_supports):
                d, w = support_values(t, k, abscissas, ordinates, layout, cursors)
                for i in range(3):
                    params[s, base + i] += shapes[s, node, i, k] * d
                    params[s, base + 3 + i] += shapes[s, node, i, k] * w


@njit(cache=True, inline="always")
def support_values(t, k, abscissas, ordinates, layout, cursors):
    """(displacement, velocity) of support k at t (rows 2k, 2k + 1)."""
    r = 2 * k
    d = multiplier_at(abscissas, ordinates, r, layout[r, 0], layout[r, 1], layout[r, 2], t, cursors)
    r += 1
    w = multiplier_at(abscissas, ordinates, r, layout[r, 0], layout[r, 1], layout[r, 2], t, cursors)
    return d, w


@njit(cache=True, inline="always")
def local_support_motion(t, rots, shapes, abscissas, ordinates, layout, cursors, drive):
    """Multiple supports for :func:`contact.local_shock_forces`: ``drive[s, node]``
    = rot Σ_k ψ_k(node) (d_k(t), v_k(t)), summed in the global frame as
    :func:`support_motion` does, then rotated. Nothing to do without supports."""
    n_supports = shapes.shape[3]
    if n_supports == 0:
        return
    for s in range(shapes.shape[0]):
        for node in range(2):
            dx, dy, dz, wx, wy, wz = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
            for k in range(n_supports):
                d, w = support_values(t, k, abscissas, ordinates, layout, cursors)
                dx += shapes[s, node, 0, k] * d
                dy += shapes[s, node, 1, k] * d
                dz += shapes[s, node, 2, k] * d
                wx += shapes[s, node, 0, k] * w
                wy += shapes[s, node, 1, k] * w
                wz += shapes[s, node, 2, k] * w
            for i in range(3):
                drive[s, node, i] = rots[s, i, 0] * dx + rots[s, i, 1] * dy + rots[s, i, 2] * dz
                drive[s, node, 3 + i] = rots[s, i, 0] * wx + rots[s, i, 1] * wy + rots[s, i, 2] * wz


@njit(cache=True, inline="always")
def total_force(t, q, v, shk, vint, exc, work, out):
    """out = F_ext(t) + Φᵀ F_shock; returns a diverging shock's index or -1."""
    out[:] = 0.0
    external_force(t, exc, out)
    flags, params, rots, phis, polars = shk.flags, shk.params, shk.rots, shk.phis, shk.polars
    support_motion(t, exc, params)
    shock = shock_forces(q, v, flags, params, rots, phis, polars, vint, work, out)
    if shock < 0 and shk.laws.shape[1] > 0:  # other relations (laws/): rows with a law
        law_forces(
            t,
            q,
            v,
            flags,
            params,
            rots,
            phis,
            polars,
            shk.laws,
            shk.rphis,
            vint,
            shk.law_scratch,
            out,
        )
    return shock


@njit(cache=True, _nrt=False)
def total_force_at(t, q, v, shk, vint, exc, work, f):
    """:func:`total_force` as a function of its own, for the steps that
    evaluate it at several call sites (DEVOGE, NEWMARK's general path): one
    compiled copy instead of one per site."""
    return total_force(t, q, v, shk, vint, exc, work, f)


@njit(cache=True, inline="always")
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


@njit(cache=True, inline="always")
def matvec(a, x, out, diagonal):
    out[:] = 0.0
    matvec_add(a, x, 1.0, out, diagonal)


@njit(cache=True, inline="always")
def matvec_row(a, x, i):
    """(a @ x)[i] with :func:`matvec`'s operations in its order for a full
    ``a`` (so the same value), for loops that use one row at a time instead
    of a scratch vector."""
    s = 0.0
    for j in range(x.shape[0]):
        s += a[i, j] * x[j]
    return s


@njit(cache=True, inline="always")
def acceleration(f, q, v, lin, residual, out):
    """out = M⁻¹ (f - K q - C v); ``residual`` is scratch."""
    minv, stiffness, damping, is_diagonal = lin
    diagonal = is_diagonal[0] == 1
    for i in range(f.shape[0]):  # residual[:] = f, which needs a temporary under _nrt=False
        residual[i] = f[i]
    matvec_add(stiffness, q, -1.0, residual, diagonal)
    matvec_add(damping, v, -1.0, residual, diagonal)
    matvec(minv, residual, out, diagonal)


@njit(cache=True, inline="always")
def copy_into(target, source):
    """target[...] = source for 1-D or 2-D arrays of the same shape, without
    the temporary numba makes for a slice assignment (loops compiled with
    ``_nrt=False`` cannot allocate it)."""
    flat_target, flat_source = target.reshape(target.size), source.reshape(source.size)
    for i in range(flat_source.shape[0]):
        flat_target[i] = flat_source[i]


@njit(cache=True, inline="always")
def all_finite(x):
    for i in range(x.shape[0]):
        if not (abs(x[i]) < 1.0e300):
            return False
    return True


@njit(cache=True, inline="always")
def state_acceleration(t, q, v, out, f, residual, vint, work, model):
    """out = M⁻¹ (F_ext(t) + F_shock(q, v) - K q - C v), the shock states
    ``vint`` updated (code_aster's dtmacce). Returns a diverging shock's
    index or -1; ``f`` receives the total force."""
    lin, shk, exc = model[LINEAR], model[SHOCKS], model[LOADS]
    shock = total_force(t, q, v, shk, vint, exc, work, f)
    acceleration(f, q, v, lin, residual, out)
    return shock


@njit(cache=True, _nrt=False)
def evaluate(t, q, v, out, f, residual, vint, work, model):
    """:func:`state_acceleration` as a function of its own, for the steps
    that evaluate several times (TRBDF2): numba's inlining copies the
    callee's IR at each call site, so three sites compiled three copies
    (93 s of compilation instead of 32; the calls cost ~2 % of a step)."""
    return state_acceleration(t, q, v, out, f, residual, vint, work, model)


@njit(cache=True, inline="always")
def diagonal_acceleration(a, f, q, v, mass_inverse, stiffness, damping):
    """a = (f - k q - c v) / m for diagonal generalized matrices stored as
    1-D arrays, in one pass; returns whether every a[i] is finite. The same
    arithmetic as :func:`acceleration` (f - k q - c v, then times 1/m)."""
    finite = True
    for i in range(a.shape[0]):
        x = (f[i] - stiffness[i] * q[i] - damping[i] * v[i]) * mass_inverse[i]
        a[i] = x
        if not (abs(x) < 1.0e300):
            finite = False
    return finite


@njit(cache=True, inline="always")
def full_acceleration(a, f, q, v, mass_inverse, stiffness, damping, residual):
    """a = M⁻¹ (f - K q - C v) for full (n, n) matrices; returns whether
    every a[i] is finite (the arithmetic of :func:`acceleration`)."""
    n = a.shape[0]
    for i in range(n):
        sk = 0.0
        sc = 0.0
        for j in range(n):
            sk += stiffness[i, j] * q[j]
        for j in range(n):
            sc += damping[i, j] * v[j]
        residual[i] = f[i] - sk - sc
    finite = True
    for i in range(n):
        s = 0.0
        for j in range(n):
            s += mass_inverse[i, j] * residual[j]
        a[i] = s
        if not (abs(s) < 1.0e300):
            finite = False
    return finite
