"""Dynamic substructuring: interfaces, macro-elements, the coupled model.

Data flow (code_aster's classical substructuring, R4.06):

    NUME_DDL ──DEFI_INTERF_DYNA──> DynamicInterfaces (nodes, components, type)
    modes + interfaces ──DEFI_BASE_MODALE CLASSIQUE──> ModeResult (the basis)
    basis ──MACR_ELEM_DYNA──> MacroElement (Φᵀ K Φ, Φᵀ M Φ on the basis)
    macro-elements + links ──DEFI_MODELE_GENE──> GeneralizedModel
    model ──NUME_DDL_GENE──> SubstructuredNumbering (the substructures'
        generalized unknowns one after the other, plus the interface
        compatibility relations B q = 0)
    numbering ──ASSE_MATR_GENE / ASSE_VECT_GENE──> block-diagonal
        GeneralizedMatrix / GeneralizedVector on that numbering

code_aster writes B q = 0 into the assembled matrices with (double)
Lagrange multipliers; here the relations stay beside the matrices, as for
the physical numberings (DofNumbering.relations), and the solvers work on
their null space. Eigenvectors and restitutions are the same.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.base import Concept
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.modes import GeneralizedNumbering, ModeResult


@dataclass(eq=False)
class Interface:
    """One INTERFACE occurrence: its nodes (mesh indices, in code_aster's
    order) and the DOF indices of the numbering it holds, node by node."""

    name: str
    kind: str  # CRAIGB, MNEAL, CB_HARMO, AUCUN
    nodes: np.ndarray
    masked: tuple[str, ...]
    dofs: np.ndarray  # indices in the numbering, grouped by node
    dof_nodes: np.ndarray  # node of each entry of ``dofs``


@dataclass(eq=False)
class DynamicInterfaces(Concept):
    """``DEFI_INTERF_DYNA`` result (an ``interf_dyna_clas``)."""

    aster_types = ("interf_dyna_clas",)

    numbering: DofNumbering
    interfaces: list[Interface]
    frequency: float = 1.0  # FREQ of the CB_HARMO interfaces

    def find(self, name: str) -> Interface | None:
        for interface in self.interfaces:
            if interface.name == name:
                return interface
        return None


@dataclass(eq=False)
class ReductionBasis(ModeResult):
    """``DEFI_BASE_MODALE(CLASSIQUE=...)``: a mode_meca that remembers the
    interfaces its static modes were built on (MACR_ELEM_DYNA reads them)."""

    interfaces: DynamicInterfaces | None = None


@dataclass(eq=False)
class MacroElement(Concept):
    """``MACR_ELEM_DYNA`` result: a substructure reduced on its basis.

    ``stiffness``, ``mass`` (and ``damping``) are the dense projections
    Φᵀ A Φ of the substructure's assembled matrices on the basis vectors."""

    aster_types = ("macr_elem_dyna",)

    basis: ModeResult
    interfaces: DynamicInterfaces
    stiffness: np.ndarray
    mass: np.ndarray
    damping: np.ndarray | None = None

    @property
    def n_modes(self) -> int:
        return self.basis.n_modes

    @property
    def mesh(self) -> Mesh:
        return self.basis.numbering.mesh


@dataclass(eq=False)
class Substructure:
    """A macro-element placed in the global frame: x_global = R x + T."""

    name: str
    macro: MacroElement
    rotation: np.ndarray  # (3, 3)
    translation: np.ndarray  # (3,)

    def to_global(self, coords: np.ndarray) -> np.ndarray:
        return np.asarray(coords, dtype=float) @ self.rotation.T + self.translation


@dataclass(eq=False)
class Link:
    """A LIAISON: interface_1 of substructure_1 glued to interface_2 of
    substructure_2, node pairs in ``pairs`` (interface positions)."""

    substructure_1: str
    interface_1: str
    substructure_2: str
    interface_2: str
    pairs: list[tuple[int, int]] = field(default_factory=list)


@dataclass(eq=False)
class GeneralizedModel(Concept):
    """``DEFI_MODELE_GENE`` result (a ``modele_gene``)."""

    aster_types = ("modele_gene",)

    substructures: list[Substructure]
    links: list[Link]

    def find(self, name: str) -> Substructure | None:
        for sub in self.substructures:
            if sub.name == name:
                return sub
        return None


@dataclass(eq=False)
class SubstructuredNumbering(GeneralizedNumbering):
    """``NUME_DDL_GENE(MODELE_GENE=...)``: the substructures' generalized
    unknowns in model order (``offsets[k]`` is the first of substructure
    k) and the compatibility relations ``constraints`` @ q = 0."""

    model: GeneralizedModel | None = None
    offsets: np.ndarray = field(default_factory=lambda: np.zeros(1, dtype=int))
    constraints: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    method: str = "CLASSIQUE"

    @property
    def n_modes(self) -> int:
        return int(self.offsets[-1])

    def block(self, name: str) -> slice:
        """The generalized unknowns of one substructure."""
        for k, sub in enumerate(self.model.substructures):
            if sub.name == name:
                return slice(int(self.offsets[k]), int(self.offsets[k + 1]))
        raise KeyError(name)


@dataclass(eq=False)
class Skeleton(Mesh):
    """``DEFI_SQUELETTE``: the substructures' meshes placed in the global
    frame, nodes and cells renamed N1.., MA1.. in substructure order.
    ``origin[i]`` is (substructure name, node index in its own mesh) of
    skeleton node i."""

    aster_types = ("squelette", "maillage_sdaster")

    origin: list[tuple[str, int]] = field(default_factory=list)
    model: Any = None

    def copy(self) -> Skeleton:
        base = Mesh.copy(self)
        return Skeleton(
            coords=base.coords,
            node_names=base.node_names,
            cell_names=base.cell_names,
            cell_types=base.cell_types,
            cell_nodes=base.cell_nodes,
            node_groups=base.node_groups,
            cell_groups=base.cell_groups,
            dim=base.dim,
            title=base.title,
            origin=list(self.origin),
            model=self.model,
        )
