"""POST_CHAMP EXTR_COQUE on the layer stresses of DKT plates: a plate bent
to w = a x^2 / 2 (every DOF imposed; kappa_xx = -a) has SIXX = -E a z /
(1 - nu^2) and SIYY = nu SIXX, -E a h / (2 (1 - nu^2)) at the top of its
upper layer; other extractions are refused by name."""

from __future__ import annotations

from pathlib import Path

from asterlite.runtime.runner import run_deck

MESH = """COOR_3D
N1 0.0 0.0 0.0
N2 1.0 0.0 0.0
N3 1.0 1.0 0.0
N4 0.0 1.0 0.0
FINSF
TRIA3
M1 N1 N2 N3
M2 N1 N3 N4
FINSF
GROUP_MA
PLATE M1 M2
FINSF
GROUP_MA
GM1 M1
FINSF
GROUP_MA
GM2 M2
FINSF
GROUP_NO
GN1 N1
FINSF
GROUP_NO
GN3 N3
FINSF
GROUP_NO
GN4 N4
FINSF
GROUP_NO
GN2 N2
FINSF
FIN
"""

E_, NU, H, A = 2.0e11, 0.3, 0.02, 1.0e-3


def _deck(extraction: str) -> str:
    nodes = {"N1": 0.0, "N2": 1.0, "N3": 1.0, "N4": 0.0}
    imposed = ", ".join(
        f"_F(GROUP_NO='G{n}', DX=0.0, DY=0.0, DZ={A * x * x / 2!r}, DRX=0.0, "
        f"DRY={-A * x!r}, DRZ=0.0)"
        for n, x in nodes.items()
    )
    return f"""DEBUT()
MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='DKT'))
CARA = AFFE_CARA_ELEM(MODELE=MO, COQUE=_F(GROUP_MA='PLATE', EPAIS={H}, COQUE_NCOU=2))
MAT = DEFI_MATERIAU(ELAS=_F(E={E_}, NU={NU}))
CHMAT = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=({imposed},))
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CHMAT, CARA_ELEM=CARA, EXCIT=_F(CHARGE=BC))
RES = CALC_CHAMP(reuse=RES, RESULTAT=RES, CONTRAINTE=('SIEF_ELGA', 'SIGM_ELNO'))
{extraction}
FIN()
"""


def _run(tmp_path: Path, extraction: str):
    (tmp_path / "d.mail").write_text(MESH)
    (tmp_path / "d.comm").write_text(_deck(extraction))
    (tmp_path / "d.export").write_text("P time_limit 60\nF comm d.comm D 1\nF mail d.mail D 20\n")
    return run_deck(tmp_path / "d.export", tmp_path / "out")


def test_extr_coque_top_of_the_upper_layer(tmp_path):
    top = -E_ * A * H / (2 * (1 - NU**2))
    extraction = f"""TOP = POST_CHAMP(RESULTAT=RES,
                 EXTR_COQUE=_F(NOM_CHAM='SIGM_ELNO', NUME_COUCHE=2, NIVE_COUCHE='SUP'))
TEST_RESU(RESU=_F(RESULTAT=TOP, NUME_ORDRE=1, NOM_CHAM='SIGM_ELNO', GROUP_NO='GN3', GROUP_MA='GM1',
                  NOM_CMP='SIXX', VALE_CALC={top!r}, VALE_REFE={top!r}, REFERENCE='ANALYTIQUE',
                  PRECISION=1e-9))
TEST_RESU(RESU=_F(RESULTAT=TOP, NUME_ORDRE=1, NOM_CHAM='SIGM_ELNO', GROUP_NO='GN1', GROUP_MA='GM2',
                  NOM_CMP='SIYY', VALE_CALC={NU * top!r}, VALE_REFE={NU * top!r},
                  REFERENCE='ANALYTIQUE', PRECISION=1e-9))
"""
    report = _run(tmp_path, extraction)
    assert report.status == "PASS", report.message
    assert len(report.tests) == 2


def test_other_extractions_are_refused(tmp_path):
    extraction = "P = POST_CHAMP(RESULTAT=RES, EXTR_PMF=_F(NOM_CHAM='SIGM_ELNO'))\n"
    report = _run(tmp_path, extraction)
    assert report.status == "UNSUPPORTED" and "POST_CHAMP EXTR_PMF" in report.message
    assert "d.comm:10" in report.message, report.message
