"""The one-node oscillator on DX of samples/friction_oscillator (its mesh),
up to its modal basis, generalized matrices and initial displacement
(``MASSEGEN``, ``RIGIDGEN``, ``DEPINI``): the deck the toy scheme and toy
relation tests end with their own DYNA_VIBRA."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "friction_oscillator"
MESH = SAMPLE / "friction_oscillator.mail"


def one_dof_prelude(mass: float, stiffness: float, u0: float) -> str:
    """The deck's text before its DYNA_VIBRA."""
    MASS, STIFFNESS, U0 = mass, stiffness, u0  # noqa: N806 (the deck's names)
    return f"""DEBUT(CODE="OUI")
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE",
                     MODELISATION="DIS_T"))
CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(
    _F(GROUP_MA="MASSE", CARA="K_T_D_N", VALE=({STIFFNESS}, {STIFFNESS}, {STIFFNESS})),
    _F(GROUP_MA="MASSE", CARA="M_T_D_N", VALE={MASS})))
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
                      CHAM_NO=VECTASS, AFFE=_F(TOUT="OUI", NOM_CMP=("DX",), VALE=({U0},)))
DEPINI = PROJ_VECT_BASE(BASE=MODES, VECT_ASSE=DEPLPHYS, NUME_DDL_GENE=NUMEGE, TYPE_VECT="DEPL")
"""


def run_in_a_new_python(folder: Path, deck: str, script: str) -> dict:
    """Run ``deck`` (with the oscillator's mesh) from a new Python that runs
    ``script`` with the export's path as its argument (a toy registers itself
    there, never in the test process) and prints one JSON line: that line."""
    (folder / "toy.comm").write_text(deck)
    shutil.copy(MESH, folder / "toy.mail")
    (folder / "toy.export").write_text(
        "P time_limit 1200\nP memory_limit 2048\nP ncpus 1\n"
        "F comm toy.comm D 1\nF mail toy.mail D 20\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script, str(folder / "toy.export")],
        capture_output=True, text=True, cwd=SAMPLE.parents[1], timeout=1200,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])
