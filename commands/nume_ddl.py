"""NUME_DDL: number the DOFs of a model and gather the kinematic relations of
the loads attached to the stiffness element matrices."""

from __future__ import annotations

from asterlite.concepts.assembly import DofNumbering
from asterlite.fem.assemble import build_numbering_dofs
from asterlite.fem.selection import as_tuple


def numbering_for(model, loads, characteristics=None, materials=None) -> DofNumbering:
    dofs = build_numbering_dofs(model.node_components())
    relations = []
    seen = set()
    for load in loads:
        if id(load) in seen:
            continue
        seen.add(id(load))
        relations.extend(load.relations)
    for cell in model.substructures.values():
        # external DOFs a superelement's CHAR_MACR_ELEM blocks (after the
        # loads' relations: their right-hand sides are zero)
        relations.extend(cell.blocked_relations())
    return DofNumbering(
        mesh=model.mesh,
        dofs=dofs,
        relations=relations,
        model=model,
        characteristics=characteristics,
        materials=materials,
    )


def run(ctx, kw):
    matrices = as_tuple(kw.get("MATR_RIGI"))
    characteristics = materials = None
    if matrices:
        model = matrices[0].model
        loads = [load for m in matrices for load in m.loads]
        characteristics = matrices[0].characteristics
        materials = getattr(matrices[0], "materials", None)
    else:
        model = kw.get("MODELE")
        if model is None:
            ctx.error("give MATR_RIGI or MODELE", None, kw)
        loads = list(as_tuple(kw.get("CHARGE")))
    numbering = numbering_for(model, loads, characteristics, materials)
    ctx.log(f"numbering: {numbering.n_dofs} DOFs, {len(numbering.relations)} relations")
    return numbering
