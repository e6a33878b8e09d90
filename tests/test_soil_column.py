"""The layered shear column of DEFI_SOL_EQUI (asterlite.harmonic.soil_column)
against closed forms."""

import numpy as np
import pytest

from asterlite.harmonic.soil_column import (
    SoilLayer,
    StrainCurve,
    complex_shear_modulus,
    equivalent_linear,
    fe_column_response,
    interface_transfer,
    midlayer_strain_transfer,
    propagate,
)

RHO, E, NU = 2000.0, 2.6e8, 0.3  # G = 1e8, Vs = 223.6 m/s


def _layer(h, eta=0.1, young=E, rho=RHO, curves=1):
    return SoilLayer(h, young, NU, rho, eta, curves)


def _kstar(freqs, young, eta, rho, lysmer=False):
    g = complex_shear_modulus(young / (2 * (1 + NU)), eta, lysmer)
    return 2 * np.pi * freqs * np.sqrt(rho / g)


@pytest.mark.parametrize("lysmer", [False, True])
def test_homogeneous_layer_on_rigid_base(lysmer):
    # u_surface / u_base = 1 / cos(k* H), whatever the split into sublayers
    freqs = np.linspace(0.1, 12.0, 97)
    H, eta = 30.0, 0.1
    for layers in ([_layer(H, eta)], [_layer(H / 3, eta) for _ in range(3)]):
        waves = propagate(layers, None, freqs, lysmer)
        tf = interface_transfer(waves, "BASE")
        exact = 1.0 / np.cos(_kstar(freqs, E, eta, RHO, lysmer) * H)
        assert np.allclose(tf[0], exact, rtol=1e-10)
        assert np.allclose(np.abs(tf[0]), np.abs(exact), rtol=1e-10)
        assert np.allclose(tf[-1], 1.0)


def test_lysmer_keeps_the_speed_modulus():
    # |G*| = G with the correction (damping ratio ξ = η/2)
    assert abs(complex_shear_modulus(1.0, 0.2, lysmer=True)) == pytest.approx(1.0, rel=1e-12)
    assert complex_shear_modulus(1.0, 0.2) == 1.0 + 0.2j


def test_layer_on_elastic_half_space_against_outcrop():
    # u_surface / u_outcrop = 1 / (cos k1 H + i α sin k1 H), α = ρ1 V1* / (ρ2 V2*)
    freqs = np.linspace(0.05, 15.0, 151)
    H, eta1, eta2 = 25.0, 0.08, 0.02
    rock = SoilLayer(1.0, 20 * E, NU, 2500.0, eta2)
    waves = propagate([_layer(H, eta1)], rock, freqs)
    k1 = _kstar(freqs, E, eta1, RHO)
    g1 = complex_shear_modulus(E / (2 * (1 + NU)), eta1)
    g2 = complex_shear_modulus(20 * E / (2 * (1 + NU)), eta2)
    alpha = np.sqrt(RHO * g1) / np.sqrt(2500.0 * g2)
    exact = 1.0 / (np.cos(k1 * H) + 1j * alpha * np.sin(k1 * H))
    assert np.allclose(interface_transfer(waves, "AFFLEURANT")[0], exact, rtol=1e-10)
    # given at the free surface, the column's base moves by cos(k1 H) and
    # the outcrop by the inverse of the transfer above
    from_surface = interface_transfer(waves, "CHAMP_LIBRE")
    assert np.allclose(from_surface[0], 1.0)
    assert np.allclose(from_surface[-1], np.cos(k1 * H), rtol=1e-10)
    assert np.allclose(2.0 * waves.up[-1] / (2.0 * waves.up[0]), 1.0 / exact, rtol=1e-10)


def test_midlayer_strain_of_a_layer_on_rigid_base():
    # u = U cos(k z) / cos(k H) per unit base motion: γ(H/2) = -k sin(kH/2) / cos(kH)
    freqs = np.linspace(0.1, 8.0, 41)
    H, eta = 40.0, 0.05
    waves = propagate([_layer(H, eta)], None, freqs)
    k = _kstar(freqs, E, eta, RHO)
    exact = -k * np.sin(k * H / 2) / np.cos(k * H)
    assert np.allclose(midlayer_strain_transfer(waves, [_layer(H, eta)], "BASE")[0], exact)


def test_outcrop_signal_needs_an_elastic_substratum():
    waves = propagate([_layer(10.0)], None, np.array([1.0]))
    with pytest.raises(ValueError, match="elastic substratum"):
        interface_transfer(waves, "AFFLEURANT")


def _harmonic_accelerogram(f0, dt, n, amp=1.0):
    t = dt * np.arange(n)
    return amp * np.sin(2 * np.pi * f0 * t)


