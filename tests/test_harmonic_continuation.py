"""DYNA_VIBRA HARM continued with reuse= and RESULTAT (code_aster's comdlh,
resu60): the new frequencies are stored after those of the result, NUME_ORDRE
going on from its last one, and each stored response equals what one call
over all the frequencies gives, on the physical and the generalized basis."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.errors import CommandError
from asterlite.io.export import describe_run
from asterlite.runtime.session import Session
from tests.test_harmonic import DECK, MESH

HEAD = DECK.split("VISC = DYNA_VIBRA")[0]
CONTINUED = (
    HEAD
    + """
MODES = CALC_MODES(MATR_RIGI=RIGI, MATR_MASS=MASS, CALC_FREQ=_F(NMAX_FREQ=2))
NUMG = NUME_DDL_GENE(BASE=MODES, STOCKAGE="PLEIN")
MG = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, MATR_ASSE=MASS)
KG = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, MATR_ASSE=RIGI)
FG = PROJ_VECT_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, VECT_ASSE=F3, TYPE_VECT="FORC")
ALL = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MASS, MATR_RIGI=RIGI,
    MATR_AMOR=AMOR, FREQ=(2.0, 9.5, 17.0, 31.0), EXCIT=_F(VECT_ASSE=F3, COEF_MULT=1.0))
PART = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MASS, MATR_RIGI=RIGI,
    MATR_AMOR=AMOR, FREQ=(2.0, 9.5), EXCIT=_F(VECT_ASSE=F3, COEF_MULT=1.0))
PART = DYNA_VIBRA(reuse=PART, RESULTAT=PART, TYPE_CALCUL="HARM", BASE_CALCUL="PHYS",
    MATR_MASS=MASS, MATR_RIGI=RIGI, MATR_AMOR=AMOR, FREQ=(17.0, 31.0),
    EXCIT=_F(VECT_ASSE=F3, COEF_MULT=1.0))
GALL = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="GENE", MATR_MASS=MG, MATR_RIGI=KG,
    AMOR_MODAL=_F(AMOR_REDUIT=0.02), FREQ=(2.0, 9.5, 17.0),
    EXCIT=_F(VECT_ASSE_GENE=FG, COEF_MULT=1.0))
GPART = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="GENE", MATR_MASS=MG, MATR_RIGI=KG,
    AMOR_MODAL=_F(AMOR_REDUIT=0.02), FREQ=2.0, EXCIT=_F(VECT_ASSE_GENE=FG, COEF_MULT=1.0))
GPART = DYNA_VIBRA(reuse=GPART, RESULTAT=GPART, TYPE_CALCUL="HARM", BASE_CALCUL="GENE",
    MATR_MASS=MG, MATR_RIGI=KG, AMOR_MODAL=_F(AMOR_REDUIT=0.02), FREQ=(9.5, 17.0),
    EXCIT=_F(VECT_ASSE_GENE=FG, COEF_MULT=1.0))
FIN()
"""
)


def _run(folder, deck):
    (folder / "d.mail").write_text(MESH)
    (folder / "d.comm").write_text(deck)
    export = folder / "d.export"
    export.write_text("P time_limit 300\nF comm d.comm D 1\nF mail d.mail D 20\n")
    session = Session(describe_run(export), output_dir=folder / "out")
    session.run_all()
    return session


@pytest.fixture(scope="module")
def continued(tmp_path_factory):
    return _run(tmp_path_factory.mktemp("harm_cont"), CONTINUED)


@pytest.mark.parametrize(("whole", "part"), [("ALL", "PART"), ("GALL", "GPART")])
def test_continued_result_is_the_whole_sweep(continued, whole, part):
    whole, part = continued.namespace[whole], continued.namespace[part]
    np.testing.assert_array_equal(part.frequencies, whole.frequencies)
    np.testing.assert_array_equal(part.order, np.arange(1, whole.frequencies.size + 1))
    assert set(part.fields) == set(whole.fields) == {"DEPL", "VITE", "ACCE"}
    for name in whole.fields:
        np.testing.assert_allclose(part.fields[name], whole.fields[name], rtol=1e-12)


def test_resultat_must_be_the_reused_result(tmp_path):
    deck = (
        HEAD
        + """
A = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MASS, MATR_RIGI=RIGI,
    MATR_AMOR=AMOR, FREQ=2.0, EXCIT=_F(VECT_ASSE=F3, COEF_MULT=1.0))
B = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MASS, MATR_RIGI=RIGI,
    MATR_AMOR=AMOR, FREQ=3.0, EXCIT=_F(VECT_ASSE=F3, COEF_MULT=1.0))
B = DYNA_VIBRA(reuse=B, RESULTAT=A, TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MASS,
    MATR_RIGI=RIGI, MATR_AMOR=AMOR, FREQ=4.0, EXCIT=_F(VECT_ASSE=F3, COEF_MULT=1.0))
FIN()
"""
    )
    with pytest.raises(CommandError, match="RESULTAT must be the result given as reuse="):
        _run(tmp_path, deck)
