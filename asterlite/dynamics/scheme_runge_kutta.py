"""RUNGE_KUTTA_32 and RUNGE_KUTTA_54: explicit embedded Runge-Kutta pairs
on the first-order form (q' = v, v' = acceleration), one tableau-driven
kernel with code_aster's step controller (intruku32 / intruku54).

A tableau is data: ``a`` (stages x stages, row k gives the stage k + 1
from the stages 1..k + 1, its last row being the solution weights), ``c``
(stages + 1 nodes, the last one 1) and ``e`` (stages + 1 error weights,
the last one applied to the derivative at the solution, first-same-as-last).
The acceleration at the end of a step is the first stage of the next.

Error control, as code_aster: with the error estimates
E_q = dt Σ e_k v_k, E_v = dt Σ e_k a_k and for each mode the scales
s_q = max(tol |q_n + α|, tol (|Δq| + α), ε), s_v likewise,

    err = max(sqrt((Σ (E_q/s_q)² + Σ (E_v/s_v)²) / (2 n)), ε)

(ε = 100 machine epsilon). A retry whose error did not decrease by 1 %
accepts the step (err = 0.99). The factor 0.9 err^(-1/p) is bounded to
[0.2, 5] (p = 4 for the 3(2) pair, 6 for the 5(4) pair, code_aster's
exponents); the step is retried while err >= 1 and the new step stays
above its lower bound (falling below it stops the run), and the next step
is min(upper bound, factor dt). Equal bounds give a fixed step.

asterlite's guard (not in code_aster): the stages evaluate the shock
forces explicitly, so an adaptive step never exceeds the stability limit
of the stiffest damped shock (c·dt inside the tableau's real stability
interval [-radius, 0], :func:`asterlite.dynamics.adapt_control.
shock_damping_step`, inf without normal or tangential shock damping). Without it a long
free flight grows the step far beyond that limit; entering the contact,
the first retries amplify the stages so much that the error grows as the
step shrinks, and the rule above accepts a step that multiplies the energy
(c_n·dt/M ~ 70 at the contact entry: 20 times the initial energy).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.dynamics import kernel as K
from asterlite.dynamics.adapt_control import shock_damping_step
from asterlite.dynamics.forces import all_finite, copy_into
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import LINEAR, ROWS, SHOCKS, TABLE
from asterlite.dynamics.local_frame import copy_vector, evaluate


@dataclass(frozen=True)
class Tableau:
    name: str
    a: np.ndarray
    c: np.ndarray
    e: np.ndarray
    exponent: float  # of the step factor 0.9 err^(-1/exponent)

    @property
    def stages(self) -> int:
        return self.a.shape[0]

    @property
    def radius(self) -> float:
        """Length of the real stability interval [-radius, 0] of the stage
        update (|R(-x)| <= 1, R the stability function of the weights)."""
        return real_stability_radius(self.a)

    def table(self) -> np.ndarray:
        """Packed for the kernel: rows 0..s-1 = a (padded), row s = c, row s+1 = e."""
        s = self.stages
        out = np.zeros((s + 2, s + 1))
        out[:s, :s] = self.a
        out[s] = self.c
        out[s + 1] = self.e
        return out


BOGACKI_SHAMPINE_32 = Tableau(
    "RUNGE_KUTTA_32",
    a=np.array(
        [
            [1 / 2, 0.0, 0.0],
            [0.0, 3 / 4, 0.0],
            [2 / 9, 1 / 3, 4 / 9],
        ]
    ),
    c=np.array([0.0, 1 / 2, 3 / 4, 1.0]),
    e=np.array([5 / 72, -1 / 12, -1 / 9, 1 / 8]),
    exponent=4.0,
)

DORMAND_PRINCE_54 = Tableau(
    "RUNGE_KUTTA_54",
    a=np.array(
        [
            [1 / 5, 0, 0, 0, 0, 0],
            [3 / 40, 9 / 40, 0, 0, 0, 0],
            [44 / 45, -56 / 15, 32 / 9, 0, 0, 0],
            [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0, 0],
            [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0],
            [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84],
        ],
        dtype=float,
    ),
    c=np.array([0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0, 1.0]),
    e=np.array([71 / 57600, 0.0, -71 / 16695, 71 / 1920, -17253 / 339200, 22 / 525, -1 / 40]),
    exponent=6.0,
)


def stability_function(a: np.ndarray, z: complex) -> complex:
    """R(z) = 1 + z bᵀ(I - z A)⁻¹ 1 of the packed ``a`` (stage rows, then
    the weights)."""
    s = a.shape[0]
    matrix = np.zeros((s, s))
    matrix[1:, : s - 1] = a[:-1, : s - 1]
    stages = np.linalg.solve(np.eye(s) - z * matrix, np.ones(s, dtype=complex))
    return complex(1.0 + z * (a[-1] @ stages))


def real_stability_radius(a: np.ndarray) -> float:
    """The first x > 0 where |R(-x)| exceeds 1 (bisection, 1e-12)."""
    x = 0.01
    while abs(stability_function(a, -x)) <= 1.0:
        x += 0.01
    low, high = x - 0.01, x
    while high - low > 1.0e-12:
        mid = 0.5 * (low + high)
        if abs(stability_function(a, -mid)) <= 1.0:
            low = mid
        else:
            high = mid
    return low


TABLEAUX = {t.name: t for t in (BOGACKI_SHAMPINE_32, DORMAND_PRINCE_54)}

# vector rows: stage state (q, v, a), residual scratch, then v and a of each stage
Q_STAGE, V_STAGE, A_STAGE, RESIDUAL = range(4)
VECTOR_ROWS = 4
S_TOL, S_ALPHA, S_DTMIN, S_DTMAX, S_ADAPTIVE, S_EXPONENT, S_RADIUS, S_CAP = range(8)
N_SCALARS = 8
EPS = 100.0 * np.finfo(np.float64).eps
HUGE = np.finfo(np.float64).max


def prepare_with(tableau: Tableau, system, dt, options):
    """(memory, adaptive); the step's bounds default to 1e-10/1e10 times dt."""
    n = system.n_modes
    s = tableau.stages
    dt_min = options.dt_min if options.dt_min is not None else 1.0e-10 * dt
    dt_max = options.dt_max if options.dt_max is not None else 1.0e10 * dt
    adaptive = abs(dt_max / dt_min - 1.0) >= EPS
    scalars = np.zeros(N_SCALARS)
    scalars[S_TOL], scalars[S_ALPHA] = options.tolerance, options.alpha
    scalars[S_DTMIN], scalars[S_DTMAX] = dt_min, dt_max
    scalars[S_ADAPTIVE] = 1.0 if adaptive else 0.0
    scalars[S_EXPONENT] = tableau.exponent
    scalars[S_RADIUS] = tableau.radius
    scalars[S_CAP] = -1.0  # the damping cap, computed from the model at the first step
    rows = np.zeros((VECTOR_ROWS + 2 * s, n))
    return (rows, scalars, tableau.table()), adaptive


