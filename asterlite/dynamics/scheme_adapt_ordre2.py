"""ADAPT_ORDRE2: leapfrog (velocity at mid-steps) with the
apparent-frequency step control of ``adapt_control`` (code_aster's
intadapt2):

    v_{n+1/2} = v_{n-1/2} + a_n p      p = (dt_proposed + dt)/2, dt/2 on the first step
    q_{n+1}   = q_n + v_{n+1/2} dt
    v_{n+1}   = v_{n+1/2} + a_n dt/2   (the velocity archived and seen by the shocks)
    a_{n+1}   = acceleration at t_{n+1} of (q_{n+1}, v_{n+1})

The mid-step velocity is carried in the scheme's memory; the state
velocity is v_{n+1}. With a constant step this is central differences.
"""

from __future__ import annotations

import numpy as np

from asterlite.dynamics import adapt_control as A
from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import all_finite, copy_into
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import ROWS, SCALARS
from asterlite.dynamics.local_frame import copy_vector, evaluate

Q_TRIAL, V_TRIAL, A_TRIAL, V_MIN, V_MID, V_MID_TRIAL, RESIDUAL = range(7)
VECTOR_ROWS = 7


def prepare(system, dt, options):
    scalars, adaptive = A.control_scalars(dt, options)
    rows = np.zeros((VECTOR_ROWS, system.n_modes))
    rows[V_MIN] = 1.0e-15
    return (rows, scalars, np.zeros((1, 1))), adaptive


@njit(cache=True, _nrt=False)
def step(t, dt, index, state, memory, model):
    """One step, compiled once without reference counting (nothing in it
    allocates): the scheme's loop (:func:`loop.scheme_loop`) and the loops shared by every scheme
    (rotation, implicit shocks) call this same machine code."""
    q, v, a, f, vint, vint_save, work = state
    rows, scalars = memory[ROWS], memory[SCALARS]
    n = q.shape[0]
    q2, v2, a2, vmin = rows[Q_TRIAL], rows[V_TRIAL], rows[A_TRIAL], rows[V_MIN]
    v_mid, v_mid_trial = rows[V_MID], rows[V_MID_TRIAL]
    adaptive = scalars[A.S_ADAPTIVE] == 1.0
    max_trials = int(round(scalars[A.S_MAX_TRIALS]))
    if scalars[A.S_FIRST_CALL] == 1.0:
        scalars[A.S_FIRST_CALL] = 0.0
        copy_vector(v_mid, v)
        dt_proposed = 0.0
    else:
        dt_proposed = dt
    if adaptive:  # a rejected trial restores the shock states it changed
        copy_into(vint_save, vint)
    dt_trial = dt
    dt_next = dt
    trials = 1
    while True:
        p = 0.5 * (dt_proposed + dt_trial)
        half = 0.5 * dt_trial
        for i in range(n):
            v_mid_trial[i] = v_mid[i] + a[i] * p
            q2[i] = q[i] + v_mid_trial[i] * dt_trial
            v2[i] = v_mid_trial[i] + half * a[i]
        shock = evaluate(t + dt_trial, q2, v2, a2, f, rows[RESIDUAL], vint, work, model)
        if shock >= 0:
            return K.STATUS_SHOCK_DIVERGED, shock, dt_trial, dt_trial, trials - 1
        if not all_finite(a2):
            K.expose_trial(q, v, a, q2, v2, a2)
            return K.STATUS_NOT_FINITE, -1, dt_trial, dt_trial, trials - 1
        if not adaptive:
            break
        err = A.frequency_error(dt_trial, q, q2, a, a2, vmin, scalars)
        factor = A.step_factor(err, scalars)
        dt_next = min(scalars[A.S_DTMAX], dt_trial * factor)
        if err >= 1.0 and dt_next >= scalars[A.S_DTMIN] and trials < max_trials:
            dt_trial = dt_next
            trials += 1
            copy_into(vint, vint_save)
            continue
        if dt_next < scalars[A.S_DTMIN]:
            return K.STATUS_STEP_UNDERFLOW, -1, dt_trial, dt_trial, trials - 1
        if trials == max_trials:
            scalars[A.S_KEPT_AT_MAX_TRIALS] += 1.0
        A.update_reference_velocities(v_mid_trial, vmin, scalars)
        break
    copy_vector(q, q2)
    copy_vector(v, v2)
    copy_vector(a, a2)
    copy_vector(v_mid, v_mid_trial)
    return K.STATUS_DONE, -1, dt_trial, dt_next, trials - 1
