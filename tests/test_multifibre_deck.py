"""A POU_D_EM deck end to end: a gmsh section mesh (format 2) read by
LIRE_MAILLAGE, its quadrangles made fibres by DEFI_GEOM_FIBRE, a cantilever
under a tip force in MECA_STATIQUE, and TEST_RESU of the tip deflection
and of one fibre's stress (POINT / SOUS_POINT) against beam theory."""

from __future__ import annotations

import numpy as np

from asterlite.runtime.runner import run_deck

# 3 x 3 nodes of a 0.1 x 0.2 rectangle (x -> section y, y -> section z), one edge
SECTION = """$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "EDGE"
2 2 "SURF"
$EndPhysicalNames
$Nodes
9
1 -0.05 -0.1 0
2 0 -0.1 0
3 0.05 -0.1 0
4 -0.05 0 0
5 0 0 0
6 0.05 0 0
7 -0.05 0.1 0
8 0 0.1 0
9 0.05 0.1 0
$EndNodes
$Elements
5
1 1 2 1 1 1 2
2 3 2 2 1 1 2 5 4
3 3 2 2 1 2 3 6 5
4 3 2 2 1 4 5 8 7
5 3 2 2 1 5 6 9 8
$EndElements
"""

BEAM = """COOR_3D
N1 0.0 0.0 0.0
N2 0.5 0.0 0.0
N3 1.0 0.0 0.0
FINSF
SEG2
M1 N1 N2
M2 N2 N3
FINSF
GROUP_MA
POUTRE M1 M2
FINSF
GROUP_MA
ROOT M1
FINSF
GROUP_NO
A N1
FINSF
GROUP_NO
B N3
FINSF
FIN
"""

E, FORCE, LENGTH = 2.0e11, 1000.0, 1.0
IY = 4 * 0.005 * 0.05**2  # the four fibres' Σ z² A
X_GAUSS = 0.5 * (0.5 - 0.5 / np.sqrt(3.0))
TIP = FORCE * LENGTH**3 / (3 * E * IY)
# fibre 3 is at z = +0.05: sigma = -M_y z / I_y with M_y = F (L - x)
STRESS = -FORCE * (LENGTH - X_GAUSS) * 0.05 / IY

DECK = f"""DEBUT(CODE="OUI")
MA = LIRE_MAILLAGE(FORMAT="ASTER")
SEC = LIRE_MAILLAGE(FORMAT="GMSH", UNITE=21)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="POU_D_EM"))
ACIER = DEFI_MATERIAU(ELAS=_F(E={E}, NU=0.3, RHO=7800.0))
GF = DEFI_GEOM_FIBRE(
    SECTION=_F(GROUP_FIBRE="S", MAILLAGE_SECT=SEC, GROUP_MA_SECT="SURF", COOR_AXE_POUTRE=(0.0, 0.0))
)
COMP = DEFI_COMPOR(GEOM_FIBRE=GF, MATER_SECT=ACIER, MULTIFIBRE=_F(GROUP_FIBRE="S", MATER=ACIER))
CHMAT = AFFE_MATERIAU(
    MAILLAGE=MA, AFFE=_F(TOUT="OUI", MATER=ACIER), AFFE_COMPOR=_F(TOUT="OUI", COMPOR=COMP)
)
CARA = AFFE_CARA_ELEM(
    MODELE=MO,
    POUTRE=_F(GROUP_MA="POUTRE", SECTION="RECTANGLE", CARA=("HY", "HZ"), VALE=(0.1, 0.2)),
    GEOM_FIBRE=GF,
    MULTIFIBRE=_F(GROUP_MA="POUTRE", GROUP_FIBRE="S", PREC_INERTIE=0.3),
)
CH = AFFE_CHAR_MECA(
    MODELE=MO,
    DDL_IMPO=_F(GROUP_NO="A", DX=0.0, DY=0.0, DZ=0.0, DRX=0.0, DRY=0.0, DRZ=0.0),
    FORCE_NODALE=_F(GROUP_NO="B", FZ={FORCE}),
)
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CHMAT, CARA_ELEM=CARA, EXCIT=_F(CHARGE=CH))
RES = CALC_CHAMP(reuse=RES, RESULTAT=RES, CONTRAINTE="SIEF_ELGA")
TEST_RESU(
    RESU=(
        _F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM="DEPL", GROUP_NO="B", NOM_CMP="DZ",
           VALE_CALC={float(TIP)!r}, VALE_REFE={float(TIP)!r},
           REFERENCE="ANALYTIQUE", PRECISION=1.0e-8),
        _F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM="SIEF_ELGA", GROUP_MA="ROOT", POINT=1,
           SOUS_POINT=3, NOM_CMP="SIXX", VALE_CALC={float(STRESS)!r}, VALE_REFE={float(STRESS)!r},
           REFERENCE="ANALYTIQUE", PRECISION=1.0e-8),
    )
)
FIN()
"""


def test_gmsh_section_cantilever_deflection_and_fibre_stress(tmp_path):
    (tmp_path / "d.comm").write_text(DECK)
    (tmp_path / "d.mail").write_text(BEAM)
    (tmp_path / "s.msh").write_text(SECTION)
    (tmp_path / "d.export").write_text("F comm d.comm D 1\nF mail d.mail D 20\nF msh s.msh D 21\n")
    report = run_deck(tmp_path / "d.export", tmp_path / "out")
    assert report.status == "PASS", report.message
