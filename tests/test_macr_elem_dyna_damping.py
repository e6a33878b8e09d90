"""MACR_ELEM_DYNA's generalized damping and measured model, against code_aster's
formulas: AMOR_REDUIT gives c_ii = 4π f_i ξ_i m_i = 2 ξ_i ω_i m_i on the dynamic
modes only (calamo: the last ratio repeated, static modes undamped);
MODELE_MESURE gives diagonal m_i, k_i = (2π f_i)² m_i, c_i = 2 ξ_i √(k_i m_i)
(op0081), so each mode keeps its frequency and reduced damping."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from asterlite.commands import macr_elem_dyna

from asterlite.errors import CommandError
from asterlite.runtime.context import CommandContext
from tests.test_fem_support import FakeSession, keywords


def _ctx():
    return CommandContext(session=FakeSession(), command="MACR_ELEM_DYNA")


def _basis():
    # three eigenmodes then two static (interface) modes, as DEFI_BASE_MODALE CLASSIQUE
    kinds = np.array(["MODE_DYN"] * 3 + ["MODE_STA"] * 2, dtype=object)
    return SimpleNamespace(
        n_modes=5,
        frequencies=np.array([2.0, 5.0, 9.0, 0.0, 0.0]),
        generalized_mass=np.array([1.5, 2.0, 0.5, 3.0, 4.0]),
        parameters={"TYPE_MODE": kinds},
    )


def test_amor_reduit_gives_modal_damping_on_the_dynamic_modes():
    basis = _basis()
    kw = keywords("MACR_ELEM_DYNA", {"AMOR_REDUIT": (0.01, 0.02)})
    damping = macr_elem_dyna.reduced_damping(_ctx(), kw, basis)
    ratios = np.array([0.01, 0.02, 0.02])  # the last ratio stands for mode 3
    omega = 2 * math.pi * basis.frequencies[:3]
    expected = np.zeros((5, 5))
    expected[[0, 1, 2], [0, 1, 2]] = 2 * ratios * omega * basis.generalized_mass[:3]
    np.testing.assert_allclose(damping, expected, rtol=1e-14)
    assert not damping[3:].any() and not damping[:, 3:].any()


def test_extra_amor_reduit_values_are_dropped():
    kw = keywords("MACR_ELEM_DYNA", {"AMOR_REDUIT": (0.01, 0.02, 0.03, 0.5, 0.5)})
    damping = macr_elem_dyna.reduced_damping(_ctx(), kw, _basis())
    assert damping[2, 2] == pytest.approx(4 * math.pi * 9.0 * 0.03 * 0.5, rel=1e-14)


def test_modele_mesure_keeps_each_mode_frequency_and_damping():
    occ = keywords(
        "MACR_ELEM_DYNA",
        {
            "MODELE_MESURE": {
                "FREQ": (1.0, 4.0),
                "MASS_GENE": (2.0, 0.5),
                "AMOR_REDUIT": (0.05, 0.1),
            }
        },
    ).factor("MODELE_MESURE")[0]
    m = macr_elem_dyna.measured_matrices(_ctx(), occ, 2)
    k, mass, c = np.diag(m["MATR_RIGI"]), np.diag(m["MATR_MASS"]), np.diag(m["MATR_AMOR"])
    np.testing.assert_allclose(np.sqrt(k / mass) / (2 * math.pi), [1.0, 4.0], rtol=1e-14)
    np.testing.assert_allclose(c / (2 * np.sqrt(k * mass)), [0.05, 0.1], rtol=1e-14)
    assert not (m["MATR_RIGI"] - np.diag(k)).any()


def test_modele_mesure_needs_one_value_per_basis_vector():
    occ = keywords(
        "MACR_ELEM_DYNA", {"MODELE_MESURE": {"FREQ": (1.0,), "MASS_GENE": (2.0, 0.5)}}
    ).factor("MODELE_MESURE")[0]
    with pytest.raises(CommandError, match="FREQ gives 1 values for the 2 vectors"):
        macr_elem_dyna.measured_matrices(_ctx(), occ, 2)
