# ruff: noqa: E501 (deck text is kept on one line per command, as in the corpus)
"""Post-processing the substructuring decks need (issue 19): SIPM_ELNO, the
extreme axial stress over a beam section, and POST_ELEM ENER_CIN, the
kinetic energy of element groups."""

from __future__ import annotations

import numpy as np

from asterlite.fem.beam_elements import beam_extreme_stresses
from tests.test_substructure_beam import FRONT, GUIDED, matrices, run_case


def test_extreme_stresses_of_circle_and_rectangle():
    efge = np.zeros((1, 2, 2, 6))
    efge[0, :, :, 0] = 10.0  # N
    efge[0, :, :, 4] = 3.0  # MFY
    efge[0, :, :, 5] = -4.0  # MFZ
    circle = {"SECTION": "CERCLE", "R": 0.1, "A": 2.0, "IY": 0.5, "IZ": 0.5}
    rectangle = {"SECTION": "RECTANGLE", "HY": 0.2, "HZ": 0.4, "A": 2.0, "IY": 0.5, "IZ": 0.25}
    out = beam_extreme_stresses(efge, [circle, rectangle])
    bending_circle = 0.1 / 0.5 * 5.0  # R sqrt(MFY² + MFZ²) / IY
    bending_rectangle = 3.0 / 0.5 * 0.2 + 4.0 / 0.25 * 0.1  # |MFY| HZ/2/IY + |MFZ| HY/2/IZ
    np.testing.assert_allclose(out[0, 0, :, 0], 5.0 - bending_circle)
    np.testing.assert_allclose(out[0, 0, :, 1], 5.0 + bending_circle)
    np.testing.assert_allclose(out[0, 1, :, 0], 5.0 - bending_rectangle)
    np.testing.assert_allclose(out[0, 1, :, 1], 5.0 + bending_rectangle)


def energy_deck() -> str:
    deck = FRONT.format(guided=GUIDED)
    deck += 'CLAMP = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO="A", DY=0.0, DRZ=0.0))\n'
    deck += matrices("W", "GUIDE, CLAMP")
    deck += """
MAYA = DEFI_GROUP(reuse=MAYA, MAILLAGE=MAYA, CREA_GROUP_MA=_F(NOM="DEBUT", MAILLE=("S1", "S2")))
MODES = CALC_MODES(MATR_RIGI=KA_W, MATR_MASS=MA_W, CALC_FREQ=_F(NMAX_FREQ=2))
ECIN = POST_ELEM(ENER_CIN=_F(GROUP_MA=("TOUT", "DEBUT")), MODELE=MODEL, CHAM_MATER=CHMAT, CARA_ELEM=CARA, RESULTAT=MODES)
SIPM = CALC_CHAMP(RESULTAT=MODES, MODELE=MODEL, CHAM_MATER=CHMAT, CARA_ELEM=CARA, CONTRAINTE="SIPM_ELNO")
FIN()
"""
    return deck


def test_kinetic_energy_of_modes_and_extreme_stresses(tmp_path):
    from tests.test_substructure_beam import beam_mesh

    result = run_case(tmp_path, "energy", energy_deck(), beam_mesh(6, 1.0))
    modes = result.concepts.raw["MODES"]
    table = result.concepts.raw["ECIN"]
    lieu = np.array(table.column("LIEU"))
    totale = np.array(table.column("TOTALE"), dtype=float)
    share = np.array(table.column("POUR_CENT"), dtype=float)
    whole = totale[lieu == "TOUT"]
    # the whole beam: ½ ω² φᵀ M φ of each mode
    np.testing.assert_allclose(whole, 0.5 * modes.omega2 * modes.generalized_mass, rtol=1e-10)
    np.testing.assert_allclose(share[lieu == "TOUT"], 100.0)
    part = totale[lieu == "DEBUT"]
    assert np.all((part > 0) & (part < whole))  # the clamped end moves least
    sipm = result.concepts.raw["SIPM"].element_fields["SIPM_ELNO"]
    assert sipm.components == ("SIXXMIN", "SIXXMAX")
    # pure bending in the XY plane: N = 0, the extremes are opposite
    np.testing.assert_allclose(
        sipm.values[..., 0], -sipm.values[..., 1], atol=1e-9 * np.abs(sipm.values).max()
    )
