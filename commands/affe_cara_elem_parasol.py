"""AFFE_CARA_ELEM RIGI_PARASOL: a foundation's global stiffness (or
damping) spread over the POI1 discrete elements at the nodes of its surface
cells (code_aster's rairep/acearp), in 3D.

Each surface cell's area (a segment's length) times its group's COEF_GROUP
is shared equally among the cell's nodes; a node's weight is its share of
the total. Translations take the given values times the weight. Rotations
take, times the weight, the given rotational value less what the nodes'
translation springs already give about the centre (GROUP_NO_CENTRE or
COOR_CENTRE): KRX - Σ w (KY z² + KZ y²), and likewise about y and z. Each
POI1 cell of GROUP_MA_POI1 gets the values (*_N) of its node; each SEG2 cell
of GROUP_MA_SEG2 (*_L) those of the first of its nodes on the surface."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DiscreteAssignment
from asterlite.fem.selection import as_scalar, as_tuple, node_group_members

_SURFACE_VERTICES = {"TRIA3": 3, "TRIA6": 3, "TRIA7": 3, "QUAD4": 4, "QUAD8": 4, "QUAD9": 4}


def _cell_measure(coords: np.ndarray, nodes, cell_type: str) -> float:
    if cell_type.startswith("SEG"):
        return float(np.linalg.norm(coords[nodes[1]] - coords[nodes[0]]))
    a = coords[nodes[2]] - coords[nodes[0]]
    if _SURFACE_VERTICES[cell_type] == 3:
        b = coords[nodes[1]] - coords[nodes[0]]
    else:
        b = coords[nodes[3]] - coords[nodes[1]]
    return 0.5 * float(np.linalg.norm(np.cross(a, b)))


def node_weights(ctx, mesh, occ) -> tuple[list[int], np.ndarray]:
    """(nodes in first-met order, their weights) of the surface groups."""
    groups = as_tuple(occ["GROUP_MA"])
    coefficients = np.atleast_1d(np.asarray(as_tuple(occ["COEF_GROUP"]), dtype=float))
    if coefficients.size != len(groups):
        ctx.error(
            f"COEF_GROUP gives {coefficients.size} values for {len(groups)} groups",
            "COEF_GROUP",
            occ,
        )
    coords = np.asarray(mesh.coords, dtype=float)
    if coords.shape[1] < 3:
        coords = np.pad(coords, ((0, 0), (0, 3 - coords.shape[1])))
    seen: set[int] = set()
    order: list[int] = []
    shares: list[tuple[tuple[int, ...], float]] = []
    total = 0.0
    kinds = set()
    for group, coefficient in zip(groups, coefficients, strict=True):
        if group not in mesh.cell_groups:
            ctx.error(f"the mesh has no cell group {group!r}", "GROUP_MA", occ)
        for cell in mesh.cell_groups[group].tolist():
            if cell in seen:
                continue  # code_aster counts a cell once
            seen.add(cell)
            cell_type = mesh.cell_types[cell]
            if cell_type not in _SURFACE_VERTICES and not cell_type.startswith("SEG"):
                ctx.error(
                    f"cell {mesh.cell_names[cell]} ({cell_type}) is neither a surface nor a "
                    "segment",
                    "GROUP_MA",
                    occ,
                )
            kinds.add("SEG" if cell_type.startswith("SEG") else "SURFACE")
            nodes = tuple(int(n) for n in mesh.cell_nodes[cell])
            for node in nodes:
                if node not in order:
                    order.append(node)
            measure = _cell_measure(coords, nodes, cell_type) * float(coefficient)
            total += measure
            shares.append((nodes, measure / len(nodes)))
    if len(kinds) > 1:
        ctx.error("RIGI_PARASOL mixes segments and surface cells", "GROUP_MA", occ)
    if total <= 0.0:
        ctx.error("the surface cells have no area", "GROUP_MA", occ)
    position = {node: k for k, node in enumerate(order)}
    weights = np.zeros(len(order))
    for nodes, share in shares:
        for node in nodes:
            weights[position[node]] += share / total
    return order, weights


def rigi_parasol(ctx, model, result, occ) -> None:
    mesh = model.mesh
    for name in ("FONC_GROUP", "UNITE"):
        if occ.get(name) is not None:
            ctx.unsupported(f"RIGI_PARASOL/{name}", name, occ)
    if mesh.dim != 3:
        ctx.unsupported("RIGI_PARASOL on a 2D model", "GROUP_MA", occ)
    coords = np.asarray(mesh.coords, dtype=float)
    if occ.get("GROUP_NO_CENTRE") is not None:
        centre = coords[node_group_members(ctx, occ, mesh, "GROUP_NO_CENTRE")[0]]
    else:
        centre = np.zeros(3)
        given = np.asarray(as_tuple(occ["COOR_CENTRE"]), dtype=float)
        centre[: given.size] = given
    nodes, weights = node_weights(ctx, mesh, occ)
    offsets = coords[nodes] - centre
    repere = as_scalar(occ.get("REPERE")) or "GLOBAL"
    values = np.asarray(as_tuple(occ["VALE"]), dtype=float)
    support_key = "GROUP_MA_POI1" if occ.get("GROUP_MA_POI1") is not None else "GROUP_MA_SEG2"
    support_group = as_scalar(occ[support_key])
    if support_group not in mesh.cell_groups:
        ctx.error(f"the mesh has no cell group {support_group!r}", support_key, occ)
    supports = mesh.cell_groups[support_group].tolist()
    if len(supports) != len(nodes):
        ctx.error(
            f"{support_group} has {len(supports)} cells for the {len(nodes)} nodes of the surface",
            support_key,
            occ,
        )
    # a support cell carries the values of the first of its nodes on the surface
    surface_nodes = set(nodes)
    cell_of_node = {}
    wanted_type = "POI1" if support_key == "GROUP_MA_POI1" else "SEG2"
    for cell in supports:
        if mesh.cell_types[cell] != wanted_type:
            ctx.error(
                f"cell {mesh.cell_names[cell]} of {support_group} is not a {wanted_type}",
                support_key,
                occ,
            )
        on_surface = [int(n) for n in mesh.cell_nodes[cell] if int(n) in surface_nodes]
        if not on_surface:
            ctx.error(
                f"cell {mesh.cell_names[cell]} of {support_group} has no node on the surface",
                support_key,
                occ,
            )
        cell_of_node[on_surface[0]] = int(cell)
    start = 0
    for cara in as_tuple(occ["CARA"]):
        rotations = "_TR_" in cara
        if cara.endswith("_N") != (support_key == "GROUP_MA_POI1"):
            ctx.error(f"{cara} does not fit the cells of {support_key}", "CARA", occ)
        count = 6 if rotations else 3
        given = values[start : start + count]
        if given.size != count:
            ctx.error(f"{cara} needs {count} values in VALE", "VALE", occ)
        start += count
        per_node = np.outer(weights, given[:3])
        if rotations:
            x, y, z = offsets[:, 0], offsets[:, 1], offsets[:, 2]
            kx, ky, kz = given[:3]
            about = np.array(
                [
                    given[3] - np.sum((ky * z**2 + kz * y**2) * weights),
                    given[4] - np.sum((kx * z**2 + kz * x**2) * weights),
                    given[5] - np.sum((ky * x**2 + kx * y**2) * weights),
                ]
            )
            per_node = np.hstack([per_node, np.outer(weights, about)])
            ctx.log(
                f"RIGI_PARASOL {cara}: rotations left to the nodes "
                + ", ".join(f"{v:.6g}" for v in about)
            )
        matrix = cara[0]
        for k, node in enumerate(nodes):
            cell = cell_of_node.get(node)
            if cell is None:
                ctx.error(
                    f"node {mesh.node_names[node]} of the surface has no cell in {support_group}",
                    support_key,
                    occ,
                )
            modelisation = model.cell_modelisation.get(cell)
            wanted = "DIS_TR" if rotations else "DIS_T"
            if modelisation != wanted:
                ctx.error(
                    f"{cara} needs {wanted} elements but cell {mesh.cell_names[cell]} is "
                    f"{modelisation}",
                    "CARA",
                    occ,
                )
            result.discrete.setdefault(cell, {})[matrix] = DiscreteAssignment(
                matrix=matrix,
                cara=cara,
                values=per_node[k].copy(),
                repere=repere,
                symmetric=True,
                hysteretic=0.0,
            )
    if start != values.size:
        ctx.error(f"VALE has {values.size} values, CARA uses {start}", "VALE", occ)
