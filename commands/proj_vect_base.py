"""PROJ_VECT_BASE: project a nodal vector on a modal basis.

TYPE_VECT='FORC' gives Φᵀ f; 'DEPL', 'VITE', 'ACCE' give the coordinates q
whose recombination Φ q best fits the field (least squares in the Euclidean
metric, as code_aster's operator does)."""

from __future__ import annotations

from asterlite.concepts.modes import GeneralizedVector
from asterlite.modal.projection import ProjectionError, fit_coordinates, project_force


def project(ctx, kw, basis, numbering_gene, field, type_vect):
    if field.numbering is not basis.numbering and field.numbering.dofs != basis.numbering.dofs:
        ctx.error("the vector and the basis use different DOF numberings", "VECT_ASSE", kw)
    if type_vect == "FORC":
        values = project_force(basis.shapes, field.values)
    else:
        try:
            values = fit_coordinates(basis.shapes, field.values)
        except ProjectionError as exc:
            ctx.error(str(exc), "BASE", kw)
    return GeneralizedVector(numbering=numbering_gene, values=values, kind=type_vect)


def run(ctx, kw):
    numbering_gene = kw["NUME_DDL_GENE"]
    basis = kw.get("BASE") or numbering_gene.basis
    if kw.get("VECT_ASSE_GENE") is not None:
        ctx.unsupported("PROJ_VECT_BASE of a generalized vector", "VECT_ASSE_GENE", kw)
    return project(ctx, kw, basis, numbering_gene, kw["VECT_ASSE"], kw.get("TYPE_VECT", "FORC"))
