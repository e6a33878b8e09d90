"""AFFE_MATERIAU: assign materials to cells (TOUT / GROUP_MA; last one wins),
and multifibre behaviours (AFFE_COMPOR). Several materials in one AFFE
occurrence are code_aster's way of giving multifibre beams the materials of
their fibre groups: asterlite accepts them on cells that receive a
multifibre behaviour, whose groups take their materials there."""

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
    several = []
    for occ in kw.factor("AFFE"):
        materials = as_tuple(occ["MATER"])
        cells = select_cells(ctx, occ, mesh)
        if len(materials) > 1:
            several.append((occ, cells))
        for cell in cells:
            field.cell_material[int(cell)] = materials[0]
            field.cell_materials[int(cell)] = tuple(materials)
    for occ in kw.factor("AFFE_COMPOR"):
        for cell in select_cells(ctx, occ, mesh):
            field.cell_behaviour[int(cell)] = occ["COMPOR"]
    for occ, cells in several:
        if any(int(c) not in field.cell_behaviour for c in cells):
            ctx.unsupported(
                "several materials in one AFFE occurrence on cells without a multifibre "
                "behaviour (AFFE_COMPOR)",
                "MATER",
                occ,
            )
    ctx.log(f"material field: {len(field.cell_material)} cells")
    return field
