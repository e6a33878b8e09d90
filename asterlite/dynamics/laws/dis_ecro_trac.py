"""DIS_ECRO_TRAC: discrete element with a hardening force–displacement curve.

Axial force = f(axial elongation): the law along the local x axis node 1 ->
node 2 (isotropic hardening). Tangential force = f(tangential displacement):
the same law in the plane (y, z) orthogonal to the axis, with isotropic or
linear kinematic hardening (linear kinematic with the first hardening
slope; the curve then has exactly 3 points).

The curve starts at (0, 0); its second point (dx0, fx0) is the elastic
limit; slopes must decrease (code_aster's checks, EXCLU prolongations).
Over each step the relative velocity is held constant and the rates of
``discrete_hardening`` are integrated by ``rk54``. The deformation rates
are u̇ = -(v1 - v2) on the driven components; the force F (positive in
tension) acts on node 1 along +x (or +y, +z) and on node 2 opposite.

Internal variables (code_aster's 20-value layout, VINT1..VINT20): local
coordinates of both nodes, then force (3), displacement (3), dissipated
energy, cumulated plastic displacement, plastic displacement (3), back
force (3).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.jit import njit
from asterlite.dynamics.laws import rk54
from asterlite.dynamics.laws.discrete_hardening import C_DX0, C_FX0, C_KINEMATIC, C_N, N_Y
from asterlite.dynamics.laws.tabulated import LawError
from asterlite.errors import field as named

# Parameters: law, controls, then the curve block read by discrete_hardening
P_AXIAL = 0  # 1.0: axial law, 0.0: transverse law
P_ITER_MAX, P_RESI = 1, 2
P_SCALES = 3  # error scales of the 14 unknowns (code_aster's choice)
P_CURVE = P_SCALES + N_Y  # curve block: kinematic flag, fx0, dx0, n, x..., y...

# Internal variables
V_LOC1, V_LOC2 = 0, 3
V_STATE = 6  # the 14 unknowns
V_FORCE = 6
V_DEPL = 9
V_DISSIP = 12
V_PCUM = 13
V_DEPL_PLAS = 14
V_BACK_FORCE = 17
N_VINT = 20
VINT_NAMES = (
    "DXLOC_1", "DYLOC_1", "DZLOC_1", "DXLOC_2", "DYLOC_2", "DZLOC_2",
    "FX", "FY", "FZ", "DX", "DY", "DZ", "DISSIP", "PCUM",
    "DXP", "DYP", "DZP", "XX", "XY", "XZ",
)  # fmt: skip
N_WORK = rk54.N_WORK  # work array: (N_WORK, 14) floats


@njit(cache=True)
def hardening_force(params, relative_velocity, dt, state_in, state_out, rate, work):
    """Local force (3) on node 1 at the end of the step; ``relative_velocity``
    = v1 - v2 in the local frame (3). Returns (fx, fy, fz, converged); NaN
    forces when the displacement goes beyond the curve's last point."""
    axial = params[P_AXIAL] == 1.0
    rate[0] = -relative_velocity[0] if axial else 0.0
    rate[1] = 0.0 if axial else -relative_velocity[1]
    rate[2] = 0.0 if axial else -relative_velocity[2]
    converged = rk54.adaptive_integrate(
        rk54.HARDENING,
        params[P_CURVE:],
        state_in[V_STATE : V_STATE + N_Y],
        rate,
        dt,
        int(params[P_ITER_MAX]),
        params[P_RESI],
        params[P_SCALES : P_SCALES + N_Y],
        state_out[V_STATE : V_STATE + N_Y],
        work,
    )
    f = state_out[V_FORCE : V_FORCE + 3]
    if axial:
        return f[0], 0.0, 0.0, converged
    return 0.0, f[1], f[2], converged


