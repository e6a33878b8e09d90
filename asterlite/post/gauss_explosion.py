"""Values of a Gauss-point field at arbitrary points, as PROJ_CHAMP
METHODE='ECLA_PG' finds them (code_aster's ecla2d tables).

Each plane source cell is split into one sub-cell per Gauss point, built on
its vertices, the middles of its edges and its centre; the field is constant
on a sub-cell (the value at its Gauss point), so a point takes the value of
the sub-cell it falls in (or of the nearest one, as collocation places
points outside every cell: past DISTANCE_MAX when given, they get no
value). Families handled, with the sub-cells of ecla2d (vertices 1.., edge
middles next, then the centre):

* triangles, FPG1: the triangle itself;
* triangles, FPG3: three quadrangles about the centroid;
* quadrangles, FPG4: four quadrangles about the centre, one per vertex;
* quadrangles, FPG9: nine quadrangles on the edges' third points and four
  inner points (each the mean of three vertices).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.concepts.mesh import Mesh
from asterlite.post.field_projection import place_nodes


# the points sub-cells are built on, as weights of the cell's vertices (ecla2d)
def _mix(n_vertices: int, *pairs) -> list[float]:
    row = [0.0] * n_vertices
    for vertex, weight in pairs:
        row[vertex] = weight
    total = sum(row)
    return [w / total for w in row]


def _corners_middles_centre(n: int) -> list[list[float]]:
    corners = [_mix(n, (k, 1)) for k in range(n)]
    middles = [_mix(n, (k, 1), ((k + 1) % n, 1)) for k in range(n)]
    return corners + middles + [_mix(n, *[(k, 1) for k in range(n)])]


_THIRDS = [_mix(4, (k, 1)) for k in range(4)]
for _k in range(4):
    _THIRDS += [_mix(4, (_k, 2), ((_k + 1) % 4, 1)), _mix(4, (_k, 1), ((_k + 1) % 4, 2))]
_THIRDS += [_mix(4, (0, 1), (1, 1), (3, 1)), _mix(4, (0, 1), (1, 1), (2, 1))]
_THIRDS += [_mix(4, (1, 1), (2, 1), (3, 1)), _mix(4, (0, 1), (2, 1), (3, 1))]

# (points, sub-cells as lists of those points), one sub-cell per Gauss point
# in the Gauss points' order; corners_middles_centre numbers the vertices
# 0..v-1, the edge middles v..2v-1 (middle k between vertices k and k+1),
# the centre 2v; _THIRDS the vertices 0..3, the third points of edge k at
# 4 + 2k (nearer vertex k) and 5 + 2k, then four inner points
_SUBCELLS = {
    ("TRIA", 1): (_corners_middles_centre(3), [(0, 1, 2)]),
    ("TRIA", 3): (_corners_middles_centre(3), [(0, 3, 6, 5), (1, 4, 6, 3), (4, 2, 5, 6)]),
    ("QUAD", 4): (
        _corners_middles_centre(4),
        [(7, 0, 4, 8), (4, 1, 5, 8), (5, 2, 6, 8), (6, 3, 7, 8)],
    ),
    ("QUAD", 9): (
        _THIRDS,
        [
            (0, 4, 12, 11),
            (1, 6, 13, 5),
            (7, 2, 8, 14),
            (15, 9, 3, 10),
            (5, 13, 12, 4),
            (6, 7, 14, 13),
            (14, 8, 9, 15),
            (15, 10, 11, 12),
            (12, 13, 14, 15),
        ],
    ),
}
_SHAPE = {"TRIA3": ("TRIA", 3), "TRIA6": ("TRIA", 3), "TRIA7": ("TRIA", 3)}
_SHAPE |= {"QUAD4": ("QUAD", 4), "QUAD8": ("QUAD", 4), "QUAD9": ("QUAD", 4)}


def exploded_mesh(mesh: Mesh, cells, n_gauss) -> tuple[Mesh, np.ndarray]:
    """The sub-cells of ``cells`` (n_gauss[i] Gauss points in cells[i]), each
    with its own nodes, and for each sub-cell (cell position, Gauss point)."""
    coords, types, conn, origin = [], [], [], []
    for position, (cell, npg) in enumerate(zip(cells, n_gauss, strict=True)):
        cell_type = mesh.cell_types[int(cell)]
        if cell_type not in _SHAPE:
            raise ValueError(f"ECLA_PG: no sub-cells for {cell_type} cells")
        shape, n_vertices = _SHAPE[cell_type]
        if (shape, int(npg)) not in _SUBCELLS:
            raise ValueError(f"ECLA_PG: no sub-cells for {cell_type} with {npg} Gauss points")
        vertices = mesh.coords[list(mesh.cell_nodes[int(cell)][:n_vertices])]
        weights, subcells = _SUBCELLS[(shape, int(npg))]
        points = np.asarray(weights) @ vertices
        for gauss, local in enumerate(subcells):
            first = len(coords)
            coords.extend(points[list(local)])
            types.append("TRIA3" if len(local) == 3 else "QUAD4")
            conn.append(tuple(range(first, first + len(local))))
            origin.append((position, gauss))
    exploded = Mesh(
        coords=np.array(coords),
        node_names=[f"N{k + 1}" for k in range(len(coords))],
        cell_names=[f"M{k + 1}" for k in range(len(types))],
        cell_types=types,
        cell_nodes=conn,
        dim=2,
    )
    return exploded, np.array(origin, dtype=int).reshape(-1, 2)


@dataclass
class GaussProjection:
    """Where each point takes its value among the sub-cells of a set of cells
    (cell position, Gauss point of each sub-cell in ``origin``): the same for
    every field on those cells, so a field of many instants is placed once."""

    origin: np.ndarray  # (n_sub, 2)
    sub_cell: np.ndarray  # (n_points,) the sub-cell giving each point its value
    scale: np.ndarray  # (n_points,) the sum of the point's weights there (1)
    placed: np.ndarray  # (n_points,) bool

    def apply(self, gauss_values) -> np.ndarray:
        """The field (gauss_values[i]: (n_gauss, n_cmp) of the i-th cell) at
        the points: (n_points, n_cmp), 0 where not placed."""
        sub_values = np.array([gauss_values[p][g] for p, g in self.origin], dtype=float)
        result = sub_values[self.sub_cell] * self.scale[:, None]
        result[~self.placed] = 0.0
        return result


def gauss_projection(
    mesh: Mesh, cells, n_gauss, points: np.ndarray, distance_max: float | None = None
) -> GaussProjection:
    """The placement of ``points`` (n, >=2) among the sub-cells of ``cells``
    (n_gauss[i] Gauss points in cells[i]): within distance_max of a sub-cell
    when given."""
    exploded, origin = exploded_mesh(mesh, cells, n_gauss)
    node_cell = np.empty(exploded.n_nodes, dtype=int)
    for sub, conn in enumerate(exploded.cell_nodes):
        node_cell[list(conn)] = sub
    pts = np.zeros((len(points), 3))
    pts[:, :2] = np.asarray(points, dtype=float)[:, :2]
    placement = place_nodes(
        exploded,
        np.arange(exploded.n_cells),
        exploded,
        np.arange(len(pts)),
        distance_max=distance_max,
        points=pts,
    )
    sub_cell = np.zeros(len(pts), dtype=int)
    scale = np.zeros(len(pts))
    placed = np.zeros(len(pts), dtype=bool)
    for k, (conn, weights) in placement.nodes.items():
        # constant on the sub-cell: its value times the weights' sum (1)
        sub_cell[k], scale[k], placed[k] = node_cell[conn[0]], float(np.sum(weights)), True
    # points outside every sub-cell's box: the nearest sub-cell's value
    for k in placement.unplaced:
        sub, distance = _nearest_subcell(exploded, pts[k, :2])
        if distance_max is None or distance <= distance_max:
            sub_cell[k], scale[k], placed[k] = sub, 1.0, True
    return GaussProjection(origin, sub_cell, scale, placed)


def values_at_points(
    mesh: Mesh, cells, gauss_values, points: np.ndarray, distance_max: float | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """The Gauss-point field (gauss_values[i]: (n_gauss, n_cmp) of cells[i])
    at ``points`` (n, >=2); also a mask of the points placed (within
    distance_max of a sub-cell when given; the others are 0)."""
    projection = gauss_projection(mesh, cells, [len(v) for v in gauss_values], points, distance_max)
    return projection.apply(gauss_values), projection.placed


def _nearest_subcell(exploded: Mesh, point: np.ndarray) -> tuple[int, float]:
    """The sub-cell whose boundary is nearest to ``point`` (outside them all)."""
    best, best_distance = 0, np.inf
    xy = exploded.coords[:, :2]
    for sub, conn in enumerate(exploded.cell_nodes):
        a = xy[list(conn)]
        b = np.roll(a, -1, axis=0)
        edge = b - a
        along = np.einsum("ij,ij->i", point - a, edge) / np.einsum("ij,ij->i", edge, edge)
        t = np.clip(along, 0.0, 1.0)
        distance = float(np.min(np.linalg.norm(a + t[:, None] * edge - point, axis=1)))
        if distance < best_distance:
            best, best_distance = sub, distance
    return best, best_distance
