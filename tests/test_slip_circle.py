"""The slip circle of POST_NEWMARK's disc and the stresses on it
(asterlite.post.slip_circle) against closed forms."""

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.fem.disk_mesh import disk_mesh
from asterlite.post import slip_circle as sc


def _square(side, n, corner):
    """A structured QUAD4 mesh of a square, n x n cells."""
    xs = corner[0] + side * np.arange(n + 1) / n
    ys = corner[1] + side * np.arange(n + 1) / n
    coords = np.array([[x, y, 0.0] for y in ys for x in xs])
    conn = [
        (j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i)
        for j in range(n)
        for i in range(n)
    ]
    return Mesh(
        coords=coords,
        node_names=[f"N{k}" for k in range(len(coords))],
        cell_names=[f"M{k}" for k in range(len(conn))],
        cell_types=["QUAD4"] * len(conn),
        cell_nodes=conn,
        dim=2,
    )


def _uniform(structure, stress):
    return [np.tile(stress, (4, 1)) for _ in range(structure.n_cells)]


def test_full_circle_in_uniform_stress():
    # sum of n.sigma.n over N equally spaced normals: N (sxx + syy) / 2;
    # sum of t.sigma.n: 0
    centre, radius, refine = (5.0, 5.0), 2.0, 1
    disc = disk_mesh(radius, refine, centre)
    structure = _square(10.0, 8, (0.0, 0.0))
    cells = np.arange(structure.n_cells)
    line = sc.slip_line(disc, structure, cells)
    n_segments = 8 * 2**refine
    assert len(line.segments) == n_segments
    sxx, syy, sxy = -3.0e5, -7.0e5, 1.2e5
    stress = np.array([sxx, syy, 0.0, sxy])
    uniform = _uniform(structure, stress)
    projection = sc.gauss_stress_projection(structure, cells, [len(v) for v in uniform], disc, line)
    gauss = sc.projected_gauss_stresses(projection, uniform, line)
    assert gauss == pytest.approx(np.broadcast_to(stress, gauss.shape))
    sig_n, sig_tn = sc.line_stresses(line, gauss)
    assert sig_n.sum() == pytest.approx(n_segments * (sxx + syy) / 2, rel=1e-12)
    assert sig_tn.sum() == pytest.approx(0.0, abs=1e-9 * abs(sxx))
    # each segment: the traction on its chord's outward normal
    mid = np.array([np.pi * (2 * k + 1) / n_segments for k in range(n_segments)])
    n = np.column_stack([np.cos(mid), np.sin(mid)])
    expected = sxx * n[:, 0] ** 2 + syy * n[:, 1] ** 2 + 2 * sxy * n[:, 0] * n[:, 1]
    assert np.sort(sig_n) == pytest.approx(np.sort(expected), rel=1e-12)


def test_circle_cut_by_the_structure_keeps_segments_inside():
    # structure below y = 5: the lower half of the circle about (5, 5)
    disc = disk_mesh(2.0, 1, (5.0, 5.0))
    structure = _square(5.0, 5, (2.5, 0.0))
    line = sc.slip_line(disc, structure, np.arange(structure.n_cells))
    ends = disc.coords[np.array([disc.cell_nodes[c] for c in line.segments])]
    assert np.all(ends[..., 1] <= 5.0 + 1e-9)
    assert len(line.segments) == 8  # the 8 of the 16 segments below the centre
    assert np.all(line.normal[:, 1] < 0.0)  # outward of the disc: downward


def test_linear_stress_extrapolated_exactly():
    # sigma_yy = y over the structure's Gauss points: the ELNO extrapolation of
    # a bilinear field is exact, the segment mean is y at its middle
    disc = disk_mesh(2.0, 1, (5.0, 5.0))
    line = sc.slip_line(disc, _square(10.0, 4, (0.0, 0.0)), np.arange(16))
    points = sc.support_gauss_points(disc, line).reshape(len(line.segments), 4, 2)
    gauss = np.zeros((len(line.segments), 4, 4))
    gauss[..., 1] = points[..., 1]
    sig_n, _ = sc.line_stresses(line, gauss)
    ends = disc.coords[np.array([disc.cell_nodes[c] for c in line.segments])]
    y_mid = ends[:, :, 1].mean(axis=1)
    assert sig_n == pytest.approx(y_mid * line.normal[:, 1] ** 2, rel=1e-10)


def test_circle_outside_the_structure_refused():
    disc = disk_mesh(1.0, 0, (50.0, 50.0))
    with pytest.raises(ValueError, match="no segment"):
        sc.slip_line(disc, _square(10.0, 2, (0.0, 0.0)), np.arange(4))