def test_linear_curves_stop_at_the_first_iteration_and_match_the_transfer():
    # constant G/Gmax = 1 and D = 5e-5 (sdls140c's curves): one analysis,
    # η = 1e-4, and a harmonic signal on the FFT grid comes out scaled by |H(f0)|
    dt, n = 0.005, 1024
    f0 = 40 / (n * dt)
    acc = _harmonic_accelerogram(f0, dt, n)
    gg = {1: StrainCurve((1e-6, 1e-2), (1.0, 1.0))}
    dd = {1: StrainCurve((1e-6, 1e-2), (5e-5, 5e-5))}
    layers = [_layer(10.0, 1e-4) for _ in range(4)]
    rock = SoilLayer(1.0, 10 * E, NU, 2600.0, 1e-4)
    res = equivalent_linear(layers, rock, acc, dt, gg, dd, resi_rela=0.1)
    assert len(res.changes) == 1 and res.changes[0] == 0.0
    assert res.loss_factors[0] == pytest.approx([1e-4] * 4)
    h = interface_transfer(propagate(layers, rock, np.array([f0])), "AFFLEURANT")[0, 0]
    surf = res.interface_acceleration[0]
    assert np.max(np.abs(surf)) == pytest.approx(abs(h), rel=1e-3)
    assert surf == pytest.approx(
        np.real(h * np.exp(-1j * np.pi / 2) * np.exp(2j * np.pi * f0 * res.times)), abs=1e-9
    )


def test_converged_column_is_strain_compatible():
    dt, n = 0.01, 2048
    f0 = 30 / (n * dt)
    acc = _harmonic_accelerogram(f0, dt, n, amp=3.0)
    strains = (1e-6, 1e-5, 1e-4, 1e-3, 1e-2)
    gg = {1: StrainCurve(strains, (1.0, 0.95, 0.7, 0.35, 0.1))}
    dd = {1: StrainCurve(strains, (0.01, 0.02, 0.06, 0.12, 0.2))}
    layers = [_layer(8.0, 0.02) for _ in range(5)]
    rock = SoilLayer(1.0, 15 * E, NU, 2500.0, 0.02)
    res = equivalent_linear(
        layers, rock, acc, dt, gg, dd, coef_gamma=0.65, resi_rela=1e-4, nmax_iter=40
    )
    assert res.changes[-1] <= 1e-4 < res.changes[0]
    # the analysed moduli are those of the curve at 0.65 γmax of that analysis
    for layer, gam in zip(res.layers, res.gamma_max[-1], strict=True):
        assert layer.young == pytest.approx(gg[1](0.65 * gam) * E, rel=2e-4)
        assert layer.loss_factor == pytest.approx(2 * dd[1](0.65 * gam), rel=2e-3)
    assert np.max(np.abs(res.strain), axis=1) == pytest.approx(res.gamma_max[-1])


def test_strain_curve_is_log_linear_and_constant_outside():
    c = StrainCurve((1e-5, 1e-3), (1.0, 0.5))
    assert c(1e-4) == pytest.approx(0.75)
    assert c(1e-7) == 1.0 and c(1.0) == 0.5
    with pytest.raises(ValueError):
        StrainCurve((1e-3, 1e-5), (1.0, 0.5))


def test_fe_column_converges_to_the_layered_continuum():
    # code_aster's column (one cell per layer) and finer ones against the wave
    # solution; an undamped substratum keeps the phase reference apart from its cell
    freqs = np.linspace(0.0, 10.0, 41)
    layers = [_layer(10.0, 0.05), _layer(15.0, 0.1, young=2 * E), _layer(5.0, 0.02)]
    rock = SoilLayer(1.0, 20 * E, NU, 2500.0, 0.0)
    exact = np.abs(interface_transfer(propagate(layers, rock, freqs), "AFFLEURANT"))
    errors = []
    for cells in (1, 4, 16, 64):
        fe = fe_column_response(layers, rock, 20.0, freqs, cells_per_layer=cells)
        assert fe.shape == (len(layers) + 2, freqs.size)
        assert np.allclose(fe[:, 0], 1.0)
        errors.append(np.max(np.abs(np.abs(fe[:-1]) - exact) / np.abs(exact)))
    assert errors[0] > errors[1] > errors[2] > errors[3]
    # second order in h (the largest relative error sits by a node of the transfer)
    assert errors[2] / errors[3] == pytest.approx(16.0, rel=0.1)
    assert errors[3] < 1e-3


def test_fe_cell_is_the_two_node_shear_element():
    # one cell of soil on its dashpot: solve the 2 x 2 system by hand
    f, h, eta = 3.0, 20.0, 0.1
    w = 2 * np.pi * f
    rock = SoilLayer(1.0, E, NU, RHO, eta)
    fe = fe_column_response([], rock, h, np.array([f]))[:, 0]
    g = complex_shear_modulus(E / (2 * (1 + NU)), eta)
    z = np.sqrt(RHO * E / (2 * (1 + NU)))
    a = np.array([[g / h, -g / h], [-g / h, g / h]]) - w**2 * RHO * h / 6 * np.array(
        [[2, 1], [1, 2]]
    )
    a[1, 1] += 1j * w * z
    assert fe == pytest.approx(np.linalg.solve(a, [0.0, 1j * w * z]), rel=1e-12)
