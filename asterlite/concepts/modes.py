"""Modal bases and the generalized (projected) objects built on them."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.assembly import AssembledMatrix, DofNumbering
from asterlite.concepts.base import Concept


@dataclass(eq=False)
class ModeResult(Concept):
    """A modal basis: ``CALC_MODES``, ``MODE_STATIQUE``, ``DEFI_BASE_MODALE``...

    ``shapes`` is (n_dofs, n_modes) on ``numbering``'s physical DOFs.
    ``frequencies`` in Hz (0 for static modes), ``generalized_mass`` and
    ``generalized_stiffness`` per mode. ``parameters`` holds per-mode
    extra quantities by code_aster name (e.g. ``"FACT_PARTICI_DX"``).
    """

    aster_types = ("mode_meca", "resultat_sdaster")

    numbering: DofNumbering
    shapes: np.ndarray
    frequencies: np.ndarray
    generalized_mass: np.ndarray
    generalized_stiffness: np.ndarray
    mass: AssembledMatrix | None = None
    stiffness: AssembledMatrix | None = None
    kind: str = "dynamic"  # dynamic, static
    parameters: dict[str, np.ndarray] = field(default_factory=dict)

    @property
    def n_modes(self) -> int:
        return self.shapes.shape[1]

    def shape_at(self, node: int | str, component: str) -> np.ndarray:
        """Row of the modal matrix for one DOF: one value per mode (0 if the
        DOF does not exist, as for a component the element does not carry)."""
        try:
            row = self.numbering.dof_index(node, component)
        except KeyError:
            return np.zeros(self.n_modes)
        return self.shapes[row, :]


@dataclass(eq=False)
class GeneralizedNumbering(Concept):
    """``NUME_DDL_GENE``: the generalized unknowns of a basis."""

    aster_types = ("nume_ddl_gene",)

    basis: ModeResult
    storage: str = "PLEIN"  # PLEIN or DIAG

    @property
    def n_modes(self) -> int:
        return self.basis.n_modes


@dataclass(eq=False)
class GeneralizedMatrix(Concept):
    """A projected matrix Φᵀ A Φ (dense, n_modes × n_modes)."""

    aster_types = ("matr_asse_gene_r", "matr_asse_gene")

    numbering: GeneralizedNumbering
    matrix: np.ndarray
    kind: str = "RIGI"  # RIGI, MASS, AMOR

    @property
    def basis(self) -> ModeResult:
        return self.numbering.basis


@dataclass(eq=False)
class GeneralizedVector(Concept):
    """A projected vector Φᵀ v (forces) or the generalized coordinates of a
    displacement/velocity field (``TYPE_VECT='DEPL'``: least-squares in the
    mass metric, as code_aster does)."""

    aster_types = ("vect_asse_gene",)

    numbering: GeneralizedNumbering
    values: np.ndarray
    kind: str = "FORC"  # FORC, DEPL, VITE, ACCE
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def basis(self) -> ModeResult:
        return self.numbering.basis
