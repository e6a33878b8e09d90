"""Modal bases and the generalized (projected) objects built on them."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.concepts.assembly import AssembledMatrix, DofNumbering
from asterlite.concepts.base import Concept
from asterlite.concepts.numpy_api import dense_copy, replaced_values
from asterlite.errors import DeckRuntimeError
from asterlite.post.deck_api import field_indexes, mode_field, set_result_mesh


@dataclass(eq=False)
class ModeResult(Concept):
    """A modal basis: ``CALC_MODES``, ``MODE_STATIQUE``, ``DEFI_BASE_MODALE``...

    ``shapes`` is (n_dofs, n_modes) on ``numbering``'s physical DOFs (the
    Lagrange multipliers of code_aster do not exist here; constrained DOFs
    hold their zero value). ``frequencies`` in Hz (0 for static modes),
    ``generalized_mass`` and ``generalized_stiffness`` per mode (φᵀMφ, φᵀKφ).
    ``parameters`` holds per-mode extra quantities by code_aster name
    (``NUME_MODE``, ``FREQ``, ``OMEGA2``, ``MASS_GENE``, ``RIGI_GENE``,
    ``FACT_PARTICI_DX``, ``MASS_EFFE_DX``, ``MASS_EFFE_UN_DX``...).

    Normalisation (``norm``): CALC_MODES without NORM_MODE divides each shape
    by its signed component of largest magnitude over all physical DOFs
    (first in DOF order on ties), so that component is +1 -- code_aster's
    ``SANS_CMP: LAGR``. NORM_MODE / CALC_MODES(NORM_MODE=...) rescale
    afterwards (``MASS_GENE``: φᵀMφ = 1, ``TRAN``: largest translation = +1,
    ...). Static modes (MODE_STATIQUE) are not normalised: a unit imposed
    displacement (MODE_STAT) or the response to a unit force (FORCE_NODALE).
    ``mode_labels`` names each static mode (``"NO1 DX"``) and is empty for
    dynamic modes.
    """

    aster_types = ("mode_meca", "resultat_sdaster")
    deck_methods = frozenset(
        {
            "getName",
            "getField",
            "getIndexes",
            "getIndexesForFieldName",
            "getNumberOfModes",
            "setMesh",
            "LIST_VARI_ACCES",
        }
    )

    numbering: DofNumbering
    shapes: np.ndarray
    frequencies: np.ndarray
    generalized_mass: np.ndarray
    generalized_stiffness: np.ndarray
    mass: AssembledMatrix | None = None
    stiffness: AssembledMatrix | None = None
    kind: str = "dynamic"  # dynamic, static
    parameters: dict[str, np.ndarray] = field(default_factory=dict)
    norm: str = "SANS_CMP: LAGR"
    mode_labels: list[str] = field(default_factory=list)
    damping: AssembledMatrix | None = None

    @property
    def n_modes(self) -> int:
        return self.shapes.shape[1]

    # deck API (code_aster's ModeResult), see asterlite.post.deck_api
    def getField(self, name, value=1, para="NUME_ORDRE"):  # noqa: N802

        return mode_field(self, name, value, para)

    def getIndexes(self) -> list[int]:  # noqa: N802
        return list(range(1, self.n_modes + 1))

    def getIndexesForFieldName(self, name) -> list[int]:  # noqa: N802
        return field_indexes(self, name)

    def getNumberOfModes(self) -> int:  # noqa: N802
        return int(self.n_modes)

    def LIST_VARI_ACCES(self) -> dict:  # noqa: N802 - code_aster's name
        """The access variables of a mode_meca, one value per mode:
        NUME_ORDRE, NUME_MODE, FREQ and NOEUD_CMP (a static mode's label,
        None for a dynamic mode)."""
        labels = list(self.mode_labels) or [None] * self.n_modes
        return {
            "NUME_ORDRE": list(range(1, self.n_modes + 1)),
            "NUME_MODE": [int(n) for n in self.mode_numbers],
            "FREQ": [float(f) for f in self.frequencies],
            "NOEUD_CMP": labels,
        }

    def setMesh(self, mesh) -> None:  # noqa: N802

        set_result_mesh(self, mesh)

    @property
    def mode_numbers(self) -> np.ndarray:
        """NUME_MODE of each mode (1-based)."""
        numbers = self.parameters.get("NUME_MODE")
        return np.arange(1, self.n_modes + 1) if numbers is None else np.asarray(numbers)

    @property
    def omega2(self) -> np.ndarray:
        return np.sign(self.frequencies) * (2.0 * np.pi * self.frequencies) ** 2

    def shapes_at(self, nodes, components) -> np.ndarray:
        """Vectorised :meth:`shape_at`: (len(nodes), n_modes); ``components`` is
        one name or one per node; absent DOFs give zero rows."""
        rows = self.numbering.dof_indices(nodes, components)
        out = np.zeros((len(rows), self.n_modes))
        present = rows >= 0
        out[present] = self.shapes[rows[present], :]
        return out

    def rescale(self, factors, norm: str | None = None) -> None:
        """Multiply each mode by its factor and update the generalized quantities."""
        factors = np.asarray(factors, dtype=float)
        self.shapes = self.shapes * factors[None, :]
        self.generalized_mass = self.generalized_mass * factors**2
        self.generalized_stiffness = self.generalized_stiffness * factors**2
        for key in ("MASS_GENE", "RIGI_GENE"):
            if key in self.parameters:
                self.parameters[key] = np.asarray(self.parameters[key]) * factors**2
        # participation factors scale as 1/factor, effective masses are invariant
        for c in ("DX", "DY", "DZ"):
            key = f"FACT_PARTICI_{c}"
            if key in self.parameters:
                self.parameters[key] = np.asarray(self.parameters[key]) / factors
        if norm is not None:
            self.norm = norm

    def select(self, indices) -> ModeResult:
        """A new basis made of the modes at 0-based ``indices`` (keeps NUME_MODE)."""
        indices = np.asarray(indices, dtype=int)
        params = {}
        for key, value in self.parameters.items():
            value = np.asarray(value)
            params[key] = value[indices] if value.shape[:1] == (self.n_modes,) else value
        return ModeResult(
            numbering=self.numbering,
            shapes=self.shapes[:, indices].copy(),
            frequencies=np.asarray(self.frequencies)[indices].copy(),
            generalized_mass=np.asarray(self.generalized_mass)[indices].copy(),
            generalized_stiffness=np.asarray(self.generalized_stiffness)[indices].copy(),
            mass=self.mass,
            stiffness=self.stiffness,
            kind=self.kind,
            parameters=params,
            norm=self.norm,
            mode_labels=[self.mode_labels[i] for i in indices] if self.mode_labels else [],
            damping=self.damping,
        )

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
    """A projected matrix Φᵀ A Φ (dense, n_modes × n_modes). With
    ``STOCKAGE='DIAG'`` only the diagonal is kept (off-diagonal terms zero),
    as code_aster stores it."""

    aster_types = ("matr_asse_gene_r", "matr_asse_gene")
    deck_methods = frozenset({"getName", "toNumpy", "fromNumpy"})

    numbering: GeneralizedNumbering
    matrix: np.ndarray
    kind: str = "RIGI"  # RIGI, MASS, AMOR

    @property
    def basis(self) -> ModeResult:
        return self.numbering.basis

    def toNumpy(self) -> np.ndarray:  # noqa: N802 - code_aster's name
        """The values as a dense array (a copy)."""

        return dense_copy(self.matrix, self.name or "matrix")

    def fromNumpy(self, values) -> None:  # noqa: N802
        """Replace the values by a deck's array of the same shape (code_aster's
        EXTR_MATR_GENE/RECU_MATR_GENE of older decks). With ``STOCKAGE='DIAG'``
        only a diagonal array is taken: code_aster stores no other term."""

        what = self.name or "matrix"
        values = replaced_values(self.matrix, values, what)
        if self.numbering.storage == "DIAG" and np.any(values - np.diag(np.diag(values))):
            raise DeckRuntimeError(
                f"{what}.fromNumpy: off-diagonal values for a matrix stored 'DIAG'"
            )
        self.matrix = values


@dataclass(eq=False)
class ComplexGeneralizedMatrix(GeneralizedMatrix):
    """A complex generalized matrix (``matr_asse_gene_c``): COMB_MATR_ASSE
    COMB_C of generalized matrices, ASSE_MATR_GENE RIGI_GENE_C (hysteretic
    stiffness K (1 + iη)); ``matrix`` is a complex dense array."""

    aster_types = ("matr_asse_gene_c", "matr_asse_gene")


@dataclass(eq=False)
class GeneralizedVector(Concept):
    """A projected vector Φᵀ f (``TYPE_VECT='FORC'``) or the generalized
    coordinates q of a displacement/velocity/acceleration field
    (``'DEPL'``/``'VITE'``/``'ACCE'``): the Euclidean least-squares fit
    q = (ΦᵀΦ)⁻¹ Φᵀ u, as code_aster's PROJ_VECT_BASE computes it (exact when
    u lies in the span of the basis)."""

    aster_types = ("vect_asse_gene",)
    deck_methods = frozenset({"getName", "EXTR_VECT_GENE", "RECU_VECT_GENE"})

    numbering: GeneralizedNumbering
    values: np.ndarray
    kind: str = "FORC"  # FORC, DEPL, VITE, ACCE
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def basis(self) -> ModeResult:
        return self.numbering.basis

    def EXTR_VECT_GENE(self) -> np.ndarray:  # noqa: N802 - code_aster's name
        """The generalized values as a numpy array (a copy)."""

        return np.array(self.values, copy=True)

    def RECU_VECT_GENE(self, values) -> None:  # noqa: N802
        """Replace the values by a deck's sequence of the same length; a real
        vector takes real values only, as code_aster's setValues."""

        what = f"{self.name or 'vector'}.RECU_VECT_GENE"
        current = np.asarray(self.values)
        try:
            array = np.asarray(values)
        except (TypeError, ValueError):
            raise DeckRuntimeError(f"{what} takes a sequence of numbers") from None
        if array.shape != current.shape:
            raise DeckRuntimeError(f"{what}: {array.size} values for a vector of {current.size}")
        if array.dtype.kind not in "biufc" or (
            array.dtype.kind == "c" and current.dtype.kind != "c"
        ):
            raise DeckRuntimeError(f"{what}: {array.dtype} values for a real vector")
        if not np.all(np.isfinite(array)):
            raise DeckRuntimeError(f"{what}: the values hold non-finite numbers")
        self.values = np.array(array, dtype=current.dtype, copy=True)


