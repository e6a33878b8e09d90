"""Newmark's sliding block (asterlite.post.sliding_block, POST_NEWMARK) and
HOMARD-like uniform refinement (asterlite.fem.refinement, MACR_ADAP_MAIL)."""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.fem.refinement import RefinementError, refine_uniformly
from asterlite.post import sliding_block as block


def test_a_block_under_constant_excess_acceleration_slides_as_half_a_t_squared():
    t = np.linspace(0.0, 2.0, 41)
    velocity, displacement = block.newmark_displacement(t, np.full(t.size, 3.0), 1.0)
    np.testing.assert_allclose(velocity, 2.0 * t, rtol=1e-14)
    np.testing.assert_allclose(displacement, t**2, rtol=1e-14)  # ½ (3 - 1) t²


def test_a_block_below_its_critical_acceleration_stays():
    t = np.linspace(0.0, 1.0, 11)
    velocity, displacement = block.newmark_displacement(t, 0.5 * np.sin(7 * t), 0.6)
    assert not velocity.any() and not displacement.any()


def test_the_block_stops_when_its_velocity_vanishes():
    # a = a_y + c (T - t): v = c (T t - t²/2) up to t = 2T, then the block
    # stays; d = 2 c T³ / 3 from then on
    c, big_t, ay = 0.8, 1.5, 0.3
    t = np.linspace(0.0, 5.0, 50001)
    velocity, displacement = block.newmark_displacement(t, ay + c * (big_t - t), ay)
    sliding = t <= 2 * big_t
    np.testing.assert_allclose(velocity[sliding], c * (big_t * t - t**2 / 2)[sliding], atol=1e-7)
    assert not velocity[t > 2 * big_t + 1e-3].any()
    np.testing.assert_allclose(displacement[-1], 2 * c * big_t**3 / 3, rtol=1e-6)


def _mesh(kinds_nodes, coords, groups=None):
    return Mesh(
        coords=np.asarray(coords, dtype=float),
        node_names=[f"N{k + 1}" for k in range(len(coords))],
        cell_names=[f"M{k + 1}" for k in range(len(kinds_nodes))],
        cell_types=[k for k, _ in kinds_nodes],
        cell_nodes=[tuple(n) for _, n in kinds_nodes],
        cell_groups=groups or {},
        dim=2,
    )


