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

    @property
    def n_external(self) -> int:
        return len(self.external_nodes) * len(self.components)


_TRANSLATIONS = ("DX", "DY", "DZ")
_ROTATIONS = ("DRX", "DRY", "DRZ")


def node_rotation(components: tuple[str, ...], rotation: np.ndarray) -> np.ndarray:
    """The (n_comp, n_comp) global-to-local map of one node's components
    under a global-to-local ``rotation`` (3, 3): translations and rotations
    turned, other components kept (code_aster's ssvaro). Components lacking
    an axis the rotation mixes in are refused (ValueError)."""
    out = np.eye(len(components))
    for family in (_TRANSLATIONS, _ROTATIONS):
        where = [k for k, c in enumerate(components) if c in family]
        axes = [family.index(components[k]) for k in where]
        if not axes:
            continue
        others = [a for a in range(3) if a not in axes]
        if others and np.abs(rotation[np.ix_(axes, others)]).max() > 1.0e-12:
            raise ValueError(
                f"the rotation mixes {', '.join(family[a] for a in others)} into the "
                f"superelement's components {', '.join(components)}"
            )
        out[np.ix_(where, where)] = rotation[np.ix_(axes, axes)]
    return out


@dataclass(eq=False)
class SuperCell:
    """A superelement placed in a mesh: its macro-element, the mesh nodes
    its external nodes became (in the macro-element's order) and, when
    DEFI_MAILLAGE turned it (ANGL_NAUT), the global-to-local rotation."""

    macro: StaticMacroElement
    nodes: np.ndarray
    rotation: np.ndarray | None = None

    def to_local(self) -> np.ndarray | None:
        """The (n_external, n_external) map of global external values to the
        superelement's own frame; None when it is not turned."""
        if self.rotation is None:
            return None
        block = node_rotation(tuple(self.macro.components), self.rotation)
        return np.kron(np.eye(len(self.nodes)), block)

    def matrix(self, kind: str) -> np.ndarray:
        """A condensed matrix in the global frame: Tᵀ A T."""
        matrix = np.asarray(self.macro.matrices[kind], dtype=float)
        local = self.to_local()
        return matrix if local is None else local.T @ matrix @ local

    def blocked_relations(self) -> list:
        """The external DOFs the superelement's CHAR_MACR_ELEM blocks, as
        relations (its own frame's component = 0) on this cell's nodes."""
        from asterlite.concepts.assembly import LinearRelation

        macro = self.macro
        if macro.blocked_external is None:
            return []
        width = len(macro.components)
        block = None
        if self.rotation is not None:
            block = node_rotation(tuple(macro.components), self.rotation)
        relations = []
        for k in np.flatnonzero(macro.blocked_external):
            node = int(self.nodes[k // width])
            row = np.eye(width)[k % width] if block is None else block[k % width]
            terms = [
                (node, macro.components[j], float(row[j]))
                for j in np.flatnonzero(np.abs(row) > 1.0e-14)
            ]
            relations.append(LinearRelation(terms=terms))
        return relations


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
            name: SuperCell(macro=cell.macro, nodes=cell.nodes.copy(), rotation=cell.rotation)
            for name, cell in self.super_cells.items()
        }
        return SuperMesh(**fields, super_cells=cells)
