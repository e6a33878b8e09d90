"""Turn TOUT / GROUP_MA / MAILLE / GROUP_NO / NOEUD keywords into index arrays.

Errors go through ``ctx.error`` so they carry the deck line and keyword path.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.mesh import Mesh
from asterlite.errors import missing_name


def as_scalar(value):
    """The single value of a keyword a catalogue may hand over as a 1-tuple."""
    if isinstance(value, (list, tuple)):
        return value[0] if len(value) == 1 else value
    return value


def as_tuple(value) -> tuple:
    if value is None:
        return ()
    if isinstance(value, (list, tuple)):
        return tuple(value)
    return (value,)


def _unique(indices) -> np.ndarray:
    """Distinct indices in first-seen order."""
    seen: dict[int, None] = {}
    for i in indices:
        seen.setdefault(int(i), None)
    return np.fromiter(seen, dtype=int, count=len(seen))


def cell_group_members(ctx, kw, mesh: Mesh, keyword: str = "GROUP_MA") -> list[int]:
    out: list[int] = []
    for name in as_tuple(kw.get(keyword)):
        if name not in mesh.cell_groups:
            ctx.error(missing_name("cell group", name, mesh.cell_groups), keyword, kw)
        out.extend(mesh.cell_groups[name].tolist())
    return out


def node_group_members(ctx, kw, mesh: Mesh, keyword: str = "GROUP_NO") -> list[int]:
    out: list[int] = []
    for name in as_tuple(kw.get(keyword)):
        if name not in mesh.node_groups:
            ctx.error(missing_name("node group", name, mesh.node_groups), keyword, kw)
        out.extend(mesh.node_groups[name].tolist())
    return out


def named_cells(ctx, kw, mesh: Mesh, keyword: str = "MAILLE") -> list[int]:
    out = []
    for name in as_tuple(kw.get(keyword)):
        index = mesh.find_cell(name)
        if index is None:
            ctx.error(f"the mesh has no cell {name!r}", keyword, kw)
        out.append(index)
    return out


def named_nodes(ctx, kw, mesh: Mesh, keyword: str = "NOEUD") -> list[int]:
    out = []
    for name in as_tuple(kw.get(keyword)):
        index = mesh.find_node(name)
        if index is None:
            ctx.error(f"the mesh has no node {name!r}", keyword, kw)
        out.append(index)
    return out


def select_cells(ctx, kw, mesh: Mesh, all_cells=None) -> np.ndarray:
    """Cells named by TOUT='OUI' (``all_cells`` or every cell), GROUP_MA, MAILLE."""
    if kw.get("TOUT") == "OUI":
        return np.arange(mesh.n_cells) if all_cells is None else np.asarray(all_cells, dtype=int)
    return _unique(cell_group_members(ctx, kw, mesh) + named_cells(ctx, kw, mesh))


def select_nodes(ctx, kw, mesh: Mesh, all_nodes=None) -> np.ndarray:
    """Nodes named by TOUT='OUI', GROUP_NO, NOEUD, and the nodes of GROUP_MA / MAILLE."""
    if kw.get("TOUT") == "OUI":
        return np.arange(mesh.n_nodes) if all_nodes is None else np.asarray(all_nodes, dtype=int)
    nodes = node_group_members(ctx, kw, mesh) + named_nodes(ctx, kw, mesh)
    cells = cell_group_members(ctx, kw, mesh) + named_cells(ctx, kw, mesh)
    if cells:
        nodes += mesh.nodes_of_cells(cells).tolist()
    return _unique(nodes)
