"""CHOC_ELAS_TRAC: nonlinear elastic shock along the axis of two nodes.

The 'length' of the discrete element is ld = L0 - d1 - d2 + (u2 - u1)·x
with L0 the rest distance of the nodes along the axis x (node 1 -> node 2)
and d1, d2 the distances of the nodes to the contact surface (the shock's
thicknesses).
In contact (ld <= 0) the element pushes the nodes apart with the force
F = f(-ld) read on the user's force curve (with its own prolongations); otherwise
there is no force. Node 1 receives -F along x, node 2 +F. Elastic: no memory.

Internal variables (VINT1, VINT2 as code_aster archives them; the rest is
asterlite's): the compressive force F (>= 0), the length ld, then the local
coordinates of both nodes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.jit import njit
from asterlite.dynamics.laws.tabulated import LawError, function_table, unpack, value
from asterlite.errors import field as named

FORCE_CURVE = named("force_curve")

P_REST = 0  # L0 - d1 - d2
P_FX = 1  # packed force curve f(crushing)

V_FORCE, V_LENGTH = 0, 1
V_LOC1, V_LOC2 = 2, 5
N_VINT = 8
VINT_NAMES = ("FORCE", "LONGUEUR", "DXLOC_1", "DYLOC_1", "DZLOC_1", "DXLOC_2", "DYLOC_2", "DZLOC_2")


@njit(cache=True)
def elastic_shock_force(params, axial_elongation, state_out):
    """Axial force on node 1 (-F when in contact); ``axial_elongation``
    = (u2 - u1)·x. NaN when the force curve is evaluated outside an EXCLU side."""
    length = params[P_REST] + axial_elongation
    force = 0.0
    if length <= 0.0:
        force = value(params, P_FX, -length)
    state_out[V_FORCE] = force
    state_out[V_LENGTH] = length
    return -force


@dataclass(frozen=True)
class ChocElasTracParameters:
    """The shock's data: the force as a function of the crushing, and the
    distances taken off the nodes' rest distance on each side (0 when not
    given)."""

    force_curve: object
    distance_1: float
    distance_2: float


def prepare_choc_elas_trac(data: ChocElasTracParameters, rest_distance: float = 0.0) -> np.ndarray:
    """Parameter array of the shock; ``rest_distance``: the distance of the
    two nodes in the mesh."""
    dist = float(data.distance_1) + float(data.distance_2)
    if data.force_curve is None:
        raise LawError(f"CHOC_ELAS_TRAC: {FORCE_CURVE} (force vs crushing DX) is missing")
    block = function_table(data.force_curve, f"CHOC_ELAS_TRAC/{FORCE_CURVE}")
    x, y, _, _ = unpack(block)
    if np.any(y < 0.0):
        raise LawError(
            f"CHOC_ELAS_TRAC/{FORCE_CURVE}: the force must be >= 0 (a shock only pushes)"
        )
    return np.concatenate([[float(rest_distance) - dist], block])
