"""DIFF_CENTRE: explicit central differences in code_aster's form
(v_{n+1} = v_n + dt a_n, q_{n+1} = q_n + dt v_{n+1}, then a_{n+1} from the
equations of motion at the new state). Order 2, conditionally stable."""

from __future__ import annotations

from numba import njit

from asterlite.dynamics.forces import acceleration, all_finite, total_force
from asterlite.dynamics.kernel import STATUS_DONE, STATUS_NOT_FINITE, STATUS_SHOCK_DIVERGED

MEMORY_ROWS = 1  # residual scratch
MEMORY_SCALARS = 1


@njit(cache=True)
def step(t, dt, q, v, a, f, mem, smem, vint, vint_save, lin, shk, exc, work):
    for i in range(q.shape[0]):
        v[i] += dt * a[i]
        q[i] += dt * v[i]
    shock = total_force(t + dt, q, v, shk, vint, exc, work, f)
    if shock >= 0:
        return STATUS_SHOCK_DIVERGED, shock, dt, dt, 0
    acceleration(f, q, v, lin, mem[0], a)
    if not all_finite(a):
        return STATUS_NOT_FINITE, -1, dt, dt, 0
    return STATUS_DONE, -1, dt, dt, 0
