"""Random excitation: DEFI_INTE_SPEC, LIRE_INTE_SPEC, GENE_FONC_ALEA,
CALC_INTE_SPEC, RECU_FONCTION(INTE_SPEC=...), and a statistical test of a
generated signal's spectral density against its target."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from asterlite.concepts.function import ComplexFunction, Function
from asterlite.concepts.interspectrum import InterSpectrum
from asterlite.errors import CommandError, UnsupportedError
from asterlite.post import spectral
from tests.test_fem_support import FakeSession, run

WIDER = Path(__file__).resolve().parent.parent.parent / "shared" / "aster-corpus-wider"


def band_spectrum(level=2.0, band=(10.0, 40.0), fmax=100.0, cross=None) -> InterSpectrum:
    """A flat density ``level`` on ``band`` (zero elsewhere), 1x1, or 2x2 with
    S22 = level / 4 and S12 = cross * sqrt(S11 S22) when ``cross`` is given."""
    f = np.linspace(0.0, fmax, 401)
    s11 = np.where((f >= band[0]) & (f <= band[1]), level, 0.0)
    if cross is None:
        return InterSpectrum("FREQ", f, [(1, 1)], [s11])
    s22 = s11 / 4.0
    s12 = cross * np.sqrt(s11 * s22) + 0j
    return InterSpectrum("FREQ", f, [(1, 1), (1, 2), (2, 2)], [s11, s12, s22])


def generated(session, inter, draws=40, points=1024, seed=None):
    values = dict(INTE_SPEC=inter, FREQ_INIT=0.0, FREQ_FIN=100.0, NB_POIN=points)
    if seed is not None:
        values["INIT_ALEA"] = seed
    return run(session, "GENE_FONC_ALEA", INTERPOL="OUI", NB_TIRAGE=draws, INFO=1, **values)


def signal(session, vect, k=1):
    return run(
        session,
        "RECU_FONCTION",
        INTE_SPEC=vect,
        NUME_ORDRE=k,
        INTERPOL="LIN",
        PROL_DROITE="CONSTANT",
        PROL_GAUCHE="EXCLU",
    )


# -- numerics -----------------------------------------------------------------


def test_radix2_fft_matches_the_dft():
    rng = np.random.default_rng(1)
    x = rng.normal(size=64) + 1j * rng.normal(size=64)
    assert np.allclose(spectral.radix2_fft(x), np.fft.fft(x), rtol=0, atol=1e-12)
    assert np.allclose(spectral.radix2_fft(x, inverse=True), np.fft.ifft(x), atol=1e-14)
    with pytest.raises(ValueError, match="power of two"):
        spectral.radix2_fft(np.ones(6))


def test_factor_reproduces_the_matrix_in_code_aster_convention():
    s = np.array([[2.0, 0.5 + 0.3j], [0.5 - 0.3j, 1.0]])
    r = spectral.factor(s)
    assert np.allclose(r @ r.conj().T, s)
    for j in range(2):  # largest component of each column real positive
        column = r[:, j]
        k = np.argmax(np.abs(column.real) + np.abs(column.imag))
        assert abs(column[k].imag) < 1e-14 and column[k].real > 0
    # eigenvalues ascending: the first column carries the smaller one
    assert np.linalg.norm(r[:, 0]) < np.linalg.norm(r[:, 1])
    assert np.array_equal(spectral.factor(np.zeros((2, 2), complex)), np.zeros((2, 2)))
    with pytest.raises(ValueError, match="zero first diagonal"):
        spectral.factor(np.array([[0.0, 1.0], [1.0, 1.0]], complex))


def test_generation_grid_as_code_aster_derives_it():
    # sdll107a: FREQ_FIN=500, NB_POIN=512, no DUREE_TIRAGE
    grid = spectral.generation_grid(np.linspace(0, 500, 11), True, 0.0, 500.0, 512, -1.0)
    assert grid.frequencies.size == 512 and grid.frequencies[0] == 0.0
    assert grid.frequencies[1] == 500.0 / 511
    # NB_POIN not a power of two is raised to the next one, with a warning
    grid = spectral.generation_grid(np.linspace(0, 500, 11), True, 0.0, 500.0, 300, -1.0)
    assert grid.frequencies.size == 512 and grid.warnings
    # DUREE_TIRAGE fixes the step; the Shannon rule fixes the count
    grid = spectral.generation_grid(np.linspace(0, 50, 11), True, 0.0, 50.0, None, 8.0)
    assert grid.frequencies[1] - grid.frequencies[0] == pytest.approx(1 / 8.0)
    assert grid.frequencies.size == 2 ** int(np.log2(2 * 50 * 8))


def test_same_seed_same_signal_and_stream_continues():
    inter = band_spectrum()
    first = generated(FakeSession(), inter, draws=2, seed=7)
    again = generated(FakeSession(), inter, draws=2, seed=7)
    assert np.array_equal(first.values[0], again.values[0])
    session = FakeSession()
    a = generated(session, inter, draws=2)
    b = generated(session, inter, draws=2)  # the deck's stream goes on
    assert not np.array_equal(a.values[0], b.values[0])
    assert np.array_equal(a.values[0], generated(FakeSession(), inter, draws=2, seed=0).values[0])


# -- statistics ----------------------------------------------------------------


def test_generated_signal_variance_is_the_two_sided_integral():
    """Parseval: each draw's mean square is 2 sum S(f_k) df over the grid
    (the density is two-sided, as code_aster's), to rounding."""
    inter = band_spectrum(level=2.0)
    vect = generated(FakeSession(), inter, draws=3)
    grid = spectral.generation_grid(inter.disc, True, 0.0, 100.0, 1024, -1.0)
    sampled = spectral.sampled_matrix(inter, grid, True)[:, 0, 0].real
    df = grid.frequencies[1] - grid.frequencies[0]
    expected = 2.0 * np.sum(sampled[1:]) * df
    n = (vect.disc.size - 1) // 3
    for draw in range(3):
        chunk = vect.values[0][1 + n * draw : 1 + n * (draw + 1)]
        assert np.mean(chunk**2) == pytest.approx(expected, rel=1e-10)
    assert expected == pytest.approx(2.0 * 2.0 * 30.0, rel=0.02)


def test_generation_on_the_spectrum_own_grid():
    """INTERPOL='NON': the spectrum's own constant step, no interpolation; the
    grid is completed to a power of two with zeros beyond the spectrum."""
    f = np.arange(0.0, 50.25, 0.5)
    s = 1.0 + 0.01 * f
    inter = InterSpectrum("FREQ", f, [(1, 1)], [s])
    vect = run(FakeSession(), "GENE_FONC_ALEA", INTE_SPEC=inter, INTERPOL="NON", NB_TIRAGE=1)
    n_fft = 128  # 2 ** (int(log2(50 / 0.5)) + 1)
    assert vect.disc.size == 2 * n_fft + 1
    assert vect.disc[1] == 1.0 / 0.5 / (2 * n_fft)  # the step of the spectrum gives T
    signal = vect.values[0][1:]
    # Parseval on the copied samples (the zero frequency is left out, as code_aster does)
    assert np.mean(signal**2) == pytest.approx(2.0 * np.sum(s[1:]) * 0.5, rel=1e-10)
    with pytest.raises(CommandError, match="constant frequency step"):
        uneven = InterSpectrum("FREQ", [0.0, 1.0, 3.0], [(1, 1)], [np.ones(3)])
        run(FakeSession(), "GENE_FONC_ALEA", INTE_SPEC=uneven, INTERPOL="NON", NB_TIRAGE=1)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_estimated_density_matches_the_target(seed):
    """Welch estimate of a generated signal (80 windows of half a draw, so that
    the windows cut across draws, sampled on the signal's own instants: no
    interpolation filter) against the target density. The random-phase
    method fixes each frequency's amplitude, so the scatter comes from the
    windows only: measured under 1 % for 5 Hz sub-bands (seeds 0, 1, 2, 5);
    the tolerance is 5 % per sub-band, and 2 % of the level away from the
    band edges (rectangular-window leakage)."""
    session = FakeSession()
    level = 2.0
    vect = generated(session, band_spectrum(level=level), draws=40, seed=seed)
    fonct = signal(session, vect)
    t_end = float(vect.disc[-1])
    window = t_end / 80
    inters = run(
        session,
        "CALC_INTE_SPEC",
        INST_INIT=0.0,
        INST_FIN=t_end,
        DUREE_ANALYSE=window,
        DUREE_DECALAGE=window,
        NB_POIN=1024,
        FONCTION=fonct,
        INFO=1,
    )
    rep = run(session, "RECU_FONCTION", INTE_SPEC=inters, NUME_ORDRE_I=1)
    f, s = rep.abscissas, rep.ordinates
    for low in np.arange(12.5, 37.5, 5.0):
        inside = (f >= low) & (f < low + 5.0)
        assert np.mean(s[inside]) == pytest.approx(level, rel=0.05)
    outside = (f > 50.0) | (f < 5.0)
    assert np.all(s[outside] < 0.02 * level)


def test_cross_spectrum_coherence_is_reproduced():
    session = FakeSession()
    coherence = 0.6  # |S12|^2 / (S11 S22) = 0.36
    vect = generated(session, band_spectrum(cross=coherence), draws=40, seed=3)
    signals = [signal(session, vect, k) for k in (1, 2)]
    t_end = float(vect.disc[-1])
    inters = run(
        session,
        "CALC_INTE_SPEC",
        INST_INIT=0.0,
        INST_FIN=t_end,
        DUREE_ANALYSE=t_end / 80,
        DUREE_DECALAGE=t_end / 80,
        NB_POIN=1024,
        FONCTION=signals,
        INFO=1,
    )
    s11 = run(session, "RECU_FONCTION", INTE_SPEC=inters, NUME_ORDRE_I=1)
    s22 = run(session, "RECU_FONCTION", INTE_SPEC=inters, NUME_ORDRE_I=2)
    s12 = run(session, "RECU_FONCTION", INTE_SPEC=inters, NUME_ORDRE_I=1, NUME_ORDRE_J=2)
    assert isinstance(s12, ComplexFunction) and isinstance(s11, Function)
    band = (s11.abscissas > 12.0) & (s11.abscissas < 38.0)
    gamma2 = np.abs(np.mean(s12.ordinates[band])) ** 2 / (
        np.mean(s11.ordinates[band]) * np.mean(s22.ordinates[band])
    )
    assert gamma2 == pytest.approx(coherence**2, abs=0.08)
    ratio = np.mean(s22.ordinates[band]) / np.mean(s11.ordinates[band])
    assert ratio == pytest.approx(0.25, rel=0.1)


# -- commands -----------------------------------------------------------------


def test_defi_inte_spec_terms():
    session = FakeSession()
    cplx = ComplexFunction(np.array([0.0, 10.0]), np.array([1 + 2j, 3 + 4j]), NOM_PARA="FREQ")
    real = Function(np.array([0.0, 10.0]), np.array([5.0, 6.0]), NOM_PARA="FREQ")
    inter = run(
        session,
        "DEFI_INTE_SPEC",
        DIMENSION=2,
        PAR_FONCTION=[
            {"NUME_ORDRE_I": 1, "NUME_ORDRE_J": 1, "FONCTION": cplx},
            {"NUME_ORDRE_I": 1, "NUME_ORDRE_J": 2, "FONCTION": real},
            {"NUME_ORDRE_I": 2, "NUME_ORDRE_J": 2, "FONCTION": real},
        ],
    )
    # a diagonal term keeps the real part; a real off-diagonal term gets a zero imaginary part
    assert np.array_equal(inter.lookup((1, 1)), [1.0, 3.0])
    assert np.array_equal(inter.lookup((2, 1)), [5.0, 6.0])
    assert inter.lookup((1, 2)).dtype.kind == "c"
    kt = run(
        session,
        "DEFI_INTE_SPEC",
        KANAI_TAJIMI={
            "NUME_ORDRE_I": 1,
            "NUME_ORDRE_J": 1,
            "FREQ_MIN": 0.0,
            "FREQ_MAX": 10.0,
            "PAS": 3.0,
            "AMOR_REDUIT": 0.6,
            "FREQ_MOY": 5.0,
            "VALE_R": 1.0,
        },
    )
    assert list(kt.disc) == [0.0, 3.0, 6.0, 10.0]  # the last point is FREQ_MAX
    f, fg, xi = 3.0, 5.0, 0.6
    expected = 2 * np.pi * (fg**4 + 4 * xi**2 * fg**2 * f**2)
    expected /= (fg**2 - f**2) ** 2 + 4 * xi**2 * fg**2 * f**2
    assert kt.values[0][1] == pytest.approx(expected, rel=1e-14)
    assert kt.values[0][0] == pytest.approx(2 * np.pi)
    with pytest.raises(CommandError, match="FREQ_MAX"):
        run(
            session,
            "DEFI_INTE_SPEC",
            CONSTANT={
                "NUME_ORDRE_I": 1,
                "NUME_ORDRE_J": 1,
                "FREQ_MIN": 5.0,
                "FREQ_MAX": 1.0,
                "PAS": 1.0,
                "VALE_R": 1.0,
            },
        )


def test_lire_inte_spec_formats_and_errors(tmp_path):
    text = "\n".join(
        [
            "INTERSPECTRE",
            "DIM = 2",
            *[
                line
                for i, j, vals in (
                    (1, 1, "2.0 0.0"),
                    (1, 2, "1.0 1.5707963267948966"),
                    (2, 2, "3.0 0.0"),
                )
                for line in (
                    "FONCTION_C",
                    f"I = {i}",
                    f"J = {j}",
                    "NB_POIN = 2",
                    "VALEUR =",
                    f" 0.0 {vals}",
                    f" 5.0 {vals}",
                    "FINSF",
                )
            ],
            "FIN",
        ]
    )
    path = tmp_path / "spec.txt"
    path.write_text(text)
    session = FakeSession({19: path})
    inter = run(
        session,
        "LIRE_INTE_SPEC",
        UNITE=19,
        FORMAT="ASTER",
        FORMAT_C="MODULE_PHASE",
        NOM_PARA="FREQ",
        NOM_RESU="DSP",
    )
    assert inter.keys == [(1, 1), (1, 2), (2, 2)]
    assert inter.lookup((1, 2))[0] == pytest.approx(1j, abs=1e-15)  # modulus 1, phase pi/2
    path.write_text(text.replace("J = 2\nNB", "J = 1\nNB", 1))
    with pytest.raises(CommandError, match="row order"):
        run(
            session,
            "LIRE_INTE_SPEC",
            UNITE=19,
            FORMAT="ASTER",
            FORMAT_C="REEL_IMAG",
            NOM_PARA="FREQ",
            NOM_RESU="DSP",
        )
    with pytest.raises(UnsupportedError, match="IDEAS"):
        run(
            session,
            "LIRE_INTE_SPEC",
            UNITE=19,
            FORMAT="IDEAS",
            FORMAT_C="REEL_IMAG",
            NOM_PARA="FREQ",
            NOM_RESU="DSP",
        )


def test_gene_fonc_alea_refusals():
    session = FakeSession()
    partial = InterSpectrum("FREQ", [0.0, 10.0], [(1, 1), (2, 2)], [np.ones(2), np.ones(2)])
    with pytest.raises(CommandError, match="upper triangle"):
        generated(session, partial, draws=1)
    with pytest.raises(UnsupportedError, match="NUME_VITE_FLUI"):
        run(
            session,
            "GENE_FONC_ALEA",
            INTE_SPEC=band_spectrum(),
            NUME_VITE_FLUI=1,
            INTERPOL="OUI",
            NB_TIRAGE=1,
        )
    with pytest.raises(CommandError, match="power of two"):
        run(
            session,
            "CALC_INTE_SPEC",
            INST_INIT=0.0,
            INST_FIN=1.0,
            NB_POIN=100,
            FONCTION=Function(np.array([0.0, 1.0]), np.array([0.0, 1.0])),
        )


def test_sdll107a_deck_passes(tmp_path):
    export = WIDER / "sdll107a" / "sdll107a.export"
    if not export.is_file():
        pytest.skip("../shared/aster-corpus-wider is not available")
    from asterlite.api import run as run_deck

    result = run_deck(export, tmp_path / "out")
    assert result.status == "PASS"
