"""NEWMARK: implicit on the linear part in displacement form, with
code_aster's treatment of the nonlinear forces (dtmforc at index 2).

With a1 = 1/(β dt²), a2 = γ/(β dt), a3 = 1/(β dt), a4 = 1/(2β) - 1,
a5 = γ/β - 1, a6 = dt/2 (γ/β - 2), a7 = dt (1 - γ), a8 = γ dt:

    (a1 M + a2 C + K) q_{n+1} = F_{n+1} + (a3 M + a5 C) v_n
                                + (a1 M + a2 C) q_n + (a4 M + a6 C) a_n
    a_{n+1} = a1 (q_{n+1} - q_n - dt v_n) - a4 a_n
    v_{n+1} = v_n + a7 a_n + a8 a_{n+1}

F_{n+1} is the external force at t_{n+1} plus the shock forces evaluated
at the state held at code_aster's index 2: the previous step's result,
i.e. (q_n, v_n) -- and zero on the very first step, where that storage is
freshly allocated. The operators are rebuilt when dt changes. Order 2 and
unconditionally stable on the linear part for the default β = 1/4,
γ = 1/2 (trapezoidal rule).

``SchemeOptions.force_at_step_start`` (decks of code_aster 13 to 15, see
asterlite.legacy.v15.OLD_BEHAVIOURS): F_{n+1} above is replaced by the forces
at the start of the step, F(t_n, q_n, v_n), as code_aster 15's intnewm did
(it evaluated the forces once per step, after the update, for the next
step); first order in the load, so results differ from today's by O(dt).
"""

from __future__ import annotations

import numpy as np

from asterlite.dynamics import energy as E
from asterlite.dynamics import implicit as I
from asterlite.dynamics import kernel as K
from asterlite.dynamics.contact import local_shock_forces
from asterlite.dynamics.forces import (
    add_external_force,
    all_finite,
    loads_cover,
    local_support_motion,
    total_force_at,
)
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import LOADS, LOCAL, ROWS, SCALARS, SHOCKS

# vector rows: index-2 displacement and velocity, right-hand side, pivots
Q_INDEX2, V_INDEX2, RHS, PIVOTS = range(4)
VECTOR_ROWS = 4
S_BETA, S_GAMMA, S_DT_BUILT, S_DIAGONAL = range(4)
A1 = 4  # a1..a8 follow
S_FORCE_AT_START = 12  # 1.0: code_aster 13-15's forces of the step's start
N_SCALARS = 13
EPS = np.finfo(np.float64).eps


def prepare(system, dt, options):
    rows = I.new_rows(VECTOR_ROWS, system)
    scalars = np.zeros(N_SCALARS)
    scalars[S_BETA], scalars[S_GAMMA] = options.beta, options.gamma
    scalars[S_DT_BUILT] = -1.0
    scalars[S_DIAGONAL] = 1.0 if system.diagonal else 0.0
    scalars[S_FORCE_AT_START] = 1.0 if getattr(options, "force_at_step_start", False) else 0.0
    return (rows, scalars, np.zeros((1, 1))), False


@njit(cache=True)
def build_operators(rows, scalars, dt, n):
    beta, gamma = scalars[S_BETA], scalars[S_GAMMA]
    a = scalars[A1 : A1 + 8]
    a[0] = 1.0 / (beta * dt * dt)
    a[1] = gamma / (beta * dt)
    a[2] = 1.0 / (beta * dt)
    a[3] = 1.0 / (2.0 * beta) - 1.0
    a[4] = gamma / beta - 1.0
    a[5] = (dt / 2.0) * (gamma / beta - 2.0)
    a[6] = dt * (1.0 - gamma)
    a[7] = gamma * dt
    mass = I.block(rows, VECTOR_ROWS, I.B_MASS, n)
    stiffness = I.block(rows, VECTOR_ROWS, I.B_STIFF, n)
    damping = I.block(rows, VECTOR_ROWS, I.B_DAMP, n)
    I.combine(I.block(rows, VECTOR_ROWS, I.B_KEFF, n), mass, stiffness, damping, a[0], 1.0, a[1])
    I.combine(I.block(rows, VECTOR_ROWS, I.B_F1, n), mass, stiffness, damping, a[2], 0.0, a[4])
    I.combine(I.block(rows, VECTOR_ROWS, I.B_F2, n), mass, stiffness, damping, a[0], 0.0, a[1])
    I.combine(I.block(rows, VECTOR_ROWS, I.B_F3, n), mass, stiffness, damping, a[3], 0.0, a[5])
    diagonal = scalars[S_DIAGONAL] == 1.0
    scalars[S_DT_BUILT] = dt
    return I.factor_effective(I.block(rows, VECTOR_ROWS, I.B_KEFF, n), rows[PIVOTS], diagonal)


