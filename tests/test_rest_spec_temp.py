"""REST_SPEC_TEMP (asterlite.post.result_fourier): closed forms of the
transforms with code_aster's lengths and mirrored spectrum, a round trip
time -> frequency -> time, the command on results, and AFFE_CHAR_MECA
VECT_ASSE (an assembled vector as a load) against the nodal force it came from."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import CommandError
from asterlite.post.result_fourier import frequency_to_time, time_to_frequency
from tests.test_fem_structures import beam_model, line_mesh
from tests.test_fem_support import FakeSession, run


def test_one_bin_gives_a_cosine_on_twice_the_power_of_two():
    # 5 frequencies (n=3: 8 bins, 16 instants with SYMETRIE='NON'), amplitude A at bin 2
    df, amplitude = 0.5, 3.0 - 1.0j
    spectrum = np.zeros((5, 1), complex)
    spectrum[2, 0] = amplitude
    instants, signal = frequency_to_time(df * np.arange(5), spectrum, "PROL_ZERO", False, 0)
    assert instants.size == 16
    np.testing.assert_allclose(np.diff(instants), 1.0 / (16 * df))
    expected = 2.0 * (amplitude * np.exp(2j * np.pi * 2 * np.arange(16) / 16)).real / 16
    np.testing.assert_allclose(signal[:, 0], expected, atol=1e-15)


def test_power_of_two_count_extrapolates_the_bin_after_nyquist():
    # 4 frequencies, N_PUIS=0: 8 bins; bin 5 (after the empty middle) takes -Re X[3] / 3
    spectrum = np.array([[1.0], [0.0], [0.0], [2.0 + 1.0j]])
    _, signal = frequency_to_time(np.arange(4.0), spectrum, "PROL_ZERO", False, 0)
    full = np.zeros(8, complex)
    full[0], full[3], full[5] = 1.0, 2.0 + 1.0j, -2.0 / 3.0
    np.testing.assert_allclose(signal[:, 0], np.fft.ifft(full).real, atol=1e-15)


def test_round_trip_of_a_band_limited_signal():
    dt, count = 0.01, 256
    t = dt * np.arange(count)
    df = 1.0 / (count * dt)
    values = np.column_stack(
        [np.cos(2 * np.pi * 5 * df * t), 0.3 + np.sin(2 * np.pi * 12 * df * t)]
    )
    frequencies, spectra = time_to_frequency(t, values, "PROL_ZERO", False, 0)
    assert frequencies.size == count // 2
    np.testing.assert_allclose(frequencies[1], df)
    assert spectra[5, 0] == pytest.approx(count / 2)
    instants, back = frequency_to_time(frequencies, spectra, "PROL_ZERO", False, 0)
    np.testing.assert_allclose(instants, t, atol=1e-12)
    np.testing.assert_allclose(back, values, atol=1e-12)


def test_lengths_of_n_puis_and_troncature():
    t = 0.1 * np.arange(100)
    values = np.ones((100, 1))
    frequencies, _ = time_to_frequency(t, values, "PROL_ZERO", False, 1)
    assert frequencies.size == 128  # 2**(7+1) / 2
    frequencies, spectra = time_to_frequency(t, values, "TRONCATURE", False, 0)
    assert frequencies.size == 32 and spectra[0, 0] == pytest.approx(64.0)
    instants, _ = frequency_to_time(np.arange(100.0), np.ones((100, 1)), "TRONCATURE", False, 0)
    assert instants.size == 128
    with pytest.raises(ValueError, match="TRONCATURE"):
        time_to_frequency(t, values, "TRONCATURE", True, 0)


def test_command_orders_fields_and_conversions():
    session = FakeSession()
    model, _, _ = beam_model(session, line_mesh(2, 1.0))
    numbering = run(session, "NUME_DDL", MODELE=model)
    n = numbering.n_dofs
    df = 0.25
    spectra = np.zeros((9, n), complex)
    spectra[3] = 1.0 + 0.5j
    harmonic = DynaHarmo(
        numbering=numbering, frequencies=df * np.arange(9), order=np.arange(1, 10),
        fields={"ACCE": spectra}, model=model,
    )  # fmt: skip
    transient = run(session, "REST_SPEC_TEMP", RESULTAT=harmonic, METHODE="PROL_ZERO",
                    SYMETRIE="NON", N_PUIS=0, TOUT_CHAM="OUI")  # fmt: skip
    assert isinstance(transient, DynaTrans)
    assert list(transient.fields) == ["ACCE"]
    assert transient.order[0] == 0 and transient.times.size == 32
    with pytest.raises(CommandError, match="no field DEPL"):
        run(session, "REST_SPEC_TEMP", RESULTAT=transient, METHODE="PROL_ZERO", SYMETRIE="NON",
            N_PUIS=0)  # fmt: skip
    back = run(session, "REST_SPEC_TEMP", RESULTAT=transient, METHODE="PROL_ZERO",
               SYMETRIE="NON", N_PUIS=0, NOM_CHAM=("ACCE",))  # fmt: skip
    assert isinstance(back, DynaHarmo) and back.order[0] == 1
    np.testing.assert_allclose(back.frequencies[:9], harmonic.frequencies)
    np.testing.assert_allclose(back.fields["ACCE"][:9], spectra, atol=1e-12)


def test_vect_asse_load_acts_as_its_forces():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(4, 2.0))
    clamp = run(session, "AFFE_CHAR_MECA", MODELE=model,
                DDL_IMPO={"GROUP_NO": "A", "LIAISON": "ENCASTRE"})  # fmt: skip
    force = run(session, "AFFE_CHAR_MECA", MODELE=model,
                FORCE_NODALE={"GROUP_NO": "B", "FY": 3.0, "MZ": 0.5})  # fmt: skip
    numbering = run(session, "NUME_DDL", MODELE=model)
    elementary = run(session, "CALC_VECT_ELEM", CHARGE=force, OPTION="CHAR_MECA")
    vector = run(session, "ASSE_VECTEUR", VECT_ELEM=elementary, NUME_DDL=numbering)
    as_vector = run(session, "AFFE_CHAR_MECA", MODELE=model, VECT_ASSE=vector)
    solutions = []
    for load in (force, as_vector):
        result = run(session, "MECA_STATIQUE", MODELE=model, CHAM_MATER=field, CARA_ELEM=cara,
                     EXCIT=[{"CHARGE": clamp}, {"CHARGE": load}])  # fmt: skip
        solutions.append(result.fields["DEPL"][0])
    assert np.abs(solutions[0]).max() > 0.0
    np.testing.assert_allclose(solutions[1], solutions[0], rtol=1e-12)


def test_generalized_results_both_ways():
    from asterlite.concepts.harmonic import HarmGene
    from asterlite.concepts.transient import TranGene

    session = FakeSession()
    basis = object()
    spectra = np.zeros((9, 2), complex)
    spectra[2] = [1.0 - 2.0j, 0.5j]
    harmonic = HarmGene(basis=basis, numbering=None, frequencies=0.5 * np.arange(9),
                        order=np.arange(1, 10), fields={"DEPL": spectra})  # fmt: skip
    transient = run(session, "REST_SPEC_TEMP", RESU_GENE=harmonic, METHODE="PROL_ZERO",
                    SYMETRIE="NON", N_PUIS=0)  # fmt: skip
    assert isinstance(transient, TranGene) and transient.basis is basis
    assert transient.order[0] == 0 and transient.times.size == 32
    assert not transient.vite.any() and not transient.acce.any()  # not computed: zero
    t = transient.times
    expected = 2.0 * (spectra[2][None, :] * np.exp(2j * np.pi * 1.0 * t[:, None])).real / 32
    np.testing.assert_allclose(transient.depl, expected, atol=1e-15)
    back = run(session, "REST_SPEC_TEMP", RESU_GENE=transient, METHODE="PROL_ZERO",
               SYMETRIE="NON", N_PUIS=0, NOM_CHAM=("DEPL",))  # fmt: skip
    assert isinstance(back, HarmGene) and list(back.fields) == ["DEPL"]
    np.testing.assert_allclose(back.fields["DEPL"][:9], spectra, atol=1e-14)
