"""DYNA_LINE_TRAN and DYNA_LINE_HARM (code_aster 10-12) run as the DYNA_VIBRA
calls code_aster 11's own DYNA_VIBRA made of them, on a 2 kg mass on a
8000 N/m spring against closed-form responses; code_aster 10's spellings
that 11 had replaced are refused by name."""

from __future__ import annotations

import math

from asterlite.runtime.check_deck import check_deck
from asterlite.runtime.runner import run_deck
from tests.conftest import SAMPLES

M, K = 2.0, 8.0e3
FRONT = """DEBUT()
M = 2.0
K = 8.0e03
W = sqrt(K / M)
MAIL = LIRE_MAILLAGE()
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE',
                     MODELISATION='DIS_T'))
CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(_F(GROUP_MA='MASSE', CARA='K_T_D_N',
                      VALE=(K, K, K)), _F(GROUP_MA='MASSE', CARA='M_T_D_N', VALE=M)))
BLOCAGE = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(TOUT='OUI', DY=0.0, DZ=0.0))
FORCE = AFFE_CHAR_MECA(MODELE=MODELE, FORCE_NODALE=_F(GROUP_NO='N1', FX=1.0))
RIGIELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION='RIGI_MECA')
MASSELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION='MASS_MECA')
VECTELEM = CALC_VECT_ELEM(CHARGE=FORCE, OPTION='CHAR_MECA')
NUMEROTA = NUME_DDL(MATR_RIGI=RIGIELEM)
MATRRIGI = ASSE_MATRICE(MATR_ELEM=RIGIELEM, NUME_DDL=NUMEROTA)
MATRMASS = ASSE_MATRICE(MATR_ELEM=MASSELEM, NUME_DDL=NUMEROTA)
VECTASS = ASSE_VECTEUR(VECT_ELEM=VECTELEM, NUME_DDL=NUMEROTA)
UN = DEFI_CONSTANTE(VALE=1.0)
HALF = pi / W
L = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=HALF, NOMBRE=1000))
"""


def _deck(tmp_path, body: str):
    (tmp_path / "d.mail").write_text(
        (SAMPLES / "friction_oscillator/friction_oscillator.mail").read_text()
    )
    (tmp_path / "d.comm").write_text(FRONT + body + "FIN()\n")
    return tmp_path / "d.comm"


def test_dyna_line_tran_and_harm_as_dyna_vibra(tmp_path):
    # unit step force from rest: x = (1 - cos wt) / K, 2 / K at half a period
    # (where the slope is zero); harmonic unit force at 5 Hz: 1 / (K - M w^2)
    x_harm = 1.0 / (K - M * (2 * math.pi * 5.0) ** 2)
    deck = _deck(
        tmp_path,
        "TRAN = DYNA_LINE_TRAN(MODELE=MODELE, CARA_ELEM=CARA, MATR_MASS=MATRMASS,\n"
        "    MATR_RIGI=MATRRIGI, SCHEMA_TEMPS=_F(SCHEMA='NEWMARK'),\n"
        "    EXCIT=_F(VECT_ASSE=VECTASS, FONC_MULT=UN), INCREMENT=_F(LIST_INST=L))\n"
        "HARM = DYNA_LINE_HARM(MATR_MASS=MATRMASS, MATR_RIGI=MATRRIGI, FREQ=5.0,\n"
        "    EXCIT=_F(VECT_ASSE=VECTASS, COEF_MULT=1.0))\n"
        "TEST_RESU(RESU=(_F(RESULTAT=TRAN, INST=HALF, NOM_CHAM='DEPL', GROUP_NO='N1',\n"
        "    NOM_CMP='DX', VALE=2.0 / K, PRECISION=1.0E-5),\n"
        "  _F(RESULTAT=HARM, FREQ=5.0, NOM_CHAM='DEPL', GROUP_NO='N1', NOM_CMP='DX',\n"
        f"    VALE_C=('RI', {x_harm!r}, 0.0), PRECISION=1.0E-9)))\n",
    )
    assert check_deck(deck).status == "VALID"  # code_aster 11's language, then DYNA_VIBRA's
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "PASS", report.message
    assert [t.verdict for t in report.tests] == ["OK", "OK"]
    log = (tmp_path / "out" / "message.log").read_text()
    assert "DYNA_VIBRA(TYPE_CALCUL='TRAN', BASE_CALCUL='PHYS')" in log
    assert "DYNA_VIBRA(TYPE_CALCUL='HARM', BASE_CALCUL='PHYS')" in log


def test_code_aster_10_scheme_factor_refused_by_name(tmp_path):
    deck = _deck(
        tmp_path,
        "TRAN = DYNA_LINE_TRAN(MODELE=MODELE, CARA_ELEM=CARA, MATR_MASS=MATRMASS,\n"
        "    MATR_RIGI=MATRRIGI, NEWMARK=_F(ALPHA=0.25, DELTA=0.5),\n"
        "    EXCIT=_F(VECT_ASSE=VECTASS, FONC_MULT=UN), INCREMENT=_F(LIST_INST=L))\n",
    )
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "UNSUPPORTED"
    assert "DYNA_LINE_TRAN: NEWMARK is code_aster 10's spelling" in report.message


def test_dyna_line_harm_on_a_generalized_basis(tmp_path):
    # mass-normalised mode of the oscillator: the physical response restored from
    # the generalized one is 1 / (K - M w^2) whatever the mode's sign
    x_harm = 1.0 / (K - M * (2 * math.pi * 5.0) ** 2)
    deck = _deck(
        tmp_path,
        "MODES = MODE_ITER_SIMULT(MATR_A=MATRRIGI, MATR_B=MATRMASS, CALC_FREQ=_F(NMAX_FREQ=1))\n"
        "NUMEGE = NUME_DDL_GENE(BASE=MODES, STOCKAGE='DIAG')\n"
        "MG = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=MATRMASS)\n"
        "KG = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=MATRRIGI)\n"
        "FG = PROJ_VECT_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, VECT_ASSE=VECTASS)\n"
        "HG = DYNA_LINE_HARM(MATR_MASS=MG, MATR_RIGI=KG, FREQ=5.0,\n"
        "    EXCIT=_F(VECT_ASSE=FG, COEF_MULT=1.0))\n"
        "HP = REST_GENE_PHYS(RESU_GENE=HG, NOM_CHAM='DEPL')\n"
        "TEST_RESU(RESU=_F(RESULTAT=HP, FREQ=5.0, NOM_CHAM='DEPL', GROUP_NO='N1',\n"
        f"    NOM_CMP='DX', VALE_C=('RI', {x_harm!r}, 0.0), PRECISION=1.0E-6))\n",
    )
    assert check_deck(deck).status == "VALID"
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "PASS", report.message
    log = (tmp_path / "out" / "message.log").read_text()
    assert "DYNA_VIBRA(TYPE_CALCUL='HARM', BASE_CALCUL='GENE')" in log
