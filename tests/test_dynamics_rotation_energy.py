"""Variable rotation speed (VITESSE_VARIABLE='OUI': C + Ω(t) G, K + Ω'(t) K_gy
updated before each NEWMARK step, as code_aster's dtmupmat) and the energy
balance of a physical transient (ENERGIE, code_aster's enerca)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, build_shocks
from asterlite.dynamics.physical import newmark
from asterlite.dynamics.physical.archive import Archive
from asterlite.dynamics.physical.energy import EnergyBalance
from asterlite.dynamics.rotation import Rotation
from tests.test_dynamics_physical import chain, physical_system
from tests.validated import scheme_options


class Table:
    """A linear DEFI_FONCTION-like multiplier."""

    INTERPOL = ("LIN", "LIN")
    PROL_GAUCHE = PROL_DROITE = "LINEAIRE"

    def __init__(self, xs, ys):
        self.abscissas = np.asarray(xs, dtype=float)
        self.ordinates = np.asarray(ys, dtype=float)

    def evaluate(self, t):
        return np.interp(t, self.abscissas, self.ordinates)


def rotor():
    """Two modes (x, y) of a rotor at 5 and 6 Hz coupled by a skew gyroscopic matrix."""
    mass = np.eye(2)
    stiffness = np.diag([(2 * np.pi * 5.0) ** 2, (2 * np.pi * 6.0) ** 2])
    damping = np.diag([0.5, 0.6])
    gyro = np.array([[0.0, 0.02], [-0.02, 0.0]])
    rigy = np.array([[0.0, 0.01], [0.01, 0.0]])
    return mass, stiffness, damping, gyro, rigy


def reference_newmark(mass, stiffness, damping, gyro, rigy, speed, accel, force, q, v, dt, n):
    """Plain Python NEWMARK (β=1/4, γ=1/2) with the matrices at each step start."""
    a = np.linalg.solve(
        mass, force(0.0) - (stiffness + accel(0.0) * rigy) @ q - (damping + speed(0.0) * gyro) @ v
    )
    beta, gamma = 0.25, 0.5
    c0, c1, c2 = 1 / (beta * dt * dt), gamma / (beta * dt), 1 / (beta * dt)
    c3, c4, c5 = 1 / (2 * beta) - 1, gamma / beta - 1, dt / 2 * (gamma / beta - 2)
    out = [q.copy()]
    t = 0.0
    for _ in range(n):
        cmat = damping + speed(t) * gyro
        kmat = stiffness + accel(t) * rigy
        keff = c0 * mass + c1 * cmat + kmat
        rhs = force(t + dt) + mass @ (c0 * q + c2 * v + c3 * a) + cmat @ (c1 * q + c4 * v + c5 * a)
        q_new = np.linalg.solve(keff, rhs)
        a_new = c0 * (q_new - q) - c2 * v - c3 * a
        v = v + dt * (1 - gamma) * a + gamma * dt * a_new
        q, a, t = q_new, a_new, t + dt
        out.append(q.copy())
    return np.array(out)


def test_variable_speed_newmark_matches_a_reference_with_updated_matrices():
    mass, stiffness, damping, gyro, rigy = rotor()
    t_end, dt = 0.5, 1.0e-3
    speed = Table([0.0, t_end], [0.0, 400.0])
    accel = Table([0.0, t_end], [800.0, 800.0])
    load = np.array([1.0, 0.5])
    rotation = Rotation(damping, stiffness, gyro, rigy, speed, accel)
    rotation.tabulate(0.0, t_end, dt / 2)
    c0, k0 = rotation.matrices_at(0.0)
    system = LinearSystem(mass, k0, c0)
    excitation = tabulate_excitation(2, [(load, 1.0)], 0.0, t_end, dt / 2)
    q0, v0 = np.array([1e-3, 0.0]), np.zeros(2)
    result = integrate(
        system, build_shocks([], system), excitation, "NEWMARK", q0, v0, 0.0, t_end, dt,
        np.array([t_end]), 1, scheme_options("NEWMARK"), rotation=rotation,
    )  # fmt: skip
    expected = reference_newmark(
        mass, stiffness, damping, gyro, rigy, speed.evaluate, accel.evaluate,
        lambda t: load, q0.copy(), v0.copy(), dt, int(round(t_end / dt)),
    )  # fmt: skip
    assert result.depl.shape == expected.shape
    np.testing.assert_allclose(result.depl, expected, rtol=1e-9, atol=1e-15)
    # the gyroscopic coupling moves the second mode, which has no initial motion
    assert np.max(np.abs(result.depl[:, 1])) > 1e-6


def test_zero_speed_rotation_is_plain_newmark():
    mass, stiffness, damping, gyro, rigy = rotor()
    t_end, dt = 0.2, 1.0e-3
    rotation = Rotation(damping, stiffness, gyro, rigy, Table([0.0, 1.0], [0.0, 0.0]))
    rotation.tabulate(0.0, t_end, dt / 2)
    runs = []
    for rot in (None, rotation):
        system = LinearSystem(mass, stiffness, damping)
        excitation = tabulate_excitation(2, [(np.array([1.0, 2.0]), 1.0)], 0.0, t_end, dt / 2)
        runs.append(
            integrate(
                system,
                build_shocks([], system),
                excitation,
                "NEWMARK",
                np.zeros(2),
                np.zeros(2),
                0.0,
                t_end,
                dt,
                np.array([t_end]),
                1,
                scheme_options("NEWMARK"),
                rotation=rot,
            ).depl  # fmt: skip
        )
    np.testing.assert_allclose(runs[1], runs[0], rtol=1e-12, atol=1e-18)


def test_energy_balance_of_undamped_newmark_closes():
    mass, stiffness, _ = chain()
    system = physical_system(mass, stiffness, 0.0 * stiffness, np.array([0.0, 0.0, 10.0]))
    times = 1.0e-3 * np.arange(201)
    q, v = np.zeros(3), np.zeros(3)
    a = system.initial_acceleration(times[0], q, v)
    energy = EnergyBalance(system, times[0])
    archive = Archive(system.n_free)
    newmark.integrate(system, times, q, v, a, np.ones(times.size, bool), archive, monitor=energy)
    t, qs, vs, _ = archive.arrays()
    last = energy.rows[-1]
    assert last["INST"] == pytest.approx(times[-1])
    assert last["ENER_CIN"] == pytest.approx(0.5 * vs[-1] @ mass @ vs[-1], rel=1e-10)
    assert last["ENER_TOT"] == pytest.approx(0.5 * qs[-1] @ stiffness @ qs[-1], rel=1e-10)
    # the trapezoidal rule conserves energy: the scheme dissipates nothing
    assert abs(last["DISS_SCH"]) < 1e-9 * last["TRAV_EXT"]
    assert len(energy.table().rows) == times.size - 1


class Keywords(dict):
    def factor(self, name):
        return self.get(name, [])


def test_physical_initial_acceleration_only_with_an_initial_state():
    """code_aster (dltali): from rest the first step starts with a = 0."""
    from asterlite.commands.dyna_vibra_phys import initial_acceleration_computed

    assert not initial_acceleration_computed(Keywords())
    assert initial_acceleration_computed(Keywords(ETAT_INIT=[{"DEPL": object()}]))
    assert initial_acceleration_computed(Keywords(ETAT_INIT=[{"VITE": object()}]))
    assert not initial_acceleration_computed(Keywords(ETAT_INIT=[{}]))
