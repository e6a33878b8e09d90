"""Meshes superposed by ASSE_MAILLAGE and the deck API around nodal fields:
SUPERPOSE's groups, Mesh.getNodes / getCoordinates, a field read from a
TABLE, PROD_MATR_CHAM, FieldOnNodes.getValuesWithDescription, and
POST_RELEVE_T's empty cells where a node lacks a component (astest
sdnl139a's chain: beams beside a solid)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.mesh import Mesh
from asterlite.runtime.runner import run_deck
from commands.asse_maillage import renamed_group

BEAM = """TITRE
two beams
FINSF
COOR_3D
A1 0.0 0.0 -2.0
A2 0.0 0.0 -1.0
A3 0.0 0.0 0.0
FINSF
SEG2
S2 A2 A3
S1 A1 A2
FINSF
FIN
"""

CUBE = """TITRE
one cube
FINSF
COOR_3D
B1 0.0 0.0 0.0
B2 1.0 0.0 0.0
B3 1.0 1.0 0.0
B4 0.0 1.0 0.0
B5 0.0 0.0 1.0
B6 1.0 0.0 1.0
B7 1.0 1.0 1.0
B8 0.0 1.0 1.0
FINSF
HEXA8
H1 B1 B2 B3 B4 B5 B6 B7 B8
FINSF
FIN
"""

DECK = """DEBUT(CODE="OUI")
import numpy as np
from code_aster import CA

test = CA.TestCase()
BEAM = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=20)
BEAM = DEFI_GROUP(reuse=BEAM, MAILLAGE=BEAM, CREA_GROUP_MA=_F(NOM="ALL", TOUT="OUI"),
                  CREA_GROUP_NO=_F(GROUP_MA="ALL"))
CUBE = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=21)
CUBE = DEFI_GROUP(reuse=CUBE, MAILLAGE=CUBE, CREA_GROUP_MA=_F(NOM="ALL", TOUT="OUI"),
                  CREA_GROUP_NO=_F(GROUP_MA="ALL"))
# nodes of a group made from cells: in increasing order, not the cells' order
test.assertSequenceEqual(BEAM.getNodes("ALL"), [0, 1, 2])
MESH = ASSE_MAILLAGE(MAILLAGE_1=BEAM, MAILLAGE_2=CUBE, OPERATION="SUPERPOSE")
test.assertEqual(MESH.getNumberOfNodes(), 11)
test.assertSequenceEqual(MESH.getNodes("ALL____0"), list(range(3, 11)))
test.assertSequenceEqual(MESH.getNodes(["ALL", "ALL____0"]), list(range(11)))
xyz = np.reshape(MESH.getCoordinates().getValues(), (11, 3))
test.assertAlmostEqual(xyz[9][1], 1.0)
test.assertAlmostEqual(float(xyz[0:1, 2:3]), -2.0)  # numpy 1's conversion of a 1-element array

MODEL = AFFE_MODELE(MAILLAGE=MESH, AFFE=(
    _F(GROUP_MA="ALL", PHENOMENE="MECANIQUE", MODELISATION="POU_D_T"),
    _F(GROUP_MA="ALL____0", PHENOMENE="MECANIQUE", MODELISATION="3D")))
CARA = AFFE_CARA_ELEM(MODELE=MODEL,
                      POUTRE=_F(GROUP_MA="ALL", SECTION="CERCLE", CARA="R", VALE=0.05))
STEEL = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU=0.3, RHO=7800.0))
MATER = AFFE_MATERIAU(MAILLAGE=MESH, AFFE=_F(TOUT="OUI", MATER=STEEL))
ASSEMBLAGE(MODELE=MODEL, CHAM_MATER=MATER, CARA_ELEM=CARA, NUME_DDL=CO("NUME"),
           MATR_ASSE=_F(MATRICE=CO("RIGI"), OPTION="RIGI_MECA"))

names = ["N%d" % (i + 1) for i in range(11)]
dx = [0.001 * (i + 1) for i in range(11)]
TAB = CREA_TABLE(LISTE=(_F(PARA="NOEUD", LISTE_K=names), _F(PARA="DX", LISTE_R=dx)))
U = CREA_CHAMP(TYPE_CHAM="NOEU_DEPL_R", OPERATION="EXTR", MAILLAGE=MESH, TABLE=TAB)
F = PROD_MATR_CHAM(MATR_ASSE=RIGI, CHAM_NO=U)

# the same product from the matrix's own values, DOF by DOF
K = RIGI.toNumpy()
u = np.array([dx[node] if cmp == "DX" else 0.0
              for node, cmp in NUME.getNodeAndComponentFromDOF()])
expected = np.dot(K, u)
test.assertTrue(np.allclose(F.getValues(), expected, rtol=1e-12, atol=1e-6))
values, (nodes, cmps) = F.getValuesWithDescription("DX", ["ALL____0"])
test.assertSequenceEqual(nodes, list(range(3, 11)))
labels = NUME.getNodeAndComponentFromDOF()
rows = [i for i, (node, cmp) in enumerate(labels) if cmp == "DX" and node >= 3]
test.assertTrue(np.allclose(values, expected[rows], rtol=1e-12, atol=1e-6))

REL = POST_RELEVE_T(ACTION=_F(OPERATION="EXTRACTION", INTITULE="F", CHAM_GD=F,
                             GROUP_NO=("ALL", "ALL____0"), NOM_CMP=("DX", "DRX")))
T = REL.EXTR_TABLE()
test.assertTrue(T.DRX[0] is not None)
test.assertTrue(T.DRX[5] is None)  # a solid's node carries no rotation
FIN()
"""


def test_superposed_beam_and_solid_through_table_fields(tmp_path):
    (tmp_path / "beam.mail").write_text(BEAM)
    (tmp_path / "cube.mail").write_text(CUBE)
    (tmp_path / "study.comm").write_text(DECK)
    (tmp_path / "study.export").write_text(
        "F comm study.comm D 1\nF mail beam.mail D 20\nF mail cube.mail D 21\n"
    )
    report = run_deck(tmp_path / "study.export", tmp_path / "out")
    log = (tmp_path / "out" / "message.log").read_text()
    assert report.status in ("DONE", "PASS"), report.message + log[-3000:]
    assert "NOOK" not in log and "FAIL" not in log


def test_renamed_group_takes_seven_characters_and_the_first_free_digit():
    assert renamed_group("ALL", {"ALL"}) == "ALL____0"
    assert renamed_group("LONGNAME_X", {"LONGNAME_X", "LONGNAM0"}) == "LONGNAM1"


def test_get_nodes_of_groups_as_code_aster_lists_them():
    mesh = Mesh(
        coords=np.zeros((4, 3)),
        node_names=["A", "B", "C", "D"],
        cell_names=["S1"],
        cell_types=["SEG2"],
        cell_nodes=[(3, 1)],
        node_groups={"G1": np.array([3, 1]), "G2": np.array([1, 0])},
    )
    assert mesh.getNodes() == [0, 1, 2, 3]
    assert mesh.getNodes("G1") == [3, 1]  # one group: its own order
    assert mesh.getNodes(["G1", "G2", "NONE"]) == [0, 1, 3]  # several: merged, sorted
    assert mesh.getNodesFromCells("NONE") == []
