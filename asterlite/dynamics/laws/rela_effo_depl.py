"""RELA_EFFO_DEPL: a nodal force that is a function of a displacement component.

With u the displacement of the chosen component at the node (global frame, from the
modal basis alone: no mesh coordinates), the force F = f(u) (the user's function) is
applied on the same component. Internal variables (code_aster's order,
VINT1..VINT3): u, F, and 1 when F is non-zero (0 otherwise).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.jit import njit
from asterlite.dynamics.laws.tabulated import LawError, function_table, value
from asterlite.errors import field as named

COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
P_COMPONENT = 0  # index in COMPONENTS
P_FUNCTION = 1  # packed F(u)

V_VALUE, V_FORCE, V_ACTIVE = 0, 1, 2
N_VINT = 3
VINT_NAMES = ("DEPL", "FORCE", "IND_NONZERO")
FORCE_FLOOR = np.finfo(np.float64).eps


@njit(cache=True)
def relation_force(params, component_value, state_out):
    """F(value) (NaN outside an EXCLU side), archived with its value."""
    force = value(params, P_FUNCTION, component_value)
    state_out[V_VALUE] = component_value
    state_out[V_FORCE] = force
    state_out[V_ACTIVE] = 0.0 if abs(force) <= FORCE_FLOOR else 1.0
    return force


@dataclass(frozen=True)
class RelationParameters:
    """The data of RELA_EFFO_DEPL / RELA_EFFO_VITE: the node's component
    (one of :data:`COMPONENTS`, or None to take the function's parameter
    when it names one) and the force as a function of that component's
    displacement or velocity."""

    component: str | None
    function: object


def prepare_relation(data: RelationParameters, relation: str, sample=None) -> np.ndarray:
    """Parameter array of RELA_EFFO_DEPL / RELA_EFFO_VITE (``relation``)."""
    func = data.function
    if func is None:
        raise LawError(f"{relation}: {named('function')} is missing")
    component = data.component
    if component is None:
        names = getattr(func, "nom_para", None) or (getattr(func, "NOM_PARA", None),)
        component = names[0] if names and names[0] in COMPONENTS else None
    if component not in COMPONENTS:
        raise LawError(f"{relation}: {named('component')} must be one of {', '.join(COMPONENTS)}")
    block = function_table(func, f"{relation}/{named('function')}", sample=sample)
    return np.concatenate([[float(COMPONENTS.index(component))], block])


def prepare_rela_effo_depl(data: RelationParameters, sample=None) -> np.ndarray:
    return prepare_relation(data, "RELA_EFFO_DEPL", sample)