@njit(cache=True, inline="always")
def attempt(t, dt, state, memory, model, s):
    """One trial step of length dt from (q, v, a): stage values in rows,
    the solution in the stage rows. Returns a diverging shock or -1."""
    q, v, a, f, vint, vint_save, work = state
    rows, table = memory[ROWS], memory[TABLE]
    n = q.shape[0]
    qs, vs, acc = rows[Q_STAGE], rows[V_STAGE], rows[A_STAGE]
    copy_vector(vs, v)
    copy_vector(acc, a)
    for stage in range(s):
        copy_vector(rows[VECTOR_ROWS + stage], vs)
        copy_vector(rows[VECTOR_ROWS + s + stage], acc)
        for i in range(n):
            dq = 0.0
            dv = 0.0
            for k in range(stage + 1):
                dq += table[stage, k] * rows[VECTOR_ROWS + k, i]
                dv += table[stage, k] * rows[VECTOR_ROWS + s + k, i]
            qs[i] = q[i] + dt * dq
            vs[i] = v[i] + dt * dv
        t_stage = t + dt * table[s, stage + 1]
        shock = evaluate(t_stage, qs, vs, acc, f, rows[RESIDUAL], vint, work, model)
        if shock >= 0:
            return shock
    return -1


@njit(cache=True, inline="always")
def scaled_error(dt, q, v, memory, s):
    rows, scalars, table = memory
    tol, alpha = scalars[S_TOL], scalars[S_ALPHA]
    qs, vs, acc = rows[Q_STAGE], rows[V_STAGE], rows[A_STAGE]
    n = q.shape[0]
    err_q = 0.0
    err_v = 0.0
    for i in range(n):
        eq = table[s + 1, s] * vs[i]
        ev = table[s + 1, s] * acc[i]
        for k in range(s):
            eq += table[s + 1, k] * rows[VECTOR_ROWS + k, i]
            ev += table[s + 1, k] * rows[VECTOR_ROWS + s + k, i]
        dq = abs(qs[i] - q[i])
        dv = abs(vs[i] - v[i])
        scale_q = max(tol * abs(q[i] + alpha), tol * (dq + alpha), EPS)
        scale_v = max(tol * abs(v[i] + alpha), tol * (dv + alpha), EPS)
        err_q += (eq / scale_q) ** 2
        err_v += (ev / scale_v) ** 2
    return max(dt * np.sqrt((err_q + err_v) / (2 * n)), EPS)


