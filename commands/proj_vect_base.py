"""PROJ_VECT_BASE: project a nodal vector on a modal basis.

TYPE_VECT='FORC' gives Φᵀ f; 'DEPL', 'VITE', 'ACCE' give the coordinates q
whose recombination Φ q best fits the field (least squares in the Euclidean
metric, as code_aster's operator does)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import GeneralizedVector
from asterlite.modal.projection import ProjectionError, fit_coordinates, project_force


def on_numbering(ctx, kw, field, numbering) -> np.ndarray:
    """The field's values on another numbering of the same mesh (by node and
    component); a non-zero value on a DOF the numbering lacks is an error."""
    if field.numbering is numbering or field.numbering.dofs == numbering.dofs:
        return field.values
    if field.numbering.mesh is not numbering.mesh:
        ctx.error("the vector and the basis are on different meshes", "VECT_ASSE", kw)
    rows = numbering.dof_indices(field.numbering.dof_nodes, field.numbering.dof_components)
    lost = (rows < 0) & (field.values != 0.0)
    if np.any(lost):
        label = field.numbering.label(int(np.flatnonzero(lost)[0]))
        ctx.error(f"the basis has no DOF {label} where the vector is non-zero", "VECT_ASSE", kw)
    values = np.zeros(numbering.n_dofs)
    values[rows[rows >= 0]] = field.values[rows >= 0]
    return values


def project(ctx, kw, basis, numbering_gene, field, type_vect):
    values = on_numbering(ctx, kw, field, basis.numbering)
    if type_vect == "FORC":
        values = project_force(basis.shapes, values)
    else:
        try:
            values = fit_coordinates(basis.shapes, values)
        except ProjectionError as exc:
            ctx.error(str(exc), "BASE", kw)
    return GeneralizedVector(numbering=numbering_gene, values=values, kind=type_vect)


def project_generalized(ctx, kw, basis, numbering_gene, vector, type_vect):
    """A generalized vector on the generalized modes Q of the same numbering:
    Qᵀ f (FORC) or the least-squares coordinates (DEPL, VITE, ACCE)."""
    vectors = getattr(basis, "vectors", None)
    if vectors is None or basis.numbering is not vector.numbering:
        ctx.error(
            "BASE must be a mode_gene computed on the numbering of VECT_ASSE_GENE",
            "VECT_ASSE_GENE",
            kw,
        )
    values = np.asarray(vector.values, dtype=float)
    if type_vect == "FORC":
        values = project_force(vectors, values)
    else:
        try:
            values = fit_coordinates(vectors, values)
        except ProjectionError as exc:
            ctx.error(str(exc), "BASE", kw)
    return GeneralizedVector(numbering=numbering_gene, values=values, kind=type_vect)


def run(ctx, kw):
    numbering_gene = kw["NUME_DDL_GENE"]
    basis = kw.get("BASE") or numbering_gene.basis
    if kw.get("VECT_ASSE_GENE") is not None:
        return project_generalized(
            ctx, kw, basis, numbering_gene, kw["VECT_ASSE_GENE"], kw.get("TYPE_VECT", "FORC")
        )
    return project(ctx, kw, basis, numbering_gene, kw["VECT_ASSE"], kw.get("TYPE_VECT", "FORC"))
