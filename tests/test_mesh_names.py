"""Mesh entities named N<i>/M<i>: code_aster 15 kept a mesh file's names,
code_aster 16 and later keep none and read ``N<i>`` as the i-th node
(char8_to_int). A mesh whose names are not its positions tells them apart."""

from __future__ import annotations

import pytest

from tests.test_fem_support import FakeSession, run

# nodes listed N2, N1, NO3: the names N1 and N2 are not their positions
MAIL = """COOR_3D
  N2   0.0 0.0 0.0
  N1   1.0 0.0 0.0
  NO3  2.0 0.0 0.0
FINSF
SEG2
  M2  N2  N1
  M1  N1  NO3
FINSF
FIN
"""


def _mesh(tmp_path, version):
    (tmp_path / "m.mail").write_text(MAIL)
    session = FakeSession({20: tmp_path / "m.mail"})
    session.aster_version = version
    return run(session, "LIRE_MAILLAGE", FORMAT="ASTER", UNITE=20)


def test_code_aster_17_reads_n_i_as_the_i_th_node(tmp_path):
    mesh = _mesh(tmp_path, 17)
    assert not mesh.names_kept
    assert mesh.find_node("N1") == 0 and mesh.find_node("N2") == 1
    assert mesh.find_cell("M1") == 0 and mesh.find_cell("M2") == 1
    # a name that is no position is still found by name; past the count, none
    assert mesh.find_node("NO3") == 2 and mesh.find_node("N3") == 2
    assert mesh.find_node("N4") is None


def test_code_aster_15_reads_names(tmp_path):
    mesh = _mesh(tmp_path, 15)
    assert mesh.names_kept
    assert mesh.find_node("N1") == 1 and mesh.find_node("N2") == 0
    assert mesh.find_cell("M1") == 1 and mesh.find_cell("M2") == 0
    # the position is the fallback of a name the mesh does not have
    assert mesh.find_node("N3") == 2


@pytest.mark.parametrize(("version", "expected"), [(17, [0]), (15, [1])])
def test_a_group_of_n1_follows_the_version(tmp_path, version, expected):
    mesh = _mesh(tmp_path, version)
    session = FakeSession()
    session.aster_version = version
    run(session, "DEFI_GROUP", MAILLAGE=mesh, CREA_GROUP_NO={"NOM": "G", "NOEUD": "N1"})
    assert mesh.node_groups["G"].tolist() == expected
    assert mesh.copy().names_kept == mesh.names_kept


def test_a_bare_number_is_a_position(tmp_path):
    mesh = _mesh(tmp_path, 17)
    assert mesh.find_node("1") == 0 and mesh.find_cell("2") == 1
    assert mesh.find_node("01") is None and mesh.find_node("9") is None
