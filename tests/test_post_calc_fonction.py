"""CALC_FONCTION, INFO_FONCTION and LIRE_FONCTION on hand-computed data."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands import calc_fonction, info_fonction, lire_fonction

from asterlite.concepts.function import Function, FunctionDomainError, Nappe
from asterlite.post import functions as fops
from tests.test_post_support import context, kw


def line(x, y, **params):
    return Function(np.asarray(x, float), np.asarray(y, float), **params)


def test_comb_uses_the_common_support():
    f = line([0, 1, 2], [0, 1, 2], NOM_PARA="INST")
    g = line([0.5, 1.5, 3], [1, 1, 1])
    h = calc_fonction.run(
        context(), kw(COMB=[{"FONCTION": f, "COEF": 2.0}, {"FONCTION": g, "COEF": -1.0}])
    )
    assert h.abscissas.tolist() == [0.5, 1.0, 1.5, 2.0]  # both EXCLU: the overlap
    assert h.ordinates.tolist() == pytest.approx([0.0, 1.0, 2.0, 3.0])
    assert h.NOM_PARA == "INST"


def test_comb_on_list_para_and_constant_extension():
    f = line([0, 1], [0, 1], PROL_DROITE="CONSTANT")
    out = calc_fonction.run(
        context(), kw(COMB=[{"FONCTION": f, "COEF": 1.0}], LIST_PARA=(0.5, 2.0))
    )
    assert out.ordinates.tolist() == pytest.approx([0.5, 1.0])


def test_integrals_of_a_parabola():
    x = np.linspace(0.0, 1.0, 11)
    f = line(x, x**2, NOM_RESU="ACCE")
    simpson = fops.integrate(f, "SIMPSON")
    assert simpson.ordinates[-1] == pytest.approx(1 / 3, rel=1e-12)  # exact for parabolas
    assert simpson.NOM_RESU == "VITE" and simpson.PROL_DROITE == "EXCLU"
    trapeze = fops.integrate(f, "TRAPEZE", 1.0)
    assert trapeze.ordinates[-1] == pytest.approx(1.0 + 1 / 3 + 0.1**2 / 6)


def test_derivative_weighted_centred():
    x = np.array([0.0, 1.0, 3.0])
    d = fops.derivative(line(x, x**2, NOM_RESU="DEPL"))
    # slopes 1 and 4; centre: (1·1 + 4·2)/3 = 3
    assert d.ordinates.tolist() == pytest.approx([1.0, 3.0, 4.0])
    assert d.NOM_RESU == "VITE"


def test_abs_power_inverse_compose_asse():
    f = line([0, 1, 2], [-1, 0, 3], PROL_DROITE="LINEAIRE")
    assert fops.absolute(f).ordinates.tolist() == [1, 0, 3]
    assert fops.absolute(f).PROL_DROITE == "EXCLU"
    assert fops.power(f, 2).ordinates.tolist() == [1, 0, 9]
    inv = fops.inverse(line([0, 1, 2], [0, 2, 4]))
    assert inv.abscissas.tolist() == [0, 2, 4] and inv.ordinates.tolist() == [0, 1, 2]
    outer = line([0, 10], [0, 100])
    assert fops.compose(outer, line([0, 1], [2, 4])).ordinates.tolist() == [20, 40]
    a, b = line([0, 1, 2], [0, 1, 2]), line([1.5, 3], [5, 6])
    assert fops.concatenate(a, b).abscissas.tolist() == [0, 1, 1.5, 3]


def test_envelope_and_extraction():
    f, g = line([0, 1], [0, 2]), line([0, 1], [1, 1])
    assert fops.envelope([f, g]).ordinates.tolist() == [1, 2]
    assert fops.envelope([f, g], "INF").ordinates.tolist() == [0, 1]
    c = Function(np.array([0.0, 1.0]), np.array([1j, 1 + 0j]))
    assert fops.extract(c, "PHASE").ordinates.tolist() == pytest.approx([90.0, 0.0])


def test_fft_of_a_cosine():
    t = np.arange(64) / 64.0
    spectrum = fops.fft(line(t, np.cos(2 * np.pi * 4 * t), NOM_PARA="INST"), "COMPLET")
    assert spectrum.NOM_PARA == "FREQ"
    assert spectrum.abscissas[4] == pytest.approx(4.0)
    assert abs(spectrum.ordinates[4]) == pytest.approx(32.0)


def test_sdof_response_to_a_harmonic_base_motion():
    # steady state of u'' + 2ξω u' + ω² u = -a sin(Ωt): |u| = a / sqrt((ω²-Ω²)² + (2ξωΩ)²)
    f0, xi, big_omega = 5.0, 0.05, 2 * np.pi * 2.0
    t = np.linspace(0.0, 20.0, 2001)
    u, _ = fops.sdof_history(t, np.sin(big_omega * t), f0, xi)
    w = 2 * np.pi * f0
    steady = 1.0 / np.hypot(w * w - big_omega**2, 2 * xi * w * big_omega)
    late = t > 10.0  # the free vibration has decayed by exp(-ξω·10) ~ 1e-7
    # the load is only piecewise linear: a small sampling error (dt = T/50)
    assert np.abs(u[late]).max() == pytest.approx(steady, rel=2e-3)


def test_sdof_exact_for_a_linear_load():
    # under a ramp base acceleration a = t, u = -(t/ω² - 2ξ/ω³) + free vibration
    f0, xi = 1.0, 0.1
    t = np.linspace(0.0, 3.0, 4)
    u, _ = fops.sdof_history(t, t, f0, xi)
    w = 2 * np.pi * f0
    wd = w * np.sqrt(1 - xi**2)
    # u(0)=0, u'(0)=0: homogeneous part e^{-ξωt}(A cos + B sin) with A = -2ξ/ω³
    a0 = -2 * xi / w**3
    b0 = (1 / w**2 + xi * w * a0) / wd
    exact = -(t / w**2 - 2 * xi / w**3) + np.exp(-xi * w * t) * (
        a0 * np.cos(wd * t) + b0 * np.sin(wd * t)
    )
    assert u == pytest.approx(exact, abs=1e-12)


def test_sdof_static_limit_of_a_ramp():
    # a slow ramp to a constant acceleration: u → -a/ω²
    t = np.linspace(0.0, 50.0, 5001)
    acc = np.minimum(t / 10.0, 1.0)
    peak_u, _, _ = fops.sdof_peak_response(t, acc, 2.0, 0.05)
    assert peak_u == pytest.approx(1.0 / (2 * np.pi * 2.0) ** 2, rel=0.02)


def test_spec_osci_nappe():
    t = np.linspace(0.0, 2.0, 401)
    f = line(t, np.sin(2 * np.pi * 3 * t), NOM_PARA="INST")
    out = calc_fonction.run(
        context(),
        kw(SPEC_OSCI=[{"FONCTION": f, "AMOR_REDUIT": (0.02, 0.05), "FREQ": (1.0, 3.0, 10.0),
                       "NORME": 1.0, "METHODE": "NIGAM", "NATURE": "ACCE", "TYPE_RESU": "NAPPE"}]),
    )  # fmt: skip
    assert isinstance(out, Nappe) and out.NOM_PARA == "AMOR"
    low, high = out.functions
    assert low.ordinates[1] > high.ordinates[1]  # less damping, larger resonance
    assert out(0.02, 3.0) == pytest.approx(low.ordinates[1])


def test_info_fonction_max_and_rms():
    f = line([0, 1, 2, 3], [0, 2, -1, 2], NOM_PARA="INST", NOM_RESU="DEPL")
    f.name = "F"
    table = info_fonction.run(context(), kw(MAX=[{"FONCTION": (f,)}]))
    maxi = [r for r in table.rows if r["TYPE"] == "MAXI"]
    assert [r["INST"] for r in maxi] == [1.0, 3.0] and maxi[0]["DEPL"] == 2.0
    g = line(np.linspace(0, 1, 101), np.full(101, 3.0))
    rms = info_fonction.run(context(), kw(RMS=[{"FONCTION": g, "METHODE": "TRAPEZE"}]))
    assert rms.value("RMS", 1) == pytest.approx(3.0)


def test_lire_fonction_blocks(tmp_path):
    text = "HEADER\n0. 1. 2.\n1. 3. 4.\n\nNEXT BLOCK\n0.0 5.0D+00\n2.0 6.0\n"
    blocks = lire_fonction.numeric_blocks(text)
    assert len(blocks) == 2
    assert lire_fonction.column(blocks, (2, 2), "INDIC_RESU").tolist() == [5.0, 6.0]
    path = tmp_path / "data.txt"
    path.write_text(text)
    ctx = context("LIRE_FONCTION")
    ctx.session.input_path = lambda unit: path
    f = lire_fonction.run(ctx, kw(UNITE=18, NOM_PARA="INST", INDIC_PARA=(1, 1), INDIC_RESU=(1, 3)))
    assert f.abscissas.tolist() == [0.0, 1.0] and f.ordinates.tolist() == [2.0, 4.0]


def test_exclu_accepts_round_off_at_the_ends():
    f = line([1.0, 2.0], [10.0, 20.0])
    assert f(1.0 - 1e-9) == 10.0 and f(2.0 + 1e-9) == 20.0
    with pytest.raises(FunctionDomainError):
        f(0.99)


def test_corr_acce_filtrage_is_the_clough_penzien_high_pass():
    # a constant offset plus a sine on an FFT bin: the offset goes (H(0) = 0),
    # the sine comes out as Re(H(w0) e^{i w0 t})
    n, dt, fc = 400, 0.01, 0.5
    t = dt * np.arange(n)
    f0 = 10.0 / (n * dt)
    w0, wc = 2 * np.pi * f0, 2 * np.pi * fc
    gain = -(w0**2) / (wc**2 - w0**2 + 2j * wc * w0)
    f = line(t, 3.0 + np.sin(w0 * t), NOM_PARA="INST", NOM_RESU="ACCE")
    g = calc_fonction.run(
        context(), kw(CORR_ACCE=[{"FONCTION": f, "METHODE": "FILTRAGE", "FREQ_FILTRE": fc}])
    )
    expected = np.real(gain * np.exp(1j * w0 * t) / 1j)
    np.testing.assert_allclose(g.ordinates, expected, atol=1e-12)
    assert g.NOM_RESU == "ACCE"


def test_corr_acce_polynome_removes_the_trends_of_acceleration_and_velocity():
    t = np.linspace(0.0, 2.0, 201)
    f = line(t, 0.5 - 2.0 * t, NOM_PARA="INST", NOM_RESU="ACCE")
    for depl in ("NON", "OUI"):
        g = calc_fonction.run(
            context(), kw(CORR_ACCE=[{"FONCTION": f, "METHODE": "POLYNOME", "CORR_DEPL": depl}])
        )
        np.testing.assert_allclose(g.ordinates, 0.0, atol=1e-12)
