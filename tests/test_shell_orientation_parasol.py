"""MODI_MAILLAGE ORIE_NORM_COQUE (asterlite.fem.shell_orientation) on a pair
of shells given opposite normals, and AFFE_CARA_ELEM RIGI_PARASOL's spread of
a foundation's stiffness over the nodes of its surface (closed forms)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.errors import CommandError
from asterlite.fem.shell_orientation import ShellOrientationError, orient_shells, reversed_nodes
from tests.test_fem_support import FakeSession, run


def two_quads(second=(1, 4, 5, 2)):
    """Two unit squares in z=0 sharing the edge N2-N5; the first turns
    counter-clockwise seen from +z, the second as given."""
    coords = np.array(
        [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]], dtype=float
    )
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(6)],
        cell_names=["Q1", "Q2", "P1", "P2", "P3", "P4", "P5", "P6"],
        cell_types=["QUAD4", "QUAD4"] + ["POI1"] * 6,
        cell_nodes=[(0, 1, 4, 3), tuple(second)] + [(i,) for i in range(6)],
        node_groups={"N1": np.array([0]), "CENTRE": np.array([1])},
        cell_groups={"DALLE": np.array([0, 1]), "PTS": np.arange(2, 8)},
    )


def normal(mesh, cell):
    p = mesh.coords[list(mesh.cell_nodes[cell])]
    return np.cross(p[1] - p[0], p[2] - p[0])


def test_reversal_keeps_the_first_vertex_and_pairs_mid_side_nodes():
    assert reversed_nodes((1, 2, 3, 4), 4) == (1, 4, 3, 2)
    assert reversed_nodes((1, 2, 3, 4, 5, 6), 3) == (1, 3, 2, 6, 5, 4)
    assert reversed_nodes((1, 2, 3, 4, 5, 6, 7, 8, 9), 4) == (1, 4, 3, 2, 8, 7, 6, 5, 9)


@pytest.mark.parametrize("vector, expected_z", [((0, 0, -1.0), -1.0), ((0, 0, 2.0), 1.0)])
def test_normals_follow_the_vector_at_the_node_and_spread(vector, expected_z):
    mesh = two_quads(second=(1, 4, 5, 2))  # clockwise: normal -z, opposite to Q1
    assert normal(mesh, 0)[2] > 0 > normal(mesh, 1)[2]
    count = orient_shells(mesh, [0, 1], vector, node=0)
    assert count == 1
    for cell in (0, 1):
        assert np.sign(normal(mesh, cell)[2]) == expected_z


def test_without_vector_the_first_cell_leads_and_unreached_cells_fail():
    mesh = two_quads(second=(1, 4, 5, 2))
    assert orient_shells(mesh, [0, 1]) == 1
    assert normal(mesh, 1)[2] > 0
    apart = two_quads(second=(2, 5, 4, 1))
    apart.coords[2] = [5.0, 0, 0]
    apart.coords[5] = [5.0, 1, 0]
    apart.cell_nodes[1] = (2, 5, 5, 2)
    with pytest.raises(ShellOrientationError, match="not connected"):
        orient_shells(apart, [0, 1], (0, 0, 1.0), node=0)


def test_segments_turn_to_the_vector_and_follow_their_neighbours():
    # N1 -> N2 -> N3 along x, the second segment given backwards (N3 -> N2)
    mesh = Mesh(
        coords=np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0]], dtype=float),
        node_names=["N1", "N2", "N3"],
        cell_names=["S1", "S2"],
        cell_types=["SEG2", "SEG2"],
        cell_nodes=[(0, 1), (2, 1)],
        node_groups={},
        cell_groups={},
    )
    # a segment's normal is (y2 - y1, x1 - x2): -y for N1 -> N2, +y for N3 -> N2
    assert orient_shells(mesh, [0, 1], (0, 1.0, 0), node=0) == 1
    assert mesh.cell_nodes[0] == (1, 0) and mesh.cell_nodes[1] == (2, 1)
    assert orient_shells(mesh, [0, 1], (0, -1.0, 0), node=0) == 2
    assert mesh.cell_nodes[0] == (0, 1) and mesh.cell_nodes[1] == (1, 2)


def test_command_orients_the_group():
    session = FakeSession()
    mesh = two_quads(second=(1, 4, 5, 2))
    occurrence = {"GROUP_MA": ("DALLE",), "VECT_NORM": (0, 0, 1.0), "GROUP_NO": "N1"}
    run(session, "MODI_MAILLAGE", MAILLAGE=mesh, ORIE_NORM_COQUE=occurrence)
    assert normal(mesh, 0)[2] > 0 and normal(mesh, 1)[2] > 0


def parasol(values, cara="K_TR_D_N", coef=(1.0,)):
    session = FakeSession()
    mesh = two_quads(second=(1, 2, 5, 4))
    model = run(session, "AFFE_MODELE", MAILLAGE=mesh,
                AFFE=[{"GROUP_MA": "DALLE", "PHENOMENE": "MECANIQUE", "MODELISATION": "DKT"},
                      {"GROUP_MA": "PTS", "PHENOMENE": "MECANIQUE",
                       "MODELISATION": "DIS_TR" if "TR" in cara else "DIS_T"}])  # fmt: skip
    cara_elem = run(session, "AFFE_CARA_ELEM", MODELE=model,
                    COQUE={"GROUP_MA": "DALLE", "EPAIS": 0.1},
                    RIGI_PARASOL={"GROUP_MA": ("DALLE",), "GROUP_MA_POI1": "PTS",
                                  "COEF_GROUP": coef, "GROUP_NO_CENTRE": "CENTRE",
                                  "CARA": (cara,), "VALE": values})  # fmt: skip
    return mesh, {c - 2: cara_elem.discrete[c]["K"].values for c in range(2, 8)}


def test_parasol_weights_and_rotations_in_closed_form():
    kx, ky, kz, krx, kry, krz = 10.0, 20.0, 30.0, 1.0e3, 2.0e3, 3.0e3
    mesh, by_node = parasol((kx, ky, kz, krx, kry, krz))
    # each square gives 1/4 of its area to each node: corners 1/8, shared nodes 1/4
    weights = np.array([1, 2, 1, 1, 2, 1]) / 8.0
    d = mesh.coords - mesh.coords[1]  # about the centre N2
    x, y, z = d.T
    rx = krx - np.sum((ky * z**2 + kz * y**2) * weights)
    ry = kry - np.sum((kx * z**2 + kz * x**2) * weights)
    rz = krz - np.sum((ky * x**2 + kx * y**2) * weights)
    for node in range(6):
        expected = weights[node] * np.array([kx, ky, kz, rx, ry, rz])
        np.testing.assert_allclose(by_node[node], expected, rtol=1e-14)
    total = sum(by_node.values())
    np.testing.assert_allclose(total[:3], [kx, ky, kz], rtol=1e-14)


def test_parasol_translations_only_and_refusals():
    _, by_node = parasol((10.0, 20.0, 30.0), cara="K_T_D_N")
    np.testing.assert_allclose(by_node[1], np.array([10.0, 20.0, 30.0]) / 4.0)
    with pytest.raises(CommandError, match="COEF_GROUP"):
        parasol((10.0, 20.0, 30.0), cara="K_T_D_N", coef=(1.0, 2.0))