@njit(cache=True, _nrt=False)
def step(t, dt, index, state, memory, model):
    """One step, compiled once without reference counting (nothing in it
    allocates): the scheme's loop (:func:`loop.scheme_loop`) and the loops shared by every scheme
    (rotation, implicit shocks) call this same machine code."""
    q, v, a, f, vint, vint_save, work = state
    rows, scalars, table = memory
    s = table.shape[0] - 2
    adaptive = scalars[S_ADAPTIVE] == 1.0
    p = scalars[S_EXPONENT]
    if scalars[S_CAP] < 0.0:
        scalars[S_CAP] = shock_damping_step(model[LINEAR], model[SHOCKS], True, scalars[S_RADIUS])
    dt_max = min(scalars[S_DTMAX], scalars[S_CAP])
    if adaptive and dt > dt_max:
        dt = dt_max
    low, high = (0.9 / 5.0) ** p, (0.9 / 0.2) ** p
    if adaptive:  # a rejected trial restores the shock states it changed
        copy_into(vint_save, vint)
    previous_error = HUGE
    rejected = 0
    dt_next = dt
    while True:
        shock = attempt(t, dt, state, memory, model, s)
        if shock >= 0:
            return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, rejected
        if not (all_finite(rows[Q_STAGE]) and all_finite(rows[V_STAGE])):
            K.expose_trial(q, v, a, rows[Q_STAGE], rows[V_STAGE], rows[A_STAGE])
            return K.STATUS_NOT_FINITE, -1, dt, dt, rejected
        if not adaptive:
            break
        err = scaled_error(dt, q, v, memory, s)
        if err * 1.01 > previous_error:
            err = 0.99  # refining does not help: proceed as is
        if err < low:
            factor = 5.0
        elif err > high:
            factor = 0.2
        else:
            factor = 0.9 * err ** (-1.0 / p)
        dt_next = min(dt_max, dt * factor)
        if err >= 1.0 and dt_next >= scalars[S_DTMIN]:
            dt = dt_next
            previous_error = err
            rejected += 1
            copy_into(vint, vint_save)
            continue
        if dt_next < scalars[S_DTMIN]:
            return K.STATUS_STEP_UNDERFLOW, -1, dt, dt, rejected
        break
    copy_vector(q, rows[Q_STAGE])
    copy_vector(v, rows[V_STAGE])
    copy_vector(a, rows[A_STAGE])
    return K.STATUS_DONE, -1, dt, dt_next, rejected
