"""ORIE_NORM_COQUE: consistent normals on a set of shell cells (code_aster's
orvlma/ornorm).

A cell's normal is that of its vertex order, (P2 - P1) x (Pn - P1) at a
vertex; a segment's (plane lines: SEG2, SEG3) is its tangent P1 -> P2 turned
by -90 degrees in the xy plane, (y2 - y1, x1 - x2). With VECT_NORM, each
cell holding the given node is turned so that its normal at that node points
along the vector; without it, the first cell of the group is kept as it is.
The orientation then spreads to the cells
sharing an edge with an oriented cell: a neighbour that runs the shared edge
the same way is reversed. Every cell must be reached (one connected surface
per starting cell). Reversing keeps the first vertex, reverses the others,
and the mid-side nodes follow their edges; a segment swaps its ends, and
segments spread through their shared ends (a neighbour starting where the
cell starts, or ending where it ends, is reversed).
"""

from __future__ import annotations

from collections import deque

import numpy as np

VERTICES = {"TRIA3": 3, "TRIA6": 3, "TRIA7": 3, "QUAD4": 4, "QUAD8": 4, "QUAD9": 4}
SEGMENTS = ("SEG2", "SEG3")


class ShellOrientationError(ValueError):
    pass


def reversed_nodes(nodes: tuple, vertices: int) -> tuple:
    """The cell's nodes in the reverse order (code_aster's swap of vertex 2
    and the last vertex, and of the mid-side nodes in pairs)."""
    out = list(nodes)
    if vertices == 2:
        out[0], out[1] = out[1], out[0]
        return tuple(out)
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
    kinds = set()
    for cell in cells:
        if mesh.cell_types[cell] not in VERTICES and mesh.cell_types[cell] not in SEGMENTS:
            raise ShellOrientationError(
                f"cell {mesh.cell_names[cell]} is a {mesh.cell_types[cell]}: ORIE_NORM_COQUE "
                "orients segments, triangles and quadrangles"
            )
        kinds.add(mesh.cell_types[cell] in SEGMENTS)
    if len(kinds) > 1:
        raise ShellOrientationError("the group mixes segments and surface cells")
    lines = kinds == {True}
    members = set(cells)
    reversed_count = 0

    def count_of(cell: int) -> int:
        return 2 if lines else VERTICES[mesh.cell_types[cell]]

    def corners(cell: int) -> list[int]:
        return list(mesh.cell_nodes[cell][: count_of(cell)])

    def reverse(cell: int) -> None:
        nonlocal reversed_count
        mesh.cell_nodes[cell] = reversed_nodes(tuple(mesh.cell_nodes[cell]), count_of(cell))
        reversed_count += 1

    oriented: set[int] = set()
    seeds: list[int] = []
    if vector is not None:
        direction = np.asarray(vector, dtype=float)
        for cell in cells:
            vertices = corners(cell)
            if node not in vertices:
                continue
            if lines:
                a, b = coords[vertices[0]], coords[vertices[1]]
                scal = float((b[1] - a[1]) * direction[0] + (a[0] - b[0]) * direction[1])
            else:
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
                if lines:
                    if edges[0] == theirs[0] or edges[1] == theirs[1]:
                        reverse(other)
                    elif edges[0] != theirs[1] and edges[1] != theirs[0]:
                        continue
                    oriented.add(other)
                    queue.append(other)
                    continue
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
