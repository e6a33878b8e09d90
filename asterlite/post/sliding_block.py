"""Newmark's sliding block (code_aster's POST_NEWMARK on a dynamic result).

The sliding zone is a set of cells of the structure: those with at least one
node in a disc (``RAYON``, as DEFI_GROUP's SPHERE option selects them), or
with at least one node inside a second mesh's cells (``MAILLAGE_GLIS``, as
DEFI_GROUP's INCLUSION then APPUI options do, a node being inside when it
lies within 1 % of the smallest edge of the mesh it belongs to from a
cell). Its mean horizontal acceleration at each instant is the resultant of
the zone's internal forces on the nodes it shares with the rest of the
structure, over its mass. The block slides while that acceleration exceeds
the critical one ``a_y = KY g``: its relative velocity is the trapezoidal
integral of ``a - a_y``, kept non-negative, and the permanent displacement
the trapezoidal integral of that velocity.
"""

from __future__ import annotations

import numpy as np

GRAVITY = 9.81  # code_aster's value in POST_NEWMARK

# vertices of the cells (the first nodes), edges between them in order
_VERTICES = {"SEG2": 2, "SEG3": 2, "TRIA3": 3, "TRIA6": 3, "TRIA7": 3}
_VERTICES |= {"QUAD4": 4, "QUAD8": 4, "QUAD9": 4}
SURFACES = ("TRIA3", "TRIA6", "TRIA7", "QUAD4", "QUAD8", "QUAD9")


def cells_near_centre(mesh, cells, centre, radius) -> np.ndarray:
    """The cells with at least one node at distance <= radius of centre (2D)."""
    centre = np.asarray(centre, dtype=float)[:2]
    near = np.sum((mesh.coords[:, :2] - centre) ** 2, axis=1) <= radius * radius
    return np.array([c for c in cells if near[list(mesh.cell_nodes[c])].any()], dtype=int)


def smallest_edge(mesh) -> float:
    """The shortest edge between consecutive vertices of the mesh's cells."""
    best = np.inf
    for kind in set(mesh.cell_types):
        n = _VERTICES.get(kind)
        if n is None:
            continue
        conn = np.array(
            [mesh.cell_nodes[c][:n] for c in range(mesh.n_cells) if mesh.cell_types[c] == kind]
        )
        pairs = [(0, 1)] if n == 2 else [(k, (k + 1) % n) for k in range(n)]
        for a, b in pairs:
            lengths = np.linalg.norm(
                mesh.coords[conn[:, a], :2] - mesh.coords[conn[:, b], :2], axis=1
            )
            best = min(best, float(lengths.min()))
    return best


def _triangles(mesh, cells) -> np.ndarray:
    """(t, 3) vertex triangles covering the surface cells (quadrangles cut in two)."""
    out = []
    for c in cells:
        kind = mesh.cell_types[c]
        nodes = mesh.cell_nodes[c]
        if _VERTICES.get(kind) == 3:
            out.append(nodes[:3])
        elif _VERTICES.get(kind) == 4:
            out.extend([(nodes[0], nodes[1], nodes[2]), (nodes[0], nodes[2], nodes[3])])
    return np.array(out, dtype=int).reshape(-1, 3)


def _distance_to_segment(points, a, b) -> np.ndarray:
    ab = b - a
    t = np.clip(((points - a) @ ab) / max(float(ab @ ab), 1e-300), 0.0, 1.0)
    return np.linalg.norm(points - (a + t[:, None] * ab), axis=1)


def points_in_cells(points: np.ndarray, mesh, cells, tolerance: float) -> np.ndarray:
    """Mask of the 2D points inside the surface cells of ``mesh`` or within
    ``tolerance`` of one of them."""
    points = np.asarray(points, dtype=float)[:, :2]
    inside = np.zeros(len(points), dtype=bool)
    triangles = _triangles(mesh, cells)
    if not triangles.size:
        return inside
    corners = mesh.coords[triangles][..., :2]  # (t, 3, 2)
    low = corners.min(axis=1) - tolerance
    high = corners.max(axis=1) + tolerance
    order = np.argsort(points[:, 0])
    xs = points[order, 0]
    for k in range(len(triangles)):
        first = np.searchsorted(xs, low[k, 0], side="left")
        last = np.searchsorted(xs, high[k, 0], side="right")
        candidates = order[first:last]
        candidates = candidates[~inside[candidates]]
        ys = points[candidates, 1]
        candidates = candidates[(ys >= low[k, 1]) & (ys <= high[k, 1])]
        if not candidates.size:
            continue
        p = points[candidates]
        a, b, c = corners[k]
        matrix = np.column_stack([b - a, c - a])
        if abs(np.linalg.det(matrix)) < 1e-300:
            continue
        local = np.linalg.solve(matrix, (p - a).T).T
        bary = np.column_stack([1.0 - local.sum(axis=1), local])
        hit = np.all(bary >= 0.0, axis=1)
        if tolerance > 0.0 and not hit.all():
            rest = ~hit
            distance = np.min(
                [_distance_to_segment(p[rest], u, v) for u, v in ((a, b), (b, c), (c, a))], axis=0
            )
            hit[rest] = distance <= tolerance
        inside[candidates[hit]] = True
    return inside


def cells_inside_mesh(mesh, cells, other, other_cells) -> np.ndarray:
    """The cells of ``mesh`` (among ``cells``) with at least one node inside
    ``other``'s cells that have at least one node inside ``cells``."""
    own_nodes = np.unique(np.concatenate([mesh.cell_nodes[c] for c in cells]))
    other_nodes = np.unique(np.concatenate([other.cell_nodes[c] for c in other_cells]))
    # the other mesh's cells reaching into the structure
    reached = np.zeros(other.n_nodes, dtype=bool)
    reached[other_nodes] = points_in_cells(
        other.coords[other_nodes], mesh, cells, 0.01 * smallest_edge(other)
    )
    domain = [c for c in other_cells if reached[list(other.cell_nodes[c])].any()]
    included = np.zeros(mesh.n_nodes, dtype=bool)
    included[own_nodes] = points_in_cells(
        mesh.coords[own_nodes], other, domain, 0.01 * smallest_edge(mesh)
    )
    return np.array([c for c in cells if included[list(mesh.cell_nodes[c])].any()], dtype=int)


def newmark_displacement(times, acceleration, critical):
    """(velocity, displacement) of the block: v' = a - a_y while v > 0 (v
    kept non-negative, trapezoids), d the trapezoidal integral of v."""
    times = np.asarray(times, dtype=float)
    excess = np.asarray(acceleration, dtype=float) - critical
    velocity = np.zeros(times.size)
    for i in range(1, times.size):
        step = 0.5 * (excess[i] + excess[i - 1]) * (times[i] - times[i - 1])
        velocity[i] = max(0.0, velocity[i - 1] + step)
    displacement = np.concatenate(
        [[0.0], np.cumsum(0.5 * (velocity[1:] + velocity[:-1]) * np.diff(times))]
    )
    return velocity, displacement
