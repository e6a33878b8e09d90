"""NEWMARK's specialised loop (local-frame shocks, helpers inlined, no
reference counting) against its general path (``specialised=False``): the
same run bit for bit when the shock frame is the global one, to rounding
otherwise; full matrices, two-node shocks, sampled multipliers, the forces
of the step's start (code_aster 13-15 decks) and ENERGIE included."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate, loop_kernel
from tests.validated import scheme_options

from .test_dynamics_specialised import N_MODES, Sampled, Table, assert_same_run, small_shock_problem


def run_newmark(system, shocks, vectors, specialised, t_end=0.05, dt=2.0e-5, **kw):
    formula = Formula(VALE="F0*sin(W*INST)", NOM_PARA="INST", extra={"F0": 2.0, "W": 190.0})
    times = np.linspace(0.0, t_end, 97)
    second = Sampled() if kw.pop("sampled", False) else Table(times, np.sin(60.0 * times) ** 2)
    loads = [(vectors[0], formula), (vectors[1], second)]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    q0 = np.full(N_MODES, 2.0e-4)  # released from a displaced state: impacts at once
    options = scheme_options("NEWMARK", force_at_step_start=kw.pop("at_start", False))
    return integrate(
        system, shocks, excitation, "NEWMARK", q0, np.zeros(N_MODES), 0.0, t_end, dt,
        np.array([0.0123, t_end]), 7, options, specialised=specialised, **kw,
    )  # fmt: skip


def test_kernel_names():
    system, shocks, _ = small_shock_problem()
    assert loop_kernel("NEWMARK", system, shocks) == "NEWMARK"
    assert loop_kernel("NEWMARK", system, shocks, specialised=False) == "NEWMARK (general path)"


@pytest.mark.parametrize("at_start", [False, True])
def test_newmark_specialised_equals_general_path_bit_for_bit(at_start):
    system, shocks, vectors = small_shock_problem()
    fast = run_newmark(system, shocks, vectors, True, t_end=0.2, at_start=at_start)
    general = run_newmark(system, shocks, vectors, False, t_end=0.2, at_start=at_start)
    fn = general.vint[:, 0, 0]
    assert (fn > 0).any() and (fn == 0).any()  # impacts and flights
    assert (general.vint[:, 0, 1] != 0).any()  # friction
    assert_same_run(fast, general, rtol=0.0)
    np.testing.assert_array_equal(fast.acce, general.acce)
    np.testing.assert_array_equal(fast.vite, general.vite)


def test_newmark_specialised_energy_and_sampled_loads_bit_for_bit():
    system, shocks, vectors = small_shock_problem()
    fast = run_newmark(system, shocks, vectors, True, sampled=True, energy=True)
    general = run_newmark(system, shocks, vectors, False, sampled=True, energy=True)
    assert_same_run(fast, general, rtol=0.0)
    np.testing.assert_array_equal(fast.energy, general.energy)


@pytest.mark.parametrize(
    "diagonal, norm_obst, two_nodes",
    [
        (True, (0.3, 0.9, 0.3), False),
        (False, (1.0, 0.0, 0.0), False),
        (True, (0.0, 1.0, 0.0), True),
    ],
)
def test_newmark_specialised_matches_general_path(diagonal, norm_obst, two_nodes):
    """Rotated frames, full matrices (LU solve), two-node shocks: rounding only."""
    system, shocks, vectors = small_shock_problem(diagonal, norm_obst, two_nodes)
    fast = run_newmark(system, shocks, vectors, True)
    general = run_newmark(system, shocks, vectors, False)
    assert (general.vint[:, 0, 0] > 0).any()
    assert_same_run(fast, general, rtol=1.0e-9)
