"""code_aster 10-12's ADAPT_ORDRE2 (mdadap) compiled in C++
(asterlite/dynamics/native/scheme_adapt_legacy.hpp, module ``_legacy``)
against numba's loop (scheme_adapt_ordre2_v11.run_loop): the same run to the
last bit on every obstacle geometry, friction kind, matrix kind, load kind
and support motion, with rejected steps, steps kept at the largest number of
trials, both reference velocities, an archive grid denser than the buffers,
pauses every few steps, and the same error where a run fails."""

from __future__ import annotations

import pytest

from asterlite.dynamics import contact as C
from asterlite.dynamics import excitation as EX
from asterlite.dynamics import integrate as I
from asterlite.dynamics import native, schemes
from asterlite.dynamics import scheme_adapt_ordre2_v11 as V11
from asterlite.errors import NumericalError
from tests import native_runs
from tests.native_runs import FORMULAS, GEOMETRIES, assert_same_bits, numba_run, run
from tests.numba_reference import assert_same, reference
from tests.validated import scheme_options

# numba's side is its stored fingerprints (tests.numba_reference)
pytestmark = pytest.mark.usefixtures("needs_native")

LEGACY = schemes.LEGACY_ADAPT_LOOP  # "ADAPT_ORDRE2 (code_aster 10-12)"
DT = 2.0e-5  # native_runs.run's step


@pytest.fixture(autouse=True)
def routed(monkeypatch):
    """The compiled loop for code_aster 10-12's ADAPT_ORDRE2 where
    native.run_loop does not route it yet (the engine's routing comes with the
    lead's edit): the loop the module ``_legacy`` lists in its KERNELS."""
    assert LEGACY in native.LOOPS
    original = native.run_loop

    def run_loop(entry, loop, *args, **kwargs):
        found = original(entry, loop, *args, **kwargs)
        if found is None and loop == LEGACY and native.available():
            return native.LOOPS[LEGACY]
        return found

    monkeypatch.setattr(native, "run_loop", run_loop)


def options(**fields):
    return scheme_options("ADAPT_ORDRE2", adapt_v11=True, **{"dt_max": 4.0e-5, **fields})


def both(request, monkeypatch, **args):
    """The run with the C++ loop, checked bit for bit against numba's; the
    C++ run."""
    args = {"scheme": "ADAPT_ORDRE2", "options": options(), **args}
    compiled = run(monkeypatch, True, **args)
    numba = numba_run(request, monkeypatch, **args)
    assert compiled.info["loop"] == f"{LEGACY} [C++]"
    assert_same_bits(compiled, numba)
    return compiled


def both_fail(request, monkeypatch, match, **args) -> str:
    """Both loops stop the run with the same error (the C++ loop's)."""
    args = {"scheme": "ADAPT_ORDRE2", "options": options(), **args}

    def message(compiled: bool) -> str:
        with pytest.raises(NumericalError, match=match) as failure:
            run(monkeypatch, compiled, **args)
        return str(failure.value)

    cpp = message(True)
    assert_same(cpp, reference(request, lambda: message(False)), "the failure")
    return cpp


def impacts(result) -> bool:
    return bool((result.vint[:, 0, C.V_FN] > 0).any())


@pytest.mark.parametrize("geometry", GEOMETRIES)
@pytest.mark.parametrize("diagonal", [True, False])
def test_every_obstacle_gives_numbas_bits(request, monkeypatch, geometry, diagonal):
    result = both(
        request, monkeypatch, geometry=geometry, diagonal=diagonal, norm_obst=(0.3, 0.9, 0.3)
    )
    assert impacts(result)
    assert result.info["adaptive"] and result.info["rejected_steps"] > 0


@pytest.mark.parametrize("friction", ["none", "one-way", "both"])
def test_every_friction_gives_numbas_bits(request, monkeypatch, friction):
    result = both(request, monkeypatch, geometry="BI_CERCLE", friction=friction)
    assert impacts(result)
    if friction != "none":
        assert (result.vint[:, 0, C.V_FT1] != 0).any()


@pytest.mark.parametrize("formula", range(len(FORMULAS)))
def test_formula_loads_give_numbas_bits(request, monkeypatch, formula):
    both(request, monkeypatch, formula=formula, diagonal=False)


