"""ADAPT_ORDRE1: symplectic Euler (v_{n+1} = v_n + a_n p, q_{n+1} = q_n +
v_{n+1} dt with p = (dt_proposed + dt)/2, p = dt below 1e-13) with the
apparent-frequency step control of ``adapt_control`` (code_aster's
intadapt1; the error is ignored on the first five steps)."""

from __future__ import annotations

import numpy as np

from asterlite.dynamics import adapt_control as A
from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import all_finite, copy_into
from asterlite.dynamics.jit import njit
from asterlite.dynamics.layouts import ROWS, SCALARS
from asterlite.dynamics.local_frame import copy_vector, evaluate

Q_TRIAL, V_TRIAL, A_TRIAL, V_MIN, RESIDUAL = range(5)
VECTOR_ROWS = 5


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
    adaptive = scalars[A.S_ADAPTIVE] == 1.0
    max_trials = int(round(scalars[A.S_MAX_TRIALS]))
    if adaptive:  # a rejected trial restores the shock states it changed
        copy_into(vint_save, vint)
    dt_proposed = dt
    dt_trial = dt
    dt_next = dt
    trials = 1
    while True:
        p = 0.5 * (dt_proposed + dt_trial)
        if dt_trial <= 1.0e-13:
            p = dt_trial
        for i in range(n):
            v2[i] = v[i] + a[i] * p
            q2[i] = q[i] + v2[i] * dt_trial
        shock = evaluate(t + dt_trial, q2, v2, a2, f, rows[RESIDUAL], vint, work, model)
        if shock >= 0:
            return K.STATUS_SHOCK_DIVERGED, shock, dt_trial, dt_trial, trials - 1
        if not all_finite(a2):
            K.expose_trial(q, v, a, q2, v2, a2)
            return K.STATUS_NOT_FINITE, -1, dt_trial, dt_trial, trials - 1
        if not adaptive:
            break
        err = A.frequency_error(dt_trial, q, q2, a, a2, vmin, scalars)
        if index < 5:
            err = 0.0
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
        A.update_reference_velocities(v2, vmin, scalars)
        break
    copy_vector(q, q2)
    copy_vector(v, v2)
    copy_vector(a, a2)
    return K.STATUS_DONE, -1, dt_trial, dt_next, trials - 1
