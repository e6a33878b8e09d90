"""NUME_DDL: number the DOFs of a model and gather the kinematic relations of
the loads attached to the stiffness element matrices."""

from __future__ import annotations

from asterlite.concepts.assembly import DofNumbering
from asterlite.fem.assemble import build_numbering_dofs
from asterlite.fem.selection import as_tuple


def numbering_for(model, loads) -> DofNumbering:
    dofs = build_numbering_dofs(model.node_components())
    relations = []
    seen = set()
    for load in loads:
        if id(load) in seen:
            continue
        seen.add(id(load))
        relations.extend(load.relations)
    return DofNumbering(mesh=model.mesh, dofs=dofs, relations=relations)


def run(ctx, kw):
    matrices = as_tuple(kw.get("MATR_RIGI"))
    if matrices:
        model = matrices[0].model
        loads = [load for m in matrices for load in m.loads]
    else:
        model = kw.get("MODELE")
        if model is None:
            ctx.error("give MATR_RIGI or MODELE", None, kw)
        loads = list(as_tuple(kw.get("CHARGE")))
    numbering = numbering_for(model, loads)
    ctx.log(f"numbering: {numbering.n_dofs} DOFs, {len(numbering.relations)} relations")
    return numbering
