"""ADAPT_ORDRE1's and ADAPT_ORDRE2's compiled C++ loops
(asterlite/dynamics/native/scheme_adapt.hpp) against numba's time loop
around their steps: the same run to the last bit on every obstacle
geometry, friction kind, matrix kind, load kind and support motion, with
adaptive and fixed steps, steps rejected and steps kept at the largest
number of trials, both reference velocities (VITE_MIN), and the same error
where a run fails."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics import contact as C
from asterlite.dynamics import integrate as I
from asterlite.dynamics import kernel as K
from asterlite.dynamics import native
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.model import build_shocks
from asterlite.errors import NumericalError
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

SCHEMES = ("ADAPT_ORDRE1", "ADAPT_ORDRE2")
DT = 2.0e-5  # native_runs.run's step


def both(request, monkeypatch, **args):
    """The run with the C++ loop, checked bit for bit against numba's; the
    C++ run."""
    compiled = run(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, **args)
    assert compiled.info["loop"] == f"{args['scheme']} [C++]"
    assert_same_bits(compiled, numba)
    return compiled


def impacts(result) -> bool:
    return bool((result.vint[:, 0, C.V_FN] > 0).any())


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_obstacle_gives_numbas_bits(request, monkeypatch, scheme, geometry, diagonal):
    args = dict(scheme=scheme, geometry=geometry, diagonal=diagonal, norm_obst=(0.3, 0.9, 0.3))
    result = both(request, monkeypatch, **args)
    assert impacts(result)
    assert result.info["adaptive"] and result.info["rejected_steps"] > 0


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("friction", ["none", "one-way", "both"])
def test_every_friction_gives_numbas_bits(request, monkeypatch, scheme, friction):
    result = both(request, monkeypatch, scheme=scheme, geometry="BI_CERCLE", friction=friction)
    assert impacts(result)
    if friction != "none":
        assert (result.vint[:, 0, C.V_FT1] != 0).any()


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("formula", range(len(FORMULAS)))
def test_formula_loads_give_numbas_bits(request, monkeypatch, scheme, formula):
    both(request, monkeypatch, scheme=scheme, formula=formula, diagonal=False)


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("geometry, diagonal", [("CERCLE", True), ("BI_PLAN_Z", False)])
def test_support_motions_give_numbas_bits(request, monkeypatch, scheme, geometry, diagonal):
    args = dict(scheme=scheme, geometry=geometry, diagonal=diagonal, supports=True, pas_arch=1)
    result = both(request, monkeypatch, **args)
    assert impacts(result)


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("diagonal", [True, False])
def test_fixed_steps_give_numbas_bits(request, monkeypatch, scheme, diagonal):
    """Equal step bounds: the step is never adapted (no error computed)."""
    options = scheme_options(scheme, dt_min=DT, dt_max=DT)
    result = both(
        request, monkeypatch, scheme=scheme, diagonal=diagonal, options=options, supports=True
    )
    assert impacts(result)
    assert not result.info["adaptive"] and result.info["rejected_steps"] == 0
    assert result.info["max_step"] == DT  # shortened only to meet the archive's instants
    assert result.info["steps_kept_at_nmax_iter_pas"] == 0


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("vite_min", ["NORM", "MAXI"])
@pytest.mark.parametrize("diagonal", [True, False])
def test_reference_velocities_give_numbas_bits(request, monkeypatch, scheme, vite_min, diagonal):
    """VITE_MIN: 1 % of the velocity norm, or the running maximum of 1 % of
    each modal velocity; the points per period and factors of a deck."""
    options = scheme_options(
        scheme, vite_min=vite_min, nb_poin_periode=30, coef_mult_pas=1.3, coef_divi_pas=2.0
    )
    result = both(
        request, monkeypatch, scheme=scheme, diagonal=diagonal, options=options, friction="none"
    )
    assert impacts(result)
    assert result.info["rejected_steps"] > 0
    assert result.info["max_step"] > DT  # grown after calm steps


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("vite_min", ["NORM", "MAXI"])
def test_steps_kept_at_the_largest_number_of_trials(request, monkeypatch, scheme, vite_min):
    """Two trials at most: steps rejected once, then kept on their second
    trial whatever its error (steps_kept_at_nmax_iter_pas counts them, those
    with an error >= 1 and the others alike)."""
    options = scheme_options(scheme, nmax_iter_pas=2, vite_min=vite_min, nb_poin_periode=80)
    result = both(request, monkeypatch, scheme=scheme, options=options, geometry="BI_CERC_INT")
    assert impacts(result)
    assert result.info["rejected_steps"] > 0
    assert result.info["steps_kept_at_nmax_iter_pas"] > 0


@pytest.mark.parametrize("scheme", SCHEMES)
def test_tiny_steps_after_a_rejection_give_numbas_bits(request, monkeypatch, scheme):
    """A division by 1e10 on a rejection: second trials of steps below 1e-13
    (where ADAPT_ORDRE1 takes p = dt, not the mean of the proposed step and
    the step), grown back by 1e9 after calm steps."""
    options = scheme_options(
        scheme, nmax_iter_pas=2, coef_divi_pas=1.0e10, coef_mult_pas=1.0e9, dt_min=1.0e-30,
        dt_max=5.0 * DT,
    )  # fmt: skip
    result = both(request, monkeypatch, scheme=scheme, options=options, t_end=0.02)
    assert impacts(result)
    assert result.info["rejected_steps"] > 0 and result.info["min_step"] <= 1.0e-13
    assert result.info["steps_kept_at_nmax_iter_pas"] > 0


def failure(monkeypatch, compiled: bool, scheme: str, options, stiff=False, loads=()):
    """A run on a one-shock system that fails: its error, and the clock,
    counters and state as the last call of the loop (C++ or numba's, as
    asked: checked) left them."""
    monkeypatch.setenv(native.SWITCH, "1" if compiled else "0")
    seen = {}

    def watched(loop, kind):
        def watch(clock, counters, state, *rest):
            status = loop(clock, counters, state, *rest)
            seen.update(
                kind=kind, status=status, arrays=[x.copy() for x in (clock, counters, *state)]
            )
            return status

        return watch

    monkeypatch.setitem(native.LOOPS, scheme, watched(native.LOOPS[scheme], "C++"))
    numba_loop = I.scheme_run_loop
    monkeypatch.setattr(I, "scheme_run_loop", lambda *args: watched(numba_loop(*args), "numba"))
    rng = np.random.default_rng(3)
    system = system_of(True, rng)
    spec = shock_of("PLAN_Y", rng, "both", (1.0, 0.0, 0.0))
    if stiff:
        spec.k_n, spec.c_n = 1.0e30, 1.0e20
    shocks = build_shocks([spec], system)
    excitation = tabulate_excitation(N_MODES, list(loads), 0.0, 0.01, 1.0e-5)
    with pytest.raises(NumericalError) as failed:
        integrate(
            system, shocks, excitation, scheme, np.full(N_MODES, 2.0e-4), np.zeros(N_MODES),
            0.0, 0.01, DT, np.array([0.01]), 1, options, load_labels=["L"] * len(loads),
        )  # fmt: skip
    assert seen["kind"] == ("C++" if compiled else "numba")
    return str(failed.value), seen


def assert_same_failure(request, monkeypatch, scheme, options, status, **problem) -> str:
    """The failure on the C++ loop, with ``status``, against numba's: the
    same status, error, clock, counters and state; the C++ loop's error."""

    def outcome(compiled: bool) -> dict:
        message, seen = failure(monkeypatch, compiled, scheme, options, **problem)
        return {"status": seen["status"], "message": message, "arrays": seen["arrays"]}

    cpp = outcome(True)
    assert cpp["status"] == status
    assert_same(cpp, reference(request, lambda: outcome(False)), "the failure")
    return cpp["message"]