@pytest.mark.parametrize("diagonal", [True, False])
def test_support_motions_give_numbas_bits(request, monkeypatch, diagonal):
    result = both(request, monkeypatch, supports=True, diagonal=diagonal, t_end=0.08)
    assert impacts(result)


def test_sampling_windows_give_numbas_bits(request, monkeypatch):
    """Windows of 64 samples: the loop stops for the next window of the
    sampled loads and support motions (loads_ready), and resumes."""
    refills = []
    refill = EX.Excitation.refill

    def counted(self, t, dt):
        if native.available():  # the C++ run's
            refills.append(t)
        return refill(self, t, dt)

    monkeypatch.setattr(EX, "SAMPLES_PER_WINDOW", 64)
    monkeypatch.setattr(EX.Excitation, "refill", counted)
    both(request, monkeypatch, supports=True)
    assert len([t for t in refills if t > 0.0]) > 2 * 20


@pytest.mark.parametrize("pas_arch", [1, 3, 50])
def test_archive_grid_gives_numbas_bits(request, monkeypatch, pas_arch):
    """mdadap's archive grid (t0 + k dt_max pas_arch, the nearer end of the
    step bracketing each) and the final state in the slots left."""
    result = both(request, monkeypatch, pas_arch=pas_arch)
    assert len(result.times) == V11.planned_slots.py_func(0.0, 0.04, 4.0e-5 * pas_arch)


def test_an_archive_grid_denser_than_the_buffers_gives_numbas_bits(request, monkeypatch):
    """The step's upper bound below the step: the slots outnumber the
    archive's first capacity (the buffers grow, the loop resumes)."""
    result = both(request, monkeypatch, options=options(dt_max=5.0e-6), pas_arch=2)
    assert len(result.times) > 2 + 3 + 2000 // 2


def test_pauses_give_numbas_bits(request, monkeypatch):
    """Paused every 50 steps: the loop resumes where it stopped."""
    monkeypatch.setattr(I.StepBudget, "FIRST_CHUNK", 50)
    monkeypatch.setattr(I.StepBudget, "resize_chunk", lambda self, seconds: None)
    result = both(request, monkeypatch, geometry="BI_PLAN_Y", diagonal=False)
    assert result.info["steps"] > 20 * 50


def test_steps_kept_at_the_largest_number_of_trials_give_numbas_bits(request, monkeypatch):
    result = both(request, monkeypatch, options=options(nmax_iter_pas=1), geometry="BI_CERCLE")
    assert result.info["steps_kept_at_nmax_iter_pas"] > 0


@pytest.mark.parametrize("vite_min", ["NORM", "MAXI"])
@pytest.mark.parametrize("points", [10, 50])
def test_step_control_options_give_numbas_bits(request, monkeypatch, vite_min, points):
    opts = options(vite_min=vite_min, nb_poin_periode=points, coef_mult_pas=1.5, coef_divi_pas=3.0)
    result = both(request, monkeypatch, options=opts, geometry="CERCLE", diagonal=False)
    assert result.info["rejected_steps"] > 0 or points == 10


def test_growth_to_the_upper_bound_gives_numbas_bits(request, monkeypatch):
    """Calm steps: the step grows from PAS to PAS_MAXI (above it)."""
    result = both(
        request, monkeypatch, options=options(dt_max=1.0e-4, nb_poin_periode=5), t_end=0.08
    )
    assert result.info["max_step"] > DT


def test_step_underflow_stops_both_alike(request, monkeypatch):
    both_fail(request, monkeypatch, "adaptive step fell below", options=options(dt_min=1.9e-5))


@pytest.mark.parametrize("friction", ["none", "both"])
def test_a_diverging_run_stops_both_alike(request, monkeypatch, friction):
    """A load that overflows at t = 0.0237: with friction, the shock's
    velocity diverges first (its check); without, the acceleration becomes
    non-finite. The same error, the same instant."""
    monkeypatch.setattr(native_runs, "FORMULAS", FORMULAS + (("exp(30000*INST)", {}),))
    match = "became non-finite" if friction == "none" else "velocity at a shock diverged"
    both_fail(request, monkeypatch, match, formula=len(FORMULAS), friction=friction)


def test_the_compiled_loop_serves_only_code_aster_10_12_s_variant():
    """The legacy kernel is the module ``_legacy``'s, under mdadap's name."""
    from asterlite.dynamics.native import _legacy

    assert _legacy.KERNELS == {LEGACY: "adapt_legacy_loop"}
