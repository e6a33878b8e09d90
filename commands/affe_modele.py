"""AFFE_MODELE: assign a mechanical modelisation to cells (or nodes)."""

from __future__ import annotations

from asterlite.concepts.assembly import Model
from asterlite.fem.dofs import MODELISATION_CELLS
from asterlite.fem.selection import as_tuple, select_cells, select_nodes


def run(ctx, kw):
    mesh = kw["MAILLAGE"]
    model = Model(mesh=mesh)
    for occ in kw.factor("AFFE"):
        phenomenon = occ.get("PHENOMENE", "MECANIQUE")
        if phenomenon != "MECANIQUE":
            ctx.unsupported(f"AFFE_MODELE PHENOMENE={phenomenon!r}", "PHENOMENE", occ)
        for modelisation in as_tuple(occ.get("MODELISATION")):
            if modelisation not in MODELISATION_CELLS:
                ctx.unsupported(f"modelisation {modelisation!r}", "MODELISATION", occ)
            accepted = MODELISATION_CELLS[modelisation]
            if occ.get("GROUP_NO") or occ.get("NOEUD"):
                # nodal discrete elements (old syntax): carried by the nodes themselves
                if "POI1" not in accepted:
                    ctx.error(f"{modelisation} cannot be assigned to nodes", "GROUP_NO", occ)
                for node in select_nodes(ctx, occ, mesh):
                    model.node_modelisation[int(node)] = modelisation
                continue
            cells = select_cells(ctx, occ, mesh)
            for cell in cells:
                # code_aster skips cells the modelisation has no element for
                if mesh.cell_types[cell] in accepted:
                    model.cell_modelisation[int(cell)] = modelisation
    if not model.cell_modelisation and not model.node_modelisation:
        ctx.error("no element was assigned: check the cell types and MODELISATION", "AFFE", kw)
    if any(m == "AXIS" for m in model.cell_modelisation.values()):
        from asterlite.fem.jacobian_check import negative_radius_nodes

        negative = negative_radius_nodes(model)
        if negative:
            node, cell = negative[0]
            ctx.error(
                f"AXIS cell {mesh.cell_names[cell]} has node {mesh.node_names[node]} at "
                f"x = {mesh.coords[node, 0]:g} < 0 (x is the radius): {len(negative)} such nodes",
                "AFFE",
                kw,
            )
    if kw.get("VERI_JACOBIEN", "OUI") == "OUI":
        from asterlite.fem.jacobian_check import folded_cells

        folded = folded_cells(model)
        if folded:
            names = ", ".join(mesh.cell_names[c] for c in folded[:10])
            ctx.log(f"warning: the Jacobian changes sign inside {len(folded)} cells ({names})")
    counts: dict[str, int] = {}
    for m in model.cell_modelisation.values():
        counts[m] = counts.get(m, 0) + 1
    ctx.log("model: " + ", ".join(f"{n} {m} elements" for m, n in sorted(counts.items())))
    return model
