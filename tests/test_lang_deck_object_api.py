"""Small decks through a whole run: code_aster 16-17's CA object (init,
close, TestCase, disable_fpe, exception classes), try/except around a
failing command, f-strings, os.path in the output folder, toNumpy of
generalized matrices, and a Python 2 deck refused when read as code_aster 17."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

import asterlite

SAMPLE = Path(__file__).resolve().parents[1] / "samples" / "friction_oscillator"

STUDY = """\
from code_aster.Commands import *
from code_aster import CA

CA.init("--test", ERREUR=_F(ALARME="EXCEPTION"))
test = CA.TestCase()

MAIL = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=20)
test.assertEqual(MAIL.getNumberOfNodes(), {nodes})
test.assertTrue(MAIL.hasGroupOfCells("MASSE"))

try:
    OTHER = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=99)
except CA.AsterError as err:
    reason = err.message
test.assertFalse("OTHER" in globals())
test.assertIn("99", reason)

with test.assertRaises(CA.AsterError):
    LIRE_MAILLAGE(FORMAT="ASTER", UNITE=98)

MODELE = AFFE_MODELE(
    MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="DIS_T")
)
CARA = AFFE_CARA_ELEM(
    MODELE=MODELE,
    DISCRET=(
        _F(GROUP_MA="MASSE", CARA="K_T_D_N", VALE=(8000.0, 8000.0, 8000.0)),
        _F(GROUP_MA="MASSE", CARA="M_T_D_N", VALE=2.0),
    ),
)
RIGIELEM = CALC_MATR_ELEM(MODELE=MODELE, CARA_ELEM=CARA, OPTION="RIGI_MECA")
MASSELEM = CALC_MATR_ELEM(MODELE=MODELE, CARA_ELEM=CARA, OPTION="MASS_MECA")
NUMEROTA = NUME_DDL(MATR_RIGI=RIGIELEM)
RIGI = ASSE_MATRICE(MATR_ELEM=RIGIELEM, NUME_DDL=NUMEROTA)
MASS = ASSE_MATRICE(MATR_ELEM=MASSELEM, NUME_DDL=NUMEROTA)
K = RIGI.toNumpy()
test.assertSequenceEqual(K.shape, (3, 3))
test.assertAlmostEqual(K[0, 0], 8000.0)

MODES = CALC_MODES(MATR_RIGI=RIGI, MATR_MASS=MASS, OPTION="PLUS_PETITE", CALC_FREQ=_F(NMAX_FREQ=3))
NUMEGE = NUME_DDL_GENE(BASE=MODES, STOCKAGE="PLEIN")
KGEN = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=RIGI)
MGEN = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=MASS)
with CA.disable_fpe():
    omega2 = KGEN.toNumpy()[0, 0] / MGEN.toNumpy()[0, 0]
test.assertAlmostEqual(omega2 / 4000.0, 1.0)
KGEN.fromNumpy(KGEN.toNumpy() * 2.0)
test.assertAlmostEqual(KGEN.toNumpy()[0, 0] / MGEN.toNumpy()[0, 0] / 8000.0, 1.0)