@njit(cache=True)
def step(t, dt, index, state, memory, model):
    q, v, a, f, vint, vint_save, work = state
    rows, scalars = memory[ROWS], memory[SCALARS]
    shk, exc = model[SHOCKS], model[LOADS]
    n = q.shape[0]
    diagonal = scalars[S_DIAGONAL] == 1.0
    built = scalars[S_DT_BUILT]
    if built < 0.0 or abs(dt / built - 1.0) >= EPS:
        if not build_operators(rows, scalars, dt, n):
            return K.STATUS_NOT_FINITE, -1, dt, dt, 0
    c = scalars[A1 : A1 + 8]
    q2, v2, rhs = rows[Q_INDEX2], rows[V_INDEX2], rows[RHS]
    at_start = scalars[S_FORCE_AT_START] == 1.0
    if not at_start:  # else f holds F(t, q, v): the loop's start or the previous step's end
        shock = total_force_at(t + dt, q2, v2, shk, vint, exc, work, f)
        if shock >= 0:
            return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    rhs[:] = f
    I.apply(I.block(rows, VECTOR_ROWS, I.B_F1, n), v, 1.0, rhs, diagonal)
    I.apply(I.block(rows, VECTOR_ROWS, I.B_F2, n), q, 1.0, rhs, diagonal)
    I.apply(I.block(rows, VECTOR_ROWS, I.B_F3, n), a, 1.0, rhs, diagonal)
    I.solve_effective(I.block(rows, VECTOR_ROWS, I.B_KEFF, n), rows[PIVOTS], rhs, diagonal)
    for i in range(n):
        a_new = -c[3] * a[i] + c[0] * (rhs[i] - q[i] - dt * v[i])
        v[i] = v[i] + c[6] * a[i] + c[7] * a_new
        a[i] = a_new
        q[i] = rhs[i]
        q2[i] = q[i]
        v2[i] = v[i]
    if not (all_finite(q) and all_finite(v)):
        return K.STATUS_NOT_FINITE, -1, dt, dt, 0
    if at_start:  # the forces of the next step's start
        shock = total_force_at(t + dt, q, v, shk, vint, exc, work, f)
        if shock >= 0:
            return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    return K.STATUS_DONE, -1, dt, dt, 0


@njit(cache=True, _nrt=False)
def fast_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy):
    """The NEWMARK loop :func:`integrate.integrate` runs: ``step``'s
    arithmetic on plain arrays with the helpers inlined, no reference
    counting (``_nrt=False``: nothing here allocates) and the shock
    kinematics in each shock's local frame, as DIFF_CENTRE's
    :func:`scheme_diff_centre.specialised_loop` (same results as the
    general path, :func:`loop.scheme_loop` around :func:`step`, when the
    shock frames are the global one, rounding otherwise). A loop of its own
    for speed, as DIFF_CENTRE's (docs/performance.md: about 5x faster than
    the general path on the tube)."""
    exc = model[LOADS]
    flags, params, rots, polars = (
        model[SHOCKS].flags,
        model[SHOCKS].params,
        model[SHOCKS].rots,
        model[SHOCKS].polars,
    )
    shapes, rest, drive = model[LOCAL]  # integrate.local_frame_bundle
    out_t, out_order, out_q, out_v, out_a, out_vint, out_info = archive
    return specialised_loop(
        clock, counters, instants, pas_arch, eps,
        state.q, state.v, state.a, state.f, state.vint, memory[ROWS], memory[SCALARS],
        flags, params, rots, shapes, rest, polars, drive,
        exc.vectors, exc.abscissas, exc.ordinates, exc.layout, exc.pending, exc.cursors,
        exc.codes, exc.constants, exc.stack,
        exc.drive_shapes, exc.drive_abscissas, exc.drive_ordinates, exc.drive_layout,
        exc.drive_pending, exc.drive_cursors,
        out_t, out_order, out_q, out_v, out_a, out_vint, out_info,
        energy, model[SHOCKS], exc,
    )  # fmt: skip


