"""DEVOGE's compiled C++ loop (asterlite/dynamics/native/scheme_devoge.hpp)
against numba's (loop.time_loop around scheme_devoge.step, shocks in their
local frames): the same run to the last bit on every obstacle, friction
kind, diagonal and full matrices (LU), formula loads, support motions, with
adaptive steps (rejected steps, the three cases of the error estimate, the
step bounds and the shock damping cap) and fixed ones, and the same stop on
every failure."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.dynamics import contact as C
from asterlite.dynamics import kernel as K
from asterlite.dynamics import native
from asterlite.dynamics import scheme_devoge as D
from asterlite.dynamics.adapt_control import shock_damping_step
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.jit import interpreted
from asterlite.dynamics.layouts import LOADS, ROWS, SCALARS
from asterlite.dynamics.model import LinearSystem, build_shocks
from tests import native_runs
from tests.native_runs import (
    FORMULAS,
    GEOMETRIES,
    N_MODES,
    assert_same_bits,
    divided_by_zero,
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
FIXED = scheme_options("DEVOGE", dt_min=DT, dt_max=DT)  # equal bounds: a fixed step


class Spy:
    """DEVOGE's C++ loop, recording each call's status and memory."""

    def __init__(self, monkeypatch):
        self.loop = native.LOOPS["DEVOGE"]
        self.calls = []
        monkeypatch.setitem(native.LOOPS, "DEVOGE", self)

    def __call__(self, clock, counters, state, memory, *rest):
        status = self.loop(clock, counters, state, memory, *rest)
        self.calls.append((status, int(counters[K.K_STEP]), memory))
        self.model = rest[0]
        return status

    def statuses(self):
        return [status for status, _, _ in self.calls]


def devoge(monkeypatch, compiled, **args):
    return run(monkeypatch, compiled, scheme="DEVOGE", **args)


def options_of(adaptive: bool):
    return None if adaptive else FIXED


def assert_steps_as_asked(result, adaptive: bool):
    """An adaptive run that rejected steps, or a fixed one on the grid."""
    assert bool(result.info["adaptive"]) == adaptive
    if adaptive:
        assert result.info["rejected_steps"] > 0
        assert result.info["min_step"] < result.info["max_step"]
    else:
        assert result.info["rejected_steps"] == 0
        assert result.info["max_step"] == DT


@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("diagonal", [True, False])
@pytest.mark.parametrize("adaptive", [True, False])
def test_every_obstacle_gives_numbas_bits(request, monkeypatch, geometry, diagonal, adaptive):
    args = dict(geometry=geometry, diagonal=diagonal, norm_obst=(0.3, 0.9, 0.3))
    spy = Spy(monkeypatch)
    compiled = devoge(monkeypatch, True, options=options_of(adaptive), **args)
    numba = numba_run(request, monkeypatch, runner=devoge, options=options_of(adaptive), **args)
    assert spy.statuses()[-1] == K.STATUS_DONE
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()  # impacts
    assert_steps_as_asked(compiled, adaptive)
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("friction", ["none", "one-way", "both"])
@pytest.mark.parametrize("diagonal", [True, False])
@pytest.mark.parametrize("adaptive", [True, False])
def test_every_friction_gives_numbas_bits(request, monkeypatch, friction, diagonal, adaptive):
    args = dict(geometry="BI_CERCLE", friction=friction, diagonal=diagonal)
    compiled = devoge(monkeypatch, True, options=options_of(adaptive), **args)
    numba = numba_run(request, monkeypatch, runner=devoge, options=options_of(adaptive), **args)
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    if friction != "none":
        assert (compiled.vint[:, 0, C.V_FT1] != 0).any()
    assert_steps_as_asked(compiled, adaptive)
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("formula", range(len(FORMULAS)))
@pytest.mark.parametrize("diagonal", [True, False])
def test_formula_loads_give_numbas_bits(request, monkeypatch, formula, diagonal):
    spy = Spy(monkeypatch)
    compiled = devoge(monkeypatch, True, formula=formula, diagonal=diagonal)
    numba = numba_run(request, monkeypatch, runner=devoge, formula=formula, diagonal=diagonal)
    assert spy.model[LOADS].codes[0, 0] > 0  # the formula runs as a program in the loop
    assert_steps_as_asked(compiled, True)
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("geometry", ["CERCLE", "BI_PLAN_Z", "BI_CERC_INT"])
@pytest.mark.parametrize("diagonal", [True, False])
@pytest.mark.parametrize("adaptive", [True, False])
def test_support_motions_give_numbas_bits(request, monkeypatch, geometry, diagonal, adaptive):
    args = dict(geometry=geometry, diagonal=diagonal, supports=True, pas_arch=1)
    compiled = devoge(monkeypatch, True, options=options_of(adaptive), **args)
    numba = numba_run(request, monkeypatch, runner=devoge, options=options_of(adaptive), **args)
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    assert_steps_as_asked(compiled, adaptive)
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("diagonal", [True, False])
def test_every_case_of_the_error_estimate_gives_numbas_bits(request, monkeypatch, diagonal):
    """Every step archived: steps equal to the last two (case 0), changed
    after two equal ones (case 1), changed after a change (case 3), equal to
    the last after a change (case 0 again, code_aster's unreachable case),
    and steps rejected several times (the previous estimate rebuilt on the
    first retry only, the half-step state rescaled on each)."""
    args = dict(diagonal=diagonal, supports=True, pas_arch=1)
    compiled = devoge(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, runner=devoge, **args)
    steps = compiled.step_info[1:, K.INFO_STEP]
    assert len(steps) == compiled.info["steps"]  # every step archived
    same = steps[1:] == steps[:-1]  # step i + 1 equal to step i
    last_two_same, same_as_last = same[:-1], same[1:]
    assert (same_as_last & last_two_same).any()
    assert (~same_as_last & last_two_same).any()
    assert (~same_as_last & ~last_two_same).any()
    assert (same_as_last & ~last_two_same).any()
    rejected = np.diff(compiled.step_info[:, K.INFO_REJECTED])
    assert (rejected >= 3).any()
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("diagonal", [True, False])
def test_the_step_bounds_give_numbas_bits(request, monkeypatch, diagonal):
    """dt_max below the first step (cut at once), dt_min above the default."""
    options = scheme_options("DEVOGE", dt_min=0.05 * DT, dt_max=0.8 * DT)
    compiled = devoge(monkeypatch, True, diagonal=diagonal, options=options)
    numba = numba_run(request, monkeypatch, runner=devoge, diagonal=diagonal, options=options)
    assert compiled.info["max_step"] == 0.8 * DT
    assert 0.05 * DT <= compiled.info["min_step"] < 0.5 * DT
    assert compiled.info["rejected_steps"] > 0
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("diagonal", [True, False])
def test_the_shock_damping_cap_gives_numbas_bits(request, monkeypatch, diagonal):
    """A stiffly damped shock: the adaptive step never exceeds the cap
    (adapt_control.shock_damping_step, radius 2), which it reaches."""

    def damped_shock(*args):
        spec = shock_of(*args)
        spec.c_n = 3.0e5
        return spec

    monkeypatch.setattr(native_runs, "shock_of", damped_shock)
    spy = Spy(monkeypatch)
    compiled = devoge(monkeypatch, True, diagonal=diagonal, t_end=0.02)
    numba = numba_run(request, monkeypatch, runner=devoge, diagonal=diagonal, t_end=0.02)
    cap = spy.calls[-1][2][SCALARS][D.S_CAP]
    rng = np.random.default_rng(11)  # run's system and shock
    system = system_of(diagonal, rng)
    shocks = build_shocks([damped_shock("CERCLE", rng, "both", (1.0, 0.0, 0.0))], system)
    # the Python definition, run as Python (numba is not compiled for the tests)
    cap_of = interpreted(shock_damping_step)
    expected = cap_of(system.bundle(), shocks.bundle(), False, D.STAGE_RADIUS)
    assert cap == expected
    assert compiled.info["max_step"] == cap
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("tolerance, alpha", [(1.0e-3, 0.0), (1.0e-7, 0.0), (1.0e-5, 1.0e-4)])
def test_the_tolerance_and_alpha_give_numbas_bits(request, monkeypatch, tolerance, alpha):
    options = scheme_options("DEVOGE", tolerance=tolerance, alpha=alpha)
    compiled = devoge(monkeypatch, True, diagonal=False, options=options)
    numba = numba_run(request, monkeypatch, runner=devoge, diagonal=False, options=options)
    default = devoge(monkeypatch, True, diagonal=False)
    assert compiled.info["steps"] != default.info["steps"]
    assert_same_bits(compiled, numba)


def test_a_scale_below_machine_epsilon_keeps_the_step_alike(request, monkeypatch):
    """tolerance * (|q| + alpha) <= eps: the estimate returns 0.9**4 (step
    factor 1: the step kept, never rejected)."""
    options = scheme_options("DEVOGE", tolerance=1.0e-45)
    compiled = devoge(monkeypatch, True, options=options, t_end=0.01)
    numba = numba_run(request, monkeypatch, runner=devoge, options=options, t_end=0.01)
    assert compiled.info["adaptive"]
    assert compiled.info["rejected_steps"] == 0
    assert compiled.info["min_step"] == compiled.info["max_step"] == DT
    assert interpreted(D.step_factor)(0.9**4) * DT == DT
    assert_same_bits(compiled, numba)


@pytest.mark.parametrize("diagonal", [True, False])
@pytest.mark.parametrize("adaptive", [True, False])
def test_runs_resumed_after_a_full_archive_give_numbas_bits(
    request, monkeypatch, diagonal, adaptive
):
    """A small archive in memory: the loop returns each time it is full and
    resumes with the memory (half-step state, operators) as it left it."""
    spy = Spy(monkeypatch)
    options = scheme_options("DEVOGE", max_archive_bytes=20000)
    if not adaptive:
        options = scheme_options("DEVOGE", max_archive_bytes=20000, dt_min=DT, dt_max=DT)
    args = dict(diagonal=diagonal, supports=True, pas_arch=1, options=options)
    compiled = devoge(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, runner=devoge, **args)
    statuses = spy.statuses()
    assert statuses.count(K.STATUS_FULL) > 2 and statuses[-1] == K.STATUS_DONE
    assert (compiled.vint[:, 0, C.V_FN] > 0).any()
    assert_steps_as_asked(compiled, adaptive)
    assert_same_bits(compiled, numba)


def outcome_of(
    request, monkeypatch, options, diagonal=True, system=None, dt=DT, t_end=0.01, **changes
):
    """The error (type, message) of a failing run with the C++ loop, checked
    against numba's: a PLAN_Y shock (its ``changes`` made) on ``system`` or
    system_of(diagonal)."""

    def outcome(compiled: bool):
        monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
        rng = np.random.default_rng(3)
        linear = system_of(diagonal, rng) if system is None else system
        spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
        for name, value in changes.items():
            setattr(spec, name, value)
        shocks = build_shocks([spec], linear)
        excitation = tabulate_excitation(N_MODES, [], 0.0, t_end, 1.0e-5)
        with pytest.raises(Exception) as failure:
            integrate(
                linear, shocks, excitation, "DEVOGE", np.full(N_MODES, 2.0e-4),
                np.zeros(N_MODES), 0.0, t_end, dt, np.array([t_end]), 1, options,
            )  # fmt: skip
        return type(failure.value), str(failure.value)

    cpp = outcome(True)
    assert_same(cpp, reference(request, lambda: outcome(False)), "the failure")
    return cpp


def test_a_diverging_shock_stops_both_alike(request, monkeypatch):
    """Absurd shock stiffness and damping, fixed step: the same error."""
    spy = Spy(monkeypatch)
    outcome = outcome_of(request, monkeypatch, FIXED, k_n=1.0e30, c_n=1.0e20)
    assert spy.statuses() == [K.STATUS_SHOCK_DIVERGED]
    assert "diverged" in outcome[1]


@pytest.mark.parametrize("step_bounds", [(None, None), (DT, 10.0 * DT)])
def test_a_step_below_its_bound_stops_both_alike(request, monkeypatch, step_bounds):
    """Adaptive: the absurd damping caps the step below dt_min; the free
    flight fails its tolerance at dt_min = dt. Both stop alike."""
    spy = Spy(monkeypatch)
    dt_min, dt_max = step_bounds
    options = scheme_options("DEVOGE", dt_min=dt_min, dt_max=dt_max)
    changes = dict(k_n=1.0e30, c_n=1.0e20) if dt_min is None else {}
    outcome = outcome_of(request, monkeypatch, options, **changes)
    assert spy.statuses()[-1] == K.STATUS_STEP_UNDERFLOW
    assert "options.dt_min" in outcome[1]


def test_a_growing_fixed_step_run_stops_both_alike(request, monkeypatch):
    """A fixed step ten times the stability limit, full matrices, the
    shock's gap wide: the trial becomes non-finite, exposed alike."""
    spy = Spy(monkeypatch)
    dt = 2.0e-3
    options = scheme_options("DEVOGE", dt_min=dt, dt_max=dt)
    outcome = outcome_of(request, monkeypatch, options, False, dt=dt, t_end=10.0, gap=10.0)
    assert spy.statuses()[-1] == K.STATUS_NOT_FINITE
    assert "non-finite" in outcome[1]


DT_EXACT = 2.0**-15  # dt * (c / dt) == c exactly


def singular_system(diagonal: bool, operator: str) -> LinearSystem:
    """C' with a first entry making H0 = 4I - dt C', H1 = 4I + dt C' or
    H2 = 6I + dt C' exactly zero on the first mode."""
    stiffness = np.diag(np.linspace(1.0e6, 2.0e7, N_MODES))
    damping = np.diag(np.full(N_MODES, 10.0))
    damping[0, 0] = {"H0": 4.0, "H1": -4.0, "H2": -6.0}[operator] / DT_EXACT
    if not diagonal:
        stiffness[1, 2] = stiffness[2, 1] = 1.0e4
    system = LinearSystem(np.eye(N_MODES), stiffness, damping)
    assert system.diagonal == diagonal
    return system


@pytest.mark.parametrize("operator", ["H0", "H1", "H2"])
def test_a_singular_full_operator_stops_both_alike(request, monkeypatch, operator):
    """Full matrices: the LU factorisation fails in start, on the first step."""
    spy = Spy(monkeypatch)
    options = scheme_options("DEVOGE", dt_min=DT_EXACT, dt_max=DT_EXACT)
    system = singular_system(False, operator)
    outcome_of(request, monkeypatch, options, system=system, dt=DT_EXACT)  # checked alike
    [(status, steps, memory)] = spy.calls
    assert (status, steps) == (K.STATUS_NOT_FINITE, 0)
    assert memory[SCALARS][D.S_READY] == 0.0


@pytest.mark.parametrize("operator", ["H0", "H1", "H2"])
def test_a_zero_diagonal_operator_raises_as_numba_does(request, monkeypatch, operator):
    """Diagonal matrices: numba's division by the zero entry raises
    ZeroDivisionError (error_model "python"); so does the C++ loop (the run then
    stops with the worded NumericalError)."""
    options = scheme_options("DEVOGE", dt_min=DT_EXACT, dt_max=DT_EXACT)
    system = singular_system(True, operator)
    outcome = outcome_of(request, monkeypatch, options, system=system, dt=DT_EXACT)
    assert divided_by_zero(outcome)


def test_a_memory_of_another_size_is_refused():
    args = [np.zeros(3)] * 53
    args[10] = np.zeros((D.memory_rows(4), 5))  # rows for 4 modes, 5 columns
    with pytest.raises(ValueError, match="memory of another size"):
        native._devoge.devoge_loop(*args)
    args[10], args[11] = np.zeros((D.memory_rows(5), 5)), np.zeros(D.MEMORY_SCALARS - 1)
    with pytest.raises(ValueError, match="memory of another size"):
        native._devoge.devoge_loop(*args)
    with pytest.raises(TypeError, match="argument counters must be int64 values"):
        native._devoge.devoge_loop(*[np.zeros(3)] * 53)


def test_the_memory_positions_are_the_python_ones():
    assert (D.Q2, D.X2, D.P0, D.P2, D.D_MINV, D.D_H2) == (0, 16, 17, 19, 20, 24)
    assert (D.MATRIX_ROWS, D.S_HDT, D.S_CAP, D.MEMORY_SCALARS) == (25, 9, 10, 11)
    assert D.memory_rows(N_MODES) == D.MATRIX_ROWS + 5 * N_MODES
    assert D.EPS == np.finfo(float).eps and ROWS == 0
