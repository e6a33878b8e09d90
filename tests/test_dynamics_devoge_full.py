"""DEVOGE on a system with full (non-proportional) damping: the implicit
operators H0, H1, H2 are LU-factored in place (the step allocates nothing),
and the motion converges to the exact one, at third order or better
(measured: 4.4 from dt = 4e-3 to 2e-3, 3.2 from 2e-3 to 1e-3)."""

from __future__ import annotations

import math

import numpy as np
from scipy.linalg import expm

from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, build_shocks
from tests.validated import scheme_options

MASS = np.diag([1.0, 2.0])
STIFFNESS = np.array([[100.0, -20.0], [-20.0, 1800.0]])
DAMPING = np.array([[0.8, -0.5], [-0.5, 3.0]])  # not a combination of M and K
Q0, V0 = np.array([0.01, -0.002]), np.array([0.0, 0.3])
T_END = 0.6


def exact_state(times):
    """(q, v) from the first-order system's exponential."""
    n = MASS.shape[0]
    minv = np.linalg.inv(MASS)
    first_order = np.block([[np.zeros((n, n)), np.eye(n)], [-minv @ STIFFNESS, -minv @ DAMPING]])
    start = np.concatenate([Q0, V0])
    states = np.array([expm(first_order * t) @ start for t in times])
    return states[:, :n], states[:, n:]


def devoge_error(dt):
    system = LinearSystem(MASS, STIFFNESS, DAMPING)
    assert not system.diagonal
    shocks = build_shocks([], system)
    excitation = tabulate_excitation(system.n_modes, [], 0.0, T_END, dt / 2.0)
    result = integrate(
        system, shocks, excitation, "DEVOGE", Q0, V0, 0.0, T_END, dt, np.array([T_END]), 1,
        scheme_options("DEVOGE", dt_min=dt, dt_max=dt),
    )  # fmt: skip
    q, v = exact_state(result.times)
    return max(
        np.abs(result.depl - q).max() / np.abs(q).max(),
        np.abs(result.vite - v).max() / np.abs(v).max(),
    )


def test_full_damping_converges_to_the_exact_motion():
    errors = [devoge_error(dt) for dt in (4.0e-3, 2.0e-3, 1.0e-3)]
    assert errors[-1] < 1.0e-7
    for coarse, fine in zip(errors[:-1], errors[1:], strict=True):
        assert math.log2(coarse / fine) > 2.8
