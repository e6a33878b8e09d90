"""Collocation inside surface and volume cells (PROJ_CHAMP, OBSERVATION):
the cell's shape functions at the reference point of the node, found by
Newton's method, reproduce a linear field on distorted cells of every
kind and a trilinear one on a box of HEXA8."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.post import field_projection as fp
from tests.solid_meshes import box_mesh

SIZE = (1.0, 0.8, 1.2)


def _targets(points) -> Mesh:
    n = len(points)
    return Mesh(
        coords=np.asarray(points, dtype=float),
        node_names=[f"C{i}" for i in range(n)],
        cell_names=[f"P{i}" for i in range(n)],
        cell_types=["POI1"] * n,
        cell_nodes=[(i,) for i in range(n)],
    )


def _interpolated(mesh, points, function):
    target = _targets(points)
    cells = fp.source_cells(mesh, None)
    placement = fp.place_nodes(mesh, cells, target, np.arange(len(points)))
    assert not placement.unplaced
    index = {(n, "X"): n for n in range(mesh.n_nodes)}
    values, missed = fp.project_values(
        placement, index, function(mesh.coords)[None, :], [(n, "X") for n in range(len(points))]
    )
    assert missed == 0
    return values[0]


def _inner_points(seed=1, count=12):
    rng = np.random.default_rng(seed)
    return rng.uniform(0.05, 0.95, (count, 3)) * np.array(SIZE)


def _linear(x):
    return 1.5 + 2.0 * x[:, 0] - 3.0 * x[:, 1] + 0.5 * x[:, 2]


@pytest.mark.parametrize(
    "kind", ["HEXA8", "HEXA20", "HEXA27", "PENTA6", "PENTA15", "TETRA4", "TETRA10", "PYRAM5"]
)
def test_a_linear_field_is_reproduced_inside_distorted_cells(kind):
    mesh = box_mesh(kind, n=(2, 2, 2), size=SIZE, jitter=0.2, seed=3)
    points = _inner_points()
    np.testing.assert_allclose(_interpolated(mesh, points, _linear), _linear(points), rtol=1e-11)


def test_a_trilinear_field_is_reproduced_in_box_hexa8():
    mesh = box_mesh("HEXA8", n=(2, 3, 2), size=SIZE)
    points = _inner_points(seed=7)

    def trilinear(x):
        return x[:, 0] * x[:, 1] * x[:, 2] + x[:, 0] * x[:, 1] - 2.0 * x[:, 2]

    np.testing.assert_allclose(
        _interpolated(mesh, points, trilinear), trilinear(points), rtol=1e-11
    )


def test_a_point_of_a_plane_mesh_inside_a_quad4():
    coords = np.array([[0, 0, 0], [2, 0, 0], [2.5, 1.5, 0], [0, 1, 0]], dtype=float)
    mesh = Mesh(coords, ["A", "B", "C", "D"], ["Q"], ["QUAD4"], [(0, 1, 2, 3)], dim=2)
    points = np.array([[1.0, 0.5, 0.0], [2.0, 1.0, 0.0]])
    np.testing.assert_allclose(_interpolated(mesh, points, _linear), _linear(points), rtol=1e-12)


def test_a_point_on_a_warped_quad4_in_3d():
    coords = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0.2], [0, 1, 0]], dtype=float)
    mesh = Mesh(coords, ["A", "B", "C", "D"], ["Q"], ["QUAD4"], [(0, 1, 2, 3)])
    # the image of reference point (0.2, -0.4): bilinear in the node values
    weights = np.array([0.8 * 1.4, 1.2 * 1.4, 1.2 * 0.6, 0.8 * 0.6]) / 4.0
    point = weights @ coords
    values = _interpolated(mesh, point[None, :], lambda x: x[:, 0] ** 2 + 3.0 * x[:, 2])
    assert values[0] == pytest.approx(weights @ (coords[:, 0] ** 2 + 3.0 * coords[:, 2]))
