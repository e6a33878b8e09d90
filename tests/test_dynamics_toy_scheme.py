"""A scheme added through the documented places only (tests/toy_scheme.py:
its module and its entry in asterlite.dynamics.schemes) runs a deck: the
catalogue accepts its SCHEMA, the command checks and integrates it, and
the archived states follow the scheme's own map, not another scheme's."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parent.parent
MESH = ROOT / "samples" / "friction_oscillator" / "friction_oscillator.mail"

DECK = """DEBUT(CODE="OUI")
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE",
                     MODELISATION="DIS_T"))
CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(
    _F(GROUP_MA="MASSE", CARA="K_T_D_N", VALE=(8.0e3, 8.0e3, 8.0e3)),
    _F(GROUP_MA="MASSE", CARA="M_T_D_N", VALE=2.0)))
BLOCAGE = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(TOUT="OUI", DY=0.0, DZ=0.0))
RIGIELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION="RIGI_MECA")
MASSELEM = CALC_MATR_ELEM(MODELE=MODELE, CHARGE=BLOCAGE, CARA_ELEM=CARA, OPTION="MASS_MECA")
NUMEROTA = NUME_DDL(MATR_RIGI=RIGIELEM)
MATRRIGI = ASSE_MATRICE(MATR_ELEM=RIGIELEM, NUME_DDL=NUMEROTA)
MATRMASS = ASSE_MATRICE(MATR_ELEM=MASSELEM, NUME_DDL=NUMEROTA)
MODES = CALC_MODES(MATR_RIGI=MATRRIGI, MATR_MASS=MATRMASS, OPTION="PLUS_PETITE",
                   CALC_FREQ=_F(NMAX_FREQ=1))
NUMEGE = NUME_DDL_GENE(BASE=MODES, STOCKAGE="DIAG")
MASSEGEN = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=MATRMASS)
RIGIDGEN = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=MATRRIGI)
FORCE = AFFE_CHAR_MECA(MODELE=MODELE, FORCE_NODALE=_F(GROUP_NO="N1", FX=1.0))
VECTASS = ASSE_VECTEUR(VECT_ELEM=CALC_VECT_ELEM(CHARGE=FORCE, OPTION="CHAR_MECA"),
                       NUME_DDL=NUMEROTA)
DEPLPHYS = CREA_CHAMP(OPERATION="AFFE", PROL_ZERO="OUI", TYPE_CHAM="NOEU_DEPL_R", MAILLAGE=MAIL,
                      CHAM_NO=VECTASS, AFFE=_F(TOUT="OUI", NOM_CMP=("DX",), VALE=(3.0e-3,)))
DEPINI = PROJ_VECT_BASE(BASE=MODES, VECT_ASSE=DEPLPHYS, NUME_DDL_GENE=NUMEGE, TYPE_VECT="DEPL")
RESUGENE = DYNA_VIBRA(TYPE_CALCUL="TRAN", BASE_CALCUL="GENE",
                      SCHEMA_TEMPS=_F(SCHEMA="TOY_EULER"),
                      MATR_MASS=MASSEGEN, MATR_RIGI=RIGIDGEN,
                      ETAT_INIT=_F(DEPL=DEPINI),
                      INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.1, PAS=1.0e-3))
FIN()
"""

RUN = """
import json, sys
import tests.toy_scheme
import asterlite
result = asterlite.run(sys.argv[1])
gene = result.concepts.raw["RESUGENE"]
stiffness = gene.basis.generalized_stiffness / gene.basis.generalized_mass
print(json.dumps({"status": result.status, "message": result.message, "scheme": gene.scheme,
                  "omega2": float(stiffness[0]), "times": gene.times.tolist(),
                  "q": gene.depl[:, 0].tolist(), "v": gene.vite[:, 0].tolist()}))
"""


@pytest.mark.slow
def test_a_toy_scheme_runs_a_deck_through_the_documented_places(tmp_path):
    (tmp_path / "toy.comm").write_text(DECK)
    shutil.copy(MESH, tmp_path / "toy.mail")
    (tmp_path / "toy.export").write_text(
        "P time_limit 1200\nP memory_limit 2048\nP ncpus 1\n"
        "F comm toy.comm D 1\nF mail toy.mail D 20\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", RUN, str(tmp_path / "toy.export")],
        capture_output=True, text=True, cwd=ROOT, timeout=1200,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    run = json.loads(done.stdout.strip().splitlines()[-1])
    assert run["status"] == "DONE", run["message"]  # no TEST_* in the deck
    assert run["scheme"] == "TOY_EULER"
    times, q, v = (np.array(run[k]) for k in ("times", "q", "v"))
    assert len(times) == 101 and times[-1] == pytest.approx(0.1)
    dt, w2 = 1.0e-3, run["omega2"]
    toy = np.array([[1.0, dt], [-w2 * dt, 1.0 - w2 * dt * dt]])  # q first, then v
    centre = np.array([[1.0 - w2 * dt * dt, dt], [-w2 * dt, 1.0]])  # DIFF_CENTRE: v first
    state = expected_toy = np.array([q[0], v[0]])
    expected_centre = state
    for k in range(1, len(times)):
        expected_toy = toy @ expected_toy
        expected_centre = centre @ expected_centre
        assert q[k] == pytest.approx(expected_toy[0], rel=1e-9, abs=1e-15)
        assert v[k] == pytest.approx(expected_toy[1], rel=1e-9, abs=1e-15)
    assert abs(q[-1] - expected_centre[0]) > 1e-6 * abs(q).max()  # another map: not DIFF_CENTRE
