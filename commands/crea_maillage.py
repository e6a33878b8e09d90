"""CREA_MAILLAGE: a new mesh from an existing one (CREA_POI1: point cells on
nodes; LINE_QUAD: linear cells made quadratic; MODI_MAILLE OPTION='SEG3_4')."""

from __future__ import annotations

import numpy as np

from asterlite.errors import CommandError, ValidationError
from asterlite.fem.mesh_degree import (
    DuplicateNodeName,
    MeshDegreeError,
    line_quad,
    seg3_to_seg4,
)
from asterlite.fem.selection import as_scalar, select_cells, select_nodes
from asterlite.legacy.v15 import computes


def _cells(ctx, occ, mesh) -> np.ndarray:
    """The cells of an occurrence: TOUT='OUI' (or nothing else given) is every cell."""
    if occ.get("TOUT") == "OUI" or not (occ.get("GROUP_MA") or occ.get("MAILLE")):
        return np.arange(mesh.n_cells)
    return select_cells(ctx, occ, mesh)


def _new_node_names(ctx, occ) -> tuple[str, int] | None:
    """How LINE_QUAD names its nodes: code_aster 15 and older by a prefix
    (PREF_NOEUD, PREF_NUME), 17 by number (and takes no prefix)."""
    if computes(ctx.session, "LINE_QUAD_NODES_NAMED_BY_PREFIX"):
        return occ.get("PREF_NOEUD", "NS"), occ.get("PREF_NUME", 1)
    for key in ("PREF_NOEUD", "PREF_NUME"):
        if key in occ:
            path, location = occ.where(key)
            raise ValidationError(
                "a keyword of code_aster 15 and older: code_aster 17 numbers the new nodes",
                location,
                path,
            )
    return None


def _change_degree(ctx, kw, mesh) -> None:
    for occ in kw.factor("LINE_QUAD"):
        try:
            added = line_quad(mesh, _cells(ctx, occ, mesh), _new_node_names(ctx, occ))
        except DuplicateNodeName as error:
            raise CommandError(str(error), None, "CREA_MAILLAGE/LINE_QUAD") from None
        ctx.log(f"LINE_QUAD: {added} nodes added")
    for occ in kw.factor("MODI_MAILLE"):
        option = occ["OPTION"]
        if option != "SEG3_4":
            ctx.unsupported(f"MODI_MAILLE OPTION={option!r}", "OPTION", occ)
        try:
            added = seg3_to_seg4(mesh, _cells(ctx, occ, mesh))
        except MeshDegreeError as error:
            ctx.error(str(error), "OPTION", occ)
        ctx.log(f"MODI_MAILLE SEG3_4: {added} nodes added")


def run(ctx, kw):
    mesh = kw["MAILLAGE"].copy()
    _change_degree(ctx, kw, mesh)
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
