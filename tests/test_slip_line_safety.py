"""Safety factors along a slip line and the critical acceleration
(asterlite.post.slip_line_safety) against closed forms."""

import numpy as np
import pytest
from scipy.optimize import curve_fit

from asterlite.post import slip_line_safety as sls


def _uniform(sxx, syy, sxy, n):
    return np.tile([sxx, syy, 0.3 * (sxx + syy), sxy], (n, 1))


def test_horizontal_segment_normal_is_minus_y():
    t, n = sls.line_frames(np.array([[0.0, 0.0]]), np.array([[2.0, 0.0]]))
    assert np.allclose(t, [[1.0, 0.0]]) and np.allclose(n, [[0.0, -1.0]])
    sig_n, sig_tn = sls.line_tractions(_uniform(-3.0, -7.0, 2.0, 1), t, n)
    # n.sigma.n = syy, t.sigma.n = -sxy
    assert sig_n == pytest.approx([-7.0]) and sig_tn == pytest.approx([-2.0])


@pytest.mark.parametrize("angle", [0.3, 1.1, 2.5, -0.7])
def test_inclined_segment_mohr_circle(angle):
    sxx, syy, sxy = -4.0, -9.0, 1.5
    first = np.array([[1.0, 2.0]])
    last = first + 3.0 * np.array([[np.cos(angle), np.sin(angle)]])
    t, n = sls.line_frames(first, last)
    sig_n, sig_tn = sls.line_tractions(_uniform(sxx, syy, sxy, 1), t, n)
    # normal at angle - pi/2: Mohr's formulas for that facet
    beta = angle - np.pi / 2
    c2, s2 = np.cos(2 * beta), np.sin(2 * beta)
    expected_n = 0.5 * (sxx + syy) + 0.5 * (sxx - syy) * c2 + sxy * s2
    # tangent = normal turned +90 degrees: shear on the facet with that sign
    expected_t = -0.5 * (sxx - syy) * s2 + sxy * c2
    assert sig_n[0] == pytest.approx(expected_n, rel=1e-12)
    assert sig_tn[0] == pytest.approx(expected_t, rel=1e-12)


def test_reversed_segment_gives_the_same_tractions():
    # t and n = t x e_z both change sign: n.sigma.n and t.sigma.n do not
    stress = _uniform(-4.0, -9.0, 1.5, 1)
    a, b = np.array([[0.0, 0.0]]), np.array([[1.0, 2.0]])
    n1, t1 = sls.line_tractions(stress, *sls.line_frames(a, b))
    n2, t2 = sls.line_tractions(stress, *sls.line_frames(b, a))
    assert n1 == pytest.approx(n2) and t1 == pytest.approx(t2)


def test_zero_length_segment_refused():
    with pytest.raises(ValueError, match="zero length"):
        sls.line_frames(np.array([[1.0, 1.0]]), np.array([[1.0, 1.0]]))


def test_static_safety_factor_of_infinite_slope():
    # dry infinite slope, facet parallel to the slope: FS = tan(phi)/tan(beta)
    # with sigma_n = -gamma h cos^2 beta, tau = gamma h sin beta cos beta
    gamma_h, beta, phi = 2.0e5, np.radians(20.0), 35.0
    k = 6
    sig_n = np.full(k, -gamma_h * np.cos(beta) ** 2)
    sig_tn = np.full(k, -gamma_h * np.sin(beta) * np.cos(beta))
    fs = sls.static_safety_factor(sig_n, sig_tn, np.full(k, phi), np.zeros(k))
    assert fs == pytest.approx(np.tan(np.radians(phi)) / np.tan(beta), rel=1e-12)
    amont = sls.static_safety_factor(sig_n, sig_tn, np.full(k, phi), np.zeros(k), sign=-1.0)
    assert amont == pytest.approx(-fs)


def test_cohesion_enters_available_shear():
    available, mobilised = sls.static_shears([-10.0, -20.0], [1.0, 2.0], [45.0, 45.0], [3.0, 4.0])
    assert available == pytest.approx(-10.0 - 20.0 - 7.0) and mobilised == pytest.approx(3.0)


def test_dynamic_safety_factor_without_dynamic_stress_is_static():
    sig_n, sig_tn = np.array([-5.0, -6.0]), np.array([-1.0, -2.0])
    phi, c = np.array([30.0, 30.0]), np.array([0.0, 0.0])
    fs = sls.dynamic_safety_factors((sig_n, sig_tn), (np.zeros((4, 2)), np.zeros((4, 2))), phi, c)
    assert fs == pytest.approx(np.full(4, sls.static_safety_factor(sig_n, sig_tn, phi, c)))
    # a dynamic shear opposite to the static one doubles the mobilised shear
    fs = sls.dynamic_safety_factors(
        (sig_n, sig_tn), (np.zeros((1, 2)), np.array([[1.5, 1.5]])), phi, c
    )
    assert fs[0] == pytest.approx(0.5 * sls.static_safety_factor(sig_n, sig_tn, phi, c))


def test_critical_acceleration_exact_line():
    acc = np.linspace(-2.0, 2.0, 41)
    fs = 1.0 - 0.1 * (acc - 0.5)  # reaches 1 at 0.5 m/s2, no scatter
    assert sls.critical_acceleration(fs, acc, nstd=3.0) == pytest.approx(0.5, abs=1e-12)


def test_critical_acceleration_matches_curve_fit_lowered_bound():
    rng = np.random.default_rng(7)
    acc = np.linspace(-3.0, 3.0, 200)
    fs = 1.05 - 0.08 * acc + rng.normal(0.0, 0.01, acc.size)
    kept = (fs > 0.8) & (fs < 1.2)
    popt, pcov = curve_fit(lambda x, a, b: a * x + b, acc[kept], fs[kept])
    a, b = popt - 2.5 * np.sqrt(np.diag(pcov))
    assert sls.critical_acceleration(fs, acc, nstd=2.5) == pytest.approx((1 - b) / a, rel=1e-7)


def test_critical_acceleration_outside_band():
    acc = np.array([0.1, 0.4, 0.2])
    assert sls.critical_acceleration([1.5, 1.6, 2.0], acc) == pytest.approx(0.44)
    assert sls.critical_acceleration([0.1, 0.5, 0.7], acc) == 0.0
    with pytest.raises(ValueError, match="crosses 1"):
        sls.critical_acceleration([0.5, 1.5, 1.6], acc)
    with pytest.raises(ValueError, match="at least 3"):
        sls.critical_acceleration([0.9, 1.1, 1.6], acc)
