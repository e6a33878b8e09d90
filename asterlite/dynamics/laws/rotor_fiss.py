"""ROTOR_FISS: cracked rotor, a rotation-dependent stiffness between two nodes.

The crack lies between node D (node 1) and node G (node 2) of a rotor
whose axis is x (``rot_axis`` = R_y(β) R_z(α), code_aster's nautical angles
of neighbour(D) - neighbour(G), the rotor nodes next to the crack nodes:
``connections.rotor_frame``). The frame turns with the rotor:
γ(t) = the user's angle function of time (radians, evaluated at the
instant of each force evaluation) when the speed is variable (the initial
angle and the constant speed then play no part), else γ0 + Ω t, as code_aster's
force routine does; as in code_aster's rot3d, sin γ and cos γ below 1e-6 in
magnitude count as 0. A tabulated angle function is packed with its points
(linear interpolation, its prolongations), a formula runs as the kernels' formula
program (:mod:`asterlite.dynamics.formula`): exact values at every instant,
no sampling.
With δθ = θ_G - θ_D (rotations, global) brought to the turning frame
(δy, δz), the crack's opening angle is
φ = atan2(δy, δz) in [0, 2π) and the moment on node D is, in that frame,

    M = (0,  K(φ) δy + ½ K'(φ) δz,  K(φ) δz - ½ K'(φ) δy)

(node G receives -M), with the stiffness K and its derivative K' = dK/dφ
the user's functions read at φ (radians).

Internal variables (code_aster's order, VINT1..VINT3): the angle φ in
degrees (code_aster 17: φ·180/π; versions up to 16 wrote φ·180/(2π)), then
M_y and M_z in the turning frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.formula import STACK_DEPTH, formula_program, run_program
from asterlite.dynamics.jit import njit
from asterlite.dynamics.laws.tabulated import LawError, function_table, value
from asterlite.errors import field as named

ANGLE_FIELD = named("angle")

P_VARIABLE_SPEED = 0  # γ from: CONSTANT_SPEED, ANGLE_TABLE or ANGLE_PROGRAM
CONSTANT_SPEED, ANGLE_TABLE, ANGLE_PROGRAM = 0.0, 1.0, 2.0
P_ANGLE0, P_SPEED = 1, 2  # initial angle γ0 (rad), rotation speed Ω (rad/s)
P_AT_K, P_AT_DK, P_AT_ANGLE = 3, 4, 5  # where the packed functions start (angle: -1 if none)
HEADER = 6

V_ANGLE, V_MY, V_MZ = 0, 1, 2
N_VINT = 3
VINT_NAMES = ("ANGLE", "MY", "MZ")
TWO_PI = 2.0 * math.pi
TIME_PARAMETER = "INST"  # the parameter of a function of time (NOM_PARA)


@njit(cache=True)
def rotor_angle(params, t):
    source = params[P_VARIABLE_SPEED]
    if source == ANGLE_TABLE:
        return value(params, int(params[P_AT_ANGLE]), t)
    if source == ANGLE_PROGRAM:
        return program_value(params, int(params[P_AT_ANGLE]), t)
    return params[P_ANGLE0] + params[P_SPEED] * t


@njit(cache=True)
def program_value(params, start, t):
    """The formula program packed at ``start`` ([n, n codes, n constants])
    at t, run by the kernels' formula interpreter."""
    n = int(params[start])
    codes = np.zeros((1, n + 1), dtype=np.int64)
    constants = np.zeros((1, n + 1))
    codes[0, 0] = n
    for i in range(n):
        codes[0, 1 + i] = int(params[start + 1 + i])
        constants[0, 1 + i] = params[start + 1 + n + i]
    return run_program(codes, constants, 0, t, np.zeros(STACK_DEPTH))


def pack_program(func, label: str) -> np.ndarray:
    """[n, codes, constants] of a formula of time, or a LawError naming
    what the kernels cannot run."""
    names = tuple(getattr(func, "NOM_PARA", ()) or ())
    if names != (TIME_PARAMETER,):
        raise LawError(f"{label}: a formula of {TIME_PARAMETER} is expected, not of {names}")
    program = formula_program(func)
    if program is None:
        raise LawError(
            f"{label}: this formula uses something the time loop cannot evaluate (a call "
            f"to another function or to a deck def): give it as a DEFI_FONCTION of "
            f"{TIME_PARAMETER} or with arithmetic and math functions only"
        )
    codes, values = program
    return np.concatenate([[float(len(codes))], np.asarray(codes, dtype=float), values])


