"""The disc mesh code_aster builds with ``Mesh.buildDisk(radius, refine)``
(used by POST_NEWMARK to sample the slip circle).

code_aster maps a structured (r, theta) grid of ``2 * 2**refine`` radial by
``8 * 2**refine`` angular segments to the plane, merges the nodes at the
centre and at theta = 2 pi with those at theta = 0, and turns the
degenerated quadrangles at the centre into triangles: TRIA3 around the
centre, QUAD4 elsewhere, all counter-clockwise, and the SEG2 of the outer
circle (group REXT, anticlockwise along it); SURFACE groups the 2D cells.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.mesh import Mesh


def disk_mesh(radius: float = 1.0, refine: int = 0, centre=(0.0, 0.0)) -> Mesh:
    """The plane disc mesh of buildDisk, translated to ``centre``."""
    if radius <= 0.0:
        raise ValueError("the radius of the disc must be positive")
    if refine < 0:
        raise ValueError("the refinement level of the disc must be >= 0")
    n_radial = 2 * 2**refine
    n_angular = 8 * 2**refine
    radii = radius * np.arange(1, n_radial + 1) / n_radial
    angles = 2.0 * np.pi * np.arange(n_angular) / n_angular
    # node 0 the centre, then ring i (1-based) angle j at 1 + (i-1) n_angular + j
    coords = np.zeros((1 + n_radial * n_angular, 3))
    coords[1:, 0] = np.repeat(radii, n_angular) * np.tile(np.cos(angles), n_radial)
    coords[1:, 1] = np.repeat(radii, n_angular) * np.tile(np.sin(angles), n_radial)
    coords[:, 0] += centre[0]
    coords[:, 1] += centre[1]

    def node(ring: int, angle: int) -> int:
        return 0 if ring == 0 else 1 + (ring - 1) * n_angular + angle % n_angular

    cell_types: list[str] = []
    cell_nodes: list[tuple[int, ...]] = []
    for j in range(n_angular):
        cell_types.append("TRIA3")
        cell_nodes.append((0, node(1, j), node(1, j + 1)))
    for i in range(1, n_radial):
        for j in range(n_angular):
            cell_types.append("QUAD4")
            cell_nodes.append((node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)))
    n_surface = len(cell_types)
    for j in range(n_angular):
        cell_types.append("SEG2")
        cell_nodes.append((node(n_radial, j), node(n_radial, j + 1)))
    return Mesh(
        coords=coords,
        node_names=[f"N{k + 1}" for k in range(len(coords))],
        cell_names=[f"M{k + 1}" for k in range(len(cell_types))],
        cell_types=cell_types,
        cell_nodes=cell_nodes,
        cell_groups={
            "SURFACE": np.arange(n_surface, dtype=int),
            "REXT": np.arange(n_surface, len(cell_types), dtype=int),
        },
        dim=2,
    )
