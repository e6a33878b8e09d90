"""Checks code_aster makes on a model's cells when AFFE_MODELE builds it.

Axisymmetric cells (``AXIS``) must lie in x >= 0 (x is the radius): a node
at x < -1e-6 x_max (x_max the mesh's largest x) stops the command.

``AFFE_MODELE`` (``VERI_JACOBIEN='OUI'``, its default) computes the Jacobian
of every 3D and plane solid cell at the points of its RIGI family and warns
about each cell where it changes sign: such a cell is folded (nodes in the
wrong order, or a mid-side node too far from the middle), and its matrices
mean nothing. code_aster raises an alarm, not an error, and so does asterlite.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from asterlite.fem.plane_elements import PLANE_MODELISATIONS, surface_cells
from asterlite.fem.solid_reference import VOLUME_CELLS, tabulated


def folded_cells(model) -> list[int]:
    """Cells whose Jacobian is positive at some RIGI points and negative at
    others (code_aster's te0328), in mesh order."""
    mesh = model.mesh
    groups: dict[tuple, list[int]] = defaultdict(list)
    for cell, modelisation in model.cell_modelisation.items():
        kind = mesh.cell_types[cell]
        if modelisation == "3D" and kind in VOLUME_CELLS:
            groups[VOLUME_CELLS[kind], 3].append(int(cell))
        elif modelisation in PLANE_MODELISATIONS and kind in surface_cells(modelisation):
            groups[surface_cells(modelisation)[kind], 2].append(int(cell))
    folded: list[int] = []
    for (spec, dim), members in groups.items():
        _, grads, _ = tabulated(spec.reference, spec.rigi)
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        coords = mesh.coords[conn][..., :dim]
        # J[e, q] = coords[e]^T grads[q], as batched matrix products (einsum is 5x slower)
        jac = np.matmul(coords[:, None, :, :].transpose(0, 1, 3, 2), grads[None, :, :, :])
        det = np.linalg.det(jac)
        mixed = np.any(det > 0.0, axis=1) & np.any(det < 0.0, axis=1)
        folded.extend(int(c) for c in np.asarray(members)[mixed])
    return sorted(folded)


def negative_radius_nodes(model) -> list[tuple[int, int]]:
    """(node, cell) pairs of AXIS cells with a node at x < -1e-6 |x_max|
    (code_aster's taxis)."""
    mesh = model.mesh
    tolerance = -1e-6 * abs(float(mesh.coords[:, 0].max()))
    out = []
    for cell, modelisation in sorted(model.cell_modelisation.items()):
        if modelisation != "AXIS":
            continue
        for node in mesh.cell_nodes[cell]:
            if mesh.coords[node, 0] < tolerance:
                out.append((int(node), int(cell)))
    return out
