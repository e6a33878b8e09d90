"""DIFF_CENTRE: explicit central differences in code_aster's form
(v_{n+1} = v_n + dt a_n, q_{n+1} = q_n + dt v_{n+1}, then a_{n+1} from the
equations of motion at the new state). Order 2, conditionally stable."""

from __future__ import annotations

import numpy as np
from numba import njit

from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import all_finite, state_acceleration

RESIDUAL = 0  # memory row: residual scratch


def prepare(system, dt, options):
    """(memory, adaptive): one scratch row, no parameters."""
    n = system.n_modes
    return (np.zeros((1, n)), np.zeros(1), np.zeros((1, 1))), False


@njit(cache=True)
def step(t, dt, index, state, memory, model):
    q, v, a, f, vint, vint_save, work = state
    rows = memory[0]
    for i in range(q.shape[0]):
        v[i] += dt * a[i]
        q[i] += dt * v[i]
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
        t, dt = K.plan_step(clock, counters, instants, eps)
        status, shock, dt_used, dt_next, rejected = step(
            t, dt, counters[K.K_STEP], state, memory, model
        )
        if status != K.STATUS_DONE:
            return K.record_failure(clock, counters, status, shock, dt)
        result = (dt_used, dt_next, rejected)
        K.complete_step(clock, counters, state, instants, pas_arch, eps, archive, result)
    return K.STATUS_DONE
