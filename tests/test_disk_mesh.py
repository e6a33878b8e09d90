"""The disc mesh of code_aster's Mesh.buildDisk (asterlite.fem.disk_mesh)."""

import numpy as np
import pytest

from asterlite.fem.disk_mesh import disk_mesh


def _signed_area(coords, nodes):
    x, y = coords[list(nodes), 0], coords[list(nodes), 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


@pytest.mark.parametrize(("refine", "n_nodes", "n_cells"), [(2, 257, None), (3, 1025, 1088)])
def test_counts_as_code_aster_mesh001a(refine, n_nodes, n_cells):
    # mesh001a: buildDisk(refine=3) has 1025 nodes and 1088 cells, refine=2 257 nodes
    mesh = disk_mesh(refine=refine)
    assert mesh.n_nodes == n_nodes
    if n_cells is not None:
        assert mesh.n_cells == n_cells
    assert sorted(mesh.cell_groups) == ["REXT", "SURFACE"]


def test_area_orientation_and_circle():
    radius, centre, refine = 50.0, (80.0, 220.0), 1
    mesh = disk_mesh(radius, refine, centre)
    n_angular = 8 * 2**refine
    areas = [_signed_area(mesh.coords, mesh.cell_nodes[c]) for c in mesh.cell_groups["SURFACE"]]
    assert min(areas) > 0.0  # counter-clockwise cells
    # the cells fill the inscribed polygon of n_angular sides exactly
    polygon = 0.5 * n_angular * radius**2 * np.sin(2.0 * np.pi / n_angular)
    assert sum(areas) == pytest.approx(polygon, rel=1e-12)
    rext = mesh.cell_groups["REXT"]
    assert len(rext) == n_angular
    for c in rext:
        a, b = mesh.coords[list(mesh.cell_nodes[c]), :2]
        assert np.hypot(*(a - centre)) == pytest.approx(radius)
        # anticlockwise along the circle: (a - centre) x (b - a) > 0
        r, d = a - centre, b - a
        assert r[0] * d[1] - r[1] * d[0] > 0.0


def test_bad_arguments():
    with pytest.raises(ValueError, match="radius"):
        disk_mesh(0.0)
    with pytest.raises(ValueError, match="refinement"):
        disk_mesh(1.0, -1)
