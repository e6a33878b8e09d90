"""Unit normals (and, on 2D edges, tangents) at the nodes of a set of skin
cells, as code_aster's canort computes them for FACE_IMPO DNOR / DTAN.

At each node, every cell of the set that holds it gives its unit normal at
that node (from the shape-function derivatives at the node's reference
position: ``dx/dxi x dx/deta`` on faces of 3D meshes, ``(dy/dxi, -dx/dxi)``
on edges of plane meshes); the node's normal is the mean of those, made unit.
A node where they differ by more than 10 degrees is reported (an alarm in
code_aster), one where they cancel out is an error.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem.element_errors import ElementError
from asterlite.fem.solid_reference import FACE_CELLS, REFERENCE_ELEMENTS

# SEG3: nodes at xi = -1, +1, 0 (code_aster's order); derivatives at each node
_SEG_DERIVATIVES = {
    "SEG2": np.array([[-0.5, 0.5], [-0.5, 0.5]]),
    "SEG3": np.array([[-1.5, -0.5, 2.0], [0.5, 1.5, -2.0], [-0.5, 0.5, 0.0]]),
}
SPREAD_ALARM_DEGREES = 10.0


def _cell_vectors(mesh, cell: int, dim: int, tangent: bool) -> tuple[list[int], np.ndarray]:
    """The cell's nodes and its unit normal (or tangent) at each of them."""
    kind = mesh.cell_types[cell]
    nodes = list(mesh.cell_nodes[cell])
    x = mesh.coords[nodes]
    if dim == 2:
        if kind not in _SEG_DERIVATIVES:
            raise ElementError(f"cell {mesh.cell_names[cell]} ({kind}) is not an edge (SEG2/SEG3)")
        d = _SEG_DERIVATIVES[kind] @ x[:, :2]  # (n, 2): dx/dxi at each node
        vectors = d if tangent else np.column_stack([d[:, 1], -d[:, 0]])
    else:
        if kind not in FACE_CELLS:
            raise ElementError(
                f"cell {mesh.cell_names[cell]} ({kind}) is not a face (TRIA3/6, QUAD4/8/9)"
            )
        if tangent:
            raise ElementError("tangents of faces of 3D meshes are not defined (DTAN is 2D only)")
        ref = REFERENCE_ELEMENTS[FACE_CELLS[kind].reference]
        grads = ref.gradients(ref.nodes)  # (n, n, 2): at each node, of each shape
        t = np.einsum("pnj,ni->pji", grads, x)
        vectors = np.cross(t[:, 0, :], t[:, 1, :])
    length = np.linalg.norm(vectors, axis=1)
    if np.any(length <= 0.0):
        raise ElementError(f"cell {mesh.cell_names[cell]} is degenerate")
    return nodes, vectors / length[:, None]


def node_normals(mesh, cells, nodes, dim: int, tangent: bool = False, log=None) -> np.ndarray:
    """Unit vectors (len(nodes), dim) at ``nodes`` from the cells ``cells``."""
    where = {int(n): k for k, n in enumerate(nodes)}
    contributions: list[list[np.ndarray]] = [[] for _ in nodes]
    for cell in cells:
        cell_nodes, vectors = _cell_vectors(mesh, int(cell), dim, tangent)
        for node, vector in zip(cell_nodes, vectors, strict=True):
            if int(node) in where:
                contributions[where[int(node)]].append(vector)
    out = np.zeros((len(nodes), dim))
    for k, vectors in enumerate(contributions):
        name = mesh.node_names[int(nodes[k])]
        if not vectors:
            raise ElementError(f"node {name} belongs to none of the cells")
        mean = np.mean(vectors, axis=0)
        size = np.linalg.norm(mean)
        if size < 1.0e-2:
            raise ElementError(f"the normals of the cells around node {name} cancel out")
        out[k] = mean / size
        cosines = np.clip(np.asarray(vectors) @ out[k], -1.0, 1.0)
        spread = float(np.degrees(np.arccos(cosines.min())))
        if spread > SPREAD_ALARM_DEGREES and log is not None:
            log(f"alarm: normals of the cells around node {name} differ by {spread:.3g} degrees")
    return out