@dataclass(eq=False)
class BucklingModes(ModeResult):
    """``CALC_MODES`` with ``TYPE_RESU='MODE_FLAMB'`` or ``'GENERAL'``: the
    pencil (A, B) solved as (A + λ B) φ = 0, code_aster's sign convention.
    ``parameters['CHAR_CRIT']`` holds λ (for A = K, B = M it is -ω²);
    ``frequencies`` are zero."""

    aster_types = ("mode_flamb", "resultat_sdaster")


@dataclass(eq=False)
class ComplexModeResult(ModeResult):
    """``CALC_MODES`` with MATR_AMOR or a complex stiffness (a ``mode_meca_c``):
    modes of (λ² M + λ C + K) φ = 0, see :mod:`asterlite.modal.quadratic`.

    ``shapes`` are complex; ``eigenvalues`` holds λ per mode (Im(λ) > 0);
    ``frequencies`` = Im(λ)/2π (code_aster's FREQ); ``parameters`` has
    AMOR_REDUIT = -Re(λ)/|λ|, OMEGA2 = Im(λ)², MASS_GENE, AMOR_GENE and
    RIGI_GENE (code_aster's generalized parameters of complex vectors)."""

    aster_types = ("mode_meca_c", "mode_meca", "resultat_sdaster")

    eigenvalues: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=complex))

    @property
    def omega2(self) -> np.ndarray:
        return np.asarray(self.eigenvalues, dtype=complex).imag ** 2

    @property
    def damping_ratios(self) -> np.ndarray:
        lam = np.asarray(self.eigenvalues, dtype=complex)
        modulus = np.where(np.abs(lam) > 0, np.abs(lam), 1.0)
        return -lam.real / modulus

    def rescale(self, factors, norm: str | None = None) -> None:
        """Multiply each mode by its (complex) factor; generalized
        parameters are recomputed from the matrices when they are known."""
        factors = np.asarray(factors, dtype=complex)
        self.shapes = self.shapes * factors[None, :]
        if self.mass is not None and self.stiffness is not None:
            from asterlite.modal.quadratic import generalized_parameters

            damping = self.damping.matrix if self.damping is not None else None
            gen = generalized_parameters(
                self.shapes, self.stiffness.matrix, damping, self.mass.matrix
            )
            self.parameters.update(gen)
            self.generalized_mass = gen["MASS_GENE"].copy()
            self.generalized_stiffness = gen["RIGI_GENE"].copy()
        else:
            scale = np.abs(factors) ** 2
            self.generalized_mass = self.generalized_mass * scale
            self.generalized_stiffness = self.generalized_stiffness * scale
            for key in ("MASS_GENE", "RIGI_GENE", "AMOR_GENE"):
                if key in self.parameters:
                    self.parameters[key] = np.asarray(self.parameters[key]) * scale
        if norm is not None:
            self.norm = norm

    def select(self, indices) -> ComplexModeResult:
        indices = np.asarray(indices, dtype=int)
        params = {}
        for key, value in self.parameters.items():
            value = np.asarray(value)
            params[key] = value[indices] if value.shape[:1] == (self.n_modes,) else value
        return dataclasses.replace(
            self,
            shapes=self.shapes[:, indices].copy(),
            frequencies=np.asarray(self.frequencies)[indices].copy(),
            generalized_mass=np.asarray(self.generalized_mass)[indices].copy(),
            generalized_stiffness=np.asarray(self.generalized_stiffness)[indices].copy(),
            parameters=params,
            mode_labels=[self.mode_labels[i] for i in indices] if self.mode_labels else [],
            eigenvalues=np.asarray(self.eigenvalues)[indices].copy(),
        )

    def shapes_at(self, nodes, components) -> np.ndarray:
        rows = self.numbering.dof_indices(nodes, components)
        out = np.zeros((len(rows), self.n_modes), dtype=complex)
        present = rows >= 0
        out[present] = self.shapes[rows[present], :]
        return out


