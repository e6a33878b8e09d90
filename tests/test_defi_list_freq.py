"""DEFI_LIST_FREQ RAFFINEMENT (code_aster's defi_list_freq_ops) in closed
form, and mode_meca's LIST_VARI_ACCES that decks feed it with."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.errors import CommandError
from tests.test_fem_support import FakeSession, run


def refine(**occurrence):
    session = FakeSession()
    base = {"NB_POINTS": 5, "PAS_MINI": 0.001, "CRITERE": "RELATIF", "DISPERSION": 0.01}
    base.update(occurrence)
    return run(session, "DEFI_LIST_FREQ", VALE=(5.0, 40.0), RAFFINEMENT=base).values


def test_largeur_3db_band_around_the_damped_resonance():
    values = refine(LIST_RAFFINE=(10.0,), CRITERE="LARGEUR_3DB", NB_POINTS=3,
                    AMOR_REDUIT=(0.05,))  # fmt: skip
    centre = 10.0 * np.sqrt(1.0 - 2.0 * 0.05**2)
    width = 2.0 * 0.05 * centre
    np.testing.assert_allclose(
        values, [5.0, centre - width / 2, centre, centre + width / 2, 40.0], rtol=1e-14
    )


def test_even_count_adds_the_centre_and_the_undamped_frequency():
    values = refine(LIST_RAFFINE=(10.0, 20.0), CRITERE="LARGEUR_3DB", NB_POINTS=2,
                    AMOR_REDUIT=(0.1,))  # fmt: skip
    # the last damping serves the second frequency too
    for f in (10.0, 20.0):
        centre = f * np.sqrt(0.98)
        for expected in (centre - 0.1 * centre, centre, centre + 0.1 * centre, f):
            assert np.min(np.abs(values - expected)) < 1e-12
    assert values.size == 2 + 2 * 4


def test_relatif_and_thinning():
    values = refine(LIST_RAFFINE=(20.0, 20.0005), NB_POINTS=3, DISPERSION=0.1)
    np.testing.assert_allclose(values, [5.0, 19.0, 20.0, 21.0, 40.0], rtol=1e-14)
    with pytest.raises(CommandError, match="even NB_POINTS"):
        refine(LIST_RAFFINE=(20.0,), NB_POINTS=4)


def test_list_vari_acces_of_modes():
    from tests.test_fem_structures import assembled, beam_model, line_mesh

    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(6, 1.0))
    bound = assembled(session, model, field, cara, {"GROUP_NO": "A", "LIAISON": "ENCASTRE"})
    stiffness, mass = bound["RIGI_MECA"], bound["MASS_MECA"]
    modes = run(session, "CALC_MODES", MATR_RIGI=stiffness, MATR_MASS=mass, OPTION="PLUS_PETITE",
                CALC_FREQ={"NMAX_FREQ": 3})  # fmt: skip
    access = modes.LIST_VARI_ACCES()
    assert access["NUME_ORDRE"] == [1, 2, 3]
    np.testing.assert_allclose(access["FREQ"], modes.frequencies)
