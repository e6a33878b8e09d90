"""RELA_EFFO_VITE: a nodal force that is a function of a velocity component.

Same as RELA_EFFO_DEPL with the velocity v of the chosen component (global frame, from
the modal basis): F = f(v) on that component. Internal variables
(VINT1..VINT3): v, F, and 1 when F is non-zero.
"""

from __future__ import annotations

from asterlite.dynamics.laws.rela_effo_depl import (
    COMPONENTS,
    N_VINT,
    P_COMPONENT,
    P_FUNCTION,
    V_ACTIVE,
    V_FORCE,
    V_VALUE,
    RelationParameters,
    prepare_relation,
    relation_force,
)

VINT_NAMES = ("VITE", "FORCE", "IND_NONZERO")
__all__ = [
    "COMPONENTS", "N_VINT", "P_COMPONENT", "P_FUNCTION", "V_ACTIVE", "V_FORCE", "V_VALUE",
    "VINT_NAMES", "RelationParameters", "prepare_rela_effo_vite", "relation_force",
]  # fmt: skip


def prepare_rela_effo_vite(data: RelationParameters, sample=None):
    return prepare_relation(data, "RELA_EFFO_VITE", sample)