@dataclass(eq=False)
class MultElasResult(Concept):
    """``MACRO_ELAS_MULT`` / ``CREA_RESU(TYPE_RESU='MULT_ELAS')``: one static
    displacement field per load case.

    ``fields`` is (n_dofs, n_cases) on ``numbering``'s DOFs (column k is the
    DEPL of case ``case_names[k]``, NUME_ORDRE k + 1). ``loads`` keeps each
    case's assembled load vector (n_dofs, n_cases) when it is known (the
    static correction of DYNA_VIBRA / MODE_CORR reads it)."""

    aster_types = ("mult_elas", "resultat_sdaster")

    numbering: DofNumbering
    fields: np.ndarray
    case_names: list[str] = field(default_factory=list)
    loads: np.ndarray | None = None
    stiffness: AssembledMatrix | None = None
    # what CREA_RESU/AFFE gave for post-processing (CALC_CHAMP): MODELE,
    # CHAM_MATER, CARA_ELEM and the CHARGE list
    model: Any = None
    materials: Any = None
    characteristics: Any = None
    charges: list = field(default_factory=list)

    @property
    def n_cases(self) -> int:
        return self.fields.shape[1]

    @property
    def shapes(self) -> np.ndarray:
        """The fields as a modal-basis-like matrix (MODE_INTF of DEFI_BASE_MODALE)."""
        return self.fields


