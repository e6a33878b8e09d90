"""DEFI_GROUP: create (or destroy) node and cell groups of a mesh, in place."""

from __future__ import annotations

import numpy as np

from asterlite.fem.selection import (
    as_scalar,
    as_tuple,
    cell_group_members,
    named_cells,
    named_nodes,
    node_group_members,
)


def _combine(ctx, occ, table: dict, unknown: str) -> np.ndarray | None:
    """UNION / INTERSEC / DIFFE of existing groups (None when none is given)."""
    for op in ("UNION", "INTERSEC", "DIFFE"):
        names = as_tuple(occ.get(op))
        if not names:
            continue
        for n in names:
            if n not in table:
                ctx.error(f"the mesh has no {unknown} group {n!r}", op, occ)
        result = list(table[names[0]])
        for n in names[1:]:
            other = set(table[n].tolist())
            if op == "UNION":
                result += [i for i in table[n].tolist() if i not in set(result)]
            elif op == "INTERSEC":
                result = [i for i in result if i in other]
            else:
                result = [i for i in result if i not in other]
        return np.array(result, dtype=int)
    return None


def _store(ctx, occ, table: dict, name: str, members, kind: str) -> None:
    if name in table:
        ctx.error(f"the {kind} group {name!r} already exists", "NOM", occ)
    table[name] = np.asarray(members, dtype=int)


def _unique(values) -> list[int]:
    return list(dict.fromkeys(int(v) for v in values))


def _crea_group_ma(ctx, mesh, occ) -> None:
    if as_scalar(occ.get("OPTION")) is not None:
        ctx.unsupported(f"DEFI_GROUP CREA_GROUP_MA OPTION={occ['OPTION']!r}", "OPTION", occ)
    name = as_scalar(occ.get("NOM"))
    combined = _combine(ctx, occ, mesh.cell_groups, "cell")
    if combined is not None:
        members = combined
    elif occ.get("TOUT") == "OUI":
        members = np.arange(mesh.n_cells)
    else:
        members = _unique(cell_group_members(ctx, occ, mesh) + named_cells(ctx, occ, mesh))
    types = as_tuple(occ.get("TYPE_MAILLE"))
    if types and "TOUT" not in types:
        wanted = {"1D": ("SEG",), "2D": ("TRIA", "QUAD"), "3D": ("TETRA", "PENTA", "HEXA", "PYRAM")}
        prefixes = tuple(p for t in types for p in wanted.get(t, (t,)))
        members = [c for c in members if mesh.cell_types[c].startswith(prefixes)]
    _store(ctx, occ, mesh.cell_groups, name, members, "cell")


def _crea_group_no(ctx, mesh, occ) -> None:
    if as_scalar(occ.get("OPTION")) is not None:
        ctx.unsupported(f"DEFI_GROUP CREA_GROUP_NO OPTION={occ['OPTION']!r}", "OPTION", occ)
    if occ.get("TOUT_GROUP_MA") == "OUI":
        for gname, cells in mesh.cell_groups.items():
            if gname not in mesh.node_groups:
                mesh.node_groups[gname] = mesh.nodes_of_cells(cells)
        return
    if occ.get("TOUT_GROUP_NO") == "OUI":
        return
    name = as_scalar(occ.get("NOM"))
    combined = _combine(ctx, occ, mesh.node_groups, "node")
    if combined is not None:
        _store(ctx, occ, mesh.node_groups, name, combined, "node")
        return
    cell_groups = as_tuple(occ.get("GROUP_MA"))
    if cell_groups and name is None:
        # one node group per cell group, named like it
        for gname in cell_groups:
            if gname not in mesh.cell_groups:
                ctx.error(f"the mesh has no cell group {gname!r}", "GROUP_MA", occ)
            if gname in mesh.node_groups:
                ctx.error(f"the node group {gname!r} already exists", "GROUP_MA", occ)
            mesh.node_groups[gname] = mesh.nodes_of_cells(mesh.cell_groups[gname])
        return
    if occ.get("TOUT") == "OUI":
        members = list(range(mesh.n_nodes))
    else:
        members = node_group_members(ctx, occ, mesh) + named_nodes(ctx, occ, mesh)
        cells = cell_group_members(ctx, occ, mesh) + named_cells(ctx, occ, mesh)
        if cells:
            members += mesh.nodes_of_cells(cells).tolist()
    if name is None:
        ctx.error("NOM is required to name the new node group", "NOM", occ)
    _store(ctx, occ, mesh.node_groups, name, _unique(members), "node")


def run(ctx, kw):
    mesh = kw["MAILLAGE"]
    for occ in kw.factor("DETR_GROUP_MA"):
        for name in as_tuple(occ.get("NOM")):
            mesh.cell_groups.pop(name, None)
    for occ in kw.factor("DETR_GROUP_NO"):
        for name in as_tuple(occ.get("NOM")):
            mesh.node_groups.pop(name, None)
    for occ in kw.factor("CREA_GROUP_MA"):
        _crea_group_ma(ctx, mesh, occ)
    for occ in kw.factor("CREA_GROUP_NO"):
        _crea_group_no(ctx, mesh, occ)
    return mesh
