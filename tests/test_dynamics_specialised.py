"""The specialised DIFF_CENTRE loop (local-frame shocks, one-pass diagonal
acceleration, multipliers searched from their last interval, formula
programs, multipliers sampled by windows) against the general path."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics import excitation as EX
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.formula import formula_program, program_tables, run_program
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from tests.validated import scheme_options

N_MODES = 4


def small_shock_problem(diagonal=True, norm_obst=(1.0, 0.0, 0.0), two_nodes=False):
    """Four modes, a CERCLE (or BI_CERCLE) shock with friction and a gap
    small enough for many impacts, a harmonic FORMULE and a tabulated load."""
    rng = np.random.default_rng(7)
    omega = np.array([30.0, 80.0, 170.0, 300.0]) * 2.0 * np.pi
    mass = np.diag([1.0, 0.8, 1.2, 0.9])
    stiffness = np.diag(omega**2 * np.diag(mass))
    damping = np.diag(2.0 * 0.02 * omega * np.diag(mass))
    if not diagonal:  # weak coupling: full matrices, same physics
        coupling = 0.01 * rng.standard_normal((N_MODES, N_MODES))
        coupling = coupling + coupling.T
        stiffness = stiffness + coupling * omega[0] ** 2
        damping = damping + 1.0e-3 * coupling
    system = LinearSystem(mass, stiffness, damping)
    phi_1 = rng.standard_normal((3, N_MODES)) * 0.3
    phi_2 = rng.standard_normal((3, N_MODES)) * 0.1 if two_nodes else None
    spec = ShockSpec(
        name="S1",
        obstacle_type="BI_CERCLE" if two_nodes else "CERCLE",
        node_1="N1",
        node_2="N2" if two_nodes else None,
        coord_1=np.array([0.5, 0.01, -0.02]),
        coord_2=np.array([0.5, 0.0, 0.0]) if two_nodes else None,
        phi_1=phi_1,
        phi_2=phi_2,
        norm_obst=np.asarray(norm_obst, dtype=float),
        orig_obst=np.array([0.5, 0.01, -0.02]),
        gap=1.0e-5,
        dist_1=0.01 - 5.0e-6 if two_nodes else 0.0,  # BI_CERCLE: 1e-5 gap at rest
        dist_2=0.01 - 5.0e-6 if two_nodes else 0.0,
        k_n=2.0e5,
        c_n=5.0,
        k_t=5.0e4,
        c_t=2.0,
        mu_dyn=0.25,
        mu_stat=0.3,
    )
    shocks = build_shocks([spec], system)
    return system, shocks, rng.standard_normal((2, N_MODES))


class Table:
    """A DEFI_FONCTION with linear interpolation: the engine keeps its points."""

    INTERPOL = ("LIN", "LIN")
    PROL_GAUCHE = PROL_DROITE = "CONSTANT"

    def __init__(self, xs, ys):
        self.abscissas, self.ordinates = np.asarray(xs), np.asarray(ys)

    def evaluate(self, t):
        return np.interp(t, self.abscissas, self.ordinates)


class Sampled:
    """A multiplier known only through ``evaluate`` (sampled by windows)."""

    def evaluate(self, t):
        return 0.5 * np.cos(140.0 * np.asarray(t))


def run(system, shocks, vectors, specialised, t_end=0.2, dt=2.0e-5, pas_arch=7, sampled=False):
    formula = Formula(VALE="F0*sin(W*INST)", NOM_PARA="INST", extra={"F0": 2.0, "W": 190.0})
    times = np.linspace(0.0, t_end, 97)
    table = Table(times, np.sin(60.0 * times) ** 2)
    second = Sampled() if sampled else table
    loads = [(vectors[0], formula), (vectors[1], second)]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    q0 = np.full(N_MODES, 2.0e-4)  # released from a displaced state: impacts at once
    v0 = np.zeros(N_MODES)
    instants = np.array([0.0123, t_end])
    return integrate(
        system, shocks, excitation, "DIFF_CENTRE", q0, v0, 0.0, t_end, dt, instants, pas_arch,
        scheme_options("DIFF_CENTRE"), specialised=specialised,
    )  # fmt: skip


def assert_same_run(fast, general, rtol):
    assert fast.info["steps"] == general.info["steps"]
    np.testing.assert_array_equal(fast.times, general.times)
    np.testing.assert_array_equal(fast.order, general.order)
    scale = np.abs(general.depl).max()
    assert np.abs(fast.depl - general.depl).max() <= rtol * scale
    assert np.abs(fast.vint - general.vint).max() <= rtol * max(1.0, np.abs(general.vint).max())


def test_specialised_loop_equals_general_path_bit_for_bit():
    """Global frame = local frame (NORM_OBST along X): identical arithmetic."""
    system, shocks, vectors = small_shock_problem()
    fast = run(system, shocks, vectors, specialised=True)
    general = run(system, shocks, vectors, specialised=False)
    fn = general.vint[:, 0, 0]
    assert (fn > 0).any() and (fn == 0).any()  # impacts and flights
    assert (general.vint[:, 0, 1] != 0).any()  # friction
    assert_same_run(fast, general, rtol=0.0)


@pytest.mark.parametrize(
    "diagonal, norm_obst, two_nodes",
    [
        (True, (0.3, 0.9, 0.3), False),
        (False, (1.0, 0.0, 0.0), False),
        (True, (0.0, 1.0, 0.0), True),
    ],
)
def test_specialised_loop_matches_general_path(diagonal, norm_obst, two_nodes):
    """Rotated frames (shapes rotated once instead of every step), full
    matrices, two-node shocks: the same trajectory up to rounding."""
    system, shocks, vectors = small_shock_problem(diagonal, norm_obst, two_nodes)
    fast = run(system, shocks, vectors, specialised=True, t_end=0.05)
    general = run(system, shocks, vectors, specialised=False, t_end=0.05)
    assert (general.vint[:, 0, 0] > 0).any()
    assert_same_run(fast, general, rtol=1.0e-9)


def test_sampled_multiplier_windows_give_the_same_run(monkeypatch):
    """A multiplier sampled every dt/2 in small windows (the loop pauses and
    the driver tabulates the next one) gives exactly the run of one window."""
    system, shocks, vectors = small_shock_problem()
    whole = run(system, shocks, vectors, specialised=True, t_end=0.05, sampled=True)
    monkeypatch.setattr(EX, "SAMPLES_PER_WINDOW", 64)
    windows = run(system, shocks, vectors, specialised=True, t_end=0.05, sampled=True)
    general = run(system, shocks, vectors, specialised=False, t_end=0.05, sampled=True)
    assert_same_run(windows, whole, rtol=0.0)
    assert_same_run(general, whole, rtol=0.0)


def test_sampled_multiplier_memory_does_not_grow_with_the_run():
    excitation = tabulate_excitation(2, [(np.ones(2), Sampled())], 0.0, 100.0, 1.0e-5)
    assert excitation.abscissas.size <= EX.SAMPLES_PER_WINDOW
    assert excitation.pending[0] == 1


@pytest.mark.parametrize(
    "text, extra",
    [
        ("Fa*sin(2*pi*f*(INST))", {"Fa": 3.0, "f": 7.0}),
        ("-INST**2 + 3*INST - 1/(INST+1)", {}),
        ("(INST > 0.3) * 2.0 + (1 if INST < 0.5 else -1)", {}),
        ("max(INST, 0.2, 0.1) + abs(INST - 0.5) + sqrt(INST) + exp(-INST) + log(1 + INST)", {}),
        ("INST % 0.3 + atan2(INST, 1) + sign(INST - 0.5) + int(3.7 * INST)", {}),
        ("INST >= 0.2 and INST <= 0.7", {}),
    ],
)
def test_formula_programs_evaluate_as_the_formula(text, extra):
    formula = Formula(VALE=text, NOM_PARA="INST", extra=extra)
    program = formula_program(formula)
    assert program is not None
    codes, constants = program_tables([program])
    stack = np.zeros(32)
    times = np.linspace(0.0, 1.0, 201)
    got = np.array([run_program(codes, constants, 0, t, stack) for t in times])
    np.testing.assert_allclose(got, formula.evaluate(times), rtol=1.0e-14, atol=1.0e-15)


def test_formula_calling_a_function_is_sampled_instead():
    inner = Formula(VALE="2*INST", NOM_PARA="INST")
    outer = Formula(VALE="F(INST) + 1", NOM_PARA="INST", extra={"F": inner})
    assert formula_program(outer) is None
    excitation = tabulate_excitation(1, [(np.ones(1), outer)], 0.0, 1.0, 0.01)
    assert excitation.program_codes[0, 0] == 0 and excitation.sampled[0] is not None
