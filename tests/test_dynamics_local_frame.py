"""The loops of DEVOGE, TRBDF2, RUNGE_KUTTA_32/54 and ADAPT_ORDRE1/2 with
the shocks in their local frames (``asterlite.dynamics.local_frame``)
against their general path (``specialised=False``): the same run bit for
bit when the shock frame is the global one, with a fixed and an adaptive
step; rounding only for rotated frames, full matrices and two-node shocks."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate, loop_kernel
from tests.validated import scheme_options

from .test_dynamics_specialised import N_MODES, Table, assert_same_run, small_shock_problem

SCHEMES = ("DEVOGE", "TRBDF2", "RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "ADAPT_ORDRE1", "ADAPT_ORDRE2")
ADAPTIVE = ("DEVOGE", "RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "ADAPT_ORDRE1", "ADAPT_ORDRE2")


def run_scheme(scheme, system, shocks, vectors, specialised, fixed=True, t_end=0.05, dt=2.0e-5):
    formula = Formula(VALE="F0*sin(W*INST)", NOM_PARA="INST", extra={"F0": 2.0, "W": 190.0})
    times = np.linspace(0.0, t_end, 97)
    loads = [(vectors[0], formula), (vectors[1], Table(times, np.sin(60.0 * times) ** 2))]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    q0 = np.full(N_MODES, 2.0e-4)  # released from a displaced state: impacts at once
    options = (
        scheme_options(scheme, dt_min=dt, dt_max=dt)
        if fixed
        else scheme_options(scheme, dt_max=4.0 * dt)
    )
    return integrate(
        system, shocks, excitation, scheme, q0, np.zeros(N_MODES), 0.0, t_end, dt,
        np.array([0.0123, t_end]), 7, options, specialised=specialised,
    )  # fmt: skip


def test_kernel_names():
    system, shocks, _ = small_shock_problem()
    assert loop_kernel("RUNGE_KUTTA_54", system, shocks) == "RUNGE_KUTTA"
    general = loop_kernel("RUNGE_KUTTA_32", system, shocks, specialised=False)
    assert general == "RUNGE_KUTTA (general path)"
    for scheme in ("DEVOGE", "TRBDF2", "ADAPT_ORDRE1", "ADAPT_ORDRE2"):
        assert loop_kernel(scheme, system, shocks) == scheme
        assert loop_kernel(scheme, system, shocks, specialised=False) == f"{scheme} (general path)"


@pytest.mark.parametrize(
    "scheme, fixed",
    [(s, True) for s in SCHEMES] + [(s, False) for s in ADAPTIVE],
)
def test_local_frames_equal_general_path_bit_for_bit(scheme, fixed):
    """NORM_OBST along X: the local frame is the global one, same arithmetic."""
    system, shocks, vectors = small_shock_problem()
    fast = run_scheme(scheme, system, shocks, vectors, True, fixed)
    general = run_scheme(scheme, system, shocks, vectors, False, fixed)
    fn = general.vint[:, 0, 0]
    assert (fn > 0).any() and (fn == 0).any()  # impacts and flights
    assert fast.info["rejected_steps"] == general.info["rejected_steps"]
    assert_same_run(fast, general, rtol=0.0)
    for name in ("depl", "vite", "acce", "vint", "step_info"):
        np.testing.assert_array_equal(getattr(fast, name), getattr(general, name))


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize(
    "diagonal, norm_obst, two_nodes",
    [
        (True, (0.3, 0.9, 0.3), False),
        (False, (1.0, 0.0, 0.0), False),
        (True, (0.0, 1.0, 0.0), True),
    ],
)
def test_local_frames_match_general_path(scheme, diagonal, norm_obst, two_nodes):
    """Rotated frames, full matrices, two-node shocks: rounding only (fixed
    step; short runs, before the stick-slip response amplifies it)."""
    system, shocks, vectors = small_shock_problem(diagonal, norm_obst, two_nodes)
    fast = run_scheme(scheme, system, shocks, vectors, True, t_end=0.01)
    general = run_scheme(scheme, system, shocks, vectors, False, t_end=0.01)
    assert (general.vint[:, 0, 0] > 0).any()
    assert_same_run(fast, general, rtol=1.0e-9)
