"""LIRE_MAILLAGE's mesh check (VERI_MAIL, code_aster's chckma), run on every
mesh read unless VERIF='NON'.

Alarms (the run goes on):
- nodes that belong to no cell, nodes shared by more than 200 cells;
- cells with the same nodes as another cell of the same node count;
- flat cells: ``sqrt(d_min^2 / d_max^2) < APLAT``, d the distances between
  any two of the cell's nodes.

Errors (the command stops):
- a cell whose first node appears twice in it;
- two quadratic cells giving one edge (same two vertices) different middle
  nodes, or one face (same vertices) different centre nodes.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from asterlite.fem.mesh_degree import QUADRATIC, edge_vertices
from asterlite.fem.solid_reference import REFERENCE_ELEMENTS

MAX_CELLS_PER_NODE = 200
_CHUNK = 4096
#: quadratic cell -> the linear cell whose edges it has
_LINEAR_OF = {quadratic: linear for linear, (quadratic, _, _) in QUADRATIC.items()}
_LINEAR_OF.update({"HEXA27": "HEXA8", "QUAD9": "QUAD4"})
#: cells with face-centre nodes: reference element, number of vertices
_FACE_CENTRES = {"HEXA27": ("H27", 8), "QUAD9": ("QU9", 4)}
#: face-centre cells this check cannot follow (no reference element here)
UNCHECKED = ("TRIA7", "PENTA18", "PENTA21", "TETRA15", "PYRAM19", "HEXA9")


@dataclass
class MeshCheck:
    """What the check found: alarms (text) and errors (text)."""

    alarms: list[str] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)


def _by_type(mesh) -> dict[str, np.ndarray]:
    groups: dict[str, list[int]] = {}
    for cell, kind in enumerate(mesh.cell_types):
        groups.setdefault(kind, []).append(cell)
    return {k: np.array(v, dtype=int) for k, v in groups.items()}


def _names(names, indices, limit=5) -> str:
    shown = ", ".join(names[int(i)] for i in indices[:limit])
    return shown + (f" and {len(indices) - limit} more" if len(indices) > limit else "")


def check_mesh(mesh, aplat: float = 1.0e-3) -> MeshCheck:
    out = MeshCheck()
    unchecked = sorted({t for t in mesh.cell_types if t in UNCHECKED})
    if unchecked:
        raise NotImplementedError(f"the mesh check of {', '.join(unchecked)} cells")
    groups = _by_type(mesh)
    conn = {
        k: np.array([mesh.cell_nodes[c] for c in cells], dtype=int) for k, cells in groups.items()
    }
    uses = np.zeros(mesh.n_nodes, dtype=int)
    for nodes in conn.values():
        np.add.at(uses, nodes.ravel(), 1)
    orphans = np.nonzero(uses == 0)[0]
    if orphans.size:
        out.alarms.append(
            f"{orphans.size} nodes belong to no cell: {_names(mesh.node_names, orphans)}"
        )
    crowded = np.nonzero(uses > MAX_CELLS_PER_NODE)[0]
    if crowded.size:
        out.alarms.append(
            f"{crowded.size} nodes belong to more than {MAX_CELLS_PER_NODE} cells: "
            f"{_names(mesh.node_names, crowded)}"
        )
    for kind, cells in groups.items():
        nodes = conn[kind]
        if nodes.shape[1] < 2:
            continue
        repeated = cells[np.count_nonzero(nodes == nodes[:, :1], axis=1) > 1]
        if repeated.size:
            out.errors.append(
                f"{repeated.size} {kind} cells hold their first node twice: "
                f"{_names(mesh.cell_names, repeated)}"
            )
        _doubled(mesh, kind, cells, nodes, out)
        _flat(mesh, kind, cells, nodes, aplat, out)
    _quadratic(mesh, groups, conn, out)
    return out


def _doubled(mesh, kind, cells, nodes, out) -> None:
    key = np.sort(nodes, axis=1)
    _, first, counts = np.unique(key, axis=0, return_index=True, return_counts=True)
    if np.any(counts > 1):
        rows = np.unique(key, axis=0, return_inverse=True)[1].ravel()
        twins = [i for i in range(len(cells)) if counts[rows[i]] > 1 and first[rows[i]] != i]
        out.alarms.append(
            f"{len(twins)} {kind} cells have the nodes of another cell: "
            f"{_names(mesh.cell_names, cells[twins])}"
        )


def _flat(mesh, kind, cells, nodes, aplat, out) -> None:
    flat = []
    upper = np.triu_indices(nodes.shape[1], 1)
    for start in range(0, len(cells), _CHUNK):  # bounded memory on big meshes
        x = mesh.coords[nodes[start : start + _CHUNK]]  # (e, n, 3)
        pairs = np.sum((x[:, upper[0], :] - x[:, upper[1], :]) ** 2, axis=2)
        largest = pairs.max(axis=1)
        ratio = np.ones(len(x))
        np.divide(pairs.min(axis=1), largest, where=largest > 0, out=ratio)
        flat.extend((start + np.nonzero((largest > 0) & (np.sqrt(ratio) < aplat))[0]).tolist())
    if flat:
        out.alarms.append(
            f"{len(flat)} {kind} cells are flat (smallest / largest node distance < {aplat:g}): "
            f"{_names(mesh.cell_names, cells[flat])}"
        )


def _quadratic(mesh, groups, conn, out) -> None:
    """Edges: one middle node per vertex pair; faces: one centre per face."""
    edges: list[np.ndarray] = []
    for kind, nodes in conn.items():
        if kind == "SEG4":
            inner = np.sort(nodes[:, 2:4], axis=1)
            ends = np.sort(nodes[:, :2], axis=1)
            edges.append(np.column_stack([ends, inner]))
            continue
        linear = _LINEAR_OF.get(kind)
        if linear is None:
            continue
        n_vertices = QUADRATIC[linear][2]
        for k, (i, j) in enumerate(edge_vertices(linear)):
            ends = np.sort(nodes[:, [i, j]], axis=1)
            middle = nodes[:, n_vertices + k]
            edges.append(np.column_stack([ends, middle, middle]))
    _one_per_key(mesh, edges, 2, "edge", "middle nodes", out)
    faces: list[np.ndarray] = []
    for kind, (reference, n_vertices) in _FACE_CENTRES.items():
        if kind not in conn:
            continue
        ref = REFERENCE_ELEMENTS[reference].nodes
        for centre in range(n_vertices, len(ref)):
            corners = _face_corners(ref, n_vertices, centre)
            if corners is not None:
                nodes = conn[kind]
                faces.append(
                    np.column_stack([np.sort(nodes[:, corners], axis=1), nodes[:, centre]])
                )
    _one_per_key(mesh, faces, 4, "face", "centre nodes", out)


def _face_corners(ref, n_vertices: int, centre: int) -> list[int] | None:
    """The four vertices of the quadrilateral face whose centre is reference
    node ``centre``, or None when that node is no face centre (an edge middle,
    the volume centre)."""
    point, vertices = ref[centre], ref[:n_vertices]
    if len(point) == 2:  # QUAD9: its centre is the centre of the cell
        return list(range(4)) if np.allclose(vertices.mean(axis=0), point) else None
    fixed = [a for a in range(3) if np.isclose(abs(point[a]), 1.0)]
    if len(fixed) != 1:
        return None
    axis = fixed[0]
    corners = [v for v in range(n_vertices) if np.isclose(vertices[v, axis], point[axis])]
    return corners if len(corners) == 4 else None


def _one_per_key(mesh, rows, width, what, nodes_name, out) -> None:
    if not rows:
        return
    table = np.unique(np.vstack(rows), axis=0)
    keys, counts = np.unique(table[:, :width], axis=0, return_counts=True)
    bad = keys[counts > 1]
    if bad.size:
        shown = "; ".join(" ".join(mesh.node_names[int(n)] for n in key) for key in bad[:3])
        out.errors.append(
            f"{len(bad)} {what}s of quadratic cells have different {nodes_name} in two "
            f"cells (vertices {shown})"
        )