def _area(mesh, cell):
    nodes = mesh.cell_nodes[cell][: 4 if mesh.cell_types[cell].startswith("QUAD") else 3]
    x, y = mesh.coords[list(nodes), 0], mesh.coords[list(nodes), 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def test_uniform_refinement_of_a_quadratic_quadrangle_triangle_and_edge():
    # QUAD8 on the unit square, TRIA6 on its right, SEG3 along the bottom
    coords = [
        (0, 0), (1, 0), (1, 1), (0, 1),  # 1-4 corners
        (0.5, 0), (1, 0.5), (0.5, 1), (0, 0.5),  # 5-8 middles
        (2, 0.5), (1.5, 0.25), (1.5, 0.75),  # 9-11 triangle apex and middles
    ]  # fmt: skip
    cells = [
        ("QUAD8", (0, 1, 2, 3, 4, 5, 6, 7)),
        ("TRIA6", (1, 8, 2, 9, 10, 5)),
        ("SEG3", (0, 1, 4)),
    ]
    mesh = _mesh(cells, coords, {"CARRE": np.array([0]), "BORD": np.array([2])})
    fine = refine_uniformly(mesh)
    assert Counter(fine.cell_types) == {"QUAD8": 4, "TRIA6": 4, "SEG3": 2}
    # the quadrangle's centre, then a middle on each of the 16 + 9 - 2 sub-edges
    # (the two halves of the shared edge counted once)
    assert fine.n_nodes == 11 + 1 + (12 + 9 - 2)
    surfaces = [c for c in range(fine.n_cells) if fine.cell_types[c] != "SEG3"]
    areas = [_area(fine, c) for c in surfaces]
    assert min(areas) > 0.0  # each child keeps its parent's orientation
    assert sum(areas) == pytest.approx(1.0 + 0.5)
    assert sorted(_area(fine, c) for c in fine.cell_groups["CARRE"]) == [0.25] * 4
    # the edge's halves share the middle nodes of the quadrangle's children
    quad_nodes = {n for c in fine.cell_groups["CARRE"] for n in fine.cell_nodes[c]}
    for c in fine.cell_groups["BORD"]:
        assert set(fine.cell_nodes[c]) <= quad_nodes
    # every interior sub-edge's middle node belongs to exactly two cells
    users = Counter(n for c in surfaces for n in set(fine.cell_nodes[c]))
    np.testing.assert_allclose(fine.coords[fine.node_index["N12"]], (0.5, 0.5))
    assert users[fine.node_index["N12"]] == 4
    assert fine.node_names[:11] == mesh.node_names


def test_uniform_refinement_refuses_other_cells():
    mesh = _mesh([("HEXA8", tuple(range(8)))], np.zeros((8, 3)))
    with pytest.raises(RefinementError, match="HEXA8"):
        refine_uniformly(mesh)


def test_nodes_inside_cells_within_a_tolerance():
    mesh = _mesh([("QUAD4", (0, 1, 2, 3))], [(0, 0), (1, 0), (1, 1), (0, 1)])
    points = np.array([(0.5, 0.5), (1.005, 0.5), (1.02, 0.5), (-0.5, -0.5), (1.0, 1.0)])
    inside = block.points_in_cells(points, mesh, [0], tolerance=0.01)
    assert inside.tolist() == [True, True, False, False, True]
    near = block.cells_near_centre(mesh, [0], (2.0, 0.0), 1.0)
    assert near.tolist() == [0]  # the node (1, 0) lies on the circle
    assert block.cells_near_centre(mesh, [0], (2.0, 0.0), 0.99).size == 0


def test_post_newmark_mean_acceleration_of_a_stretched_plane_strain_strip():
    # two QUAD4 cells side by side, u_x = eps(t) x: the left cell (the zone,
    # the disc reaching its nodes only) pushes on the right one through the
    # edge x = 1 with sigma_xx = (lambda + 2 mu) eps, over its mass rho x 1 x 1
    from asterlite.concepts.assembly import DofNumbering
    from asterlite.concepts.transient import DynaTrans
    from asterlite.fem.assemble import build_numbering_dofs
    from tests.test_fem_plane import NU, RHO, E, grid_mesh, plane_model
    from tests.test_fem_support import FakeSession, run

    mesh = grid_mesh("QUAD4", n=(2, 1), size=(2.0, 1.0))
    mesh.cell_groups["TOUT"] = np.arange(mesh.n_cells)
    model, materials = plane_model(mesh, "D_PLAN")
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    times = np.linspace(0.0, 1.0, 11)
    strain = 1.0e-7 * times
    depl = np.zeros((times.size, numbering.n_dofs))
    for k, (node, comp) in enumerate(numbering.dofs):
        if comp == "DX":
            depl[:, k] = strain * mesh.coords[node, 0]
    result = DynaTrans(numbering=numbering, times=times, order=np.arange(1, 12),
                       fields={"DEPL": depl}, model=model, materials=materials)  # fmt: skip
    session = FakeSession()
    ky = 0.02
    table = run(session, "POST_NEWMARK", RESULTAT=result, KY=ky, RAYON=1.2, CENTRE_X=-1.0,
                CENTRE_Y=0.5, GROUP_MA_CALC="TOUT", POSITION="AVAL")  # fmt: skip
    lam, mu = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
    expected = (lam + 2 * mu) * strain / RHO
    columns = table.EXTR_TABLE().values()
    np.testing.assert_allclose(columns["ACCE_MOY"], expected, rtol=1e-10)
    _, displacement = block.newmark_displacement(times, expected, ky * block.GRAVITY)
    assert displacement[-1] > 0.0  # up to 3.4 m/s² against a_y = 0.196 m/s²
    np.testing.assert_allclose(columns["DEPL"], displacement, rtol=1e-10)
    # upstream, the same forces pull the other way: no sliding
    upstream = run(session, "POST_NEWMARK", RESULTAT=result, KY=ky, RAYON=1.2, CENTRE_X=-1.0,
                   CENTRE_Y=0.5, GROUP_MA_CALC="TOUT", POSITION="AMONT")  # fmt: skip
    np.testing.assert_allclose(upstream.EXTR_TABLE().values()["ACCE_MOY"], -expected, rtol=1e-10)
    assert not any(upstream.EXTR_TABLE().values()["DEPL"])
