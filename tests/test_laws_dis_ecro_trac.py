"""DIS_ECRO_TRAC: curve following, elastic unloading, energy balance."""

import math

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_relations import read_dis_ecro_trac
from hypothesis import given, settings
from hypothesis import strategies as st

from asterlite.concepts.function import Function
from asterlite.dynamics.laws.dis_ecro_trac import (
    N_VINT,
    N_WORK,
    V_BACK_FORCE,
    V_DEPL_PLAS,
    V_DISSIP,
    V_FORCE,
    V_PCUM,
    hardening_force,
    prepare_dis_ecro_trac,
)
from asterlite.dynamics.laws.discrete_hardening import N_Y
from asterlite.dynamics.laws.tabulated import LawError
from tests.validated import relation

X = np.array([0.0, 0.01, 0.03, 0.08])
F = np.array([0.0, 100.0, 140.0, 170.0])  # k = 1e4, hardening slopes decreasing
K = 1.0e4


def curve(parameter, x, y, left="EXCLU", right="EXCLU"):
    """A DEFI_FONCTION of ``parameter`` (the relation wants DX for FX, DTAN for FTAN)."""
    return Function(
        abscissas=x, ordinates=y, NOM_PARA=parameter, PROL_GAUCHE=left, PROL_DROITE=right
    )


def axial(**kw):
    return prepare_dis_ecro_trac(
        read_dis_ecro_trac(relation("DIS_ECRO_TRAC", dict(FX=curve("DX", X, F), **kw)))
    )


def drive(params, path, component=0, dt=1.0e-3, strict=True):
    """Prescribed elongation path (one component); returns forces and state."""
    rate, work = np.zeros(3), np.zeros((N_WORK, N_Y))
    state = np.zeros(N_VINT)
    forces, u = [0.0], 0.0
    for target in path[1:]:
        vrel = np.zeros(3)
        vrel[component] = -(target - u) / dt  # v1 - v2 = - elongation rate
        f = hardening_force(params, vrel, dt, state, state, rate, work)
        assert f[3] or not strict
        forces.append(f[component])
        u = target
    return np.array(forces), state


def test_monotonic_loading_follows_the_curve():
    p = axial(RESI_INTE=1e-8)
    path = np.linspace(0.0, 0.075, 1501)
    forces, state = drive(p, path)
    assert np.allclose(forces, np.interp(path, X, F), atol=0.05)
    plastic = path[-1] - forces[-1] / K
    assert state[V_DEPL_PLAS] == pytest.approx(plastic, rel=1e-3)
    assert state[V_PCUM] == pytest.approx(plastic, rel=1e-3)


def test_unloading_is_elastic_and_isotropic_reloading_in_compression():
    p = axial(RESI_INTE=1e-8)
    path = np.concatenate([np.linspace(0.0, 0.05, 501), np.linspace(0.05, 0.0, 501)[1:]])
    forces, _ = drive(p, path)
    f_top = np.interp(0.05, X, F)
    reverse_yield = 0.05 - 2.0 * f_top / K
    back = (np.arange(path.size) > 500) & (path > reverse_yield + 1e-4)  # elastic unloading
    assert np.allclose(forces[back], f_top - K * (0.05 - path[back]), atol=0.05)
    # isotropic: compressive yield starts at the hardened threshold, then hardens further
    assert forces[np.argmin(np.abs(path[500:] - reverse_yield)) + 500] == pytest.approx(
        -f_top, abs=1.0
    )
    assert -F[-1] < forces.min() < -f_top


