"""MACR_ELEM_DYNA: a substructure reduced on its classical basis.

The macro-element keeps the basis, its interfaces and the projections
Φᵀ K Φ, Φᵀ M Φ (Φᵀ C Φ with MATR_AMOR) of the substructure's matrices:
those of the basis's modes unless MATR_RIGI / MATR_MASS are given.
AMOR_REDUIT gives instead a diagonal generalized damping on the basis's
dynamic modes, c_ii = 4π f_i ξ_i m_i (code_aster's calamo: the last value
stands for the modes it does not reach, the static modes get none).
MODELE_MESURE replaces the projections by measured modal data: diagonal
mass m_i, stiffness (2π f_i)² m_i and damping 2 ξ_i √(k_i m_i), one value
per vector of the basis (op0081)."""

from __future__ import annotations

import math

import numpy as np

from asterlite.concepts.substructure import MacroElement, ReductionBasis
from asterlite.modal.projection import project_matrix
from asterlite.modal.renumber import same_dofs

# the macro-element's physical nodes (GROUP_NO / SANS_GROUP_NO: its image in a
# finite-element model), impedances and load cases are not computed here
_REFUSED = (
    "MACR_ELEM_DYNA",
    "SANS_GROUP_NO",
    "GROUP_NO",
    "MATR_IMPE",
    "MATR_IMPE_RIGI",
    "MATR_IMPE_MASS",
    "MATR_IMPE_AMOR",
    "CAS_CHARGE",
)


def run(ctx, kw):
    for keyword in _REFUSED:
        if keyword in kw:
            ctx.unsupported(f"MACR_ELEM_DYNA {keyword}", keyword, kw)
    basis = kw["BASE_MODALE"]
    if not isinstance(basis, ReductionBasis) or basis.interfaces is None:
        ctx.unsupported(
            "MACR_ELEM_DYNA on a basis without interfaces (only DEFI_BASE_MODALE CLASSIQUE)",
            "BASE_MODALE",
            kw,
        )
    if kw.factor("MODELE_MESURE"):
        matrices = measured_matrices(ctx, kw.factor("MODELE_MESURE")[0], basis.n_modes)
    else:
        matrices = projected_matrices(ctx, kw, basis)
    ctx.log(f"macro-element: {basis.n_modes} generalized DOFs")
    return MacroElement(
        basis=basis,
        interfaces=basis.interfaces,
        stiffness=matrices["MATR_RIGI"],
        mass=matrices["MATR_MASS"],
        damping=matrices.get("MATR_AMOR"),
    )


def projected_matrices(ctx, kw, basis) -> dict[str, np.ndarray]:
    """Φᵀ A Φ of the substructure's matrices; the damping from MATR_AMOR,
    else from AMOR_REDUIT, else none."""
    matrices = {}
    for keyword, default in (
        ("MATR_RIGI", basis.stiffness),
        ("MATR_MASS", basis.mass),
        ("MATR_AMOR", None),
    ):
        matrix = kw.get(keyword) or default
        if matrix is None:
            if keyword != "MATR_AMOR":
                ctx.error(f"the basis does not know its {keyword}; give it", keyword, kw)
            continue
        if not same_dofs(matrix.numbering, basis.numbering):
            ctx.error(f"{keyword} and the basis use different numberings", keyword, kw)
        matrices[keyword] = project_matrix(basis.shapes, matrix.matrix)
    if kw.get("AMOR_REDUIT") is not None:
        matrices["MATR_AMOR"] = reduced_damping(ctx, kw, basis)
    return matrices


def dynamic_modes(basis) -> np.ndarray:
    """Indices of the basis's eigenmodes (its static modes excluded)."""
    kinds = basis.parameters.get("TYPE_MODE")
    if kinds is None:
        return np.arange(basis.n_modes)
    return np.flatnonzero(np.asarray(kinds, dtype=object) != "MODE_STA")


def reduced_damping(ctx, kw, basis) -> np.ndarray:
    """Diagonal generalized damping 4π f_i ξ_i m_i on the dynamic modes."""
    ratios = np.atleast_1d(np.asarray(kw["AMOR_REDUIT"], dtype=float))
    modes = dynamic_modes(basis)
    if ratios.size > modes.size:
        ctx.log(
            f"warning: AMOR_REDUIT gives {ratios.size} values for {modes.size} dynamic "
            f"modes: the first {modes.size} are used"
        )
    elif ratios.size < modes.size:
        ctx.log(
            f"warning: AMOR_REDUIT gives {ratios.size} values for {modes.size} dynamic "
            f"modes: the last one stands for the {modes.size - ratios.size} others"
        )
    per_mode = np.concatenate([ratios, np.full(max(0, modes.size - ratios.size), ratios[-1])])
    frequencies = np.asarray(basis.frequencies, dtype=float)[modes]
    masses = np.asarray(basis.generalized_mass, dtype=float)[modes]
    damping = np.zeros((basis.n_modes, basis.n_modes))
    damping[modes, modes] = 4.0 * math.pi * frequencies * per_mode[: modes.size] * masses
    return damping


def measured_matrices(ctx, occ, n_vectors: int) -> dict[str, np.ndarray]:
    """MODELE_MESURE: diagonal mass m_i, stiffness (2π f_i)² m_i and, with
    AMOR_REDUIT, damping 2 ξ_i √(k_i m_i); one value per basis vector."""
    given = {}
    for keyword in ("MASS_GENE", "FREQ", "AMOR_REDUIT"):
        if occ.get(keyword) is None:
            continue
        values = np.atleast_1d(np.asarray(occ[keyword], dtype=float))
        if values.size != n_vectors:
            ctx.error(
                f"{keyword} gives {values.size} values for the {n_vectors} vectors of the basis",
                keyword,
                occ,
            )
        given[keyword] = values
    mass = given["MASS_GENE"]
    stiffness = (2.0 * math.pi * given["FREQ"]) ** 2 * mass
    matrices = {"MATR_MASS": np.diag(mass), "MATR_RIGI": np.diag(stiffness)}
    if "AMOR_REDUIT" in given:
        matrices["MATR_AMOR"] = np.diag(2.0 * given["AMOR_REDUIT"] * np.sqrt(stiffness * mass))
    return matrices
