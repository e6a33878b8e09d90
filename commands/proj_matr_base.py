"""PROJ_MATR_BASE: Φᵀ A Φ on a modal basis."""

from __future__ import annotations

from asterlite.concepts.modes import GeneralizedMatrix
from asterlite.modal.projection import project_matrix

_KIND = {"RIGI": "RIGI", "MASS": "MASS", "AMOR": "AMOR"}


def project(ctx, kw, basis, numbering_gene, matrix):
    if matrix.numbering is not basis.numbering and matrix.numbering.dofs != basis.numbering.dofs:
        ctx.error("the matrix and the basis use different DOF numberings", "MATR_ASSE", kw)
    values = project_matrix(basis.shapes, matrix.matrix, numbering_gene.storage)
    return GeneralizedMatrix(
        numbering=numbering_gene, matrix=values, kind=_KIND.get(matrix.kind, "RIGI")
    )


def run(ctx, kw):
    numbering_gene = kw["NUME_DDL_GENE"]
    basis = kw.get("BASE") or numbering_gene.basis
    if kw.get("MATR_ASSE_GENE") is not None:
        ctx.unsupported("PROJ_MATR_BASE of a generalized matrix", "MATR_ASSE_GENE", kw)
    return project(ctx, kw, basis, numbering_gene, kw["MATR_ASSE"])
