"""CALC_SPECTRE_IPM and the FFT / oscillator-spectrum pieces it is built on,
against closed forms."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands import calc_fonction, calc_spectre_ipm

from asterlite.concepts.function import Function
from asterlite.concepts.table import Table
from asterlite.errors import CommandError
from asterlite.post import functions as fops
from asterlite.post.floor_spectra import Equipment, corrected_acceleration, interaction_transfer
from tests.test_post_support import context, kw

EQUIPMENT = Equipment(
    mass_ratio=0.1,
    support_frequency=10.0,
    support_damping=0.07,
    mass_fractions=(0.5, 0.25, 0.25),
    frequencies=(10.0, 28.0, 7.0),
    dampings=(0.05, 0.05, 0.05),
)


def signal(n=2000, dt=1e-3):
    t = np.arange(n) * dt
    return Function(t, np.sin(2 * np.pi * 20 * t) * np.sin(np.pi * t / t[-1]), NOM_PARA="INST")


def test_inverse_fft_of_the_whole_spectrum_gives_the_signal_back():
    f = signal(2001)
    spectrum = calc_fonction.run(context(), kw(FFT=[{"FONCTION": f, "METHODE": "COMPLET"}]))
    back = calc_fonction.run(context(), kw(FFT=[{"FONCTION": spectrum, "METHODE": "COMPLET"}]))
    assert back.NOM_PARA == "INST" and not back.is_complex
    assert back.abscissas == pytest.approx(f.abscissas, abs=1e-12)
    assert back.ordinates == pytest.approx(f.ordinates, abs=1e-12)


@pytest.mark.parametrize("n", [2000, 2002])
def test_inverse_fft_mirrors_the_positive_half(n):
    """A band-limited signal is rebuilt from the first N/2 values of its
    spectrum (SYME='NON'), even or odd half length alike."""
    f = signal(n)
    spectrum = fops.fft(f, "COMPLET")
    half = n // 2
    positive = spectrum.with_values(spectrum.abscissas[:half], spectrum.ordinates[:half])
    out = calc_fonction.run(
        context(), kw(FFT=[{"FONCTION": positive, "METHODE": "COMPLET", "SYME": "NON"}])
    )
    m = out.ordinates.size
    assert m == (n if half % 2 == 0 else n - 2)
    step = 1.0 / (spectrum.abscissas[1] * m)
    assert out.abscissas[1] == pytest.approx(step)
    expected = np.interp(out.abscissas, f.abscissas, f.ordinates)
    assert np.abs(out.ordinates - expected).max() < 2e-2


def test_prol_zero_keeps_a_power_of_two_length():
    f = Function(np.arange(8) * 0.1, np.arange(8.0), NOM_PARA="INST")
    assert fops.fft(f, "PROL_ZERO").ordinates.size == 8
    g = Function(np.arange(9) * 0.1, np.arange(9.0), NOM_PARA="INST")
    assert fops.fft(g, "PROL_ZERO").ordinates.size == 16
    assert fops.fft(g, "TRONCATURE").ordinates.size == 8


def test_oscillator_spectrum_at_resonance_is_one_over_twice_the_damping():
    """Harmonic base acceleration at the oscillator's frequency: the steady
    pseudo-acceleration is A / (2 xi) (the start transient has died out)."""
    t = np.arange(0, 10.0, 1e-3)
    f = Function(t, 3.0 * np.sin(2 * np.pi * 5.0 * t), NOM_PARA="INST")
    value = fops.response_spectrum(f, [5.0], 0.05, "ACCE", 1.0)[0]
    assert value == pytest.approx(3.0 / (2 * 0.05), rel=2e-3)


def test_spectrum_for_all_frequencies_at_once_matches_one_by_one():
    """... and NORME divides the spectrum (the accelerogram is in the deck's units)."""
    f = signal()
    freqs = [2.0, 20.0, 45.0]
    together = fops.response_spectrum(f, freqs, 0.05, "ACCE", 9.81)
    alone = [
        (2 * np.pi * fr) ** 2
        * fops.sdof_peak_response(f.abscissas, f.ordinates, fr, 0.05)[0]
        / 9.81
        for fr in freqs
    ]
    assert together == pytest.approx(alone, rel=1e-12)


def transmissibility_of_model_b(w, eq: Equipment) -> complex:
    """Absolute support motion / base motion of the support (mass 1, the
    stiffness and damping coefficient of model A) carrying the equipment
    oscillators: the linear system solved directly."""
    lam = eq.mass_ratio
    omega_s = 2 * np.pi * eq.support_frequency
    k = (1 + lam) * omega_s**2
    c = 2 * (1 + lam) * eq.support_damping * omega_s
    n = len(eq.frequencies)
    a = np.zeros((n + 1, n + 1), dtype=complex)
    rhs = np.zeros(n + 1, dtype=complex)
    a[0, 0] = -(w**2) + k + 1j * w * c
    rhs[0] = k + 1j * w * c
    for i, (mu, f, xi) in enumerate(
        zip(eq.mass_fractions, eq.frequencies, eq.dampings, strict=True), 1
    ):
        m = lam * mu
        omega = 2 * np.pi * f
        z = m * omega**2 + 1j * w * 2 * m * xi * omega
        a[0, 0] += z
        a[0, i] = a[i, 0] = -z
        a[i, i] = -(w**2) * m + z
    return np.linalg.solve(a, rhs)[0]


def test_transfer_is_the_ratio_of_the_two_floor_transmissibilities():
    freqs = np.array([0.0, 3.0, 7.0, 9.5, 10.0, 12.0, 28.0, 60.0])
    transfer = interaction_transfer(freqs, EQUIPMENT)
    for f, value in zip(freqs, transfer, strict=True):
        w = 2 * np.pi * f
        omega_s = 2 * np.pi * EQUIPMENT.support_frequency
        damping = 2j * w * omega_s * EQUIPMENT.support_damping
        model_a = (omega_s**2 + damping) / (omega_s**2 - w**2 + damping)
        assert value == pytest.approx(transmissibility_of_model_b(w, EQUIPMENT) / model_a)


def test_no_equipment_mass_leaves_the_acceleration_unchanged():
    light = Equipment(0.0, 10.0, 0.07, (1.0,), (12.0,), (0.05,))
    assert interaction_transfer(np.linspace(0, 100, 7), light) == pytest.approx(np.ones(7))
    f = signal(2000)
    out = corrected_acceleration(f, light)
    assert out.abscissas == pytest.approx(f.abscissas)
    assert np.abs(out.ordinates - f.ordinates).max() < 2e-2


def ipm_keywords(function, **changes):
    values = dict(
        EQUIPEMENT=[dict(NOM="P", NOEUD=("7",), RAPPORT_MASSE_TOTALE=0.1,
                         COEF_MASS_EQUIP=(0.5, 0.25, 0.25), FREQ_EQUIP=(10.0, 28.0, 7.0),
                         FREQ_SUPPORT=10.0, AMOR_SUPPORT=0.07, AMOR_EQUIP=(0.05, 0.05, 0.05))],
        CALCUL="ABSOLU", AMOR_SPEC=(0.05, 0.02), FREQ=(5.0, 20.0), NORME=1.0,
        RESU=[dict(FONCTION=function)], TOLE_INIT=1e-3, CORR_INIT="NON",
    )  # fmt: skip
    values.update(changes)
    return kw(**values)


def test_command_table_columns_and_spectra():
    f = signal()
    table = calc_spectre_ipm.run(context(), ipm_keywords(f))
    assert isinstance(table, Table)
    assert table.columns == ["FREQ P", "IPM P 2%", "IPM P 5%"]
    expected = fops.response_spectrum(corrected_acceleration(f, EQUIPMENT), [5.0, 20.0], 0.05,
                                      "ACCE", 1.0)  # fmt: skip
    assert table.column("IPM P 5%") == pytest.approx(expected.tolist())


def test_command_reads_a_table_of_components():
    f = signal()
    rows = {"INST": f.abscissas.tolist(), "NOEUD": ["7"] * f.abscissas.size,
            "NOM_CHAM": ["ACCE"] * f.abscissas.size, "NOM_CMP": ["DZ"] * f.abscissas.size,
            "VALE": f.ordinates.tolist()}  # fmt: skip
    table = calc_spectre_ipm.run(
        context(), ipm_keywords(None, RESU=[dict(TABLE=Table.from_columns(rows))])
    )
    direct = calc_spectre_ipm.run(context(), ipm_keywords(f))
    assert table.column("IPM P 5%") == pytest.approx(direct.column("IPM P 5%"))


def test_command_refuses_a_signal_not_at_rest_unless_corrected():
    t = np.arange(1000) * 1e-3
    f = Function(t, np.cos(2 * np.pi * 20 * t), NOM_PARA="INST")
    with pytest.raises(CommandError, match="TOLE_INIT"):
        calc_spectre_ipm.run(context(), ipm_keywords(f))
    corrected = calc_spectre_ipm.run(context(), ipm_keywords(f, CORR_INIT="OUI"))
    assert np.all(np.isfinite(corrected.column("IPM P 5%")))


def test_command_refuses_mass_fractions_not_summing_to_one():
    occurrence = dict(ipm_keywords(signal())["EQUIPEMENT"][0])
    occurrence["COEF_MASS_EQUIP"] = (0.5, 0.25, 0.2)
    with pytest.raises(CommandError, match="sums to"):
        calc_spectre_ipm.run(context(), ipm_keywords(signal(), EQUIPEMENT=[occurrence]))


def test_spec_osci_scales_by_norme_and_stops_below_its_first_frequency():
    f = signal()
    occurrence = {"FONCTION": f, "AMOR_REDUIT": (0.05,), "FREQ": (2.0, 20.0), "NORME": 1.0,
                  "METHODE": "NIGAM", "NATURE": "ACCE", "TYPE_RESU": "FONCTION"}  # fmt: skip
    in_units = calc_fonction.run(context(), kw(SPEC_OSCI=[occurrence]))
    in_g = calc_fonction.run(context(), kw(SPEC_OSCI=[{**occurrence, "NORME": 9.81}]))
    assert in_g.ordinates == pytest.approx(in_units.ordinates / 9.81, rel=1e-12)
    assert (in_g.PROL_GAUCHE, in_g.PROL_DROITE) == ("EXCLU", "CONSTANT")
    with pytest.raises(CommandError):
        in_g(1.0)
