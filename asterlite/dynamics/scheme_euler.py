"""EULER: code_aster 10's explicit Euler scheme of order one (mdeul1, later
inteuler), kept as an asterlite extension for legacy decks whose
DYNA_TRAN_MODAL used METHODE='EULER' (the code_aster 10 default).

One step from t to t + dt, with a_n the acceleration of the state at t
(computed at the end of the previous step, or the initial acceleration)::

    v_{n+1} = v_n + dt a_n        (velocity first)
    q_{n+1} = q_n + dt v_{n+1}    (displacement with the new velocity)
    a_{n+1} = M^-1 (F_ext(t + dt) + F_shock(q_{n+1}, v_{n+1}) - K q_{n+1} - C v_{n+1})

that is the semi-implicit (symplectic) Euler form. Order 1 for the
displacement and the velocity at the step instants; conditionally stable
(code_aster 10's mdptem checked PAS against 1/20 of the shortest period,
shock stiffness included, as for DIFF_CENTRE).

code_aster 14 renamed this scheme: its DYNA_VIBRA/GENE 'DIFF_CENTRE' runs the
same routine (dtmprep maps it to _SCH_EULER), so EULER and DIFF_CENTRE give
the same arithmetic; this module is the plain path (one ``step`` per step on
the ``(lin, shk, exc)`` bundles) and handles every nonlinearity the general
path does.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import all_finite, loads_ready, state_acceleration

RESIDUAL = 0  # memory row: residual scratch


def prepare(system, dt, options):
    """(memory, adaptive): one scratch row, no parameters, fixed step."""
    n = system.n_modes
    return (np.zeros((1, n)), np.zeros(1), np.zeros((1, 1))), False


@njit(cache=True)
def step(t, dt, index, state, memory, model):
    q, v, a, f, vint, vint_save, work = state
    rows = memory[0]
    for i in range(q.shape[0]):
        v[i] = v[i] + dt * a[i]  # a: acceleration of the state at t
        q[i] = q[i] + dt * v[i]  # the updated velocity
    shock = state_acceleration(t + dt, q, v, a, f, rows[RESIDUAL], vint, work, model)
    if shock >= 0:
        return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    if not all_finite(a):
        return K.STATUS_NOT_FINITE, -1, dt, dt, 0
    return K.STATUS_DONE, -1, dt, dt, 0


@njit(cache=True)
def run_loop(clock, counters, state, memory, model, instants, pas_arch, eps, archive):
    while K.unfinished(clock, counters, eps):
        if K.archive_full(counters, archive):
            return K.STATUS_FULL
        if not loads_ready(clock, model[2]):
            return K.STATUS_LOADS
        t, dt = K.plan_step(clock, counters, instants, eps)
        status, shock, dt_used, dt_next, rejected = step(
            t, dt, counters[K.K_STEP], state, memory, model
        )
        if status != K.STATUS_DONE:
            return K.record_failure(clock, counters, status, shock, dt)
        result = (dt_used, dt_next, rejected)
        K.complete_step(clock, counters, state, instants, pas_arch, eps, archive, result)
    return K.STATUS_DONE
