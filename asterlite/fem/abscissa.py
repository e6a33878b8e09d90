"""Curvilinear abscissa along a line of segment cells (MODI_MAILLAGE ABSC_CURV).

The chosen cells must be segments (``SEG2``, ``SEG3``, ``SEG4``) forming one
open line, plus ``POI1`` cells lying on its nodes. Walking from the origin
node (one of the line's two ends), each segment gets the abscissa of its
nodes in connectivity order: ``ABSC1`` (node 1), ``ABSC2`` (node 2) and, for
quadratic and cubic segments, ``ABSC3``/``ABSC4`` of the inner nodes. A
straight ``SEG2`` adds its chord; ``SEG3``/``SEG4`` are taken as circular
arcs through their nodes (straight when the first three nodes turn by less
than one degree), as code_aster does. A ``POI1`` gets the abscissa of its
node. The result is code_aster's ``ABSC_R`` carte of the mesh.
"""

from __future__ import annotations

import numpy as np

SEGMENT_NODES = {"SEG2": 2, "SEG3": 3, "SEG4": 4}
ABSCISSA_COMPONENTS = ("ABSC1", "ABSC2", "ABSC3", "ABSC4")


class AbscissaError(ValueError):
    """The cells do not form a line the abscissa can follow."""


def arc_abscissae(points: np.ndarray) -> np.ndarray:
    """Abscissa of each node of one segment, in connectivity order (node 1
    at 0, node 2 at the segment's length): chords for ``SEG2`` and nearly
    straight segments, the arc of the circle through nodes 1, 3, 2 otherwise."""
    points = np.asarray(points, dtype=float)
    n = len(points)
    s = np.zeros(n)
    if n == 2:
        s[1] = np.linalg.norm(points[1] - points[0])
        return s
    a, c, b = points[0], points[1], points[2]
    ab, bc = b - a, c - b
    normal = np.cross(ab, bc)
    sin_turn = np.linalg.norm(normal) / (np.linalg.norm(ab) * np.linalg.norm(bc))
    if np.degrees(abs(np.arcsin(min(sin_turn, 1.0)))) < 1.0:
        # walk 1 -> 3 [-> 4] -> 2 along chords
        walk = [0, 2] + ([3] if n == 4 else []) + [1]
        for prev, node in zip(walk, walk[1:], strict=False):
            s[node] = s[prev] + np.linalg.norm(points[node] - points[prev])
        return s
    # centre: on the bisecting planes of AB and BC and in the plane of A, B, C
    matrix = np.array([ab, bc, normal])
    rhs = np.array([ab @ (a + b) / 2.0, bc @ (b + c) / 2.0, normal @ a])
    centre = np.linalg.solve(matrix, rhs)
    radius = np.linalg.norm(centre - a)
    for k in range(1, n):
        r_k = np.linalg.norm(centre - points[k])
        if abs(r_k - radius) > 1e-2 * radius:
            raise AbscissaError(
                f"the nodes of a {n}-node segment are not on one circle "
                f"(from {tuple(a)} to {tuple(c)})"
            )
        cos_angle = (centre - a) @ (centre - points[k]) / radius**2
        s[k] = radius * np.arccos(np.clip(cos_angle, -1.0, 1.0))
    return s


def _ordered_segments(cell_nodes, segments, origin: int):
    """The segments end to end from ``origin``: (cell, forward) pairs, forward
    when the walk enters the cell by its node 1."""
    touching: dict[int, list[int]] = {}
    for cell in segments:
        for node in cell_nodes[cell][:2]:
            touching.setdefault(int(node), []).append(cell)
    ends = [node for node, cells in touching.items() if len(cells) == 1]
    for node, cells in touching.items():
        if len(cells) > 2:
            raise AbscissaError(f"node {node + 1} ends more than two segments: not a line")
    if len(ends) != 2:
        raise AbscissaError(f"the segments have {len(ends)} free ends, a line has 2")
    if origin not in ends:
        raise AbscissaError(f"the origin node {origin + 1} is not an end of the line")
    walk, node, previous = [], origin, None
    while len(walk) < len(segments):
        following = [c for c in touching[node] if c != previous]
        if not following:
            raise AbscissaError("the segments do not form one connected line")
        cell = following[0]
        first, second = (int(v) for v in cell_nodes[cell][:2])
        forward = node == first
        walk.append((cell, forward))
        node, previous = (second if forward else first), cell
    return walk


def curvilinear_abscissa(mesh, cells, origin: int) -> dict[int, tuple[float, ...]]:
    """The ``ABSC_R`` carte: for each of ``cells`` (mesh indices), the
    abscissa of its nodes (ABSC1... in connectivity order) from node ``origin``."""
    segments, points = [], []
    for cell in (int(c) for c in cells):
        kind = mesh.cell_types[cell]
        if kind in SEGMENT_NODES:
            segments.append(cell)
        elif kind == "POI1":
            points.append(cell)
        else:
            raise AbscissaError(
                f"cell {mesh.cell_names[cell]} is a {kind}: only POI1 and SEG2/3/4 cells "
                "carry a curvilinear abscissa"
            )
    carte: dict[int, tuple[float, ...]] = {}
    at_node: dict[int, float] = {}
    total = 0.0
    for cell, forward in _ordered_segments(mesh.cell_nodes, segments, int(origin)):
        nodes = [int(n) for n in mesh.cell_nodes[cell][: SEGMENT_NODES[mesh.cell_types[cell]]]]
        local = arc_abscissae(mesh.coords[nodes])
        length = local[1]
        # entered by node 2: the abscissa runs from node 2 back to node 1
        values = total + (local if forward else length - local)
        carte[cell] = tuple(float(v) for v in values)
        at_node.update(zip(nodes[:2], carte[cell][:2], strict=True))
        total += length
    for cell in points:
        node = int(mesh.cell_nodes[cell][0])
        if node not in at_node:
            raise AbscissaError(f"POI1 cell {mesh.cell_names[cell]} is on no segment of the line")
        carte[cell] = (at_node[node],)
    return carte
