"""Localized nonlinearities of a modal transient other than DIS_CHOC.

One module per COMPORTEMENT relation of DYNA_VIBRA (TRAN/GENE): a compiled
force law working on local scalars and flat float64 arrays (parameters,
internal variables in code_aster's archived layout), and a plain-Python
``prepare_*`` turning the validated keyword occurrence into the parameter
array. The time-loop kernel computes the local kinematics (frames,
distances, relative velocities) and projects the returned local forces on
the modes; see each module's docstring for what it needs.

``RELATIONS`` maps each relation to its module, the number of archived
internal variables and their names (VINT1.. in RECU_FONCTION order).
"""

from __future__ import annotations

from types import ModuleType

from asterlite.dynamics.laws import (
    anti_sism,
    choc_elas_trac,
    dis_ecro_trac,
    dis_visc,
    flambage,
    rela_effo_depl,
    rela_effo_vite,
    rotor_fiss,
)
from asterlite.dynamics.laws.tabulated import LawError

RELATIONS: dict[str, ModuleType] = {
    "FLAMBAGE": flambage,
    "ANTI_SISM": anti_sism,
    "DIS_VISC": dis_visc,
    "DIS_ECRO_TRAC": dis_ecro_trac,
    "CHOC_ELAS_TRAC": choc_elas_trac,
    "RELA_EFFO_DEPL": rela_effo_depl,
    "RELA_EFFO_VITE": rela_effo_vite,
    "ROTOR_FISS": rotor_fiss,
}


def internal_variable_names(relation: str) -> tuple[str, ...]:
    """Descriptive names of a relation's archived internal variables (VINT1..)."""
    return RELATIONS[relation].VINT_NAMES


__all__ = ["RELATIONS", "LawError", "internal_variable_names"]
