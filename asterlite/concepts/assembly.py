"""Concepts of the structural front end: model, characteristics, loads,
elementary matrices, DOF numbering, assembled matrices and nodal fields.

Owner: the front end (``asterlite.fem``). Other rooms read these through the
attributes documented here; add fields, do not rename them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.concepts.mesh import Mesh


@dataclass(eq=False)
class Model(Concept):
    """``AFFE_MODELE`` result: which modelisation each cell carries."""

    aster_types = ("modele_sdaster",)

    mesh: Mesh
    cell_modelisation: dict[int, str] = field(default_factory=dict)  # cell index -> "DIS_T", ...
    node_modelisation: dict[int, str] = field(default_factory=dict)  # node-supported elements


@dataclass(eq=False)
class LinearRelation:
    """sum(coef * u[node, component]) = rhs, as given by DDL_IMPO or LIAISON_DDL."""

    terms: list[tuple[int, str, float]]  # (node index, component "DX", coefficient)
    rhs: float = 0.0


@dataclass(eq=False)
class MechanicalLoad(Concept):
    """``AFFE_CHAR_MECA`` result: kinematic relations and nodal forces."""

    aster_types = ("char_meca",)

    model: Model
    relations: list[LinearRelation] = field(default_factory=list)
    nodal_forces: list[tuple[int, str, float]] = field(default_factory=list)
    extra: dict[str, Any] = field(default_factory=dict)  # other load kinds, keyed by keyword


@dataclass(eq=False)
class DofNumbering(Concept):
    """``NUME_DDL`` result: the physical unknowns and the constraints on them.

    ``dofs[i] = (node index, component)``; ``index[(node, component)] = i``.
    Constraints (from the loads given to the matrices) are kept as linear
    relations; assembled matrices live on the physical DOFs only and the
    eigen solver / static solver apply the relations (equivalent to
    code_aster's dualised Lagrange multipliers).
    """

    aster_types = ("nume_ddl_sdaster",)

    mesh: Mesh
    dofs: list[tuple[int, str]]
    relations: list[LinearRelation] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.index = {dof: i for i, dof in enumerate(self.dofs)}

    @property
    def n_dofs(self) -> int:
        return len(self.dofs)

    def dof_index(self, node: int | str, component: str) -> int:
        """Index of (node, component); raises KeyError when absent."""
        if isinstance(node, str):
            node = self.mesh.node_index[node]
        return self.index[(node, component)]


@dataclass(eq=False)
class AssembledMatrix(Concept):
    """``ASSE_MATRICE`` result on the physical DOFs (scipy sparse CSR)."""

    aster_types = ("matr_asse_depl_r", "matr_asse")

    numbering: DofNumbering
    matrix: Any  # scipy.sparse.csr_matrix (n_dofs, n_dofs)
    kind: str = "RIGI"  # RIGI, MASS, AMOR


@dataclass(eq=False)
class NodalField(Concept):
    """A field on nodes (``cham_no_sdaster``): one value per DOF of a numbering."""

    aster_types = ("cham_no_sdaster",)

    numbering: DofNumbering
    values: np.ndarray
