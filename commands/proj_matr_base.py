"""PROJ_MATR_BASE: Φᵀ A Φ on a modal basis."""

from __future__ import annotations

from asterlite.concepts.modes import GeneralizedMatrix
from asterlite.modal.projection import project_matrix
from asterlite.modal.renumber import same_dofs, transfer

_KIND = {"RIGI": "RIGI", "MASS": "MASS", "AMOR": "AMOR"}


def project(ctx, kw, basis, numbering_gene, matrix):
    shapes = basis.shapes
    if not same_dofs(matrix.numbering, basis.numbering):
        # a matrix on another numbering of the mesh (e.g. one substructure's):
        # the basis vectors are restricted to its DOFs, by node and component
        if matrix.numbering.mesh is not basis.numbering.mesh:
            ctx.error("the matrix and the basis are on different meshes", "MATR_ASSE", kw)
        shapes = transfer(shapes, basis.numbering, matrix.numbering)
    values = project_matrix(shapes, matrix.matrix, numbering_gene.storage)
    return GeneralizedMatrix(
        numbering=numbering_gene, matrix=values, kind=_KIND.get(matrix.kind, "RIGI")
    )


def project_generalized(ctx, kw, basis, numbering_gene, matrix):
    """Qᵀ A Q of a generalized matrix on the generalized modes Q (a mode_gene
    computed from matrices on the same generalized numbering)."""
    vectors = getattr(basis, "vectors", None)
    if vectors is None or basis.numbering is not matrix.numbering:
        ctx.error(
            "BASE must be a mode_gene computed on the numbering of MATR_ASSE_GENE",
            "MATR_ASSE_GENE",
            kw,
        )
    values = project_matrix(vectors, matrix.matrix, numbering_gene.storage)
    return GeneralizedMatrix(numbering=numbering_gene, matrix=values, kind=matrix.kind)


def run(ctx, kw):
    numbering_gene = kw["NUME_DDL_GENE"]
    basis = kw.get("BASE") or numbering_gene.basis
    if kw.get("MATR_ASSE_GENE") is not None:
        return project_generalized(ctx, kw, basis, numbering_gene, kw["MATR_ASSE_GENE"])
    return project(ctx, kw, basis, numbering_gene, kw["MATR_ASSE"])