@dataclass(frozen=True)
class DisEcroTracParameters:
    """The element's data: its force-displacement curve (a DEFI_FONCTION or
    a ``Curve``), axial (along x) or transverse (in the plane y, z), the
    transverse curve's hardening (kinematic or isotropic), the local
    integration's controls, and the name the messages give the curve."""

    curve: object
    axial: bool
    kinematic: bool
    max_iterations: int
    tolerance: float
    curve_label: str


def prepare_dis_ecro_trac(data: DisEcroTracParameters) -> np.ndarray:
    """Parameter array of the element, after code_aster's checks on its curve."""
    axial = bool(data.axial)
    kinematic = bool(data.kinematic) and not axial
    x, y = check_curve(data.curve, axial, kinematic, data.curve_label)
    n = x.size
    p = np.zeros(P_CURVE + C_N + 1 + 2 * n)
    p[P_AXIAL] = 1.0 if axial else 0.0
    p[P_ITER_MAX] = int(data.max_iterations)
    p[P_RESI] = float(data.tolerance)
    if p[P_ITER_MAX] < 1 or p[P_RESI] <= 0.0:
        raise LawError(
            f"DIS_ECRO_TRAC: {named('max_iterations')} must be >= 1 and {named('tolerance')} > 0"
        )
    fx0, dx0 = y[1], x[1]
    scales = np.empty(N_Y)
    scales[0:3] = fx0 / 10.0
    scales[3:6] = dx0 / 10.0
    scales[6] = fx0 * dx0 / 100.0
    scales[7:11] = dx0 / 10.0
    scales[11:14] = fx0 / 100.0
    p[P_SCALES : P_SCALES + N_Y] = scales
    curve = p[P_CURVE:]
    curve[C_KINEMATIC] = 1.0 if kinematic else 0.0
    curve[C_FX0], curve[C_DX0] = fx0, dx0
    curve[C_N] = n
    curve[C_N + 1 : C_N + 1 + n] = x
    curve[C_N + 1 + n :] = y
    return p


def check_curve(func, axial, kinematic, label, precision=1.0e-10):
    """(x, y) of the curve after code_aster's checks on DIS_ECRO_TRAC curves
    (an axial curve is of DX, a transverse one of DTAN)."""
    x = np.asarray(getattr(func, "abscissas", None if not isinstance(func, tuple) else func[0]))
    y = np.asarray(getattr(func, "ordinates", None if not isinstance(func, tuple) else func[1]))
    if x.dtype == object or y.dtype == object:
        raise LawError(f"{label}: a function (DEFI_FONCTION) is expected")
    x, y = x.astype(float), y.astype(float)
    expected = "DX" if axial else "DTAN"
    para = getattr(func, "NOM_PARA", expected)
    problems = []
    if para != expected:
        problems.append(f"NOM_PARA must be {expected}, not {para}")
    if tuple(getattr(func, "INTERPOL", ("LIN", "LIN"))) != ("LIN", "LIN"):
        problems.append("INTERPOL must be 'LIN'")
    if (getattr(func, "PROL_GAUCHE", "EXCLU"), getattr(func, "PROL_DROITE", "EXCLU")) != (
        "EXCLU",
        "EXCLU",
    ):
        problems.append("PROL_GAUCHE and PROL_DROITE must be 'EXCLU'")
    if kinematic and x.size != 3:
        problems.append("kinematic hardening needs exactly 3 points")
    elif x.size < 3:
        problems.append("at least 3 points are needed")
    elif not (0.0 <= x[0] <= precision and 0.0 <= y[0] <= precision):
        problems.append("the first point must be (0, 0)")
    else:
        slopes = np.diff(y) / np.diff(x)
        if np.any(np.diff(x) <= 0.0) or np.any(np.diff(y) <= 0.0):
            problems.append("abscissas and forces must increase strictly")
        elif np.any(np.diff(slopes) > 0.0):
            problems.append("slopes must decrease from one segment to the next")
    if problems:
        raise LawError(f"{label}: " + "; ".join(problems))
    return x, y
