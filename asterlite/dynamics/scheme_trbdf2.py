"""TRBDF2: a trapezoidal stage to t + γ dt followed by a second-order
backward-difference stage to t + dt, γ = 2 - √2, implicit on the linear
part with code_aster's formulation (inttrbdf2).

Both stages share the effective stiffness K_eff = a1 M + a2 C + K with
h = γ dt, a1 = 4/h², a2 = 2/h (for this γ the BDF2 coefficient g3 dt
equals h/2), F1 = a2 M, F2 = a1 M + a2 C. With g1 = 1/(γ(2-γ)),
g2 = -(1-γ)²/(γ(2-γ)), g3 = (1-γ)/(2-γ):

    TR:   ã  = acceleration at t + h of the state held at index 2
          K_eff Δ = h (F2 v_n + F1 (a_n + ã)/2)
          ã' = acceleration at t + dt of the same (unchanged) state
          q_γ = q_n + Δ,  v_γ = 2 Δ/h - v_n
    BDF2: r_q = q_n - g1 q_γ - g2 q_n - g3 dt v_n
          r_v = v_n - g1 v_γ - g2 v_n - g3 dt ã'
          K_eff Δ = -(F1 r_v + F2 r_q)
          q_{n+1} = q_n + Δ,  v_{n+1} = v_n + (Δ + r_q)/(g3 dt)
          a_{n+1} = acceleration at t + dt of (q_{n+1}, v_{n+1})

The accelerations of the state held at index 2 carry the shock forces
explicitly: that state is the previous step's result (q_n, v_n), and zero
on the very first step as in code_aster. L-stable on the linear part.

Order. From the second step on, each step is exactly the TR-BDF2 step of
the linear system, modal damping included (substituting ã = M⁻¹(F - K q_n
- C v_n) makes the TR stage the trapezoidal rule on (q, v) and the BDF2
stage the BDF2 rule, C v taken at the stage's own velocity): order 2 with
or without damping. The first step is not: code_aster allocates
displacement/velocity/acceleration at index 2 on the first call of inttrbdf2 (intinivec fills
them with zeros), and both dtmacce(index 2) calls of that step evaluate
the accelerations at q = 0, v = 0 instead of (q_0, v_0). Asterlite keeps
that parity (rows Q_INDEX2/V_INDEX2 start at zero). With e = M⁻¹(K q_0 +
C v_0 - F_shock(q_0, v_0) + F_shock(0, 0)), the first step ends with

    q_1 += (1 - √2/2) dt² e,    v_1 += (1 - √2/4) dt e

(to leading order), an O(dt) velocity jump carried by the rest of the run:
the trajectory converges at order 1 whenever e ≠ 0, at order 2 when the
run starts from rest or from a state with K q_0 + C v_0 = 0. Damping is
not the cause in itself: an undamped start from q_0 ≠ 0 loses the order
the same way (the 1.2e-4 -> 3.0e-5 for dt/4 measured on a damped
oscillator launched with v_0 ≠ 0 is this first step, C v_0 ≠ 0); a
damped, forced oscillator starting from rest converges at order 2.
Seeding index 2 with (q_0, v_0) would restore order 2 from any state;
it would also change the first step's shock forces and internal
variables, so asterlite stays with code_aster
(tests/test_dynamics_schemes.py measures both behaviours).
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.dynamics import implicit as I
from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import all_finite
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import ROWS, SCALARS
from asterlite.dynamics.local_frame import copy_vector, evaluate

Q_INDEX2, V_INDEX2, A_INDEX2, DELTA_ROW, R_Q, R_V, RESIDUAL, PIVOTS = range(8)
VECTOR_ROWS = 8
S_DT_BUILT, S_DIAGONAL, S_A1, S_A2 = range(4)
N_SCALARS = 4
STAGE_FRACTION = 2.0 - math.sqrt(2.0)  # TR-BDF2's γ: the trapezoidal stage ends at t + γ dt
G1 = 1.0 / STAGE_FRACTION / (2.0 - STAGE_FRACTION)
G2 = -((1.0 - STAGE_FRACTION) ** 2) / STAGE_FRACTION / (2.0 - STAGE_FRACTION)
G3 = (1.0 - STAGE_FRACTION) / (2.0 - STAGE_FRACTION)
EPS = np.finfo(np.float64).eps


def prepare(system, dt, options):
    rows = I.new_rows(VECTOR_ROWS, system, blocks=6)
    scalars = np.zeros(N_SCALARS)
    scalars[S_DT_BUILT] = -1.0
    scalars[S_DIAGONAL] = 1.0 if system.diagonal else 0.0
    return (rows, scalars, np.zeros((1, 1))), False


@njit(cache=True)
def build_operators(rows, scalars, dt, n):
    h = STAGE_FRACTION * dt
    a1, a2 = 4.0 / (h * h), 2.0 / h
    scalars[S_A1], scalars[S_A2] = a1, a2
    mass = I.block(rows, VECTOR_ROWS, I.B_MASS, n)
    stiffness = I.block(rows, VECTOR_ROWS, I.B_STIFF, n)
    damping = I.block(rows, VECTOR_ROWS, I.B_DAMP, n)
    I.combine(I.block(rows, VECTOR_ROWS, I.B_KEFF, n), mass, stiffness, damping, a1, 1.0, a2)
    I.combine(I.block(rows, VECTOR_ROWS, I.B_F1, n), mass, stiffness, damping, a2, 0.0, 0.0)
    I.combine(I.block(rows, VECTOR_ROWS, I.B_F2, n), mass, stiffness, damping, a1, 0.0, a2)
    scalars[S_DT_BUILT] = dt
    diagonal = scalars[S_DIAGONAL] == 1.0
    return I.factor_effective(I.block(rows, VECTOR_ROWS, I.B_KEFF, n), rows[PIVOTS], diagonal)


@njit(cache=True, _nrt=False)
def step(t, dt, index, state, memory, model):
    """One step, compiled once without reference counting (nothing in it
    allocates): the scheme's loop (:func:`loop.scheme_loop`) and the loops shared by every scheme
    (rotation, implicit shocks) call this same machine code."""
    q, v, a, f, vint, vint_save, work = state
    rows, scalars = memory[ROWS], memory[SCALARS]
    n = q.shape[0]
    diagonal = scalars[S_DIAGONAL] == 1.0
    built = scalars[S_DT_BUILT]
    if built < 0.0 or abs(dt / built - 1.0) >= EPS:
        if not build_operators(rows, scalars, dt, n):
            return K.STATUS_NOT_FINITE, -1, dt, dt, 0
    keff = I.block(rows, VECTOR_ROWS, I.B_KEFF, n)
    f1 = I.block(rows, VECTOR_ROWS, I.B_F1, n)
    f2 = I.block(rows, VECTOR_ROWS, I.B_F2, n)
    q2, v2, a2 = rows[Q_INDEX2], rows[V_INDEX2], rows[A_INDEX2]
    delta, r_q, r_v, residual = rows[DELTA_ROW], rows[R_Q], rows[R_V], rows[RESIDUAL]
    h = STAGE_FRACTION * dt
    # --- trapezoidal stage to t + h
    shock = evaluate(t + h, q2, v2, a2, f, residual, vint, work, model)
    if shock >= 0:
        return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    for i in range(n):
        r_v[i] = 0.5 * (a[i] + a2[i])
    delta[:] = 0.0
    I.apply(f2, v, h, delta, diagonal)
    I.apply(f1, r_v, h, delta, diagonal)
    I.solve_effective(keff, rows[PIVOTS], delta, diagonal)
    shock = evaluate(t + dt, q2, v2, a2, f, residual, vint, work, model)
    if shock >= 0:
        return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    for i in range(n):
        q2[i] = q[i] + delta[i]
        v2[i] = v[i] + 2.0 * (delta[i] / h - v[i])
    # --- BDF2 stage to t + dt
    for i in range(n):
        r_q[i] = q[i] - G1 * q2[i] - G2 * q[i] - G3 * dt * v[i]
        r_v[i] = v[i] - G1 * v2[i] - G2 * v[i] - G3 * dt * a2[i]
    delta[:] = 0.0
    I.apply(f1, r_v, -1.0, delta, diagonal)
    I.apply(f2, r_q, -1.0, delta, diagonal)
    I.solve_effective(keff, rows[PIVOTS], delta, diagonal)
    for i in range(n):
        q2[i] = q[i] + delta[i]
        v2[i] = v[i] + (delta[i] + r_q[i]) / G3 / dt
    shock = evaluate(t + dt, q2, v2, a2, f, residual, vint, work, model)
    if shock >= 0:
        return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    copy_vector(q, q2)
    copy_vector(v, v2)
    copy_vector(a, a2)
    if not (all_finite(q) and all_finite(v) and all_finite(a)):
        return K.STATUS_NOT_FINITE, -1, dt, dt, 0
    return K.STATUS_DONE, -1, dt, dt, 0
