"""DEFI_GROUP: create (or destroy) node and cell groups of a mesh, in place."""

from __future__ import annotations

import numpy as np

from asterlite.errors import missing_name
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


def _point(ctx, mesh, occ, keyword: str = "POINT") -> np.ndarray:
    """The centre of an option: POINT, NOEUD_CENTRE or GROUP_NO_CENTRE."""
    if occ.get(keyword) is not None:
        values = np.atleast_1d(np.asarray(as_tuple(occ[keyword]), dtype=float))
        point = np.zeros(3)
        point[: min(3, values.size)] = values[:3]
        return point
    nodes = node_group_members(ctx, occ, mesh, "GROUP_NO_CENTRE") + named_nodes(
        ctx, occ, mesh, "NOEUD_CENTRE"
    )
    if len(nodes) != 1:
        ctx.error("the centre must be one node", "GROUP_NO_CENTRE", occ)
    return mesh.coords[nodes[0]].copy()


def _single_node(ctx, mesh, occ, keyword: str) -> int:
    nodes = node_group_members(ctx, occ, mesh, keyword)
    if len(nodes) != 1:
        ctx.error(f"{keyword} must hold exactly one node", keyword, occ)
    return int(nodes[0])


def _axis(ctx, occ) -> np.ndarray:
    if occ.get("VECT_NORMALE") is not None:
        v = np.zeros(3)
        given = np.asarray(as_tuple(occ["VECT_NORMALE"]), dtype=float)
        v[: given.size] = given[:3]
    else:
        angles = np.radians(np.asarray(as_tuple(occ["ANGL_NAUT"]), dtype=float))
        a = angles[0]
        b = angles[1] if angles.size > 1 else 0.0
        v = np.array([np.cos(a) * np.cos(b), np.sin(a) * np.cos(b), -np.sin(b)])
    norm = np.linalg.norm(v)
    if not norm > 0.0:
        ctx.error("the direction is a zero vector", "VECT_NORMALE", occ)
    return v / norm


def _chain_order(ctx, mesh, cells, start: int | None, end: int | None, occ) -> list[int]:
    """Nodes of a line of SEG cells ordered from ``start`` (or a free end)."""
    neighbours: dict[int, list[int]] = {}
    for cell in cells:
        conn = mesh.cell_nodes[cell]
        a, b = conn[0], conn[1] if len(conn) > 1 else conn[0]
        if a == b:
            continue
        neighbours.setdefault(a, []).append(b)
        neighbours.setdefault(b, []).append(a)
    if not neighbours:
        ctx.error("NOEUD_ORDO needs segment cells", "GROUP_MA", occ)
    ends = [n for n, nb in neighbours.items() if len(nb) == 1]
    if any(len(nb) > 2 for nb in neighbours.values()):
        ctx.error("NOEUD_ORDO: the cells do not form a simple line", "GROUP_MA", occ)
    if start is None:
        if end is not None and end in ends:
            start = next(n for n in ends if n != end)
        elif ends:
            start = min(ends)
        else:
            start = min(neighbours)
    if start not in neighbours:
        ctx.error("GROUP_NO_ORIG is not a node of the line", "GROUP_NO_ORIG", occ)
    order, previous, current = [start], None, start
    while True:
        following = [n for n in neighbours[current] if n != previous and n not in order[:1]]
        following = [n for n in following if n not in order]
        if not following:
            break
        previous, current = current, following[0]
        order.append(current)
        if current == end:
            break
    return order


