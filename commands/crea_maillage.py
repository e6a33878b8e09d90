"""CREA_MAILLAGE: a new mesh from an existing one (CREA_POI1: point cells on nodes)."""

from __future__ import annotations

import numpy as np

from asterlite.fem.selection import as_scalar, select_nodes


def run(ctx, kw):
    mesh = kw["MAILLAGE"].copy()
    for occ in kw.factor("CREA_POI1"):
        nodes = select_nodes(ctx, occ, mesh)
        cells, new_names, new_nodes = [], [], []
        for node in nodes:
            # cells are named after their node; a node given twice (several
            # occurrences) keeps its one POI1 cell, as in code_aster
            base = mesh.node_names[node]
            existing = mesh.cell_index.get(base)
            if existing is not None and mesh.cell_nodes[existing] == (int(node),):
                cells.append(existing)
                continue
            name, k = base, 1
            while name in mesh.cell_index or name in new_names:
                name, k = f"{base}_{k}", k + 1
            new_names.append(name)
            new_nodes.append((int(node),))
            cells.append(-len(new_names))  # placeholder, filled below
        created = mesh.add_cells(new_names, "POI1", new_nodes)
        cells = [c if c >= 0 else int(created[-c - 1]) for c in cells]
        group = as_scalar(occ.get("NOM_GROUP_MA"))
        if group is not None:
            if group in mesh.cell_groups:
                ctx.error(f"the cell group {group!r} already exists", "NOM_GROUP_MA", occ)
            mesh.cell_groups[group] = np.asarray(cells, dtype=int)
    return mesh
