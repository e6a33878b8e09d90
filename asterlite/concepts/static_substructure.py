"""Concepts of static substructuring: the static superelement
(``MACR_ELEM_STAT``), the mesh holding superelements (``super_mesh``,
DEFI_MAILLAGE / ASSE_MAILLAGE SOUS_STR) and the sensors a measured
projection keeps (PROJ_MESU_MODAL's result carries one as ``measurement``,
read by MACR_ELEM_STAT PROJ_MESU)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.assembly import LinearRelation
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
class LoadCase:
    """A condensed load case (CAS_CHARGE): the load on the external DOFs
    (the superelement's frame), the interior response with the external
    DOFs held, and whether the load turns with the super-cell (SUIV)."""

    vector: np.ndarray
    interior: np.ndarray
    follows: bool = True
    # what a turned super-cell recondenses a load that does not follow
    # (SUIV='NON'): the forces on the superelement's DOFs, the inside
    # relations' matrix and imposed values
    forces: Any = None
    relations: Any = None
    values: Any = None


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
    stiffness: Any = None  # the model's assembled stiffness the condensation used
    # relations of CHAR_MACR_ELEM between external DOFs only: (positions in
    # the external DOFs, coefficients), imposed in the models using it
    external_relations: list = field(default_factory=list)
    inside_relations: Any = None  # rows of the numbering's relations kept inside
    load_cases: dict[str, LoadCase] = field(default_factory=dict)

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


def dof_rotation(numbering, rotation: np.ndarray):
    """The sparse global-to-local map of every DOF of a numbering, node by
    node (:func:`node_rotation`)."""
    import scipy.sparse as sp

    by_node: dict[int, list[int]] = {}
    for index, (node, _) in enumerate(numbering.dofs):
        by_node.setdefault(node, []).append(index)
    rows, cols, vals = [], [], []
    for indices in by_node.values():
        block = node_rotation(tuple(numbering.dofs[i][1] for i in indices), rotation)
        for a, i in enumerate(indices):
            for b, j in enumerate(indices):
                if block[a, b] != 0.0:
                    rows.append(i)
                    cols.append(j)
                    vals.append(block[a, b])
    n = numbering.n_dofs
    return sp.csr_matrix((vals, (rows, cols)), shape=(n, n))


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

    def load_case(self, case: str) -> tuple[np.ndarray, np.ndarray]:
        """(condensed load in the superelement's frame, interior response)
        of a case placed in this cell. A load that does not follow the
        turned cell (SUIV='NON') keeps its global directions: turned into
        the superelement's frame, then condensed again (code_aster's ssvalv)."""
        from asterlite.substructure.static_condensation import condensed_load

        macro = self.macro
        load = macro.load_cases[case]
        if self.rotation is None or load.follows:
            return load.vector, load.interior
        turned = dof_rotation(macro.numbering, self.rotation) @ load.forces
        condensed, interior = condensed_load(
            macro.guyan, macro.stiffness, load.relations, load.values, turned
        )
        full = np.zeros(macro.n_external)
        full[np.flatnonzero(~macro.blocked_external)] = condensed
        return full, interior

    def load_terms(self, case: str) -> list[tuple[int, str, float]]:
        """The condensed load of a case as nodal terms on this cell's nodes,
        in the global frame (KeyError: no such case)."""
        vector, _ = self.load_case(case)
        local = self.to_local()
        if local is not None:
            vector = local.T @ vector
        width = len(self.macro.components)
        return [
            (int(self.nodes[k // width]), self.macro.components[k % width], float(v))
            for k, v in enumerate(vector)
            if v != 0.0
        ]

    def blocked_relations(self) -> list:
        """The relations CHAR_MACR_ELEM puts on the external DOFs (blocked
        ones, relations between external DOFs), in the superelement's frame,
        as relations of this cell's nodes."""
        macro = self.macro
        if macro.blocked_external is None:
            return []
        width = len(macro.components)
        local = self.to_local()
        if local is None:
            local = np.eye(macro.n_external)
        rows = [(np.array([k]), np.ones(1)) for k in np.flatnonzero(macro.blocked_external)]
        rows += macro.external_relations
        relations = []
        for positions, coefficients in rows:
            # Σ c u_local = 0 with u_local = T u_global
            combined = coefficients @ local[positions]
            terms = [
                (int(self.nodes[j // width]), macro.components[j % width], float(combined[j]))
                for j in np.flatnonzero(np.abs(combined) > 1.0e-14 * np.abs(combined).max())
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
