"""DIS_VISC: generalized Zener viscous element between two nodes (axial).

Acts along the local x axis node 1 -> node 2. Over a time step the
relative axial velocity is held constant; the total deformation rate of
the element is ε̇ = -(v1 - v2)·x (elongation rate) and the Zener rates of
``zener`` are integrated by ``rk54`` (local sub-steps, the local
integration's tolerance and iteration bound). The force σ (> 0 in tension) acts on node 1 along +x
(towards node 2) and on node 2 along -x.

Internal variables (code_aster's 11-value layout, VINT1..VINT11): local
coordinates of both nodes, the relative axial velocity, then σ, εv, ε and
the dissipated energy (VINT8..VINT11).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.jit import njit
from asterlite.dynamics.laws import rk54
from asterlite.dynamics.laws.tabulated import LawError
from asterlite.dynamics.laws.zener import M_ALPHA, M_C, M_K2, M_S1, M_S3
from asterlite.errors import field as named

SERIES, BRANCH = named("series_flexibility"), named("branch_flexibility")

# Parameters: the Zener model (s1, k2, s3, c, alpha) then the local integration controls
P_MODEL = 0
P_ITER_MAX, P_RESI = 5, 6
N_PARAMS = 7

# Internal variables
V_LOC1, V_LOC2 = 0, 3
V_VREL = 6  # relative axial velocity (v1 - v2)·x
V_FORCE = 7
V_EPS_VISC = 8
V_EPS = 9
V_DISSIP = 10
N_VINT = 11
VINT_NAMES = (
    "DXLOC_1", "DYLOC_1", "DZLOC_1", "DXLOC_2", "DYLOC_2", "DZLOC_2",
    "V_REL", "FORCE", "EPS_VISQ", "EPSI", "DISSIP",
)  # fmt: skip
N_WORK = rk54.N_WORK  # work array: (N_WORK, 4) floats
N_Y = 4


@njit(cache=True)
def zener_force(params, relative_axial_velocity, dt, state_in, state_out, rate, work):
    """Force σ on node 1 along +x at the end of the step of length ``dt``
    (dt = 0: the state is only copied). ``rate``: scratch of 3 floats,
    ``work``: scratch (N_WORK, 4). Returns (σ, converged)."""
    rate[0] = -relative_axial_velocity
    rate[1] = 0.0
    rate[2] = 0.0
    converged = rk54.adaptive_integrate(
        rk54.ZENER,
        params[P_MODEL : P_MODEL + 5],
        state_in[V_FORCE : V_FORCE + N_Y],
        rate,
        dt,
        int(params[P_ITER_MAX]),
        params[P_RESI],
        params[0:0],
        state_out[V_FORCE : V_FORCE + N_Y],
        work,
    )
    state_out[V_VREL] = relative_axial_velocity
    return state_out[V_FORCE], converged


@dataclass(frozen=True)
class DisViscParameters:
    """The Zener element's data: the flexibilities of the spring in series
    (1/k1) and of the viscous branch's spring (1/k3), 0 for a rigid one,
    the stiffness parallel to the dashpot (k2), the dashpot's coefficient c
    and exponent α (σ = C ε̇^α), and the local integration's controls."""

    series_flexibility: float
    parallel_stiffness: float
    branch_flexibility: float
    viscosity: float
    exponent: float
    max_iterations: int
    tolerance: float


def prepare_dis_visc(data: DisViscParameters) -> np.ndarray:
    """Parameter array of the element, after code_aster's checks."""
    p = np.zeros(N_PARAMS)
    p[P_MODEL + M_S1] = float(data.series_flexibility)
    p[P_MODEL + M_S3] = float(data.branch_flexibility)
    p[P_MODEL + M_K2] = float(data.parallel_stiffness)
    if p[P_MODEL + M_S1] < 0.0 or p[P_MODEL + M_S3] < 0.0:
        raise LawError(f"DIS_VISC: the flexibilities {SERIES} and {BRANCH} must be >= 0")
    if p[P_MODEL + M_K2] < 0.0:
        raise LawError(f"DIS_VISC: {named('parallel_stiffness')} must be >= 0")
    s1, k2, s3 = p[P_MODEL + M_S1], p[P_MODEL + M_K2], p[P_MODEL + M_S3]
    if s1 + s3 + k2 * s1 * s3 <= 0.0:
        raise LawError(f"DIS_VISC: {SERIES} and {BRANCH} cannot both be zero (rigid element)")
    p[P_MODEL + M_C] = float(data.viscosity)
    p[P_MODEL + M_ALPHA] = float(data.exponent)
    if p[P_MODEL + M_C] <= 0.0:
        raise LawError(f"DIS_VISC: {named('viscosity')} must be > 0")
    if not 0.0 < p[P_MODEL + M_ALPHA] <= 1.0:
        raise LawError(f"DIS_VISC: {named('exponent')} must be in ]0, 1]")
    p[P_ITER_MAX] = int(data.max_iterations)
    p[P_RESI] = float(data.tolerance)
    if p[P_ITER_MAX] < 1 or p[P_RESI] <= 0.0:
        raise LawError(
            f"DIS_VISC: {named('max_iterations')} must be >= 1 and {named('tolerance')} > 0"
        )
    return p


def relaxation(params, strain, t):
    """Closed-form force under a strain step held from t = 0, for a linear
    dashpot (exponent 1), starting from the instantaneous elastic
    response (dashpot locked). Returns σ(t) (array)."""
    s1, k2, s3, c, alpha = params[P_MODEL : P_MODEL + 5]
    if alpha != 1.0:
        raise ValueError("closed form only for a linear dashpot (exponent 1)")
    k3 = np.inf if s3 == 0.0 else 1.0 / s3
    instant = strain / (s1 + 1.0 / (k2 + k3)) if np.isfinite(k3) else strain / s1
    relaxed = k2 * strain / (1.0 + k2 * s1)
    rate = (1.0 + k2 * s1) / (c * (s1 + s3 + k2 * s1 * s3))
    return relaxed + (instant - relaxed) * np.exp(-rate * np.asarray(t, float))
