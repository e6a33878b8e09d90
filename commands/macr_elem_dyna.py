"""MACR_ELEM_DYNA: a substructure reduced on its classical basis.

The macro-element keeps the basis, its interfaces and the projections
Φᵀ K Φ, Φᵀ M Φ (Φᵀ C Φ with MATR_AMOR) of the substructure's matrices:
those of the basis's modes unless MATR_RIGI / MATR_MASS are given."""

from __future__ import annotations

from asterlite.concepts.substructure import MacroElement, ReductionBasis
from asterlite.modal.projection import project_matrix
from asterlite.modal.renumber import same_dofs

_REFUSED = (
    "MACR_ELEM_DYNA",
    "AMOR_REDUIT",
    "SANS_GROUP_NO",
    "GROUP_NO",
    "MATR_IMPE",
    "MATR_IMPE_RIGI",
    "MATR_IMPE_MASS",
    "MATR_IMPE_AMOR",
    "MODELE_MESURE",
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
    ctx.log(f"macro-element: {basis.n_modes} generalized DOFs")
    return MacroElement(
        basis=basis,
        interfaces=basis.interfaces,
        stiffness=matrices["MATR_RIGI"],
        mass=matrices["MATR_MASS"],
        damping=matrices.get("MATR_AMOR"),
    )
