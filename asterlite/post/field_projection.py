"""Collocation of nodal fields from one mesh to another (PROJ_CHAMP).

Each target node is located in the source cells of the highest dimension
(code_aster's automatic case: volumes, else surfaces, else lines): the cell
whose reference coordinate places the node inside (within a small relative
tolerance), else the nearest one (within DISTANCE_MAX when given). Its
value is the shape-function combination of the cell's nodal values, each
component on its own, as code_aster's collocation does.

Located exactly: nodes inside line cells (SEG2, SEG3), nodes that coincide
with a node of a source cell of any type (there the shape functions reduce
to that node's value), and nodes inside surface and volume cells, whose
reference coordinates Newton's method finds from the cell's own shape
functions (code_aster's reereg; its tetrahedral search only gives the
starting point there): the weights are those shape functions at that point.
A surface cell in 3D is reached by the nearest point of the surface.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.concepts.mesh import Mesh
from asterlite.fem.solid_reference import FACE_CELLS, REFERENCE_ELEMENTS, VOLUME_CELLS

_DIMENSION = {
    "POI1": 0,
    "SEG2": 1,
    "SEG3": 1,
    "SEG4": 1,
    "TRIA3": 2,
    "TRIA6": 2,
    "TRIA7": 2,
    "QUAD4": 2,
    "QUAD8": 2,
    "QUAD9": 2,
}

#: relative tolerance (of a cell's size) for "the node lies in the cell"
INSIDE_TOLERANCE = 1.0e-6


class ProjectionError(ValueError):
    """A node the projection cannot place."""


class ProjectionUnsupported(ProjectionError):
    """A placement asterlite does not compute (inside a surface or volume cell)."""


@dataclass
class Placement:
    """Target node -> (source node indices, weights)."""

    nodes: dict[int, tuple[np.ndarray, np.ndarray]]
    unplaced: list[int]
    farthest: float  # largest distance of a node placed outside every cell


def cell_dimension(cell_type: str) -> int:
    return _DIMENSION.get(cell_type, 3)


def source_cells(mesh: Mesh, cells: np.ndarray | None, dimension: int | None = None) -> np.ndarray:
    """The cells used: those of the highest dimension among ``cells`` (all by
    default), or of ``dimension`` when the deck forces it (CAS_FIGURE)."""
    if cells is None:
        cells = np.arange(mesh.n_cells)
    cells = np.asarray(cells, dtype=int)
    if cells.size == 0:
        return cells
    dims = np.array([cell_dimension(mesh.cell_types[c]) for c in cells])
    return cells[dims == (dims.max() if dimension is None else dimension)]


def _segment_weights(cell_type: str, t: float) -> np.ndarray:
    """Shape functions at fraction ``t`` of a straight segment (corners first)."""
    if cell_type == "SEG2":
        return np.array([1.0 - t, t])
    if cell_type == "SEG3":
        xi = 2.0 * t - 1.0
        return np.array([xi * (xi - 1.0) / 2.0, xi * (xi + 1.0) / 2.0, 1.0 - xi * xi])
    raise ProjectionUnsupported(f"interpolation in {cell_type} cells")


def _on_segment(coords: np.ndarray, conn, point: np.ndarray) -> tuple[float, float]:
    """(fraction along the chord, distance to it, clamped to the segment)."""
    a, b = coords[conn[0]], coords[conn[1]]
    chord = b - a
    length2 = float(chord @ chord)
    t = float((point - a) @ chord) / length2 if length2 > 0.0 else 0.0
    clamped = min(max(t, 0.0), 1.0)
    return t, float(np.linalg.norm(a + clamped * chord - point))


def place_nodes(
    source: Mesh,
    cells: np.ndarray,
    target: Mesh,
    nodes: np.ndarray,
    distance_max: float | None = None,
    points: np.ndarray | None = None,
) -> Placement:
    """Where each target node falls among the source cells, and its weights;
    ``points`` (one row per node of ``nodes``): where to look for them
    instead of their coordinates (a transformation of mesh 2)."""
    placed: dict[int, tuple[np.ndarray, np.ndarray]] = {}
    unplaced: list[int] = []
    farthest = 0.0
    coords = source.coords
    cell_nodes = [np.asarray(source.cell_nodes[c], dtype=int) for c in cells]
    sizes = [_cell_size(coords[conn]) for conn in cell_nodes]
    nearby = _neighbourhoods(coords, cell_nodes, sizes)
    for position, node in enumerate(nodes):
        point = target.coords[node] if points is None else points[position]
        best = None  # (distance, inside?, position)
        for k in nearby(point):
            conn = cell_nodes[k]
            found = _locate(source.cell_types[cells[k]], coords, conn, point, sizes[k])
            if found is None:
                continue
            distance, inside, weights = found
            if inside:
                best = (distance, True, conn, weights)
                break
            if best is None or distance < best[0]:
                best = (distance, False, conn, weights)
        if best is None:
            unplaced.append(int(node))
            continue
        distance, inside, conn, weights = best
        if not inside:
            if distance_max is not None and distance > distance_max:
                unplaced.append(int(node))
                continue
            farthest = max(farthest, distance)
        placed[int(node)] = (conn, weights)
    return Placement(placed, unplaced, farthest)


def _neighbourhoods(coords, cell_nodes, sizes):
    """Candidate cells of a point, in cell order: those whose centre lies within
    the largest cell size (every cell when none does, for the nearest one)."""
    from scipy.spatial import cKDTree

    if not cell_nodes:
        return lambda point: []
    centres = np.array([coords[conn].mean(axis=0) for conn in cell_nodes])
    tree = cKDTree(centres)
    radius = max(sizes) * (1.0 + INSIDE_TOLERANCE)
    everything = list(range(len(cell_nodes)))

    def candidates(point):
        found = tree.query_ball_point(point, radius)
        return sorted(found) if found else everything

    return candidates


def _cell_size(points: np.ndarray) -> float:
    span = points.max(axis=0) - points.min(axis=0)
    return float(np.linalg.norm(span)) or 1.0


def _locate(cell_type, coords, conn, point, size):
    """(distance, inside, weights) of ``point`` for one cell; None when the
    cell cannot be used for it."""
    tolerance = INSIDE_TOLERANCE * size
    gaps = np.linalg.norm(coords[conn] - point, axis=1)
    corner = int(np.argmin(gaps))
    if gaps[corner] <= tolerance:  # on a node: every shape function is 0 or 1
        weights = np.zeros(len(conn))
        weights[corner] = 1.0
        return float(gaps[corner]), True, weights
    if cell_dimension(cell_type) == 1:
        t, distance = _on_segment(coords, conn, point)
        inside = -INSIDE_TOLERANCE <= t <= 1.0 + INSIDE_TOLERANCE and distance <= tolerance
        return distance, inside, _segment_weights(cell_type, min(max(t, 0.0), 1.0))
    if cell_dimension(cell_type) == 0:
        return float(gaps[corner]), False, np.ones(1)
    lower, upper = coords[conn].min(axis=0) - tolerance, coords[conn].max(axis=0) + tolerance
    if np.all(point >= lower) and np.all(point <= upper):
        return _in_cell(cell_type, coords[conn], point, tolerance)
    return None


def _reference(cell_type: str):
    kind = VOLUME_CELLS.get(cell_type) or FACE_CELLS.get(cell_type)
    if kind is None:
        raise ProjectionUnsupported(f"interpolation inside {cell_type} cells")
    return REFERENCE_ELEMENTS[kind.reference]


def _in_cell(cell_type, nodes, point, tolerance):
    """(distance, inside, weights) of ``point`` for a surface or volume cell:
    the reference point whose image is ``point`` (least squares: the nearest
    point of a surface in 3D), by Gauss-Newton from the reference centre."""
    reference = _reference(cell_type)
    xi = reference.nodes.mean(axis=0)
    for _ in range(30):
        image = reference.values(xi)[0].real @ nodes
        jacobian = nodes.T @ reference.gradients(xi)[0]  # (3, dim)
        step = np.linalg.lstsq(jacobian, point - image, rcond=None)[0]
        xi = xi + step
        if np.linalg.norm(step) <= 1e-13 * (1.0 + np.linalg.norm(xi)):
            break
    else:
        return None  # no reference point found: the cell is no candidate
    inside = _in_reference(reference.name, xi, INSIDE_TOLERANCE)
    if not inside:
        xi = _clamped(reference.name, xi)
    weights = reference.values(xi)[0].real
    distance = float(np.linalg.norm(weights @ nodes - point))
    return distance, inside and distance <= tolerance, weights


_BOXES = ("HE8", "H20", "H27", "QU4", "QU8", "QU9")
_SIMPLICES = ("TE4", "T10", "TR3", "TR6")
_WEDGES = ("PE6", "P15")  # x along the axis, (y, z) in a triangle; else pyramids


def _in_reference(name: str, xi: np.ndarray, tol: float) -> bool:
    if name in _BOXES:
        return bool(np.all(np.abs(xi) <= 1.0 + tol))
    if name in _SIMPLICES:
        return bool(np.all(xi >= -tol)) and xi.sum() <= 1.0 + tol
    if name in _WEDGES:
        return abs(xi[0]) <= 1.0 + tol and bool(np.all(xi[1:] >= -tol)) and xi[1:].sum() <= 1 + tol
    # pyramids: |x| + |y| <= 1 - z, 0 <= z <= 1
    return -tol <= xi[2] <= 1.0 + tol and abs(xi[0]) + abs(xi[1]) <= 1.0 - xi[2] + tol


def _clamped(name: str, xi: np.ndarray) -> np.ndarray:
    """A reference point of the cell near ``xi`` (for the distance of a point
    outside every cell)."""
    xi = xi.copy()
    if name in _BOXES:
        return np.clip(xi, -1.0, 1.0)
    if name in _SIMPLICES:
        return _simplex_clamped(xi)
    if name in _WEDGES:
        xi[0] = min(max(xi[0], -1.0), 1.0)
        xi[1:] = _simplex_clamped(xi[1:])
        return xi
    xi[2] = min(max(xi[2], 0.0), 1.0)
    spread = abs(xi[0]) + abs(xi[1])
    if spread > 1.0 - xi[2]:
        xi[:2] *= (1.0 - xi[2]) / spread
    return xi


def _simplex_clamped(xi: np.ndarray) -> np.ndarray:
    xi = np.maximum(xi, 0.0)
    total = xi.sum()
    return xi / total if total > 1.0 else xi


def project_values(
    placement: Placement,
    source_index: dict,
    source_values: np.ndarray,
    target_dofs: list[tuple[int, str]],
    default: float = 0.0,
) -> tuple[np.ndarray, int]:
    """Values on ``target_dofs`` ((n_states, n_target)) from ``source_values``
    ((n_states, n_source)) on DOFs ``source_index`` ((node, cmp) -> column);
    a DOF the projection does not reach gets ``default``. Also returns how many
    DOFs were not reached."""
    states = source_values.shape[0]
    # complex for a harmonic result's fields
    dtype = np.result_type(source_values, float)
    out = np.full((states, len(target_dofs)), default, dtype=dtype)
    missed = 0
    for j, (node, component) in enumerate(target_dofs):
        where = placement.nodes.get(int(node))
        if where is None:
            missed += 1
            continue
        conn, weights = where
        columns = [source_index.get((int(n), component)) for n in conn]
        used = [(c, w) for c, w in zip(columns, weights, strict=True) if w != 0.0]
        if any(c is None for c, _ in used) or not used:
            missed += 1
            continue
        out[:, j] = sum(w * source_values[:, c] for c, w in used)
    return out, missed