@njit(cache=True, inline="always")
def local_force(
    t, q, v, f, vint, flags, params, rots, shapes, rest, polars, drive,
    load_vectors, load_abscissas, load_ordinates, load_layout, load_cursors, load_codes,
    load_constants, load_stack, support_shapes, support_abscissas, support_ordinates,
    support_layout, support_cursors,
):  # fmt: skip
    """f = F_ext(t) + the shock forces at (q, v) (``forces.total_force`` in
    the shocks' local frames); returns a diverging shock's index or -1."""
    for i in range(f.shape[0]):
        f[i] = 0.0
    add_external_force(
        t, load_vectors, load_abscissas, load_ordinates, load_layout, load_cursors,
        load_codes, load_constants, load_stack, f,
    )  # fmt: skip
    local_support_motion(
        t, rots, support_shapes, support_abscissas, support_ordinates, support_layout,
        support_cursors, drive,
    )  # fmt: skip
    return local_shock_forces(q, v, flags, params, shapes, rest, polars, drive, vint, f)


@njit(cache=True, _nrt=False)
def start_force(
    t, q, v, f, vint, flags, params, rots, shapes, rest, polars, drive,
    load_vectors, load_abscissas, load_ordinates, load_layout, load_cursors, load_codes,
    load_constants, load_stack, support_shapes, support_abscissas, support_ordinates,
    support_layout, support_cursors,
):  # fmt: skip
    """:func:`local_force` as a function of its own for the loop's second
    call site (code_aster 13-15's forces of the step's start): numba's
    inlining copies the shock forces at each site, and a second copy made
    NEWMARK's loop the slowest kernel to compile."""
    return local_force(
        t, q, v, f, vint, flags, params, rots, shapes, rest, polars, drive,
        load_vectors, load_abscissas, load_ordinates, load_layout, load_cursors, load_codes,
        load_constants, load_stack, support_shapes, support_abscissas, support_ordinates,
        support_layout, support_cursors,
    )  # fmt: skip


@njit(cache=True, inline="always")
def newmark_update(rows, scalars, q, v, a, f, dt, n):
    """``step``'s update once the force f is known: the right-hand side,
    the solve, then a, v, q and the index-2 copies."""
    diagonal = scalars[S_DIAGONAL] == 1.0
    c = scalars[A1 : A1 + 8]
    q2, v2, rhs = rows[Q_INDEX2], rows[V_INDEX2], rows[RHS]
    f1 = rows[VECTOR_ROWS + I.B_F1 * n : VECTOR_ROWS + (I.B_F1 + 1) * n]  # I.block inline
    f2 = rows[VECTOR_ROWS + I.B_F2 * n : VECTOR_ROWS + (I.B_F2 + 1) * n]
    f3 = rows[VECTOR_ROWS + I.B_F3 * n : VECTOR_ROWS + (I.B_F3 + 1) * n]
    keff = rows[VECTOR_ROWS + I.B_KEFF * n : VECTOR_ROWS + (I.B_KEFF + 1) * n]
    if diagonal:  # I.apply and I.solve_effective written out
        for i in range(n):
            x = f[i]
            x += 1.0 * f1[i, i] * v[i]
            x += 1.0 * f2[i, i] * q[i]
            x += 1.0 * f3[i, i] * a[i]
            rhs[i] = x / keff[i, i]
    else:
        for i in range(n):
            rhs[i] = f[i]
        I.apply(f1, v, 1.0, rhs, False)
        I.apply(f2, q, 1.0, rhs, False)
        I.apply(f3, a, 1.0, rhs, False)
        I.solve_effective(keff, rows[PIVOTS], rhs, False)
    for i in range(n):
        a_new = -c[3] * a[i] + c[0] * (rhs[i] - q[i] - dt * v[i])
        v[i] = v[i] + c[6] * a[i] + c[7] * a_new
        a[i] = a_new
        q[i] = rhs[i]
        q2[i] = q[i]
        v2[i] = v[i]


