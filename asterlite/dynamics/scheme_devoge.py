"""DEVOGE: Devogelaere-Fu scheme (order 4), with code_aster's step control.

The state is carried at whole steps (index 1, t) and half steps (index 2,
t - dt/2). With r = M⁻¹F - M⁻¹K q (the "reduced" force) and C' = M⁻¹C:

    q3 = q1 + dt/2 v1 + dt²/24 (4 r1 - r2 - C'(4 v1 - v2))        t + dt/2
    v3 = v1 + dt/4 (r1 + r3 - C'(v1 + v3))                       implicit in C'
    q4 = q1 + dt v1 + dt²/6 (r1 + 2 r3 - C'(v1 + 2 v3))           t + dt
    v4 = v1 + dt/6 (r1 + 4 r3 + r4 - C'(v1 + 4 v3 + v4))         Simpson

Shock forces at 3 and 4 use the finite-difference velocities
(q3 - q1)/(dt/2) and (q4 - q3)/(dt/2), as code_aster does. Unless the step's
bounds are equal the step adapts: a local error estimate on q3, compared
with tol * (|q| + alpha), rescales dt by 0.5..1.5 (up to 24 retries).

asterlite's guard (not in code_aster): the shock forces, with their
finite-difference velocities, are explicit, so the adaptive step never
exceeds the stability limit of the stiffest damped shock (c_n·dt/M
<= 2 for a heavy damping: :func:`asterlite.dynamics.adapt_control.
shock_damping_step` with radius 2, the modal damping being implicit; inf
without normal or tangential shock damping). The error estimate on q3 does not see that
instability: entering a stiffly damped contact after a long free flight it
accepts steps with c_n·dt/M ~ 15 that double the energy.
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.dynamics import kernel as K
from asterlite.dynamics.adapt_control import shock_damping_step
from asterlite.dynamics.forces import all_finite, copy_into, matvec_row
from asterlite.dynamics.jit import njit
from asterlite.dynamics.kernel import (
    STATUS_DONE,
    STATUS_NOT_FINITE,
    STATUS_SHOCK_DIVERGED,
    STATUS_STEP_UNDERFLOW,
)
from asterlite.dynamics.layouts import LINEAR, ROWS, SCALARS, SHOCKS
from asterlite.dynamics.linalg import lu_factor, lu_solve
from asterlite.dynamics.local_frame import copy_vector, total_force_at

Q2, V2, R2, R1, Q3, V3, R3, Q4, V4, R4, X1, Q2E, Q1P, V1P, R1P, Q3E, X2 = range(17)
P0, P1, P2 = 17, 18, 19  # the pivots of H0, H1, H2's LU factors (full damping)
# the diagonals of M⁻¹, M⁻¹C, M⁻¹K, H1, H2 as rows: a diagonal system's loops
# then read contiguous memory (and vectorise) instead of a[i, i]
D_MINV, D_C, D_K, D_H1, D_H2 = 20, 21, 22, 23, 24
MATRIX_ROWS = 25  # then invm_c, invm_k, H1, H2, H0 (LU factors when full): n rows each
S_READY, S_DTOLD, S_OLDPAS1, S_OLDPAS2, S_ADAPTIVE, S_TOL, S_ALPHA, S_DTMIN, S_DTMAX, S_HDT = range(
    10
)
S_CAP = 10  # the shock damping cap (-1 until the first step computes it)
MEMORY_SCALARS = 11
STAGE_RADIUS = 2.0  # real stability interval of the explicit shock damping
EPS = np.finfo(np.float64).eps


def memory_rows(n: int) -> int:
    return MATRIX_ROWS + 5 * n


def prepare(system, dt, options):
    """(memory, adaptive): operators and control parameters. The step adapts
    unless its bounds are equal (defaults 1e-10 and 1e10 times dt)."""
    n = system.n_modes
    dt_min = options.dt_min if options.dt_min is not None else 1.0e-10 * dt
    dt_max = options.dt_max if options.dt_max is not None else 1.0e10 * dt
    adaptive = abs(dt_max / dt_min - 1.0) >= EPS
    mem = np.zeros((memory_rows(n), n))
    smem = np.zeros(MEMORY_SCALARS)
    fill_operators(
        mem, smem, system.minv, system.stiffness, system.damping, adaptive,
        options.tolerance, options.alpha, dt_min, dt_max,
    )  # fmt: skip
    return (mem, smem, np.zeros((1, 1))), adaptive


def fill_operators(mem, smem, minv, stiffness, damping, adaptive, tolerance, alpha, dt_min, dt_max):
    n = minv.shape[0]
    ops = mem[MATRIX_ROWS:]
    ops[0:n] = minv @ damping
    ops[n : 2 * n] = minv @ stiffness
    # fill_diagonal_rows's copies, in numpy: a run on the compiled C++ loop
    # then never imports numba (the rotation loop calls the kernel itself)
    mem[D_MINV], mem[D_C], mem[D_K] = (
        np.diagonal(minv),
        np.diagonal(ops[0:n]),
        np.diagonal(ops[n : 2 * n]),
    )
    smem[:] = 0.0
    smem[S_ADAPTIVE] = 1.0 if adaptive else 0.0
    smem[S_TOL], smem[S_ALPHA] = tolerance, alpha
    smem[S_DTMIN], smem[S_DTMAX] = dt_min, dt_max
    smem[S_HDT] = -1.0
    smem[S_CAP] = -1.0


@njit(cache=True, inline="always")  # views of mem, no tuple of them returned by a call
def operators(mem, n):
    base = MATRIX_ROWS
    return (
        mem[base : base + n],
        mem[base + n : base + 2 * n],
        mem[base + 2 * n : base + 3 * n],
        mem[base + 3 * n : base + 4 * n],
    )


@njit(cache=True)
def fill_diagonal_rows(mem, minv, n):
    """The rows D_MINV, D_C, D_K from M⁻¹ and the M⁻¹C, M⁻¹K blocks (after
    ``prepare`` and after a rotation speed's update of those blocks)."""
    invm_c, invm_k, _, _ = operators(mem, n)
    for i in range(n):
        mem[D_MINV, i] = minv[i, i]
        mem[D_C, i] = invm_c[i, i]
        mem[D_K, i] = invm_k[i, i]


@njit(cache=True, inline="always")
def start_operator(mem, n):
    """H0's block (built and factored once per run, by :func:`start`)."""
    base = MATRIX_ROWS + 4 * n
    return mem[base : base + n]


@njit(cache=True, inline="always")
def times(a, a_diagonal, x, i, diagonal):
    """(a @ x)[i], from ``a``'s diagonal row when the system is diagonal."""
    if diagonal:
        return a_diagonal[i] * x[i]
    return matvec_row(a, x, i)


@njit(cache=True)
def update_implicit_operators(mem, invm_c, h1, h2, dt, diagonal):
    """H1 = 4I + dt C', H2 = 6I + dt C' (and their diagonal rows),
    LU-factored in place when full (only when the step changes); False when
    one is singular."""
    n = invm_c.shape[0]
    for i in range(n):
        for j in range(n):
            h1[i, j] = dt * invm_c[i, j]
            h2[i, j] = dt * invm_c[i, j]
        h1[i, i] += 4.0
        h2[i, i] += 6.0
        mem[D_H1, i] = h1[i, i]
        mem[D_H2, i] = h2[i, i]
    if diagonal:
        return True
    return lu_factor(h1, mem[P1]) and lu_factor(h2, mem[P2])


@njit(cache=True, inline="always")
def solve_with(h, h_diagonal, pivots, rhs, out, diagonal):
    """out = H⁻¹ rhs, H diagonal or LU-factored (no allocation: the step is
    compiled without reference counting)."""
    if diagonal:
        for i in range(out.shape[0]):
            out[i] = rhs[i] / h_diagonal[i]
    else:
        for i in range(out.shape[0]):
            out[i] = rhs[i]
        lu_solve(h, pivots, out)


@njit(cache=True, inline="always")
def reduced_force(f, q, minv, invm_k, mem, out, diagonal):
    """out = M⁻¹ f - M⁻¹K q."""
    d_minv, d_k = mem[D_MINV], mem[D_K]
    for i in range(out.shape[0]):
        out[i] = times(minv, d_minv, f, i, diagonal) - times(invm_k, d_k, q, i, diagonal)


@njit(cache=True)
def start(dt, q, v, f, mem, smem, minv, invm_c, invm_k, h1, h2, diagonal):
    """Build the half-step state at t - dt/2 from (q, v, F) at t; False when
    an implicit operator is singular."""
    n = q.shape[0]
    q2, v2, r2, r1, x1, x2 = mem[Q2], mem[V2], mem[R2], mem[R1], mem[X1], mem[X2]
    if not update_implicit_operators(mem, invm_c, h1, h2, dt, diagonal):
        return False
    smem[S_HDT] = dt
    copy_vector(mem[Q1P], q)
    copy_vector(mem[V1P], v)
    copy_vector(mem[R1P], f)  # code_aster keeps the raw force here on the first step
    smem[S_OLDPAS1] = dt
    smem[S_OLDPAS2] = dt
    smem[S_DTOLD] = dt
    half = dt / 2.0
    d_c = mem[D_C]
    reduced_force(f, q, minv, invm_k, mem, r1, diagonal)
    for i in range(n):
        q2[i] = q[i] - half * v[i] + (half / 4.0) * (r1[i] - times(invm_c, d_c, v, i, diagonal))
    reduced_force(f, q2, minv, invm_k, mem, r2, diagonal)
    # v2 from H0 v2 = H1 v1 - dt (r1 + r2), H0 = 4I - dt C'
    h0 = start_operator(mem, n)
    h0_diagonal = x1  # free here
    for i in range(n):
        for j in range(n):
            h0[i, j] = -dt * invm_c[i, j]
        h0[i, i] += 4.0
        h0_diagonal[i] = h0[i, i]
    for i in range(n):
        x2[i] = 4.0 * v[i] + dt * times(invm_c, d_c, v, i, diagonal) - dt * (r1[i] + r2[i])
    if not (diagonal or lu_factor(h0, mem[P0])):
        return False
    solve_with(h0, h0_diagonal, mem[P0], x2, v2, diagonal)
    if smem[S_ADAPTIVE] == 1.0:
        for i in range(n):
            mem[Q2E, i] = (
                (2.0 * q2[i] - q[i]) + half * (2.0 * v2[i] - v[i]) + (half**2 / 24.0) * 13.0 * r1[i]
            )
    smem[S_READY] = 1.0
    return True


@njit(cache=True, _nrt=False)
def step(t, dt, index, state, memory, model):
    """One step: the scheme's loop (:func:`loop.scheme_loop`) and the loops shared by every scheme
    call it. The forces through :func:`local_frame.total_force_at` (local
    frames with the model's 4th bundle). Compiled without reference
    counting: nothing in it or its callees allocates (the implicit
    operators are LU-factored in place, in the memory ``prepare`` made)."""
    q, v, a, f, vint, vint_save, work = state
    mem, smem = memory[ROWS], memory[SCALARS]
    lin, shk = model[LINEAR], model[SHOCKS]
    minv, stiffness, damping, is_diagonal = lin
    diagonal = is_diagonal[0] == 1
    n = q.shape[0]
    invm_c, invm_k, h1, h2 = operators(mem, n)
    adaptive = smem[S_ADAPTIVE] == 1.0
    if smem[S_CAP] < 0.0:
        smem[S_CAP] = shock_damping_step(lin, shk, False, STAGE_RADIUS)
    dt_max = min(smem[S_DTMAX], smem[S_CAP])
    if adaptive and dt > dt_max:
        dt = dt_max
    if smem[S_READY] == 0.0:
        if not start(dt, q, v, f, mem, smem, minv, invm_c, invm_k, h1, h2, diagonal):
            return STATUS_NOT_FINITE, -1, dt, dt, 0
    q2, v2, r2, r1 = mem[Q2], mem[V2], mem[R2], mem[R1]
    q3, v3, r3, q4, v4, r4 = mem[Q3], mem[V3], mem[R3], mem[Q4], mem[V4], mem[R4]
    x1, x2 = mem[X1], mem[X2]
    d_c, d_h1, d_h2 = mem[D_C], mem[D_H1], mem[D_H2]
    if adaptive:  # a rejected trial restores the shock states it changed
        copy_into(vint_save, vint)
    dtold = smem[S_DTOLD]
    attempts = 0
    dtnew = dt
    while True:
        half = dt / 2.0
        coeff = dt / dtold
        if abs(coeff - 1.0) >= EPS:
            if dt != smem[S_HDT]:
                if not update_implicit_operators(mem, invm_c, h1, h2, dt, diagonal):
                    return STATUS_NOT_FINITE, -1, dt, dt, attempts
                smem[S_HDT] = dt
            if attempts > 0:  # retry with a smaller step: rescale the half-step state
                for i in range(n):
                    r2[i] = r1[i] + coeff * (r2[i] - r1[i])
                    q2[i] = q[i] + coeff * (q2[i] - q[i])
                    v2[i] = v[i] + coeff * (v2[i] - v[i])
        # --- t + dt/2
        for i in range(n):
            x1[i] = 4.0 * v[i] - v2[i]
        for i in range(n):
            damped = times(invm_c, d_c, x1, i, diagonal)
            q3[i] = q[i] + half * v[i] + (dt * dt / 24.0) * (4.0 * r1[i] - r2[i] - damped)
            v3[i] = (q3[i] - q[i]) / half
        shock = total_force_at(t + half, q3, v3, vint, work, f, model)
        if shock >= 0:
            return STATUS_SHOCK_DIVERGED, shock, dt, dt, attempts
        reduced_force(f, q3, minv, invm_k, mem, r3, diagonal)
        for i in range(n):
            damped = times(invm_c, d_c, v, i, diagonal)
            x1[i] = 4.0 * (v[i] + (dt / 4.0) * (r1[i] + r3[i] - damped))
        solve_with(h1, d_h1, mem[P1], x1, v3, diagonal)
        # --- t + dt
        for i in range(n):
            x1[i] = v[i] + 2.0 * v3[i]
        for i in range(n):
            damped = times(invm_c, d_c, x1, i, diagonal)
            q4[i] = q[i] + dt * v[i] + (dt * dt / 6.0) * (r1[i] + 2.0 * r3[i] - damped)
            v4[i] = (q4[i] - q3[i]) / half
        shock = total_force_at(t + dt, q4, v4, vint, work, f, model)
        if shock >= 0:
            return STATUS_SHOCK_DIVERGED, shock, dt, dt, attempts
        reduced_force(f, q4, minv, invm_k, mem, r4, diagonal)
        for i in range(n):
            x1[i] = 4.0 * v3[i] + v[i]
        for i in range(n):
            damped = times(invm_c, d_c, x1, i, diagonal)
            x2[i] = 6.0 * (v[i] + (dt / 6.0) * (r4[i] + 4.0 * r3[i] + r1[i] - damped))
        solve_with(h2, d_h2, mem[P2], x2, v4, diagonal)
        if not (all_finite(q4) and all_finite(v4)):
            K.expose_trial(q, v, a, q4, v4, a)
            return STATUS_NOT_FINITE, -1, dt, dt, attempts
        if not adaptive:
            break
        err = relative_error(dt, q, v, mem, smem, attempts, n)
        attempts += 1
        dtnew = min(max(step_factor(err) * dt, smem[S_DTMIN]), dt_max)
        if err < 1.0 and abs(dtnew / dt - 1.0) < 0.15:
            dtnew = dt
        if err > 1.0 and attempts < 25:
            if abs(dtnew / dt - 1.0) < EPS:
                return STATUS_STEP_UNDERFLOW, -1, dt, dt, attempts
            dtold = dt
            dt = dtnew
            copy_into(vint, vint_save)
            continue
        copy_vector(mem[Q1P], q)
        copy_vector(mem[V1P], v)
        copy_vector(mem[R1P], r1)
        copy_vector(mem[Q2E], mem[Q3E])
        smem[S_OLDPAS1] = smem[S_OLDPAS2]
        smem[S_OLDPAS2] = dt
        break
    # --- shift: half step 3 -> 2, whole step 4 -> 1
    for i in range(n):
        a[i] = r4[i] - times(invm_c, d_c, v4, i, diagonal)
        q2[i], v2[i], r2[i] = q3[i], v3[i], r3[i]
        q[i], v[i], r1[i] = q4[i], v4[i], r4[i]
    smem[S_DTOLD] = dt
    rejected = attempts - 1 if attempts > 0 else 0
    return STATUS_DONE, -1, dt, dtnew, rejected


@njit(cache=True)
def step_factor(err):
    if err < (0.9 / 1.5) ** 4:
        return 1.5
    if err > (0.9 / 0.5) ** 4:
        return 0.5
    return 0.9 * err ** (-0.25)


@njit(cache=True)
def relative_error(dt, q, v, mem, smem, attempts, n):
    """code_aster's error estimate on the half-step displacement, divided by
    the tolerance; > 1 rejects the step."""
    half = dt / 2.0
    q2, r2, r1 = mem[Q2], mem[R2], mem[R1]
    q3, v3, r3, q4, v4, r4 = mem[Q3], mem[V3], mem[R3], mem[Q4], mem[V4], mem[R4]
    q2e, q3e = mem[Q2E], mem[Q3E]
    oldpas1, oldpas2 = smem[S_OLDPAS1], smem[S_OLDPAS2]
    same_as_last = abs(dt - oldpas2) <= EPS
    last_two_same = abs(oldpas2 - oldpas1) <= EPS
    if same_as_last and last_two_same:
        case = 0
    elif (not same_as_last) and last_two_same:
        case = 1
    elif not same_as_last:
        case = 3
    else:
        case = 0  # code_aster's second-step case is unreachable (it compares oldpas1 with itself)
    c24 = half * half / 24.0
    for i in range(n):
        if case == 0:
            q3e[i] = q4[i] - half * v4[i] + c24 * (7.0 * r4[i] + 6.0 * r3[i] - r1[i])
        else:
            q3e[i] = q[i] + half * v[i] + c24 * (7.0 * r1[i] + 6.0 * r3[i] - r4[i])
    pas0, pas1 = oldpas1 / 2.0, oldpas2 / 2.0
    if attempts == 1:
        for i in range(n):
            q2e[i] = (
                mem[Q1P, i]
                + pas1 * mem[V1P, i]
                + (pas1 * pas1 / 24.0) * (7.0 * mem[R1P, i] + 6.0 * r2[i] - r1[i])
            )
    w_new, w_old = 1.0, 1.0
    if case == 0:
        beta = 45.0 * half / 4.0
    elif case == 1:
        c1 = half / pas1
        w_old = c1**3 * (2.0 + c1) / 3.0
        beta = 5.0 * pas1 * (12.0 + 7.0 * c1 - c1 * c1) / (8.0 * c1)
    else:
        c0 = pas1 / pas0
        c1 = half / pas1
        w_old = c1**3 * (2.0 + c1) / 3.0
        w_new = (1.0 + 2.0 / c0) / 3.0
        beta = (
            5.0
            * half
            * (
                c0 * c0 * (12.0 + 7.0 * c1 - c1 * c1)
                + c0 * (20.0 + 12.0 * c1 - 2.0 * c1 * c1)
                + 2.0 * c1
                + 4.0
            )
            / (24.0 * c0 * c0 * c1 * c1)
        )
    total = 0.0
    magnitude = 0.0
    for i in range(n):
        e = (w_new * (q3e[i] - q3[i]) - w_old * (q2e[i] - q2[i])) / beta
        total += e * e
        m = max(abs(q3[i]), abs(v3[i] * dt))
        magnitude += m * m
    err_displacement = math.sqrt(total) * half / n
    scale = smem[S_TOL] * (math.sqrt(magnitude) / n + smem[S_ALPHA])
    if scale <= EPS:
        return 0.9**4
    return err_displacement / scale
