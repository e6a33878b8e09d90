"""DIFF_CENTRE on the physical system (code_aster's dldiff / dldif0):
explicit central differences with a diagonal (lumped) mass.

    v_{n+1/2} = v_{n-1/2} + dt a_n          (v_{-1/2} = v_0 - dt/2 a_0)
    q_{n+1}   = q_n + dt v_{n+1/2}
    a_{n+1}   = M⁻¹ (F_{n+1} - K q_{n+1} - C v_{n+1/2})
    v_{n+1}   = v_{n+1/2} + dt/2 a_{n+1}    (the archived velocity)

DOFs without mass keep their initial value, as code_aster's extraction of
the diagonal does for blocked DOFs.
"""

from __future__ import annotations

import numpy as np

from asterlite.dynamics.physical.stepping import fixed_step_loop


def stability_limit(system, inverse_mass) -> float:
    """code_aster's check: dt <= 0.05 · 2π / sqrt(k_ii / m_ii) over the DOFs."""
    k = system.reduced_stiffness().diagonal()
    omega2 = k * inverse_mass
    omega2 = omega2[(inverse_mass != 0.0) & (omega2 > 0.0)]
    if omega2.size == 0:
        return np.inf
    return 0.05 * 2.0 * np.pi / np.sqrt(omega2.max())


def integrate(system, times, q, v, a, mask, archive, inverse_mass, monitor=None):
    half = {"v": None}

    def step(dt, force, q, v, a):
        if half["v"] is None:
            half["v"] = v - 0.5 * dt * a
        v_half = half["v"] + dt * a
        q_new = q + dt * v_half
        rhs = force - system.reduced_stiffness() @ q_new
        if system.damping is not None:
            rhs -= system.damping @ v_half
        a_new = inverse_mass * rhs
        half["v"] = v_half
        return q_new, v_half + 0.5 * dt * a_new, a_new

    fixed_step_loop(system, times, q, v, a, mask, archive, step, monitor)
    return half["v"]  # v_{N-1/2}: what code_aster archives last for an excluded velocity field