@pytest.mark.parametrize(
    "scheme, adaptive, status",
    [
        ("ADAPT_ORDRE1", True, K.STATUS_SHOCK_DIVERGED),
        ("ADAPT_ORDRE1", False, K.STATUS_SHOCK_DIVERGED),
        ("ADAPT_ORDRE2", True, K.STATUS_STEP_UNDERFLOW),  # its steps divided to the bound
        ("ADAPT_ORDRE2", False, K.STATUS_SHOCK_DIVERGED),
    ],
)
def test_an_absurd_stiffness_stops_both_alike(request, monkeypatch, scheme, adaptive, status):
    """The run stops with the same status, state and error on both."""
    fields = {} if adaptive else {"dt_min": DT, "dt_max": DT}
    options = scheme_options(scheme, **fields)
    message = assert_same_failure(request, monkeypatch, scheme, options, status, stiff=True)
    assert ("diverged" if status == K.STATUS_SHOCK_DIVERGED else "fell below") in message


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("adaptive", [True, False])
def test_a_non_finite_acceleration_stops_both_alike(request, monkeypatch, scheme, adaptive):
    """A load that jumps to 1e305: the trial's acceleration is not finite
    and the trial is exposed in the state, alike on both."""
    fields = {} if adaptive else {"dt_min": DT, "dt_max": DT}
    options = scheme_options(scheme, **fields)
    jump = Formula(VALE="(INST > 0.001) * 1.0e305", NOM_PARA="INST", extra={})
    loads = [(np.ones(N_MODES), jump)]
    message = assert_same_failure(
        request, monkeypatch, scheme, options, K.STATUS_NOT_FINITE, loads=loads
    )
    assert "non-finite" in message


@pytest.mark.parametrize("scheme", SCHEMES)
def test_a_step_below_its_lower_bound_stops_both_alike(request, monkeypatch, scheme):
    """A lower bound just under the first step: the first rejection stops
    the run (the step underflows) at the same instant on both."""
    options = scheme_options(scheme, dt_min=0.9 * DT, dt_max=10.0 * DT, nb_poin_periode=400)
    message = assert_same_failure(request, monkeypatch, scheme, options, K.STATUS_STEP_UNDERFLOW)
    assert "fell below" in message