@njit(cache=True)
def cracked_rotor_moment(params, t, rot_axis, dtheta_x, dtheta_y, dtheta_z, state_out):
    """Global moment (3) on node D; ``dtheta`` = θ_G - θ_D in the global frame."""
    gamma = rotor_angle(params, t)
    cg, sg = math.cos(gamma), math.sin(gamma)
    if abs(cg) < 1.0e-6:  # code_aster's rot3d zeroes such entries
        cg = 0.0
    if abs(sg) < 1.0e-6:
        sg = 0.0
    a = rot_axis[1, 0] * dtheta_x + rot_axis[1, 1] * dtheta_y + rot_axis[1, 2] * dtheta_z
    b = rot_axis[2, 0] * dtheta_x + rot_axis[2, 1] * dtheta_y + rot_axis[2, 2] * dtheta_z
    dy = cg * a + sg * b  # turning frame: rotation by γ about x
    dz = -sg * a + cg * b
    phi = math.atan2(dy, dz)
    if phi < 0.0:
        phi += TWO_PI
    k = value(params, int(params[P_AT_K]), phi)
    dk = value(params, int(params[P_AT_DK]), phi)
    my = k * dy + 0.5 * dk * dz
    mz = k * dz - 0.5 * dk * dy
    state_out[V_ANGLE] = math.degrees(phi)
    state_out[V_MY] = my
    state_out[V_MZ] = mz
    # back to the axis frame, then to the global frame
    ma = cg * my - sg * mz
    mb = sg * my + cg * mz
    return (
        rot_axis[1, 0] * ma + rot_axis[2, 0] * mb,
        rot_axis[1, 1] * ma + rot_axis[2, 1] * mb,
        rot_axis[1, 2] * ma + rot_axis[2, 2] * mb,
    )


ANGLE_SAMPLES = np.linspace(0.0, TWO_PI, 3601)


@dataclass(frozen=True)
class RotorFissParameters:
    """The crack's data: the stiffness K(φ) and its derivative K'(φ)
    (functions of the opening angle in radians), the rotor's angle at
    t = 0 (degrees) and, at variable speed, its angle as a function of the
    instant (None otherwise)."""

    stiffness: object
    stiffness_derivative: object
    initial_angle: float
    angle: object | None


def prepare_rotor_fiss(
    data: RotorFissParameters, rotation_speed: float = 0.0, variable_speed: bool = False
) -> np.ndarray:
    """Parameter array of the crack. ``rotation_speed`` (rad/s, constant
    speed only) and ``variable_speed``: the transient's rotation."""
    header = np.zeros(HEADER)
    header[P_ANGLE0] = math.radians(float(data.initial_angle))
    header[P_SPEED] = float(rotation_speed)
    blocks = []
    for label, function in (
        (f"ROTOR_FISS/{named('stiffness')}", data.stiffness),
        (f"ROTOR_FISS/{named('stiffness_derivative')}", data.stiffness_derivative),
    ):
        if function is None:
            raise LawError(f"{label} is missing")
        blocks.append(function_table(function, label, sample=ANGLE_SAMPLES))
    header[P_AT_ANGLE] = -1.0
    if variable_speed:
        angle = data.angle
        if angle is None:
            raise LawError(
                f"ROTOR_FISS: {ANGLE_FIELD} (angle vs {TIME_PARAMETER}) is needed at variable speed"
            )
        if hasattr(angle, "VALE") and hasattr(angle, "evaluate"):  # a formula
            header[P_VARIABLE_SPEED] = ANGLE_PROGRAM
            blocks.append(pack_program(angle, f"ROTOR_FISS/{ANGLE_FIELD}"))
        else:
            header[P_VARIABLE_SPEED] = ANGLE_TABLE
            blocks.append(function_table(angle, f"ROTOR_FISS/{ANGLE_FIELD}", para=TIME_PARAMETER))
    at = HEADER
    for slot, block in zip((P_AT_K, P_AT_DK, P_AT_ANGLE), blocks, strict=False):
        header[slot] = at
        at += block.size
    return np.concatenate([header, *blocks])