@njit(cache=True, _nrt=False)
def specialised_loop(
    clock, counters, instants, pas_arch, eps, q, v, a, f, vint, rows, scalars,
    flags, params, rots, shapes, rest, polars, drive,
    load_vectors, load_abscissas, load_ordinates, load_layout, load_pending, load_cursors,
    load_codes, load_constants, load_stack,
    support_shapes, support_abscissas, support_ordinates, support_layout, support_pending,
    support_cursors,
    out_t, out_order, out_q, out_v, out_a, out_vint, out_info, energy, shk, exc,
):  # fmt: skip
    """The NEWMARK loop on plain arrays (see :func:`fast_loop`); the status
    codes, archiving rules and operator rebuilds of the general path."""
    n = q.shape[0]
    balance = E.is_active(energy)
    q2, v2 = rows[Q_INDEX2], rows[V_INDEX2]
    at_start = scalars[S_FORCE_AT_START] == 1.0
    while K.unfinished(clock, counters, eps):
        paused = K.pause_status(counters, out_t)
        if paused:
            return paused
        t_ahead = clock[K.C_TIME] + 2.0 * clock[K.C_STEP]
        if not (
            loads_cover(t_ahead, load_abscissas, load_layout, load_pending)
            and loads_cover(t_ahead, support_abscissas, support_layout, support_pending)
        ):
            return K.STATUS_LOADS
        t, dt = K.plan_step(clock, counters, instants, eps)
        built = scalars[S_DT_BUILT]
        if built < 0.0 or abs(dt / built - 1.0) >= EPS:
            if not build_operators(rows, scalars, dt, n):
                return K.record_failure(clock, counters, K.STATUS_NOT_FINITE, -1, dt)
        if not at_start:  # else f holds F(t, q, v): the loop's start or the previous step's end
            shock = local_force(
                t + dt, q2, v2, f, vint, flags, params, rots, shapes, rest, polars, drive,
                load_vectors, load_abscissas, load_ordinates, load_layout, load_cursors,
                load_codes, load_constants, load_stack, support_shapes, support_abscissas,
                support_ordinates, support_layout, support_cursors,
            )  # fmt: skip
            if shock >= 0:
                return K.record_failure(clock, counters, K.STATUS_SHOCK_DIVERGED, shock, dt)
        newmark_update(rows, scalars, q, v, a, f, dt, n)
        if not (all_finite(q) and all_finite(v)):
            return K.record_failure(clock, counters, K.STATUS_NOT_FINITE, -1, dt)
        if at_start:  # the forces of the next step's start
            shock = start_force(
                t + dt, q, v, f, vint, flags, params, rots, shapes, rest, polars, drive,
                load_vectors, load_abscissas, load_ordinates, load_layout, load_cursors,
                load_codes, load_constants, load_stack, support_shapes, support_abscissas,
                support_ordinates, support_layout, support_cursors,
            )  # fmt: skip
            if shock >= 0:
                return K.record_failure(clock, counters, K.STATUS_SHOCK_DIVERGED, shock, dt)
        archived = counters[K.K_ARCHIVED] if balance else 0
        K.advance_clock(
            clock, counters, q, v, a, vint, instants, pas_arch, eps,
            out_t, out_order, out_q, out_v, out_a, out_vint, out_info, dt, dt, 0,
        )  # fmt: skip
        if balance:
            E.after_step(
                energy, archived, counters[K.K_ARCHIVED], clock[K.C_TIME], dt,
                q, v, a, vint, shk, exc,
            )  # fmt: skip
    return K.STATUS_DONE
