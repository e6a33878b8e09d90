"""ANTI_SISM: seismic stop device between two nodes (code_aster's mdfdas).

The device acts along the axis node 1 -> node 2 (a BI_PLAN_Y connection
whose normal is that axis). With ``d`` the signed normal distance (the
elongation of the device, > 0 when the nodes move apart) and ``v`` its
rate, the force on node 1 along the normal n is::

    F = -k2 d - (k1 - k2) d / sqrt(1 + (k1 d / f_s)^2)
        - c sign(v) |v d / d_max|^a

(node 2 receives -F n). The first two terms are an elastic law with
initial stiffness k1 that saturates towards the threshold f_s and then
stiffens again with the final stiffness k2; the last is a viscous term of
coefficient c, exponent a and reference stroke d_max that code_aster writes
with the product |v d| (not |v|), kept as is. Below machine precision in
|v| the viscous term is dropped, as code_aster does.

Stateless: no internal memory, only archived quantities.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.jit import njit
from asterlite.dynamics.laws.tabulated import LawError
from asterlite.errors import field as named

# Parameters
P_K1, P_K2, P_SEUIL_FX, P_C, P_ALPHA, P_DX_MAX = range(6)
N_PARAMS = 6

# Archived internal variables (code_aster's order, VINT1..VINT8)
V_FORCE = 0  # force of the device (signed, along the normal)
V_LOC1 = 1  # local coordinates of node 1 (3)
V_LOC2 = 4  # local coordinates of node 2 (3)
V_VN = 7  # normal relative velocity
N_VINT = 8
VINT_NAMES = ("FORCE", "DXLOC_1", "DYLOC_1", "DZLOC_1", "DXLOC_2", "DYLOC_2", "DZLOC_2", "VNORM")

VELOCITY_FLOOR = np.finfo(np.float64).eps  # code_aster's r8prem


@njit(cache=True)
def antiseismic_force(params, d, v):
    """Force on node 1 along the connection normal; ``d`` the normal
    distance relative to rest, ``v`` its rate (relative normal velocity)."""
    k1, k2 = params[P_K1], params[P_K2]
    seuil = params[P_SEUIL_FX]
    # saturating elastic part; a zero threshold is its limit (no k1 - k2 part)
    if seuil != 0.0:
        f = -k2 * d - (k1 - k2) * d / math.sqrt(1.0 + (k1 * d / seuil) ** 2)
    else:
        f = -k2 * d
    if abs(v) >= VELOCITY_FLOOR:
        f -= (
            params[P_C]
            * (1.0 if v >= 0.0 else -1.0)
            * abs(v * d / params[P_DX_MAX]) ** params[P_ALPHA]
        )
    return f


@njit(cache=True)
def elastic_energy(params, d):
    """Energy stored in the elastic part at distance d (for checks): -∫ F_el dd."""
    k1, k2, seuil = params[P_K1], params[P_K2], params[P_SEUIL_FX]
    energy = 0.5 * k2 * d * d
    if seuil != 0.0:
        a = k1 / seuil
        energy += (k1 - k2) * (math.sqrt(1.0 + (a * d) ** 2) - 1.0) / (a * a)
    return energy


@dataclass(frozen=True)
class AntiSismParameters:
    """The device's data (N, m, s): initial and final stiffnesses, the force
    threshold between them, the viscous coefficient and exponent, and the
    stroke that scales the viscous term."""

    initial_stiffness: float
    final_stiffness: float
    threshold: float
    viscosity: float
    exponent: float
    stroke: float


def prepare_anti_sism(data: AntiSismParameters) -> np.ndarray:
    """Parameter array of the device, after code_aster's checks."""
    p = np.zeros(N_PARAMS)
    p[P_K1] = float(data.initial_stiffness)
    p[P_K2] = float(data.final_stiffness)
    p[P_SEUIL_FX] = float(data.threshold)
    p[P_C] = float(data.viscosity)
    p[P_ALPHA] = float(data.exponent)
    p[P_DX_MAX] = float(data.stroke)
    if p[P_K1] < 0.0 or p[P_K2] < 0.0:
        raise LawError(
            f"ANTI_SISM: {named('initial_stiffness')} and {named('final_stiffness')} must be >= 0"
        )
    if p[P_SEUIL_FX] < 0.0:
        raise LawError(f"ANTI_SISM: {named('threshold')} must be >= 0")
    if p[P_C] < 0.0 or p[P_ALPHA] < 0.0:
        raise LawError(f"ANTI_SISM: {named('viscosity')} and {named('exponent')} must be >= 0")
    if p[P_DX_MAX] <= 0.0:
        raise LawError(f"ANTI_SISM: {named('stroke')} must be > 0 (it divides the viscous term)")
    return p


def reference_distance(coord1, coord2, info: int = 1) -> float:
    """The 'gap' code_aster subtracts from the node distance along the axis.

    code_aster stores the squared node distance and takes its square root
    only when its information level is 2 (a quirk of its preparation
    routine); the distance is then split in two equal halves of gap/2 on each
    node of a BI_PLAN_Y connection with no play. Reproduced so that decks
    give code_aster's numbers; with ``info=2`` (or unit
    distance) ``d`` is the true elongation.
    """
    squared = float(np.sum((np.asarray(coord2, float) - np.asarray(coord1, float)) ** 2))
    return math.sqrt(squared) if info == 2 else squared
