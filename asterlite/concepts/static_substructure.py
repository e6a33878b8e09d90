"""Concepts of static substructuring: the static superelement
(``MACR_ELEM_STAT``), the mesh holding superelements (``super_mesh``,
DEFI_MAILLAGE / ASSE_MAILLAGE SOUS_STR) and the sensors a measured
projection keeps (PROJ_MESU_MODAL's result carries one as ``measurement``,
read by MACR_ELEM_STAT PROJ_MESU)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.concepts.mesh import Mesh


@dataclass(eq=False)
class SensorProjection:
    """What PROJ_MESU_MODAL projected: the sensors of the measurement model
    (node of its mesh, unit direction, component name DX/DY/DZ or D1..D3),
    and the projection basis seen by them, ``observation`` (n_sensors, n_basis)."""

    measurement_model: Any
    basis: Any  # ModeResult on the calculation model
    sensors: list[tuple[int, np.ndarray, str]]
    observation: np.ndarray


@dataclass(eq=False)
class StaticMacroElement(Concept):
    """``MACR_ELEM_STAT``: a superelement condensed on its external nodes.

    ``external_nodes`` are nodes of ``mesh`` (the model's), each carrying
    ``components``; the external DOFs are node by node in that order.
    ``matrices`` holds the condensed RIGI, MASS and AMOR matrices computed so
    far. ``guyan`` (finite-element interior) or ``measured`` (PROJ_MESU)
    says how the interior is restituted."""

    aster_types = ("macr_elem_stat",)

    model: Any
    mesh: Mesh
    external_nodes: np.ndarray
    components: tuple[str, ...]
    matrices: dict[str, np.ndarray] = field(default_factory=dict)
    guyan: Any = None  # asterlite.substructure.static_condensation.GuyanCondensation
    numbering: Any = None  # the model's DofNumbering the Guyan condensation used
    measured: Any = None  # MeasuredCondensation
    sensors: SensorProjection | None = None
    measured_modes: Any = None  # MODE_MESURE
    definition: Any = None  # the DEFINITION keywords (model, materials, characteristics)
    blocked: Any = None  # DOFs of ``numbering`` CHAR_MACR_ELEM blocks
    # which external DOFs (node by node, ``components`` within) it blocks
    blocked_external: Any = None

    def blocked_relations(self, nodes) -> list:
        """The blocked external DOFs as relations u = 0 on ``nodes`` (the
        mesh nodes the external nodes became)."""
        from asterlite.concepts.assembly import LinearRelation

        if self.blocked_external is None:
            return []
        width = len(self.components)
        return [
            LinearRelation(terms=[(int(nodes[k // width]), self.components[k % width], 1.0)])
            for k in np.flatnonzero(self.blocked_external)
        ]

    @property
    def n_external(self) -> int:
        return len(self.external_nodes) * len(self.components)


@dataclass(eq=False)
class SuperCell:
    """A superelement placed in a mesh: its macro-element and the mesh nodes
    its external nodes became (in the macro-element's order)."""

    macro: StaticMacroElement
    nodes: np.ndarray


@dataclass(eq=False)
class SuperMesh(Mesh):
    """A mesh with superelements (code_aster's ``super_mesh``): ordinary
    nodes and cells, plus ``super_cells`` by name."""

    aster_types = ("super_mesh", "maillage_sdaster")

    super_cells: dict[str, SuperCell] = field(default_factory=dict)

    def copy(self) -> SuperMesh:
        base = Mesh.copy(self)
        fields = {name: getattr(base, name) for name in Mesh.__dataclass_fields__}
        cells = {
            name: SuperCell(macro=cell.macro, nodes=cell.nodes.copy())
            for name, cell in self.super_cells.items()
        }
        return SuperMesh(**fields, super_cells=cells)
