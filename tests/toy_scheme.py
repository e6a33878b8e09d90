"""A toy GENE scheme added through the documented places only
(docs/architecture.md, "Adding a scheme"): this module (``prepare``,
``step``: the engine's one time loop runs the step) and its description
registered in
:mod:`asterlite.dynamics.schemes`. Importing it makes SCHEMA='TOY_EULER'
available to a deck run in the same process.

The scheme is the position-first symplectic Euler (q_{n+1} = q_n + dt v_n,
a_{n+1} = a(t + dt, q_{n+1}, v_n), v_{n+1} = v_n + dt a_{n+1}): on an
undamped oscillator its map is [[1, dt], [-ω² dt, 1 - ω² dt²]], which
tests/test_dynamics_toy_scheme.py checks the run against.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from asterlite.dynamics import kernel as K
from asterlite.dynamics.forces import all_finite, state_acceleration
from asterlite.dynamics.schemes import SCHEMES, Scheme, register

NAME = "TOY_EULER"


def prepare(system, dt, options):
    """(memory, adaptive): a residual scratch row, fixed step."""
    return (np.zeros((1, system.n_modes)), np.zeros(1), np.zeros((1, 1))), False


@njit(cache=True)
def step(t, dt, index, state, memory, model):
    q, v, a, f, vint, vint_save, work = state
    for i in range(q.shape[0]):
        q[i] += dt * v[i]
    shock = state_acceleration(t + dt, q, v, a, f, memory[0][0], vint, work, model)
    if shock >= 0:
        return K.STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    for i in range(q.shape[0]):
        v[i] += dt * a[i]
    if not (all_finite(a) and all_finite(v)):
        return K.STATUS_NOT_FINITE, -1, dt, dt, 0
    return K.STATUS_DONE, -1, dt, dt, 0


if NAME not in SCHEMES:
    register(
        Scheme(
            NAME,
            __name__,
            NAME,
            code=-1,  # no branch in the loops shared by every scheme
            step_checked=False,
            loops="own",  # one loop, no local-frame variant
            shared_loops=False,
        )
    )
