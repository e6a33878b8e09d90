"""ORIE_PEAU on plane meshes: skin edges turned so that their normal (dy, -dx)
points out of the surface cell they bound (code_aster's 2D skins), on a mesh
with 2D or constant-Z 3D coordinates."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.fem.skin import SkinError, is_plane, orient_edges


def _square(z=0.0):
    """Unit square split into two TRIA3 (diagonal 0-2) and one QUAD8-free
    skin: four SEG2 edges and one SEG3, given in mixed orientations."""
    coords = np.array(
        [[0, 0, z], [1, 0, z], [1, 1, z], [0, 1, z], [0.5, 0, z]], dtype=float
    )  # node 4: middle of the bottom edge
    cells = [(0, 1, 2), (0, 2, 3), (1, 0, 4), (1, 2), (3, 2), (0, 3)]
    types = ["TRIA3", "TRIA3", "SEG3", "SEG2", "SEG2", "SEG2"]
    return Mesh(
        coords=coords,
        node_names=[f"N{i}" for i in range(5)],
        cell_names=[f"M{i}" for i in range(len(cells))],
        cell_types=types,
        cell_nodes=cells,
        node_groups={},
        cell_groups={"SURF": np.array([0, 1]), "SKIN": np.array([2, 3, 4, 5])},
    )


def _outward(mesh, edge):
    a, b = mesh.cell_nodes[edge][:2]
    t = mesh.coords[b, :2] - mesh.coords[a, :2]
    normal = np.array([t[1], -t[0]])
    middle = mesh.coords[[a, b], :2].mean(axis=0)
    return float(normal @ (middle - (0.5, 0.5)))


def test_skin_edges_point_out_of_the_surface():
    mesh = _square(z=2.5)
    assert is_plane(mesh)
    before = [_outward(mesh, e) > 0 for e in (2, 3, 4, 5)]
    count = orient_edges(mesh, [2, 3, 4, 5], [0, 1])
    assert count == before.count(False) == 3
    assert all(_outward(mesh, e) > 0 for e in (2, 3, 4, 5))
    assert mesh.cell_nodes[2] == (0, 1, 4)  # a SEG3 keeps its middle node last
    assert orient_edges(mesh, [2, 3, 4, 5], [0, 1]) == 0


def test_an_inner_edge_needs_the_inner_side():
    mesh = _square()
    mesh.cell_types.append("SEG2")
    mesh.cell_nodes.append((0, 2))  # the diagonal, between both triangles
    mesh.cell_names.append("DIAG")
    with pytest.raises(SkinError, match="GROUP_MA_INTERNE"):
        orient_edges(mesh, [6])
    assert orient_edges(mesh, [6], [1]) in (0, 1)
    assert _outward_of(mesh, 6, 1) > 0


def _outward_of(mesh, edge, cell):
    a, b = mesh.cell_nodes[edge][:2]
    t = mesh.coords[b, :2] - mesh.coords[a, :2]
    inside = mesh.coords[list(mesh.cell_nodes[cell]), :2].mean(axis=0)
    return float(np.array([t[1], -t[0]]) @ (mesh.coords[[a, b], :2].mean(axis=0) - inside))


def test_a_warped_mesh_is_not_plane():
    mesh = _square()
    mesh.coords[2, 2] = 0.1
    assert not is_plane(mesh)


def test_an_edge_on_no_surface_is_left_as_it_is():
    """code_aster's orilma leaves a skin cell with no cell behind it alone."""
    mesh = _square()
    alone: list[int] = []
    # the skin against the first triangle only: the top and left edges bound none
    orient_edges(mesh, [2, 3, 4, 5], [0], alone)
    assert alone == [4, 5] and mesh.cell_nodes[4] == (3, 2) and mesh.cell_nodes[5] == (0, 3)
    assert _outward(mesh, 2) > 0 and _outward(mesh, 3) > 0
