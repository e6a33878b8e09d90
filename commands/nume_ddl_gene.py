"""NUME_DDL_GENE: the generalized unknowns of a modal basis, or of a
generalized model (the substructures' unknowns and their interface
relations, asterlite.concepts.substructure)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import GeneralizedNumbering
from asterlite.concepts.substructure import SubstructuredNumbering


def run(ctx, kw):
    basis = kw.get("BASE")
    if basis is None:
        return _on_model(ctx, kw)
    return GeneralizedNumbering(basis=basis, storage=kw.get("STOCKAGE", "PLEIN"))


def _on_model(ctx, kw):
    return numbering_of_model(
        ctx, kw, kw["MODELE_GENE"], kw.get("METHODE", "CLASSIQUE"), kw.get("STOCKAGE", "LIGN_CIEL")
    )


def numbering_of_model(ctx, kw, model, method, storage):
    """The generalized numbering of a model (also ASSE_ELEM_SSD's)."""

    from asterlite.substructure.coupling import CouplingError, constraint_rows

    if method == "INITIAL":
        ctx.unsupported("NUME_DDL_GENE METHODE='INITIAL'", "METHODE", kw)
    sizes = [sub.macro.n_modes for sub in model.substructures]
    offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(int)
    try:
        constraints = constraint_rows(model, offsets)
    except CouplingError as exc:
        ctx.error(str(exc), "MODELE_GENE", kw)
    ctx.log(
        f"generalized numbering: {offsets[-1]} unknowns, {constraints.shape[0]} interface"
        f" relations ({'eliminated' if method == 'ELIMINE' else 'dualised in code_aster'})"
    )
    return SubstructuredNumbering(
        basis=None,
        storage=storage,
        model=model,
        offsets=offsets,
        constraints=constraints,
        method=method,
    )
