"""AFFE_MATERIAU: assign materials to cells (TOUT / GROUP_MA; last one wins)."""

from __future__ import annotations

from asterlite.concepts.assembly import MaterialField
from asterlite.fem.selection import as_tuple, select_cells


def run(ctx, kw):
    model = kw.get("MODELE")
    mesh = kw.get("MAILLAGE") or (model.mesh if model is not None else None)
    if model is not None and kw.get("MAILLAGE") is not None and model.mesh is not mesh:
        ctx.error("MODELE is built on another mesh than MAILLAGE", "MODELE", kw)
    if kw.get("CHAM_MATER") is not None:
        ctx.unsupported("AFFE_MATERIAU CHAM_MATER (copy of a material field)", "CHAM_MATER", kw)
    if kw.factor("AFFE_VARC"):
        ctx.unsupported("AFFE_MATERIAU AFFE_VARC (command variables)", "AFFE_VARC", kw)
    field = MaterialField(mesh=mesh)
    for occ in kw.factor("AFFE"):
        materials = as_tuple(occ["MATER"])
        if len(materials) > 1:
            ctx.unsupported("several materials in one AFFE occurrence (multifibre)", "MATER", occ)
        for cell in select_cells(ctx, occ, mesh):
            field.cell_material[int(cell)] = materials[0]
    ctx.log(f"material field: {len(field.cell_material)} cells")
    return field
