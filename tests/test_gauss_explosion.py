"""Gauss-point fields at points by the sub-cells of PROJ_CHAMP ECLA_PG
(asterlite.post.gauss_explosion)."""

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.post.gauss_explosion import exploded_mesh, values_at_points


def _mesh():
    # a unit square QUAD4 and a triangle on its right side
    coords = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0.5, 0]], dtype=float)
    return Mesh(
        coords=coords,
        node_names=[f"N{k}" for k in range(5)],
        cell_names=["Q", "T"],
        cell_types=["QUAD4", "TRIA3"],
        cell_nodes=[(0, 1, 2, 3), (1, 4, 2)],
        dim=2,
    )


def test_subcells_tile_the_cells():
    mesh = _mesh()
    exploded, origin = exploded_mesh(mesh, [0, 1], [4, 3])
    assert exploded.n_cells == 7 and origin.tolist()[:5] == [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0]]
    for conn in exploded.cell_nodes:
        x, y = exploded.coords[list(conn), 0], exploded.coords[list(conn), 1]
        assert 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y) > 0.0
    # quarters of the square: each 0.25; thirds of the triangle (area 0.5)
    areas = []
    for conn in exploded.cell_nodes:
        x, y = exploded.coords[list(conn), 0], exploded.coords[list(conn), 1]
        areas.append(0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))
    assert areas == pytest.approx([0.25] * 4 + [0.5 / 3] * 3)


def test_each_quarter_takes_its_gauss_point_value():
    mesh = _mesh()
    quad = np.array([[1.0, 10.0], [2.0, 20.0], [3.0, 30.0], [4.0, 40.0]])
    tria = np.array([[7.0, 70.0]])
    points = np.array(
        [[0.2, 0.2], [0.8, 0.1], [0.9, 0.7], [0.1, 0.9], [1.5, 0.5], [0.5, 0.5 - 1e-3]]
    )
    values, placed = values_at_points(mesh, [0, 1], [quad, tria], points)
    assert placed.all()
    assert values[:, 0] == pytest.approx([1.0, 2.0, 3.0, 4.0, 7.0, 1.0])
    assert values[:, 1] == pytest.approx(10.0 * values[:, 0])


def test_points_outside_nearest_or_beyond_distance_max():
    mesh = _mesh()
    quad = np.array([[1.0], [2.0], [3.0], [4.0]])
    tria = np.array([[7.0]])
    points = np.array([[-0.1, -0.1], [3.0, 0.5]])
    values, placed = values_at_points(mesh, [0, 1], [quad, tria], points)
    assert placed.all() and values[:, 0] == pytest.approx([1.0, 7.0])
    values, placed = values_at_points(mesh, [0, 1], [quad, tria], points, distance_max=0.5)
    assert placed.tolist() == [True, False] and values[1, 0] == 0.0


def test_unknown_family_refused():
    with pytest.raises(ValueError, match="QUAD4 with 7 Gauss points"):
        exploded_mesh(_mesh(), [0], [7])


def test_quadrangle_with_nine_gauss_points_ninths():
    mesh = _mesh()
    exploded, _ = exploded_mesh(mesh, [0], [9])
    areas = []
    for conn in exploded.cell_nodes:
        x, y = exploded.coords[list(conn), 0], exploded.coords[list(conn), 1]
        areas.append(0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))
    assert areas == pytest.approx([1.0 / 9.0] * 9)
    # FPG9 order: the 4 corner points, the 4 edge middles (edge 1-2 first), the centre
    quad = np.arange(1.0, 10.0)[:, None]
    points = np.array(
        [[0.1, 0.1], [0.9, 0.1], [0.9, 0.9], [0.1, 0.9], [0.5, 0.1], [0.9, 0.5], [0.5, 0.9]]
        + [[0.1, 0.5], [0.5, 0.5]]
    )
    values, placed = values_at_points(mesh, [0], [quad], points)
    assert placed.all() and values[:, 0] == pytest.approx(np.arange(1.0, 10.0))


def test_triangle_with_three_gauss_points_one_third_each():
    mesh = _mesh()
    tria = np.array([[1.0], [2.0], [3.0]])  # FPG3: points nearest vertices 1, 2, 3
    points = np.array([[1.05, 0.1], [1.9, 0.5], [1.05, 0.9]])
    values, placed = values_at_points(mesh, [1], [tria], points)
    assert placed.all() and values[:, 0] == pytest.approx([1.0, 2.0, 3.0])
