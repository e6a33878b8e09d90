"""CREA_MAILLAGE: a new mesh from an existing one (CREA_POI1: point cells on nodes)."""

from __future__ import annotations

import numpy as np

from asterlite.fem.selection import select_nodes

_HANDLED = ("MAILLAGE", "CREA_POI1", "INFO", "TITRE")


def run(ctx, kw):
    for key, value in kw.items():
        if key not in _HANDLED and isinstance(value, list) and value:
            ctx.unsupported(f"CREA_MAILLAGE/{key}", key, kw)
    mesh = kw["MAILLAGE"].copy()
    for occ in kw.factor("CREA_POI1"):
        nodes = select_nodes(ctx, occ, mesh)
        names = []
        for node in nodes:
            # the new cell takes the node's name (made unique if a cell already has it)
            base = mesh.node_names[node]
            name, k = base, 1
            while name in mesh.cell_index or name in names:
                name, k = f"{base}_{k}", k + 1
            names.append(name)
        cells = mesh.add_cells(names, "POI1", [(int(n),) for n in nodes])
        group = occ.get("NOM_GROUP_MA")
        if group is not None:
            if group in mesh.cell_groups:
                ctx.error(f"the cell group {group!r} already exists", "NOM_GROUP_MA", occ)
            mesh.cell_groups[group] = np.asarray(cells, dtype=int)
    return mesh
