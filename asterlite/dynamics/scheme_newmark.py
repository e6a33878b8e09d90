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
"""

from __future__ import annotations

import numpy as np
from numba import njit

from asterlite.dynamics import energy as E
from asterlite.dynamics import implicit as I
from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import all_finite, loads_ready, total_force

# vector rows: index-2 displacement and velocity, right-hand side, pivots
Q_INDEX2, V_INDEX2, RHS, PIVOTS = range(4)
VECTOR_ROWS = 4
S_BETA, S_GAMMA, S_DT_BUILT, S_DIAGONAL = range(4)
A1 = 4  # a1..a8 follow
N_SCALARS = 12
EPS = np.finfo(np.float64).eps


def prepare(system, dt, options):
    rows = I.new_rows(VECTOR_ROWS, system)
    scalars = np.zeros(N_SCALARS)
    scalars[S_BETA], scalars[S_GAMMA] = options.beta, options.gamma
    scalars[S_DT_BUILT] = -1.0
    scalars[S_DIAGONAL] = 1.0 if system.diagonal else 0.0
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
    rows, scalars = memory[0], memory[1]
    shk, exc = model[1], model[2]
    n = q.shape[0]
    diagonal = scalars[S_DIAGONAL] == 1.0
    built = scalars[S_DT_BUILT]
    if built < 0.0 or abs(dt / built - 1.0) >= EPS:
        if not build_operators(rows, scalars, dt, n):
            return K.STATUS_NOT_FINITE, -1, dt, dt, 0
    c = scalars[A1 : A1 + 8]
    q2, v2, rhs = rows[Q_INDEX2], rows[V_INDEX2], rows[RHS]
    shock = total_force(t + dt, q2, v2, shk, vint, exc, work, f)
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
    return K.STATUS_DONE, -1, dt, dt, 0


@njit(cache=True)
def run_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive, energy):
    balance = E.is_active(energy)  # ENERGIE: asterlite.dynamics.energy
    while K.unfinished(clock, counters, eps):
        paused = K.pause_status(counters, archive[0])
        if paused:
            return paused
        if not loads_ready(clock, model[2]):
            return K.STATUS_LOADS
        t, dt = K.plan_step(clock, counters, instants, eps)
        status, shock, dt_used, dt_next, rejected = step(
            t, dt, counters[K.K_STEP], state, memory, model
        )
        if status != K.STATUS_DONE:
            return K.record_failure(clock, counters, status, shock, dt_used)
        result = (dt_used, dt_next, rejected)
        archived = counters[K.K_ARCHIVED]
        K.complete_step(clock, counters, state, instants, pas_arch, eps, archive, result)
        if balance:
            E.hook(energy, archived, counters, clock, dt_used, state, model)
    return K.STATUS_DONE
