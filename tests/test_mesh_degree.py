"""CREA_MAILLAGE LINE_QUAD and MODI_MAILLE SEG3_4: quadratic cells with the
mid-edge nodes of code_aster's reference elements, shared between cells, and
SEG4 nodes at the thirds of a SEG3's parabola."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.fem.mesh_degree import line_quad, seg3_to_seg4
from tests.solid_meshes import box_mesh
from tests.test_fem_support import FakeSession, run


@pytest.mark.parametrize(
    "linear, quadratic",
    [("HEXA8", "HEXA20"), ("TETRA4", "TETRA10"), ("PENTA6", "PENTA15"), ("PYRAM5", "PYRAM13")],
)
def test_line_quad_matches_the_quadratic_box(linear, quadratic):
    mesh = box_mesh(linear, n=(2, 2, 1), jitter=0.2, seed=3)
    expected = box_mesh(quadratic, n=(2, 2, 1), jitter=0.2, seed=3)
    before = mesh.n_nodes
    added = line_quad(mesh, range(mesh.n_cells))
    assert mesh.n_nodes == expected.n_nodes == before + added
    for cell in range(mesh.n_cells):
        assert mesh.cell_types[cell] == quadratic
        got = mesh.coords[list(mesh.cell_nodes[cell])]
        want = expected.coords[list(expected.cell_nodes[cell])]
        np.testing.assert_allclose(got, want, atol=1e-14)
    assert len(set(mesh.node_names)) == mesh.n_nodes


def _strip():
    """Two QUAD4 and a SEG2 on their common edge: one middle node per edge."""
    coords = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0.0]])
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(6)],
        cell_names=["Q1", "Q2", "S1", "P1"],
        cell_types=["QUAD4", "QUAD4", "SEG2", "POI1"],
        cell_nodes=[(0, 1, 4, 3), (1, 2, 5, 4), (1, 4), (0,)],
        node_groups={"LEFT": np.array([0, 3])},
        cell_groups={"Q": np.array([0, 1])},
    )


def test_shared_edges_get_one_node_and_groups_keep_theirs():
    mesh = _strip()
    assert line_quad(mesh, range(4)) == 7  # 7 distinct edges
    q1, q2, s1 = (mesh.cell_nodes[c] for c in range(3))
    assert mesh.cell_types[:3] == ["QUAD8", "QUAD8", "SEG3"] and mesh.cell_types[3] == "POI1"
    assert q1[5] == q2[7] == s1[2]  # the edge 1-4: QUAD8 edges 2-3 and 4-1, SEG3 middle
    assert mesh.coords[s1[2]] == pytest.approx([1.0, 0.5, 0.0])
    assert mesh.node_groups["LEFT"].tolist() == [0, 3]
    assert mesh.node_names[6] == "N7" and mesh.find_node("N13") == 12


def test_seg3_to_seg4_on_an_arc_and_a_chord():
    """code_aster's SEG3_4: the middle node moves to the first third of the
    arc through the three nodes, one node is added at the second third."""
    # S: a quarter of the unit circle; T: a straight segment along x
    coords = [[1.0, 0, 0], [0, 1.0, 0], [0.5**0.5, 0.5**0.5, 0], [2.0, 0, 0], [3.0, 0, 0]]
    mesh = Mesh(
        coords=np.array([*coords, [2.5, 0, 0]]),
        node_names=["A", "B", "C", "D", "E", "F"],
        cell_names=["S", "T"],
        cell_types=["SEG3", "SEG3"],
        cell_nodes=[(0, 1, 2), (3, 4, 5)],
    )
    assert seg3_to_seg4(mesh, [0, 1]) == 2
    assert mesh.cell_types == ["SEG4", "SEG4"]
    a, b, third, two_thirds = mesh.cell_nodes[0]
    assert third == 2
    angle = np.pi / 6.0
    assert mesh.coords[third] == pytest.approx([np.cos(angle), np.sin(angle), 0.0])
    assert mesh.coords[two_thirds] == pytest.approx([np.cos(2 * angle), np.sin(2 * angle), 0.0])
    _, _, third, two_thirds = mesh.cell_nodes[1]
    assert mesh.coords[third] == pytest.approx([2.0 + 1.0 / 3.0, 0.0, 0.0])
    assert mesh.coords[two_thirds] == pytest.approx([2.0 + 2.0 / 3.0, 0.0, 0.0])


def test_crea_maillage_keeps_the_original_mesh():
    mesh = _strip()
    session = FakeSession()
    quadratic = run(session, "CREA_MAILLAGE", MAILLAGE=mesh, LINE_QUAD={"GROUP_MA": "Q"})
    assert mesh.cell_types[:2] == ["QUAD4", "QUAD4"] and mesh.n_nodes == 6
    assert quadratic.cell_types == ["QUAD8", "QUAD8", "SEG2", "POI1"]
    assert quadratic.n_nodes == 6 + 7


def test_line_quad_names_nodes_as_code_aster_15_did():
    # cmlqnd: PREF_NOEUD + PREF_NUME, PREF_NUME + 1... in the order the edges are met
    mesh = _strip()
    line_quad(mesh, range(4), prefix=("NS", 1))
    assert mesh.node_names[6:] == [f"NS{i}" for i in range(1, 8)]
    q1 = mesh.cell_nodes[0]
    assert [mesh.node_names[n] for n in q1[4:]] == ["NS1", "NS2", "NS3", "NS4"]
    with pytest.raises(ValueError, match="already has a node named 'N6'"):
        line_quad(_strip(), range(4), prefix=("N", 6))


def test_a_code_aster_15_deck_reads_the_prefixed_names(tmp_path):
    from asterlite.runtime.check_deck import check_deck

    (tmp_path / "m.mail").write_text(
        "COOR_3D\nN1 0 0 0\nN2 1 0 0\nN3 1 1 0\nN4 0 1 0\nFINSF\n"
        "QUAD4\nQ1 N1 N2 N3 N4\nFINSF\nFIN\n"
    )
    deck = tmp_path / "m.comm"
    uses = "G = DEFI_GROUP(MAILLAGE=MA, CREA_GROUP_NO=_F(NOM='M', NOEUD='{}'))\n"
    body = (
        "DEBUT()\nMA0 = LIRE_MAILLAGE(FORMAT='ASTER')\n"
        "MA = CREA_MAILLAGE(MAILLAGE=MA0, LINE_QUAD=_F(TOUT='OUI'))\n"
    )
    (tmp_path / "m.export").write_text("F comm m.comm D 1\nF mail m.mail D 20\n")
    for name, known in (("NS4", True), ("NS5", False)):
        deck.write_text(body + uses.format(name) + "FIN()\n")
        found = [f.text() for f in check_deck(tmp_path / "m.export", aster_version=15).findings]
        assert (not any(f"no node '{name}'" in text for text in found)) == known, found
