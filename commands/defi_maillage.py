"""DEFI_MAILLAGE: a mesh whose cells are static superelements (op0088).

Each super-cell brings its macro-element's external nodes as new nodes (in
the macro-element's order, shifted by TRAN), named by DEFI_NOEUD (TOUT with
INDEX: PREFIXE, then the characters INDEX[0]..INDEX[1] of the super-cell's
name, then INDEX[2]..INDEX[3] of the node's name; NOEUD_INIT renames one)
or N<i> by position. ANGL_NAUT (degrees) turns a super-cell about CENTRE:
its nodes are placed and its matrices expressed in the global frame.
DEFI_GROUP_NO copies the groups of the macro-element's mesh restricted to
its external nodes (named the same way from the group's name), or one
group (GROUP_NO_INIT -> GROUP_NO_FIN). Super-cells are named by
SUPER_MAILLE, else after their macro-element. RECO_GLOBAL merges the
coincident nodes of several super-cells, RECO_SUPER_MAILLE those of named
groups (by position, in order or in reverse order).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.static_substructure import (
    StaticMacroElement,
    SuperCell,
    SuperMesh,
    node_rotation,
)
from asterlite.fem.frames import rotation_from_angles

#: code_aster's names are 8 characters at most
NAME_LENGTH = 8


def run(ctx, kw):
    coords, sources, cells = [], [], {}
    for occ in kw.factor("DEFI_SUPER_MAILLE"):
        macros = list(np.atleast_1d(occ["MACR_ELEM"]))
        names = [str(n) for n in np.atleast_1d(occ.get("SUPER_MAILLE") or ())]
        if names and len(names) != len(macros):
            ctx.error("give one SUPER_MAILLE name per MACR_ELEM", "SUPER_MAILLE", occ)
        shift, rotation, centre = _placement(occ)
        for k, macro in enumerate(macros):
            if not isinstance(macro, StaticMacroElement):
                ctx.unsupported(
                    "DEFI_MAILLAGE of a dynamic macro-element (MACR_ELEM_DYNA)", "MACR_ELEM", occ
                )
            if "RIGI" not in macro.matrices:
                ctx.error(
                    f"{macro.name}: the superelement has no stiffness (RIGI_MECA)", "MACR_ELEM"
                )
            name = names[k] if names else (macro.name or f"SM{len(cells) + 1}")
            if name in cells:
                ctx.error(f"two super-cells named {name}", "SUPER_MAILLE", occ)
            if rotation is not None:
                try:
                    node_rotation(tuple(macro.components), rotation)
                except ValueError as exc:
                    ctx.unsupported(f"DEFI_MAILLAGE ANGL_NAUT: {exc}", "ANGL_NAUT", occ)
            start = len(sources)
            dim = 2 if macro.mesh.dim == 2 else 3
            for node in macro.external_nodes:
                sources.append((name, macro, int(node)))
                coords.append(_placed(macro.mesh.coords[node], shift, rotation, centre, dim))
            cells[name] = SuperCell(
                macro=macro, nodes=np.arange(start, len(sources)), rotation=rotation
            )
    coords = np.asarray(coords, dtype=float).reshape(-1, 3)
    kept = _merged(ctx, kw, coords, cells)
    names = _node_names(ctx, kw, sources, cells)
    groups = _node_groups(ctx, kw, cells)
    # the nodes RECO_GLOBAL merges disappear into the first of them
    survivors = np.unique(kept)
    position = np.full(len(kept), -1)
    position[survivors] = np.arange(survivors.size)
    renumber = position[kept]
    node_names = [names[i] for i in survivors]
    _check_unique(ctx, node_names)
    for cell in cells.values():
        cell.nodes = renumber[cell.nodes]
    mesh = SuperMesh(
        coords=coords[survivors],
        node_names=node_names,
        cell_names=[],
        cell_types=[],
        cell_nodes=[],
        super_cells=cells,
    )
    mesh.node_groups = {
        name: np.asarray(list(dict.fromkeys(renumber[members].tolist())), dtype=int)
        for name, members in groups.items()
    }
    ctx.log(f"DEFI_MAILLAGE: {len(cells)} super-cells, {mesh.n_nodes} nodes")
    return mesh


def _placement(occ):
    """TRAN, the global-to-local rotation of ANGL_NAUT (degrees) or None, CENTRE."""
    shift, centre = np.zeros(3), np.zeros(3)
    if occ.get("TRAN") is not None:
        given = np.atleast_1d(np.asarray(occ["TRAN"], dtype=float))
        shift[: given.size] = given
    rotation = None
    if occ.get("ANGL_NAUT") is not None:
        angles = np.zeros(3)
        given = np.atleast_1d(np.asarray(occ["ANGL_NAUT"], dtype=float))
        angles[: given.size] = np.radians(given)
        if np.abs(angles).sum() > 1.0e-6:  # code_aster's threshold (ssrone)
            rotation = rotation_from_angles(angles)
        if occ.get("CENTRE") is not None:
            given = np.atleast_1d(np.asarray(occ["CENTRE"], dtype=float))
            centre[: given.size] = given
    return shift, rotation, centre


def _placed(point, shift, rotation, centre, dim: int) -> np.ndarray:
    """A node of the superelement where the super-cell puts it: turned about
    CENTRE (the mesh's own dimensions only, as code_aster's ssdmge), then shifted."""
    out = np.asarray(point, dtype=float).copy()
    if rotation is not None:
        out[:dim] = centre[:dim] + rotation[:dim, :dim].T @ (out[:dim] - centre[:dim])
    return out + shift


def _indexed(ctx, occ, prefix: str, cell: str, name: str) -> str:
    index = [int(i) for i in np.atleast_1d(occ["INDEX"])]
    if len(index) != 4:
        ctx.error("INDEX takes 4 integers", "INDEX", occ)
    out = prefix + cell[index[0] - 1 : index[1]] + name[index[2] - 1 : index[3]]
    if len(out) > NAME_LENGTH:
        ctx.error(f"the name {out} is longer than {NAME_LENGTH} characters", "INDEX", occ)
    return out


def _node_names(ctx, kw, sources, cells) -> list[str]:
    names = [f"N{i + 1}" for i in range(len(sources))]
    for occ in kw.factor("DEFI_NOEUD"):
        if occ.get("TOUT") == "OUI":
            prefix = str(occ.get("PREFIXE") or "")
            for i, (cell, macro, node) in enumerate(sources):
                names[i] = _indexed(ctx, occ, prefix, cell, macro.mesh.node_label(node))
            continue
        cell = str(occ["SUPER_MAILLE"])
        if cell not in cells:
            ctx.error(f"no super-cell {cell}", "SUPER_MAILLE", occ)
        macro = cells[cell].macro
        initial = macro.mesh.find_node(str(occ["NOEUD_INIT"]))
        where = np.flatnonzero(macro.external_nodes == initial) if initial is not None else []
        if len(where) == 0:
            ctx.error(f"{occ['NOEUD_INIT']} is not an external node of {cell}", "NOEUD_INIT", occ)
        names[int(cells[cell].nodes[where[0]])] = str(occ["NOEUD_FIN"])
    return names


def _check_unique(ctx, names) -> None:
    seen: dict[str, int] = {}
    for name in names:
        seen[name] = seen.get(name, 0) + 1
    twice = [n for n, count in seen.items() if count > 1]
    if twice:
        ctx.error(f"nodes named twice: {', '.join(twice[:5])}", "DEFI_NOEUD")


def _merged(ctx, kw, coords, cells) -> np.ndarray:
    """RECO_GLOBAL: for each node, the node it becomes. Nodes of two listed
    super-cells closer than PRECISION (ABSOLU) or PRECISION times the
    smaller of the two super-cells' shortest distance between their own
    nodes (RELATIF) are one node, the first of them (code_aster's ssdmrg)."""
    target = np.arange(len(coords))

    def root(i: int) -> int:
        while target[i] != i:
            i = target[i]
        return i

    shortest = {name: _shortest_distance(coords[cell.nodes]) for name, cell in cells.items()}
    for occ in kw.factor("RECO_GLOBAL"):
        if occ.get("TOUT") == "OUI":
            names = list(cells)
        else:
            names = [str(n) for n in np.atleast_1d(occ["SUPER_MAILLE"])]
            unknown = [n for n in names if n not in cells]
            if unknown:
                ctx.error(f"no super-cell {unknown[0]}", "SUPER_MAILLE", occ)
        precision = float(occ.get("PRECISION", 1.0e-3))
        relative = occ.get("CRITERE", "RELATIF") == "RELATIF"
        for a, first in enumerate(names):
            for second in names[a + 1 :]:
                limit = precision
                if relative:
                    limit *= min(shortest[first], shortest[second])
                nodes_1, nodes_2 = cells[first].nodes, cells[second].nodes
                gaps = np.linalg.norm(
                    coords[nodes_1][:, None, :] - coords[nodes_2][None, :, :], axis=2
                )
                for i, j in zip(*np.nonzero(gaps <= limit), strict=True):
                    low, high = sorted((root(int(nodes_1[i])), root(int(nodes_2[j]))))
                    target[high] = low
    for occ in kw.factor("RECO_SUPER_MAILLE"):
        _paired_groups(ctx, occ, coords, cells, shortest, root, target)
    return np.array([root(i) for i in range(len(coords))], dtype=int)


def _paired_groups(ctx, occ, coords, cells, shortest, root, target) -> None:
    """RECO_SUPER_MAILLE: the external nodes of a group of each listed
    super-cell merged pairwise (code_aster's ssdmrm): in order
    (NOEUD_A_NOEUD), the first list reversed (INVERSE), or by position
    (GEOMETRIQUE, PRECISION as RECO_GLOBAL's)."""
    names = [str(n) for n in np.atleast_1d(occ["SUPER_MAILLE"])]
    groups = [str(g) for g in np.atleast_1d(occ["GROUP_NO"])]
    if len(names) != len(groups):
        ctx.error("give one GROUP_NO per SUPER_MAILLE", "GROUP_NO", occ)
    if len(names) < 2:
        ctx.error("RECO_SUPER_MAILLE joins at least two super-cells", "SUPER_MAILLE", occ)
    members = []
    for name, group in zip(names, groups, strict=True):
        if name not in cells:
            ctx.error(f"no super-cell {name}", "SUPER_MAILLE", occ)
        macro = cells[name].macro
        if group not in macro.mesh.node_groups:
            ctx.error(f"no group {group} in the mesh of super-cell {name}", "GROUP_NO", occ)
        position = {int(n): k for k, n in enumerate(macro.external_nodes)}
        # the group's external nodes, in the group's order
        members.append(
            [
                cells[name].nodes[position[int(n)]]
                for n in macro.mesh.node_groups[group]
                if int(n) in position
            ]
        )
    option = occ.get("OPTION", "GEOMETRIQUE")
    precision = float(occ.get("PRECISION", 1.0e-3))
    relative = occ.get("CRITERE", "RELATIF") == "RELATIF"

    def merge(a: int, b: int) -> None:
        low, high = sorted((root(int(a)), root(int(b))))
        target[high] = low

    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            count = min(len(members[i]), len(members[j]))
            if len(members[i]) != len(members[j]):
                ctx.log(f"warning: groups {groups[i]} and {groups[j]} differ in size")
            first, second = members[i][:count], members[j][:count]
            if option == "NOEUD_A_NOEUD":
                pairs = list(zip(first, second, strict=True))
            elif option == "INVERSE":
                order = first[::-1] if i == 0 else first
                pairs = list(zip(order, second, strict=True))
            else:
                limit = precision
                if relative:
                    limit *= min(shortest[names[i]], shortest[names[j]])
                pairs = []
                for a in first:
                    gaps = np.linalg.norm(coords[second] - coords[a], axis=1)
                    close = np.flatnonzero(gaps <= limit)
                    if close.size:
                        pairs.append((a, second[close[0]]))
                if len(pairs) != count:
                    ctx.log(f"warning: not every node of {groups[i]} meets one of {groups[j]}")
            for a, b in pairs:
                merge(a, b)


def _shortest_distance(points: np.ndarray) -> float:
    """The shortest distance between two of the points (0 for fewer than two)."""
    if len(points) < 2:
        return 0.0
    gaps = np.linalg.norm(points[:, None, :] - points[None, :, :], axis=2)
    return float(gaps[np.triu_indices(len(points), 1)].min())


def _node_groups(ctx, kw, cells) -> dict[str, np.ndarray]:
    groups: dict[str, np.ndarray] = {}
    for occ in kw.factor("DEFI_GROUP_NO"):
        chosen = cells if occ.get("TOUT") == "OUI" else None
        if chosen is None:
            cell = str(occ["SUPER_MAILLE"])
            if cell not in cells:
                ctx.error(f"no super-cell {cell}", "SUPER_MAILLE", occ)
            chosen = {cell: cells[cell]}
        initial = occ.get("GROUP_NO_INIT")
        for cell, placed in chosen.items():
            macro = placed.macro
            position = {int(n): k for k, n in enumerate(macro.external_nodes)}
            wanted = [str(initial)] if initial is not None else list(macro.mesh.node_groups)
            for group in wanted:
                if group not in macro.mesh.node_groups:
                    ctx.error(f"no group {group} in the superelement's mesh", "GROUP_NO_INIT", occ)
                members = [position[int(n)] for n in macro.mesh.node_groups[group] if n in position]
                if not members:
                    if initial is not None:
                        ctx.log(f"warning: group {group} has no external node of {cell}")
                    continue
                if initial is not None:
                    name = str(occ["GROUP_NO_FIN"])
                else:
                    name = _indexed(ctx, occ, str(occ.get("PREFIXE") or ""), cell, group)
                if name in groups:
                    ctx.error(f"the group {name} is defined twice", "DEFI_GROUP_NO", occ)
                groups[name] = placed.nodes[np.asarray(members, dtype=int)]
    return groups