@dataclass(eq=False)
class GeneralizedModes(Concept):
    """``CALC_MODES`` on generalized matrices (a ``mode_gene``): eigenvectors
    ``vectors`` (n_gene, n_modes) in the generalized coordinates of
    ``numbering`` (the NUME_DDL_GENE of the projected matrices), with
    ``frequencies`` and ``parameters`` as a ModeResult. :meth:`physical` gives
    the restored modes Φ q on the physical DOFs of the projection basis
    (what REST_GENE_PHYS returns)."""

    aster_types = ("mode_gene", "resultat_sdaster")

    numbering: GeneralizedNumbering
    vectors: np.ndarray
    frequencies: np.ndarray
    generalized_mass: np.ndarray
    generalized_stiffness: np.ndarray
    parameters: dict[str, np.ndarray] = field(default_factory=dict)
    norm: str = "SANS_CMP: LAGR"

    @property
    def n_modes(self) -> int:
        return self.vectors.shape[1]

    @property
    def mode_numbers(self) -> np.ndarray:
        numbers = self.parameters.get("NUME_MODE")
        return np.arange(1, self.n_modes + 1) if numbers is None else np.asarray(numbers)

    def select(self, indices) -> GeneralizedModes:
        """The modes at 0-based ``indices`` (EXTR_MODE), NUME_MODE kept."""
        idx = np.asarray(indices, dtype=int)
        return GeneralizedModes(
            numbering=self.numbering,
            vectors=self.vectors[:, idx].copy(),
            frequencies=np.asarray(self.frequencies)[idx].copy(),
            generalized_mass=np.asarray(self.generalized_mass)[idx].copy(),
            generalized_stiffness=np.asarray(self.generalized_stiffness)[idx].copy(),
            parameters={
                k: (np.asarray(v)[idx] if np.ndim(v) == 1 else v)
                for k, v in self.parameters.items()
            },
            norm=self.norm,
        )

    @staticmethod
    def concatenate(parts) -> GeneralizedModes:
        """The modes of several mode_gene on one numbering, one after the other."""
        keys = set.intersection(*(set(p.parameters) for p in parts))
        return GeneralizedModes(
            numbering=parts[0].numbering,
            vectors=np.hstack([p.vectors for p in parts]),
            frequencies=np.concatenate([p.frequencies for p in parts]),
            generalized_mass=np.concatenate([p.generalized_mass for p in parts]),
            generalized_stiffness=np.concatenate([p.generalized_stiffness for p in parts]),
            parameters={
                k: np.concatenate([np.asarray(p.parameters[k]) for p in parts]) for k in keys
            },
            norm=parts[0].norm,
        )

    def physical(self, indices=None, basis=None) -> ModeResult:
        """The modes restored on the physical basis (REST_GENE_PHYS): Φ q with
        Φ the projection basis, or ``basis`` (MODE_MECA) when given; 0-based
        ``indices`` select modes (default: all)."""
        basis = self.numbering.basis if basis is None else basis
        idx = np.arange(self.n_modes) if indices is None else np.asarray(indices, dtype=int)
        shapes = basis.shapes[:, : self.vectors.shape[0]] @ self.vectors[:, idx]
        params = {k: np.asarray(v)[idx] for k, v in self.parameters.items() if np.ndim(v) == 1}
        return ModeResult(
            numbering=basis.numbering,
            shapes=shapes,
            frequencies=np.asarray(self.frequencies)[idx].copy(),
            generalized_mass=np.asarray(self.generalized_mass)[idx].copy(),
            generalized_stiffness=np.asarray(self.generalized_stiffness)[idx].copy(),
            mass=basis.mass,
            stiffness=basis.stiffness,
            kind="dynamic",
            parameters=params,
            norm=self.norm,
        )