def _crea_group_no_option(ctx, mesh, occ, option: str) -> None:
    name = as_scalar(occ.get("NOM"))
    coords = mesh.coords
    if option in ("ENV_SPHERE", "ENV_CYLINDRE", "PLAN"):
        centre = _point(ctx, mesh, occ)
        tol = float(occ["PRECISION"])
        d = coords - centre
        if option == "ENV_SPHERE":
            distance = np.abs(np.linalg.norm(d, axis=1) - float(occ["RAYON"]))
        elif option == "ENV_CYLINDRE":
            axis = _axis(ctx, occ)
            radial = d - np.outer(d @ axis, axis)
            distance = np.abs(np.linalg.norm(radial, axis=1) - float(occ["RAYON"]))
        else:
            distance = np.abs(d @ _axis(ctx, occ))
        members = np.flatnonzero(distance <= tol)
    elif option == "SEGM_DROI_ORDO":
        origin = _single_node(ctx, mesh, occ, "GROUP_NO_ORIG")
        extremity = _single_node(ctx, mesh, occ, "GROUP_NO_EXTR")
        candidates = np.array(_unique(node_group_members(ctx, occ, mesh)), dtype=int)
        a, b = coords[origin], coords[extremity]
        length = np.linalg.norm(b - a)
        if not length > 0.0:
            ctx.error("GROUP_NO_ORIG and GROUP_NO_EXTR are the same point", "GROUP_NO_EXTR", occ)
        u = (b - a) / length
        d = coords[candidates] - a
        s = d @ u
        off = np.linalg.norm(d - np.outer(s, u), axis=1)
        tol = float(occ["PRECISION"])
        if occ["CRITERE"] == "RELATIF":
            tol *= length
        bad = candidates[(off > tol) | (s < -tol) | (s > length + tol)]
        if bad.size:
            ctx.error(
                f"node {mesh.node_names[bad[0]]} is not on the segment ORIG-EXTR", "GROUP_NO", occ
            )
        members = candidates[np.argsort(s, kind="stable")]
    elif option == "NOEUD_ORDO":
        cells = cell_group_members(ctx, occ, mesh)
        start = _single_node(ctx, mesh, occ, "GROUP_NO_ORIG") if occ.get("GROUP_NO_ORIG") else None
        end = _single_node(ctx, mesh, occ, "GROUP_NO_EXTR") if occ.get("GROUP_NO_EXTR") else None
        members = _chain_order(ctx, mesh, cells, start, end, occ)
    else:
        ctx.unsupported(f"DEFI_GROUP CREA_GROUP_NO OPTION={option!r}", "OPTION", occ)
    if len(members) == 0:
        ctx.error(f"OPTION={option} selects no node for group {name!r}", "OPTION", occ)
    _store(ctx, occ, mesh.node_groups, name, members, "node")


def _crea_group_no(ctx, mesh, occ) -> None:
    option = as_scalar(occ.get("OPTION"))
    if option is not None:
        _crea_group_no_option(ctx, mesh, occ, option)
        return
    if occ.get("TOUT_GROUP_MA") == "OUI":
        for gname, cells in mesh.cell_groups.items():
            if gname not in mesh.node_groups:
                mesh.node_groups[gname] = np.sort(mesh.nodes_of_cells(cells))
        return
    if occ.get("TOUT_GROUP_NO") == "OUI":
        return
    name = as_scalar(occ.get("NOM"))
    combined = _combine(ctx, occ, mesh.node_groups, "node")
    if combined is not None:
        _store(ctx, occ, mesh.node_groups, name, combined, "node")
        return
    cell_groups = as_tuple(occ.get("GROUP_MA"))
    names = as_tuple(occ.get("NOM"))
    if cell_groups and (name is None or len(names) == len(cell_groups)):
        # one node group per cell group, named like it (or by NOM, one to one)
        for gname, new_name in zip(cell_groups, names or cell_groups, strict=True):
            if gname not in mesh.cell_groups:
                ctx.error(missing_name("cell group", gname, mesh.cell_groups), "GROUP_MA", occ)
            if new_name in mesh.node_groups:
                ctx.error(f"the node group {new_name!r} already exists", "GROUP_MA", occ)
            # in increasing node order, as code_aster lists them (gmgnre)
            mesh.node_groups[new_name] = np.sort(mesh.nodes_of_cells(mesh.cell_groups[gname]))
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
