"""ANTI_SISM: saturating stiffness, thresholds and viscous dissipation."""

import math

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_relations import read_anti_sism, relation_words
from hypothesis import given, settings
from hypothesis import strategies as st

from asterlite.dynamics.laws.anti_sism import (
    antiseismic_force,
    elastic_energy,
    prepare_anti_sism,
    reference_distance,
)
from asterlite.dynamics.laws.tabulated import LawError
from tests.validated import relation

KW = dict(RIGI_K1=6.0e6, RIGI_K2=0.53e6, SEUIL_FX=1200.0, C=7.0e3, PUIS_ALPHA=0.2, DX_MAX=0.03)


def elastic(kw):
    return prepare_anti_sism(read_anti_sism(relation("ANTI_SISM", dict(kw, C=0.0))))


def test_initial_stiffness_is_k1():
    p = elastic(KW)
    d = 1.0e-9
    assert -antiseismic_force(p, d, 0.0) / d == pytest.approx(KW["RIGI_K1"], rel=1e-6)


def test_threshold_then_k2_asymptote():
    """Far beyond the threshold the force is SEUIL_FX (K1-K2)/K1 + K2 d."""
    p = elastic(KW)
    k1, k2, fy = KW["RIGI_K1"], KW["RIGI_K2"], KW["SEUIL_FX"]
    for d in (0.05, 0.2, -0.1):
        asymptote = math.copysign(fy * (k1 - k2) / k1, d) + k2 * d
        assert -antiseismic_force(p, d, 0.0) == pytest.approx(asymptote, rel=1e-4)
    # with K2 = 0 the force saturates exactly at the threshold
    p0 = elastic(dict(KW, RIGI_K2=0.0))
    assert -antiseismic_force(p0, 10.0, 0.0) == pytest.approx(fy, rel=1e-6)
    assert abs(antiseismic_force(p0, 1.0e3, 0.0)) < fy


def test_force_is_odd_and_conservative_without_viscosity():
    p = elastic(KW)
    d = np.linspace(-0.01, 0.01, 20001)
    f = np.array([antiseismic_force(p, x, 0.0) for x in d])
    assert np.allclose(f, -f[::-1])
    work = -np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(d))  # energy given to the device
    assert work == pytest.approx(elastic_energy(p, d[-1]) - elastic_energy(p, d[0]), abs=1e-9)


def test_coulomb_like_damper_loop_area():
    """PUIS_ALPHA = 0: the viscous term is C sign(v); a cycle of amplitude A
    dissipates 4 A C, the elastic part gives back what it took."""
    p = prepare_anti_sism(read_anti_sism(relation("ANTI_SISM", dict(KW, PUIS_ALPHA=0.0))))
    amplitude, c = 0.004, KW["C"]
    t = np.linspace(0.0, 2.0 * math.pi, 40001)
    d, v = amplitude * np.sin(t), amplitude * np.cos(t)
    f = np.array([antiseismic_force(p, x, y) for x, y in zip(d, v, strict=True)])
    dissipated = -np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(d))
    assert dissipated == pytest.approx(4.0 * amplitude * c, rel=2e-3)


def test_prepare_errors_and_reference_distance():
    with pytest.raises(LawError, match="DX_MAX"), relation_words("ANTI_SISM"):
        prepare_anti_sism(read_anti_sism(relation("ANTI_SISM", dict(KW, DX_MAX=0.0))))
    with pytest.raises(LawError, match="RIGI_K1"), relation_words("ANTI_SISM"):
        prepare_anti_sism(read_anti_sism(relation("ANTI_SISM", dict(KW, RIGI_K1=-1.0))))
    assert reference_distance([0, 0, 0], [0.0, 3.0, 4.0], info=2) == pytest.approx(5.0)
    assert reference_distance([0, 0, 0], [0.0, 3.0, 4.0], info=1) == pytest.approx(25.0)


@settings(max_examples=80, deadline=None)
@given(
    st.floats(-0.05, 0.05),
    st.floats(-10.0, 10.0),
    st.floats(0.0, 1.0),
    st.floats(0.0, 1e4),
)
def test_finite_and_viscous_power_dissipative(d, v, alpha, c):
    p = prepare_anti_sism(read_anti_sism(relation("ANTI_SISM", dict(KW, PUIS_ALPHA=alpha, C=c))))
    f = antiseismic_force(p, d, v)
    assert math.isfinite(f)
    viscous = f - antiseismic_force(p, d, 0.0)
    assert viscous * v <= 1e-12  # the device never gives energy through its damper