@dataclass(eq=False)
class FieldOnElements(Concept):
    """A field by element (``cham_elem``), as CREA_CHAMP EXTR takes it from a
    result's ELNO/ELGA field (:class:`~asterlite.concepts.assembly.ElementField`).

    ``values`` is (n_cells, n_points, n_components) on the mesh cells
    ``cells``; points are the cell's nodes in connectivity order (ELNO) or its
    Gauss points (ELGA). ``field_type`` is CREA_CHAMP's TYPE_CHAM
    (``ELNO_SIEF_R``) and ``field_name`` the result's field (``SIPO_ELNO``)."""

    aster_types = ("cham_elem", "cham_gd_sdaster")

    mesh: Any
    field_type: str
    field_name: str
    cells: np.ndarray
    components: tuple[str, ...]
    values: np.ndarray

    def value(self, cell: int, point: int, component: str) -> float:
        """Value at one cell (mesh index), point (0-based) and component."""
        rows = np.flatnonzero(np.asarray(self.cells) == int(cell))
        if rows.size == 0:
            raise KeyError(f"cell {self.mesh.cell_names[int(cell)]} is not in the field")
        if component not in self.components:
            raise KeyError(f"component {component} is not in the field")
        return float(self.values[rows[0], point, self.components.index(component)])

    def node_value(self, cell: int, node: int, component: str) -> float:
        """ELNO value of ``component`` at mesh node ``node`` of mesh cell ``cell``."""
        nodes = list(np.asarray(self.mesh.cell_nodes[int(cell)], dtype=int))
        if int(node) not in nodes:
            raise KeyError(
                f"node {self.mesh.node_names[int(node)]} is not a node of cell "
                f"{self.mesh.cell_names[int(cell)]}"
            )
        return self.value(cell, nodes.index(int(node)), component)