import os.path as osp
import numpy as np
np.savetxt("omega.txt", np.array([omega2]))
test.assertTrue(osp.exists("omega.txt"))
test.assertFalse(osp.isfile("other.txt"))
_label = f"omega2 = {{omega2:.1f}}"
print(_label)
test.assertEqual(_label, "omega2 = 4000.0")
test.printSummary()
CA.close()
x = 1 / 0
"""


@pytest.fixture
def study(tmp_path):
    shutil.copy(SAMPLE / "friction_oscillator.mail", tmp_path / "study.mail")
    (tmp_path / "study.export").write_text(
        "P time_limit 60\nF comm study.comm D 1\nF mail study.mail D 20\n"
    )
    return tmp_path


def test_a_code_aster_17_study_runs_with_the_object_api(study):
    (study / "study.comm").write_text(STUDY.format(nodes=1))
    result = asterlite.run(study / "study.export", study / "run")
    assert result.status == "PASS", result.message
    labels = [check.label for check in result.checks]
    assert any("assertRaises" in label for label in labels)
    log = (study / "run" / "message.log").read_text()
    assert "# caught by the deck (study.comm:13)" in log  # said, with the command's message
    assert "omega2 = 4000.0" in log
    assert (study / "run" / "omega.txt").is_file()


def test_lagrange_values_of_a_constrained_field_are_refused_by_name(study):
    (study / "study.comm").write_text(
        "DEBUT()\nMAIL = LIRE_MAILLAGE(FORMAT='ASTER')\n"
        "MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', "
        "MODELISATION='DIS_T'))\n"
        "CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(_F(GROUP_MA='MASSE', CARA='K_T_D_N', "
        "VALE=(1.0, 1.0, 1.0)), _F(GROUP_MA='MASSE', CARA='M_T_D_N', VALE=2.0)))\n"
        "BLOC = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(TOUT='OUI', DY=0.0, DZ=0.0))\n"
        "RE = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOC, CARA_ELEM=CARA, OPTION='RIGI_MECA')\n"
        "NU = NUME_DDL(MATR_RIGI=RE)\nK = ASSE_MATRICE(MATR_ELEM=RE, NUME_DDL=NU)\n"
        "k = K.toNumpy()\nprint('size', k.shape[0], len(NU.getLagrangeDOFs()))\n"
        "U = CREA_CHAMP(OPERATION='AFFE', TYPE_CHAM='NOEU_DEPL_R', NUME_DDL=NU, MODELE=MODELE,"
        " AFFE=_F(TOUT='OUI', NOM_CMP='DX', VALE=1.0), PROL_ZERO='OUI')\n"
        "try:\n    u = U.getValues()\nexcept:\n    u = None\nFIN()\n"
    )
    result = asterlite.run(study / "study.export", study / "run")
    log = (study / "run" / "message.log").read_text()
    # one DIS_T node: DX, DY, DZ and two multipliers for each of DY = 0, DZ = 0
    assert "size 7 4" in log
    assert result.status == "UNSUPPORTED"  # never caught: code_aster would have given it
    assert "Lagrange multiplier" in result.message and "study.comm:13" in result.message


def test_a_python2_deck_runs_as_code_aster_13_and_is_refused_as_17(study):
    (study / "study.comm").write_text(
        "DEBUT()\nn = 7 / 2\nprint 'n =', n\nTEST_RESU(VALEUR=_F(VALE_CALC=n, VALE_REFE=3, "
        "REFERENCE='ANALYTIQUE', VALE_ABS='OUI'))\nFIN()\n"
    )
    result = asterlite.run(study / "study.export", study / "run")
    log = (study / "run" / "message.log").read_text()
    assert "is Python 2 (code_aster 13)" in log and "n = 3" in log
    from asterlite.runtime.runner import run_deck

    refused = run_deck(study / "study.export", study / "run17", aster_version=17)
    assert refused.status == "ERROR"
    assert "reads as Python 2" in refused.message and "code_aster 17" in refused.message
    assert result.status in ("PASS", "UNSUPPORTED", "ERROR", "DONE")


def test_ca_init_refuses_options_that_would_change_the_run(study):
    (study / "study.comm").write_text(
        "from code_aster import CA\nCA.init('--memory=4000')\nFIN()\n"
    )
    result = asterlite.run(study / "study.export", study / "run")
    assert result.status == "UNSUPPORTED" and "--memory=4000" in result.message


def test_check_lets_the_deck_catch_what_it_expects_to_fail(study):
    """Under check, a command failing inside a try or with block raises as in
    a run (the deck's handler runs) rather than being reported."""
    (study / "study.comm").write_text(STUDY.format(nodes=1))
    result = asterlite.check(study / "study.export")
    assert not result.errors, result.errors
