"""A toy COMPORTEMENT relation added through the documented places only
(docs/architecture.md, "Adding a relation"): this module (its parameter
record, ``prepare``, ``build`` and its archived variables), its entry in
``asterlite.dynamics.laws.connections.RELATIONS``, its reader in
``asterlite.commands.dyna_vibra_relations.READERS`` and its block in
DYNA_VIBRA's catalogue (``catalogues/common_post.register_relation``).
Importing it, before a deck is run in the same process, makes
``RELATION='TOY_RESSORT'`` available.

The relation is a linear spring between a node and the ground on one
component: F = -RAIDEUR · u(NOM_CMP). Its force is the one of the kernel's
nodal branch (``laws.kernel.RELA_EFFO_DEPL``: a force that is a tabulated
function of a node's displacement component), so the time loop needs no
code of its own: the function packed is the line through (0, 0) and
(1, -RAIDEUR), extended linearly on both sides (exact for every u).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass

import numpy as np
from asterlite.catalogues.common_post import register_relation
from asterlite.commands import dyna_vibra_relations as readers

from asterlite.catalog import SIMP
from asterlite.dynamics.laws import connections
from asterlite.dynamics.laws import kernel as law_kernel
from asterlite.dynamics.laws.rela_effo_depl import COMPONENTS
from asterlite.dynamics.laws.tabulated import LawError, pack

NAME = "TOY_RESSORT"
# the kernel's nodal branch archives (value, force, force non-zero)
N_VINT = 3
VINT_NAMES = ("ALLONGEMENT", "FORCE", "ACTIF")


@dataclass(frozen=True)
class ToySpringParameters:
    """The spring's stiffness (N/m) and the node's component it acts on."""

    stiffness: float
    component: str


def prepare(data: ToySpringParameters) -> np.ndarray:
    """The parameter array of the kernel's nodal branch: the component's
    index, then F(u) = -stiffness · u packed as a tabulated function."""
    if data.component not in COMPONENTS[:3]:
        raise LawError(f"{NAME}: the component must be DX, DY or DZ, not {data.component!r}")
    if data.stiffness < 0.0:
        raise LawError(f"{NAME}: the stiffness must be >= 0")
    line = pack([0.0, 1.0], [0.0, -data.stiffness], "LINEAIRE", "LINEAIRE", label=NAME)
    return np.concatenate([[float(COMPONENTS.index(data.component))], line])


def build(connection, spec, mesh) -> None:
    spec.law = prepare(connection.parameters)


def read(occ) -> ToySpringParameters:
    return ToySpringParameters(stiffness=float(occ["RAIDEUR"]), component=occ["NOM_CMP"])


register_relation(
    NAME,
    regles=(),
    GROUP_NO=SIMP(statut="o", typ="grno"),
    NOM_CMP=SIMP(statut="o", typ="TXM", into=("DX", "DY", "DZ")),
    RAIDEUR=SIMP(statut="o", typ="R", val_min=0.0),
)
connections.register(
    connections.Relation(NAME, sys.modules[__name__], law_kernel.RELA_EFFO_DEPL, build)
)
readers.register(NAME, readers.Reader(read, ends=(("NOEUD", "GROUP_NO"),)))