@pytest.mark.parametrize("hardening", ["ISOTROPE", "CINEMATIQUE"])
def test_loop_energy_balance_transverse(hardening):
    """Work = ½|F|²/k (+ ½|X|²/H kinematic) + dissipated energy, along a
    closed in-plane loop; the loop area is the dissipation."""
    xs, fs = (X[:3], F[:3]) if hardening == "CINEMATIQUE" else (X, F)
    p = prepare_dis_ecro_trac(
        read_dis_ecro_trac(
            relation(
                "DIS_ECRO_TRAC",
                dict(FTAN=curve("DTAN", xs, fs), ECROUISSAGE=hardening, RESI_INTE=1e-8),
            )
        )
    )
    h = (fs[2] - fs[1]) / ((xs[2] - fs[2] / K) - (xs[1] - fs[1] / K))
    theta = np.linspace(0.0, 4.0 * math.pi, 4001)
    radius = 0.02
    uy, uz = radius * np.sin(theta), radius * (1.0 - np.cos(theta)) * 0.5
    rate, work = np.zeros(3), np.zeros((N_WORK, N_Y))
    state = np.zeros(N_VINT)
    done, dt = 0.0, 1.0e-3
    for i in range(1, theta.size):
        vrel = np.array([0.0, -(uy[i] - uy[i - 1]) / dt, -(uz[i] - uz[i - 1]) / dt])
        f_old = state[V_FORCE : V_FORCE + 3].copy()
        _, fy, fz, ok = hardening_force(p, vrel, dt, state, state, rate, work)
        assert ok
        done += 0.5 * (f_old[1] + fy) * (uy[i] - uy[i - 1]) + 0.5 * (f_old[2] + fz) * (
            uz[i] - uz[i - 1]
        )
    f = state[V_FORCE : V_FORCE + 3]
    stored = 0.5 * f @ f / K
    if hardening == "CINEMATIQUE":
        x = state[V_BACK_FORCE : V_BACK_FORCE + 3]
        stored += 0.5 * x @ x / h
    assert state[V_DISSIP] > 0.0
    assert done == pytest.approx(stored + state[V_DISSIP], rel=2e-3)


def test_curve_checks():
    with pytest.raises(LawError, match="slopes must decrease"):
        prepare_dis_ecro_trac(
            read_dis_ecro_trac(
                relation("DIS_ECRO_TRAC", dict(FX=curve("DX", X, [0.0, 100.0, 110.0, 200.0])))
            )
        )
    with pytest.raises(LawError, match=r"first point must be \(0, 0\)"):
        prepare_dis_ecro_trac(
            read_dis_ecro_trac(relation("DIS_ECRO_TRAC", dict(FX=curve("DX", X + 0.01, F))))
        )
    with pytest.raises(LawError, match="exactly 3 points"):
        prepare_dis_ecro_trac(
            read_dis_ecro_trac(
                relation("DIS_ECRO_TRAC", dict(FTAN=curve("DTAN", X, F), ECROUISSAGE="CINEMATIQUE"))
            )
        )
    with pytest.raises(LawError, match="EXCLU"):
        prepare_dis_ecro_trac(
            read_dis_ecro_trac(
                relation("DIS_ECRO_TRAC", dict(FX=curve("DX", X, F, "CONSTANT", "EXCLU")))
            )
        )


def test_beyond_the_last_point_is_reported():
    """Elongation 0.2 > the curve's last abscissa: the step reports failure
    (the kernel must stop, as code_aster does), forces stay bounded."""
    p = axial()
    rate, work = np.zeros(3), np.zeros((N_WORK, N_Y))
    state = np.zeros(N_VINT)
    status = []
    for _ in range(200):
        fx, _, _, ok = hardening_force(
            p, np.array([-1.0, 0.0, 0.0]), 1.0e-3, state, state, rate, work
        )
        status.append(ok)
        assert math.isfinite(fx) and fx <= F[-1] + 1e-4
    assert status[0] and not status[-1]


@settings(max_examples=25, deadline=None)
@given(st.lists(st.floats(-0.04, 0.04), min_size=2, max_size=12))
def test_random_histories_finite_and_dissipative(points):
    p = axial()
    path = np.concatenate([[0.0], np.repeat(points, 1)])
    fine = np.concatenate(
        [np.linspace(a, b, 20, endpoint=False) for a, b in zip(path[:-1], path[1:], strict=True)]
        + [path[-1:]]
    )
    forces, state = drive(p, fine, strict=False)  # long paths may exhaust the curve
    assert np.all(np.isfinite(forces))
    assert state[V_DISSIP] >= 0.0
    assert np.all(np.abs(forces) <= F[-1] * (1.0 + 1e-5))  # within the RK tolerance
