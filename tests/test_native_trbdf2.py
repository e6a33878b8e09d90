"""TRBDF2's compiled C++ loop (asterlite/dynamics/native/scheme_trbdf2.hpp)
against numba's (loop.time_loop around scheme_trbdf2.step, shocks in their
local frames): the same run to the last bit on every obstacle, friction
kind, diagonal (the fast path) and full matrices (LU), formula loads,
support motions, changes of step (the operators rebuilt) and failures."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asterlite.dynamics import contact as C
from asterlite.dynamics import implicit as I
from asterlite.dynamics import kernel as K
from asterlite.dynamics import native
from asterlite.dynamics import scheme_trbdf2 as T
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.layouts import LOADS, ROWS, SCALARS
from asterlite.dynamics.model import LinearSystem, build_shocks
from tests.native_runs import (
    FORMULAS,
    GEOMETRIES,
    N_MODES,
    assert_same_bits,
    numba_run,
    run,
    shock_of,
    system_of,
)
from tests.numba_reference import assert_same, reference
from tests.validated import scheme_options

# numba's side is its stored fingerprints (tests.numba_reference)
pytestmark = pytest.mark.usefixtures("needs_native")

DT = 2.0e-5  # tests/native_runs.py's step


class Spy:
    """TRBDF2's C++ loop, recording each call's status and memory."""

    def __init__(self, monkeypatch):
        self.loop = native.LOOPS["TRBDF2"]
        self.calls = []
        monkeypatch.setitem(native.LOOPS, "TRBDF2", self)

    def __call__(self, clock, counters, state, memory, *rest):
        status = self.loop(clock, counters, state, memory, *rest)
        self.calls.append((status, int(counters[K.K_STEP]), memory))
        self.model = rest[0]
        return status


def trbdf2(monkeypatch, compiled, **args):
    return run(monkeypatch, compiled, scheme="TRBDF2", **args)


def test_the_constants_are_the_products_the_header_computes():
    gamma = 2.0 - math.sqrt(2.0)
    assert T.STAGE_FRACTION == gamma
    assert T.G2 == -((1.0 - gamma) * (1.0 - gamma)) / gamma / (2.0 - gamma)


@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_obstacle_gives_numbas_bits(request, monkeypatch, geometry, diagonal):
    args = dict(geometry=geometry, diagonal=diagonal, norm_obst=(0.3, 0.9, 0.3))
    spy = Spy(monkeypatch)
    compiled = trbdf2(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, runner=trbdf2, **args)
    assert spy.calls and spy.calls[-1][0] == K.STATUS_DONE
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()  # impacts
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("friction", ["none", "one-way", "both"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_friction_gives_numbas_bits(request, monkeypatch, friction, diagonal):
    args = dict(geometry="BI_CERCLE", friction=friction, diagonal=diagonal)
    compiled = trbdf2(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, runner=trbdf2, **args)
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    if friction != "none":
        assert (compiled.vint[:, 0, C.V_FT1] != 0).any()
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("formula", range(len(FORMULAS)))
@pytest.mark.parametrize("diagonal", [True, False])
def test_formula_loads_give_numbas_bits(request, monkeypatch, formula, diagonal):
    spy = Spy(monkeypatch)
    compiled = trbdf2(monkeypatch, True, formula=formula, diagonal=diagonal)
    numba = numba_run(request, monkeypatch, runner=trbdf2, formula=formula, diagonal=diagonal)
    assert spy.model[LOADS].codes[0, 0] > 0  # the formula runs as a program in the loop
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("geometry", ["CERCLE", "BI_PLAN_Z", "BI_CERC_INT"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_support_motions_give_numbas_bits(request, monkeypatch, geometry, diagonal):
    args = dict(geometry=geometry, diagonal=diagonal, supports=True, pas_arch=1)
    compiled = trbdf2(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, runner=trbdf2, **args)
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("diagonal", [True, False])
def test_a_change_of_step_rebuilds_the_operators_alike(request, monkeypatch, diagonal):
    """The instants 0.0123 and 0.0123 + 0.3 dt make steps of 0.3 dt and 0.7
    dt between steps of dt: K_eff, F1, F2 built anew at each change."""
    spy = Spy(monkeypatch)
    args = dict(diagonal=diagonal, supports=True, pas_arch=1, t_end=0.016)
    compiled = trbdf2(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, runner=trbdf2, **args)
    steps = np.diff(compiled.times)
    for fraction in (0.3, 0.7, 1.0):
        assert np.isclose(steps, fraction * DT, rtol=1e-9, atol=0.0).any()
    assert compiled.info["min_step"] < compiled.info["max_step"]
    memory = spy.calls[-1][2]
    assert memory[SCALARS][T.S_DT_BUILT] == DT  # back to dt after the short steps
    assert memory[SCALARS][T.S_DIAGONAL] == (1.0 if diagonal else 0.0)
    assert_same_bits(compiled, numba)


def test_a_diverging_shock_stops_both_alike(request, monkeypatch):
    """Absurd shock stiffness and damping: the same error on both."""
    spy = Spy(monkeypatch)

    def outcome(compiled: bool) -> str:
        monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
        rng = np.random.default_rng(3)
        system = system_of(True, rng)
        spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
        spec.k_n, spec.c_n = 1.0e30, 1.0e20
        shocks = build_shocks([spec], system)
        excitation = tabulate_excitation(N_MODES, [], 0.0, 0.01, 1.0e-5)
        with pytest.raises(Exception) as failure:
            integrate(
                system, shocks, excitation, "TRBDF2", np.full(N_MODES, 2.0e-4),
                np.zeros(N_MODES), 0.0, 0.01, DT, np.array([0.01]), 1, scheme_options("TRBDF2"),
            )  # fmt: skip
        return str(failure.value)

    message = outcome(True)
    assert_same(message, reference(request, lambda: outcome(False)), "the failure")
    assert [status for status, _, _ in spy.calls] == [K.STATUS_SHOCK_DIVERGED]
    assert "diverged" in message


def test_a_singular_effective_stiffness_stops_both_alike(request, monkeypatch):
    """K = -a1 M on the first mode (C = 0): the first column of K_eff = a1 M +
    K + a2 C is exactly zero, the LU factorisation fails on the first step."""
    spy = Spy(monkeypatch)
    h = T.STAGE_FRACTION * DT
    stiffness = np.diag(np.linspace(1.0e6, 2.0e7, N_MODES))
    stiffness[0, 0] = -4.0 / (h * h)
    stiffness[1, 2] = stiffness[2, 1] = 1.0e4  # full matrices: the LU path
    system = LinearSystem(np.eye(N_MODES), stiffness, np.zeros((N_MODES, N_MODES)))
    assert not system.diagonal

    def outcome(compiled: bool) -> str:
        monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
        rng = np.random.default_rng(3)
        shocks = build_shocks([shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))], system)
        excitation = tabulate_excitation(N_MODES, [], 0.0, 0.01, 1.0e-5)
        with pytest.raises(Exception) as failure:
            integrate(
                system, shocks, excitation, "TRBDF2", np.zeros(N_MODES), np.zeros(N_MODES),
                0.0, 0.01, DT, np.array([0.01]), 1, scheme_options("TRBDF2"),
            )  # fmt: skip
        return str(failure.value)

    message = outcome(True)
    assert_same(message, reference(request, lambda: outcome(False)), "the failure")
    [(status, steps, memory)] = spy.calls
    assert (status, steps) == (K.STATUS_NOT_FINITE, 0)
    start = T.VECTOR_ROWS + I.B_KEFF * N_MODES  # implicit.block, read from Python
    keff = memory[ROWS][start : start + N_MODES]
    assert (keff[:, 0] == 0.0).all()  # the vanishing pivot, not a non-finite state


@pytest.mark.parametrize("diagonal", [True, False])
def test_runs_resumed_after_a_full_archive_give_numbas_bits(request, monkeypatch, diagonal):
    """A small archive in memory: the loop returns each time it is full and
    resumes with the memory (index-2 state, operators) as it left it."""
    spy = Spy(monkeypatch)
    options = scheme_options("TRBDF2", max_archive_bytes=20000)
    args = dict(diagonal=diagonal, supports=True, pas_arch=1, options=options)
    compiled = trbdf2(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, runner=trbdf2, **args)
    statuses = [status for status, _, _ in spy.calls]
    assert statuses.count(K.STATUS_FULL) > 10 and statuses[-1] == K.STATUS_DONE
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    assert_same_bits(compiled, numba)
