"""DIS_VISC: generalized Zener viscous element between two nodes (axial).

Acts along the local x axis node 1 -> node 2. Over a time step the
relative axial velocity is held constant; the total deformation rate of
the element is ε̇ = -(v1 - v2)·x (elongation rate) and the Zener rates of
``zener`` are integrated by ``rk54`` (local sub-steps, RESI_INTE,
ITER_INTE_MAXI). The force σ (> 0 in tension) acts on node 1 along +x
(towards node 2) and on node 2 along -x.

Internal variables (code_aster's 11-value layout, VINT1..VINT11): local
coordinates of both nodes, the relative axial velocity, then σ, εv, ε and
the dissipated energy (VINT8..VINT11).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from asterlite.dynamics.laws import rk54
from asterlite.dynamics.laws.tabulated import LawError
from asterlite.dynamics.laws.zener import M_ALPHA, M_C, M_K2, M_S1, M_S3

# Parameters: the Zener model (s1, K2, s3, C, alpha) then the local integration controls
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


def flexibility(kw, stiffness_key: str, flexibility_key: str) -> float:
    if kw.get(stiffness_key) is not None:
        k = float(kw[stiffness_key])
        if k <= 0.0:
            raise LawError(f"DIS_VISC: {stiffness_key} must be > 0")
        return 1.0 / k
    if kw.get(flexibility_key) is not None:
        s = float(kw[flexibility_key])
        if s < 0.0:
            raise LawError(f"DIS_VISC: {flexibility_key} must be >= 0")
        return s
    raise LawError(f"DIS_VISC: give {stiffness_key} or {flexibility_key}")


def prepare_dis_visc(kw) -> np.ndarray:
    """Parameter array from a validated DIS_VISC occurrence (defaults filled)."""
    p = np.zeros(N_PARAMS)
    p[P_MODEL + M_S1] = flexibility(kw, "K1", "UNSUR_K1")
    p[P_MODEL + M_S3] = flexibility(kw, "K3", "UNSUR_K3")
    if kw.get("K2") is not None:
        p[P_MODEL + M_K2] = float(kw["K2"])
    elif kw.get("UNSUR_K2") is not None:
        if float(kw["UNSUR_K2"]) <= 0.0:
            raise LawError("DIS_VISC: UNSUR_K2 must be > 0")
        p[P_MODEL + M_K2] = 1.0 / float(kw["UNSUR_K2"])
    else:
        raise LawError("DIS_VISC: give K2 or UNSUR_K2")
    if p[P_MODEL + M_K2] < 0.0:
        raise LawError("DIS_VISC: K2 must be >= 0")
    s1, k2, s3 = p[P_MODEL + M_S1], p[P_MODEL + M_K2], p[P_MODEL + M_S3]
    if s1 + s3 + k2 * s1 * s3 <= 0.0:
        raise LawError("DIS_VISC: UNSUR_K1 and UNSUR_K3 cannot both be zero (rigid element)")
    p[P_MODEL + M_C] = float(kw["C"])
    p[P_MODEL + M_ALPHA] = float(kw.get("PUIS_ALPHA", 0.5))
    if p[P_MODEL + M_C] <= 0.0:
        raise LawError("DIS_VISC: C must be > 0")
    if not 0.0 < p[P_MODEL + M_ALPHA] <= 1.0:
        raise LawError("DIS_VISC: PUIS_ALPHA must be in ]0, 1]")
    p[P_ITER_MAX] = int(kw.get("ITER_INTE_MAXI", 20))
    p[P_RESI] = float(kw.get("RESI_INTE", 1.0e-6))
    if p[P_ITER_MAX] < 1 or p[P_RESI] <= 0.0:
        raise LawError("DIS_VISC: ITER_INTE_MAXI must be >= 1 and RESI_INTE > 0")
    return p


def relaxation(params, strain, t):
    """Closed-form force under a strain step held from t = 0, for a linear
    dashpot (PUIS_ALPHA = 1), starting from the instantaneous elastic
    response (dashpot locked). Returns σ(t) (array)."""
    s1, k2, s3, c, alpha = params[P_MODEL : P_MODEL + 5]
    if alpha != 1.0:
        raise ValueError("closed form only for PUIS_ALPHA = 1")
    k3 = np.inf if s3 == 0.0 else 1.0 / s3
    instant = strain / (s1 + 1.0 / (k2 + k3)) if np.isfinite(k3) else strain / s1
    relaxed = k2 * strain / (1.0 + k2 * s1)
    rate = (1.0 + k2 * s1) / (c * (s1 + s3 + k2 * s1 * s3))
    return relaxed + (instant - relaxed) * np.exp(-rate * np.asarray(t, float))
