"""MODI_MAILLAGE MODI_MAILLE OPTION='NOEUD_QUART' (code_aster's momaba): the
middle nodes of the edges leaving a crack-front vertex move to the quarter
of the edge from it; the front's own middle nodes (3D) stay; other nodes
do not move."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.errors import CommandError
from asterlite.fem.mesh_degree import edge_vertices
from tests.solid_meshes import box_mesh
from tests.test_fem_plane import grid_mesh
from tests.test_fem_support import FakeSession, run


def _expected(mesh, original, front, linear, n_vertices):
    """Coordinates after NOEUD_QUART, from the edge tables."""
    out = original.copy()
    for nodes in mesh.cell_nodes:
        for k, (i, j) in enumerate(edge_vertices(linear)):
            for tip, other in ((nodes[i], nodes[j]), (nodes[j], nodes[i])):
                if tip in front:
                    out[nodes[n_vertices + k]] = original[tip] + 0.25 * (
                        original[other] - original[tip]
                    )
    return out


def test_quarter_points_around_a_2d_crack_tip():
    mesh = grid_mesh("QUAD8", (2, 2), (2.0, 2.0), (0.0, 0.0))
    mesh.dim = 2
    tip = int(np.argmin(np.linalg.norm(mesh.coords[:, :2] - [1.0, 1.0], axis=1)))
    mesh.node_groups = {**mesh.node_groups, "PF": np.array([tip])}
    original = mesh.coords.copy()
    run(FakeSession(), "MODI_MAILLAGE", MAILLAGE=mesh,
        MODI_MAILLE={"OPTION": "NOEUD_QUART", "GROUP_NO_FOND": "PF"})  # fmt: skip
    expected = _expected(mesh, original, {tip}, "QUAD4", 4)
    np.testing.assert_allclose(mesh.coords, expected, atol=1e-14)
    moved = np.flatnonzero(np.any(mesh.coords != original, axis=1))
    assert moved.size == 4  # the four edges leaving the centre node
    for node in moved:
        assert np.linalg.norm(mesh.coords[node] - original[tip]) == pytest.approx(0.25)


def test_quarter_points_along_a_3d_front_keep_the_front_middles():
    mesh = box_mesh("HEXA20", n=(2, 2, 1), size=(2.0, 2.0, 1.0))
    centre = np.linalg.norm(mesh.coords[:, :2] - [1.0, 1.0], axis=1) < 1e-12
    front = [int(n) for n in np.flatnonzero(centre)]  # z = 0, 0.5, 1 on the axis
    assert len(front) == 3
    mesh.node_groups = {**mesh.node_groups, "FOND": np.array(front)}
    original = mesh.coords.copy()
    run(FakeSession(), "MODI_MAILLAGE", MAILLAGE=mesh,
        MODI_MAILLE={"OPTION": "NOEUD_QUART", "GROUP_NO_FOND": "FOND"})  # fmt: skip
    vertices = {n for n in front if abs(original[n, 2] - 0.5) > 1e-12}
    expected = _expected(mesh, original, vertices, "HEXA8", 8)
    middle = next(n for n in front if n not in vertices)
    expected[middle] = original[middle]  # the front's own middle node stays
    np.testing.assert_allclose(mesh.coords, expected, atol=1e-14)


def test_noeud_quart_refusals():
    mesh = grid_mesh("QUAD4", (1, 1), (1.0, 1.0), (0.0, 0.0))
    mesh.dim = 2
    mesh.node_groups = {**mesh.node_groups, "PF": np.array([0])}
    with pytest.raises(CommandError, match="no quadratic cell"):
        run(FakeSession(), "MODI_MAILLAGE", MAILLAGE=mesh,
            MODI_MAILLE={"OPTION": "NOEUD_QUART", "GROUP_NO_FOND": "PF"})  # fmt: skip
    mesh.node_groups = {**mesh.node_groups, "TWO": np.array([0, 1])}
    with pytest.raises(CommandError, match="a 2D crack front is one node"):
        run(FakeSession(), "MODI_MAILLAGE", MAILLAGE=mesh,
            MODI_MAILLE={"OPTION": "NOEUD_QUART", "GROUP_NO_FOND": "TWO"})  # fmt: skip
