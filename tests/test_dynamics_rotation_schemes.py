"""VITESSE_VARIABLE='OUI' with every GENE scheme: C + Ω(t) G and
K + Ω'(t) K_gy updated at the start of each step (code_aster's dtmcalc
calls dtmupmat before dtmintg whatever the scheme)."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, build_shocks
from asterlite.dynamics.rotation import Rotation
from asterlite.dynamics.schemes import TABLE
from tests.test_dynamics_rotation_energy import Table, rotor
from tests.validated import scheme_options

# every scheme the loop shared by all runs with VITESSE_VARIABLE
SCHEMES = [entry.name for entry in TABLE if entry.shared_loops]

T_END = 0.4
LOAD = np.array([1.0, 0.5])


def run(scheme, dt, rotation=None, system=None, t_end=T_END, options=None):
    mass, stiffness, damping, gyro, rigy = rotor()
    if rotation is not None:
        rotation.tabulate(0.0, t_end, dt / 2)
        c0, k0 = rotation.matrices_at(0.0)
        system = LinearSystem(mass, k0, c0)
    excitation = tabulate_excitation(2, [(LOAD, 1.0)], 0.0, t_end, dt / 2)
    return integrate(
        system, build_shocks([], system), excitation, scheme, np.array([1e-3, 0.0]), np.zeros(2),
        0.0, t_end, dt, np.array([t_end]), 1, options or scheme_options(scheme), rotation=rotation,
    )  # fmt: skip


@pytest.mark.parametrize("scheme", SCHEMES)
def test_constant_speed_is_the_fixed_matrices_run(scheme):
    """Ω = 300 rad/s, Ω' = 0: the rotating loop must reproduce the run with
    C + Ω G (and K) as fixed matrices, step for step."""
    mass, stiffness, damping, gyro, rigy = rotor()
    dt = 1.0e-3
    rotation = Rotation(damping, stiffness, gyro, rigy, Table([0.0, 1.0], [300.0, 300.0]))
    rotating = run(scheme, dt, rotation=rotation)
    fixed = run(scheme, dt, system=LinearSystem(mass, stiffness, damping + 300.0 * gyro))
    np.testing.assert_array_equal(rotating.times, fixed.times)
    np.testing.assert_allclose(rotating.depl, fixed.depl, rtol=1e-10, atol=1e-16)
    np.testing.assert_allclose(rotating.vite, fixed.vite, rtol=1e-10, atol=1e-14)
    # the gyroscopic coupling moves the second coordinate (no initial motion)
    assert np.max(np.abs(rotating.depl[:, 1])) > 1e-5


def reference(speed, accel, t_end):
    """The continuous equations, tight tolerance (matrices at every instant)."""
    mass, stiffness, damping, gyro, rigy = rotor()

    def rhs(t, y):
        q, v = y[:2], y[2:]
        c = damping + speed(t) * gyro
        k = stiffness + accel(t) * rigy
        return np.concatenate([v, np.linalg.solve(mass, LOAD - k @ q - c @ v)])

    y0 = np.array([1e-3, 0.0, 0.0, 0.0])
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=1e-12, atol=1e-15)
    return sol.y[:2, -1]


# run at a fixed step (PAS_MINI = PAS_MAXI) in the convergence test
ADAPTIVE = ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "DEVOGE", "ADAPT_ORDRE1", "ADAPT_ORDRE2")


@pytest.mark.parametrize("scheme", SCHEMES)
def test_ramped_speed_converges_to_the_continuous_equations(scheme):
    """Ω(t) from 0 to 2000 rad/s, Ω' = 5000 rad/s²: the matrices held at
    each step start make an O(dt) error at most, so halving the step
    must bring the final state towards the continuous solution, and the
    speed must matter (the fixed-speed run lies far off)."""
    mass, stiffness, damping, gyro, rigy = rotor()
    speed = Table([0.0, T_END], [0.0, 2000.0])
    accel = Table([0.0, T_END], [5000.0, 5000.0])
    exact = reference(speed.evaluate, accel.evaluate, T_END)
    errors = []
    for dt in (4.0e-4, 2.0e-4, 1.0e-4):
        fixed = scheme in ADAPTIVE
        options = scheme_options(scheme, dt_min=dt, dt_max=dt) if fixed else scheme_options(scheme)
        rotation = Rotation(damping, stiffness, gyro, rigy, speed, accel)
        result = run(scheme, dt, rotation=rotation, options=options)
        errors.append(np.linalg.norm(result.depl[-1] - exact))
    scale = np.linalg.norm(exact)
    assert errors[-1] < 0.02 * scale
    assert errors[2] < 0.7 * errors[0]  # converging, at least first order
    still = run(scheme, 1.0e-4, system=LinearSystem(mass, stiffness, damping))
    assert np.linalg.norm(still.depl[-1] - exact) > 10 * errors[-1]


@pytest.mark.parametrize("scheme", ["DEVOGE", "RUNGE_KUTTA_54", "ADAPT_ORDRE2"])
def test_adaptive_steps_follow_the_ramped_speed(scheme):
    """The adaptive families with their own step control and the speed ramp."""
    mass, stiffness, damping, gyro, rigy = rotor()
    speed = Table([0.0, T_END], [0.0, 2000.0])
    accel = Table([0.0, T_END], [5000.0, 5000.0])
    exact = reference(speed.evaluate, accel.evaluate, T_END)
    rotation = Rotation(damping, stiffness, gyro, rigy, speed, accel)
    options = scheme_options(scheme, tolerance=1e-7, dt_max=5.0e-4)
    result = run(scheme, 1.0e-4, rotation=rotation, options=options)
    assert np.linalg.norm(result.depl[-1] - exact) < 0.03 * np.linalg.norm(exact)


def test_variable_speed_with_runge_kutta_through_dyna_vibra():
    """The command accepts VITESSE_VARIABLE='OUI' with RUNGE_KUTTA_32 and
    gives the NEWMARK answer to the accuracy of the matrices held per step."""
    from asterlite.concepts.modes import GeneralizedMatrix
    from tests.test_dynamics_excit_resu import two_modes
    from tests.test_dynamics_vibra import run_vibra

    gnum, m, k = two_modes(k1=(2 * np.pi * 5.0) ** 2, k2=(2 * np.pi * 6.0) ** 2)
    _, _, damping, gyro, rigy = rotor()
    amor = GeneralizedMatrix(numbering=gnum, matrix=damping, kind="AMOR")
    gyro_m = GeneralizedMatrix(numbering=gnum, matrix=gyro, kind="GYRO")
    speed = Table([0.0, 1.0], [0.0, 2000.0])
    runs = {}
    for scheme in ("NEWMARK", "RUNGE_KUTTA_32"):
        runs[scheme] = run_vibra(
            m, k, scheme, 1.0e-4, 0.3, etat={"DEPL": two_mode_vector(gnum)},
            MATR_AMOR=amor, VITESSE_VARIABLE="OUI", MATR_GYRO=gyro_m, VITE_ROTA=speed,
            veri="NON",
        )  # fmt: skip
    a, b = runs["NEWMARK"].depl[-1], runs["RUNGE_KUTTA_32"].depl[-1]
    # the second coordinate moves through G only (no load, no initial motion)
    assert np.abs(a[1]) > 1e-4 and np.abs(b[1]) > 1e-4
    # RUNGE_KUTTA_32 holds the matrices over its own (longer) adaptive steps
    np.testing.assert_allclose(b, a, atol=5e-3 * np.max(np.abs(a)))


def two_mode_vector(gnum):
    from asterlite.concepts.modes import GeneralizedVector

    return GeneralizedVector(numbering=gnum, values=np.array([1e-3, 0.0]), kind="DEPL")
