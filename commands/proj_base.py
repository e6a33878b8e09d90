"""PROJ_BASE: project several matrices and vectors on a basis at once; each
result is bound to its CO(...) name."""

from __future__ import annotations

import numpy as np
from asterlite.commands import proj_matr_base, proj_vect_base

from asterlite.concepts.modes import GeneralizedNumbering
from asterlite.concepts.transient import TranGene
from asterlite.modal.fields import FieldError, field_stack
from asterlite.modal.projection import ProjectionError, fit_coordinates, project_force
from asterlite.modal.renumber import transfer


def _resu_gene(ctx, occ, basis):
    """A tran_gene holding the generalized coordinates of a physical result's
    fields DEPL, VITE and ACCE at each instant: a least-squares fit for
    kinematic fields, or the generalized force (TYPE_VECT='FORC')."""

    result = occ["RESU"]
    as_force = occ["TYPE_VECT"] == "FORC"
    stacks = {}
    for name in ("DEPL", "VITE", "ACCE"):
        try:
            numbering, values, access = field_stack(result, name)
        except FieldError:
            continue
        physical = transfer(values.T, numbering, basis.numbering)
        try:
            if as_force:
                stacks[name] = project_force(basis.shapes, physical).T
            else:
                stacks[name] = fit_coordinates(basis.shapes, physical).T
        except ProjectionError as exc:
            ctx.error(str(exc), "BASE", occ)
        times, order = access.get("INST"), access["NUME_ORDRE"]
    if not stacks:
        ctx.error("the result has no DEPL, VITE or ACCE field", "RESU", occ)
    shape = next(iter(stacks.values())).shape
    zeros = np.zeros(shape)
    return TranGene(
        basis=basis,
        times=np.asarray(times if times is not None else np.zeros(shape[0]), dtype=float),
        order=np.asarray(order),
        depl=stacks.get("DEPL", zeros),
        vite=stacks.get("VITE", zeros),
        acce=stacks.get("ACCE", zeros),
    )


def generalized_numbering(ctx, kw, basis) -> GeneralizedNumbering:
    """NUME_DDL_GENE: an existing numbering is used as it is (its own storage,
    as code_aster does); CO("NAME") or nothing builds one on the basis with
    STOCKAGE (bound to the name when given)."""
    storage = kw.get("STOCKAGE", "PLEIN")  # code_aster too ignores it for an existing one
    given = kw.get("NUME_DDL_GENE")
    if isinstance(given, GeneralizedNumbering):
        return given
    numbering = GeneralizedNumbering(basis=basis, storage=storage)
    if given is not None:
        ctx.bind(given, numbering)
    return numbering


def run(ctx, kw):
    basis = kw["BASE"]
    if kw.get("NB_VECT") is not None and int(kw["NB_VECT"]) < basis.n_modes:
        basis = basis.select(np.arange(int(kw["NB_VECT"])))
    numbering_gene = generalized_numbering(ctx, kw, basis)
    for occ in kw.factor("MATR_ASSE_GENE"):
        if occ.get("MATR_ASSE") is None:  # a generalized matrix on a mode_gene
            result = proj_matr_base.project_generalized(
                ctx, occ, basis, numbering_gene, occ["MATR_ASSE_GENE"]
            )
        else:
            result = proj_matr_base.project(ctx, occ, basis, numbering_gene, occ["MATR_ASSE"])
        ctx.bind(occ["MATRICE"], result)
    for occ in kw.factor("VECT_ASSE_GENE"):
        type_vect = occ.get("TYPE_VECT", "FORC")
        if occ.get("VECT_ASSE") is None:  # a generalized vector on a mode_gene
            result = proj_vect_base.project_generalized(
                ctx, occ, basis, numbering_gene, occ["VECT_ASSE_GENE"], type_vect
            )
        else:
            result = proj_vect_base.project(
                ctx, occ, basis, numbering_gene, occ["VECT_ASSE"], type_vect
            )
        ctx.bind(occ["VECTEUR"], result)
    for occ in kw.factor("RESU_GENE"):
        ctx.bind(occ["RESULTAT"], _resu_gene(ctx, occ, basis))
    return None
