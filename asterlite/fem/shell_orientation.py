"""ORIE_NORM_COQUE: consistent normals on a set of shell cells (code_aster's
orvlma/ornorm).

A cell's normal is that of its vertex order, (P2 - P1) x (Pn - P1) at a
vertex. With VECT_NORM, each cell holding the given node is turned so that
its normal at that node points along the vector; without it, the first cell
of the group is kept as it is. The orientation then spreads to the cells
sharing an edge with an oriented cell: a neighbour that runs the shared edge
the same way is reversed. Every cell must be reached (one connected surface
per starting cell). Reversing keeps the first vertex, reverses the others,
and the mid-side nodes follow their edges.
"""

from __future__ import annotations

from collections import deque

import numpy as np

VERTICES = {"TRIA3": 3, "TRIA6": 3, "TRIA7": 3, "QUAD4": 4, "QUAD8": 4, "QUAD9": 4}


class ShellOrientationError(ValueError):
    pass


def reversed_nodes(nodes: tuple, vertices: int) -> tuple:
    """The cell's nodes in the reverse order (code_aster's swap of vertex 2
    and the last vertex, and of the mid-side nodes in pairs)."""
    out = list(nodes)
    out[1], out[vertices - 1] = out[vertices - 1], out[1]
    if len(out) > vertices:
        for i in range(1, vertices // 2 + 1):
            a, b = vertices + i - 1, 2 * vertices - i
            out[a], out[b] = out[b], out[a]
    return tuple(out)


def _vertex_normal(coords: np.ndarray, corners: list[int], position: int) -> np.ndarray:
    n = len(corners)
    here = coords[corners[position]]
    following = coords[corners[(position + 1) % n]]
    previous = coords[corners[position - 1]]
    return np.cross(following - here, previous - here)


def orient_shells(mesh, cells, vector=None, node: int | None = None) -> int:
    """Orient ``cells`` in place (their node lists); the number reversed."""
    cells = [int(c) for c in cells]
    coords = np.asarray(mesh.coords, dtype=float)
    if coords.shape[1] < 3:
        coords = np.pad(coords, ((0, 0), (0, 3 - coords.shape[1])))
    for cell in cells:
        if mesh.cell_types[cell] not in VERTICES:
            raise ShellOrientationError(
                f"cell {mesh.cell_names[cell]} is a {mesh.cell_types[cell]}: ORIE_NORM_COQUE "
                "orients triangles and quadrangles"
            )
    members = set(cells)
    reversed_count = 0

    def corners(cell: int) -> list[int]:
        return list(mesh.cell_nodes[cell][: VERTICES[mesh.cell_types[cell]]])

    def reverse(cell: int) -> None:
        nonlocal reversed_count
        mesh.cell_nodes[cell] = reversed_nodes(
            tuple(mesh.cell_nodes[cell]), VERTICES[mesh.cell_types[cell]]
        )
        reversed_count += 1

    oriented: set[int] = set()
    seeds: list[int] = []
    if vector is not None:
        direction = np.asarray(vector, dtype=float)
        for cell in cells:
            vertices = corners(cell)
            if node not in vertices:
                continue
            scal = float(_vertex_normal(coords, vertices, vertices.index(node)) @ direction)
            if scal == 0.0:
                raise ShellOrientationError(
                    f"cell {mesh.cell_names[cell]}: its normal is orthogonal to VECT_NORM"
                )
            if scal < 0.0:
                reverse(cell)
            oriented.add(cell)
            seeds.append(cell)
        if not seeds:
            raise ShellOrientationError(
                f"no cell of the group holds the node {mesh.node_names[node]}"
            )
    elif cells:
        seeds, oriented = [cells[0]], {cells[0]}
    by_node: dict[int, list[int]] = {}
    for cell in cells:
        for n in corners(cell):
            by_node.setdefault(n, []).append(cell)
    for seed in seeds:
        queue = deque([seed])
        while queue:
            current = queue.popleft()
            edges = corners(current)
            directed = {(edges[i], edges[(i + 1) % len(edges)]) for i in range(len(edges))}
            neighbours = sorted({c for n in edges for c in by_node[n]} - oriented)
            for other in neighbours:
                if other not in members:
                    continue
                theirs = corners(other)
                their_edges = [
                    (theirs[i], theirs[(i + 1) % len(theirs)]) for i in range(len(theirs))
                ]
                if any(edge in directed for edge in their_edges):
                    reverse(other)
                elif not any((b, a) in directed for a, b in their_edges):
                    continue  # a shared vertex only
                oriented.add(other)
                queue.append(other)
    missing = [c for c in cells if c not in oriented]
    if missing:
        raise ShellOrientationError(
            f"cell {mesh.cell_names[missing[0]]} is not connected by edges to the cells "
            "oriented first: its orientation is undetermined"
        )
    return reversed_count
